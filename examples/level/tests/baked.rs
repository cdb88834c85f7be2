//! The statics the bake writes (`build.rs` bakes the firmware's levels into `OUT_DIR`, as the
//! firmware's build script does) are exactly the mesh `Mesh::build` makes of the loaded level
//! at run time: nodes, prepared triangles with their active edges, order and grid, bit for bit;
//! likewise the compact meshes and the heightfields.

use ballcast::bvh::{LeafSize, nodes_for};
use ballcast::heightfield::HOLE;
use ballcast::import::weld;
use ballcast::{CompactMesh, Degenerates, Heightfield, Mesh, MeshError, MeshIndex, Node, Scalar};
use ballcast_level::{Emit, Placement, load, load_heightmap, triangles};

mod ramp_f32 {
    include!(concat!(env!("OUT_DIR"), "/ramp_f32.rs"));
}
mod ramp_f32_four {
    include!(concat!(env!("OUT_DIR"), "/ramp_f32_four.rs"));
}
mod ramp_f64 {
    include!(concat!(env!("OUT_DIR"), "/ramp_f64.rs"));
}
// Each fixed-point module has a `fixed` of its own that is not the crate: the baked source
// must name its types through `ballcast::fixed`, so that a firmware without a `fixed`
// dependency of its own compiles it.
mod ramp_i16f16 {
    mod fixed {}
    include!(concat!(env!("OUT_DIR"), "/ramp_i16f16.rs"));
}
mod ramp_i32f32 {
    mod fixed {}
    include!(concat!(env!("OUT_DIR"), "/ramp_i32f32.rs"));
}
mod arena_i16f16 {
    mod fixed {}
    include!(concat!(env!("OUT_DIR"), "/arena_i16f16.rs"));
}
mod ramp_compact_f32 {
    include!(concat!(env!("OUT_DIR"), "/ramp_compact_f32.rs"));
}
mod arena_compact_i16f16 {
    mod fixed {}
    include!(concat!(env!("OUT_DIR"), "/arena_compact_i16f16.rs"));
}
mod hills_i16f16 {
    mod fixed {}
    include!(concat!(env!("OUT_DIR"), "/hills_i16f16.rs"));
}
mod hills_f32 {
    include!(concat!(env!("OUT_DIR"), "/hills_f32.rs"));
}

fn equals_run_time_build<S: Scalar + Emit>(
    baked: &Mesh<'static, S>,
    file: &str,
    triangles_in: usize,
) {
    equals_run_time_build_with(baked, file, triangles_in, LeafSize::Two);
}

/// The statics baked with leaves of `leaf_size` are the mesh built with them at run time (and
/// not the one built with the other size).
fn equals_run_time_build_with<S: Scalar + Emit>(
    baked: &Mesh<'static, S>,
    file: &str,
    triangles_in: usize,
    leaf_size: LeafSize,
) {
    let level = load(format!("{}/../data/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let sources = triangles::<S>(&level).unwrap();
    let n = sources.len();
    assert_eq!((n, baked.len()), (triangles_in, triangles_in));
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut prepared = vec![Mesh::<S>::filler(); n];
    let mut order = vec![0u32; n];
    let mut scratch = vec![0u64; 6 * n];
    let mut verify = |leaves| {
        baked.verify_sided(
            &sources,
            |i| level.is_two_sided(i),
            Degenerates::Skip.with_leaf_size(leaves),
            &mut nodes,
            &mut prepared,
            &mut order,
            &mut scratch,
        )
    };
    assert_eq!(verify(leaf_size), Ok(()));
    let other = match leaf_size {
        LeafSize::Two => LeafSize::Four,
        LeafSize::Four => LeafSize::Two,
    };
    assert!(matches!(verify(other), Err(MeshError::Mismatch { .. })));
}

#[test]
fn baked_ramp_equals_run_time_build_in_every_scalar() {
    equals_run_time_build(&ramp_f32::MESH, "ramp.obj", 96);
    equals_run_time_build(&ramp_f64::MESH, "ramp.obj", 96);
    equals_run_time_build(&ramp_i16f16::MESH, "ramp.obj", 96);
    equals_run_time_build(&ramp_i32f32::MESH, "ramp.obj", 96);
    equals_run_time_build_with(&ramp_f32_four::MESH, "ramp.obj", 96, LeafSize::Four);
}

#[test]
fn baked_arena_equals_run_time_build() {
    equals_run_time_build(&arena_i16f16::MESH, "arena.obj", 2168);
}

/// The compact statics are [`CompactMesh::compact`] of the mesh built at run time with leaves of
/// four over the level's welded vertices: tree, vertices, indices, order and bytes.
fn compact_equals_run_time_build<S: Scalar + Emit, I: MeshIndex>(
    baked: &CompactMesh<'static, S, I>,
    file: &str,
) {
    let level = load(format!("{}/../data/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let sources = triangles::<S>(&level).unwrap();
    let n = sources.len();
    let (vertices, indices) = weld(&sources).unwrap();
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut prepared = vec![Mesh::<S>::filler(); n];
    let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
    let four = Degenerates::Skip.with_leaf_size(LeafSize::Four);
    let build = Mesh::build(
        &sources,
        four,
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    );
    let (mesh, _) = build.unwrap();
    let (mut t, mut o, mut b) = (
        vec![[I::default(); 3]; n],
        vec![I::default(); n],
        vec![0; n],
    );
    let built = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    assert_eq!(baked.len(), n);
    assert_eq!(*baked, built);
}

#[test]
fn baked_compact_meshes_equal_run_time_builds() {
    compact_equals_run_time_build(&ramp_compact_f32::MESH, "ramp.obj");
    compact_equals_run_time_build(&arena_compact_i16f16::MESH, "arena.obj");
}

/// The heightfield statics are [`Heightfield::build`] of the loaded heightmap, placed as
/// `build.rs` places it; the hole pixel's cells are holes.
fn heightfield_equals_run_time_build<S: Scalar + Emit>(baked: &Heightfield<'static, S>) {
    let map = load_heightmap(format!("{}/../data/hills.png", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let placement = Placement {
        origin: [-8.0, -1.0, -8.0],
        spacing: 0.5,
        height: 4.0,
    };
    let mut cells = vec![0u8; 32 * 32];
    let hole = |i: u32, k: u32| map.holes[k as usize * 32 + i as usize];
    let (shape, heights) = map.grid::<S>(&placement).unwrap();
    let built = Heightfield::build(shape, &heights, hole, &mut cells);
    assert_eq!(Ok(*baked), built);
    // Four transparent pixels cut the nine cells around them.
    let holes = baked.cells().iter().filter(|&&c| c & HOLE != 0).count();
    assert_eq!((baked.len(), holes), (2 * 32 * 32, 9));
}

#[test]
fn baked_heightfields_equal_run_time_builds() {
    heightfield_equals_run_time_build(&hills_i16f16::HEIGHTFIELD);
    heightfield_equals_run_time_build(&hills_f32::HEIGHTFIELD);
}

/// The source's header names the file it came from, quoted: a path holding a line break (any
/// byte is allowed in a file name) cannot end the comment and inject code.
#[test]
fn a_path_cannot_inject_code_into_the_baked_source() {
    let mut level =
        load(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/quads.obj"))
            .unwrap();
    level.path = "x\npub static INJECTED: u8 = 1; .obj".into();
    let source = ballcast_level::bake::<f32>(&level).unwrap().source;
    let header = source.lines().next().unwrap();
    assert!(
        header.starts_with("// Generated by ballcast-level from \"x\\npub static"),
        "{header}"
    );
    assert!(!source.lines().any(|l| l.starts_with("pub static INJECTED")));
}
