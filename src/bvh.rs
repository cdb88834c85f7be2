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
//! consecutive triangles, referenced from its parent's child slot, whose top bits also carry the
//! subtree's *seam class* (below). A node costs 44 bytes per about 12 triangles: 3.7 bytes per
//! triangle, in every scalar.
//!
//! # Build
//! The triangles are put in Morton order of their box centres (13 bits per axis, one scale for
//! all three so a flat terrain's few height levels do not scatter it; ties by index), by one
//! stable radix sort, as linear BVH builders do (Lauterbach et al., *Fast BVH construction on
//! GPUs*, 2009; Karras, *Maximizing parallelism in the construction of BVHs, octrees, and k-d
//! trees*, HPG 2012). Then top down, a node's run of triangles is cut into up to four runs, each
//! (but the last) as long as a complete subtree one level down holds, so leaves are full and a
//! node is shared by about `3 LEAF` triangles (Jolt's `AABBTreeBuilder` likewise gathers a binary
//! tree's descendants into quad-tree nodes). Each level costs one pass to bound the
//! children, so the build takes `O(N log N)` (the sort is `O(N)`), and the depth is at most
//! `log4(N / LEAF) + 1`, which bounds the traversal stack. Keys and boxes are integers, so every
//! decision is exact: the same triangles in the same order give the same nodes, byte for byte,
//! on every target. Cuts by count in Morton order give up some of the quality of binned SAH
//! (Wald, *On fast construction of SAH-based bounding volume hierarchies*, 2007, as tinybvh
//! builds) for a guaranteed depth and a build several times faster; on a terrain, whose
//! triangles are alike and spread evenly, they lose little.
//!
//! # Traversal
//! The segment from `p0` to `p1` is taken to grid units in `f64` once per query, with the
//! reciprocal of its direction; each child box is decoded, grown, and clipped against the
//! segment with the slab test (Kay and Kajiya, 1986), so no node needs a division. Children are
//! pushed farthest first, so the nearest is visited first, and a subtree is skipped when the
//! segment enters its box after the reach of the contacts found so far (the earliest alpha plus
//! the tie window).
//!
//! Culling is conservative: a box is grown by `r`, by a bound on every rounding between the
//! exact segment and what [`StandardTriangle::cast`](crate::StandardTriangle::cast) computes —
//! `64 EPSILON` per unit of the path's length and of the coordinates' magnitude (floats;
//! `1/1024` of that for fixed point, whose frames round to 30 or 62 fractional bits), `64
//! EPSILON` absolute, `2^-40` of the magnitudes for the `f64` arithmetic here, two grid cells —
//! and by `2^c` seam margins `r / 64 + 4 EPSILON`. The face test moves a triangle's inactive
//! edges out by one seam margin, so it reaches beyond the triangle by up to `1 / sin(θ/2)`
//! margins at a corner of angle θ (`1 / sin θ` where only one of the corner's edges moved): far,
//! for a sliver. Each child carries the class `c` of its subtree, with `2^c` at least twice the
//! worst such factor of its triangles (zero when all edges are active). The rounding bounds are
//! several times the largest rounding the contact tests can make, so a triangle whose `cast`
//! reports a contact within reach is never skipped and the answer is the linear scan's, bit for
//! bit (`tests/mesh.rs` checks it on 10^5 sweeps per scalar).

use crate::merge::Earliest;
use crate::{Scalar, Sweep};

/// Most triangles in a leaf.
pub const LEAF: usize = 4;
/// Deepest tree the traversal's stack is sized for: `log4(2^24 / LEAF) + 1 = 12` levels suffice
/// for the largest mesh the build accepts.
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
pub(crate) fn seam_class(all_active: bool, [x1, z1, x2]: [f64; 3]) -> u32 {
    if all_active {
        return 0;
    }
    let corners = [(0.0, 0.0), (x1, z1), (x2, 0.0)];
    let mut worst = 1.0f64;
    for k in 0..3 {
        let (o, a, b) = (corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]);
        let (ux, uz) = (a.0 - o.0, a.1 - o.1);
        let (vx, vz) = (b.0 - o.0, b.1 - o.1);
        let len = |x: f64, z: f64| libm::sqrt(x * x + z * z);
        let (lu, lv) = (len(ux, uz), len(vx, vz));
        let sin = (ux * vz - uz * vx).abs() / (lu * lv);
        // sin(θ/2) is half the chord between the two unit directions.
        let half = len(ux / lu - vx / lv, uz / lu - vz / lv) / 2.0;
        worst = worst.max(1.0 / sin).max(1.0 / half);
    }
    let f = 2.0 * worst;
    // NaN (a zero angle) lands here too.
    if f.is_nan() || f >= (1u64 << MAX_CLASS) as f64 {
        return MAX_CLASS;
    }
    let mut c = 0;
    while ((1u64 << c) as f64) < f {
        c += 1;
    }
    c
}

/// A 4-wide node: child boxes quantized to bytes relative to this node's own box.
///
/// Child `k < count` has the box `lo + (boxes[k][a] << shift[a])` to
/// `lo + (boxes[k][3 + a] << shift[a])` per axis `a`, in grid cells, where `lo` is the node's
/// box's minimum (known from its parent, or [`Grid`] for the root). `children[k]` is a node
/// index, or with the top bit set a leaf: `first << 2 | (count - 1)` over the mesh's triangle
/// slots `first .. first + count`.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Node {
    /// Per child: minimum x, y, z, then maximum x, y, z, in steps of `2^shift`.
    pub boxes: [[u8; 6]; 4],
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

    /// The cells of the box from `min` to `max` (world units, `min <= max`), rounded outward
    /// and grown by one cell.
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

/// Why a tree could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BuildError {
    /// The node slice holds fewer than this many nodes.
    Nodes(usize),
    /// Deeper than [`MAX_DEPTH`] (cannot happen below [`MAX_TRIANGLES`]).
    Depth,
}

/// The sizes of the up to four children of a node over `n > 0` items (zeros unused): each takes
/// as many as a complete subtree one level down holds (`LEAF * 4^k` for the smallest `k` with
/// `4^(k+1)` leaves enough for all), the last what remains. Every subtree but the last at each
/// level is complete, so a mesh of `N` triangles needs about `N / (3 LEAF)` nodes.
const fn parts(n: usize) -> [usize; 4] {
    let leaves = n.div_ceil(LEAF);
    let mut per = 1;
    while per * 4 < leaves {
        per *= 4;
    }
    let per = per * LEAF;
    let mut out = [0; 4];
    let (mut k, mut left) = (0, n);
    while k < 4 {
        out[k] = if left < per { left } else { per };
        left -= out[k];
        k += 1;
    }
    out
}

/// Nodes the build makes for `n` triangles (zero for none): size the node slice with it.
pub const fn nodes_for(n: usize) -> usize {
    if n == 0 {
        return 0;
    }
    let p = parts(n);
    let mut total = 1;
    let mut k = 0;
    while k < 4 {
        if p[k] > LEAF {
            total += nodes_for(p[k]);
        }
        k += 1;
    }
    total
}

/// One triangle during the build: its box in cells (three words), its index (fourth word, low
/// half) and its [`seam_class`] (fourth word, high half).
pub(crate) type Item = [u64; 4];

/// Packs a box, an index and a seam class into an [`Item`].
pub(crate) fn item((lo, hi): Cells, index: usize, class: u32) -> Item {
    let w = |a: i32, b: i32| (a as u32 as u64) | ((b as u32 as u64) << 32);
    [
        w(lo[0], lo[1]),
        w(lo[2], hi[0]),
        w(hi[1], hi[2]),
        index as u32 as u64 | (class as u64) << 32,
    ]
}

/// The index of an [`Item`].
pub(crate) fn item_index(it: &Item) -> usize {
    it[3] as u32 as usize
}

/// The box of an [`Item`].
pub(crate) fn item_box(it: &Item) -> Cells {
    let lo = |w: u64| w as u32 as i32;
    let hi = |w: u64| (w >> 32) as u32 as i32;
    (
        [lo(it[0]), hi(it[0]), lo(it[1])],
        [hi(it[1]), lo(it[2]), hi(it[2])],
    )
}

/// The union of the items' boxes.
pub(crate) fn union(items: &[Item]) -> Cells {
    let mut b = ([i32::MAX; 3], [i32::MIN; 3]);
    for it in items {
        let (lo, hi) = item_box(it);
        for a in 0..3 {
            b.0[a] = b.0[a].min(lo[a]);
            b.1[a] = b.1[a].max(hi[a]);
        }
    }
    b
}

/// Bits per axis of a Morton key.
pub(crate) const MORTON_BITS: u32 = 13;

/// The Morton key of a point with coordinates below `2^MORTON_BITS`: their bits interleaved,
/// x lowest.
pub(crate) fn morton(q: [u64; 3]) -> u64 {
    let mut key = 0;
    for bit in 0..MORTON_BITS {
        for (a, &v) in q.iter().enumerate() {
            key |= (v >> bit & 1) << (3 * bit + a as u32);
        }
    }
    key
}

/// Builds the tree over `items` (each a triangle's box, index and seam class, in Morton order)
/// into `nodes`, the root's box being `root`. Returns the number of nodes used.
pub(crate) fn build(
    items: &mut [Item],
    root: Cells,
    nodes: &mut [Node],
) -> Result<usize, BuildError> {
    let n = items.len();
    let needed = nodes_for(n);
    if nodes.len() < needed {
        return Err(BuildError::Nodes(needed));
    }
    if n == 0 {
        return Ok(0);
    }
    // (node, first item, item count, node box, depth)
    let mut work: heapless::Vec<(usize, usize, usize, Cells, usize), STACK> = heapless::Vec::new();
    let _ = work.push((0, 0, n, root, 1));
    let mut next = 1;
    while let Some((at, first, count, (lo, hi), depth)) = work.pop() {
        if depth > MAX_DEPTH {
            return Err(BuildError::Depth);
        }
        let range = &mut items[first..first + count];
        // Up to four runs of the Morton order.
        let p = parts(count);
        let bounds = [
            (0, p[0]),
            (p[0], p[0] + p[1]),
            (p[0] + p[1], p[0] + p[1] + p[2]),
            (p[0] + p[1] + p[2], count),
        ];
        let mut node = Node::default();
        for ax in 0..3 {
            let extent = hi[ax] as i64 - lo[ax] as i64;
            let mut s = 0;
            while extent > 255 << s {
                s += 1;
            }
            node.shift[ax] = s as u8;
        }
        for &(s, e) in &bounds {
            if s == e {
                continue;
            }
            let part = &mut range[s..e];
            let (clo, chi) = union(part);
            let k = node.count as usize;
            let mut dlo = [0; 3];
            let mut dhi = [0; 3];
            for ax in 0..3 {
                let sh = node.shift[ax] as u32;
                let step = 1i64 << sh;
                let qlo = (clo[ax] as i64 - lo[ax] as i64) >> sh;
                let qhi = (chi[ax] as i64 - lo[ax] as i64 + step - 1) >> sh;
                node.boxes[k][ax] = qlo as u8;
                node.boxes[k][3 + ax] = qhi as u8;
                dlo[ax] = lo[ax] + ((qlo as i32) << sh);
                dhi[ax] = lo[ax] + ((qhi as i32) << sh);
            }
            let class = part
                .iter()
                .map(|it| (it[3] >> 32) as u32)
                .max()
                .unwrap_or(0);
            let class = class.min(MAX_CLASS) << CLASS_SHIFT;
            if part.len() <= LEAF {
                part.sort_unstable_by_key(item_index);
                node.children[k] =
                    LEAF_FLAG | class | ((first + s) as u32) << 2 | (part.len() - 1) as u32;
            } else {
                let child = next;
                next += 1;
                if child >= nodes.len() {
                    return Err(BuildError::Nodes(needed));
                }
                node.children[k] = class | child as u32;
                if work
                    .push((child, first + s, e - s, (dlo, dhi), depth + 1))
                    .is_err()
                {
                    return Err(BuildError::Depth);
                }
            }
            node.count += 1;
        }
        nodes[at] = node;
    }
    Ok(next)
}

/// A child to visit: where the segment enters its box, its reference, and its box's minimum
/// (all that decoding its children needs).
#[derive(Clone, Copy)]
struct Entry {
    enter: f64,
    child: u32,
    lo: [i32; 3],
}

/// The swept segment in grid units, with what every box test needs.
pub(crate) struct Segment {
    q0: [f64; 3],
    d: [f64; 3],
    inv: [f64; 3],
    /// How far (cells) every box is grown: the radius plus every rounding (module docs).
    pad: f64,
    /// The seam margin `r / 64 + 4 EPSILON` (cells), grown by `2^class` per child.
    seam: f64,
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
        let eps = S::PRECISION.epsilon;
        let per_unit = if S::PRECISION.relative {
            1.0
        } else {
            1.0 / 1024.0
        };
        let pad = r
            + eps * 64.0 * (1.0 + 3.0 * big(d))
            + (64.0 * eps * per_unit + 1.0 / (1u64 << 40) as f64) * 3.0 * magnitude;
        let seam = r / 64.0 + 4.0 * eps;
        let q0 = p0.map(|x| x * s);
        let d = d.map(|x| x * s);
        Self {
            q0,
            d,
            inv: d.map(|x| 1.0 / x),
            pad: pad * s + 2.0,
            seam: seam * s,
        }
    }

    /// Where the segment, over `[0, limit]`, enters each of the four child boxes of `node` (whose
    /// own minimum is `lo`), each grown by the pad and `2^class` seam margins of its child;
    /// infinity where it misses. The four are computed side by side, lane by lane, so the
    /// compiler can use vector registers; slots beyond `count` are computed and ignored.
    #[inline]
    fn enter4(&self, node: &Node, lo: [i32; 3], limit: f64) -> [f64; 4] {
        let mut pad = [0.0f64; 4];
        for (k, p) in pad.iter_mut().enumerate() {
            let class = ((node.children[k] & !LEAF_FLAG) >> CLASS_SHIFT).min(MAX_CLASS);
            // 2^class, exactly.
            *p = self.pad + self.seam * f64::from_bits(((1023 + class) as u64) << 52);
        }
        let (mut t0, mut t1) = ([0.0f64; 4], [limit; 4]);
        for (a, &base) in lo.iter().enumerate() {
            let sh = node.shift[a].min(31) as u32;
            let at = |v: u8| base.wrapping_add((v as i32).wrapping_shl(sh)) as f64;
            let near: [f64; 4] =
                core::array::from_fn(|k| at(node.boxes[k][a]) - pad[k] - self.q0[a]);
            let far: [f64; 4] =
                core::array::from_fn(|k| at(node.boxes[k][3 + a]) + pad[k] - self.q0[a]);
            let inv = self.inv[a];
            if !inv.is_finite() {
                // Parallel to the slab (or as good as): inside it all along, or never.
                let d = self.d[a].abs();
                for k in 0..4 {
                    if near[k] > d || far[k] < -d {
                        t0[k] = f64::INFINITY;
                    }
                }
                continue;
            }
            let (first, second) = if inv > 0.0 { (near, far) } else { (far, near) };
            for k in 0..4 {
                let (ta, tb) = (first[k] * inv, second[k] * inv);
                // Plain comparisons: a NaN (never expected) would only widen the interval.
                if ta > t0[k] {
                    t0[k] = ta;
                }
                if tb < t1[k] {
                    t1[k] = tb;
                }
            }
        }
        core::array::from_fn(|k| if t0[k] <= t1[k] { t0[k] } else { f64::INFINITY })
    }
}

/// Decodes child `k` of `node`, whose own box has minimum `lo`.
#[inline]
fn child_cells(node: &Node, k: usize, lo: [i32; 3]) -> Cells {
    let q = node.boxes[k];
    let at =
        |a: usize, v: u8| lo[a].wrapping_add((v as i32).wrapping_shl(node.shift[a].min(31) as u32));
    (
        [at(0, q[0]), at(1, q[1]), at(2, q[2])],
        [at(0, q[3]), at(1, q[4]), at(2, q[5])],
    )
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
    let limit = |r: S| r.to_f64() + 1.0 / (1u64 << 50) as f64;
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
        let mut near = [(0.0f64, 0usize, [0i32; 3]); 4];
        let mut n = 0;
        for (k, &t) in enter.iter().enumerate().take((node.count as usize).min(4)) {
            if t <= lim {
                // Insertion by entry, nearest first; equal entries keep child order.
                let mut at = n;
                while at > 0 && near[at - 1].0 > t {
                    near[at] = near[at - 1];
                    at -= 1;
                }
                near[at] = (t, k, child_cells(node, k, e.lo).0);
                n += 1;
            }
        }
        for &(t, k, lo) in near[..n].iter().rev() {
            let entry = Entry {
                enter: t,
                child: node.children[k],
                lo,
            };
            if stack.push(entry).is_err() {
                return false;
            }
        }
    }
    true
}
