//! Active edges from adjacency: the one rule [`Scene`](crate::Scene) and [`Mesh`](crate::Mesh)
//! both apply, and the sort that finds a mesh's shared edges in `O(N)` (a radix sort).
//!
//! An edge shared by two triangles with opposite winding (the same two vertices in value:
//! `-0.0` is `0.0`) is switched off in both when the surface continues flat there (front normals within 1/1024 per
//! component) or, for one-sided triangles, folds towards the front (a valley: the neighbour's far
//! vertex lies in front of the triangle's plane). Ridges and open edges stay active. A vertex stays
//! active while one of the triangle's two edges through it does. These are Jolt's *active edges*
//! (`Jolt/Geometry/ActiveEdges.h`), decided here by exact comparisons in the scalar.

use crate::merge::same_plane;
use crate::{Features, Scalar, StandardTriangle, Triangle, Vec3};
use core::cmp::Ordering;

/// Whether, across an edge shared by triangles `a` and `b` (whose vertex off the edge is `apex`),
/// the surface continues flat or folds towards the front of both. `a` is the later of the two in
/// input order: the valley test runs in its frame. `apex` is a vertex of a validated triangle,
/// within `±LIMIT`.
pub(crate) fn hides<S: Scalar>(
    ta: &StandardTriangle<S>,
    tb: &StandardTriangle<S>,
    apex: Vec3<S>,
) -> bool {
    let one_sided = !ta.is_two_sided() && !tb.is_two_sided();
    // `apex` lies in range (it was validated): its height needs no check.
    let valley = || ta.height_of(apex) > S::ZERO;
    same_plane(ta.normal(), tb.normal()) || (one_sided && valley())
}

/// Switches off `edge` of `tri`; a vertex stays active while either of its edges through it is.
pub(crate) fn deactivate<S: Scalar>(tri: &mut StandardTriangle<S>, edge: usize) {
    let off = if edge < 3 { 1 << edge } else { 0 };
    tri.features = Features::of_edges(tri.features().bits() & !off);
}

/// Bits of a record holding `triangle * 3 + edge`: room for 2^28 triangles.
const SLOT_BITS: u32 = 30;
/// Bits of an edge's hash in a record: with the direction, the sort's key is three bytes.
const HASH_BITS: u32 = 23;

/// Applies [`hides`] to every pair of triangles sharing an edge with opposite winding, as
/// [`Scene`](crate::Scene) does pair by pair, in `O(N + P)`: one record per edge, radix-sorted.
///
/// `triangles[c]` is the prepared form of `sources[order[c]]`, in any order of the slots `c`;
/// both slices hold the mesh's slots and no more (`triangles.len() == order.len() <= 2^28`);
/// `records` holds at least `6 * triangles.len()` words (records and the radix sort's other
/// buffer: with fewer, nothing is linked).
/// A record is a 23-bit hash of the edge's unordered vertex pair, one bit for its direction and
/// the edge's slot; records with equal hashes are adjacent once sorted, and only the pairs of
/// opposite direction within such a run are compared, exactly. P counts those pairs: one per
/// shared edge in a manifold mesh; `k * m` where `k` triangles run one way along an edge and `m`
/// the other (identical copies of a triangle add none). A run of two (a manifold edge) is not
/// compared at once: its later slot notes the earlier one, and the comparisons are made in slot
/// order, so the prepared triangles are read in order, as the cache likes.
///
/// Then marks each triangle's open edges in the top bits of its `order` entry (see
/// [`open_edges`]): those still active that share their vertex pair with no opposite edge
/// (other than that of the triangle's exact reverse), such as an edge along a T-junction or
/// the mesh's border.
pub(crate) fn link_all<S: Scalar>(
    sources: &[Triangle<S>],
    order: &mut [u32],
    triangles: &mut [StandardTriangle<S>],
    records: &mut [u64],
) {
    let n = triangles.len().min(order.len());
    let (records, temp) = records.split_at_mut(records.len().min(3 * n));
    let mut used = 0;
    for (slots, i) in records.chunks_exact_mut(3).zip(order.iter()).take(n) {
        let Some(v) = sources.get(*i as usize).map(Triangle::vertices) else {
            return;
        };
        let h = v.map(hash);
        for (e, slot) in slots.iter_mut().enumerate() {
            let (a, b) = (v[e], v[(e + 1) % 3]);
            let (ha, hb) = (h[e], h[(e + 1) % 3]);
            // Any order of a pair's two vertices on which both its edges agree: by hash, and
            // on equal hashes (equal or colliding points) by x, then y, then z.
            // (Decided without a branch on the hashes' random order: one the predictor misses
            // half the time.)
            let forward = if ha != hb {
                ha < hb
            } else {
                lexical(a, b) == Ordering::Less
            };
            let key = (ha ^ hb) >> (64 - HASH_BITS);
            *slot = key << (SLOT_BITS + 1) | (forward as u64) << SLOT_BITS | (used + e) as u64;
        }
        used += 3;
    }
    let records = &mut records[..used];
    // Records are made in slot order, so a stable sort on the hash and direction sorts them fully.
    let in_temp = crate::radix::sort::<SLOT_BITS, { SLOT_BITS + 1 + HASH_BITS }>(records, temp);
    let Some(temp) = temp.get_mut(..used) else {
        return;
    };
    // `earlier[s]`: one more than the slot of the edge a manifold edge `s` meets, or zero;
    // and the flag `PAIRED` once the edge is found to share its vertex pair with another. It
    // takes the buffer the sorted records are not in.
    let (records, earlier): (&[u64], &mut [u64]) = if in_temp {
        (temp, records)
    } else {
        (records, temp)
    };
    earlier.fill(0);
    let slot = |r: u64| (r & ((1 << SLOT_BITS) - 1)) as usize;
    let mut start = 0;
    while start < records.len() {
        let key = records[start] >> (SLOT_BITS + 1);
        let mut end = start + 1;
        while end < records.len() && records[end] >> (SLOT_BITS + 1) == key {
            end += 1;
        }
        let run = records.get(start..end).unwrap_or_default();
        let forward = |r: u64| (r >> SLOT_BITS) & 1 == 1;
        // Backward records (direction bit 0) sort before forward ones within a run.
        if let &[x, y] = run
            && !forward(x)
            && forward(y)
        {
            let (a, b) = (slot(x).min(slot(y)), slot(x).max(slot(y)));
            if let Some(e) = earlier.get_mut(b) {
                *e = a as u64 + 1;
            }
        } else {
            let split = run.partition_point(|&r| !forward(r));
            for &x in &run[..split] {
                for &y in &run[split..] {
                    if link(sources, order, triangles, slot(x), slot(y)) {
                        paired(earlier, slot(x));
                        paired(earlier, slot(y));
                    }
                }
            }
        }
        start = end;
    }
    for b in 0..used {
        let a = earlier.get(b).map_or(0, |&a| (a & !PAIRED) as usize);
        if a != 0 && link(sources, order, triangles, a - 1, b) {
            paired(earlier, a - 1);
            paired(earlier, b);
        }
    }
    let marks = earlier.chunks_exact(3).zip(triangles.iter());
    for (o, (flags, t)) in order.iter_mut().zip(marks) {
        let mask = (0..3).fold(0, |m, e| {
            let lone = flags[e] & PAIRED == 0 && t.features().edge(e);
            m | (lone as u32) << e
        });
        *o |= mask << OPEN_SHIFT;
    }
}

/// Where [`link_all`] marks a triangle's open edges in its `order` entry: the three bits from
/// here up (input indices are below `2^28`).
const OPEN_SHIFT: u32 = 29;

/// An `order` entry marked by [`link_all`]: the input index and the open edges' mask.
pub(crate) fn open_edges(entry: u32) -> (u32, u8) {
    (entry & ((1 << OPEN_SHIFT) - 1), (entry >> OPEN_SHIFT) as u8)
}

/// The flag of an edge slot in `link_all`'s `earlier` that shares its vertex pair.
const PAIRED: u64 = 1 << 63;

/// Flags edge slot `s` as sharing its vertex pair with an opposite edge.
fn paired(earlier: &mut [u64], s: usize) {
    if let Some(e) = earlier.get_mut(s) {
        *e |= PAIRED;
    }
}

/// Compares the edges in slots `sx` and `sy` exactly and deactivates them where one hides the
/// other; returns whether they share their vertex pair (in opposite directions) as two
/// triangles that are not each other's reverse.
#[inline(always)]
fn link<S: Scalar>(
    sources: &[Triangle<S>],
    order: &[u32],
    triangles: &mut [StandardTriangle<S>],
    sx: usize,
    sy: usize,
) -> bool {
    // `a` is the later triangle in input order, as in `Scene::push`, whatever the slots' order.
    let input = |c: usize| order.get(c).copied().unwrap_or(0);
    let (x, y) = ((sx / 3, sx % 3), (sy / 3, sy % 3));
    let ((a, i), (b, j)) = if input(x.0) > input(y.0) {
        (x, y)
    } else {
        (y, x)
    };
    let source = |c: usize| order.get(c).and_then(|&k| sources.get(k as usize));
    let (Some(ta), Some(tb)) = (source(a), source(b)) else {
        return false;
    };
    // The vertices from `i` and `j` on, around each triangle: each read from the source
    // through a reference chosen without a branch (the edge varies at random from pair to
    // pair, and a mispredicted branch costs a modern core more than the loads), not from an
    // array copied out first (loads at a computed index from stores just made wait for them:
    // the comparisons took a sixth longer). `i`, `j` < 3 (remainders): no bounds checks.
    let around = |t: &Triangle<S>, k: usize| {
        let at = |k: usize| match k {
            0 => &t.v0,
            1 => &t.v1,
            _ => &t.v2,
        };
        [*at(k), *at([1, 2, 0][k]), *at([2, 0, 1][k])]
    };
    let (va, vb) = (around(ta, i), around(tb, j));
    if a == b || va[0] != vb[1] || va[1] != vb[0] {
        return false;
    }
    let (Some(pa), Some(pb)) = (triangles.get(a), triangles.get(b)) else {
        return false;
    };
    if hides(pa, pb, vb[2]) {
        deactivate(&mut triangles[a], i);
        deactivate(&mut triangles[b], j);
    }
    // A triangle's exact reverse (its back, as a two-sided floor is made) is no partner.
    va[2] != vb[2]
}

/// Orders points by x, then y, then z (validated, so never NaN).
fn lexical<S: Scalar>(a: Vec3<S>, b: Vec3<S>) -> Ordering {
    let c = |p: S, q: S| p.partial_cmp(&q).unwrap_or(Ordering::Equal);
    c(a.x, b.x).then(c(a.y, b.y)).then(c(a.z, b.z))
}

/// A hash of a point's exact value: equal points (`-0.0 == 0.0` included) hash equal.
fn hash<S: Scalar>(p: Vec3<S>) -> u64 {
    let bits = |s: S| (s.to_f64() + 0.0).to_bits();
    mix(bits(p.x) ^ bits(p.y).rotate_left(21) ^ bits(p.z).rotate_left(42))
}

/// SplitMix64's finaliser (Steele, Lea and Flood, 2014): a fixed, portable bit mixer.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}
