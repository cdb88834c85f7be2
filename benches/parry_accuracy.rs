//! The same sweeps through ballcast `f32` and parry3d's `cast_shapes(Ball, Triangle)` (f32),
//! both against ballcast `f64` on the same inputs: the distance error along the normal at
//! contact (median, p99, max), at scene scale 10.
//!
//! Run: `cargo run --release --example parry_accuracy`

use ballcast::{StandardTriangle, Sweep, Triangle, Vec3};
use parry3d::math::{Pose, Vector};
use parry3d::query::{ShapeCastOptions, cast_shapes};
use parry3d::shape::{Ball, Triangle as PTriangle};

type P = [f64; 3];

struct Rng(u64);
impl Rng {
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn point(&mut self, h: f64) -> P {
        [0; 3].map(|_| self.range(-h, h))
    }
}

fn ours<S: ballcast::Scalar>(t: [P; 3], p0: P, p1: P, r: f64) -> Option<(f64, P)> {
    let v = |p: P| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
    let st = StandardTriangle::new(&Triangle::new(v(t[0]), v(t[1]), v(t[2]))).ok()?;
    let h = st.cast(&Sweep::new(v(p0), v(p1), S::from_f64(r)).ok()?)?;
    Some((h.alpha.to_f64(), h.normal.to_array().map(S::to_f64)))
}

fn parry(t: [P; 3], p0: P, p1: P, r: f64) -> Option<f64> {
    let f = |p: P| Vector::new(p[0] as f32, p[1] as f32, p[2] as f32);
    let tri = PTriangle::new(f(t[0]), f(t[1]), f(t[2]));
    let opts = ShapeCastOptions {
        max_time_of_impact: 1.0,
        target_distance: 0.0,
        stop_at_penetration: false,
        compute_impact_geometry_on_penetration: false,
    };
    let from = Pose::translation(p0[0] as f32, p0[1] as f32, p0[2] as f32);
    let hit = cast_shapes(
        &from,
        f(p1) - f(p0),
        &Ball::new(r as f32),
        &Pose::IDENTITY,
        Vector::ZERO,
        &tri,
        opts,
    );
    hit.ok().flatten().map(|h| h.time_of_impact as f64)
}

fn stats(mut e: Vec<f64>) -> String {
    e.sort_by(f64::total_cmp);
    let at = |q: f64| e[((e.len() - 1) as f64 * q) as usize];
    format!(
        "{:.2e} | {:.2e} | {:.2e} | {}",
        at(0.5),
        at(0.99),
        e[e.len() - 1],
        e.len()
    )
}

fn main() {
    let mut g = Rng(0xACC);
    let (mut ours_err, mut parry_err) = (Vec::new(), Vec::new());
    for _ in 0..200_000 {
        // Falling sweeps from the front, inputs exact in f32 so all three see the same values.
        let q = |p: P| p.map(|x| x as f32 as f64);
        let t = [g.point(10.0), g.point(10.0), g.point(10.0)].map(q);
        let n = {
            let (a, b) = (
                [0, 1, 2].map(|k| t[1][k] - t[0][k]),
                [0, 1, 2].map(|k| t[2][k] - t[0][k]),
            );
            let c = [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ];
            let l = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
            c.map(|x| x / l)
        };
        let h = g.range(1.0, 30.0);
        let (a, b) = (g.point(10.0), g.point(10.0));
        let p0 = q([0, 1, 2].map(|k| a[k] + n[k] * h));
        let p1 = q([0, 1, 2].map(|k| b[k] - n[k] * h));
        let r = g.range(0.1, 2.0) as f32 as f64;
        let (Some((want, m)), Some((got, _)), Some(theirs)) = (
            ours::<f64>(t, p0, p1, r),
            ours::<f32>(t, p0, p1, r),
            parry(t, p0, p1, r),
        ) else {
            continue;
        };
        let approach = ([0, 1, 2].map(|k| (p1[k] - p0[k]) * m[k]))
            .iter()
            .sum::<f64>()
            .abs();
        ours_err.push((got - want).abs() * approach);
        parry_err.push((theirs - want).abs() * approach);
    }
    println!("distance error along the normal at contact against ballcast f64, scene scale 10:");
    println!("| | median | p99 | max | hits |");
    println!("|---|---|---|---|---|");
    println!("| ballcast f32 `cast` | {} |", stats(ours_err));
    println!("| parry3d f32 `cast_shapes` | {} |", stats(parry_err));
}
