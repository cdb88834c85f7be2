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
mod terrain;

use terrain::{QUERIES, heightfield};

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

fn to_sweeps<S: Scalar>(raw: &[inputs::Path]) -> Vec<Sweep<S>> {
    inputs::sweeps(raw)
}

fn ours<S: Scalar>(c: &mut Criterion, name: &str, w: usize) {
    let src: Vec<Triangle<S>> = heightfield(w).iter().map(|&t| inputs::tri(t)).collect();
    let n = src.len();
    let mut buffers = Buffers::<S>::new(n);
    let (short, long) = terrain::queries(w);
    let (short, long) = (to_sweeps::<S>(&short), to_sweeps::<S>(&long));

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
    use parry3d::shape::{TriMesh, TriMeshFlags};
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
    // The same work as `Mesh::build`: shared vertices found and internal edges fixed (the
    // pseudo-normals that keep balls from catching on them), as ballcast's active edges do.
    let fix = TriMeshFlags::FIX_INTERNAL_EDGES;
    g.bench_function(
        BenchmarkId::from_parameter("parry3d_TriMesh_fix_internal_edges"),
        |b| b.iter(|| TriMesh::with_flags(vertices.clone(), indices.clone(), fix).unwrap()),
    );
    g.finish();
    let mesh = TriMesh::new(vertices.clone(), indices.clone()).unwrap();
    let (short, long) = terrain::queries(w);
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
