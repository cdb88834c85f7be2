//! The terrain inputs of `benches/mesh.rs`, shared with `examples/callgrind_mesh.rs` so that
//! time and instruction counts are measured on the same sweeps: a bumpy heightfield (1-unit
//! cells, heights within ±0.65 from a fixed sin/cos formula, front faces up), short moves and
//! long casts over it.

use super::inputs::{P, Path, Rng};

/// Sweeps per query benchmark.
pub const QUERIES: usize = 256;

/// The terrain height at `(x, z)`: within ±0.65.
pub fn height(x: f64, z: f64) -> f64 {
    0.4 * (0.7 * x).sin() * (0.5 * z).cos() + 0.25 * (1.3 * x + 0.9 * z).sin()
}

/// `2 w²` triangles over `[-w/2, w/2]²`, front faces up.
pub fn heightfield(w: usize) -> Vec<[P; 3]> {
    let half = w as f64 / 2.0;
    let p = |i: usize, j: usize| {
        let (x, z) = (i as f64 - half, j as f64 - half);
        [x, height(x, z), z]
    };
    let mut out = Vec::with_capacity(2 * w * w);
    for i in 0..w {
        for j in 0..w {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            out.push([a, b, c]);
            out.push([a, c, d]);
        }
    }
    out
}

/// Short moves: radius 0.2–0.5, starting 0.1–0.3 above the ground, 0.5 forward and 0.5 down.
pub fn short_moves(w: usize, rng: &mut Rng) -> Vec<Path> {
    let half = w as f64 / 2.0 - 1.0;
    (0..QUERIES)
        .map(|_| {
            let r = rng.range(0.2, 0.5);
            let (x, z) = (rng.range(-half, half), rng.range(-half, half));
            let p0 = [x, height(x, z) + r + rng.range(0.1, 0.3), z];
            let a = rng.range(0.0, std::f64::consts::TAU);
            (p0, [x + 0.5 * a.cos(), p0[1] - 0.5, z + 0.5 * a.sin()], r)
        })
        .collect()
}

/// Long casts: radius 0.1–0.5, from 2–5 above the ground to 1 below it, across 0.5–1 terrain
/// widths horizontally.
pub fn long_casts(w: usize, rng: &mut Rng) -> Vec<Path> {
    let (width, half) = (w as f64, w as f64 / 2.0 - 0.5);
    let mut out = Vec::new();
    while out.len() < QUERIES {
        let (x0, z0) = (rng.range(-half, half), rng.range(-half, half));
        let (x1, z1) = (rng.range(-half, half), rng.range(-half, half));
        let dist = ((x1 - x0).powi(2) + (z1 - z0).powi(2)).sqrt();
        if dist < 0.5 * width || dist > width {
            continue;
        }
        let p0 = [x0, height(x0, z0) + rng.range(2.0, 5.0), z0];
        let p1 = [x1, height(x1, z1) - 1.0, z1];
        out.push((p0, p1, rng.range(0.1, 0.5)));
    }
    out
}

/// The sweeps of a terrain of width `w`: short moves, then long casts (one generator, seeded by
/// the width).
pub fn queries(w: usize) -> (Vec<Path>, Vec<Path>) {
    let mut rng = Rng(0x4D45_5348 + w as u64);
    let short = short_moves(w, &mut rng);
    let long = long_casts(w, &mut rng);
    (short, long)
}
