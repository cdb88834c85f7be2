//! How error grows over a simulation, and how much of it comes from the user's own constants.
//!
//! A ball of radius 0.5 is thrown across a 200 × 200 floor under gravity (it lands, then slides
//! without friction), 60 steps a second, for 60 seconds: the character loop of the README. Each
//! scalar runs it twice in f64's eyes:
//! - `constants`: f64 with the time step, gravity and throw rounded to the scalar first: what
//!   the user's own numbers cost, with exact arithmetic;
//! - `arithmetic`: the scalar itself, against that same rounded-constants f64 run: what the
//!   crate's rounding costs.
//!
//! Prints the distance from the exact f64 run at 1, 10 and 60 seconds.
//! `cargo run --release --example drift`

use ballcast::{Scalar, Scene, Triangle, Vec3, move_and_slide};
use fixed::types::{I16F16, I32F32};

/// The throw: start, velocity, gravity, time step, radius.
#[derive(Clone, Copy)]
struct Setup {
    start: [f64; 3],
    velocity: [f64; 3],
    gravity: f64,
    dt: f64,
    radius: f64,
}

const SETUP: Setup = Setup {
    start: [-90.0, 3.0, -20.0],
    velocity: [2.9, 1.7, 0.7],
    gravity: -9.81,
    dt: 1.0 / 60.0,
    radius: 0.5,
};

/// Every constant rounded to `S` (and back to f64).
fn rounded<S: Scalar>(s: Setup) -> Setup {
    let r = |x: f64| S::from_f64(x).to_f64();
    Setup {
        start: s.start.map(r),
        velocity: s.velocity.map(r),
        gravity: r(s.gravity),
        dt: r(s.dt),
        radius: r(s.radius),
    }
}

/// Positions after each whole second, up to `seconds`.
fn run<S: Scalar>(s: Setup, seconds: usize) -> Vec<[f64; 3]> {
    let v = |p: [f64; 3]| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
    let mut floor: Scene<S, 2> = Scene::new();
    let c = [
        [-100.0, 0.0, -100.0],
        [-100.0, 0.0, 100.0],
        [100.0, 0.0, 100.0],
        [100.0, 0.0, -100.0],
    ];
    floor
        .push(Triangle::new(v(c[0]), v(c[1]), v(c[2])))
        .unwrap();
    floor
        .push(Triangle::new(v(c[0]), v(c[2]), v(c[3])))
        .unwrap();
    let (dt, g, r) = (
        S::from_f64(s.dt),
        S::from_f64(s.gravity),
        S::from_f64(s.radius),
    );
    let (mut p, mut vel) = (v(s.start), v(s.velocity));
    let mut out = Vec::new();
    for _ in 0..seconds {
        for _ in 0..60 {
            vel.y = vel.y + g.mul(dt);
            let step = move_and_slide(&floor, p, vel * dt, r).unwrap();
            p = step.position;
            vel = step.clip(vel).unwrap();
        }
        out.push([p.x.to_f64(), p.y.to_f64(), p.z.to_f64()]);
    }
    out
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt()
}

fn report<S: Scalar>(name: &str, exact: &[[f64; 3]]) {
    let consts = run::<f64>(rounded::<S>(SETUP), exact.len());
    let own = run::<S>(SETUP, exact.len());
    let dt = rounded::<S>(SETUP).dt;
    print!("| {name} | {:.2e} |", (dt - SETUP.dt).abs() / SETUP.dt);
    for t in [1, 10, 60] {
        let (c, a) = (
            dist(consts[t - 1], exact[t - 1]),
            dist(own[t - 1], consts[t - 1]),
        );
        print!(" {c:.1e} | {a:.1e} |");
    }
    println!();
}

fn main() {
    let exact = run::<f64>(SETUP, 60);
    println!("f64 at 60 s: {:?}", exact[59]);
    println!(
        "| scalar | dt's relative rounding | constants 1 s | arithmetic 1 s | constants 10 s | arithmetic 10 s | constants 60 s | arithmetic 60 s |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    report::<f32>("f32", &exact);
    report::<I32F32>("I32F32", &exact);
    report::<I16F16>("I16F16", &exact);
}
