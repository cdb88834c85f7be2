//! Instructions per query of `Heightfield` and of the prepared `Mesh` of the same triangles, for
//! callgrind: each form's sweeps run in a function of their own.
//!
//! Run: `cargo build --release --example terrain_counts -p ballcast-benches && valgrind
//! --tool=callgrind target/release/examples/terrain_counts W [f32|i16f16]`, then `callgrind_annotate
//! --inclusive=yes` (`short_*` and `long_*`, 256 sweeps each). W: 16, 64 or 224 cells a side.

use ballcast::bvh::nodes_for;
use ballcast::{Degenerates, Heightfield, Mesh, Node, Scalar, Sweep, Triangle};
use fixed::types::I16F16;
use std::hint::black_box;

mod inputs;
mod terrain;

/// One function per form and kind of sweep, so callgrind counts each apart.
macro_rules! queries {
    ($($name:ident: $form:ident, $tag:literal),*) => {$(
        #[inline(never)]
        fn $name<S: Scalar>(g: &$form<'_, S>, sweeps: &[Sweep<S>]) -> usize {
            // A distinct constant each, so that the compiler does not merge identical bodies.
            let hits = sweeps.iter().filter(|s| black_box(g).cast(s).is_some()).count();
            hits + black_box($tag) - $tag
        }
    )*};
}
queries!(short_heightfield: Heightfield, 1, long_heightfield: Heightfield, 2, short_mesh: Mesh, 3,
    long_mesh: Mesh, 4);

fn run<S: Scalar>(w: usize) {
    let half = w as f64 / 2.0;
    let heights: Vec<i16> = (0..(w + 1) * (w + 1))
        .map(|v| {
            let (x, z) = ((v % (w + 1)) as f64 - half, (v / (w + 1)) as f64 - half);
            (terrain::height(x, z) * 1024.0).round() as i16
        })
        .collect();
    let mut cells = vec![0u8; w * w];
    let origin = inputs::v::<S>([-half, 0.0, -half]);
    let unit = S::from_f64(1.0 / 1024.0);
    let (c, r) = (w as u32, w as u32);
    let hf = Heightfield::build(
        origin,
        S::ONE,
        unit,
        c,
        r,
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let src: Vec<Triangle<S>> = (0..hf.len()).filter_map(|t| hf.triangle(t)).collect();
    let n = src.len();
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut tris = vec![Mesh::<S>::filler(); n];
    let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
    let (mesh, _) = Mesh::build(
        &src,
        Degenerates::Refuse,
        &mut nodes,
        &mut tris,
        &mut order,
        &mut scratch,
    )
    .unwrap();
    let mut rng = inputs::Rng(0x4D45_5348 + w as u64);
    let short = inputs::sweeps::<S>(&terrain::short_moves(w, &mut rng));
    let long = inputs::sweeps::<S>(&terrain::long_casts(w, &mut rng));
    assert_eq!(short_heightfield(&hf, &short), short_mesh(&mesh, &short));
    assert_eq!(long_heightfield(&hf, &long), long_mesh(&mesh, &long));
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let w = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(64);
    match args.get(2).map(String::as_str) {
        Some("i16f16") => run::<I16F16>(w),
        _ => run::<f32>(w),
    }
}
