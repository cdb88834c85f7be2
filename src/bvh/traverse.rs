//! The swept-ball traversal: the segment against inflated child boxes, nearest child first
//! (see the module docs of [`bvh`](super)).

use super::{CLASS_SHIFT, Cells, Grid, LEAF_FLAG, MAX_CLASS, Node, PAYLOAD, STACK};
use crate::merge::Earliest;
use crate::{Scalar, Sweep};

/// A child to visit: where the segment enters its box, its reference, and its box's minimum
/// (all that decoding its children needs).
#[derive(Clone, Copy)]
struct Entry {
    enter: f32,
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

/// The swept segment in grid units, with what every box test needs.
pub(crate) struct Segment {
    q0: [f64; 3],
    /// Per axis, the reciprocal of the segment's extent, `2^100` where that is below `2^-100`
    /// (parallel to the slab, as good as: the pad covers the difference).
    inv: [f64; 3],
    /// How far (cells) every box is grown: the radius plus every rounding (module docs), in
    /// `f32` for the node tests, rounded up.
    pad: f32,
    /// The seam margin `r / 64 + 4 EPSILON` (cells), grown by `2^class` per child; `f32`,
    /// rounded up.
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
        let cells = grid.lo.iter().chain(grid.hi.iter());
        let mesh = cells.fold(0.0f64, |m, &c| m.max((c as f64).abs())) / s;
        let d = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
        let magnitude = big(p0).max(big(p1)).max(mesh);
        let pad = rounding_pad::<S>(r, big(d), magnitude);
        let seam = r / 64.0 + 4.0 * S::PRECISION.epsilon;
        let q0 = p0.map(|x| x * s);
        let d = d.map(|x| x * s);
        let tiny = 1.0 / pow2(100);
        // The node tests' `f32` arithmetic: a few roundings of 2^-24 of terms below the
        // segment's and the mesh's magnitudes in cells, a node's extent (2^26) and the pad.
        let grow = 1.0 + 1.0 / pow2(19);
        let slack = (2.0 * magnitude * s + pow2(26)) / pow2(19);
        Self {
            q0,
            inv: d.map(|x| if x.abs() > tiny { 1.0 / x } else { pow2(100) }),
            pad: up((pad * s + 2.0 + slack) * grow),
            seam: up(seam * s * grow),
        }
    }

    /// Where the segment, over `[0, limit]`, enters each of the four child boxes of `node` (whose
    /// own minimum is `lo`), each grown by the pad and `2^class` seam margins of its child;
    /// infinity where it misses. The four are computed side by side, lane by lane and without
    /// branches, so the compiler can use vector registers; slots beyond `count` are computed and
    /// ignored.
    #[inline]
    fn enter4(&self, node: &Node, lo: [i32; 3], limit: f32) -> [f32; 4] {
        let pad: [f32; 4] = core::array::from_fn(|k| {
            let class = ((node.children[k] & !LEAF_FLAG) >> CLASS_SHIFT).min(MAX_CLASS);
            self.pad + self.seam * pow2(class) as f32
        });
        let (mut t0, mut t1) = ([0.0f32; 4], [limit; 4]);
        for (a, (&inv, &base)) in self.inv.iter().zip(&lo).enumerate() {
            // The side the segment enters a slab by, and the pad's sign there, as parameters.
            let (first, second, signed) = if inv >= 0.0 {
                (a, 3 + a, inv as f32)
            } else {
                (3 + a, a, -inv as f32)
            };
            // In the node's steps: t = byte * per_step + at_zero (module docs).
            let per_step = (pow2(node.shift[a].min(31) as u32) * inv) as f32;
            let at_zero = ((base as f64 - self.q0[a]) * inv) as f32;
            let (qa, qb) = (node.boxes[first], node.boxes[second]);
            for k in 0..4 {
                let grow = pad[k] * signed;
                let ta = qa[k] as f32 * per_step + (at_zero - grow);
                let tb = qb[k] as f32 * per_step + (at_zero + grow);
                // Plain comparisons: a NaN (an overflow, never expected) only widens the interval.
                t0[k] = if ta > t0[k] { ta } else { t0[k] };
                t1[k] = if tb < t1[k] { tb } else { t1[k] };
            }
        }
        core::array::from_fn(|k| if t0[k] <= t1[k] { t0[k] } else { f32::INFINITY })
    }
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

/// Decodes child `k` of `node`, whose own box has minimum `lo`.
#[inline]
pub(super) fn child_cells(node: &Node, k: usize, lo: [i32; 3]) -> Cells {
    let at = |b: usize| {
        let (a, v) = (b % 3, node.boxes[b][k & 3]);
        lo[a].wrapping_add((v as i32).wrapping_shl(node.shift[a].min(31) as u32))
    };
    ([at(0), at(1), at(2)], [at(3), at(4), at(5)])
}

/// The triangle slots of a leaf reference: `first .. first + count`.
#[inline]
pub(crate) fn leaf_slots(child: u32) -> Option<core::ops::Range<usize>> {
    (child & LEAF_FLAG != 0).then(|| {
        let first = ((child & PAYLOAD) >> 2) as usize;
        first..first + (child & 3) as usize + 1
    })
}

/// Visits the leaves the segment may reach within the current reach, nearest first, calling
/// `leaf` with each leaf's slots; `reach` gives the current limit on alpha. Returns false if the
/// tree is malformed (a stack overflow or a cycle: only possible for parts not made by the
/// build), in which case the caller must answer another way.
pub(crate) fn traverse<S: Scalar>(
    nodes: &[Node],
    grid: &Grid,
    seg: &Segment,
    acc: &mut Earliest<S>,
    mut leaf: impl FnMut(&mut Earliest<S>, core::ops::Range<usize>),
) -> bool {
    if nodes.is_empty() {
        return true;
    }
    let limit = |r: S| up(r.to_f64() + 1.0 / (1u64 << 50) as f64);
    let mut stack: heapless::Vec<Entry, STACK> = heapless::Vec::new();
    let _ = stack.push(Entry {
        enter: 0.0,
        child: 0,
        lo: grid.lo,
    });
    let mut budget = 5 * nodes.len() + 5;
    while let Some(e) = stack.pop() {
        budget = match budget.checked_sub(1) {
            Some(b) => b,
            None => return false,
        };
        let lim = limit(acc.reach());
        if e.enter > lim {
            continue;
        }
        if let Some(slots) = leaf_slots(e.child) {
            leaf(acc, slots);
            continue;
        }
        let Some(node) = nodes.get((e.child & PAYLOAD) as usize) else {
            return false;
        };
        let enter = seg.enter4(node, e.lo, lim);
        let mut near = [(0.0f32, 0usize); 4];
        let mut n = 0;
        for (k, &t) in enter.iter().enumerate().take((node.count as usize).min(4)) {
            if t <= lim {
                // Insertion by entry, nearest first; equal entries keep child order.
                let mut at = n;
                while at > 0 && near[at - 1].0 > t {
                    near[at] = near[at - 1];
                    at -= 1;
                }
                near[at] = (t, k);
                n += 1;
            }
        }
        for &(enter, k) in near[..n].iter().rev() {
            let child = node.children[k & 3];
            let entry = Entry {
                enter,
                child,
                // A leaf needs no box.
                lo: if child & LEAF_FLAG == 0 {
                    child_cells(node, k, e.lo).0
                } else {
                    e.lo
                },
            };
            if stack.push(entry).is_err() {
                return false;
            }
        }
    }
    true
}
