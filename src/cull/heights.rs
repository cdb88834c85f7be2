//! The heights of a fixed-point sweep above a triangle's plane, bounded in 64-bit integers
//! before the triangle is prepared: where `f64` is software (a Cortex-M0), a compact mesh's
//! triangle behind the integer box is passed by here when the heights its frame would give
//! certainly fail [`within_reach`], without the frame's three
//! square roots and normalisations.
//!
//! The exact normal `N = (v1 − v0) × (v2 − v0)` of the vertices' bits (`I16F16` vertices lie
//! within `±2^28` steps, so edges within `2^29` and `N` within `2^59`) is shifted down to below
//! `2^30` per component (`N'`, rounded down), and heights times `|N'|` follow exactly from
//! products of 32-bit operands: `(p − v0) · N'`. The prepared normal is tilted from the exact
//! one by at most the bound [`Path::near_plane`](super::Path::near_plane) allows (a unit
//! vector's step over the edges' product and `|N|`); here twice that, plus `2^-26` for `N'`'s
//! rounding and the prepared normal's length, times the larger distance `|p − v0|` (by its L1
//! norm) of the path's ends, bounds how far a prepared height can stray. A path whose both ends
//! (the start, and the centre at the reach) lie on the same side of the plane, farther than the
//! radius, `above_at`'s allowance and that bound, cannot pass the heights test: on the front,
//! the ball is still too high at the reach or moves away; behind, it never comes within `r`.
//! A one-sided triangle is also passed by where the path starts behind its plane by more than
//! the bound (the heights test lets no such sweep through).

use super::unit_bits;
use crate::contact::within_reach;
use crate::scalar::{LeadingZeros, isqrt_nearest_64, wide_mul_i32, wide_mul_u32};
use crate::{Scalar, Sweep, Vec3};

/// The largest magnitude of a vertex or sweep coordinate's bits this bound is made for.
const RANGE: i64 = 1 << 28;

/// A fixed-point sweep in its scalar's units (`2^-frac`), with what every triangle's bound needs.
pub(crate) struct UnitHeights {
    p0: [i64; 3],
    p1: [i64; 3],
    d: [i64; 3],
    frac: u32,
    /// `r`, the allowance of `above_at` (`4 · 8` units and twice `4 EPSILON` times the path's
    /// largest component) and 16 units for the roundings of the heights' interpolation.
    height: u32,
}

impl UnitHeights {
    /// The sweep's bound, for a fixed-point scalar with at most 30 fractional bits whose
    /// coordinates lie within `±2^28` units (all of `I16F16`'s range); `None` otherwise.
    pub(crate) fn new<S: Scalar>(sweep: &Sweep<S>) -> Option<Self> {
        let (r, frac) = sweep.radius().fixed_bits()?;
        let (p0, p1) = (in_range(sweep.p0())?, in_range(sweep.p1())?);
        if frac > 30 || r > RANGE {
            return None;
        }
        let d = zip(p1, p0, |a, b| a - b);
        let length = d.iter().fold(0, |m, x| m.max(x.unsigned_abs()));
        // `tie().mul(length)` is `4 length / 2^frac` rounded: one unit more covers it.
        let tie = ((4 * length) >> frac) + 1;
        let height = r as u64 + 32 + 2 * tie + 16;
        Some(Self {
            p0,
            p1,
            d,
            frac,
            height: u32::try_from(height).ok()?,
        })
    }

    /// Whether the heights of the sweep above the plane of the triangle `v`, up to alpha
    /// `reach`, leave no contact with it possible (the module docs give the bound). False
    /// where the bound does not apply: vertices beyond its range, a zero normal, a sliver
    /// whose tilt exceeds 32 bits.
    pub(crate) fn rule_out<S: Scalar>(
        &self,
        sweep: &Sweep<S>,
        v: [Vec3<S>; 3],
        reach: S,
        one_sided: bool,
    ) -> bool {
        self.try_rule_out(sweep, v, reach, one_sided)
            .unwrap_or(false)
    }

    fn try_rule_out<S: Scalar>(
        &self,
        sweep: &Sweep<S>,
        v: [Vec3<S>; 3],
        reach: S,
        one_sided: bool,
    ) -> Option<bool> {
        let [a, b, c] = [in_range(v[0])?, in_range(v[1])?, in_range(v[2])?];
        // Within 2^29: 32-bit operands.
        let sub = |p: [i64; 3], q: [i64; 3]| zip(p, q, |a, b| (a - b) as i32);
        let (e, f, g) = (sub(b, a), sub(c, a), sub(c, b));
        let m = |x: i32, y: i32| wide_mul_i32(x, y);
        let n = [
            m(e[1], f[2]) - m(e[2], f[1]),
            m(e[2], f[0]) - m(e[0], f[2]),
            m(e[0], f[1]) - m(e[1], f[0]),
        ];
        let big = n.iter().fold(0, |m, x| m.max(x.unsigned_abs()));
        if big == 0 {
            return None;
        }
        // Square to an axis (a level's floors and walls), the frame's normal is that axis
        // exactly and its heights are the coordinates' differences: decided exactly.
        if let Some((k, up)) = axis(n) {
            let along = |p: Vec3<S>| {
                let d = p - v[0];
                let y = match k {
                    0 => d.x,
                    1 => d.y,
                    _ => d.z,
                };
                if up { y } else { -y }
            };
            let heights = (along(sweep.p0()), along(sweep.p1()));
            return Some(within_reach(sweep, heights, !one_sided, reach).is_none());
        }
        // N' = N / 2^s rounded down, below 2^30 per component.
        let s = (64 - big.clz()).saturating_sub(30);
        let n = n.map(|x| low_word(x, s));
        let n2 = n
            .iter()
            .fold(0u64, |sum, &x| sum + wide_mul_i32(x, x) as u64);
        let norm = u32::try_from(isqrt_nearest_64(n2) + 1).ok()?;
        // The start and the centre at the reach (rounded down: a unit off per component),
        // from `v0`. A reach is at most `1 + 4 EPSILON` (an alpha and the tie window).
        let t = reach.fixed_bits()?.0.max(0);
        let t = i32::try_from(t)
            .ok()
            .filter(|&t| t <= (1 << self.frac) + 8)?;
        let q0 = sub(self.p0, a);
        let qr = if t == 1 << self.frac {
            sub(self.p1, a)
        } else {
            zip(q0, self.d, |q, d| {
                q + low_word(wide_mul_i32(d as i32, t), self.frac)
            })
        };
        let dot = |q: [i32; 3]| zip(q, n, wide_mul_i32).iter().sum::<i64>();
        let (h0, hr) = (dot(q0), dot(qr));
        // The tilt times |N'|: twice a unit vector's step (2^-(frac+6)) times the two longest
        // edges' largest components over |N| = |N'| 2^s, plus 2^-26 of |N'|.
        let l = [e, f, g].map(|x| x.iter().fold(0u32, |m, c| m.max(c.unsigned_abs())));
        let [l1, l2, _] = sorted(l);
        let product = wide_mul_u32(l1, l2);
        let tilt = (product >> (self.frac + 5 + s)) + (norm >> 26) as u64 + 1;
        let far = [q0, qr]
            .iter()
            .fold(0u32, |m, q| m.max(q.iter().map(|c| c.unsigned_abs()).sum()))
            + 4;
        let stray = wide_mul_u32(far, u32::try_from(tilt).ok()?);
        let limit = wide_mul_u32(self.height, norm).checked_add(stray + 2 * norm as u64)?;
        let limit = i64::try_from(limit).ok()?;
        let beyond = (h0 > limit && hr > limit) || (h0 < -limit && hr < -limit);
        let behind = one_sided && h0 < -i64::try_from(stray + 2 * norm as u64).ok()?;
        Some(beyond || behind)
    }
}

/// `x / 2^s` rounded down, for `s < 32` and a quotient that fits 32 bits: from the two 32-bit
/// halves (a 64-bit shift is a library call on a Cortex-M0).
fn low_word(x: i64, s: u32) -> i32 {
    let (low, high) = (x as u32, (x >> 32) as u32);
    if s == 0 {
        low as i32
    } else {
        ((low >> s) | (high << (32 - s))) as i32
    }
}

/// `[f(a0, b0), f(a1, b1), f(a2, b2)]`, by destructuring (no index to check).
fn zip<T, U, V>([a0, a1, a2]: [T; 3], [b0, b1, b2]: [U; 3], f: impl Fn(T, U) -> V) -> [V; 3] {
    [f(a0, b0), f(a1, b1), f(a2, b2)]
}

/// The one axis `n` has a nonzero component along, if it has one alone, and whether that
/// component is positive.
fn axis([x, y, z]: [i64; 3]) -> Option<(usize, bool)> {
    match (x != 0, y != 0, z != 0) {
        (true, false, false) => Some((0, x > 0)),
        (false, true, false) => Some((1, y > 0)),
        (false, false, true) => Some((2, z > 0)),
        _ => None,
    }
}

/// A point's [`unit_bits`], if every one lies within [`RANGE`].
fn in_range<S: Scalar>(p: Vec3<S>) -> Option<[i64; 3]> {
    unit_bits(p).filter(|b| b.iter().all(|x| x.abs() <= RANGE))
}

/// Three values, largest first.
fn sorted([a, b, c]: [u32; 3]) -> [u32; 3] {
    let (a, b) = if a < b { (b, a) } else { (a, b) };
    let (b, c) = if b < c { (c, b) } else { (b, c) };
    if a < b { [b, a, c] } else { [a, b, c] }
}

#[cfg(test)]
mod tests {
    use super::UnitHeights;
    use crate::contact::within_reach;
    use crate::triangle::Frame;
    use crate::xorshift::Rng;
    use crate::{Scalar, Sweep, Triangle, Vec3};
    use fixed::types::I16F16;

    fn point<S: Scalar>(p: [f64; 3]) -> Vec3<S> {
        Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
    }

    /// Every triangle the bound passes by, the heights of its frame pass by too (so the
    /// answer cannot change), on terrain cells, random triangles, slivers and needles, near the
    /// origin and near the range's ends, one- and two-sided, short moves and long casts, paths
    /// whose ends lie just beyond the radius from the plane, over random reaches; and the bound
    /// passes by most of what the heights do.
    #[test]
    fn bound_passes_by_only_what_the_heights_do() {
        let mut rng = Rng(0x04e1_6475);
        let (mut ruled, mut exact, mut tried) = (0u32, 0u32, 0u32);
        for k in 0..200_000 {
            let far = if k % 5 == 0 { 4000.0 } else { 8.0 };
            let c = [0, 1, 2].map(|_| far * rng.signed());
            let size = [0.01, 1.0, 30.0][k % 3];
            let mut v = [0, 1, 2].map(|_| [0, 1, 2].map(|a| c[a] + size * rng.signed()));
            match k % 4 {
                // A terrain cell.
                0 => v.iter_mut().for_each(|p| p[1] = c[1] + 0.1 * (p[1] - c[1])),
                // A sliver, or a needle.
                1 => {
                    let (t, w) = (0.5 + 0.5 * rng.signed(), [1e-2, 1e-4][(k / 4) % 2]);
                    v[2] = [0, 1, 2].map(|a| v[0][a] + t * (v[1][a] - v[0][a]) + w * rng.signed());
                }
                // A floor or a wall, square to an axis.
                2 => {
                    let a = k / 4 % 3;
                    v.iter_mut().for_each(|p| p[a] = c[a]);
                }
                _ => {}
            }
            let v = v.map(|p| p.map(|x| x.clamp(-4095.0, 4095.0)));
            let tri = Triangle::new(point::<I16F16>(v[0]), point(v[1]), point(v[2]));
            let Ok(frame) = Frame::of(&tri) else {
                continue;
            };
            let two_sided = k % 7 == 0;
            // The exact unit normal, for sweeps that start and end near the bound's limit.
            let (e, f) = (
                [0, 1, 2].map(|a| v[1][a] - v[0][a]),
                [0, 1, 2].map(|a| v[2][a] - v[0][a]),
            );
            let n = [
                e[1] * f[2] - e[2] * f[1],
                e[2] * f[0] - e[0] * f[2],
                e[0] * f[1] - e[1] * f[0],
            ];
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            let n = n.map(|x| x / len);
            for j in 0..16 {
                let reach = if j % 2 == 0 { 2.0 * size + 1.0 } else { 0.3 };
                let r = (0.05 + 0.5 * (rng.signed() + 1.0)) * size.min(1.0);
                let mut p0 = [0, 1, 2].map(|a| v[0][a] + reach * rng.signed());
                let mut p1 = [0, 1, 2].map(|a| p0[a] + reach * rng.signed());
                if j >= 8 {
                    // Both ends at the radius from the plane (resting), or a little more, on
                    // one side.
                    let side = if j < 12 { 1.0 } else { -1.0 };
                    let scale = [0.0, 1e-4, 3e-3, 0.05][j % 4];
                    let h = |rng: &mut Rng| side * (r + (rng.signed() + 1.0) * scale);
                    let (h0, h1) = (h(&mut rng), h(&mut rng));
                    let at = |p: [f64; 3], h: f64| {
                        let off = (0..3).map(|a| (p[a] - v[0][a]) * n[a]).sum::<f64>();
                        [0, 1, 2].map(|a| p[a] + (h - off) * n[a])
                    };
                    (p0, p1) = (at(p0, h0), at(p1, h1));
                }
                let clamp = |p: [f64; 3]| point::<I16F16>(p.map(|x| x.clamp(-4096.0, 4096.0)));
                let Ok(sweep) = Sweep::new(clamp(p0), clamp(p1), I16F16::from_f64(r)) else {
                    continue;
                };
                let Some(bound) = UnitHeights::new(&sweep) else {
                    continue;
                };
                let alpha = I16F16::from_f64([1.0, 0.5, 0.01, 1.0 + 4.0 / 65536.0][j % 4]);
                let out = bound.rule_out(&sweep, tri.vertices(), alpha, !two_sided);
                let heights = frame.heights(&sweep);
                let passes = within_reach(&sweep, heights, two_sided, alpha).is_some();
                assert!(
                    !(out && passes),
                    "{v:?} {p0:?} -> {p1:?} r {r} reach {alpha}"
                );
                tried += 1;
                ruled += out as u32;
                exact += !passes as u32;
            }
        }
        assert!(
            ruled > exact / 4 * 3 && tried > 3_000_000,
            "{ruled} passed by of {exact} the heights pass by, of {tried}"
        );
    }
}
