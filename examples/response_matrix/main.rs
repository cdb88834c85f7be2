//! A matrix of character scenes for judging a change to the response: walls leaning back or
//! over, inside corners and convex edges, stairs up and down, V-shaped and lopsided ditches,
//! bumpy ground beside a wall, a pocket of steep bumps and standing still on slopes (the ditches
//! also 1 400 units out and turned), each run
//! through `slide::Character` in `f64`, `f32` and `I16F16` at 60 to 960 Hz (a few seconds on
//! two cores). A rule that stops a ball in one scene often makes another jitter or stick,
//! which a test of the scene at hand does not show: run the matrix before and after a change
//! to the response, and compare.
//!
//! ```sh
//! cargo run --release --example response_matrix > before.txt   # on the old code
//! cargo run --release --example response_matrix > after.txt    # on the new
//! cargo run --release --example response_matrix -- --compare before.txt after.txt
//! ```
//!
//! Each line is one scene, scalar and rate, measured after the first two seconds of five:
//! `prog` (distance made along the scene's heading), `stuck` (frames that made less than a
//! twentieth of the walk's step along it), `zig` (the largest vertical move that reversed the
//! one before: a bob or a jitter), `ground` (frames on a floor) and `pen` (the deepest overlap
//! with the scene). `--compare` lists the lines where the second file is worse or better by
//! more than the thresholds in `changes`, counts them, and says on how many lines `f32` and
//! `I16F16` make `f64`'s progress. The lines are evidence to read, not a verdict: more progress
//! down a ditch too steep to stand in can be a ball flying off it, and an `I16F16` line that
//! makes less progress than before may now be the one that agrees with `f64`.

use ballcast::bvh::nodes_for;
use ballcast::slide::Character;
use ballcast::{Degenerates, Mesh, Node, Scalar, Triangle, Vec3, penetration};
use fixed::types::I16F16;
use rayon::prelude::*;
use std::collections::BTreeMap;

mod scenes;

use scenes::{Case, P, cases};

fn v<S: Scalar>(p: P) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}

/// The case's line for scalar `S` at `hz` frames a second.
fn run<S: Scalar>(case: &Case, hz: f64, scalar: &str) -> String {
    let tris: Vec<Triangle<S>> = case
        .tris
        .iter()
        .map(|t| Triangle::new(v(t[0]), v(t[1]), v(t[2])))
        .collect();
    let n = tris.len();
    let (mut nodes, mut prepared) = (vec![Node::default(); nodes_for(n)], vec![Mesh::filler(); n]);
    let (mut order, mut scratch) = (vec![0; n], vec![0; 6 * n]);
    let built = Mesh::build(
        &tris,
        Degenerates::Refuse,
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    );
    let scene = match built {
        Ok((mesh, _)) => mesh,
        Err(e) => return format!("{} | {scalar} | {hz} | refused: {e}", case.name),
    };
    let (r, dt, g) = (
        S::from_f64(0.5),
        S::from_f64(1.0 / hz),
        v::<S>([0.0, -9.81, 0.0]),
    );
    let mut me = Character::new(v(case.start), r).unwrap();
    let step = (case.wish[0].hypot(case.wish[2])) / hz;
    let (mut prog, mut stuck, mut zig, mut ground, mut pen) = (0.0, 0, 0.0f64, 0, 0.0f64);
    let mut last_dy = 0.0;
    let back = |p: Vec3<S>| p.to_array().map(|c| c.to_f64());
    for frame in 0..(5.0 * hz) as usize {
        let before = back(me.position);
        if me.update(&scene, v(case.wish), g, dt).is_err() {
            return format!("{} | {scalar} | {hz} | error at frame {frame}", case.name);
        }
        if (frame as f64) < 2.0 * hz {
            continue;
        }
        let now = back(me.position);
        let d = [now[0] - before[0], now[1] - before[1], now[2] - before[2]];
        let along = d[0] * case.heading[0] + d[1] * case.heading[1] + d[2] * case.heading[2];
        prog += along;
        // (Standing still, no frame is stuck.)
        stuck += (along < step / 20.0 && step > 0.0) as usize;
        if d[1] * last_dy < 0.0 {
            zig = zig.max(d[1].abs().min(last_dy.abs()));
        }
        last_dy = d[1];
        ground += me.is_grounded() as usize;
        let deep = penetration(&scene, me.position, r).ok().flatten();
        pen = pen.max(deep.map_or(0.0, |p| p.depth.to_f64()));
    }
    format!(
        "{} | {scalar} | {hz} | prog {prog:.3} stuck {stuck} zig {zig:.1e} ground {ground} pen {pen:.1e}",
        case.name
    )
}

/// The measures of a line, by name.
fn measures(line: &str) -> BTreeMap<&str, f64> {
    let fields = line.rsplit(" | ").next().unwrap_or("");
    let words: Vec<&str> = fields.split_whitespace().collect();
    words
        .chunks(2)
        .filter_map(|w| Some((w[0], w.get(1)?.parse().ok()?)))
        .collect()
}

/// A measure's name, and whether its second value is worse than its first.
type Rule = (&'static str, fn(f64, f64) -> bool);

/// What got worse, and what better, from `a` to `b` beyond what rounding moves: progress by
/// 2 %, stuck and grounded frames by 2, a zig by half and 2e-5, an overlap by 1e-4.
fn changes(a: &BTreeMap<&str, f64>, b: &BTreeMap<&str, f64>) -> [Vec<String>; 2] {
    let get = |m: &BTreeMap<&str, f64>, k| m.get(k).copied().unwrap_or(f64::NAN);
    // Per measure: whether `y` is worse than `x`.
    let rules: [Rule; 5] = [
        ("prog", |x, y| y < x - 0.02 * x.abs().max(1.0)),
        ("stuck", |x, y| y > x + 2.0),
        ("ground", |x, y| y < x - 2.0),
        ("zig", |x, y| y > 1.5 * x + 2e-5),
        ("pen", |x, y| y > x + 1e-4),
    ];
    let mut out = [Vec::new(), Vec::new()];
    for (k, bad) in rules {
        let (x, y) = (get(a, k), get(b, k));
        let said = format!("{k} {x} -> {y}");
        if bad(x, y) {
            out[0].push(said);
        } else if bad(y, x) {
            out[1].push(said);
        }
    }
    out
}

fn compare(before: &str, after: &str) {
    let read = |p: &str| std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{p}: {e}"));
    let (a, b) = (read(before), read(after));
    let key = |l: &str| l.rsplit_once(" | ").map(|(k, _)| k.to_string());
    let old: BTreeMap<String, &str> = a.lines().filter_map(|l| Some((key(l)?, l))).collect();
    let (mut w, mut bt) = (0, 0);
    for line in b.lines() {
        let Some(old) = key(line).and_then(|k| old.get(&k)) else {
            continue;
        };
        let [worse, better] = changes(&measures(old), &measures(line));
        for (tag, list, count) in [("worse", worse, &mut w), ("better", better, &mut bt)] {
            if !list.is_empty() {
                *count += 1;
                println!(
                    "{tag}: {} | {}",
                    key(line).unwrap_or_default(),
                    list.join("; ")
                );
            }
        }
    }
    println!("{w} lines worse, {bt} better, of {}", b.lines().count());
    for (file, text) in [(before, &a), (after, &b)] {
        println!("{file}: {}", agreement(text));
    }
}

/// How many lines of `f32` and of `I16F16` make the progress `f64` makes in the same scene at
/// the same rate, within 2 %: the cross-precision promise, scene by scene.
fn agreement(text: &str) -> String {
    let prog = |l: &str| measures(l).get("prog").copied();
    let mut f64s = BTreeMap::new();
    let mut rows = Vec::new();
    for l in text.lines() {
        let parts: Vec<&str> = l.split(" | ").collect();
        if let [scene, scalar, hz, _] = parts.as_slice() {
            if *scalar == "f64" {
                f64s.insert((*scene, *hz), prog(l));
            } else {
                rows.push((*scalar, (*scene, *hz), prog(l)));
            }
        }
    }
    ["f32", "I16F16"]
        .map(|s| {
            let mine: Vec<_> = rows.iter().filter(|r| r.0 == s).collect();
            let near = mine.iter().filter(|(_, key, p)| {
                matches!((f64s.get(key).copied().flatten(), p), (Some(x), Some(y)) if (x - y).abs() <= 0.02 * x.abs().max(1.0))
            });
            format!("{s} within 2 % of f64's progress on {} of {}", near.count(), mine.len())
        })
        .join(", ")
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let [_, flag, before, after] = args.as_slice()
        && flag == "--compare"
    {
        return compare(before, after);
    }
    let cases = cases();
    let jobs: Vec<(usize, f64, usize)> = (0..cases.len())
        .flat_map(|c| {
            [60.0, 120.0, 240.0, 480.0, 960.0]
                .into_iter()
                .flat_map(move |hz| (0..3).map(move |s| (c, hz, s)))
        })
        .collect();
    let lines: Vec<String> = jobs
        .par_iter()
        .map(|&(c, hz, s)| match s {
            0 => run::<f64>(&cases[c], hz, "f64"),
            1 => run::<f32>(&cases[c], hz, "f32"),
            _ => run::<I16F16>(&cases[c], hz, "I16F16"),
        })
        .collect();
    for l in lines {
        println!("{l}");
    }
}
