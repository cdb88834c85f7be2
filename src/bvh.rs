//! A bounding volume hierarchy over a mesh's triangles: 4-wide nodes with child boxes quantized
//! to bytes on an integer grid, built by object-median splits, traversed nearest child first
//! by a ball's swept segment.
//!
//! # Layout
//! Every box lives on one integer grid per mesh ([`Grid`]): a cell is `2^exponent` units, chosen
//! so the largest coordinate spans at most 2^24 cells, and a triangle's box is its vertices'
//! box rounded outward (down for minima, up for maxima) and grown by one cell. A [`Node`]
//! (44 bytes) holds up to four children; each child's box is stored in six bytes relative to
//! the node's own box, in steps of `2^shift` cells per axis, minima rounded down and maxima up,
//! so a decoded box always contains what it stands for. Rounding outward on purpose is Jolt's
//! (`Jolt/AABBTree/NodeCodec/NodeCodecQuadTreeHalfFloat.h` stores four child boxes per 64-byte
//! node as half floats, minima rounded towards −∞ and maxima towards +∞); bytes relative to the
//! parent are the compressed wide BVH's (Ylitie, Karras and Laine, *Efficient incoherent ray
//! traversal on GPUs through compressed wide BVHs*, HPG 2017). Here the arithmetic is integer,
//! so decoding is exact and the same on every target. A leaf is a run of at most [`LEAF`]
//! consecutive triangles (the build makes leaves of up to two, or four: [`LeafSize`]),
//! referenced from its parent's child slot, whose top bits also carry the subtree's *seam
//! class* (below). The boxes are stored bound by bound (the four children's
//! minima in x, then in y, ...), so the traversal loads one bound of all four children at once.
//! A node costs 44 bytes per about 6 triangles with leaves of two (7.3 bytes per triangle, in
//! every scalar), per about 12 with leaves of four (3.7 bytes). Leaves of two test fewer
//! triangles that are near but out of reach (a short move on a terrain of 10^5 triangles: about
//! 8 instead of 13), which saves more than the extra nodes cost: such queries take about 0.85
//! times as long, long casts about 0.8 times; a compact mesh, whose triangles are small and
//! whose tree is a large share of its memory, takes leaves of four.
//!
//! # Build
//! Top down, a node's triangles are split at the median of their box centres along the longest
//! axis of the node's box, and each half again along its own longest axis (of the node's box cut
//! at the median), into up to four runs, each (but the last) as long as a complete subtree one
//! level down holds, so leaves are full and a node is shared by about three leaves' triangles (Jolt's
//! `AABBTreeBuilder` likewise gathers a binary tree's descendants into quad-tree nodes).
//! Splitting into equal counts along the longest axis is pbrt's *equal counts* method (Pharr,
//! Jakob and Humphreys, *Physically Based Rendering*, 4th ed., 7.3). Each triangle is one
//! 64-bit key: its centre quantized to 13 bits per axis on one scale for the three axes, above
//! its index; each split arranges the centres in the keys by the node's axes, longest first,
//! and selects (`select_nth_unstable`, `O(n)`) by the whole key: the centre on the split axis,
//! then on the next longest, the last, the index. (Where centres tie on the split axis, as a
//! grid's columns do, the next longest axis keeps a run cut out of a column a stretch of it: by
//! height instead, leaves of a 224 × 224 terrain took triangles from all along their column,
//! and its short moves and long casts cost 5 % more instructions.) So each level costs `O(N)`,
//! the build `O(N log N)`, and the depth is at most
//! `log4(N / 2) + 1`, which bounds the traversal stack. Keys and boxes are integers and the
//! order is total, so every split is exact: the same triangles in the same order give the same
//! nodes, byte for byte, on every target, whatever algorithm makes the selection. Equal counts
//! give up some of the quality of binned SAH (Wald, *On fast construction of SAH-based bounding
//! volume hierarchies*, 2007, as tinybvh builds) for a guaranteed depth and a faster build; on a
//! terrain, whose triangles are alike and spread evenly, they lose little. Cutting a Morton
//! order into runs by count, as linear BVH builders do (Lauterbach et al., *Fast BVH
//! construction on GPUs*, 2009), makes runs that straddle the Morton cells: on a 10^5-triangle
//! terrain, short moves visit more nodes.
//!
//! # Traversal
//! The segment from `p0` to `p1` is taken to grid units in `f64` once per query, with the
//! reciprocal of its direction (`2^100` on an axis where the direction is below `2^-100`: the
//! pad below covers the difference), that reciprocal rounded to `f32` (an axis along which
//! the segment spans more than `2^100` cells, whose reciprocal `f32` cannot scale exactly,
//! culls nothing). Each node takes the segment into its own byte steps per axis
//! (`t = byte · 2^shift / d + (lo − p0) / d`: a scale, `2^shift` times the `f32` reciprocal,
//! exact, and an offset, in `f64`), and clips its four child boxes, grown, against it with the
//! slab test (Kay and Kajiya, 1986) in `f32`, four lanes side by side, bound by bound, without
//! a branch or a division: per axis the earlier of the two bounds' crossings is where the line
//! enters the slab, whichever way it runs, and both move out by the pad. Children are
//! ordered by where the segment's line enters their boxes, even before the start (boxes that
//! hold the start all begin at zero along the segment itself, and this orders them on a short
//! move better than child order): the first is visited next (a leaf at once), the others wait
//! on a stack, and a subtree is skipped when the segment enters its box after the reach of the
//! contacts found so far (the earliest alpha plus the tie window, taken anew after each leaf).
//! A leaf's triangles are cast in index order, with that reach lowered to where the segment
//! leaves the leaf's grown box where that comes first (the box holds every contact with them,
//! so none comes later), which lets a cast give up early when the ball is still above the
//! triangle's plane there.
//!
//! A short segment, no longer on any axis than the pad, is hardly thinner than its own box, so
//! for it the slab test is replaced by a box walk: the segment's box up to the current reach,
//! grown by the pad and rounded outward to cells, is compared with each child's box, grown by
//! its seam margins, in integers — six comparisons per child and no floating point, which on a
//! core without a floating-point unit (Cortex-M0) saves the software `f32` arithmetic of every
//! node. Children are visited in the order of their centres along the motion's signs, nearest
//! first; the box shrinks as contacts are found. Every box the padded segment enters meets its
//! box, so the walk reaches every leaf the slab test does, and the answer is the same. For a
//! fixed-point scalar the walk's box is made from the coordinates' bits by integer shifts
//! (a cell is a power of two of the scalar's steps), with the pad's terms rounded up, so a
//! short sweep there needs no floating point at all.
//!
//! Culling is conservative: a box is grown by `r`, by a bound on every rounding between the
//! exact segment and what [`StandardTriangle::cast`](crate::StandardTriangle::cast) computes —
//! `8 EPSILON` per unit of the path's largest component (a contact's alpha is rounded by up to
//! half a step, `EPSILON / 2`, which moves it along the path by that much per unit of length),
//! `192 EPSILON` per unit of the coordinates' magnitude (floats; `1/1024` of that for fixed
//! point, whose frames round to 30 or 62 fractional bits), `64 EPSILON` absolute, `2^-40` of the magnitudes for the `f64` arithmetic here, two grid cells,
//! and for the `f32` node tests (a few roundings of `2^-24` of their terms) `2^-19` of twice the
//! magnitudes in cells plus a node's largest extent (2^26 cells), with the whole pad grown by
//! `2^-19` of itself — and by `2^c` seam margins `r / 64 + 4 EPSILON`. The face test moves a triangle's inactive
//! edges out by one seam margin, so it reaches beyond the triangle by up to `1 / sin(θ/2)`
//! margins at a corner of angle θ (`1 / sin θ` where only one of the corner's edges moved): far,
//! for a sliver. Each child carries the class `c` of its subtree, with `2^c` at least twice the
//! worst such factor of its triangles (zero when all edges are active). The rounding bounds are
//! several times the largest rounding the contact tests can make, so a triangle whose `cast`
//! reports a contact within reach is never skipped and the answer is the linear scan's, bit for
//! bit (`tests/mesh.rs` checks it on 10^5 sweeps per scalar).

mod build;
mod decode;
mod overlap;
mod short;
#[cfg(test)]
mod tests;
mod traverse;

use crate::{Scalar, Triangle, Vec3};

pub(crate) use build::{BuildError, build, item, key_index, set_classes};
pub use build::{nodes_for, nodes_for_leaves};
pub(crate) use decode::leaf_slots;
pub(crate) use overlap::{overlapping, query_cells};
pub(crate) use short::unit_pad;
pub(crate) use traverse::{leaves_along, ray_pad, rounding_pad};

/// Most triangles in a leaf of any tree (a leaf reference holds its count in two bits).
pub const LEAF: usize = 4;

/// How many triangles the build puts in a leaf: the tree's memory against the triangles a query
/// tests. Queries test every triangle of the leaves they reach, so smaller leaves test fewer
/// triangles that are near but out of reach, for about twice the nodes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LeafSize {
    /// Up to two triangles a leaf: about 7.3 bytes of tree per triangle, the fastest queries.
    #[default]
    Two,
    /// Up to four: about 3.7 bytes of tree per triangle, for the smallest meshes (a
    /// [`CompactMesh`](crate::CompactMesh) borrows its mesh's tree); queries test about 1.6
    /// times the triangles.
    Four,
}

impl LeafSize {
    /// The most triangles in a leaf.
    pub const fn triangles(self) -> usize {
        match self {
            LeafSize::Two => 2,
            LeafSize::Four => 4,
        }
    }
}

/// Deepest tree the traversal's stack is sized for: the largest mesh the build accepts, 2^24
/// triangles in leaves of two, takes 12 levels.
pub const MAX_DEPTH: usize = 16;
/// Entries of the traversal stack: three siblings wait per level, plus the root.
const STACK: usize = 3 * MAX_DEPTH + 4;

/// A child reference with this bit set is a leaf: `first << 2 | (count - 1)`.
const LEAF_FLAG: u32 = 1 << 31;
/// Bits 26 to 30 of a child reference: its subtree's [`seam_class`].
const CLASS_SHIFT: u32 = 26;
/// The payload of a child reference: a node index, or a leaf's `first << 2 | (count - 1)`.
const PAYLOAD: u32 = (1 << CLASS_SHIFT) - 1;
/// The most triangles a tree takes (leaf references hold `first` in 24 bits).
pub const MAX_TRIANGLES: usize = 1 << 24;
/// The largest seam class: boxes grown by `2^31` seam margins, reached by every query.
const MAX_CLASS: u32 = 31;

/// How far beyond its triangle a face contact of `cast` can lie, in units of the seam margin
/// `r / 64 + 4 EPSILON` by which inactive edges are moved out: the class `c` with
/// `2^c >= 2 F`, where `F` is the largest displacement of a corner when the edges of the
/// standardized triangle `(0, 0)`, `(x1, z1)`, `(x2, 0)` are moved out by one unit: `1 / sin(θ/2)`
/// where both edges at a corner of angle θ move, `1 / sin θ` where one does. The factor 2 covers
/// the rounding of the frame. Zero when every edge is active (no margin), [`MAX_CLASS`] for a
/// sliver too thin to tell.
///
/// The sines come from the prepared triangle's unit edge directions `u` (leaving a corner) and
/// `w` (arriving): `sin θ = |u × w|` and `sin(θ/2) = |u + w| / 2`, compared squared, so no
/// square root and one division (a tenth off the build of a mesh of 10^5 triangles). Those
/// directions are rounded (by up to `2^-24` for `f32`), so the result is grown by a margin
/// that covers it, which takes the class one higher than the shape's own where that lies
/// within a fifth of a percent below a power of two; a sine below `2^-10`, which the rounding
/// moves by more, comes from its shape in `f64` instead ([`sliver_class`]).
pub(crate) fn seam_class<S: crate::Scalar>(
    all_active: bool,
    t: &crate::StandardTriangle<S>,
) -> u32 {
    if all_active {
        return 0;
    }
    let dir = |i: usize| t.edge(i).dir.map(S::unit_to_f64);
    let d = [dir(0), dir(1), dir(2)];
    // The smallest squared sine over the corners, of the angle and of its half.
    let mut least = f64::INFINITY;
    for k in 0..3 {
        // At corner k edge k leaves (u) and edge k + 2 arrives (w, pointing in).
        let ([ux, uz], [wx, wz]) = (d[k], d[(k + 2) % 3]);
        let sin = ux * wz - uz * wx;
        let (hx, hz) = (ux + wx, uz + wz);
        least = least.min(sin * sin).min((hx * hx + hz * hz) * 0.25);
    }
    if !least.is_finite() || least < 1.0 / (1u64 << 20) as f64 {
        let [_, b, c] = t.vertices();
        return sliver_class([b.x, b.z, c.x].map(S::to_f64));
    }
    // 2^c >= f = 2 max(1 / sin, 1) where 4^c >= f^2 = 4 max(1 / least, 1): c is half of
    // f^2's exponent rounded up (itself rounded up unless f^2 is a power of two). `f^2` is
    // grown by 2^-9, more than the directions' rounding moves it (their components are off by
    // up to 2^-24, so a sine of at least 2^-10 by under 2^-12 of itself): the class never
    // falls short.
    let f2 = 4.0 * (1.0 / least).max(1.0) * (1.0 + 1.0 / 512.0);
    let bits = f2.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as u32 - 1023;
    (exponent + (bits & ((1 << 52) - 1) != 0) as u32).div_ceil(2)
}

/// [`seam_class`] of a sliver from its standardized shape `[x1, z1, x2]`, in `f64`.
fn sliver_class([x1, z1, x2]: [f64; 3]) -> u32 {
    let corners = [(0.0, 0.0), (x1, z1), (x2, 0.0)];
    let len = |x: f64, z: f64| libm::sqrt(x * x + z * z);
    // Edge k runs from corner k to corner k + 1: its vector, length and unit direction.
    let edge = |(ox, oz): (f64, f64), (ax, az): (f64, f64)| {
        let (x, z) = (ax - ox, az - oz);
        let l = len(x, z);
        (x, z, l, x / l, z / l)
    };
    let edges = [
        edge(corners[0], corners[1]),
        edge(corners[1], corners[2]),
        edge(corners[2], corners[0]),
    ];
    // The smallest sine over the corners, of the angle and of its half: the worst factor is
    // its reciprocal (NaN, from a zero angle, is left out by `min`).
    let mut least = f64::INFINITY;
    for k in 0..3 {
        // At corner k one edge leaves (u, edge k) and one arrives (w, edge k + 2, pointing in).
        let (ux, uz, lu, dux, duz) = edges[k];
        let (wx, wz, lw, dwx, dwz) = edges[(k + 2) % 3];
        let sin = (ux * wz - uz * wx).abs() / (lu * lw);
        // sin(θ/2) is half the chord between the two unit directions away from the corner.
        let half = len(dux + dwx, duz + dwz) / 2.0;
        least = least.min(sin).min(half);
    }
    let f = 2.0 * (1.0 / least).max(1.0);
    // NaN cannot reach here; a zero sine makes `f` infinite.
    if f >= (1u64 << MAX_CLASS) as f64 {
        return MAX_CLASS;
    }
    // The smallest c with 2^c >= f (f >= 2): f's exponent, plus one unless f is a power of two.
    let bits = f.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as u32 - 1023;
    exponent + (bits & ((1 << 52) - 1) != 0) as u32
}

/// The seam class of the subtree a child reference (of a [`Node`]) leads to.
pub(crate) fn class_bits(child: u32) -> u32 {
    (child >> CLASS_SHIFT) & MAX_CLASS
}

/// The [`seam_class`] of a prepared triangle, by its active edges and its shape.
pub(crate) fn class_of<S: crate::Scalar>(t: &crate::StandardTriangle<S>) -> u32 {
    seam_class((0..3).all(|e| t.features().edge(e)), t)
}

/// A 4-wide node: child boxes quantized to bytes relative to this node's own box.
///
/// Child `k < count` has the box `lo + (boxes[a][k] << shift[a])` to
/// `lo + (boxes[3 + a][k] << shift[a])` per axis `a`, in grid cells, where `lo` is the node's
/// box's minimum (known from its parent, or [`Grid`] for the root). `children[k]` is a node
/// index, or with the top bit set a leaf: `first << 2 | (count - 1)` over the mesh's triangle
/// slots `first .. first + count`.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Node {
    /// Minimum x, y, z, then maximum x, y, z, each per child, in steps of `2^shift` (bound by
    /// bound, so the traversal loads one bound of the four children at once).
    pub boxes: [[u8; 4]; 6],
    /// Per axis: the step of the quantized boxes, `2^shift` grid cells.
    pub shift: [u8; 3],
    /// Children in use, 1 to 4.
    pub count: u8,
    /// Per child: a node index, or a leaf (top bit set).
    pub children: [u32; 4],
}

const _: () = assert!(core::mem::size_of::<Node>() == 44);

/// The integer grid of a mesh's boxes and the root's box on it.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Grid {
    /// A cell is `2^exponent` units of length.
    pub exponent: i32,
    /// The root box's minimum, in cells.
    pub lo: [i32; 3],
    /// The root box's maximum, in cells.
    pub hi: [i32; 3],
}

/// An axis-aligned box in grid cells.
pub(crate) type Cells = ([i32; 3], [i32; 3]);

impl Grid {
    /// `2^-exponent`: world units to cells (exact, a power of two).
    pub(crate) fn scale(exponent: i32) -> f64 {
        f64::from_bits(((1023 - exponent.clamp(-1000, 1000)) as u64) << 52)
    }

    /// The exponent for coordinates up to `largest` in magnitude: at most 2^24 cells from the
    /// origin, clamped so scaled coordinates stay normal `f64` numbers.
    pub(crate) fn exponent_for(largest: f64) -> i32 {
        let e = ((largest.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        (e + 1 - 24).clamp(-900, 1000)
    }

    /// The largest coordinate's magnitude of the root box, world units.
    pub(crate) fn magnitude(&self) -> f64 {
        let cells = self.lo.iter().chain(self.hi.iter());
        cells.fold(0.0f64, |m, &c| m.max((c as f64).abs())) / Self::scale(self.exponent)
    }

    /// The box a query from `min` to `max` (a [`Geometry::visit`](crate::Geometry::visit))
    /// takes, world units: grown by every rounding of the exact tests its triangles go to, at
    /// the magnitude of the box or of the mesh (as a heightfield's query is), so a triangle
    /// those tests find within reach is never left out.
    pub(crate) fn visit_box<S: Scalar>(&self, min: Vec3<S>, max: Vec3<S>) -> [[f64; 3]; 2] {
        let (lo, hi) = (min.to_array().map(S::to_f64), max.to_array().map(S::to_f64));
        let big = |a: [f64; 3]| a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let magnitude = big(lo).max(big(hi)).max(self.magnitude());
        let slack = traverse::rounding_pad::<S>(0.0, 0.0, magnitude);
        [lo.map(|v| v - slack), hi.map(|v| v + slack)]
    }

    /// The bounding box of a triangle in world units, `f64`.
    #[inline]
    pub(crate) fn bounds<S: Scalar>(t: &Triangle<S>) -> ([f64; 3], [f64; 3]) {
        let (p, q, r) = (t.v0.to_array(), t.v1.to_array(), t.v2.to_array());
        let lo = |a: S, b: S| if b < a { b } else { a };
        let hi = |a: S, b: S| if b > a { b } else { a };
        (
            [0, 1, 2].map(|a| lo(lo(p[a], q[a]), r[a]).to_f64()),
            [0, 1, 2].map(|a| hi(hi(p[a], q[a]), r[a]).to_f64()),
        )
    }

    /// The cells of the box from `min` to `max` (world units, `min <= max`), rounded outward
    /// and grown by one cell.
    #[inline]
    pub(crate) fn cells(exponent: i32, min: [f64; 3], max: [f64; 3]) -> Cells {
        let s = Self::scale(exponent);
        (min.map(|v| floor(v * s) - 1), max.map(|v| ceil(v * s) + 1))
    }
}

/// The largest integer not above `v`, for `|v| < 2^30` (exact: no rounding mode involved).
fn floor(v: f64) -> i32 {
    let t = v as i32;
    if (t as f64) > v { t - 1 } else { t }
}

/// The smallest integer not below `v`, for `|v| < 2^30`.
fn ceil(v: f64) -> i32 {
    let t = v as i32;
    if (t as f64) < v { t + 1 } else { t }
}
