//! Edges covered by flat neighbours that share no vertex pair with them: T-junctions.
//!
//! Where two triangles share an edge's two vertices, adjacency finds the pair directly. In a
//! floor whose triangles meet in a T-junction (a vertex of one lying inside another's edge),
//! an edge can lie entirely along the edges of coplanar neighbours on its other side without
//! sharing a vertex pair with any of them. Such an edge is inside the surface: it can never be
//! the first thing a ball touches, only a "ghost" bump from rounding, so it is switched off.
//!
//! The test runs in the edge's triangle's standard frame: a neighbour's edge counts when both
//! its ends lie on the edge's line (within the rounding of a height there) and it runs the other
//! way, its triangle lying on the edge's other side (its third vertex beyond the line by more
//! than a coordinate's rounding); the edge is covered when those intervals, joined, span it
//! from end to end (one at least, however short the edge). Lines closer together than twice
//! the tolerance cannot be told apart: a [`Heightfield`](crate::Heightfield) refuses cells that
//! small ([`least_cell`]), so the mesh of its triangles keeps the edges it keeps.

use crate::merge::same_plane;
use crate::{Scalar, StandardTriangle, Triangle, Vec3};

/// Whether edge `i` of `t` is covered by opposite, collinear edges of flat neighbours among
/// `others` (prepared triangles with their sources). `others` may include `t` itself, which
/// never covers its own edges.
pub(crate) fn covered<'a, S: Scalar + 'a>(
    t: &StandardTriangle<S>,
    i: usize,
    others: impl Iterator<Item = (&'a StandardTriangle<S>, &'a Triangle<S>)> + Clone,
) -> bool {
    spans(
        t,
        i,
        others.flat_map(move |(o, src)| intervals(t, i, o, src)),
    )
}

/// The stretches of edge `i` of `t` that the edges of the flat neighbour `o` (with its
/// source `src`) run along in the opposite direction.
fn intervals<'a, S: Scalar>(
    t: &'a StandardTriangle<S>,
    i: usize,
    o: &'a StandardTriangle<S>,
    src: &Triangle<S>,
) -> impl Iterator<Item = (S, S)> + Clone + 'a {
    let v = src.vertices();
    // Only a flat neighbour has any (`interval` asks again, for its other callers).
    let flat = !same_triangle(o, t) && same_plane(o.normal(), t.normal());
    let edges = if flat { 0..3 } else { 0..0 };
    edges.filter_map(move |j| interval(t, i, o, v, j))
}

/// Whether the stretches `[lo, hi]` (distances along edge `i` of `t`), joined, span the edge
/// from end to end (within the tolerance).
fn spans<S: Scalar>(
    t: &StandardTriangle<S>,
    i: usize,
    intervals: impl Iterator<Item = (S, S)> + Clone,
) -> bool {
    let (len, tol) = (t.edge(i).len, tolerance(t, i));
    // Extend the covered stretch [0, reach] from the edge's start until no interval extends it.
    // It takes one interval at least: an edge shorter than the tolerance allows at its ends
    // (coordinates near the scalar's resolution) is not spanned by nothing.
    let (mut reach, mut any) = (S::ZERO, false);
    loop {
        if any && reach >= len - tol {
            return true;
        }
        let next = intervals
            .clone()
            .filter(|(lo, hi)| *lo <= reach + tol && *hi > reach)
            .map(|(_, hi)| hi)
            .reduce(|a, b| if b > a { b } else { a });
        match next {
            Some(hi) => (reach, any) = (hi, true),
            None => return false,
        }
    }
}

/// How many stretches [`cover_open`] gathers for one edge: an edge along more neighbours than
/// this stays active.
const STRETCHES: usize = 64;

/// How many triangles near one edge [`cover_open`] looks at: an edge with more stays active.
const NEIGHBOURS: usize = 256;

/// How many triangles near edges [`cover_open`] meets in all, per triangle of the mesh: beyond
/// that, the open edges not yet checked stay active. Only a mesh whose triangles' boxes overlap
/// wholesale (long thin triangles side by side, say), where any query meets most of the mesh,
/// gets there; the bound keeps its build's time in `O(N log N)` all the same.
const MEETINGS: usize = 256;

/// [`covered`] for the open edges of a mesh (those `open` gives for a slot: active, and
/// sharing no vertex pair with an opposite edge), switching each covered one off, taking the
/// triangles in the order of `slots`. `near(a, b, r, f)` calls `f` with the slots of every
/// triangle that may come within `r` of the segment from `a` to `b` (each slot `s` being
/// `triangles[s]`, prepared from `source(s)`), and maybe more; a neighbour whose edge runs along
/// one within the tolerance does. Only the triangles whose boxes meet the segment's, grown by
/// `r`, are looked at and counted towards an edge's limit, so below the overall budget (every
/// triangle `near` gives counts towards that, which bounds the time) the result does not
/// depend on how `near` finds them (the tree's leaf size); `slots` is the input order, so
/// edges are cut off by the budget in an order every tree shares. Returns whether any edge was
/// switched off.
pub(crate) fn cover_open<'a, S: Scalar + 'a>(
    triangles: &mut [StandardTriangle<S>],
    slots: impl Iterator<Item = usize>,
    source: impl Fn(usize) -> Option<&'a Triangle<S>>,
    open: impl Fn(usize) -> u8,
    near: impl Fn(Vec3<S>, Vec3<S>, S, &mut dyn FnMut(usize)),
) -> bool {
    let mut changed = false;
    let (budget, mut spent) = (MEETINGS * triangles.len() + 4096, 0);
    for s in slots {
        let mask = open(s);
        if mask == 0 {
            continue;
        }
        let Some(src) = source(s) else {
            continue;
        };
        for i in (0..3).filter(|i| mask & (1 << i) != 0) {
            if spent > budget {
                return changed;
            }
            let t = &triangles[s];
            let (a, b) = (src.vertices()[i], src.vertices()[(i + 1) % 3]);
            let tol = tolerance(t, i);
            let mut found: heapless::Vec<(S, S), STRETCHES> = heapless::Vec::new();
            let (mut full, mut looked, mut met) = (false, 0, 0);
            near(a, b, tol + tol, &mut |o| {
                // Every triangle met counts towards the time budget, only those whose boxes
                // meet the edge's towards the edge's own limit.
                met += 1;
                let (Some(ot), Some(osrc)) = (triangles.get(o), source(o)) else {
                    return;
                };
                if full || !boxes_meet(osrc, (a, b), tol + tol) {
                    return;
                }
                looked += 1;
                full = looked > NEIGHBOURS;
                if !full {
                    for stretch in intervals(t, i, ot, osrc) {
                        full |= found.push(stretch).is_err();
                    }
                }
            });
            spent += met;
            if !full && spans(t, i, found.iter().copied()) {
                crate::adjacency::deactivate(&mut triangles[s], i);
                changed = true;
            }
        }
    }
    changed
}

/// Whether the box of `t` meets the box of the segment from `a` to `b` grown by `r`: the
/// neighbours [`cover_open`] counts, a set that does not depend on how they were found.
fn boxes_meet<S: Scalar>(t: &Triangle<S>, (a, b): (Vec3<S>, Vec3<S>), r: S) -> bool {
    let [v0, v1, v2] = t.vertices();
    let (lo, hi) = (v0.min(v1).min(v2), v0.max(v1).max(v2));
    let grow = Vec3::new(r, r, r);
    let (slo, shi) = (a.min(b) - grow, a.max(b) + grow);
    lo.x <= shi.x
        && lo.y <= shi.y
        && lo.z <= shi.z
        && hi.x >= slo.x
        && hi.y >= slo.y
        && hi.z >= slo.z
}

/// The stretch `[lo, hi]` of edge `i` of `t` (as distances from its start) that edge `j` of the
/// flat neighbour `o` (whose source's vertices are `v`) runs along in the opposite direction,
/// from the edge's other side, if it does.
pub(crate) fn interval<S: Scalar>(
    t: &StandardTriangle<S>,
    i: usize,
    o: &StandardTriangle<S>,
    v: [Vec3<S>; 3],
    j: usize,
) -> Option<(S, S)> {
    if same_triangle(o, t) || !same_plane(o.normal(), t.normal()) {
        return None;
    }
    let (corner, edge, tol) = (t.corner(i), t.edge(i), tolerance(t, i));
    let [a, b, apex] = [j, j + 1, j + 2].map(|k| t.standard_point(v[k % 3]));
    let out = |p: Vec3<S>| edge.out_of(p - corner);
    let on_line = |p: Vec3<S>| p.y.abs() <= tol && out(p).abs() <= tol;
    let along = |p: Vec3<S>| edge.along_of(p - corner);
    let (ua, ub) = (along(a), along(b));
    // A neighbour on the edge's own side (a strip of slivers along it) hides nothing; nor does
    // one whose apex lies on the line, as rounded (the other half of a grid's border cell,
    // where the cells are few steps of the scalar across): it must lie beyond by more than
    // a coordinate's rounding there. A sliver thinner than the tolerance still covers.
    let beyond = S::div_pow2(S::height_error(extent(t, i)), 2);
    (on_line(a) && on_line(b) && ub < ua && out(apex) > beyond).then_some((ub, ua))
}

/// Whether `o` is `t` or an identical copy, whatever edges either has switched off so far: a
/// triangle never covers its own edges, nor a copy of it (which would make the result depend
/// on which of the two is looked at first).
fn same_triangle<S: Scalar>(o: &StandardTriangle<S>, t: &StandardTriangle<S>) -> bool {
    let all = |x: &StandardTriangle<S>| x.with_features(crate::Features::ALL);
    all(o) == all(t)
}

/// The rounding of a height at the edge's coordinates (four steps of the scalar at the larger
/// of its triangle's origin and its length for floats, eight steps for fixed point): how far
/// off the line a neighbour's vertex may lie and still count as on it. A vertex placed on the
/// line strays from it by the rounding of its coordinates (about a step) and of the frame's
/// (a few steps at the edge's length); a wider tolerance would reach across the cells of a
/// grid only a few dozen steps across, and let a neighbour beyond a hole cover its edge.
fn tolerance<S: Scalar>(t: &StandardTriangle<S>, i: usize) -> S {
    S::height_error(extent(t, i))
}

/// The side a grid's cells must exceed at coordinates (and edge lengths) up to `extent` for
/// the test to tell their lines apart: twice the tolerance there. Closer lines, a cell's
/// neighbour across a hole, say, or the two ends of a cell's diagonal, would count as one.
pub(crate) fn least_cell<S: Scalar>(extent: S) -> S {
    let e = S::height_error(extent);
    e + e
}

/// The larger of the magnitude of the triangle's origin and edge `i`'s length.
fn extent<S: Scalar>(t: &StandardTriangle<S>, i: usize) -> S {
    let (o, len) = (t.origin().abs().max_element(), t.edge(i).len);
    if o > len { o } else { len }
}
