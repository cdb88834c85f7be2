//! Accuracy against speed, per scalar and scene scale: the same 10^6 random sweeps per scale,
//! in f32, I32F32 and I16F16, each against f64's `cast` on the same (rounded) inputs.
//!
//! Per scalar and scale it prints one markdown row: nanoseconds per `cast` (median of several
//! timed repetitions over 4096 prepared cases), instructions per `cast` (from
//! `target/callgrind.tsv`, written by `scripts/callgrind.sh`; "n/a" without it), the distance
//! error along the normal at contact, `|alpha_S - alpha_f64| * |(p1 - p0) · n_f64|` (median,
//! p99, max over the cases both report a hit), the error of `Hit::position` (the centre at
//! contact) along f64's normal against f64's (p99, max), the normal's angle error, hit/miss disagreements
//! (all, and outside the rounding band) and the safe range used. It writes the table to
//! `docs/tradeoff.md` and the plot (p99 distance error against ns per test, log–log) to
//! `docs/tradeoff.svg` (drawn with `plotters`). The accuracy rows run on all cores (`rayon`),
//! each from its own seeded cases, so the numbers are those of a single-threaded run; a progress
//! bar (`indicatif`) counts the cases on stderr. The timing runs after, on one thread.
//!
//! Cases: half uniform (triangle within ±s, path within ±4s, radius 0.01s–0.2s), half falling
//! through the triangle's plane from the front (about a third of those hit), at scales s = 1, 10,
//! 100, 1000, and "far": scale-10 geometry offset by (o, o, o), o = 1e4 for f32 and f64 and
//! o = 0.9 LIMIT for fixed-point. A row is skipped when its largest coordinate, 4s + o, exceeds
//! the scalar's LIMIT.
//!
//! Disagreements follow the rule of `tests/cast.rs`: a hit/miss difference counts as outside
//! the rounding band unless f64 itself flips between radius r - band and r + band, or the
//! contact is at the start (f64 alpha < 1e-6 or the scalar's < 1e-3). The band is twice the
//! scalar's distance tolerance from `tests/common/mod.rs` (defined at scale 10), scaled by
//! s / 10 for s > 10 since errors grow with the scene. "over tol" counts both-hit cases whose
//! error beyond alpha's rounding (distance - EPSILON/2 * approach) exceeds that distance
//! tolerance (scaled the same way), or whose angle exceeds the angle allowed in `tests/cast.rs`
//! (with the scaled tolerance); the first three of each row are printed to stderr.
//!
//! Run: `scripts/callgrind.sh && cargo run --release --example tradeoff`
//! (`tradeoff --kernel <scalar> <scale> <n>` is the mode `scripts/callgrind.sh` runs under
//! callgrind: `cast` over the first n cases of that scale, nothing else measured.)

use ballcast::{Error, Scalar, StandardTriangle, Sweep, Triangle};
use fixed::types::{I16F16, I32F32};
use indicatif::{ProgressBar, ProgressStyle};
use plotters::prelude::*;
use rayon::prelude::*;
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

const CASES: usize = 1_000_000;
const TIMED: usize = 4096;
const REPS: usize = 15;
const SCALES: [&str; 5] = ["1", "10", "100", "1000", "far"];

// The case generator, vector helpers and tolerance table of the tests, so the report measures
// exactly what they check.
#[path = "../tests/common/mod.rs"]
mod common;

use common::{Case, P, Rng, Tolerance, add, angle, back, dot, norm, sub, v};

/// The scalars measured (names and tolerances from `tests/common/mod.rs`), with the offset of
/// their "far" scale.
trait Measured: Tolerance {
    const FAR: f64;
}
impl Measured for f64 {
    const FAR: f64 = 1e4;
}
impl Measured for f32 {
    const FAR: f64 = 1e4;
}
impl Measured for I32F32 {
    const FAR: f64 = 0.9 * 268_435_456.0;
}
impl Measured for I16F16 {
    const FAR: f64 = 0.9 * 4096.0;
}

/// Geometry scale and offset of a scale label, for scalar `S`.
fn geometry<S: Measured>(label: &str) -> (f64, f64) {
    match label {
        "far" => (10.0, S::FAR),
        s => (s.parse().unwrap(), 0.0),
    }
}

/// The case stream of a scale: the same for every scalar (offset added per scalar).
fn cases(label: &str, s: f64, off: f64) -> impl Iterator<Item = Case> {
    let seed = 0x7EAD_0FF5_0000_0001 ^ label.bytes().fold(0u64, |h, b| h * 131 + b as u64);
    let mut rng = Rng(seed);
    let o = [off; 3];
    (0..).map(move |i| {
        let c = if i % 2 == 0 {
            rng.case(s)
        } else {
            rng.falling_case(s)
        };
        Case {
            tri: c.tri.map(|p| add(p, o)),
            p0: add(c.p0, o),
            p1: add(c.p1, o),
            r: c.r,
        }
    })
}

/// The triangle and sweep of a case in `S`, for timing.
fn prepare<S: Scalar>(c: &Case, r: f64) -> Result<(StandardTriangle<S>, Sweep<S>), Error> {
    let [a, b, t] = c.tri.map(v::<S>);
    let st = StandardTriangle::new(&Triangle::new(a, b, t))?;
    Ok((st, Sweep::new(v(c.p0), v(c.p1), S::from_f64(r))?))
}

/// The full `cast` of a case in `S`, every feature active: alpha, normal and `Hit::position`.
fn cast<S: Scalar>(c: &Case, r: f64) -> Result<Option<(f64, P, P)>, Error> {
    let (st, sw) = prepare::<S>(c, r)?;
    Ok(st
        .cast(&sw)
        .map(|h| (h.alpha.to_f64(), back(h.normal), back(h.position))))
}

fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

/// One row of the table.
struct Row {
    scalar: &'static str,
    scale: &'static str,
    offset: f64,
    ns: f64,
    instr: Option<f64>,
    skipped: Option<String>,
    valid: usize,
    rejected: usize,
    hits: usize,
    dist: [f64; 3],
    position: [f64; 2],
    angle: [f64; 2],
    over_tol: usize,
    disagree: usize,
    outside: usize,
    reach: f64,
    limit: f64,
}

/// The first `n` cases of a scale that `S` accepts, prepared, for timing and callgrind.
fn prepared<S: Measured>(label: &str, n: usize) -> Vec<(StandardTriangle<S>, Sweep<S>)> {
    let (s, off) = geometry::<S>(label);
    cases(label, s, off)
        .take(4 * n)
        .filter_map(|c| {
            let c = c.rounded::<S>();
            prepare::<S>(&c, c.r).ok()
        })
        .take(n)
        .collect()
}

/// A timer for `cast` over the first `TIMED` cases of a scale: each call runs one repetition
/// (about 10 ms) and returns nanoseconds per `cast`.
fn timer<S: Measured + 'static>(label: &'static str) -> Box<dyn FnMut() -> f64> {
    let set = prepared::<S>(label, TIMED);
    let run = move |passes: usize| {
        let t = Instant::now();
        let mut hits = 0usize;
        for _ in 0..passes {
            for (st, sw) in &set {
                hits += black_box(st).cast(black_box(sw)).is_some() as usize;
            }
        }
        black_box(hits);
        t.elapsed().as_nanos() as f64 / (passes * set.len()) as f64
    };
    let once = run(1) * TIMED as f64 * 1e-9;
    let passes = ((0.01 / once.max(1e-6)).ceil() as usize).clamp(1, 1000);
    Box::new(move || run(passes))
}

/// Instructions per call of `cast` on this scale's cases, from `scripts/callgrind.sh`.
fn instructions(scalar: &str, label: &str) -> Option<f64> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/target/callgrind.tsv");
    let text = std::fs::read_to_string(path).ok()?;
    text.lines().find_map(|l| {
        let f: Vec<&str> = l.split('\t').collect();
        (f.len() >= 6 && f[0] == "cast" && f[1] == scalar && f[2] == format!("tradeoff-{label}"))
            .then(|| f[5].parse().ok())
            .flatten()
    })
}

/// `cases`, counted on `bar` in steps of 4096.
fn counted<'a, T>(
    cases: impl Iterator<Item = T> + 'a,
    bar: &'a ProgressBar,
) -> impl Iterator<Item = T> + 'a {
    cases.enumerate().map(move |(i, c)| {
        if i % 4096 == 4095 {
            bar.inc(4096);
        }
        c
    })
}

fn measure<S: Measured>(label: &'static str, bar: &ProgressBar) -> Row {
    let (s, off) = geometry::<S>(label);
    let limit = S::LIMIT.to_f64();
    let reach = 4.0 * s + off;
    let mut row = Row {
        scalar: S::NAME,
        scale: label,
        offset: off,
        ns: f64::NAN,
        instr: instructions(S::NAME, label),
        skipped: None,
        valid: 0,
        rejected: 0,
        hits: 0,
        dist: [f64::NAN; 3],
        position: [f64::NAN; 2],
        angle: [f64::NAN; 2],
        over_tol: 0,
        disagree: 0,
        outside: 0,
        reach,
        limit,
    };
    if reach > limit {
        row.skipped = Some(format!("4s + offset = {reach} > LIMIT = {limit}"));
        bar.inc(CASES as u64);
        return row;
    }
    if S::NAME == "f64" {
        // The reference: only speed and the hit count.
        for c in counted(cases(label, s, off).take(CASES), bar) {
            match cast::<f64>(&c, c.r) {
                Ok(h) => {
                    row.valid += 1;
                    row.hits += h.is_some() as usize;
                }
                Err(_) => row.rejected += 1,
            }
        }
        return row;
    }
    let tol = S::DISTANCE * (s / 10.0).max(1.0);
    let band = 2.0 * tol;
    let eps = S::EPSILON.to_f64();
    let (mut dist, mut positions, mut angles) = (Vec::new(), Vec::new(), Vec::new());
    for c in counted(cases(label, s, off).take(CASES), bar) {
        let c = c.rounded::<S>();
        let (Ok(got), Ok(want)) = (cast::<S>(&c, c.r), cast::<f64>(&c, c.r)) else {
            row.rejected += 1;
            continue;
        };
        row.valid += 1;
        match (got, want) {
            (Some((a, n, at)), Some((b, m, want_at))) => {
                row.hits += 1;
                let d = sub(c.p1, c.p0);
                let approach = dot(d, m).abs();
                let err = (a - b).abs() * approach;
                let tilt = angle(n, m);
                let incidence = approach / norm(d);
                let allowed_tilt = S::ANGLE.max(4.0 * tol / (c.r * incidence));
                if err - eps / 2.0 * approach > tol || tilt > allowed_tilt {
                    row.over_tol += 1;
                    if row.over_tol <= 3 {
                        eprintln!(
                            "{} scale {label}: over tolerance: distance {err:e} (beyond alpha's rounding {:e}, allowed {:e}), angle {tilt:e} (allowed {allowed_tilt:e}), got {got:?}, f64 {want:?}, case {c:?}",
                            S::NAME,
                            err - eps / 2.0 * approach,
                            tol
                        );
                    }
                }
                dist.push(err);
                positions.push(dot(sub(at, want_at), m).abs());
                angles.push(tilt);
            }
            (None, None) => {}
            (got, want) => {
                row.disagree += 1;
                let flips = |r: f64| cast::<f64>(&c, r.max(0.0)).ok().flatten().is_some();
                let (lo, hi) = (flips(c.r - band), flips(c.r + band));
                let at_start =
                    want.is_some_and(|(a, ..)| a < 1e-6) || got.is_some_and(|(a, ..)| a < 1e-3);
                if lo == hi && !at_start {
                    row.outside += 1;
                }
            }
        }
    }
    dist.sort_by(f64::total_cmp);
    positions.sort_by(f64::total_cmp);
    angles.sort_by(f64::total_cmp);
    row.position = [0.99, 1.0].map(|q| quantile(&positions, q));
    row.dist = [0.5, 0.99, 1.0].map(|q| quantile(&dist, q));
    row.angle = [0.99, 1.0].map(|q| quantile(&angles, q));
    row
}

fn e(x: f64) -> String {
    if x.is_nan() {
        "—".into()
    } else if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.2e}")
    }
}

fn table(rows: &[Row]) -> String {
    let mut t = String::new();
    t += "| scalar | scale | offset | ns/test | instr/test | hits / valid | dist. err. median | p99 | max | position err. p99 | max | over tol | angle p99 (rad) | angle max | disagree: all / outside band | coords used / safe range |\n";
    t += "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for r in rows {
        if let Some(why) = &r.skipped {
            let _ = writeln!(
                t,
                "| {} | {} | {} | skipped: {why} |||||||||||||",
                r.scalar, r.scale, r.offset
            );
            continue;
        }
        let reference = r.scalar == "f64";
        let instr = r.instr.map_or("n/a".into(), |i| format!("{i:.0}"));
        let (d, pos, a, tol, dis) = if reference {
            (
                ["reference".into(), "—".into(), "—".into()],
                ["—".into(), "—".into()],
                ["—".into(), "—".into()],
                "—".into(),
                "—".into(),
            )
        } else {
            (
                r.dist.map(e),
                r.position.map(e),
                r.angle.map(e),
                r.over_tol.to_string(),
                format!("{} / {}", r.disagree, r.outside),
            )
        };
        let rej = if r.rejected > 0 {
            format!(" ({} rejected)", r.rejected)
        } else {
            String::new()
        };
        let _ = writeln!(
            t,
            "| {} | {} | {} | {:.1} | {instr} | {} / {}{rej} | {} | {} | {} | {} | {} | {tol} | {} | {} | {dis} | ±{} / ±{} |",
            r.scalar,
            r.scale,
            r.offset,
            r.ns,
            r.hits,
            r.valid,
            d[0],
            d[1],
            d[2],
            pos[0],
            pos[1],
            a[0],
            a[1],
            r.reach,
            r.limit
        );
    }
    t
}

/// A log-scale axis range around `values`, from a power of ten (so the axis has labels) to
/// `room` times the largest (so the points' labels fit).
fn around(values: impl Iterator<Item = f64>, room: f64) -> std::ops::Range<f64> {
    let (lo, hi) = values.fold((f64::INFINITY, 0.0f64), |(l, h), v| (l.min(v), h.max(v)));
    10f64.powf(lo.log10().floor())..hi * room
}

/// The plot: p99 distance error against ns per cast, both log scale, one point per scalar and
/// scale (f64, the reference, at the floor that stands for zero error); points of one scalar
/// that nearly coincide share a label.
fn plot(rows: &[Row], file: &str) -> Result<(), Box<dyn std::error::Error>> {
    let floor = 1e-16;
    let error = |r: &Row| if r.scalar == "f64" { 0.0 } else { r.dist[1] }.max(floor);
    let timed: Vec<&Row> = rows
        .iter()
        .filter(|r| r.skipped.is_none() && r.ns.is_finite() && error(r).is_finite())
        .collect();
    let root = SVGBackend::new(file, (860, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "ballcast cast: p99 contact distance error against f64, and time per cast",
            ("sans-serif", 16),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(
            around(timed.iter().map(|r| r.ns), 1.6).log_scale(),
            around(timed.iter().map(|r| error(r)), 10.0).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("ns per cast (median)")
        .y_desc("p99 distance error along the normal (scene units; 0 drawn at 1e-16)")
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    let font = |c: RGBColor| ("sans-serif", 11).into_font().color(&c);
    for (name, colour) in [
        ("f64", BLACK),
        ("f32", BLUE),
        ("I32F32", GREEN),
        ("I16F16", RED),
    ] {
        // (ns, error, label): a point within 8 % in time and a factor 1.5 in error of an
        // earlier one of the same scalar joins its label.
        let mut points: Vec<(f64, f64, String)> = Vec::new();
        for r in timed.iter().filter(|r| r.scalar == name) {
            let (x, y) = (r.ns, error(r));
            let label = if r.scale == "far" {
                "far".into()
            } else {
                format!("s={}", r.scale)
            };
            let near = |p: &&mut (f64, f64, String)| {
                (p.0 / x).ln().abs() < 0.08 && (p.1 / y).ln().abs() < 0.4
            };
            match points.iter_mut().find(|p| near(p)) {
                Some(p) => p.2 = format!("{}, {label}", p.2),
                None => points.push((x, y, label)),
            }
        }
        chart
            .draw_series(points.into_iter().map(|(x, y, label)| {
                EmptyElement::at((x, y))
                    + Circle::new((0, 0), 5, colour.filled())
                    + Text::new(label, (8, -4), font(colour))
            }))?
            .label(name)
            .legend(move |(x, y)| Circle::new((x + 8, y), 5, colour.filled()));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// `cast` over prepared cases, isolated for callgrind's `--toggle-collect`.
macro_rules! kernels {
    ($($s:ty => $f:ident),*) => {$(
        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $f(set: &[(StandardTriangle<$s>, Sweep<$s>)]) -> usize {
            let mut hits = 0;
            for (st, sw) in set {
                hits += black_box(st).cast(black_box(sw)).is_some() as usize;
            }
            hits
        }
    )*};
}
kernels!(f64 => tradeoff_cast_f64, f32 => tradeoff_cast_f32, I32F32 => tradeoff_cast_I32F32,
    I16F16 => tradeoff_cast_I16F16);

fn kernel(scalar: &str, label: &str, n: usize) {
    let label: &'static str = SCALES.into_iter().find(|s| *s == label).expect("scale");
    let (calls, hits) = match scalar {
        "f64" => {
            let p = prepared::<f64>(label, n);
            (p.len(), tradeoff_cast_f64(black_box(&p)))
        }
        "f32" => {
            let p = prepared::<f32>(label, n);
            (p.len(), tradeoff_cast_f32(black_box(&p)))
        }
        "I32F32" => {
            let p = prepared::<I32F32>(label, n);
            (p.len(), tradeoff_cast_I32F32(black_box(&p)))
        }
        "I16F16" => {
            let p = prepared::<I16F16>(label, n);
            (p.len(), tradeoff_cast_I16F16(black_box(&p)))
        }
        _ => panic!("unknown scalar {scalar}"),
    };
    println!("calls {calls} hits {hits}");
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.len() == 5 && args[1] == "--kernel" {
        return kernel(&args[2], &args[3], args[4].parse().expect("n"));
    }
    let start = Instant::now();
    // Every (scale, scalar) row is independent of the others and draws its cases from its own
    // seeded generator, so rows measured side by side on all cores give the numbers one core
    // gives, in the same order.
    let jobs: Vec<(&'static str, &'static str)> = SCALES
        .into_iter()
        .flat_map(|l| ["f64", "f32", "I32F32", "I16F16"].map(|n| (n, l)))
        .collect();
    let bar = ProgressBar::new((jobs.len() * CASES) as u64).with_style(
        ProgressStyle::with_template("{msg} {wide_bar} {percent}% ({eta} left)")
            .expect("a valid template"),
    );
    bar.set_message("measuring accuracy");
    let mut rows: Vec<Row> = jobs
        .par_iter()
        .map(|&(scalar, label)| match scalar {
            "f64" => measure::<f64>(label, &bar),
            "f32" => measure::<f32>(label, &bar),
            "I32F32" => measure::<I32F32>(label, &bar),
            _ => measure::<I16F16>(label, &bar),
        })
        .collect();
    bar.finish_and_clear();
    eprintln!("measured after {:.1} s", start.elapsed().as_secs_f64());
    // Timing: every row's repetitions interleaved, so that load from elsewhere on the machine
    // spreads over all rows rather than landing on one; the median of REPS per row.
    let mut timers: Vec<Option<Box<dyn FnMut() -> f64>>> = rows
        .iter()
        .map(|r| {
            r.skipped.is_none().then(|| match r.scalar {
                "f64" => timer::<f64>(r.scale),
                "f32" => timer::<f32>(r.scale),
                "I32F32" => timer::<I32F32>(r.scale),
                _ => timer::<I16F16>(r.scale),
            })
        })
        .collect();
    let mut samples = vec![Vec::new(); rows.len()];
    for _ in 0..REPS {
        for (t, s) in timers.iter_mut().zip(&mut samples) {
            if let Some(t) = t {
                s.push(t());
            }
        }
    }
    for (row, mut s) in rows.iter_mut().zip(samples) {
        s.sort_by(f64::total_cmp);
        row.ns = quantile(&s, 0.5);
    }
    eprintln!("timed after {:.1} s", start.elapsed().as_secs_f64());
    // Group the table by scalar.
    let order = ["f64", "f32", "I32F32", "I16F16"];
    rows.sort_by_key(|r| order.iter().position(|n| *n == r.scalar));
    let t = table(&rows);
    println!("{t}");
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/docs");
    std::fs::create_dir_all(dir).expect("docs/");
    plot(&rows, &format!("{dir}/tradeoff.svg")).expect("write docs/tradeoff.svg");
    // Wall-clock times depend on what else runs; record the machine's load with them.
    let load = std::fs::read_to_string("/proc/loadavg")
        .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "n/a".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    eprintln!("load average after the run: {load} on {cores} cores");
    let md = format!(
        "# Accuracy against speed\n\n{} random sweeps per scale (half uniform, half falling), every scalar against f64's `cast` on the same rounded inputs. Regenerate: `scripts/callgrind.sh && cargo run --release --example tradeoff`. ns/test is wall-clock time (load average {load} on {cores} cores when this was written); instr/test comes from callgrind and does not depend on load.\n\nThe position error is that of `Hit::position`, the centre at contact, along f64's normal. It is absolute, so far from the origin it is set by the spacing of the coordinates there (f32 at 10^4: 2^-10, about 1e-3, per component), while alpha's error is relative to the path. In I32F32's far row (2.4e8 from the origin) f64's own spacing, 2^-25 (3e-8), is coarser than I32F32's 2^-32: that row's position error is mostly the reference's.\n\n{t}\n![p99 distance error against ns per test](tradeoff.svg)\n",
        CASES
    );
    std::fs::write(format!("{dir}/tradeoff.md"), md).expect("write md");
    eprintln!(
        "wrote docs/tradeoff.svg and docs/tradeoff.md after {:.1} s",
        start.elapsed().as_secs_f64()
    );
}
