//! A ball that starts overlapping a triangle's edges or vertices, outside its face region: the
//! rule that decides between holding it at alpha 0 and letting it go.
//!
//! The distance from a point moving along a straight path to a point or to a line is a convex
//! function of alpha, so the ball is within `r` of each active edge (its interior) or vertex over
//! one interval of the path. A ball that starts within `r` of some of them is held at alpha 0
//! when it does not move away from the nearest (the distance to the triangle does not grow, as
//! for the face). Otherwise it is let go: the intervals that meet the one it starts in form the
//! stretch of path over which it is still overlapping, and no contact inside that stretch is
//! reported (it would be an overlap reported later along the path). The first contact after it,
//! if any, is a fresh one. For a lone triangle (every feature active, a convex set) the distance
//! to the triangle only grows once it has grown at the start, so a ball let go meets nothing.

use crate::contact::off_line;
use crate::{Scalar, StandardTriangle, Vec3};

/// The part of the path, as alpha from `from` to `to`, over which the ball is within `r` of a
/// feature, and whether it is there at the start (closer than `r`).
#[derive(Clone, Copy)]
struct Span<S> {
    from: S,
    to: S,
    start: bool,
}

impl<S: Scalar> StandardTriangle<S> {
    /// For a sweep whose centre starts within `r` of the plane (`p0`, `d` in the standard frame,
    /// from the front) and whose earliest edge or vertex contact is at alpha `first`: the alpha
    /// from which contacts count, if that contact is not one (the rule above).
    #[cold]
    #[inline(never)]
    pub(crate) fn clear_after(&self, p0: Vec3<S>, d: Vec3<S>, r: S, first: S) -> Option<S> {
        if self.held(p0, d, r) {
            return None;
        }
        let end = self.clear_from(p0, d, r);
        (end > first).then_some(end)
    }

    /// Whether the ball starts clear of every active edge and vertex, or does not move away
    /// from the nearest of those it starts within `r` of (the first of equals, edges first).
    /// No square root of the path and no division: most calls end here.
    fn held(&self, p0: Vec3<S>, d: Vec3<S>, r: S) -> bool {
        let mut nearest: Option<(S, bool)> = None;
        // `q` the offset from the feature's nearest point, `m` the motion relative to it. The
        // sign's products are those of `chord`'s bound (|q| < r) times the path's length.
        let mut consider = |q: Vec3<S>, m: Vec3<S>| {
            if let Some(k) = S::chord(r, q).filter(|&k| k > S::ZERO)
                && nearest.is_none_or(|(n, _)| k > n)
            {
                nearest = Some((k, S::dot_sign(q, m).is_le()));
            }
        };
        for i in 0..3 {
            if self.features.edge(i) {
                let (e, rel) = (self.edge(i), p0 - self.corner(i));
                let u0 = S::dot_unit(rel, e.along());
                if u0 > S::ZERO && u0 < e.len {
                    let out = e.out();
                    let q = Vec3::new(S::dot_unit(rel, out), p0.y, S::ZERO);
                    consider(q, Vec3::new(S::dot_unit(d, out), d.y, S::ZERO));
                }
            }
        }
        for i in 0..3 {
            if self.features.vertex(i) {
                consider(p0 - self.corner(i), d);
            }
        }
        nearest.is_none_or(|(_, stays)| stays)
    }

    /// The alpha from which a ball that starts overlapping is clear of every active edge and
    /// vertex it overlaps: the end of the union of the spans that meet the one it starts in.
    fn clear_from(&self, p0: Vec3<S>, d: Vec3<S>, r: S) -> S {
        let mut spans = [None; 6];
        for i in 0..3 {
            if self.features.edge(i) {
                spans[i] = self.edge_span(i, p0, d, r);
            }
            if self.features.vertex(i) {
                spans[3 + i] = span(p0 - self.corner(i), d, r, (S::ZERO, S::ONE));
            }
        }
        let spans = spans.iter().flatten();
        let mut end = S::ZERO;
        for s in spans.clone().filter(|s| s.start) {
            end = if s.to > end { s.to } else { end };
        }
        // Spans that begin before the ball is clear keep it overlapping until they end.
        let mut grew = true;
        while grew {
            grew = false;
            for s in spans.clone() {
                if s.from < end && s.to > end {
                    end = s.to;
                    grew = true;
                }
            }
        }
        end
    }

    /// The [`Span`] of the interior of edge `i`: within `r` of its line while the centre is
    /// beside the edge (strictly between its ends, as for a contact).
    fn edge_span(&self, i: usize, p0: Vec3<S>, d: Vec3<S>, r: S) -> Option<Span<S>> {
        let e = self.edge(i);
        let rel = p0 - self.corner(i);
        let (along, out) = (e.along(), e.out());
        let (u0, du) = (S::dot_unit(rel, along), S::dot_unit(d, along));
        let (w0, dw) = (S::dot_unit(rel, out), S::dot_unit(d, out));
        let z = S::ZERO;
        // Beside the edge: 0 < u0 + alpha du < len.
        let beside = if du > z {
            (fraction(-u0, du), fraction(e.len - u0, du))
        } else if du < z {
            (fraction(u0 - e.len, -du), fraction(u0, -du))
        } else if u0 > z && u0 < e.len {
            (z, S::ONE)
        } else {
            return None;
        };
        let mut s = span(Vec3::new(w0, p0.y, z), Vec3::new(dw, d.y, z), r, beside)?;
        s.start &= u0 > z && u0 < e.len;
        Some(s)
    }
}

/// The [`Span`] of a feature at offset `q` from the start of a path `d`, within the alphas
/// `bounds` where the feature counts: the alphas at which `|q + alpha d| < r`, the distance
/// being convex in alpha. `None` where the two do not meet.
fn span<S: Scalar>(q: Vec3<S>, d: Vec3<S>, r: S, (lo, hi): (S, S)) -> Option<Span<S>> {
    let start = S::chord(r, q).is_some_and(|k| k > S::ZERO);
    let (from, to) = match S::direction(d) {
        // No motion relative to the feature: the distance never changes.
        None if start => (S::ZERO, S::ONE),
        None => return None,
        Some((len, dir)) => {
            let s = S::dot_unit(q, dir);
            let k = S::chord(r, off_line(q, dir))?;
            (fraction(-s - k, len), fraction(-s + k, len))
        }
    };
    let from = if lo > from { lo } else { from };
    let to = if hi < to { hi } else { to };
    (from < to).then_some(Span { from, to, start })
}

/// `n / d` clamped to `[0, 1]`, for `d > 0`, dividing only where the quotient is inside (so a
/// fixed-point quotient never saturates).
fn fraction<S: Scalar>(n: S, d: S) -> S {
    if n <= S::ZERO {
        S::ZERO
    } else if n >= d {
        S::ONE
    } else {
        n.div(d)
    }
}
