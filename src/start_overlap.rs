//! A ball that starts overlapping a triangle's edges or vertices, outside its face region: the
//! rule that decides between holding it at alpha 0 and letting it go.
//!
//! The distance from a point moving along a straight path to a point or to a line is a convex
//! function of alpha, so the ball is within `r` of each active edge (its interior) or vertex over
//! one span of the path; it is within `r` of the face region over another (the region is convex,
//! and the height below `r` an interval). A ball that starts within `r` of some edges or
//! vertices is held at alpha 0 when it does not move away from the nearest (the distance to the
//! triangle does not grow, as for the face). Otherwise it is let go: the spans that meet the
//! ones it starts in form the stretch of path over which it is still overlapping (including
//! features it reaches before it is clear of the others), and no contact inside that stretch is
//! reported (it would be an overlap reported later along the path). The first contact after it,
//! if any, is a fresh one. For a lone triangle (every feature active, a convex set) the distance
//! to the triangle only grows once it has grown at the start, so a ball let go meets nothing.

use crate::contact::{Touch, off_line};
use crate::seam::seam_margin;
use crate::{Contact, Scalar, StandardTriangle, Vec3};

/// The part of the path, as alpha from `from` to `to`, over which the ball is within `r` of a
/// feature, and whether it is there at the start (closer than `r`).
#[derive(Clone, Copy)]
struct Span<S> {
    from: S,
    to: S,
    start: bool,
}

/// An active edge or vertex as seen from the path: `q`, the offset of the centre's start from
/// the feature (for an edge, across it: out of the triangle and up), and `m`, the path relative
/// to it; for an edge also the centre's position along it, `u0 + alpha du` against its length.
struct Feature<S> {
    q: Vec3<S>,
    m: Vec3<S>,
    along: Option<(S, S, S)>,
}

impl<S: Scalar> Feature<S> {
    /// Whether the start is beside the feature (an edge counts strictly between its ends).
    fn beside(&self) -> bool {
        self.along
            .is_none_or(|(u0, _, len)| u0 > S::ZERO && u0 < len)
    }

    /// The alphas over which the centre is beside the feature: `0 <= u0 + alpha du <= len`.
    fn bounds(&self) -> (S, S) {
        let mut b = (S::ZERO, S::ONE);
        if let Some((u0, du, len)) = self.along {
            clip(&mut b, -u0, -du);
            clip(&mut b, u0 - len, du);
        }
        b
    }
}

impl<S: Scalar> StandardTriangle<S> {
    /// For a sweep whose centre starts within `r` of the plane (`p0`, `d` in the standard frame,
    /// from the front) and whose earliest edge or vertex contact is `first` (its alpha and
    /// feature): the alpha from which contacts count, if that contact is not one (the rule
    /// above).
    #[cold]
    #[inline(never)]
    pub(crate) fn clear_after(
        &self,
        p0: Vec3<S>,
        d: Vec3<S>,
        r: S,
        &(first, _, contact, _): &Touch<S>,
    ) -> Option<S> {
        // Held where the nearest feature it starts within r of, and does not move away from,
        // gave the contact: at alpha 0, or a little later where that feature's own test,
        // rounding the start's distance otherwise, put the start just short of `r` (a ball
        // grazing an edge, within a step of touching it: let go, it went on into the edge with
        // no contact). Any other first contact means that feature gave none (it moves away
        // from it, as that test rounds the motion): the ball is let go.
        match self.nearest_at_start(p0, d, r) {
            None => return None,
            Some((true, nearest)) if first == S::ZERO || nearest == contact => return None,
            Some(_) => {}
        }
        let end = self.clear_from(p0, d, r);
        (end > first).then_some(end)
    }

    /// Active feature `k`: edges 0 to 2, then vertices 0 to 2.
    #[inline(never)]
    fn feature(&self, k: usize, p0: Vec3<S>, d: Vec3<S>) -> Option<Feature<S>> {
        let i = k % 3;
        let rel = p0 - self.corner(i);
        if k >= 3 {
            return self.features.vertex(i).then_some(Feature {
                q: rel,
                m: d,
                along: None,
            });
        }
        if !self.features.edge(i) {
            return None;
        }
        let e = self.edge(i);
        let z = S::ZERO;
        Some(Feature {
            q: Vec3::new(e.out_of(rel), p0.y, z),
            m: Vec3::new(e.out_of(d), d.y, z),
            along: Some((e.along_of(rel), e.along_of(d), e.len)),
        })
    }

    /// `None` if the ball starts clear of every active edge and vertex, else whether it does not
    /// move away from the nearest of those it starts within `r` of (the first of equals, edges
    /// first), and which that is. No square root of the path and no division: most calls end here.
    fn nearest_at_start(&self, p0: Vec3<S>, d: Vec3<S>, r: S) -> Option<(bool, Contact)> {
        let mut nearest: Option<(S, bool, Contact)> = None;
        for (k, f) in (0..6).filter_map(|k| Some((k, self.feature(k, p0, d)?))) {
            // The sign's products are those of `chord`'s bound (|q| < r) times the path's length.
            if let Some(c) = S::chord(r, f.q).filter(|&c| c > S::ZERO)
                && f.beside()
                && nearest.is_none_or(|(n, ..)| c > n)
            {
                let at = (k % 3) as u8;
                let which = if k < 3 {
                    Contact::Edge(at)
                } else {
                    Contact::Vertex(at)
                };
                nearest = Some((c, S::dot_sign(f.q, f.m).is_le(), which));
            }
        }
        nearest.map(|(_, stays, which)| (stays, which))
    }

    /// The alpha from which a ball that starts overlapping is clear of the triangle: the end of
    /// the union of the spans (active edges and vertices, and the face region) that meet the
    /// ones it starts in.
    fn clear_from(&self, p0: Vec3<S>, d: Vec3<S>, r: S) -> S {
        let mut spans = [None; 7];
        for (k, s) in spans.iter_mut().take(6).enumerate() {
            *s = self.feature(k, p0, d).and_then(|f| {
                let mut s = span(f.q, f.m, r, f.bounds())?;
                s.start &= f.beside();
                Some(s)
            });
        }
        spans[6] = self.face_span(p0, d, r);
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

    /// The [`Span`] over which the centre is over the face region (widened along inactive edges
    /// as `cast` widens it) and below height `r`: within `r` of the face. A ball that starts
    /// there never reaches this stage, so the span only extends the overlapping stretch.
    fn face_span(&self, p0: Vec3<S>, d: Vec3<S>, r: S) -> Option<Span<S>> {
        let mut b = (S::ZERO, S::ONE);
        let mut clip = |w0: S, dw: S| clip(&mut b, w0, dw);
        let margin = seam_margin(r);
        for i in 0..3 {
            let e = self.edge(i);
            let seam = if self.features.edge(i) {
                S::ZERO
            } else {
                margin
            };
            clip(e.out_of(p0 - self.corner(i)) - seam, e.out_of(d));
        }
        // The triangle's box grown by the margin bounds the widening, as in `cast`.
        let ((lo, hi), z1) = (self.x_extent(), self.shape().1);
        clip(lo - margin - p0.x, -d.x);
        clip(p0.x - hi - margin, d.x);
        clip(-margin - p0.z, -d.z);
        clip(p0.z - z1 - margin, d.z);
        clip(p0.y - r, d.y);
        clip(-p0.y, -d.y);
        let (from, to) = b;
        (from < to).then_some(Span {
            from,
            to,
            start: false,
        })
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

/// Narrows the alphas `(from, to)` to those at which `w0 + alpha dw <= 0`.
fn clip<S: Scalar>((from, to): &mut (S, S), w0: S, dw: S) {
    if dw > S::ZERO {
        let t = fraction(-w0, dw);
        *to = if t < *to { t } else { *to };
    } else if dw < S::ZERO {
        let t = fraction(w0, -dw);
        *from = if t > *from { t } else { *from };
    } else if w0 > S::ZERO {
        *to = S::ZERO;
    }
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
