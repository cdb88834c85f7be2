//! Edge and vertex contacts: the first moment the ball's centre comes within `r` of an active
//! edge or vertex, solved by closest approach (see the [module docs](super)).

use super::Touch;
use crate::reject::Cut;
use crate::scalar::{largest, tie};
use crate::{Contact, Scalar, StandardTriangle, Vec3};

/// An edge or vertex contact with its alpha still as a fraction `t / len` (see `first_touch`):
/// two contacts whose rounded alphas tie are still ordered exactly by it.
type Timed<S> = ((S, Option<Vec3<S>>, Contact), (S, S));

impl<S: Scalar> StandardTriangle<S> {
    /// The earliest contact with an active edge or vertex: the part of
    /// [`cast_front`](Self::cast_front) that most sweeps never reach, kept out of line so that
    /// the face path does not pay for its registers.
    #[inline(never)]
    pub(super) fn edges_and_vertices(
        &self,
        p0: Vec3<S>,
        d: Vec3<S>,
        r: S,
        cut: Cut<S>,
    ) -> Option<Touch<S>> {
        let mut from = S::ZERO;
        // A second pass only for a ball let go from a starting overlap: from where it is clear.
        for _ in 0..2 {
            let best = self.earliest(p0, d, r, from, cut)?;
            // Only a centre within r of the plane can start overlapping an edge or vertex.
            match (from == S::ZERO && p0.y < r).then(|| self.clear_after(p0, d, r, &best)) {
                Some(Some(end)) => from = end,
                _ => return Some(best),
            }
        }
        None
    }

    /// The earliest contact with an active edge or vertex at alpha `from` or later, passing
    /// over those met after the `cut`.
    #[inline(always)]
    fn earliest(&self, p0: Vec3<S>, d: Vec3<S>, r: S, from: S, cut: Cut<S>) -> Option<Touch<S>> {
        let after = |c: &Timed<S>| c.0.0 >= from;
        let mut best: Option<Timed<S>> = None;
        // Each edge's rounded alpha, for the vertices at its ends.
        let mut edges: [Option<S>; 3] = [None; 3];
        for (i, at) in edges.iter_mut().enumerate() {
            if self.features.edge(i) {
                let e = self.edge_contact(i, p0, d, r, cut).filter(after);
                *at = e.map(|e| e.0.0);
                best = earlier(best, e);
            }
        }
        // The path's length and direction, computed once and only if a vertex needs them.
        let mut motion = None;
        // Where an edge's contact lies next to its vertex, the two arrive together; the edge's
        // normal is the right one, so a vertex must be earlier than each edge through it by
        // more than rounding. Against any other contact (another vertex, the opposite edge) the
        // exact order decides: there a margin would keep a contact later than the vertex's.
        let tie = tie::<S>();
        for i in 0..3 {
            if !self.features.vertex(i)
                || self.vertex_out_of_reach(i, p0, d, r)
                || self.vertex_line_misses(i, p0, d, r)
                || cut.short_of(p0 - self.corner(i), d, r)
            {
                continue;
            }
            let v = match *motion.get_or_insert_with(|| S::direction(d)) {
                Some(m) => self.vertex_contact(i, p0, d, m, r),
                // No motion: only an overlap at the start.
                None => {
                    let q = p0 - self.corner(i);
                    let at = (S::ZERO, Some(q), Contact::Vertex(i as u8));
                    resting(q, r).then_some((at, (S::ZERO, S::ONE)))
                }
            };
            // The edges through vertex `i`: edge `i` (from it) and the one before (to it).
            let shadowed = |v: &Timed<S>| {
                [i, (i + 2) % 3]
                    .iter()
                    .any(|&e| edges[e].is_some_and(|a| v.0.0 >= a - tie))
            };
            let v = v.filter(|v| after(v) && !shadowed(v));
            best = earlier(best, v);
        }
        best.map(|((alpha, offset, contact), key)| (alpha, offset, contact, key))
    }

    /// The triangle's extent along the standard frame's x axis.
    pub(crate) fn x_extent(&self) -> (S, S) {
        let (x1, _, x2) = self.shape();
        if x1 < S::ZERO {
            (x1, x2)
        } else {
            (S::ZERO, if x1 > x2 { x1 } else { x2 })
        }
    }

    /// Vertex `i` in the standard frame.
    pub(crate) fn corner(&self, i: usize) -> Vec3<S> {
        let (x1, z1, x2) = self.shape();
        let z = S::ZERO;
        match i {
            0 => Vec3::new(z, z, z),
            1 => Vec3::new(x1, z, z1),
            _ => Vec3::new(x2, z, z),
        }
    }

    /// First contact with the interior of edge `i`, from vertex `i` to vertex `i + 1`, if
    /// before the `cut`.
    fn edge_contact(
        &self,
        i: usize,
        p0: Vec3<S>,
        d: Vec3<S>,
        r: S,
        cut: Cut<S>,
    ) -> Option<Timed<S>> {
        let e = &self.edge(i);
        let rel = p0 - self.corner(i);
        // Along the edge (u) and away from the triangle in its plane (w).
        let out = e.out();
        let (u0, du) = (e.along_of(rel), e.along_of(d));
        let (w0, dw) = (e.out_of(rel), e.out_of(d));
        let (u1, w1) = (u0 + du, w0 + dw);
        let beside = (u0 > S::ZERO || u1 > S::ZERO) && (u0 < e.len || u1 < e.len);
        let within = (w0 <= r || w1 <= r) && (w0 >= -r || w1 >= -r);
        if !(beside && within) {
            return None;
        }
        // Across the edge, the line of motion passes too far from it: no square root needed.
        let reach = largest(w0.abs(), p0.y.abs(), S::ZERO);
        if S::line_misses([w0, p0.y], [dw, d.y], r, reach) {
            return None;
        }
        // Across the edge the problem is planar: the centre moves from (w0, y0) along (dw, dy).
        let z = S::ZERO;
        let across = Vec3::new(dw, d.y, z);
        if cut.short_of(Vec3::new(w0, p0.y, z), across, r) {
            return None;
        }
        let Some(motion) = S::direction(across) else {
            // No motion across the edge (none at all, or along it): only an overlap at the start.
            if !(u0 > z && u0 < e.len && resting(Vec3::new(w0, p0.y, z), r)) {
                return None;
            }
            let offset = Vec3::new(S::mul_unit(w0, out.x), p0.y, S::mul_unit(w0, out.z));
            return Some(((z, Some(offset), Contact::Edge(i as u8)), (z, S::ONE)));
        };
        let (beta, key) = first_touch_across((w0, p0.y), motion, r)?;
        let (u, w, y) = (u0 + beta.mul(du), w0 + beta.mul(dw), p0.y + beta.mul(d.y));
        // One-sided, the centre must be in front at contact; two-sided, either side will do.
        if !(u > z && u < e.len && (y >= z || self.two_sided)) {
            return None;
        }
        let offset = Vec3::new(S::mul_unit(w, out.x), y, S::mul_unit(w, out.z));
        Some(((beta, Some(offset), Contact::Edge(i as u8)), key))
    }

    /// First contact with vertex `i`; `motion` is the path's length and unit direction.
    fn vertex_contact(
        &self,
        i: usize,
        p0: Vec3<S>,
        d: Vec3<S>,
        motion: (S, Vec3<S::Unit>),
        r: S,
    ) -> Option<Timed<S>> {
        let v = self.corner(i);
        let (beta, key) = first_touch(p0 - v, motion, r)?;
        let offset = p0 - v + d.scale(beta);
        let side = offset.y >= S::ZERO || self.two_sided;
        side.then_some(((beta, Some(offset), Contact::Vertex(i as u8)), key))
    }
}

/// The fraction of a path at which a point starting at offset `q0` from a feature, moving a
/// distance `len` along the unit direction `dir`, first comes within `r` of it; zero if it
/// starts within `r` and approaches, `None` if it never does, moves away, or arrives too late.
/// Also returns the fraction unrounded, as `(t, len)`.
fn first_touch<S: Scalar>(
    q0: Vec3<S>,
    (len, dir): (S, Vec3<S::Unit>),
    r: S,
) -> Option<(S, (S, S))> {
    touch(S::dot_unit(q0, dir), || S::chord(r, off_line(q0, dir)), len)
}

/// [`first_touch`] for an edge, in the plane across it: the offset `(w0, y0, 0)` from the
/// edge's line and a direction whose z is zero. The same numbers with the zero terms left out
/// (a float's sum less a zero may differ in the sign of a zero, which no result keeps).
fn first_touch_across<S: Scalar>(
    (w0, y0): (S, S),
    (len, dir): (S, Vec3<S::Unit>),
    r: S,
) -> Option<(S, (S, S))> {
    // The in-plane dot and cross products as x–z dot products: (w0, y0)·(x, y) and the cross
    // product's only nonzero component, w0 y − y0 x.
    let s = S::dot_unit_xz(Vec3::new(w0, S::ZERO, y0), [dir.x, dir.y]);
    let off = || S::dot_unit_xz(Vec3::new(w0, S::ZERO, -y0), [dir.y, dir.x]);
    touch(s, || S::chord(r, Vec3::new(S::ZERO, S::ZERO, off())), len)
}

/// [`first_touch`] from `s`, the start's offset along the direction, and the half-chord the
/// line of motion cuts from the ball about the feature (`None`: it passes farther than `r`).
#[inline(always)]
fn touch<S: Scalar>(s: S, chord: impl FnOnce() -> Option<S>, len: S) -> Option<(S, (S, S))> {
    // Moving away from the feature; moving square to it counts, for a ball already within r.
    if s > S::ZERO {
        return None;
    }
    let t = -s - chord()?;
    // At or before the start: alpha `+0`. (A ball exactly `r` from the feature moving square to
    // it has `s = +0` and a chord of zero: `-s - 0` is a float's `-0`, which `t / len` kept.)
    if t <= S::ZERO {
        return Some((S::ZERO, (S::ZERO, len)));
    }
    if t >= len {
        return None;
    }
    // Rounded to nearest, a fraction just below one can become one: that is no contact.
    let beta = S::div(t, len);
    (beta < S::ONE).then_some((beta, (t, len)))
}

/// `q0 × dir`: the offset of a feature from a line through `q0` along the unit `dir`, whose
/// length is their distance; each component a two-term dot product (rounded once in fixed
/// point; a float rounds each product and their sum).
pub(crate) fn off_line<S: Scalar>(q0: Vec3<S>, dir: Vec3<S::Unit>) -> Vec3<S> {
    // Each `a u - b v` as the x–z dot product of (a, _, -b) with (u, v).
    let two =
        |a: S, b: S, u: S::Unit, v: S::Unit| S::dot_unit_xz(Vec3::new(a, S::ZERO, -b), [u, v]);
    Vec3::new(
        two(q0.y, q0.z, dir.z, dir.y),
        two(q0.z, q0.x, dir.x, dir.z),
        two(q0.x, q0.y, dir.y, dir.x),
    )
}

/// Whether a ball that does not move relative to a feature (offset `q` from it, the centre in
/// front of the plane) overlaps it: closer than `r`. Rare, so kept out of the hot path.
#[cold]
#[inline(never)]
fn resting<S: Scalar>(q: Vec3<S>, r: S) -> bool {
    q.y >= S::ZERO && S::chord(r, q).is_some_and(|k| k > S::ZERO)
}

/// The earlier of two contacts, by their exact fractions `t / len` (the first on a tie).
fn earlier<S: Scalar>(a: Option<Timed<S>>, b: Option<Timed<S>>) -> Option<Timed<S>> {
    match (a, b) {
        (Some(x), Some(y)) => {
            let ((tx, lx), (ty, ly)) = (x.1, y.1);
            Some(if S::mul_cmp(ty, lx, tx, ly).is_lt() {
                y
            } else {
                x
            })
        }
        (x, y) => x.or(y),
    }
}
