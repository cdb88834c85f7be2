//! The measured loops of a mesh's instruction counts under callgrind: the build of the terrain
//! of `benches/mesh.rs` and its short moves and long casts, per scalar.
//!
//! Each loop is an `#[inline(never)]`, unmangled function `cm_<what>_<scalar>`, so callgrind's
//! `--toggle-collect` counts it and nothing of the set-up:
//!
//! ```sh
//! cargo build --release --example callgrind_mesh
//! valgrind --tool=callgrind --collect-atstart=no --toggle-collect=cm_short_f32 \
//!     target/release/examples/callgrind_mesh short f32 224 4
//! ```
//!
//! Run: `callgrind_mesh <build|short|long> <f32|I16F16> <width> <repeats>`: the terrain of
//! `2 width²` triangles; `build` builds it `repeats` times, `short` and `long` run the 256
//! sweeps `repeats` times. Prints the calls made and the hits found.

use ballcast::bvh::nodes_for;
use ballcast::{Degenerates, Mesh, Node, Scalar, StandardTriangle, Sweep, Triangle};
use fixed::types::I16F16;
use std::hint::black_box;

#[path = "../benches/inputs/mod.rs"]
mod inputs;
#[path = "../benches/terrain/mod.rs"]
mod terrain;

/// A mesh's buffers.
pub struct Buffers<S: Scalar> {
    nodes: Vec<Node>,
    tris: Vec<StandardTriangle<S>>,
    order: Vec<u32>,
    scratch: Vec<u64>,
}

impl<S: Scalar> Buffers<S> {
    fn new(n: usize) -> Self {
        Self {
            nodes: vec![Node::default(); nodes_for(n)],
            tris: vec![Mesh::<S>::filler(); n],
            order: vec![0; n],
            scratch: vec![0; 6 * n],
        }
    }
    fn build(&mut self, src: &[Triangle<S>]) -> Mesh<'_, S> {
        let (nodes, tris, order) = (&mut self.nodes, &mut self.tris, &mut self.order);
        let scratch = &mut self.scratch;
        Mesh::build(src, Degenerates::Refuse, nodes, tris, order, scratch)
            .expect("the terrain builds")
            .0
    }
}

macro_rules! loops {
    ($($s:ty => $build:ident, $short:ident, $long:ident, $run:ident);*) => {$(
        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $build(b: &mut Buffers<$s>, src: &[Triangle<$s>], n: usize) -> usize {
            (0..n).map(|_| black_box(b.build(black_box(src))).len()).sum()
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $short(mesh: &Mesh<'_, $s>, sw: &[Sweep<$s>], n: usize) -> usize {
            queries(mesh, sw, n)
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $long(mesh: &Mesh<'_, $s>, sw: &[Sweep<$s>], n: usize) -> usize {
            // Not the same body as the short moves', so the two are never merged into one.
            queries(mesh, sw, n) + black_box(0)
        }

        #[allow(non_snake_case)]
        fn $run(what: &str, w: usize, n: usize) -> (usize, usize) {
            let src: Vec<Triangle<$s>> =
                terrain::heightfield(w).iter().map(|&t| inputs::tri(t)).collect();
            let mut b = Buffers::<$s>::new(src.len());
            if what == "build" {
                return (n, $build(&mut b, &src, n));
            }
            let (short, long) = terrain::queries(w);
            let mesh = b.build(&src);
            match what {
                "short" => (n * short.len(), $short(&mesh, &inputs::sweeps(&short), n)),
                "long" => (n * long.len(), $long(&mesh, &inputs::sweeps(&long), n)),
                _ => panic!("unknown loop {what}"),
            }
        }
    )*};
}

loops!(
    f32 => cm_build_f32, cm_short_f32, cm_long_f32, run_f32;
    I16F16 => cm_build_I16F16, cm_short_I16F16, cm_long_I16F16, run_I16F16
);

/// How many of `n` rounds of the sweeps hit the mesh.
fn queries<S: Scalar>(mesh: &Mesh<'_, S>, sw: &[Sweep<S>], n: usize) -> usize {
    let mut hits = 0;
    for _ in 0..n {
        for s in sw {
            hits += black_box(mesh).cast(black_box(s)).is_some() as usize;
        }
    }
    hits
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let arg = |i: usize| args.get(i).map(String::as_str).unwrap_or("");
    let (w, n) = (arg(3).parse().unwrap_or(224), arg(4).parse().unwrap_or(1));
    let (calls, hits) = match arg(2) {
        "f32" => run_f32(arg(1), w, n),
        "I16F16" => run_I16F16(arg(1), w, n),
        s => panic!("unknown scalar {s:?}"),
    };
    println!("calls {calls} hits {hits}");
}
