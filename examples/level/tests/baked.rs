//! The statics the bake writes (`build.rs` bakes the firmware's levels into `OUT_DIR`, as the
//! firmware's build script does) are exactly the mesh `Mesh::build` makes of the loaded level
//! at run time: nodes, prepared triangles with their active edges, order and grid, bit for bit.

use ballcast::{Degenerates, Mesh, Node, Scalar, bvh::nodes_for};
use ballcast_level::{Emit, load, triangles};

mod ramp_f32 {
    include!(concat!(env!("OUT_DIR"), "/ramp_f32.rs"));
}
mod ramp_f64 {
    include!(concat!(env!("OUT_DIR"), "/ramp_f64.rs"));
}
mod ramp_i16f16 {
    include!(concat!(env!("OUT_DIR"), "/ramp_i16f16.rs"));
}
mod ramp_i32f32 {
    include!(concat!(env!("OUT_DIR"), "/ramp_i32f32.rs"));
}
mod arena_i16f16 {
    include!(concat!(env!("OUT_DIR"), "/arena_i16f16.rs"));
}

fn equals_run_time_build<S: Scalar + Emit>(
    baked: &Mesh<'static, S>,
    file: &str,
    triangles_in: usize,
) {
    let level = load(format!("{}/../data/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let sources = triangles::<S>(&level).unwrap();
    let n = sources.len();
    assert_eq!((n, baked.len()), (triangles_in, triangles_in));
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut prepared = vec![Mesh::<S>::filler(); n];
    let mut order = vec![0u32; n];
    let mut scratch = vec![0u64; 6 * n];
    let verdict = baked.verify(
        &sources,
        Degenerates::Skip,
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    );
    assert_eq!(verdict, Ok(()));
}

#[test]
fn baked_ramp_equals_run_time_build_in_every_scalar() {
    equals_run_time_build(&ramp_f32::MESH, "ramp.obj", 96);
    equals_run_time_build(&ramp_f64::MESH, "ramp.obj", 96);
    equals_run_time_build(&ramp_i16f16::MESH, "ramp.obj", 96);
    equals_run_time_build(&ramp_i32f32::MESH, "ramp.obj", 96);
}

#[test]
fn baked_arena_equals_run_time_build() {
    equals_run_time_build(&arena_i16f16::MESH, "arena.obj", 2168);
}
