//! Seams: where two triangles of a mesh meet along an inactive edge, rounding in their two
//! standard frames must not open a gap a ball could fall through. The face test therefore
//! treats each inactive edge as lying a small margin further out, so neighbouring faces overlap
//! slightly along their seam (a scene merges the two contacts); active edges keep the exact test.

use crate::scalar::tie;
use crate::{Scalar, StandardTriangle, Vec3};

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
        let ((lo, hi), z1) = (self.x_extent(), self.shape().1);
        let boxed = lo - margin <= xq && xq <= hi + margin && -margin <= zq && zq <= z1 + margin;
        let q = Vec3::new(xq, S::ZERO, zq);
        boxed
            && (0..3).all(|i| {
                let w = S::dot_unit(q - self.corner(i), self.edge(i).out());
                w <= if self.features.edge(i) {
                    S::ZERO
                } else {
                    margin
                }
            })
    }
}

/// How far a face is widened along an inactive edge (and beyond its box) for a ball of
/// radius `r`: `r / 64 + 4 EPSILON`.
pub(crate) fn seam_margin<S: Scalar>(r: S) -> S {
    S::div_pow2(r, 6) + tie::<S>()
}
