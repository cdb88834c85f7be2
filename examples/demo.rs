//! A ball thrown through a small room, simulated side by side in f64, f32, I32F32 and I16F16.
//!
//! The room is a 20 × 10 × 20 box (each face split into 8 triangles, normals facing inwards) with a
//! ramp in one corner: 52 triangles. The ball bounces off faces using the face test alone; each
//! scalar prints the contacts it found, where the ball ends, and how far its path ever strayed
//! from the f64 run. Everything is fixed: no randomness at run time.
//!
//! Run: `cargo run --release --example demo`

use ballcast::{Scalar, StandardTriangle, Sweep, Triangle, Vec3};
use fixed::types::{I16F16, I32F32};

const STEPS: usize = 240; // 4 s at 60 Hz
const DT: f64 = 1.0 / 60.0;
const RADIUS: f64 = 0.5;
const RESTITUTION: f64 = 0.8;
/// After a contact the ball is lifted this far off the face, so rounding never starts the next
/// sweep inside the face's plane (the face test ignores balls that start there).
const SKIN: f64 = 1e-3;

/// The room's triangles in f64; every scalar converts the same list.
fn room() -> Vec<[[f64; 3]; 3]> {
    let mut tris = Vec::new();
    // A quad (origin o, edges a and b) split 2 × 2 into 8 triangles facing a × b.
    let mut quad = |o: [f64; 3], a: [f64; 3], b: [f64; 3]| {
        let at = |i: f64, j: f64| [0, 1, 2].map(|k| o[k] + a[k] * i / 2.0 + b[k] * j / 2.0);
        for i in 0..2 {
            for j in 0..2 {
                let (i, j) = (i as f64, j as f64);
                tris.push([at(i, j), at(i + 1.0, j), at(i + 1.0, j + 1.0)]);
                tris.push([at(i, j), at(i + 1.0, j + 1.0), at(i, j + 1.0)]);
            }
        }
    };
    let (w, h) = (20.0, 10.0);
    quad([0.0, 0.0, 0.0], [0.0, 0.0, w], [w, 0.0, 0.0]); // floor, faces +y
    quad([0.0, h, 0.0], [w, 0.0, 0.0], [0.0, 0.0, w]); // ceiling, faces -y
    quad([0.0, 0.0, 0.0], [w, 0.0, 0.0], [0.0, h, 0.0]); // wall z = 0, faces +z
    quad([0.0, 0.0, w], [0.0, h, 0.0], [w, 0.0, 0.0]); // wall z = w, faces -z
    quad([0.0, 0.0, 0.0], [0.0, h, 0.0], [0.0, 0.0, w]); // wall x = 0, faces +x
    quad([w, 0.0, 0.0], [0.0, 0.0, w], [0.0, h, 0.0]); // wall x = w, faces -x
    // A ramp rising towards +x in the far corner: two quads' worth of triangles.
    let (r0, r1) = ([12.0, 0.01, 12.0], [19.9, 4.0, 12.0]);
    let (r2, r3) = ([12.0, 0.01, 19.9], [19.9, 4.0, 19.9]);
    tris.push([r0, r2, r1]);
    tris.push([r1, r2, r3]);
    tris.push([r0, r2, [16.0, 2.0, 16.0]]);
    tris.push([[16.0, 2.0, 16.0], r2, r3]);
    tris
}

struct Run {
    name: &'static str,
    contacts: usize,
    path: Vec<[f64; 3]>,
}

fn simulate<S: Scalar>(name: &'static str) -> Run {
    let c = S::from_f64;
    let v3 = |p: [f64; 3]| Vec3::new(c(p[0]), c(p[1]), c(p[2]));
    let tris: Vec<StandardTriangle<S>> = room()
        .iter()
        .map(|t| StandardTriangle::new(&Triangle::new(v3(t[0]), v3(t[1]), v3(t[2]))))
        .collect::<Result<_, _>>()
        .expect("the room's triangles are valid");
    let (dt, r, skin) = (c(DT), c(RADIUS), c(SKIN));
    let bounce = S::ONE + c(RESTITUTION);
    let gravity = Vec3::new(S::ZERO, c(-9.81), S::ZERO);
    let mut p = v3([3.0, 6.0, 4.0]);
    let mut v = v3([14.0, 5.0, 11.0]);
    let mut run = Run {
        name,
        contacts: 0,
        path: Vec::with_capacity(STEPS),
    };
    for _ in 0..STEPS {
        v = v + gravity * dt;
        let mut remaining = S::ONE;
        // A few sub-steps: after each bounce the ball continues for the rest of the step.
        for _ in 0..4 {
            let target = p + v * (dt * remaining);
            let sweep = Sweep::new(p, target, r).expect("the ball stays in range");
            let first = tris
                .iter()
                .filter_map(|t| t.face_collision(&sweep))
                .min_by(|a, b| a.alpha.partial_cmp(&b.alpha).unwrap());
            let Some(hit) = first else {
                p = target;
                break;
            };
            run.contacts += 1;
            p = p + (target - p) * hit.alpha + hit.normal * skin;
            v = v - hit.normal * (bounce * v.dot(hit.normal));
            remaining = remaining * (S::ONE - hit.alpha);
        }
        run.path.push(p.to_array().map(S::to_f64));
    }
    run
}

fn main() {
    let runs = [
        simulate::<f64>("f64"),
        simulate::<f32>("f32"),
        simulate::<I32F32>("I32F32"),
        simulate::<I16F16>("I16F16"),
    ];
    let reference = &runs[0].path;
    println!(
        "room: {} triangles, {STEPS} steps of {DT:.4} s, radius {RADIUS}",
        room().len()
    );
    println!("| scalar | contacts | final position | largest divergence from f64 |");
    println!("|---|---|---|---|");
    for run in &runs {
        let divergence = run
            .path
            .iter()
            .zip(reference)
            .map(|(a, b)| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt())
            .fold(0.0, f64::max);
        let [x, y, z] = run.path[STEPS - 1];
        println!(
            "| {} | {} | ({x:.4}, {y:.4}, {z:.4}) | {divergence:.3e} |",
            run.name, run.contacts
        );
    }
}
