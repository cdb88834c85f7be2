//! The firmware example's scene, as plain f64 triangles: a 6 × 6 height field (one-unit cells)
//! that rises into a ramp beyond x = 2 and tilts towards the corner at the origin, closed by two
//! walls meeting there. `cargo run --example bake` prepares it for flash (`baked.rs`).

/// Cells per side of the height field.
pub const CELLS: usize = 6;
/// Triangles: two per cell, and two walls of `CELLS` panels, two triangles each.
pub const TRIANGLES: usize = 2 * CELLS * CELLS + 4 * CELLS;

fn height(x: f64, z: f64) -> f64 {
    let ramp = if x > 2.0 { 0.5 * (x - 2.0) } else { 0.0 };
    0.125 * (x + z) + ramp
}

/// The triangles, counter-clockwise seen from the inside of the room.
pub fn triangles() -> [[[f64; 3]; 3]; TRIANGLES] {
    let mut out = [[[0.0; 3]; 3]; TRIANGLES];
    let p = |x: usize, z: usize| [x as f64, height(x as f64, z as f64), z as f64];
    let mut n = 0;
    for i in 0..CELLS {
        for j in 0..CELLS {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            out[n] = [a, b, c];
            out[n + 1] = [a, c, d];
            n += 2;
        }
    }
    for k in 0..CELLS {
        let (u, w, lo, hi) = (k as f64, k as f64 + 1.0, -1.0, 6.0);
        out[n] = [[0.0, lo, u], [0.0, hi, u], [0.0, hi, w]];
        out[n + 1] = [[0.0, lo, u], [0.0, hi, w], [0.0, lo, w]];
        out[n + 2] = [[u, lo, 0.0], [w, lo, 0.0], [w, hi, 0.0]];
        out[n + 3] = [[u, lo, 0.0], [w, hi, 0.0], [u, hi, 0.0]];
        n += 4;
    }
    out
}
