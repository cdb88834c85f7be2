//! A ball rolls down a ramp of many triangles and comes to rest in a corner, simulated side by
//! side in f64, f32, I32F32 and I16F16.
//!
//! The scene is a 16 × 16 height field (one-unit cells, two triangles each: 512 triangles) that
//! tilts gently towards the corner at the origin and rises into a ramp beyond x = 6, closed by
//! two walls meeting at that corner (64 triangles). Each step adds gravity, moves the ball with
//! `move_and_slide`, removes from its velocity whatever pointed into the contacts, and applies
//! a little rolling resistance. Everything is fixed: no randomness at run time. Each scalar
//! prints its contacts, where the ball ends, its final speed, and how far its path ever strayed
//! from the f64 run, and a picture goes to `target/demo.svg`: the level and the four paths from
//! above and from the side, and each scalar's distance from the f64 path over time.
//!
//! Run: `cargo run --release --example demo`

use ballcast::{Scalar, Scene, Triangle, Vec3, move_and_slide};
use fixed::types::{I16F16, I32F32};
use plotters::prelude::*;

const STEPS: usize = 1200; // 20 s at 60 Hz
const DT: f64 = 1.0 / 60.0;
const RADIUS: f64 = 0.4;
const DAMPING: f64 = 0.99; // velocity kept per step: rolling resistance
const CELLS: usize = 16;
const CAPACITY: usize = 2 * CELLS * CELLS + 64;

fn height(x: f64, z: f64) -> f64 {
    0.05 * (x + z) + 0.4 * (x - 6.0).max(0.0)
}

/// The scene's triangles in f64, front faces towards the inside; every scalar converts these.
fn triangles() -> Vec<[[f64; 3]; 3]> {
    let mut tris = Vec::new();
    let p = |x: usize, z: usize| [x as f64, height(x as f64, z as f64), z as f64];
    for i in 0..CELLS {
        for j in 0..CELLS {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    // Walls x = 0 (facing +x) and z = 0 (facing +z), 16 long and 2 high, in 16 panels each.
    for k in 0..CELLS {
        let (u, w) = (k as f64, k as f64 + 1.0);
        let (lo, hi) = (-1.0, 2.0);
        tris.push([[0.0, lo, u], [0.0, hi, u], [0.0, hi, w]]);
        tris.push([[0.0, lo, u], [0.0, hi, w], [0.0, lo, w]]);
        tris.push([[u, lo, 0.0], [w, lo, 0.0], [w, hi, 0.0]]);
        tris.push([[u, lo, 0.0], [w, hi, 0.0], [u, hi, 0.0]]);
    }
    tris
}

struct Run {
    name: &'static str,
    contacts: usize,
    speed: f64,
    path: Vec<[f64; 3]>,
}

fn simulate<S: Scalar>(name: &'static str) -> Run {
    let c = S::from_f64;
    let v3 = |p: [f64; 3]| Vec3::new(c(p[0]), c(p[1]), c(p[2]));
    let mut scene: Scene<S, CAPACITY> = Scene::new();
    for t in triangles() {
        scene
            .push(Triangle::new(v3(t[0]), v3(t[1]), v3(t[2])))
            .expect("the scene's triangles are valid and fit");
    }
    let (dt, r, damping) = (c(DT), c(RADIUS), c(DAMPING));
    let gravity = Vec3::new(S::ZERO, c(-9.81), S::ZERO);
    let mut p = v3([15.0, height(15.0, 12.0) + RADIUS + 0.5, 12.0]);
    let mut v = v3([0.0, 0.0, 0.0]);
    let mut run = Run {
        name,
        contacts: 0,
        speed: 0.0,
        path: Vec::with_capacity(STEPS),
    };
    for _ in 0..STEPS {
        v += gravity.scale(dt);
        let out = move_and_slide(&scene, p, v.scale(dt), r).expect("the ball stays in range");
        run.contacts += out.contacts.iter().flatten().count();
        p = out.position;
        v = out
            .clip(v)
            .expect("the velocity stays in range")
            .scale(damping);
        run.path.push(p.to_array().map(S::to_f64));
    }
    run.speed = v
        .to_array()
        .map(S::to_f64)
        .iter()
        .map(|x| x * x)
        .sum::<f64>()
        .sqrt();
    run
}

/// How far `path` is from `reference` at each step.
fn divergence(path: &[[f64; 3]], reference: &[[f64; 3]]) -> Vec<f64> {
    path.iter()
        .zip(reference)
        .map(|(a, b)| (0..3).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt())
        .collect()
}

const COLOURS: [RGBColor; 4] = [BLACK, BLUE, GREEN, RED];

/// The picture: the level's triangle edges and every scalar's path from above (x, z) and from the
/// side (x, y), and each scalar's distance from the f64 path over time (log scale).
fn picture(runs: &[Run], file: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(file, (1100, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let (views, lower) = root.split_vertically(520);
    let views = views.split_evenly((1, 2));
    let tris = triangles();
    // (horizontal, vertical) coordinate of each view, and its caption.
    // The paths agree to a fraction of a line's width here: the lower panel tells them apart.
    let axes = [
        ((0, 2), "from above: x, z (the four paths overlap)"),
        ((0, 1), "from the side: x, y"),
    ];
    for (area, ((h, v), caption)) in views.iter().zip(axes) {
        let range = |k: usize| {
            let all = tris.iter().flatten().map(|p| p[k]);
            all.clone().fold(f64::INFINITY, f64::min) - 0.5..all.fold(0.0, f64::max) + 0.5
        };
        let mut chart = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(30)
            .y_label_area_size(40)
            .build_cartesian_2d(range(h), range(v))?;
        chart.configure_mesh().disable_mesh().draw()?;
        let grey = RGBColor(205, 205, 205);
        chart.draw_series(tris.iter().map(|t| {
            let mut outline: Vec<(f64, f64)> = t.iter().map(|p| (p[h], p[v])).collect();
            outline.push(outline[0]);
            PathElement::new(outline, grey)
        }))?;
        for (run, colour) in runs.iter().zip(COLOURS) {
            chart
                .draw_series(LineSeries::new(
                    run.path.iter().map(|p| (p[h], p[v])),
                    colour.stroke_width(2),
                ))?
                .label(run.name)
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    // Distances below this floor (f64's own zero among them) are drawn at it.
    let floor = 1e-9;
    let seconds = STEPS as f64 * DT;
    let mut chart = ChartBuilder::on(&lower)
        .caption("distance from the f64 path", ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..seconds, (floor..1.0).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("simulated time (s)")
        .y_desc("distance (scene units)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (run, colour) in runs.iter().zip(COLOURS).skip(1) {
        let d = divergence(&run.path, &runs[0].path);
        let points = d
            .iter()
            .enumerate()
            .map(|(i, &x)| ((i + 1) as f64 * DT, x.max(floor)));
        chart
            .draw_series(LineSeries::new(points, colour.stroke_width(2)))?
            .label(run.name)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
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
        "scene: {} triangles; ball radius {RADIUS}, {STEPS} steps of {DT:.4} s, rolling from (15, _, 12) towards the corner at the origin",
        triangles().len()
    );
    println!("| scalar | contacts | final position | final speed | largest divergence from f64 |");
    println!("|---|---|---|---|---|");
    for run in &runs {
        let divergence = divergence(&run.path, reference)
            .into_iter()
            .fold(0.0, f64::max);
        let [x, y, z] = run.path[STEPS - 1];
        println!(
            "| {} | {} | ({x:.4}, {y:.4}, {z:.4}) | {:.2e} | {divergence:.3e} |",
            run.name, run.contacts, run.speed
        );
    }
    // The repository's `target/` (this package lives in `examples/demo/`), made if a build
    // directory elsewhere (`CARGO_TARGET_DIR`) left it out.
    let manifest = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = manifest
        .ancestors()
        .nth(2)
        .unwrap_or(manifest)
        .join("target");
    let file = dir.join("demo.svg");
    let written = std::fs::create_dir_all(&dir)
        .map_err(Into::into)
        .and_then(|()| picture(&runs, &file));
    match written {
        Ok(()) => println!("picture: {}", file.display()),
        Err(e) => {
            eprintln!("could not write {}: {e}", file.display());
            std::process::exit(1);
        }
    }
}
