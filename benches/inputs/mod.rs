//! The benchmark inputs, shared by `benches/cast.rs` and `examples/callgrind_kernel.rs` so
//! that time and instruction counts are measured on the same sweeps.
#![allow(dead_code)] // each user takes a different part

use ballcast::{Scalar, Sweep, Triangle, Vec3};

pub const SWEEPS: usize = 64;
pub type P = [f64; 3];
/// A ball path: start, end, radius.
pub type Path = (P, P, f64);

/// A deterministic generator (xorshift64), fixed seed.
pub struct Rng(pub u64);
impl Rng {
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

pub const TRIANGLE: [P; 3] = [[0.3, 0.2, 0.1], [1.0, 0.4, 6.5], [7.0, -0.3, 0.5]];

/// Sweeps from above the triangle down through its plane: about half hit the face, and many
/// of the rest pass close to an edge or vertex.
pub fn single_sweeps() -> Vec<Path> {
    let mut g = Rng(0x9E37_79B9_7F4A_7C15);
    (0..SWEEPS)
        .map(|_| {
            let p0 = [g.range(-2.0, 8.0), g.range(1.0, 6.0), g.range(-2.0, 8.0)];
            let p1 = [g.range(-2.0, 8.0), g.range(-4.0, 1.0), g.range(-2.0, 8.0)];
            (p0, p1, g.range(0.1, 1.0))
        })
        .collect()
}

/// Sweeps as a scene's moving balls meet a triangle: starts anywhere in a box around it (half a
/// radius to two radii of clearance above or below its plane, or beside its edges), short moves
/// in random directions pulled down a little, as a physics step makes. Most are settled by the
/// heights (behind the plane, moving away, stopping short) or pass beside the triangle; 5 of
/// the 64 touch it (1 on the face, 4 on an edge or vertex).
pub fn near_sweeps() -> Vec<Path> {
    let mut g = Rng(0xD1B5_4A32_D192_ED03);
    (0..SWEEPS)
        .map(|_| {
            let p0 = [g.range(-1.5, 8.5), g.range(-1.5, 2.5), g.range(-1.5, 8.0)];
            let d = [g.range(-1.0, 1.0), g.range(-1.5, 0.7), g.range(-1.0, 1.0)];
            let len = g.range(0.2, 2.5) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            let p1 = [0, 1, 2].map(|i| p0[i] + d[i] * len);
            (p0, p1, g.range(0.2, 1.0))
        })
        .collect()
}

/// `n` triangles in general position, as a terrain's: a grid of 1 × 1 cells at scene scale
/// 10, each split in two, its heights jittered up to ±0.5, front faces up.
pub fn terrain(n: usize) -> Vec<[P; 3]> {
    let mut g = Rng(0x7E44_A1B2);
    let mut h = |x: f64, z: f64| [x, g.range(-0.5, 0.5), z];
    (0..n / 2)
        .flat_map(|k| {
            let (x, z) = ((k % 20) as f64 - 10.0, (k / 20 % 20) as f64 - 10.0);
            let (a, b, c, d) = (h(x, z), h(x, z + 1.0), h(x + 1.0, z + 1.0), h(x + 1.0, z));
            [[a, b, d], [b, c, d]]
        })
        .collect()
}

/// A room 16 × 8 × 16 facing inwards, its six walls tiled, the first `n` triangles of it (the
/// last walls may be partly open), and short ball moves inside it, as a physics step makes.
pub fn room(n: usize) -> (Vec<[P; 3]>, Vec<Path>) {
    let per_side = (n as f64 / 12.0).sqrt().ceil() as usize;
    let mut tris = Vec::new();
    let mut quad = |o: P, a: P, b: P| {
        let k = per_side as f64;
        let at = |i: usize, j: usize| {
            [0, 1, 2].map(|c| o[c] + a[c] * i as f64 / k + b[c] * j as f64 / k)
        };
        for i in 0..per_side {
            for j in 0..per_side {
                tris.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                tris.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    };
    let (w, h) = (16.0, 8.0);
    quad([0.0; 3], [0.0, 0.0, w], [w, 0.0, 0.0]);
    quad([0.0, h, 0.0], [w, 0.0, 0.0], [0.0, 0.0, w]);
    quad([0.0; 3], [w, 0.0, 0.0], [0.0, h, 0.0]);
    quad([0.0, 0.0, w], [0.0, h, 0.0], [w, 0.0, 0.0]);
    quad([0.0; 3], [0.0, h, 0.0], [0.0, 0.0, w]);
    quad([w, 0.0, 0.0], [0.0, 0.0, w], [0.0, h, 0.0]);
    tris.truncate(n);
    let mut g = Rng(0x5EED);
    let sweeps = (0..SWEEPS)
        .map(|_| {
            let p0 = [
                g.range(1.0, w - 1.0),
                g.range(1.0, h - 1.0),
                g.range(1.0, w - 1.0),
            ];
            let d = [g.range(-1.5, 1.5), g.range(-1.5, 1.5), g.range(-1.5, 1.5)];
            (p0, [p0[0] + d[0], p0[1] + d[1], p0[2] + d[2]], 0.5)
        })
        .collect();
    (tris, sweeps)
}

pub fn v<S: Scalar>(p: P) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}

pub fn sweeps<S: Scalar>(raw: &[Path]) -> Vec<Sweep<S>> {
    raw.iter()
        .map(|&(a, b, r)| Sweep::new(v(a), v(b), S::from_f64(r)).unwrap())
        .collect()
}

pub fn tri<S: Scalar>(t: [P; 3]) -> Triangle<S> {
    Triangle::new(v(t[0]), v(t[1]), v(t[2]))
}
