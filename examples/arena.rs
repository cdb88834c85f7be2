//! The arena run on the host (`embedded/src/arena.rs`): the mesh built at run time from
//! `examples/data/arena.obj` in I16F16; prints `I16F16 hash`, the line the Cortex-M0 program
//! `arena` (the same mesh baked into flash) must print bit for bit (`.ci/embedded.sh` compares
//! them). Contacts and escapes go to stderr.
//!
//! Run: `cargo run --release --example arena`

use ballcast::bvh::nodes_for;
use ballcast::{Degenerates, Mesh, Node};
use fixed::types::I16F16;

#[path = "../embedded/src/arena.rs"]
mod arena;
#[path = "../embedded/src/lockstep.rs"]
mod lockstep;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let level = ballcast_level::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/data/arena.obj"
    ))?;
    let sources = ballcast_level::triangles::<I16F16>(&level)?;
    let n = sources.len();
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut prepared = vec![Mesh::<I16F16>::filler(); n];
    let mut order = vec![0u32; n];
    let mut scratch = vec![0u64; 6 * n];
    let (mesh, _) = Mesh::build(
        &sources,
        Degenerates::Skip,
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    )?;
    let o = arena::simulate::<I16F16, _>(&mesh, arena::THROWS, arena::STEPS_PER_THROW);
    println!("I16F16 {:016x}", o.hash);
    eprintln!(
        "arena: {} triangles, {} steps, {} contacts, {} escapes",
        mesh.len(),
        arena::THROWS * arena::STEPS_PER_THROW,
        o.contacts,
        o.escapes
    );
    Ok(())
}
