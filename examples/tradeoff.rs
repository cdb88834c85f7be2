//! Accuracy against speed, per scalar and scene scale: the same 10^6 random sweeps per scale,
//! in f32, I32F32 and I16F16, each against f64's `cast` on the same (rounded) inputs.
//!
//! Per scalar and scale it prints one markdown row: nanoseconds per `cast` (median of several
//! timed repetitions over 4096 prepared cases), instructions per `cast` (from
//! `target/callgrind.tsv`, written by `scripts/callgrind.sh`; "n/a" without it), the distance
//! error along the normal at contact, `|alpha_S - alpha_f64| * |(p1 - p0) · n_f64|` (median,
//! p99, max over the cases both report a hit), the normal's angle error, hit/miss disagreements
//! (all, and outside the rounding band) and the safe range used. It writes the table to
//! `docs/tradeoff.md` and the plot (p99 distance error against ns per test, log–log) to
//! `docs/tradeoff.svg`.
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

use ballcast::{Contact, Error, Features, Scalar, StandardTriangle, Sweep, Triangle};
use fixed::types::{I16F16, I32F32};
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

use common::{Case, P, Rng, Tolerance, add, angle, dot, norm, sub, v};

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

/// The full `cast` of a case in `S`, every feature active.
fn cast<S: Scalar>(c: &Case, r: f64) -> Result<Option<(f64, P, Contact)>, Error> {
    c.cast_with::<S>(r, Features::ALL)
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

fn measure<S: Measured>(label: &'static str) -> Row {
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
        angle: [f64::NAN; 2],
        over_tol: 0,
        disagree: 0,
        outside: 0,
        reach,
        limit,
    };
    if reach > limit {
        row.skipped = Some(format!("4s + offset = {reach} > LIMIT = {limit}"));
        return row;
    }
    if S::NAME == "f64" {
        // The reference: only speed and the hit count.
        for c in cases(label, s, off).take(CASES) {
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
    let (mut dist, mut angles) = (Vec::new(), Vec::new());
    for c in cases(label, s, off).take(CASES) {
        let c = c.rounded::<S>();
        let (Ok(got), Ok(want)) = (cast::<S>(&c, c.r), cast::<f64>(&c, c.r)) else {
            row.rejected += 1;
            continue;
        };
        row.valid += 1;
        match (got, want) {
            (Some((a, n, _)), Some((b, m, _))) => {
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
    angles.sort_by(f64::total_cmp);
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
    t += "| scalar | scale | offset | ns/test | instr/test | hits / valid | dist. err. median | p99 | max | over tol | angle p99 (rad) | angle max | disagree: all / outside band | coords used / safe range |\n";
    t += "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
    for r in rows {
        if let Some(why) = &r.skipped {
            let _ = writeln!(
                t,
                "| {} | {} | {} | skipped: {why} |||||||||||",
                r.scalar, r.scale, r.offset
            );
            continue;
        }
        let reference = r.scalar == "f64";
        let instr = r.instr.map_or("n/a".into(), |i| format!("{i:.0}"));
        let (d, a, tol, dis) = if reference {
            (
                ["reference".into(), "—".into(), "—".into()],
                ["—".into(), "—".into()],
                "—".into(),
                "—".into(),
            )
        } else {
            (
                r.dist.map(e),
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
            "| {} | {} | {} | {:.1} | {instr} | {} / {}{rej} | {} | {} | {} | {tol} | {} | {} | {dis} | ±{} / ±{} |",
            r.scalar,
            r.scale,
            r.offset,
            r.ns,
            r.hits,
            r.valid,
            d[0],
            d[1],
            d[2],
            a[0],
            a[1],
            r.reach,
            r.limit
        );
    }
    t
}

/// The plot: p99 distance error against ns per test, both log scale, one point per scalar and
/// scale, as hand-written SVG.
fn svg(rows: &[Row]) -> String {
    let (w, h) = (860.0, 560.0);
    let (l, r, top, bot) = (90.0, 190.0, 50.0, 70.0);
    let pts: Vec<&Row> = rows
        .iter()
        .filter(|r| r.skipped.is_none() && r.scalar != "f64" && r.dist[1].is_finite())
        .collect();
    let floor = 1e-16;
    let ys: Vec<f64> = pts.iter().map(|r| r.dist[1].max(floor)).collect();
    let xs: Vec<f64> = rows
        .iter()
        .filter(|r| r.ns.is_finite())
        .map(|r| r.ns)
        .collect();
    let dec = |v: &[f64], lo: bool| {
        let f = if lo { f64::min } else { f64::max };
        let m = v
            .iter()
            .copied()
            .fold(if lo { f64::INFINITY } else { 0.0 }, f);
        if lo {
            m.log10().floor()
        } else {
            m.log10().ceil()
        }
    };
    let (x0, mut x1) = (dec(&xs, true), dec(&xs, false));
    let (y0, mut y1) = (dec(&ys, true), dec(&ys, false));
    if x1 <= x0 {
        x1 = x0 + 1.0;
    }
    if y1 <= y0 {
        y1 = y0 + 1.0;
    }
    let px = |ns: f64| l + (ns.log10() - x0) / (x1 - x0) * (w - l - r);
    let py = |err: f64| h - bot - (err.log10() - y0) / (y1 - y0) * (h - top - bot);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="24" font-size="15" text-anchor="middle">ballcast cast: p99 contact distance error vs f64 against time per test</text>"#,
        (l + w - r) / 2.0
    );
    // Grid and tick labels, one per decade (with 2 and 5 minor lines on x).
    for k in (x0 as i32)..=(x1 as i32) {
        for m in [1.0, 2.0, 5.0] {
            let v = m * 10f64.powi(k);
            if v.log10() > x1 + 1e-9 {
                continue;
            }
            let x = px(v);
            let stroke = if m == 1.0 { "#bbb" } else { "#e4e4e4" };
            let _ = writeln!(
                s,
                r#"<line x1="{x:.1}" y1="{top}" x2="{x:.1}" y2="{}" stroke="{stroke}"/>"#,
                h - bot
            );
            let _ = writeln!(
                s,
                r#"<text x="{x:.1}" y="{}" text-anchor="middle">{v}</text>"#,
                h - bot + 16.0
            );
        }
    }
    for k in (y0 as i32)..=(y1 as i32) {
        let y = py(10f64.powi(k));
        let _ = writeln!(
            s,
            r##"<line x1="{l}" y1="{y:.1}" x2="{}" y2="{y:.1}" stroke="#bbb"/>"##,
            w - r
        );
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{:.1}" text-anchor="end">1e{k}</text>"#,
            l - 6.0,
            y + 4.0
        );
    }
    let _ = writeln!(
        s,
        r#"<rect x="{l}" y="{top}" width="{}" height="{}" fill="none" stroke="black"/>"#,
        w - l - r,
        h - top - bot
    );
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" text-anchor="middle">ns per cast (median, log scale)</text>"#,
        (l + w - r) / 2.0,
        h - bot + 40.0
    );
    let _ = writeln!(
        s,
        r#"<text transform="translate(24 {}) rotate(-90)" text-anchor="middle">p99 distance error along the normal (scene units, log scale)</text>"#,
        (top + h - bot) / 2.0
    );
    // f64's time per scale: ticks along the bottom.
    for row in rows
        .iter()
        .filter(|r| r.scalar == "f64" && r.ns.is_finite())
    {
        let x = px(row.ns);
        let _ = writeln!(
            s,
            r##"<line x1="{x:.1}" y1="{}" x2="{x:.1}" y2="{}" stroke="#555" stroke-dasharray="3 2"/>"##,
            h - bot - 14.0,
            h - bot
        );
    }
    if let Some(x) = rows
        .iter()
        .filter(|r| r.scalar == "f64" && r.ns.is_finite())
        .map(|r| px(r.ns))
        .reduce(f64::max)
    {
        let _ = writeln!(
            s,
            r##"<text x="{:.1}" y="{}" font-size="11" fill="#555">f64</text>"##,
            x + 4.0,
            h - bot - 4.0
        );
    }
    let color = |n: &str| match n {
        "f32" => "#1f77b4",
        "I32F32" => "#2ca02c",
        _ => "#d62728",
    };
    // Points, then labels: points of one scalar closer than a label's height share one label.
    let mut labels: Vec<(f64, f64, &str, String)> = Vec::new();
    for (row, &y) in pts.iter().zip(&ys) {
        let (x, y) = (px(row.ns), py(y));
        let c = color(row.scalar);
        let _ = writeln!(
            s,
            r#"<circle cx="{x:.1}" cy="{y:.1}" r="5" fill="{c}" stroke="black" stroke-width="0.5"/>"#
        );
        let label = if row.scale == "far" {
            "far".to_string()
        } else {
            format!("s={}", row.scale)
        };
        match labels
            .iter_mut()
            .find(|(lx, ly, lc, _)| *lc == c && (lx - x).abs() < 40.0 && (ly - y).abs() < 12.0)
        {
            Some(l) => l.3 = format!("{}, {label}", l.3),
            None => labels.push((x, y, c, label)),
        }
    }
    for (x, y, c, label) in labels {
        let _ = writeln!(
            s,
            r#"<text x="{:.1}" y="{:.1}" fill="{c}" font-size="11">{label}</text>"#,
            x + 8.0,
            y + 4.0
        );
    }
    // Legend.
    let lx = w - r + 15.0;
    let _ = writeln!(
        s,
        r#"<text x="{lx}" y="{}" font-weight="bold">scalar</text>"#,
        top + 10.0
    );
    for (i, n) in ["f32", "I32F32", "I16F16"].iter().enumerate() {
        let y = top + 30.0 + 20.0 * i as f64;
        let _ = writeln!(
            s,
            r#"<circle cx="{}" cy="{}" r="5" fill="{}" stroke="black" stroke-width="0.5"/><text x="{}" y="{}">{n}</text>"#,
            lx + 5.0,
            y - 4.0,
            color(n),
            lx + 16.0,
            y
        );
    }
    let notes = [
        "labels: scene scale s",
        "(triangles ±s, paths ±4s);",
        "far: s=10 offset by",
        "1e4 (f32), 0.9·LIMIT (fixed)",
        "dashed ticks at bottom:",
        "f64 ns per scale",
        "(the reference, error 0)",
        "errors of 0 drawn at 1e-16",
    ];
    for (i, t) in notes.iter().enumerate() {
        let _ = writeln!(
            s,
            r##"<text x="{lx}" y="{}" font-size="11" fill="#333">{t}</text>"##,
            top + 110.0 + 15.0 * i as f64
        );
    }
    s += "</svg>\n";
    s
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
    let mut rows = Vec::new();
    for label in SCALES {
        rows.push(measure::<f64>(label));
        rows.push(measure::<f32>(label));
        rows.push(measure::<I32F32>(label));
        rows.push(measure::<I16F16>(label));
        eprintln!(
            "scale {label} done after {:.1} s",
            start.elapsed().as_secs_f64()
        );
    }
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
    std::fs::write(format!("{dir}/tradeoff.svg"), svg(&rows)).expect("write svg");
    // Wall-clock times depend on what else runs; record the machine's load with them.
    let load = std::fs::read_to_string("/proc/loadavg")
        .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
        .unwrap_or_else(|_| "n/a".into());
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    eprintln!("load average after the run: {load} on {cores} cores");
    let md = format!(
        "# Accuracy against speed\n\n{} random sweeps per scale (half uniform, half falling), every scalar against f64's `cast` on the same rounded inputs. Regenerate: `scripts/callgrind.sh && cargo run --release --example tradeoff`. ns/test is wall-clock time (load average {load} on {cores} cores when this was written); instr/test comes from callgrind and does not depend on load.\n\n{t}\n![p99 distance error against ns per test](tradeoff.svg)\n",
        CASES
    );
    std::fs::write(format!("{dir}/tradeoff.md"), md).expect("write md");
    eprintln!(
        "wrote docs/tradeoff.svg and docs/tradeoff.md after {:.1} s",
        start.elapsed().as_secs_f64()
    );
}
