//! The heightfield's query: rows of cells along the sweep, nearest first (see the module docs of
//! [`heightfield`](super)).

use super::units::UnitGrid;
use super::{HOLE, Heightfield};
use crate::cache::{Cacheable, Keep, Slots};
use crate::compound::CompoundPart;
use crate::cull::{Path, SOFT_F64, is_less};
use crate::merge::{Earliest, earliest};
use crate::{Geometry, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};

/// Whether the path, over `[t0, t1]`, comes within the pad of the half of a cell (corner `c` in
/// x–z) on one side of its diagonal: `above` (z − x growing) for the cell's first triangle. Seen
/// from above, a ball within its radius of a triangle is within it of the triangle's shadow.
fn beside_diagonal(path: &Path, c: [f64; 2], above: bool, (t0, t1): (f64, f64)) -> bool {
    let side = |t: f64| {
        let (x, z) = (path.p0[0] + t * path.d[0], path.p0[2] + t * path.d[2]);
        (z - c[1]) - (x - c[0])
    };
    // Finite both (the path is): ordered by one comparison.
    let (a, b) = (side(t0), side(t1));
    let (low, high) = if b < a { (b, a) } else { (a, b) };
    // `pad √2` bounds the distance across the diagonal, with room for rounding.
    let reach = 1.5 * path.pad;
    if above {
        !is_less(high, -reach)
    } else {
        !is_less(reach, low)
    }
}

impl<S: Scalar> Heightfield<'_, S> {
    /// The earliest contact along the sweep: the answer of the slice
    /// [`Geometry`] over the same prepared triangles (holes left out) in index
    /// order, bit for bit, simultaneous contacts merged as in [`Scene::cast`](crate::Scene::cast).
    /// Its cost grows with the cells the grown path crosses.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        earliest(sweep, |acc| self.offer(sweep, acc, ()))
    }

    /// Offers the contacts of the triangles under the path, taking and keeping prepared
    /// triangles in `cache` if there is one.
    fn offer<K: Keep<S>>(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: K) {
        if self.cells_count().is_none() {
            return;
        }
        // Where `f64` is software, a fixed-point sweep's short query runs in integers.
        if SOFT_F64 && UnitGrid::new(self, sweep).is_some_and(|g| g.offer(self, sweep, acc, cache))
        {
            return;
        }
        let path = Path::new(sweep, self.extent(), self.class);
        let o = self.origin.to_array().map(S::to_f64);
        self.walk(sweep, &path, o, acc, cache)
    }

    /// The largest magnitude of any coordinate of the grid.
    fn extent(&self) -> f64 {
        let o = self.origin.to_array().map(S::to_f64);
        let (sp, unit) = (self.spacing.to_f64(), self.unit.to_f64());
        let far = [
            sp * self.columns as f64,
            unit.abs() * 32768.0,
            sp * self.rows as f64,
        ];
        (0..3).fold(0.0f64, |m, a| m.max(o[a].abs() + far[a]))
    }

    /// Visits the cells the grown path crosses within the terrain's box, row by row in the
    /// direction of travel, and casts the triangles whose boxes (and planes, and halves of the
    /// cell) the path comes near before the current reach. Where `f64` is software (see
    /// [`offer`](Self::offer)) out of line, so that its frame is not added to the integer
    /// walk's; inline elsewhere, where it is the only walk.
    #[cfg_attr(all(target_arch = "arm", target_os = "none"), inline(never))]
    fn walk<K: Keep<S>>(
        &self,
        sweep: &Sweep<S>,
        path: &Path,
        o: [f64; 3],
        acc: &mut Earliest<S>,
        cache: K,
    ) {
        let (w, h) = (self.columns as i64, self.rows as i64);
        let (sp, unit) = (self.spacing.to_f64(), self.unit.to_f64());
        let limit = |acc: &Earliest<S>| acc.reach().to_f64() + 1.0 / (1u64 << 50) as f64;
        // The culls take the vertices as the triangles have them. Fixed point makes heights and
        // grid lines exactly (an integer times a step, plus the origin, in range); a float
        // rounds them, and near the range's edge that can tilt a plane far more than the pad
        // allows for over a long path: there they are made in `S`, as the triangles' are.
        let float = S::PRECISION.relative;
        let y = |h: i16| {
            if float {
                (self.origin.y + self.unit.mul(S::from_int(h as i32))).to_f64()
            } else {
                o[1] + h as f64 * unit
            }
        };
        let line = |o: S, n: i64| {
            if float {
                self.along(o, n as u32).to_f64()
            } else {
                o.to_f64() + sp * n as f64
            }
        };
        let (ylo, yhi) = (y(self.bounds[0]), y(self.bounds[1]));
        let (ox, oz) = (self.origin.x, self.origin.z);
        let whole = (
            [o[0], ylo.min(yhi), o[2]],
            [line(ox, w), ylo.max(yhi), line(oz, h)],
        );
        // The part of the path near the terrain at all: above or below it nothing is reached.
        let Some((ta, tb)) = path.clip(whole.0, whole.1, limit(acc)) else {
            return;
        };
        // The cells (along one axis) that may hold coordinate `v`, clamped to `0..n`: the one
        // the division gives, and its neighbour where `v` lies within the division's rounding
        // (a few ulps of the operands' magnitude, far below 2^-40 of it) of their border.
        let cells = |v: f64, a: usize, n: i64| {
            let q = (v - o[a]) / sp;
            let e = (v.abs() + o[a].abs()) / sp / (1u64 << 40) as f64 + 1.0 / (1u64 << 40) as f64;
            // The floor of `q` clamped to `0..n`: below zero the clamp decides, and at or above
            // it the truncation of `as` is the floor (no call to `floor`); NaN gives 0, as
            // `floor` and `as` would.
            let at = |q: f64| if q < 0.0 { 0 } else { (q as i64).min(n - 1) };
            (at(q - e), at(q + e))
        };
        let span = |a: usize, t0: f64, t1: f64| {
            let (u, v) = (path.p0[a] + path.d[a] * t0, path.p0[a] + path.d[a] * t1);
            let (low, high) = if v < u { (v, u) } else { (u, v) };
            (low - path.pad, high + path.pad)
        };
        let (zlo, zhi) = span(2, ta, tb);
        let (k0, k1) = (cells(zlo, 2, h).0, cells(zhi, 2, h).1);
        let (up, right) = (path.d[2] >= 0.0, path.d[0] >= 0.0);
        for n in 0..=(k1 - k0) {
            let k = if up { k0 + n } else { k1 - n };
            // The part of the path within this row's strip, grown. Strips come in travel order:
            // once one's slab starts beyond the reach, so do the rest's (a strip missed for
            // another reason, behind the start or beside a path along it, ends nothing).
            let z = [line(oz, k), line(oz, k + 1)];
            let lim = limit(acc).min(tb);
            if path.inv[2].is_finite() {
                let near = if up { z[0] - path.pad } else { z[1] + path.pad };
                if (near - path.p0[2]) * path.inv[2] > lim {
                    break;
                }
            }
            let strip = ([0.0, 0.0, z[0]], [0.0, 0.0, z[1]]);
            let Some((t0, t1)) = path.clip_within(strip.0, strip.1, (0.0, lim), 2..3) else {
                continue;
            };
            let (xlo, xhi) = span(0, t0.max(ta), t1);
            let (i0, i1) = (cells(xlo, 0, w).0, cells(xhi, 0, w).1);
            for m in 0..=(i1 - i0) {
                let i = if right { i0 + m } else { i1 - m };
                let x = [line(ox, i), line(ox, i + 1)];
                let lim = limit(acc);
                // Cells come in travel order along x too: once one's slab starts beyond the
                // reach, so do the rest of the row's.
                if path.inv[0].is_finite() {
                    let near = if right {
                        x[0] - path.pad
                    } else {
                        x[1] + path.pad
                    };
                    if (near - path.p0[0]) * path.inv[0] > lim {
                        break;
                    }
                }
                let c = (k * w + i) as usize;
                let byte = match self.cells.get(c) {
                    Some(&byte) if byte & HOLE == 0 => byte,
                    Some(_) => continue,
                    None => return,
                };
                let at = |di: i64, dk: i64| {
                    let v = (k + dk) * (w + 1) + i + di;
                    y(self.heights.get(v as usize).map_or(0, |&h| h))
                };
                let (p00, p01) = ([x[0], at(0, 0), z[0]], [x[0], at(0, 1), z[1]]);
                let (p11, p10) = ([x[1], at(1, 1), z[1]], [x[1], at(1, 0), z[0]]);
                // Heights are finite: plain comparisons, cheaper than `f64::min` and `max`.
                let (lo, hi) = [p01[1], p11[1], p10[1]]
                    .iter()
                    .fold((p00[1], p00[1]), |(l, u), &v| {
                        (if v < l { v } else { l }, if v > u { v } else { u })
                    });
                // The row's part of the path already lies within the cell's z slab.
                let (lo, hi) = ([x[0], lo, 0.0], [x[1], hi, 0.0]);
                let Some(span) = path.clip_within(lo, hi, (t0, t1.min(lim)), 0..2) else {
                    continue;
                };
                for (half, v) in [(0, [p00, p01, p11]), (1, [p00, p11, p10])] {
                    let t = 2 * c + half;
                    // A kept triangle is cast at once: its heights cull as the plane would.
                    let kept = cache.get(t);
                    if kept.is_none()
                        && !(beside_diagonal(path, [x[0], z[0]], half == 0, span)
                            && path.near_plane(v, span, true))
                    {
                        continue;
                    }
                    let fresh;
                    let tri = match &kept {
                        Some(tri) => tri,
                        None => {
                            let Some(tri) = self.prepare_cell(i as u32, k as u32, t, byte) else {
                                continue;
                            };
                            fresh = tri;
                            cache.put(t, &fresh);
                            &fresh
                        }
                    };
                    if let Some(hit) = tri.cast_within(sweep, acc.reach()) {
                        acc.offer(t, hit);
                    }
                }
            }
        }
    }
}

impl<S: Scalar> CompoundPart<S> for Heightfield<'_, S> {
    /// Two per cell: triangle `2 c` and `2 c + 1` of cell `c = row × columns + column`.
    fn index_bound(&self) -> usize {
        self.cells_count().map_or(0, |n| 2 * n)
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: bool) -> bool {
        self.offer(sweep, acc, ());
        true
    }
}

impl<S: Scalar> Cacheable<S> for Heightfield<'_, S> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool {
        self.offer(sweep, acc, cache);
        true
    }
}

impl<S: Scalar> Geometry<S> for Heightfield<'_, S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Heightfield::cast(self, sweep)
    }

    /// The triangles of the cells under the box whose heights reach into it (the box grown by
    /// a bound on the rounding of the vertices).
    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        if self.cells_count().is_none() {
            return;
        }
        let (o, sp) = (self.origin.to_array().map(S::to_f64), self.spacing.to_f64());
        let slack = crate::bvh::rounding_pad::<S>(0.0, 0.0, self.extent());
        let lo = min.to_array().map(|v| v.to_f64() - slack);
        let hi = max.to_array().map(|v| v.to_f64() + slack);
        // Cells along one axis that the box's span covers, clamped to the grid (empty if none).
        let range = |a: usize, n: u32| {
            let at = |v: f64| libm::floor((v - o[a]) / sp);
            let (first, last) = (at(lo[a]).max(0.0), at(hi[a]).min(n as f64 - 1.0));
            first as u32..(last + 1.0).max(first) as u32
        };
        let unit = self.unit.to_f64();
        for k in range(2, self.rows) {
            for i in range(0, self.columns) {
                let corner = |di: u32, dk: u32| {
                    let v = (k + dk) as usize * (self.columns as usize + 1) + (i + di) as usize;
                    o[1] + unit * self.heights.get(v).map_or(0.0, |&h| h as f64)
                };
                let ys = [corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)];
                let (ylo, yhi) = ys
                    .iter()
                    .fold((ys[0], ys[0]), |(l, u), &y| (l.min(y), u.max(y)));
                if yhi < lo[1] || ylo > hi[1] {
                    continue;
                }
                let c = k as usize * self.columns as usize + i as usize;
                for t in [2 * c, 2 * c + 1] {
                    if let Some(st) = self.prepared(t) {
                        f(t, &st);
                    }
                }
            }
        }
    }
}
