//! Per scalar: standardization, the face test and the full `cast` against one precomputed
//! triangle on two mixes of sweeps (`single_triangle`: down through the triangle, most misses
//! close to an edge or vertex; `near_triangle`: a scene's short moves around it), and scene
//! casts over 12 and 256 triangles; parry3d's `cast_shapes(Ball, Triangle)` on the same
//! single-triangle sweeps, in the same groups, so ratios come from one run.
//!
//! Run: `cargo bench --bench cast` (`cargo bench --bench cast -- triangle/` for the two mixes)

use ballcast::{Scalar, Scene, StandardTriangle};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixed::types::{I16F16, I32F32};
use std::hint::black_box;

mod inputs;
mod peer;

use inputs::*;

/// A generator of one mix of sweeps.
type Mix = fn() -> Vec<Path>;

/// The two single-triangle mixes: the adversarial one (sweeps down through the triangle, most
/// of the misses close to an edge or vertex) and the one a scene produces (`near_sweeps`).
const MIXES: [(&str, Mix); 2] = [
    ("single_triangle", single_sweeps),
    ("near_triangle", near_sweeps),
];

fn single<S: Scalar>(c: &mut Criterion, name: &str) {
    let st = StandardTriangle::new(&tri::<S>(TRIANGLE)).unwrap();
    for (group, mix) in MIXES {
        let sw = sweeps::<S>(&mix());
        let mut g = c.benchmark_group(group);
        g.throughput(Throughput::Elements(SWEEPS as u64));
        g.bench_function(BenchmarkId::new("face_collision", name), |b| {
            b.iter(|| {
                sw.iter()
                    .filter(|s| black_box(&st).face_collision(s).is_some())
                    .count()
            })
        });
        g.bench_function(BenchmarkId::new("cast", name), |b| {
            b.iter(|| {
                sw.iter()
                    .filter(|s| black_box(&st).cast(s).is_some())
                    .count()
            })
        });
        g.finish();
    }
    let t = tri::<S>(TRIANGLE);
    c.bench_function(&format!("standardize/{name}"), |b| {
        b.iter(|| StandardTriangle::new(black_box(&t)))
    });
}

fn parry(c: &mut Criterion) {
    let p = peer::point;
    let t = parry3d::shape::Triangle::new(p(TRIANGLE[0]), p(TRIANGLE[1]), p(TRIANGLE[2]));
    for (group, mix) in MIXES {
        let sw = peer::sweeps(&mix());
        let mut g = c.benchmark_group(group);
        g.throughput(Throughput::Elements(SWEEPS as u64));
        g.bench_function(BenchmarkId::new("parry3d_cast_shapes", "f32"), |b| {
            b.iter(|| peer::hits(&t, &sw))
        });
        g.finish();
    }
}

fn scene<S: Scalar, const N: usize>(c: &mut Criterion, name: &str) {
    let (tris, raw) = room(N);
    let mut scene: Scene<S, N> = Scene::new();
    for t in &tris {
        scene.push(tri(*t)).unwrap();
    }
    let sw = sweeps::<S>(&raw);
    let mut g = c.benchmark_group(format!("scene_cast_{}", scene.len()));
    g.throughput(Throughput::Elements(SWEEPS as u64));
    g.bench_function(BenchmarkId::from_parameter(name), |b| {
        b.iter(|| {
            sw.iter()
                .filter(|s| black_box(&scene).cast(s).is_some())
                .count()
        })
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    single::<f32>(c, "f32");
    single::<f64>(c, "f64");
    single::<I32F32>(c, "I32F32");
    single::<I16F16>(c, "I16F16");
    parry(c);
    scene::<f32, 16>(c, "f32");
    scene::<f32, 256>(c, "f32");
    scene::<f64, 256>(c, "f64");
    scene::<I32F32, 256>(c, "I32F32");
    scene::<I16F16, 256>(c, "I16F16");
}

criterion_group!(cast, benches);
criterion_main!(cast);
