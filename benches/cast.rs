//! Per scalar: standardization, the face test and the full `cast` against one precomputed
//! triangle, and scene casts over 12 and 256 triangles; parry3d's `cast_shapes(Ball, Triangle)`
//! on the same single-triangle sweeps, in the same group, so ratios come from one run.
//!
//! Run: `cargo bench --bench cast`

use ballcast::{Scalar, Scene, StandardTriangle, Sweep, Triangle, Vec3};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixed::types::{I16F16, I32F32};
use std::hint::black_box;

const SWEEPS: usize = 64;
type P = [f64; 3];
/// A ball path: start, end, radius.
type Path = (P, P, f64);

/// A deterministic generator (xorshift64), fixed seed.
struct Rng(u64);
impl Rng {
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

const TRIANGLE: [P; 3] = [[0.3, 0.2, 0.1], [1.0, 0.4, 6.5], [7.0, -0.3, 0.5]];

/// Sweeps from above the triangle down through its plane: about half hit the face, and many
/// of the rest pass close to an edge or vertex.
fn single_sweeps() -> Vec<Path> {
    let mut g = Rng(0x9E37_79B9_7F4A_7C15);
    (0..SWEEPS)
        .map(|_| {
            let p0 = [g.range(-2.0, 8.0), g.range(1.0, 6.0), g.range(-2.0, 8.0)];
            let p1 = [g.range(-2.0, 8.0), g.range(-4.0, 1.0), g.range(-2.0, 8.0)];
            (p0, p1, g.range(0.1, 1.0))
        })
        .collect()
}

/// A room 16 × 8 × 16 facing inwards, its six walls tiled, the first `n` triangles of it (the
/// last walls may be partly open), and short ball moves inside it, as a physics step makes.
fn room(n: usize) -> (Vec<[P; 3]>, Vec<Path>) {
    let per_side = (n as f64 / 12.0).sqrt().ceil() as usize;
    let mut tris = Vec::new();
    let mut quad = |o: P, a: P, b: P| {
        let k = per_side as f64;
        let at = |i: usize, j: usize| {
            [0, 1, 2].map(|c| o[c] + a[c] * i as f64 / k + b[c] * j as f64 / k)
        };
        for i in 0..per_side {
            for j in 0..per_side {
                tris.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                tris.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    };
    let (w, h) = (16.0, 8.0);
    quad([0.0; 3], [0.0, 0.0, w], [w, 0.0, 0.0]);
    quad([0.0, h, 0.0], [w, 0.0, 0.0], [0.0, 0.0, w]);
    quad([0.0; 3], [w, 0.0, 0.0], [0.0, h, 0.0]);
    quad([0.0, 0.0, w], [0.0, h, 0.0], [w, 0.0, 0.0]);
    quad([0.0; 3], [0.0, h, 0.0], [0.0, 0.0, w]);
    quad([w, 0.0, 0.0], [0.0, 0.0, w], [0.0, h, 0.0]);
    tris.truncate(n);
    let mut g = Rng(0x5EED);
    let sweeps = (0..SWEEPS)
        .map(|_| {
            let p0 = [
                g.range(1.0, w - 1.0),
                g.range(1.0, h - 1.0),
                g.range(1.0, w - 1.0),
            ];
            let d = [g.range(-1.5, 1.5), g.range(-1.5, 1.5), g.range(-1.5, 1.5)];
            (p0, [p0[0] + d[0], p0[1] + d[1], p0[2] + d[2]], 0.5)
        })
        .collect();
    (tris, sweeps)
}

fn v<S: Scalar>(p: P) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}

fn sweeps<S: Scalar>(raw: &[Path]) -> Vec<Sweep<S>> {
    raw.iter()
        .map(|&(a, b, r)| Sweep::new(v(a), v(b), S::from_f64(r)).unwrap())
        .collect()
}

fn tri<S: Scalar>(t: [P; 3]) -> Triangle<S> {
    Triangle::new(v(t[0]), v(t[1]), v(t[2]))
}

fn single<S: Scalar>(c: &mut Criterion, name: &str) {
    let st = StandardTriangle::new(&tri::<S>(TRIANGLE)).unwrap();
    let sw = sweeps::<S>(&single_sweeps());
    let mut g = c.benchmark_group("single_triangle");
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
    let t = tri::<S>(TRIANGLE);
    c.bench_function(&format!("standardize/{name}"), |b| {
        b.iter(|| StandardTriangle::new(black_box(&t)))
    });
}

fn parry(c: &mut Criterion) {
    use parry3d::math::{Pose, Vector};
    use parry3d::query::{ShapeCastOptions, cast_shapes};
    use parry3d::shape::{Ball, Triangle as PTriangle};
    let p = |a: P| Vector::new(a[0] as f32, a[1] as f32, a[2] as f32);
    let t = PTriangle::new(p(TRIANGLE[0]), p(TRIANGLE[1]), p(TRIANGLE[2]));
    let sw: Vec<(Vector, Vector, Ball)> = single_sweeps()
        .iter()
        .map(|&(a, b, r)| (p(a), p(b) - p(a), Ball::new(r as f32)))
        .collect();
    let opts = ShapeCastOptions {
        max_time_of_impact: 1.0,
        target_distance: 0.0,
        stop_at_penetration: false,
        compute_impact_geometry_on_penetration: false,
    };
    let mut g = c.benchmark_group("single_triangle");
    g.throughput(Throughput::Elements(SWEEPS as u64));
    g.bench_function(BenchmarkId::new("parry3d_cast_shapes", "f32"), |b| {
        b.iter(|| {
            sw.iter()
                .filter(|(p0, d, ball)| {
                    let from = Pose::translation(p0.x, p0.y, p0.z);
                    let hit = cast_shapes(
                        &from,
                        *d,
                        ball,
                        &Pose::IDENTITY,
                        Vector::ZERO,
                        black_box(&t),
                        opts,
                    );
                    matches!(hit, Ok(Some(_)))
                })
                .count()
        })
    });
    g.finish();
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
