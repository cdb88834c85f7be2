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
//! way; the edge is covered when those intervals, joined, span it from end to end.

use crate::merge::same_plane;
use crate::scalar::largest;
use crate::{Scalar, StandardTriangle, Triangle, Vec3};

/// Whether edge `i` of `t` is covered by opposite, collinear edges of flat neighbours among
/// `others` (prepared triangles with their sources). `others` may include `t` itself, which
/// never covers its own edges.
pub(crate) fn covered<'a, S: Scalar + 'a>(
    t: &StandardTriangle<S>,
    i: usize,
    others: impl Iterator<Item = (&'a StandardTriangle<S>, &'a Triangle<S>)> + Clone,
) -> bool {
    let len = t.edges[i].len;
    let tol = tolerance(t, i);
    // Each usable neighbour edge as an interval [lo, hi] of the edge's own coordinate u.
    let intervals = others.flat_map(move |(o, src)| {
        let v = src.vertices();
        (0..3).filter_map(move |j| interval(t, i, o, (v[j], v[(j + 1) % 3])))
    });
    // Extend the covered stretch [0, reach] from the edge's start until no interval extends it.
    let mut reach = S::ZERO;
    loop {
        if reach >= len - tol {
            return true;
        }
        let next = intervals
            .clone()
            .filter(|(lo, hi)| *lo <= reach + tol && *hi > reach)
            .map(|(_, hi)| hi)
            .reduce(|a, b| if b > a { b } else { a });
        match next {
            Some(hi) => reach = hi,
            None => return false,
        }
    }
}

/// The stretch `[lo, hi]` of edge `i` of `t` (as distances from its start) that the edge
/// `(a, b)` of the flat neighbour `o` runs along in the opposite direction, if it does.
pub(crate) fn interval<S: Scalar>(
    t: &StandardTriangle<S>,
    i: usize,
    o: &StandardTriangle<S>,
    (a, b): (Vec3<S>, Vec3<S>),
) -> Option<(S, S)> {
    if o == t || !same_plane(o.normal(), t.normal()) {
        return None;
    }
    let (corner, edge, tol) = (t.corner(i), t.edges[i], tolerance(t, i));
    let (a, b) = (t.standard_point(a), t.standard_point(b));
    let on_line = |p: Vec3<S>| p.y.abs() <= tol && S::dot_unit(p - corner, edge.out()).abs() <= tol;
    let along = |p: Vec3<S>| S::dot_unit(p - corner, edge.along());
    let (ua, ub) = (along(a), along(b));
    (on_line(a) && on_line(b) && ub < ua).then_some((ub, ua))
}

/// Four times the rounding of a height at the edge's coordinates: how far off the line a
/// neighbour's vertex may lie and still count as on it.
fn tolerance<S: Scalar>(t: &StandardTriangle<S>, i: usize) -> S {
    let o = t.origin();
    let extent = largest(o.x.abs(), o.y.abs(), o.z.abs());
    let len = t.edges[i].len;
    let e = S::height_error(if extent > len { extent } else { len });
    e + e + e + e
}
