//! The box walk's query for a short fixed-point sweep, in integers. A fixed-point coordinate is
//! an integer times `2^-F` and a grid cell `2^exponent` units, so the segment's box up to the
//! reach, grown by the pad, comes to cells by shifts, exactly: no floating point per query
//! (on a Cortex-M0, whose `f64` is software, the floating-point set-up of [`Segment`] costs
//! about a third of a short mesh query). Floats, and the rare sweep or grid whose terms would
//! overflow 64 bits, take [`Segment`]'s `f64` set-up.
//!
//! [`Segment`]: super::traverse::Segment

use super::overlap::Walk;
use super::{Cells, Grid};
use crate::cull::unit_bits;
use crate::{Scalar, Sweep};

/// A short sweep in its scalar's units (`2^-frac`): the start, the motion and the pad.
pub(crate) struct ShortBox {
    p0: [i64; 3],
    d: [i64; 3],
    pad: i64,
    frac: u32,
    /// A cell is `2^shift` units (`shift` may be negative: cells finer than the units).
    shift: i32,
    /// The cells of the whole segment's box (the reach at its start, one).
    whole: Cells,
}

/// `v / 2^s` rounded down for `s >= 0`, `v * 2^-s` for `s < 0`; `None` on overflow.
#[inline]
fn shift_down(v: i64, s: i32) -> Option<i64> {
    match s {
        0.. => Some(v >> s.min(63)),
        // By comparisons, not `checked_mul`, which a Cortex-M0 does in a slow library call.
        -62..=-1 => (v.unsigned_abs() >> (62 + s) == 0).then(|| v << -s),
        _ => None,
    }
}

/// `a * b` where `|a| < 2^30` and `|b| <= 2^32` (so the product is below `2^62`), else `None`:
/// a motion times a fraction of at most one.
#[inline]
fn small_product(a: i64, b: i64) -> Option<i64> {
    (a.unsigned_abs() < 1 << 30 && b.unsigned_abs() <= 1 << 32).then(|| a * b)
}

/// `v / 2^s` rounded up, as [`shift_down`].
#[inline]
fn shift_up(v: i64, s: i32) -> Option<i64> {
    shift_down(v.checked_neg()?, s)?.checked_neg()
}

/// The pad of [`rounding_pad`](super::rounding_pad) in a fixed-point scalar's units (of
/// `EPSILON`, `2^-frac`), rounded up, for a radius of `r` units, a path whose largest component
/// is `length` units and coordinates up to `magnitude` units: `r`, 64 units, 8 units per unit
/// of the path's largest component, 3/16 unit per unit of the coordinates' magnitude and
/// `3 · 2^-40` of the magnitude; for a ray (`r` zero), 256 units more
/// ([`ray_pad`](super::ray_pad)). `None` on overflow.
pub(crate) fn unit_pad(r: i64, frac: u32, length: i64, magnitude: i64) -> Option<i64> {
    let f = frac as i32;
    let thrice = (magnitude <= i64::MAX / 3).then(|| 3 * magnitude)?;
    [
        if r == 0 { 64 + 256 } else { 64 },
        shift_up(length, f - 3)?,
        shift_up(thrice, f + 4)?,
        shift_up(thrice, 40)?,
    ]
    .iter()
    .try_fold(r, |sum, &term| sum.checked_add(term))
}

/// Where the cells are clamped: beyond every grid (built grids lie within about `±2^25`).
const BOUND: i64 = 1 << 30;

impl ShortBox {
    /// The sweep in units of its fixed-point scalar, with the walk that goes with it, if the
    /// scalar is fixed point and the sweep short: no longer on any axis than the pad. `None`
    /// for floats, long sweeps, and terms beyond 64 bits.
    pub(crate) fn new<S: Scalar>(sweep: &Sweep<S>, grid: &Grid) -> Option<(Self, Walk)> {
        let (r, frac) = sweep.radius().fixed_bits()?;
        let (p0, p1) = (unit_bits(sweep.p0())?, unit_bits(sweep.p1())?);
        let f = frac as i32;
        let shift = f.checked_add(grid.exponent)?;
        let d = [
            p1[0].checked_sub(p0[0])?,
            p1[1].checked_sub(p0[1])?,
            p1[2].checked_sub(p0[2])?,
        ];
        let big = |v: [i64; 3]| {
            v.iter()
                .try_fold(0i64, |m, x| Some(m.max(x.checked_abs()?)))
        };
        let cells = grid.lo.iter().chain(&grid.hi);
        let mesh = shift_up(
            cells.fold(0, |m, &c| m.max(c.unsigned_abs())) as i64,
            -shift,
        )?;
        let length = big(d)?;
        let magnitude = big(p0)?.max(big(p1)?).max(mesh);
        let pad = unit_pad(r, frac, length, magnitude)?;
        if length > pad {
            return None;
        }
        // The seam margin r / 64 + 4 units, in whole cells, rounded up.
        let seam = shift_up(shift_up(r, 6)? + 4, shift)?;
        let walk = Walk {
            toward: d.map(|x| x.signum() as i32),
            seam,
        };
        let mut short = Self {
            p0,
            d,
            pad,
            frac,
            shift,
            whole: ([0; 3], [0; 3]),
        };
        // The box must come to cells without overflow; the reach only shrinks it.
        short.whole = short.box_at(1i64 << frac)?;
        Some((short, walk))
    }

    /// The cells of the segment's box over `[0, reach]` (`reach` clamped to `[0, 1]`), grown by
    /// the pad and by two cells, clamped to `±BOUND`.
    pub(crate) fn cells<S: Scalar>(&self, reach: S) -> Cells {
        let one = 1i64 << self.frac;
        let t = reach.fixed_bits().map_or(one, |(b, _)| b.max(0).min(one));
        // `new` made sure the whole segment's box converts, and a shorter one's terms are
        // smaller; were it not so, the whole segment's box.
        if t == one {
            return self.whole;
        }
        self.box_at(t).unwrap_or(self.whole)
    }

    /// The cells of the box over `[0, t / 2^frac]`, `0 <= t <= 2^frac`; `None` on overflow.
    fn box_at(&self, t: i64) -> Option<Cells> {
        let f = self.frac as i32;
        let side = |a: usize, up: bool| -> Option<i32> {
            let moved = small_product(self.d[a], t)?;
            let cell = if up {
                let end = self.p0[a].checked_add(shift_up(moved, f)?)?;
                shift_up(self.p0[a].max(end).checked_add(self.pad)?, self.shift)? + 2
            } else {
                let end = self.p0[a].checked_add(shift_down(moved, f)?)?;
                shift_down(self.p0[a].min(end).checked_sub(self.pad)?, self.shift)? - 2
            };
            // Constant bounds: `clamp`'s check that they are ordered folds away (no panic path).
            Some(cell.clamp(-BOUND, BOUND) as i32)
        };
        Some((
            [side(0, false)?, side(1, false)?, side(2, false)?],
            [side(0, true)?, side(1, true)?, side(2, true)?],
        ))
    }
}
