//! The heightfield's query: rows of cells along the sweep, nearest first (see the module docs of
//! [`heightfield`](super)).

use super::{HOLE, Heightfield};
use crate::merge::{Earliest, earliest};
use crate::{Geometry, Scalar, SceneHit, Sweep};

/// The sweep in world units (`f64`), with what every box test needs.
struct Path {
    p0: [f64; 3],
    d: [f64; 3],
    inv: [f64; 3],
    /// How far every box is grown: the radius, every rounding, and the seam margins.
    pad: f64,
}

impl Path {
    /// Where the segment, over `[0, limit]`, enters the box `lo..hi` grown by the pad.
    fn enter(&self, lo: [f64; 3], hi: [f64; 3], limit: f64) -> Option<f64> {
        let (mut t0, mut t1) = (0.0f64, limit);
        for a in 0..3 {
            let (near, far) = (lo[a] - self.pad - self.p0[a], hi[a] + self.pad - self.p0[a]);
            if !self.inv[a].is_finite() {
                // Parallel to the slab (or as good as): inside it all along, or never.
                let d = self.d[a].abs();
                if near > d || far < -d {
                    return None;
                }
                continue;
            }
            let (ta, tb) = (near * self.inv[a], far * self.inv[a]);
            t0 = t0.max(ta.min(tb));
            t1 = t1.min(ta.max(tb));
        }
        (t0 <= t1).then_some(t0)
    }
}

impl<S: Scalar> Heightfield<'_, S> {
    /// The earliest contact along the sweep: the answer of the slice
    /// [`Geometry`](crate::Geometry) over the same prepared triangles (holes left out) in index
    /// order, bit for bit, simultaneous contacts merged as in [`Scene::cast`](crate::Scene::cast).
    /// Its cost grows with the cells the grown path crosses.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        let f = |p: crate::Vec3<S>| p.to_array().map(S::to_f64);
        let (p0, p1, o) = (f(sweep.p0()), f(sweep.p1()), f(self.origin));
        let d = [0, 1, 2].map(|a| p1[a] - p0[a]);
        let (sp, unit) = (self.spacing.to_f64(), self.unit.to_f64());
        let big = |a: [f64; 3]| a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let extent = [
            sp * self.columns as f64,
            unit.abs() * 32768.0,
            sp * self.rows as f64,
        ];
        let magnitude = big(p0).max(big(p1)).max(big(o) + big(extent));
        let r = sweep.radius().to_f64();
        // 2^class seam margins, exactly.
        let seams = f64::from_bits(((1023 + self.class.min(31) as u32) as u64) << 52);
        let pad = crate::bvh::rounding_pad::<S>(r, big(d), magnitude)
            + (r / 64.0 + 4.0 * S::PRECISION.epsilon) * seams;
        let path = Path {
            p0,
            d,
            inv: d.map(|x| 1.0 / x),
            pad,
        };
        earliest(|acc| self.walk(sweep, &path, o, acc))
    }

    /// Visits the cells the grown path crosses, row by row in the direction of travel, and
    /// casts the triangles whose boxes the path reaches within the current reach.
    fn walk(&self, sweep: &Sweep<S>, path: &Path, o: [f64; 3], acc: &mut Earliest<S>) {
        let (w, h) = (self.columns as i64, self.rows as i64);
        let (sp, unit) = (self.spacing.to_f64(), self.unit.to_f64());
        let (p0, d, pad) = (path.p0, path.d, path.pad);
        let limit = |acc: &Earliest<S>| acc.reach().to_f64() + 1.0 / (1u64 << 50) as f64;
        // The cell (along one axis) holding coordinate `v`, clamped to `0..n`.
        let cell = |v: f64, a: usize, n: i64| {
            let c = libm::floor((v - o[a]) / sp);
            if c < 0.0 { 0 } else { (c as i64).min(n - 1) }
        };
        let span = |a: usize, t0: f64, t1: f64| {
            let (u, v) = (p0[a] + d[a] * t0, p0[a] + d[a] * t1);
            (u.min(v) - pad, u.max(v) + pad)
        };
        let (zlo, zhi) = span(2, 0.0, 1.0);
        if zhi < o[2] || zlo > o[2] + sp * h as f64 {
            return;
        }
        let (k0, k1) = (cell(zlo, 2, h), cell(zhi, 2, h));
        let up = d[2] >= 0.0;
        for n in 0..=(k1 - k0) {
            let k = if up { k0 + n } else { k1 - n };
            // The part of the path within this row's strip, grown; strips come in travel order,
            // so once one starts beyond the reach, so do the rest.
            let z = [o[2] + sp * k as f64, o[2] + sp * (k + 1) as f64];
            let strip = ([f64::MIN, f64::MIN, z[0]], [f64::MAX, f64::MAX, z[1]]);
            let lim = limit(acc);
            let Some(t0) = path.enter(strip.0, strip.1, lim) else {
                continue;
            };
            let t1 = exit(path, z, lim);
            let (xlo, xhi) = span(0, t0, t1);
            if xhi < o[0] || xlo > o[0] + sp * w as f64 {
                continue;
            }
            let (i0, i1) = (cell(xlo, 0, w), cell(xhi, 0, w));
            let right = d[0] >= 0.0;
            for m in 0..=(i1 - i0) {
                let i = if right { i0 + m } else { i1 - m };
                let c = (k * w + i) as usize;
                let Some(&byte) = self.cells.get(c) else {
                    return;
                };
                if byte & HOLE != 0 {
                    continue;
                }
                let x = [o[0] + sp * i as f64, o[0] + sp * (i + 1) as f64];
                let at = |di: i64, dk: i64| {
                    let v = (k + dk) * (w + 1) + i + di;
                    self.heights.get(v as usize).map_or(0.0, |&y| y as f64)
                };
                let (h00, h01, h11, h10) = (at(0, 0), at(0, 1), at(1, 1), at(1, 0));
                for (t, [a, b, e]) in [(2 * c, [h00, h01, h11]), (2 * c + 1, [h00, h11, h10])] {
                    let (lo, hi) = (a.min(b).min(e) * unit, a.max(b).max(e) * unit);
                    let y = [o[1] + lo.min(hi), o[1] + lo.max(hi)];
                    let reached = path.enter([x[0], y[0], z[0]], [x[1], y[1], z[1]], limit(acc));
                    if reached.is_some()
                        && let Some(tri) = self.prepared(t)
                        && let Some(hit) = tri.cast(sweep)
                    {
                        acc.offer(t, hit);
                    }
                }
            }
        }
    }
}

/// Where the path, over `[0, limit]`, leaves the strip `z[0]..z[1]` grown by the pad.
fn exit(path: &Path, z: [f64; 2], limit: f64) -> f64 {
    if !path.inv[2].is_finite() {
        return limit;
    }
    let (a, b) = (
        (z[0] - path.pad - path.p0[2]) * path.inv[2],
        (z[1] + path.pad - path.p0[2]) * path.inv[2],
    );
    a.max(b).min(limit)
}

impl<S: Scalar> Geometry<S> for Heightfield<'_, S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Heightfield::cast(self, sweep)
    }
}
