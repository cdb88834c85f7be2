//! Cross-precision check of a user's own level: loads a Wavefront OBJ or glTF 2.0 / GLB file
//! (through `ballcast-level`, as the bake does; default `examples/data/valley.obj`), builds it
//! as a `Mesh` in every scalar (degenerate triangles skipped), rolls three scripted balls
//! dropped above it with `move_and_slide`, and prints where each scalar diverges from f64, next
//! to what the precision planner predicts for one contact.
//!
//! The scalars run side by side on all cores (`rayon`), with a progress bar (`indicatif`) on
//! stderr; each run is independent of the others, so the numbers are those of a single thread.
//!
//! Run: `cargo run --release --example cross_precision [path/to/level.obj|.gltf|.glb]`

use ballcast::bvh::nodes_for;
use ballcast::{Degenerates, Mesh, Node, Scalar, Triangle, Vec3, move_and_slide};
use fixed::types::{I16F16, I32F32};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

const STEPS: usize = 600;
const BALLS: usize = 3;
const RADIUS: f64 = 0.25;
type P = [f64; 3];

/// Every step's position of each scripted ball, in f64, plus the contacts.
fn roll<S: Scalar>(
    tris: &[[P; 3]],
    sides: &[bool],
    bar: &ProgressBar,
) -> Result<(Vec<P>, usize), String> {
    let v3 = |p: P| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
    let src: Vec<Triangle<S>> = tris
        .iter()
        .map(|t| Triangle::new(v3(t[0]), v3(t[1]), v3(t[2])))
        .collect();
    let n = src.len();
    let (mut nodes, mut prepared) = (vec![Node::default(); nodes_for(n)], vec![Mesh::filler(); n]);
    let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
    // Two-sided where the level says so (a glTF material's `doubleSided`), as the bake does.
    let (mesh, _) = Mesh::build_sided(
        &src,
        |i| sides.get(i) == Some(&true),
        Degenerates::Skip,
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    )
    .map_err(|e| e.to_string())?;
    if mesh.is_empty() {
        return Err(format!("all {n} triangles are degenerate"));
    }
    // Drops above the level: at fixed fractions of its extent, one unit over its top.
    let (lo, hi) = bounds(tris);
    let at = |fx: f64, fz: f64| {
        let f = [fx, 0.0, fz];
        [0, 1, 2].map(|a| {
            if a == 1 {
                hi[1] + 1.0
            } else {
                lo[a] + f[a] * (hi[a] - lo[a])
            }
        })
    };
    let (dt, r) = (S::from_f64(1.0 / 60.0), S::from_f64(RADIUS));
    let g = v3([0.0, -9.81, 0.0]);
    let (mut path, mut contacts) = (Vec::new(), 0);
    for start in [at(0.2, 0.6), at(0.75, 0.3), at(0.55, 0.8)] {
        let (mut p, mut v) = (v3(start), v3([0.0, 0.0, -1.0]));
        for _ in 0..STEPS {
            v += g.scale(dt);
            let out = move_and_slide(&mesh, p, v.scale(dt), r).map_err(|e| e.to_string())?;
            contacts += out.contacts.iter().flatten().count();
            p = out.position;
            v = out.clip(v).map_err(|e| e.to_string())?;
            path.push(p.to_array().map(S::to_f64));
        }
        bar.inc(STEPS as u64);
    }
    Ok((path, contacts))
}

/// The level's bounding box.
fn bounds(tris: &[[P; 3]]) -> (P, P) {
    let points = tris.iter().flatten();
    let lo = points
        .clone()
        .fold([f64::MAX; 3], |m, p| [0, 1, 2].map(|a| m[a].min(p[a])));
    let hi = points.fold([f64::MIN; 3], |m, p| [0, 1, 2].map(|a| m[a].max(p[a])));
    (lo, hi)
}

fn main() {
    let file = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "examples/data/valley.obj".into());
    let level = match ballcast_level::load(&file) {
        Ok(level) => level,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let (tris, sides) = (&level.triangles, &level.two_sided);
    let extent = tris
        .iter()
        .flatten()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    println!("{file}: {} triangles, extent ±{extent}", tris.len());
    let names = ["f64", "f32", "I32F32", "I16F16"];
    let bar = ProgressBar::new((names.len() * BALLS * STEPS) as u64).with_style(
        ProgressStyle::with_template("{msg} {wide_bar} {percent}%").expect("a valid template"),
    );
    bar.set_message("rolling");
    let runs: Vec<Result<(Vec<P>, usize), String>> = names
        .par_iter()
        .map(|&name| match name {
            "f64" => roll::<f64>(tris, sides, &bar),
            "f32" => roll::<f32>(tris, sides, &bar),
            "I32F32" => roll::<I32F32>(tris, sides, &bar),
            _ => roll::<I16F16>(tris, sides, &bar),
        })
        .collect();
    bar.finish_and_clear();
    let reference = match &runs[0] {
        Ok((path, _)) => path,
        Err(e) => {
            eprintln!("{file}: f64 refused the level: {e}");
            std::process::exit(1);
        }
    };
    println!(
        "| scalar | contacts | largest divergence from f64 | first step over 1e-3 | planner: one contact's error |"
    );
    println!("|---|---|---|---|---|");
    let precisions = [f32::PRECISION, I32F32::PRECISION, I16F16::PRECISION];
    for ((name, run), p) in names.iter().zip(&runs).skip(1).zip(precisions) {
        let (path, contacts) = match run {
            Ok(r) => r,
            Err(e) => {
                println!("| {name} | refused: {e} | | | |");
                continue;
            }
        };
        let dist = |a: &P, b: &P| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt();
        let d: Vec<f64> = path
            .iter()
            .zip(reference)
            .map(|(a, b)| dist(a, b))
            .collect();
        let worst = d.iter().fold(0.0f64, |m, x| m.max(*x));
        let first = d
            .iter()
            .position(|x| *x > 1e-3)
            .map_or("never".into(), |i| i.to_string());
        let planned = if p.fits(extent, RADIUS) {
            format!("{:.1e}", p.distance_error(extent, 1.0))
        } else {
            "does not fit".into()
        };
        println!("| {name} | {contacts} | {worst:.2e} | {first} | {planned} |");
    }
}
