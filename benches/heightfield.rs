//! `Heightfield` and `CompactMesh` against the prepared `Mesh` of the same triangles: the terrain of
//! `benches/mesh.rs` with its heights in steps of 1/1024 (so both hold exactly the same
//! triangles), at 512 / 8 192 / 100 352 triangles, `f32` and `I16F16`, short moves and long
//! casts in the same groups, and a character's walk of 256 frames, where the heightfield and
//! the compact mesh run with a `TriangleCache` of 32 slots beside them too; the bytes per
//! triangle of each form on stderr.
//!
//! Run: `cargo bench --bench heightfield -- --warm-up-time 1 --measurement-time 3`

use ballcast::{
    Cacheable, Cached, CompactMesh, Geometry, Mesh, MeshIndex, Scalar, StandardTriangle, Sweep,
};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixed::types::I16F16;
use std::hint::black_box;

mod inputs;
mod terrain;

use terrain::{Level, QUERIES, long_casts, short_moves};

fn hits<S: Scalar, G: Geometry<S>>(geometry: &G, sweeps: &[Sweep<S>]) -> usize {
    sweeps
        .iter()
        .filter(|s| black_box(geometry).cast(s).is_some())
        .count()
}

fn compare<S: Scalar>(c: &mut Criterion, name: &str, w: usize) {
    let level = Level::<S>::new(w);
    let hf = level.heightfield();
    let n = level.triangles.len();
    let mesh = level.mesh();
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
    // The compact mesh: the grid's vertices shared, u16 indices where vertices and triangles fit.
    if level.vertices.len().max(level.triangles.len()) <= u16::MAX as usize + 1 {
        groups::<S, u16>(c, name, &level, &mesh, [&short, &long]);
    } else {
        groups::<S, u32>(c, name, &level, &mesh, [&short, &long]);
    }
}

/// The three forms side by side on both kinds of sweep.
fn groups<S: Scalar, I: MeshIndex + Default>(
    c: &mut Criterion,
    name: &str,
    level: &Level<S>,
    mesh: &Mesh<'_, S>,
    [short, long]: [&[Sweep<S>]; 2],
) {
    let (hf, n) = (level.heightfield(), mesh.len());
    let (vertices, indices) = (&level.vertices, &level.indices);
    let (mut t, mut o, mut b) = (
        vec![[I::default(); 3]; n],
        vec![I::default(); n],
        vec![0u8; n],
    );
    // The compact mesh borrows the tree with leaves of four, the smallest.
    let small = level.small_tree_mesh();
    let compact = CompactMesh::compact(&small, vertices, indices, &mut t, &mut o, &mut b).unwrap();
    let bytes = size_of_val(small.nodes())
        + size_of_val(vertices.as_slice())
        + n * (4 * size_of::<I>() + 1);
    eprintln!(
        "{name} {n} triangles: compact mesh {:.1} bytes per triangle ({}-byte indices)",
        bytes as f64 / n as f64,
        size_of::<I>()
    );
    for (what, sweeps) in [("short_move", short), ("long_cast", long)] {
        assert_eq!(hits(&hf, sweeps), hits(mesh, sweeps));
        assert_eq!(hits(&compact, sweeps), hits(mesh, sweeps));
        let mut g = c.benchmark_group(format!("terrain_{what}_{n}"));
        g.throughput(Throughput::Elements(QUERIES as u64));
        g.bench_function(BenchmarkId::new("heightfield", name), |b| {
            b.iter(|| hits(&hf, sweeps))
        });
        g.bench_function(BenchmarkId::new("mesh", name), |b| {
            b.iter(|| hits(mesh, sweeps))
        });
        g.bench_function(BenchmarkId::new("compact", name), |b| {
            b.iter(|| hits(&compact, sweeps))
        });
        g.finish();
    }
    // The character loop comes back to the same triangles: with a cache, each is prepared
    // once while the ball stays near it. Each walk lends the cache anew (emptied).
    let walked = terrain::walk(mesh);
    assert_eq!(terrain::walk(&hf), walked);
    assert_eq!(terrain::walk(&compact), walked);
    let mut g = c.benchmark_group(format!("terrain_character_{n}"));
    g.throughput(Throughput::Elements(terrain::FRAMES as u64));
    g.bench_function(BenchmarkId::new("mesh", name), |b| {
        b.iter(|| terrain::walk(mesh))
    });
    g.bench_function(BenchmarkId::new("heightfield", name), |b| {
        b.iter(|| terrain::walk(&hf))
    });
    g.bench_function(BenchmarkId::new("heightfield_cached", name), |b| {
        b.iter(|| cached_walk(hf, walked))
    });
    g.bench_function(BenchmarkId::new("compact", name), |b| {
        b.iter(|| terrain::walk(&compact))
    });
    g.bench_function(BenchmarkId::new("compact_cached", name), |b| {
        b.iter(|| cached_walk(compact, walked))
    });
    g.finish();
}

/// The walk on `geometry` with a cache of 32 slots beside it, checked against `walked`.
fn cached_walk<S: Scalar, G: Cacheable<S>>(geometry: G, walked: (ballcast::Vec3<S>, usize)) {
    let level: Cached<G, S, 32> = Cached::new(geometry);
    assert_eq!(terrain::walk(&level), walked);
}

fn benches(c: &mut Criterion) {
    for w in [16, 64, 224] {
        compare::<f32>(c, "f32", w);
        compare::<I16F16>(c, "I16F16", w);
    }
}

criterion_group!(heightfield_benches, benches);
criterion_main!(heightfield_benches);
