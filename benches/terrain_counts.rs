//! Instructions per query of `Heightfield`, `CompactMesh` and the prepared `Mesh` of the same
//! triangles, for callgrind: each form's sweeps run in a function of their own.
//!
//! Run: `cargo build --release --example terrain_counts -p ballcast-benches && valgrind
//! --tool=callgrind target/release/examples/terrain_counts W [f32|i16f16]`, then
//! `callgrind_annotate --inclusive=yes --threshold=100` (`short_*` and `long_*`, each run once,
//! 256 sweeps each). W: 16, 64 or 224 cells a side.

use ballcast::{CompactMesh, Geometry, Mesh, MeshIndex, Scalar, Sweep};
use fixed::types::I16F16;
use std::hint::black_box;

mod inputs;
mod terrain;

/// One function per form and kind of sweep, so callgrind counts each apart.
macro_rules! queries {
    ($($name:ident, $tag:literal),*) => {$(
        #[inline(never)]
        fn $name<S: Scalar, G: Geometry<S>>(g: &G, sweeps: &[Sweep<S>]) -> usize {
            // A distinct constant each, so that the compiler does not merge identical bodies.
            let hits = sweeps.iter().filter(|s| black_box(g).cast(s).is_some()).count();
            hits + black_box($tag) - $tag
        }
    )*};
}
queries!(
    short_heightfield,
    1,
    long_heightfield,
    2,
    short_mesh,
    3,
    long_mesh,
    4,
    short_compact,
    5,
    long_compact,
    6
);

fn run<S: Scalar>(w: usize) {
    let level = terrain::Level::<S>::new(w);
    let hf = level.heightfield();
    let mesh = level.mesh();
    let mut rng = inputs::Rng(0x4D45_5348 + w as u64);
    let short = inputs::sweeps::<S>(&terrain::short_moves(w, &mut rng));
    let long = inputs::sweeps::<S>(&terrain::long_casts(w, &mut rng));
    // Each form's sweeps run once, so that each function's inclusive count is one pass.
    let hits = (short_mesh(&mesh, &short), long_mesh(&mesh, &long));
    assert_eq!(short_heightfield(&hf, &short), hits.0);
    assert_eq!(long_heightfield(&hf, &long), hits.1);
    // u16 indices where the vertices and triangles fit.
    if level.vertices.len().max(level.triangles.len()) <= u16::MAX as usize + 1 {
        compact::<S, u16>(&level, &mesh, (&short, &long), hits);
    } else {
        compact::<S, u32>(&level, &mesh, (&short, &long), hits);
    }
}

fn compact<S: Scalar, I: MeshIndex + Default>(
    level: &terrain::Level<S>,
    mesh: &Mesh<'_, S>,
    (short, long): (&[Sweep<S>], &[Sweep<S>]),
    hits: (usize, usize),
) {
    let n = mesh.len();
    let (mut t, mut o, mut b) = (
        vec![[I::default(); 3]; n],
        vec![I::default(); n],
        vec![0u8; n],
    );
    let (v, i) = (&level.vertices, &level.indices);
    // The compact mesh borrows the tree with leaves of four, the smallest.
    let small = level.small_tree_mesh();
    let compact = CompactMesh::compact(&small, v, i, &mut t, &mut o, &mut b).unwrap();
    assert_eq!(short_compact(&compact, short), hits.0);
    assert_eq!(long_compact(&compact, long), hits.1);
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let w = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(64);
    match args.get(2).map(String::as_str) {
        Some("i16f16") => run::<I16F16>(w),
        _ => run::<f32>(w),
    }
}
