//! The arena run (`embedded/src/arena.rs`) on the two compact forms of `embedded/src/forms.rs`,
//! built at run time: the arena as a `CompactMesh` and the 64 × 64 terrain `Heightfield`, each
//! alone and both as one `Compound` level, in I16F16, and a `Character` walking over the
//! terrain (`embedded/src/walker.rs`), without and with a cache of 16 triangles. Prints
//! `compact I16F16 hash`, `heightfield I16F16 hash`, `compound I16F16 hash`, `character I16F16
//! hash` and `character cached I16F16 hash`, the lines the Cortex-M0 program `forms`
//! (the same forms baked into flash) must print bit for bit (`.ci/embedded.sh` compares them).
//! Contacts and escapes go to stderr.
//!
//! Run: `cargo run --release --example forms`

use ballcast::bvh::{LeafSize, nodes_for};
use ballcast::{Cached, CompactMesh, Compound, Degenerates, Heightfield, Mesh, Node};
use fixed::types::I16F16;

#[path = "../embedded/src/arena.rs"]
mod arena;
#[path = "../embedded/src/forms.rs"]
mod forms;
#[path = "../embedded/src/lockstep.rs"]
mod lockstep;
#[path = "../embedded/src/walker.rs"]
mod walker;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (throws, steps) = (arena::THROWS, arena::STEPS_PER_THROW);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/data/arena.obj");
    let tris = ballcast_level::triangles::<I16F16>(&ballcast_level::load(path)?)?;
    let n = tris.len();
    let (mut nodes, mut prepared) = (vec![Node::default(); nodes_for(n)], vec![Mesh::filler(); n]);
    let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
    // Leaves of four: the smallest tree, which the compact mesh borrows.
    let (mesh, _) = Mesh::build(
        &tris,
        Degenerates::Skip.with_leaf_size(LeafSize::Four),
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    )?;
    let (vertices, indices) = ballcast::import::weld(&tris)?;
    let k = mesh.len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; k], vec![0u16; k], vec![0u8; k]);
    let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b)?;
    let c = arena::simulate::<I16F16, _>(&compact, throws, steps);
    println!("compact I16F16 {:016x}", c.hash);
    let heights = forms::heights();
    let mut cells = vec![0u8; (forms::CELLS * forms::CELLS) as usize];
    let field = Heightfield::build(forms::shape(), &heights, |_, _| false, &mut cells)?;
    let h = arena::simulate::<I16F16, _>(&field, throws, steps);
    println!("heightfield I16F16 {:016x}", h.hash);
    let b = arena::simulate::<I16F16, _>(&Compound::new(&compact, &field)?, throws, steps);
    println!("compound I16F16 {:016x}", b.hash);
    let (walked, grounded) = walker::walk::<I16F16, _>(&field);
    println!("character I16F16 {walked:016x}");
    let cached: Cached<_, I16F16, 16> = Cached::new(field);
    let (walked, _) = walker::walk::<I16F16, _>(&cached);
    println!("character cached I16F16 {walked:016x}");
    eprintln!(
        "compact: {} triangles, {} contacts, {} escapes; heightfield: {} triangles, {} contacts, {} escapes; compound: {} contacts, {} escapes",
        compact.len(),
        c.contacts,
        c.escapes,
        field.len(),
        h.contacts,
        h.escapes,
        b.contacts,
        b.escapes
    );
    eprintln!(
        "character: {} frames on the heightfield, grounded on {grounded}",
        walker::FRAMES
    );
    // The same run on the prepared mesh, for comparison: the compact form answers as it does.
    let m = arena::simulate::<I16F16, _>(&mesh, throws, steps);
    if m.hash != c.hash {
        return Err("the compact mesh's run differs from the prepared mesh's".into());
    }
    Ok(())
}
