//! Cross-precision check of a user's own scene: reads an OBJ-like triangle list (`v x y z` and
//! `f a b c` lines, 1-based; default `examples/data/valley.obj`), rolls a few scripted balls
//! through it with `move_and_slide` in every scalar, and prints where each scalar diverges from
//! f64, next to what the precision planner predicts for one contact.
//!
//! Run: `cargo run --release --example cross_precision [path/to/scene.obj]`

use ballcast::{Scalar, Scene, Triangle, Vec3, move_and_slide};
use fixed::types::{I16F16, I32F32};

const CAPACITY: usize = 1024;
const STEPS: usize = 600;
type P = [f64; 3];

/// Parses the triangle list; std-only helper, so the library itself stays allocation-free.
fn parse(text: &str) -> Result<Vec<[P; 3]>, String> {
    let (mut verts, mut tris) = (Vec::new(), Vec::new());
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let nums = |w: std::str::SplitWhitespace| -> Result<Vec<f64>, String> {
            w.map(|x| x.parse::<f64>().map_err(|e| format!("line {}: {e}", n + 1)))
                .collect()
        };
        match words.next() {
            Some("v") => match nums(words)?[..] {
                [x, y, z] => verts.push([x, y, z]),
                _ => return Err(format!("line {}: a vertex needs 3 numbers", n + 1)),
            },
            Some("f") => {
                let ids = nums(words)?;
                let get = |i: f64| verts.get((i as usize).wrapping_sub(1)).copied();
                match ids[..] {
                    [a, b, c] => match (get(a), get(b), get(c)) {
                        (Some(a), Some(b), Some(c)) => tris.push([a, b, c]),
                        _ => return Err(format!("line {}: no such vertex", n + 1)),
                    },
                    _ => return Err(format!("line {}: a face needs 3 vertices", n + 1)),
                }
            }
            _ => {}
        }
    }
    Ok(tris)
}

/// Every step's position of each scripted ball, in f64, plus the contacts.
fn roll<S: Scalar>(tris: &[[P; 3]]) -> Result<(Vec<P>, usize), ballcast::Error> {
    let v3 = |p: P| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
    let mut scene: Scene<S, CAPACITY> = Scene::new();
    for t in tris {
        scene.push(Triangle::new(v3(t[0]), v3(t[1]), v3(t[2])))?;
    }
    let (dt, r) = (S::from_f64(1.0 / 60.0), S::from_f64(0.25));
    let g = v3([0.0, -9.81, 0.0]);
    let (mut path, mut contacts) = (Vec::new(), 0);
    for start in [[-3.0, 4.0, 1.0], [2.5, 3.0, -2.0], [0.5, 2.0, 3.0]] {
        let (mut p, mut v) = (v3(start), v3([0.0, 0.0, -1.0]));
        for _ in 0..STEPS {
            v += g.scale(dt);
            let out = move_and_slide(&scene, p, v.scale(dt), r)?;
            contacts += out.contacts.iter().flatten().count();
            p = out.position;
            v = out.clip(v)?;
            path.push(p.to_array().map(S::to_f64));
        }
    }
    Ok((path, contacts))
}

fn main() -> Result<(), String> {
    let file = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "examples/data/valley.obj".into());
    let text = std::fs::read_to_string(&file).map_err(|e| format!("{file}: {e}"))?;
    let tris = parse(&text)?;
    let extent = tris
        .iter()
        .flatten()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    println!("{file}: {} triangles, extent ±{extent}", tris.len());
    let reference = roll::<f64>(&tris).map_err(|e| e.to_string())?.0;
    println!(
        "| scalar | contacts | largest divergence from f64 | first step over 1e-3 | planner: one contact's error |"
    );
    println!("|---|---|---|---|---|");
    let report =
        |name: &str, run: Result<(Vec<P>, usize), ballcast::Error>, p: ballcast::Precision| {
            let Ok((path, contacts)) = run else {
                println!("| {name} | refused: {} | | | |", run.unwrap_err());
                return;
            };
            let dist = |a: &P, b: &P| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt();
            let d: Vec<f64> = path
                .iter()
                .zip(&reference)
                .map(|(a, b)| dist(a, b))
                .collect();
            let worst = d.iter().fold(0.0f64, |m, x| m.max(*x));
            let first = d
                .iter()
                .position(|x| *x > 1e-3)
                .map_or("never".into(), |i| i.to_string());
            let planned = if p.fits(extent, 0.25) {
                format!("{:.1e}", p.distance_error(extent, 1.0))
            } else {
                "does not fit".into()
            };
            println!("| {name} | {contacts} | {worst:.2e} | {first} | {planned} |");
        };
    report("f32", roll::<f32>(&tris), f32::PRECISION);
    report("I32F32", roll::<I32F32>(&tris), I32F32::PRECISION);
    report("I16F16", roll::<I16F16>(&tris), I16F16::PRECISION);
    Ok(())
}
