//! The heightfield's query in integers, for a fixed-point sweep where `f64` is software (a
//! Cortex-M, whose `f64` arithmetic is a library call per operation): the cells under the
//! box of the sweep's grown path, found from the coordinates' bits, each culled by its heights,
//! each triangle by the bound of [`UnitHeights`] on the sweep's heights above its plane, then
//! prepared in two halves (its frame, and the rest only where the frame's heights leave a
//! contact possible) and cast. Culls only pass triangles by, so the answer is the `f64`
//! walk's, bit for bit; a sweep whose box spans more than [`MAX_CELLS`] cells (a long cast,
//! whose box holds far more cells than its path crosses) takes that walk instead.

use super::{HOLE, Heightfield, features, half};
use crate::bvh;
use crate::cache::Keep;
use crate::contact::within_reach;
use crate::cull::{UnitHeights, unit_bits};
use crate::merge::Earliest;
use crate::triangle::Frame;
use crate::{Hit, Scalar, Sweep, Triangle};

/// The most cells a query's box may span for the integer query.
pub(super) const MAX_CELLS: i64 = 64;

/// A fixed-point sweep's path over a heightfield's grid, in the scalar's units (`2^-frac`):
/// its box grown by the `f64` walk's pad (rounded up), and the box of the terrain's vertices.
pub(super) struct UnitGrid {
    lo: [i64; 3],
    hi: [i64; 3],
    terrain: ([i64; 3], [i64; 3]),
    origin: [i64; 3],
    spacing: i64,
    unit: i64,
}

impl UnitGrid {
    /// The path of `sweep` over `field`'s grid; `None` for floats, a grid that is not valid
    /// and terms beyond 64 bits.
    pub(super) fn new<S: Scalar>(field: &Heightfield<'_, S>, sweep: &Sweep<S>) -> Option<Self> {
        let (r, frac) = sweep.radius().fixed_bits()?;
        let b = |v: S| v.fixed_bits().map(|(b, _)| b);
        let (p0, p1) = (unit_bits(sweep.p0())?, unit_bits(sweep.p1())?);
        let o = unit_bits(field.origin)?;
        let (spacing, unit) = (b(field.spacing)?, b(field.unit)?);
        if spacing <= 0 {
            return None;
        }
        let far = |o: i64, n: u32| o.checked_add(spacing.checked_mul(n as i64)?);
        let y = |h: i16| o[1].checked_add(unit.checked_mul(h as i64)?);
        let (ya, yb) = (y(field.bounds[0])?, y(field.bounds[1])?);
        // Vertices lie within: `origin + (i spacing, h unit, k spacing)`, exactly.
        let terrain = (
            [o[0], ya.min(yb), o[2]],
            [
                far(o[0], field.columns)?,
                ya.max(yb),
                far(o[2], field.rows)?,
            ],
        );
        let big = |v: [i64; 3]| v.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0);
        // The `f64` walk's magnitude for the grid (any height, `32768 |unit|`, counts), so the
        // pad is never below its.
        let reach = (unit.unsigned_abs()).checked_mul(32768)?;
        let grid = o[1].unsigned_abs().checked_add(reach)?;
        let magnitude = [p0, p1, terrain.0, terrain.1]
            .map(big)
            .into_iter()
            .chain([grid])
            .max();
        let ([x0, y0, z0], [x1, y1, z1]) = (p0, p1);
        let length = x1.abs_diff(x0).max(y1.abs_diff(y0)).max(z1.abs_diff(z0));
        let magnitude = i64::try_from(magnitude.unwrap_or(0)).ok()?;
        // The seam margin r / 64 + 4 units, rounded up, 2^class times.
        let seams = ((r + 63) / 64 + 4).checked_mul(1i64.checked_shl(field.class as u32)?)?;
        let pad = bvh::unit_pad(r, frac, i64::try_from(length).ok()?, magnitude)?;
        let pad = pad.checked_add(seams)?;
        let lo = [(x0, x1), (y0, y1), (z0, z1)].map(|(a, b)| a.min(b).saturating_sub(pad));
        let hi = [(x0, x1), (y0, y1), (z0, z1)].map(|(a, b)| a.max(b).saturating_add(pad));
        Some(Self {
            lo,
            hi,
            terrain,
            origin: o,
            spacing,
            unit,
        })
    }

    /// Whether the path's box lies wholly beside the terrain's on some axis: then the sweep
    /// touches no triangle.
    pub(super) fn clear(&self) -> bool {
        let (lo, hi) = self.terrain;
        let apart = |a: usize| self.lo[a] > hi[a] || self.hi[a] < lo[a];
        apart(0) || apart(1) || apart(2)
    }

    /// The cells `first..=last` along one axis whose span `[o + i s, o + (i + 1) s]` meets
    /// `lo..=hi`, within `0..n`; `None` if none do.
    fn cells(&self, o: i64, (lo, hi): (i64, i64), n: u32) -> Option<(i64, i64)> {
        let at = |v: i64| v.saturating_sub(o).checked_div_euclid(self.spacing);
        // A span's end on a cell border also meets the cell before.
        let (first, last) = ((at(lo)? - 1).max(0), at(hi)?.min(n as i64 - 1));
        (first <= last).then_some((first, last))
    }

    /// Offers the contacts the `f64` walk would offer; false, offering none (take that walk),
    /// where the box spans more than [`MAX_CELLS`] cells.
    pub(super) fn offer<S: Scalar, K: Keep<S>>(
        &self,
        field: &Heightfield<'_, S>,
        sweep: &Sweep<S>,
        acc: &mut Earliest<S>,
        cache: K,
    ) -> bool {
        if self.clear() {
            return true;
        }
        let (o, (lo, hi)) = (self.origin, (self.lo, self.hi));
        let (Some((i0, i1)), Some((k0, k1))) = (
            self.cells(o[0], (lo[0], hi[0]), field.columns),
            self.cells(o[2], (lo[2], hi[2]), field.rows),
        ) else {
            return false;
        };
        if (i1 - i0 + 1) * (k1 - k0 + 1) > MAX_CELLS {
            return false;
        }
        let bound = UnitHeights::new(sweep);
        // The heights a cell must span to reach the box (`None`: not known, every cell may).
        let span = height_span(o[1], self.unit, (lo[1], hi[1]));
        let d = sweep.p1() - sweep.p0();
        let w = field.columns as usize;
        // Rows, then columns, in the direction of travel: near cells first, so that early
        // contacts lower the reach the later cells are culled by.
        for n in 0..=(k1 - k0) {
            let k = if d.z >= S::ZERO { k0 + n } else { k1 - n };
            for m in 0..=(i1 - i0) {
                let i = if d.x >= S::ZERO { i0 + m } else { i1 - m };
                let c = k as usize * w + i as usize;
                let Some(&byte) = field.cells.get(c).filter(|&&b| b & HOLE == 0) else {
                    continue;
                };
                if !cell_in_reach(field, span, i as u32, k as u32) {
                    continue;
                }
                let Some(corners) = field.corners(i as u32, k as u32) else {
                    continue;
                };
                for t in [2 * c, 2 * c + 1] {
                    let reach = acc.reach();
                    // A kept triangle is cast at once: its heights cull as the bound would.
                    if let Some(kept) = cache.get(t) {
                        if let Some(hit) = kept.cast_within(sweep, reach) {
                            acc.offer(t, hit);
                        }
                        continue;
                    }
                    let tri = half(corners, t % 2);
                    let out = bound
                        .as_ref()
                        .is_some_and(|b| b.rule_out(sweep, tri.vertices(), reach, true));
                    if out {
                        continue;
                    }
                    // With a cache the whole triangle is prepared and kept, for the next query.
                    let hit = if K::ON {
                        Heightfield::prepare_from(corners, t, byte).and_then(|st| {
                            cache.put(t, &st);
                            st.cast_within(sweep, reach)
                        })
                    } else {
                        cast_lazily(&tri, t, byte, sweep, reach)
                    };
                    if let Some(hit) = hit {
                        acc.offer(t, hit);
                    }
                }
            }
        }
        true
    }
}

/// Whether the heights of the cell at column `i`, row `k` span some of `span` (see
/// [`height_span`]; `None`: any may).
fn cell_in_reach<S: Scalar>(
    field: &Heightfield<'_, S>,
    span: Option<(i64, i64)>,
    i: u32,
    k: u32,
) -> bool {
    let w = field.columns as usize + 1;
    let at = |di: u32, dk: u32| {
        let v = (k + dk) as usize * w + (i + di) as usize;
        field.heights.get(v).copied().unwrap_or(0)
    };
    let hs = [at(0, 0), at(0, 1), at(1, 1), at(1, 0)];
    let (l, u) = hs
        .iter()
        .fold((i16::MAX, i16::MIN), |(l, u), &h| (l.min(h), u.max(h)));
    // Heights map to y linearly: the cell's span of heights meets the box's, or not.
    span.is_none_or(|(first, last)| u as i64 >= first && l as i64 <= last)
}

/// The real heights `h` whose vertices' y, `origin + unit h`, lies within `lo..=hi`, as the
/// integers `[first, last]` a span of integer heights must meet to hold one of them (empty,
/// `first > last`, if none does); `None` where a term leaves 64 bits. Two divisions per query,
/// where comparing each cell's y would take two 64-bit products (library calls on a
/// Cortex-M0).
fn height_span(origin: i64, unit: i64, (lo, hi): (i64, i64)) -> Option<(i64, i64)> {
    // unit h within [a, b]; with a negative unit, (-unit) h within [-b, -a].
    let (a, b) = (lo.checked_sub(origin)?, hi.checked_sub(origin)?);
    let (a, b, unit) = if unit < 0 {
        (b.checked_neg()?, a.checked_neg()?, unit.checked_neg()?)
    } else {
        (a, b, unit)
    };
    if unit == 0 {
        let all = a <= 0 && 0 <= b;
        return Some(if all { (i64::MIN, i64::MAX) } else { (1, 0) });
    }
    // h within [ceil(a / unit), floor(b / unit)]: floors of a positive divisor's quotients.
    let first = a.checked_neg()?.div_euclid(unit).checked_neg()?;
    Some((first, b.div_euclid(unit)))
}

/// The contact of triangle `t` of a heightfield (`byte` its cell's), prepared in two halves
/// as [`prepare_from`](Heightfield::prepare_from) prepares it, with the sweep at alpha `reach`
/// or earlier.
fn cast_lazily<S: Scalar>(
    tri: &Triangle<S>,
    t: usize,
    byte: u8,
    sweep: &Sweep<S>,
    reach: S,
) -> Option<Hit<S>> {
    let frame = Frame::of(tri).ok()?;
    let heights = frame.heights(sweep);
    within_reach(sweep, heights, false, reach)?;
    let st = frame.finish(tri).ok()?;
    st.with_features(features(byte, t))
        .cast_within_heights(sweep, heights, reach)
}

#[cfg(test)]
mod tests;
