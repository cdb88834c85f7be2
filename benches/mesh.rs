//! `Mesh` on a bumpy heightfield (1-unit cells, heights within ±0.65 from a fixed
//! sin/cos formula, front faces up) at 512 / 8 192 / 100 352 triangles, `f32` and `I16F16`:
//! the build (preparation, active edges and tree, into buffers allocated beforehand), short moves
//! and long casts; parry3d's `TriMesh` (build and ball shape cast) in the same groups as the peer.
//! Also the 256-triangle room of `benches/cast.rs` as a mesh next to its `Scene`.
//!
//! Run: `cargo bench --bench mesh -- --warm-up-time 1 --measurement-time 3`

use ballcast::bvh::nodes_for;
use ballcast::{Degenerates, Mesh, Node, Scalar, Scene, StandardTriangle, Sweep, Triangle};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixed::types::I16F16;
use std::hint::black_box;

mod inputs;
mod peer;

type P = [f64; 3];
/// Sweeps per iteration of a query benchmark.
const QUERIES: usize = 256;

/// The terrain height at grid point `(i, j)`: within ±0.65.
fn height(x: f64, z: f64) -> f64 {
    0.4 * (0.7 * x).sin() * (0.5 * z).cos() + 0.25 * (1.3 * x + 0.9 * z).sin()
}

/// `2 w²` triangles over `[-w/2, w/2]²`, front faces up.
fn heightfield(w: usize) -> Vec<[P; 3]> {
    let half = w as f64 / 2.0;
    let p = |i: usize, j: usize| {
        let (x, z) = (i as f64 - half, j as f64 - half);
        [x, height(x, z), z]
    };
    let mut out = Vec::with_capacity(2 * w * w);
    for i in 0..w {
        for j in 0..w {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            out.push([a, b, c]);
            out.push([a, c, d]);
        }
    }
    out
}

/// Short moves: radius 0.2–0.5, starting 0.1–0.3 above the ground, 0.5 forward and 0.5 down.
fn short_moves(w: usize, rng: &mut inputs::Rng) -> Vec<(P, P, f64)> {
    let half = w as f64 / 2.0 - 1.0;
    (0..QUERIES)
        .map(|_| {
            let r = rng.range(0.2, 0.5);
            let (x, z) = (rng.range(-half, half), rng.range(-half, half));
            let p0 = [x, height(x, z) + r + rng.range(0.1, 0.3), z];
            let a = rng.range(0.0, std::f64::consts::TAU);
            (p0, [x + 0.5 * a.cos(), p0[1] - 0.5, z + 0.5 * a.sin()], r)
        })
        .collect()
}

/// Long casts: radius 0.1–0.5, from 2–5 above the ground to 1 below it, across 0.5–1 terrain
/// widths horizontally.
fn long_casts(w: usize, rng: &mut inputs::Rng) -> Vec<(P, P, f64)> {
    let (width, half) = (w as f64, w as f64 / 2.0 - 0.5);
    let mut out = Vec::new();
    while out.len() < QUERIES {
        let (x0, z0) = (rng.range(-half, half), rng.range(-half, half));
        let (x1, z1) = (rng.range(-half, half), rng.range(-half, half));
        let dist = ((x1 - x0).powi(2) + (z1 - z0).powi(2)).sqrt();
        if dist < 0.5 * width || dist > width {
            continue;
        }
        let p0 = [x0, height(x0, z0) + rng.range(2.0, 5.0), z0];
        let p1 = [x1, height(x1, z1) - 1.0, z1];
        out.push((p0, p1, rng.range(0.1, 0.5)));
    }
    out
}

/// A mesh's buffers, allocated once.
struct Buffers<S: Scalar> {
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
        Mesh::build(
            src,
            Degenerates::Refuse,
            nodes,
            tris,
            order,
            &mut self.scratch,
        )
        .unwrap()
        .0
    }
}

fn to_sweeps<S: Scalar>(raw: &[(P, P, f64)]) -> Vec<Sweep<S>> {
    inputs::sweeps(raw)
}

fn ours<S: Scalar>(c: &mut Criterion, name: &str, w: usize) {
    let src: Vec<Triangle<S>> = heightfield(w).iter().map(|&t| inputs::tri(t)).collect();
    let n = src.len();
    let mut buffers = Buffers::<S>::new(n);
    let mut rng = inputs::Rng(0x4D45_5348 + w as u64);
    let short = to_sweeps::<S>(&short_moves(w, &mut rng));
    let long = to_sweeps::<S>(&long_casts(w, &mut rng));

    let mut g = c.benchmark_group(format!("mesh_build_{n}"));
    g.sample_size(10);
    g.bench_function(BenchmarkId::from_parameter(name), |b| {
        b.iter(|| black_box(buffers.build(black_box(&src))).len())
    });
    g.finish();
    let mesh = buffers.build(&src);
    for (what, sweeps) in [("short_move", &short), ("long_cast", &long)] {
        let mut g = c.benchmark_group(format!("mesh_{what}_{n}"));
        g.throughput(Throughput::Elements(QUERIES as u64));
        g.bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| hits(&mesh, sweeps))
        });
        g.finish();
    }
}

fn parry(c: &mut Criterion, w: usize) {
    use parry3d::math::Vector;
    use parry3d::shape::TriMesh;
    let tris = heightfield(w);
    let n = tris.len();
    let vertices: Vec<Vector> = tris.iter().flatten().map(|&a| peer::point(a)).collect();
    let indices: Vec<[u32; 3]> = (0..n as u32)
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    let mut g = c.benchmark_group(format!("mesh_build_{n}"));
    g.sample_size(10);
    g.bench_function(BenchmarkId::from_parameter("parry3d_TriMesh"), |b| {
        b.iter(|| TriMesh::new(vertices.clone(), indices.clone()).unwrap())
    });
    g.finish();
    let mesh = TriMesh::new(vertices.clone(), indices.clone()).unwrap();
    let mut rng = inputs::Rng(0x4D45_5348 + w as u64);
    let short = short_moves(w, &mut rng);
    let long = long_casts(w, &mut rng);
    for (what, raw) in [("short_move", &short), ("long_cast", &long)] {
        let sweeps = peer::sweeps(raw);
        let mut g = c.benchmark_group(format!("mesh_{what}_{n}"));
        g.throughput(Throughput::Elements(QUERIES as u64));
        g.bench_function(BenchmarkId::from_parameter("parry3d_TriMesh"), |b| {
            b.iter(|| peer::hits(&mesh, &sweeps))
        });
        g.finish();
    }
}

/// The room of `benches/cast.rs` (256 triangles, short moves) as a `Scene` and as a `Mesh`.
/// How many of the sweeps hit the geometry.
fn hits<S: Scalar, G: ballcast::Geometry<S>>(geometry: &G, sweeps: &[Sweep<S>]) -> usize {
    sweeps
        .iter()
        .filter(|s| black_box(geometry).cast(s).is_some())
        .count()
}

fn room(c: &mut Criterion) {
    let (tris, raw) = inputs::room(256);
    let src: Vec<Triangle<f32>> = tris.iter().map(|&t| inputs::tri(t)).collect();
    let mut scene: Scene<f32, 256> = Scene::new();
    for t in &src {
        scene.push(*t).unwrap();
    }
    let mut buffers = Buffers::<f32>::new(src.len());
    let mesh = buffers.build(&src);
    let sweeps = to_sweeps::<f32>(&raw);
    let mut g = c.benchmark_group("room_256");
    g.throughput(Throughput::Elements(sweeps.len() as u64));
    g.bench_function("scene_f32", |b| b.iter(|| hits(&scene, &sweeps)));
    g.bench_function("mesh_f32", |b| b.iter(|| hits(&mesh, &sweeps)));
    g.finish();
}

fn benches(c: &mut Criterion) {
    for w in [16, 64, 224] {
        ours::<f32>(c, "f32", w);
        ours::<I16F16>(c, "I16F16", w);
        parry(c, w);
    }
    room(c);
}

criterion_group!(mesh_benches, benches);
criterion_main!(mesh_benches);
