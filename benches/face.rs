//! The face test with a precomputed frame, per scalar, over a fixed set of sweeps (about half of
//! them hits), plus standardization of a triangle.
//!
//! Run: `cargo bench --bench face`

use ballcast::{Scalar, StandardTriangle, Sweep, Triangle, Vec3};
use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixed::types::{I16F16, I32F32};
use std::hint::black_box;

const SWEEPS: usize = 64;

/// Deterministic sweeps from above the triangle's plane towards or through it (xorshift, fixed seed).
fn sweeps_f64() -> Vec<([f64; 3], [f64; 3], f64)> {
    let mut s = 0x9E37_79B9_7F4A_7C15_u64;
    let mut next = move |lo: f64, hi: f64| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        lo + (hi - lo) * (s >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..SWEEPS)
        .map(|_| {
            let p0 = [next(-2.0, 8.0), next(1.0, 6.0), next(-2.0, 8.0)];
            let p1 = [next(-2.0, 8.0), next(-4.0, 1.0), next(-2.0, 8.0)];
            (p0, p1, next(0.1, 1.0))
        })
        .collect()
}

fn triangle<S: Scalar>() -> Triangle<S> {
    let v = |x: f64, y: f64, z: f64| Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z));
    Triangle::new(v(0.3, 0.2, 0.1), v(1.0, 0.4, 6.5), v(7.0, -0.3, 0.5))
}

fn bench_scalar<S: Scalar>(c: &mut Criterion, name: &str) {
    let v = |p: [f64; 3]| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
    let tri = StandardTriangle::new(&triangle::<S>()).unwrap();
    let sweeps: Vec<Sweep<S>> = sweeps_f64()
        .into_iter()
        .map(|(a, b, r)| Sweep::new(v(a), v(b), S::from_f64(r)).unwrap())
        .collect();
    let mut g = c.benchmark_group("face_collision");
    g.throughput(criterion::Throughput::Elements(SWEEPS as u64));
    g.bench_function(BenchmarkId::from_parameter(name), |b| {
        b.iter(|| {
            let mut hits = 0u32;
            for s in &sweeps {
                hits += black_box(&tri).face_collision(black_box(s)).is_some() as u32;
            }
            hits
        })
    });
    g.finish();
    let t = triangle::<S>();
    c.benchmark_group("standardize")
        .bench_function(BenchmarkId::from_parameter(name), |b| {
            b.iter(|| StandardTriangle::new(black_box(&t)))
        });
}

fn benches(c: &mut Criterion) {
    bench_scalar::<f32>(c, "f32");
    bench_scalar::<f64>(c, "f64");
    bench_scalar::<I32F32>(c, "I32F32");
    bench_scalar::<I16F16>(c, "I16F16");
}

criterion_group!(face, benches);
criterion_main!(face);
