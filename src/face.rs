//! The face test of the HMC CS121 course notes: when does a moving ball first touch the front face of a triangle?
//!
//! [`standard_face`] follows the course notes' standardized face collision algorithm line by line, on a
//! triangle in standard orientation: v0 at the origin, v2 = (x2, 0, 0) on the positive x axis,
//! v1 = (x1, 0, z1) with z1 > 0, front face looking along +y.
//! [`StandardTriangle::face_collision`] is the whole algorithm: transform the sweep into the
//! triangle's precomputed frame, run the standardized test, report the world normal.

use crate::{Contact, Hit, Scalar, StandardSweep, StandardTriangle, Sweep, Vec3};
use core::cmp::Ordering;

/// The standardized face collision algorithm: the fraction `beta` of the path from `p0` to `p1`
/// at which the ball of radius `r` touches the front face, or `None` (the course notes' alpha = 1).
///
/// With `y0`, `y1` the heights of the start and end (see `face_point`, which computes `beta`
/// and `q'`, and `contains`, the half-plane tests):
/// - no hit if `y0 < r` (the ball starts in or below the face's plane) or `y0 == y1` (it moves
///   parallel to the plane), nor if `y1 > y0` (it moves away from the front);
/// - else `beta = (r - y0) / (y1 - y0)`, `q = p0 + beta (p1 - p0)`, `q' = (xq, 0, zq)`;
/// - a hit iff `0 <= beta < 1` and `q'` is inside the triangle or on its boundary: inside with
///   respect to each of the three edges (half-plane tests).
///
/// ```
/// use ballcast::{standard_face, StandardSweep, StandardTriangle, Triangle, Vec3};
/// let t = Triangle::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 4.0), Vec3::new(4.0, 0.0, 0.0));
/// let st = StandardTriangle::<f64>::new(&t)?;
/// // Falls from height 3 to -1 with radius 1 above (1, _, 1): touches after 2 of 4 units.
/// let s = StandardSweep::new(Vec3::new(1.0, 3.0, 1.0), Vec3::new(1.0, -1.0, 1.0), 1.0)?;
/// assert_eq!(standard_face(&st, &s), Some(0.5));
/// # Ok::<(), ballcast::Error>(())
/// ```
pub fn standard_face<S: Scalar>(tri: &StandardTriangle<S>, s: &StandardSweep<S>) -> Option<S> {
    let (beta, xq, zq) = face_point(s)?;
    (contains(tri, xq, zq) && beta >= S::ZERO && beta < S::ONE).then_some(beta)
}

/// The first half of the course notes' test: `beta` and `q' = (xq, 0, zq)`, if the ball reaches height
/// `r` within the path while moving towards the front.
pub(crate) fn face_point<S: Scalar>(s: &StandardSweep<S>) -> Option<(S, S, S)> {
    let (p0, p1, r) = (s.p0, s.p1, s.radius);
    let (y0, y1) = (p0.y, p1.y);

    if y0 < r || y0 == y1 {
        return None;
    }
    // beta < 1 exactly when y1 < r, which with y0 >= r also rules out moving away (y1 > y0).
    // Deciding it before dividing keeps a fixed-point quotient in [0, 1], never overflowing.
    if y1 >= r {
        return None;
    }
    // (r - y0) / (y1 - y0) with both signs turned, the same quotient (rounding depends only on
    // the exact one), so a ball starting at height r touches at +0, not at a float's −0 from
    // zero over a negative drop (alpha is reported in [0, 1), its bits hashed by lockstep peers).
    let beta = S::div(y0 - r, y0 - y1);
    let xq = p0.x + beta.mul(p1.x - p0.x);
    let zq = p0.z + beta.mul(p1.z - p0.z);
    Some((beta, xq, zq))
}

/// Whether `q' = (xq, 0, zq)` is inside the standardized triangle or on its boundary: in with
/// respect to all three edges, each a half-plane test on the triangle's side of the edge's line.
pub(crate) fn contains<S: Scalar>(tri: &StandardTriangle<S>, xq: S, zq: S) -> bool {
    let (x1, z1, x2) = tri.shape();
    let in_v0_v2 = zq >= S::ZERO;
    let in_v0_v1 = || S::mul_cmp(z1, xq, x1, zq) != Ordering::Less;
    let in_v1_v2 = || S::mul_cmp(x1 - x2, zq, z1, xq - x2) != Ordering::Less;
    // In that order, each only if the ones before hold: outside v0-v2 costs no product.
    in_v0_v2 && in_v0_v1() && in_v1_v2()
}

impl<S: Scalar> StandardTriangle<S> {
    /// The face collision algorithm for this triangle: the first contact of the sweep's ball with
    /// the front face, or `None` (alpha = 1). The transform is rigid, so alpha is the
    /// standardized `beta`; the normal is the front unit normal in world orientation.
    ///
    /// ```
    /// use ballcast::{StandardTriangle, Sweep, Triangle, Vec3};
    /// use fixed::types::I16F16;
    /// let v = |x: i32, y: i32, z: i32| Vec3::new(I16F16::from_num(x), I16F16::from_num(y), I16F16::from_num(z));
    /// // A floor facing +y; a ball of radius 1 falls from y = 5 to y = -3.
    /// let st = StandardTriangle::new(&Triangle::new(v(0, 0, 0), v(0, 0, 8), v(8, 0, 0)))?;
    /// let hit = st.face_collision(&Sweep::new(v(2, 5, 2), v(2, -3, 2), I16F16::ONE)?).unwrap();
    /// assert_eq!(hit.alpha, I16F16::from_num(0.5));
    /// assert_eq!(hit.normal, v(0, 1, 0));
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    pub fn face_collision(&self, sweep: &Sweep<S>) -> Option<Hit<S>> {
        // The heights alone settle most sweeps (the course notes' first test, or beta >= 1): the rest of
        // the transform is only computed when q' is needed.
        let (y0, y1) = self.heights(sweep);
        let r = sweep.radius();
        if y0 < r || y1 >= r {
            return None;
        }
        let alpha = standard_face(self, &self.standardize_from(sweep, (y0, y1)))?;
        let (p0, p1) = (sweep.p0(), sweep.p1());
        Some(Hit {
            alpha,
            position: self.face_position(p0, p1 - p0, r, (r - y0, y1 - y0, alpha), false),
            normal: self.normal(),
            contact: Contact::Face,
        })
    }
}

impl<S: Scalar> StandardTriangle<S> {
    /// The ball's centre where the path from `p0` along `d` comes down to height `r` over the
    /// plane (over the back, mirrored, if `back`), the fraction given unrounded as `num / den`
    /// (heights: `r - y0` over `y1 - y0`) and rounded as `alpha` (`num.div(den)`).
    ///
    /// A float height carries rounding in proportion to the point's distance from the triangle's
    /// origin (the difference, the products and the normal's own rounding), and a path's ends
    /// may lie far from it. So for floats the centre found is checked once more: its own height,
    /// measured where the contact is, and the centre moved along the plane's normal by the
    /// remaining difference. Not along the path: for a path that runs nearly along the plane
    /// that would carry the centre far from alpha's point, past geometry that may lie just
    /// beyond it. Fixed-point rounds heights by the same absolute step anywhere, and keeps the
    /// first.
    pub(crate) fn face_position(
        &self,
        p0: Vec3<S>,
        d: Vec3<S>,
        r: S,
        (num, den, alpha): (S, S, S),
        back: bool,
    ) -> Vec3<S> {
        let at = p0 + S::scale_fraction(d, num, den, alpha);
        if !S::PRECISION.relative || num == S::ZERO {
            return at;
        }
        let up = self.up();
        let h = self.height_of(at);
        let fix = if back { -r - h } else { r - h };
        at + up.map(|u| S::mul_unit(fix, u))
    }
}
