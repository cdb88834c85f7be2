//! The swept-ball traversal: the segment against inflated child boxes, nearest child first
//! (see the module docs of [`bvh`](super)).

use super::decode::{child_lo, leaf_slots, shifts};
use super::overlap::Walk;
use super::short::ShortBox;
use super::{Cells, Grid, LEAF_FLAG, Node, PAYLOAD, STACK};
use crate::merge::Earliest;
use crate::{Scalar, Sweep};

/// A child waiting to be visited: where the segment enters and leaves its box, its reference,
/// and its box's minimum (all that decoding its children needs).
#[derive(Clone, Copy)]
struct Entry {
    enter: f32,
    exit: f32,
    child: u32,
    lo: [i32; 3],
}

/// How far a box must be grown for a ball of radius `r` whose path's largest component is
/// `length`, among coordinates up to `magnitude`: the radius plus a bound on every rounding
/// between the exact segment and what `cast` computes (the [module docs](super) give the terms).
pub(crate) fn rounding_pad<S: Scalar>(r: f64, length: f64, magnitude: f64) -> f64 {
    let eps = S::PRECISION.epsilon;
    let per_unit = if S::PRECISION.relative {
        1.0
    } else {
        1.0 / 1024.0
    };
    r + eps * (64.0 + 8.0 * length)
        + (64.0 * eps * per_unit + 1.0 / (1u64 << 40) as f64) * 3.0 * magnitude
}

/// What a ray (radius zero) adds to [`rounding_pad`]: it meets a face grown by up to 16 times
/// twice a height's rounding at its frame's coordinates (`StandardTriangle::within_rounding`),
/// which lie within four times `magnitude`. Zero for a ball.
pub(crate) fn ray_pad<S: Scalar>(r: f64, magnitude: f64) -> f64 {
    if r != 0.0 {
        return 0.0;
    }
    let eps = S::PRECISION.epsilon;
    if S::PRECISION.relative {
        128.0 * eps * (4.0 * magnitude).max(1.0)
    } else {
        256.0 * eps
    }
}

/// The swept segment in grid units, with what every box test needs, worked out once per query
/// so that a node costs only its own terms.
pub(crate) struct Segment {
    q0: [f64; 3],
    /// The segment's extent per axis, `p1 - p0` in cells.
    d: [f64; 3],
    /// Per axis, the reciprocal of the segment's extent, `2^100` where that is below `2^-100`
    /// (parallel to the slab, as good as: the pad covers the difference), in `f64` and in `f32`
    /// (rounded to nearest), and the latter's magnitude: infinite where the extent exceeds
    /// `2^100` cells (a reciprocal too small for `f32` to scale exactly: that axis then culls
    /// nothing).
    inv: [f64; 3],
    inv32: [f32; 3],
    /// Per axis, the pad's scale into the segment's parameter: the magnitude of the `f32`
    /// reciprocal, or infinity where the reciprocal is below `2^-100`.
    slope: [f32; 3],
    /// How far (cells) every box is grown: the radius plus every rounding (module docs), in
    /// `f32` for the node tests, rounded up.
    pad: f32,
    /// The seam margin `r / 64 + 4 EPSILON` (cells), grown by `2^class` per child; `f32`,
    /// rounded up, at least the smallest normal `f32` (so `2^class` times it is exact).
    seam: f32,
}

impl Segment {
    /// The sweep in the cells of `grid`.
    pub(crate) fn new<S: Scalar>(sweep: &Sweep<S>, grid: &Grid) -> Self {
        let v = |p: crate::Vec3<S>| [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()];
        let (p0, p1) = (v(sweep.p0()), v(sweep.p1()));
        let r = sweep.radius().to_f64();
        let s = Grid::scale(grid.exponent);
        let big = |a: [f64; 3]| a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let mesh = grid.magnitude();
        let d = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
        let magnitude = big(p0).max(big(p1)).max(mesh);
        let pad = rounding_pad::<S>(r, big(d), magnitude) + ray_pad::<S>(r, magnitude);
        let seam = r / 64.0 + 4.0 * S::PRECISION.epsilon;
        let q0 = p0.map(|x| x * s);
        let d = d.map(|x| x * s);
        let tiny = 1.0 / pow2(100);
        let inv = d.map(|x| if x.abs() > tiny { 1.0 / x } else { pow2(100) });
        // The node tests' `f32` arithmetic: a few roundings of 2^-24 of terms below the
        // segment's and the mesh's magnitudes in cells, a node's extent (2^26) and the pad.
        let grow = 1.0 + 1.0 / pow2(19);
        let slack = (2.0 * magnitude * s + pow2(26)) / pow2(19);
        let inv32 = inv.map(|x| x as f32);
        Self {
            q0,
            d,
            inv,
            inv32,
            slope: inv.map(|x| {
                if x.abs() >= tiny {
                    (x as f32).abs()
                } else {
                    f32::INFINITY
                }
            }),
            pad: up((pad * s + 2.0 + slack) * grow),
            seam: up(seam * s * grow).max(f32::MIN_POSITIVE),
        }
    }

    /// The box walk for this segment if it is short: no longer on any axis than the pad, so
    /// that its box is hardly larger than the padded segment itself and integer box tests
    /// (a few comparisons per child, no floating point) lose little to the slab test.
    pub(crate) fn short_walk(&self) -> Option<Walk> {
        let pad = self.pad as f64;
        self.d.iter().all(|x| x.abs() <= pad).then(|| Walk {
            toward: self.d.map(|x| (x > 0.0) as i32 - (x < 0.0) as i32),
            seam: libm::ceil(self.seam as f64) as i64,
        })
    }

    /// The cells of the segment's box over `[0, limit]`, grown by the pad, rounded outward and
    /// grown by a cell (for this `f64` arithmetic), clamped to `±2^30`.
    pub(crate) fn cells(&self, limit: f32) -> Cells {
        let t = (limit as f64).clamp(0.0, 1.0);
        let pad = self.pad as f64;
        let bound = (1u64 << 30) as f64;
        let end = |a: usize| self.q0[a] + self.d[a] * t;
        let lo = [0, 1, 2].map(|a| (self.q0[a].min(end(a)) - pad).clamp(-bound, bound));
        let hi = [0, 1, 2].map(|a| (self.q0[a].max(end(a)) + pad).clamp(-bound, bound));
        Grid::cells(0, lo, hi)
    }

    /// Where the segment's line enters each of the four child boxes of `node` (whose own
    /// minimum is `lo`), each grown by the pad and `2^class` seam margins of its child (before
    /// the start: negative, where the start lies in the box), where the segment, over
    /// `[0, limit]`, leaves it, and a mask of the children it meets there (bit `k` for child
    /// `k < count`; a child met is entered no later than `limit`). The four are computed side
    /// by side, lane by lane and without branches, so the compiler can use vector registers;
    /// slots beyond `count` are computed and left out of the mask.
    /// `shift` is the node's, each at most 31 ([`shifts`]).
    #[inline(always)]
    fn enter4(
        &self,
        node: &Node,
        lo: [i32; 3],
        shift: [u32; 3],
        limit: f32,
    ) -> ([f32; 4], [f32; 4], u32) {
        let pad: [f32; 4] = core::array::from_fn(|k| {
            let class = super::class_bits(node.children[k]);
            self.pad + self.seam * pow2f(class)
        });
        let (mut t0, mut t1) = ([f32::NEG_INFINITY; 4], [limit; 4]);
        for (a, &base) in lo.iter().enumerate() {
            let (min, max) = (node.boxes[a], node.boxes[3 + a]);
            // In the node's steps: t = byte * per_step + at_zero (module docs); `2^shift`
            // times the `f32` reciprocal is exact, as `2^shift` times the `f64` one rounded.
            let per_step = self.inv32[a] * pow2f(shift[a]);
            let at_zero = ((base as f64 - self.q0[a]) * self.inv[a]) as f32;
            let slope = self.slope[a];
            for k in 0..4 {
                // Where the line crosses the box's two bounds: the earlier is where it enters
                // the slab, whichever way it runs (so no branch on the direction); then both
                // moved out by the pad. A NaN (from `± grow` after an overflow, never
                // expected) is left out of the plain comparisons, which only widens the
                // interval.
                let tmin = min[k] as f32 * per_step + at_zero;
                let tmax = max[k] as f32 * per_step + at_zero;
                let (ta, tb) = if tmax < tmin {
                    (tmax, tmin)
                } else {
                    (tmin, tmax)
                };
                let grow = pad[k] * slope;
                let (ta, tb) = (ta - grow, tb + grow);
                t0[k] = if ta > t0[k] { ta } else { t0[k] };
                t1[k] = if tb < t1[k] { tb } else { t1[k] };
            }
        }
        // Met: entered no later than left, and left no earlier than the start (`t0` and `t1`
        // are never NaN), one comparison per lane, so one mask of the four (`movmskps` on x86).
        let met: [bool; 4] = core::array::from_fn(|k| {
            let from = if t0[k] > 0.0 { t0[k] } else { 0.0 };
            from <= t1[k]
        });
        let met = (0..4).fold(0, |m, k| m | (met[k] as u32) << k);
        let count = (1u32 << node.count.min(4)) - 1;
        (t0, t1, met & count)
    }
}

/// The reach of the contacts found so far as a bound on the segment's parameter, rounded up
/// (with room for the conversion).
pub(crate) fn reach_limit<S: Scalar>(reach: S) -> f32 {
    up(reach.to_f64() + 1.0 / (1u64 << 50) as f64)
}

/// The smallest `f32` not below `x` (`x` finite or infinite, not NaN).
fn up(x: f64) -> f32 {
    let y = x as f32;
    if (y as f64) < x { y.next_up() } else { y }
}

/// `2^e` for `e <= 1023`, exactly.
#[inline]
fn pow2(e: u32) -> f64 {
    f64::from_bits(((1023 + e.min(1023)) as u64) << 52)
}

/// `2^e` for `e <= 127`, exactly, in `f32`.
#[inline]
fn pow2f(e: u32) -> f32 {
    f32::from_bits((127 + e.min(127)) << 23)
}

/// `exit` if before `lim`, else infinity.
#[inline]
fn before(exit: f32, lim: f32) -> f32 {
    if exit < lim { exit } else { f32::INFINITY }
}

/// The leaves a sweep may reach, nearest first: by the box walk where the segment is short
/// ([`ShortBox`] for fixed point, [`Segment::short_walk`] for floats), else by
/// [`traverse_leaves`], whose `leaf` arguments it takes (the walk gives no exit: infinity).
/// Returns false if the tree is malformed.
pub(crate) fn leaves_along<S: Scalar>(
    nodes: &[Node],
    grid: &Grid,
    sweep: &Sweep<S>,
    acc: &mut Earliest<S>,
    mut leaf: impl FnMut(&mut Earliest<S>, core::ops::Range<usize>, f32),
) -> bool {
    let leaf_of_walk = |acc: &mut Earliest<S>, slots| leaf(acc, slots, f32::INFINITY);
    if let Some((short, walk)) = ShortBox::new(sweep, grid) {
        return walk.run(nodes, grid, acc, cached(|r| short.cells(r)), leaf_of_walk);
    }
    let seg = Segment::new(sweep, grid);
    match seg.short_walk() {
        Some(walk) => walk.run(
            nodes,
            grid,
            acc,
            cached(|r| seg.cells(reach_limit(r))),
            leaf_of_walk,
        ),
        None => traverse_leaves(nodes, grid, &seg, acc, leaf),
    }
}

/// The query box of a walk: `cells` of the reach, taken anew only when the reach changes.
fn cached<S: Scalar>(cells: impl Fn(S) -> Cells) -> impl FnMut(&Earliest<S>) -> Cells {
    let mut last: Option<(S, Cells)> = None;
    move |acc: &Earliest<S>| {
        let reach = acc.reach();
        match last {
            Some((r, c)) if r == reach => c,
            _ => {
                let c = cells(reach);
                last = Some((reach, c));
                c
            }
        }
    }
}

/// Visits the leaves the segment may reach within the current reach, nearest first, calling
/// `leaf` with each leaf's slots and where the segment leaves the leaf's grown box (a contact
/// with one of its triangles comes no later), infinity if not before the current reach;
/// `reach` gives the current limit on alpha. The
/// nearest child of a node is visited next without going through the stack, its siblings wait
/// there. Returns false if the tree is malformed (a stack overflow or a cycle: only possible
/// for parts not made by the build), in which case the caller must answer another way.
pub(crate) fn traverse_leaves<S: Scalar>(
    nodes: &[Node],
    grid: &Grid,
    seg: &Segment,
    acc: &mut Earliest<S>,
    mut leaf: impl FnMut(&mut Earliest<S>, core::ops::Range<usize>, f32),
) -> bool {
    if nodes.is_empty() {
        return true;
    }
    // The reach as an `f32` bound on the node tests' parameter; it only changes at a leaf
    // that finds a contact, and is converted anew only then.
    let mut reach = acc.reach();
    let mut lim = reach_limit(reach);
    let mut stack: heapless::Vec<Entry, STACK> = heapless::Vec::new();
    // Node visits: a tree visits each node once at most, so running out means a cycle.
    let mut budget = 5 * nodes.len() + 5;
    // The node in hand: its reference and its box's minimum.
    let (mut child, mut lo) = (0u32, grid.lo);
    loop {
        budget = match budget.checked_sub(1) {
            Some(b) => b,
            None => return false,
        };
        let Some(node) = nodes.get((child & PAYLOAD) as usize) else {
            return false;
        };
        let shift = shifts(node);
        let (enter, exit, mut met) = seg.enter4(node, lo, shift, lim);
        // The child met first is visited next (a leaf at once), the others wait on the stack.
        let mut next = None;
        if met != 0 {
            // The children met by entry, nearest first; equal entries keep child order.
            let mut near = [met.trailing_zeros() as usize; 4];
            let mut n = 1;
            met &= met - 1;
            if met != 0 && met & (met - 1) == 0 {
                // Two (the most common case after one): a single comparison.
                let k = met.trailing_zeros() as usize;
                if enter[k & 3] < enter[near[0] & 3] {
                    near[0] = k;
                } else {
                    near[1] = k;
                }
                n = 2;
            } else {
                // One, or an insertion sort of three or four.
                while met != 0 && n < 4 {
                    let k = met.trailing_zeros() as usize;
                    met &= met - 1;
                    let mut at = n;
                    while at > 0 && enter[near[at - 1] & 3] > enter[k & 3] {
                        near[at] = near[at - 1];
                        at -= 1;
                    }
                    near[at] = k;
                    n += 1;
                }
            }
            // Farthest first, so that the stack gives them back nearest first.
            for &k in near[1..n].iter().rev() {
                let child = node.children[k & 3];
                // A leaf needs no box.
                let lo = if child & LEAF_FLAG == 0 {
                    child_lo(node, shift, k, lo)
                } else {
                    lo
                };
                let (enter, exit) = (enter[k & 3], exit[k & 3]);
                if stack
                    .push(Entry {
                        enter,
                        exit,
                        child,
                        lo,
                    })
                    .is_err()
                {
                    return false;
                }
            }
            let first = near[0];
            let child = node.children[first & 3];
            match leaf_slots(child) {
                Some(slots) => {
                    leaf(acc, slots, before(exit[first & 3], lim));
                    if acc.reach() != reach {
                        reach = acc.reach();
                        lim = reach_limit(reach);
                    }
                }
                None => next = Some((child, child_lo(node, shift, first, lo))),
            }
        }
        // Else the nearest waiting child still within reach, visiting the leaves on the way.
        (child, lo) = match next {
            Some(c) => c,
            None => loop {
                let Some(e) = stack.pop() else {
                    return true;
                };
                if e.enter > lim {
                    continue;
                }
                match leaf_slots(e.child) {
                    Some(slots) => {
                        leaf(acc, slots, before(e.exit, lim));
                        if acc.reach() != reach {
                            reach = acc.reach();
                            lim = reach_limit(reach);
                        }
                    }
                    None => break (e.child, e.lo),
                }
            },
        };
    }
}
