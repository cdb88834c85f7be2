//! Seams: where two triangles of a mesh meet along an inactive edge, rounding in their two
//! standard frames must not open a gap a ball could fall through. The face test therefore
//! treats each inactive edge as lying a small margin further out, so neighbouring faces overlap
//! slightly along their seam (a scene merges the two contacts); active edges keep the exact test.
//! And where a centre already below height `r` crosses a seam into the face, it meets the face
//! there ([`seam_entry`](StandardTriangle::seam_entry)): the two frames' heights differ by
//! their rounding, which a path nearly along the plane stretches far beyond any margin.

use crate::scalar::{largest, tie};
use crate::{Scalar, StandardTriangle, Vec3};
use core::cmp::Ordering;

impl<S: Scalar> StandardTriangle<S> {
    /// Whether `q'` lies inside the triangle once each inactive edge is moved out by
    /// `r / 64 + 4 EPSILON`. An inactive edge is a seam with a coplanar or hiding neighbour;
    /// rounding in two frames must not open a gap along it, so the faces overlap slightly there
    /// (the scene merges the two contacts). Active edges keep the exact test.
    #[inline]
    pub(crate) fn within_seams(&self, xq: S, zq: S, r: S) -> bool {
        self.features.bits() & 0b111 != 0b111 && self.widened_contains(xq, zq, r)
    }

    /// [`within_seams`](Self::within_seams) for a triangle with an inactive edge.
    fn widened_contains(&self, xq: S, zq: S, r: S) -> bool {
        let margin = seam_margin(r);
        // Where both edges at a sharp corner are seams, their moved lines meet far beyond it:
        // the triangle's box grown by the margin bounds the widening.
        let q = Vec3::new(xq, S::ZERO, zq);
        self.within_box(q, margin)
            && (0..3).all(|i| {
                let (w, limit) = self.seam_line(q, i, margin);
                w <= limit
            })
    }

    /// How far `q` lies outside edge `i`'s line in the x–z plane, and how far it may: `margin`
    /// where the edge is a seam (inactive), zero where it is active.
    fn seam_line(&self, q: Vec3<S>, i: usize, margin: S) -> (S, S) {
        let limit = if self.features.edge(i) {
            S::ZERO
        } else {
            margin
        };
        (self.edge(i).out_of(q - self.corner(i)), limit)
    }

    /// For a ray (`r` zero, which meets no edge or vertex) moving by `d` in the frame: whether
    /// `(xq, zq)` lies inside the triangle with every edge moved out by the rounding of the
    /// point where it crosses the plane: twice a height's rounding at `m` (the magnitude of the
    /// sweep's and the triangle's coordinates in the frame), times the ray's run along the plane
    /// over its drop across it (a slanted ray's crossing moves that much further for an error
    /// in height), up to 16 (a ray within 3.6° of the plane may still pass a seam's rounding).
    /// Each frame rounds the crossing on its own, and a ray through an edge or vertex shared by
    /// neighbours could be put outside all of them: it passed through a closed mesh (one shot
    /// in 20 aimed at its vertices or edges, in every scalar). A ray within rounding of an edge
    /// meets the face there.
    pub(crate) fn within_rounding(&self, xq: S, zq: S, m: S, d: Vec3<S>) -> bool {
        let h = S::height_error(m);
        let (run, drop) = (largest(d.x.abs(), d.z.abs(), S::ZERO), d.y.abs());
        let most = S::from_int(16);
        let slant = if run <= drop {
            S::ONE
        } else if run >= drop.mul(most) {
            most
        } else {
            S::div(run, drop)
        };
        let margin = (h + h).mul(slant);
        let q = Vec3::new(xq, S::ZERO, zq);
        self.within_box(q, margin)
            && (0..3).all(|i| self.edge(i).out_of(q - self.corner(i)) <= margin)
    }

    /// Whether `q` lies in the triangle's box in the x–z plane grown by `grow`.
    pub(crate) fn within_box(&self, q: Vec3<S>, grow: S) -> bool {
        let ((lo, hi), z1) = (self.x_extent(), self.shape().1);
        lo - grow <= q.x && q.x <= hi + grow && -grow <= q.z && q.z <= z1 + grow
    }

    /// Where a centre already below height `r` (in front) comes over the face widened at its
    /// seams, entering across a seam at alpha `from` or later: the alpha and its unrounded
    /// fraction. Two neighbours' frames round the plane's height differently (a few steps of
    /// the coordinates' magnitude), and a path that runs nearly along the plane carries that
    /// difference far along it: one frame may see the centre reach height `r` beyond the seam,
    /// the other see it below `r` already, over the first. This frame then meets it as it
    /// crosses the seam, as an exact plane would have met it at the neighbour's face. Across an
    /// active edge the edge test meets it first.
    pub(crate) fn seam_entry(&self, p0: Vec3<S>, d: Vec3<S>, r: S, from: S) -> Option<(S, (S, S))> {
        if self.features.bits() & 0b111 == 0b111 {
            return None;
        }
        let margin = seam_margin(r);
        let beyond = |p: Vec3<S>, i: usize| {
            let (w, limit) = self.seam_line(p, i, margin);
            w - limit
        };
        // The latest crossing into an edge's half-plane, as `(edge, w0, w0 - w1)`.
        let mut entry: Option<(usize, S, S)> = None;
        for i in 0..3 {
            let w0 = beyond(p0, i);
            if w0 <= S::ZERO {
                continue;
            }
            let w1 = beyond(p0 + d, i);
            if w1 >= S::ZERO {
                return None;
            }
            let later =
                entry.is_none_or(|(_, n, m)| S::mul_cmp(w0, m, n, w0 - w1) == Ordering::Greater);
            if later {
                entry = Some((i, w0, w0 - w1));
            }
        }
        let (e, num, den) = entry?;
        // Only an entry within the frames' rounding below height `r` can be one the
        // neighbour's frame missed: the two heights differ by a rounding of a height each, at
        // the frames' coordinates (eight allowed). A deeper one is a real overlap (a ball let go
        // from a valley's other slope) or follows a contact the neighbour met (on a path coming
        // down steeply, the common case), and is left to the rules for those.
        let (x1, z1, x2) = self.shape();
        let m = largest(largest(x1.abs(), z1, x2), p0.x.abs(), p0.z.abs());
        let h = S::height_error(m);
        let h4 = h + h + h + h;
        let depth = p0.y - r + h4 + h4;
        if self.features.edge(e) || S::mul_cmp(depth, den, num, -d.y) == Ordering::Less {
            return None;
        }
        let alpha = S::div(num, den);
        if alpha < from {
            return None;
        }
        let q = p0 + S::scale_fraction(d, num, den, alpha);
        // `q` lies on the entry's moved line only up to rounding, and edge 2's is a side of the
        // box that bounds the widening at sharp corners: that box, grown by a margin more.
        let boxed = self.within_box(q, margin + margin);
        let inside = (0..3).all(|i| i == e || beyond(Vec3::new(q.x, S::ZERO, q.z), i) <= S::ZERO);
        (boxed && inside).then_some((alpha, (num, den)))
    }
}

/// How far a face is widened along an inactive edge (and beyond its box) for a ball of
/// radius `r`: `r / 64 + 4 EPSILON`.
pub(crate) fn seam_margin<S: Scalar>(r: S) -> S {
    S::div_pow2(r, 6) + tie::<S>()
}
