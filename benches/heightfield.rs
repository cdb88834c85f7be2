//! `Heightfield` against the prepared `Mesh` of the same triangles: the terrain of
//! `benches/mesh.rs` with its heights in steps of 1/1024 (so both hold exactly the same
//! triangles), at 512 / 8 192 / 100 352 triangles, `f32` and `I16F16`, short moves and long
//! casts in the same groups; the bytes per triangle of each form on stderr.
//!
//! Run: `cargo bench --bench heightfield -- --warm-up-time 1 --measurement-time 3`

use ballcast::bvh::nodes_for;
use ballcast::heightfield::HOLE;
use ballcast::{
    Degenerates, Geometry, Heightfield, Mesh, Node, Scalar, StandardTriangle, Sweep, Triangle,
};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixed::types::I16F16;
use std::hint::black_box;

mod inputs;
mod terrain;

use terrain::{QUERIES, height, long_casts, short_moves};

/// Heights in steps of this many units.
const UNIT: f64 = 1.0 / 1024.0;

fn hits<S: Scalar, G: Geometry<S>>(geometry: &G, sweeps: &[Sweep<S>]) -> usize {
    sweeps
        .iter()
        .filter(|s| black_box(geometry).cast(s).is_some())
        .count()
}

fn compare<S: Scalar>(c: &mut Criterion, name: &str, w: usize) {
    let half = w as f64 / 2.0;
    let heights: Vec<i16> = (0..(w + 1) * (w + 1))
        .map(|v| {
            let (x, z) = ((v % (w + 1)) as f64 - half, (v / (w + 1)) as f64 - half);
            (height(x, z) / UNIT).round() as i16
        })
        .collect();
    let mut cells = vec![0u8; w * w];
    let origin = inputs::v::<S>([-half, 0.0, -half]);
    let (one, unit) = (S::ONE, S::from_f64(UNIT));
    let (cols, rows) = (w as u32, w as u32);
    let hf = Heightfield::build(
        origin,
        one,
        unit,
        cols,
        rows,
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let src: Vec<Triangle<S>> = (0..hf.len()).filter_map(|t| hf.triangle(t)).collect();
    let n = src.len();
    assert!(hf.cells().iter().all(|&b| b & HOLE == 0));
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
    let mesh_bytes =
        size_of_val(mesh.nodes()) + n * (size_of::<StandardTriangle<S>>() + size_of::<u32>());
    let field_bytes = size_of_val(hf.heights()) + hf.cells().len();
    eprintln!(
        "{name} {n} triangles: heightfield {:.2} bytes per triangle, mesh {:.1}",
        field_bytes as f64 / n as f64,
        mesh_bytes as f64 / n as f64
    );
    let mut rng = inputs::Rng(0x4D45_5348 + w as u64);
    let short = inputs::sweeps::<S>(&short_moves(w, &mut rng));
    let long = inputs::sweeps::<S>(&long_casts(w, &mut rng));
    for (what, sweeps) in [("short_move", &short), ("long_cast", &long)] {
        assert_eq!(hits(&hf, sweeps), hits(&mesh, sweeps));
        let mut g = c.benchmark_group(format!("terrain_{what}_{n}"));
        g.throughput(Throughput::Elements(QUERIES as u64));
        g.bench_function(BenchmarkId::new("heightfield", name), |b| {
            b.iter(|| hits(&hf, sweeps))
        });
        g.bench_function(BenchmarkId::new("mesh", name), |b| {
            b.iter(|| hits(&mesh, sweeps))
        });
        g.finish();
    }
}

fn benches(c: &mut Criterion) {
    for w in [16, 64, 224] {
        compare::<f32>(c, "f32", w);
        compare::<I16F16>(c, "I16F16", w);
    }
}

criterion_group!(heightfield_benches, benches);
criterion_main!(heightfield_benches);
