//! Edge and vertex contacts, and [`StandardTriangle::cast`]: the earliest contact of a moving
//! ball with a whole triangle (face, edges, vertices).
//!
//! Every test runs in the triangle's standard frame, where the triangle lies in the x–z plane.
//! An edge or vertex contact is the first moment the ball's centre comes within `r` of the
//! feature. Each is solved by closest approach instead of a squared quadratic: with `dir` the
//! unit direction of motion, `s` the signed distance of the start along it and `h` the distance
//! of the feature from the line of motion, contact is `sqrt(r² - h²)` before closest approach.
//! Only distances are formed, never squares of coordinates, so fixed-point stays in range.

use crate::face::{contains, face_point};
use crate::reject::Cut;
use crate::scalar::{largest, tie};
use crate::{Contact, Hit, Scalar, StandardSweep, StandardTriangle, Sweep, Vec3};

pub use crate::features::Features;

mod edges;

pub(crate) use edges::off_line;

/// A contact in the standard frame: alpha, the offset from the touched point to the ball's
/// centre (`None` for the face, whose normal is +y), the feature, and alpha unrounded, as a
/// fraction `(num, den)` that rounds to alpha (`num.div(den)`), from which the contact's
/// position is computed in one rounding.
pub(crate) type Touch<S> = (S, Option<Vec3<S>>, Contact, (S, S));

impl<S: Scalar> StandardTriangle<S> {
    /// The earliest contact of the sweep's ball with the triangle: its face (the course notes' test),
    /// its active edges and its active vertices.
    ///
    /// Rules, so that results are predictable at the boundaries:
    /// - One-sided by default: nothing counts unless the centre starts in front of the plane.
    ///   The face counts only for a ball moving towards the front; an edge or vertex counts
    ///   with the centre in front at contact, also for a ball moving along the plane or away
    ///   from it (falling past the top edge of a wall, the ball lands on the edge). Two-sided,
    ///   the side the centre starts on is the front for the face, and the edges and vertices
    ///   count from either side (a ball that passes the plane beside the triangle and comes
    ///   back at its edge from behind touches it).
    /// - A ball that *starts* overlapping the triangle (centre in front, closer than `r` to the
    ///   face region, an active edge or an active vertex) and does not move away from the
    ///   nearest of them (it moves further in, or square to it as rounded) is reported at
    ///   `alpha = 0`, with the normal pushing it out. One that moves away from the nearest is let
    ///   go: nothing is reported until it is clear of the triangle, including what it reaches
    ///   while still overlapping (for a lone triangle, nothing at all). Overlap is never
    ///   reported later along the path.
    /// - Across an inactive edge (a seam), a centre already below height `r` that comes over
    ///   the face (the face widened at its seams) within eight roundings of a height below `r`
    ///   meets the face there: the neighbour's frame may have rounded the plane a step higher
    ///   and seen the centre reach `r` only beyond the seam. Deeper, it is an overlap, not
    ///   reported later along the path.
    /// - A ray (radius 0) touches only the face, which includes its boundary grown by the
    ///   rounding of the point where the ray crosses the plane (twice a height's rounding,
    ///   more for a slanted ray, up to 16 times that within 3.6° of the plane): a ray through
    ///   an edge or vertex shared by neighbours meets one of them, where each frame alone may
    ///   round the crossing outside its face. A ray within that of an edge from outside meets
    ///   the face there. A ball of a radius below a few roundings of its coordinates has edge
    ///   and vertex contacts whose rounding exceeds it: at a convex edge or vertex it may pass
    ///   between neighbours (`I16F16`: up to 20 steps, at coordinates near 30).
    /// - The normal is the unit vector from the touched point to the ball's centre.
    ///
    /// ```
    /// use ballcast::{Contact, StandardTriangle, Sweep, Triangle, Vec3};
    /// let t = Triangle::new(Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 4.0), Vec3::new(4.0, 0.0, 0.0));
    /// let st = StandardTriangle::<f64>::new(&t)?;
    /// // Falling just beside edge v2-v0 (the x axis, z = 0): the ball catches the edge.
    /// let s = Sweep::new(Vec3::new(2.0, 3.0, -0.6), Vec3::new(2.0, -3.0, -0.6), 1.0)?;
    /// let hit = st.cast(&s).unwrap();
    /// assert_eq!(hit.contact, Contact::Edge(2));
    /// // Contact when the centre is at height 0.8: (0.6² + 0.8² = 1) after 2.2 of 6 units.
    /// assert!((hit.alpha - 2.2 / 6.0).abs() < 1e-12);
    /// assert!((hit.normal.y - 0.8).abs() < 1e-12 && (hit.normal.z + 0.6).abs() < 1e-12);
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<Hit<S>> {
        let (y0, y1) = self.heights(sweep);
        let (back, ..) = facing(sweep, (y0, y1), self.two_sided)?;
        self.cast_facing(sweep, (y0, y1), back, S::ONE)
    }

    /// [`cast`](Self::cast) where only contacts at alpha `reach` or earlier matter: the same
    /// answer when it is one of those; when `cast`'s contact would come later, `None` or
    /// another contact after `reach` (edges and vertices met later are passed by, so the
    /// earliest of the rest may be another feature's). A scene passes the reach of the
    /// contacts it has so far (or where the path leaves a leaf's box, which holds every contact
    /// with the leaf's triangles), which rejects a triangle whose plane the ball is still too
    /// high above at that alpha before any of the transform; callers offer what it returns to
    /// an accumulator that drops contacts after its own reach.
    pub(crate) fn cast_within(&self, sweep: &Sweep<S>, reach: S) -> Option<Hit<S>> {
        let (y0, y1) = self.heights(sweep);
        let (back, start, end) = facing(sweep, (y0, y1), self.two_sided)?;
        if above_at(sweep, (start, end), reach) {
            return None;
        }
        self.cast_facing(sweep, (y0, y1), back, reach)
    }

    /// [`cast_within`](Self::cast_within) given the [`heights`](Self::heights) already found
    /// (by the triangle's [`Frame`](crate::triangle::Frame), before the rest was prepared).
    pub(crate) fn cast_within_heights(
        &self,
        sweep: &Sweep<S>,
        heights: (S, S),
        reach: S,
    ) -> Option<Hit<S>> {
        let back = within_reach(sweep, heights, self.two_sided, reach)?;
        self.cast_facing(sweep, heights, back, reach)
    }

    /// The rest of [`cast`](Self::cast) for a sweep that may touch the triangle from the side
    /// `back` says, its ends at heights `y0` and `y1` above the plane; edges and vertices
    /// met after alpha `reach` may be passed over ([`Cut`]).
    #[inline]
    fn cast_facing(
        &self,
        sweep: &Sweep<S>,
        (y0, y1): (S, S),
        back: bool,
        reach: S,
    ) -> Option<Hit<S>> {
        let mut s = self.standardize_from(sweep, (y0, y1));
        if back {
            s.p0.y = -s.p0.y;
            s.p1.y = -s.p1.y;
        }
        let (alpha, offset, contact, (num, den)) = self.cast_front(&s, reach)?;
        // The centre at contact from the unrounded fraction: a few steps of `S` off, where
        // `p0 + alpha (p1 - p0)` would carry alpha's rounding times the path's length.
        let (p0, d) = (sweep.p0(), sweep.p1() - sweep.p0());
        let position = if offset.is_none() {
            self.face_position(p0, d, sweep.radius(), (num, den, alpha), back)
        } else {
            p0 + S::scale_fraction(d, num, den, alpha)
        };
        let normal = match offset {
            None => self.normal(),
            Some(mut v) => {
                if back {
                    v.y = -v.y;
                }
                unit(self.world_direction(v)).unwrap_or(self.normal())
            }
        };
        Some(Hit {
            alpha,
            position,
            normal: if back && offset.is_none() {
                -normal
            } else {
                normal
            },
            contact,
        })
    }

    /// `cast` for a sweep whose centre starts in front of the plane (or in it); edges and
    /// vertices met after alpha `reach` may be passed over.
    fn cast_front(&self, s: &StandardSweep<S>, reach: S) -> Option<Touch<S>> {
        let (p0, p1, r) = (s.p0, s.p1, s.radius);
        let d = p1 - p0;
        // Moving away, starting behind the plane, or never within r of it: only a ball rising
        // from within r of the plane can still meet an edge or vertex. A path along the plane
        // is met where it starts overlapping, at alpha = 0, or later by an edge or vertex.
        if d.y > S::ZERO || p0.y < S::ZERO || p1.y >= r {
            let rising = d.y > S::ZERO && p0.y >= S::ZERO && p0.y < r;
            return if rising {
                self.cast_rising(p0, p1, r, self.cut(reach, p0, p1, r))
            } else {
                None
            };
        }
        // The face is reached at height r, before any edge or vertex can be.
        let face = face_point(s);
        if let Some((beta, xq, zq)) = face
            && beta < S::ONE
            && self.face_holds(xq, zq, p0, p1, r)
        {
            return Some((beta, None, Contact::Face, (r - p0.y, p1.y - p0.y)));
        }
        if p0.y < r && (contains(self, p0.x, p0.z) || self.within_seams(p0.x, p0.z, r)) {
            return Some((S::ZERO, None, Contact::Face, (S::ZERO, S::ONE)));
        }
        // Edges and vertices can only be touched once the centre is below height r: from q'
        // (or the start, if already there) to the end.
        let band = match face {
            // Missed where alpha's rounding could have decided it (never in floats): q' again.
            // (A face point starts at height r or above: the start test above was not its.)
            Some((beta, xq, zq)) if beta_rounding_counts(d) && beta < S::ONE => {
                match self.face_point_again(s, (xq, zq)) {
                    Some((_, _, true)) => {
                        return Some((beta, None, Contact::Face, (r - p0.y, p1.y - p0.y)));
                    }
                    Some((xq, zq, false)) => Vec3::new(xq, r, zq),
                    None => Vec3::new(xq, r, zq),
                }
            }
            Some((_, xq, zq)) => Vec3::new(xq, r, zq),
            None => p0,
        };
        if r == S::ZERO || !self.near_path(band, p1, r) || self.beyond_an_edge(band, p1, r) {
            return None;
        }
        let edge = self.edges_and_vertices(p0, d, r, self.cut(reach, p0, p1, r));
        let from = face.map_or(S::ZERO, |f| f.0);
        match self.seam_entry(p0, d, r, from) {
            Some((alpha, key)) if edge.is_none_or(|e| alpha < e.0) => {
                Some((alpha, None, Contact::Face, key))
            }
            _ => edge,
        }
    }

    /// `q'` again, from the unrounded fraction in one rounding, where the face test missed with
    /// `q'` from beta as rounded and that rounding could have decided it ([`beta_rounding_counts`];
    /// `I16F16`: 0.011 on a run of 1 442, where a ball of 0.01 landed 0.002 inside an edge and
    /// met neither the face nor the edge, and went 0.7 through the plane), with `q'` within
    /// that of where the face reaches: the new `q'` and whether the face holds it. `None` where
    /// `q'` stands (far off).
    #[inline(never)]
    fn face_point_again(&self, s: &StandardSweep<S>, (xq, zq): (S, S)) -> Option<(S, S, bool)> {
        let (p0, p1, r) = (s.p0, s.p1, s.radius);
        let d = p1 - p0;
        let off = S::EPSILON.mul(largest(d.x.abs(), d.z.abs(), S::ZERO));
        // The most the face reaches beyond the triangle: the seam margin (a ball), or 32
        // height roundings (a ray: `within_rounding`'s most, 16 times two; only fixed point comes
        // here, whose height rounding is the same everywhere).
        let h = S::height_error(S::ZERO);
        let reach = if r == S::ZERO {
            S::from_int(32).mul(h)
        } else {
            crate::seam::seam_margin(r)
        };
        if !self.within_box(Vec3::new(xq, S::ZERO, zq), off + reach) {
            return None;
        }
        // `face_point` held `p0.y >= r > p1.y`: the fraction is within [0, 1].
        let (n, den) = (r - p0.y, p1.y - p0.y);
        let (xq, zq) = (
            p0.x + S::mul_div(d.x, n, den),
            p0.z + S::mul_div(d.z, n, den),
        );
        Some((xq, zq, self.face_holds(xq, zq, p0, p1, r)))
    }

    /// Whether the face, grown along its seams (and for a ray by the rounding of its crossing),
    /// holds the point `(xq, 0, zq)` where the ball reaches height `r`.
    #[inline(always)]
    fn face_holds(&self, xq: S, zq: S, p0: Vec3<S>, p1: Vec3<S>, r: S) -> bool {
        contains(self, xq, zq)
            || self.within_seams(xq, zq, r)
            || (r == S::ZERO && self.ray_within_rounding(xq, zq, p0, p1))
    }

    /// [`within_rounding`](Self::within_rounding) for a ray from `p0` to `p1` (in the frame),
    /// at the largest coordinate of its ends and of the triangle: out of line, as rays are
    /// rare and the face test of every ball passes by it.
    #[cold]
    #[inline(never)]
    fn ray_within_rounding(&self, xq: S, zq: S, p0: Vec3<S>, p1: Vec3<S>) -> bool {
        let (x1, z1, x2) = self.shape();
        let ends = largest(p0.abs().max_element(), p1.abs().max_element(), S::ZERO);
        let m = largest(ends, largest(x1.abs(), x2, z1), S::ZERO);
        self.within_rounding(xq, zq, m, p1 - p0)
    }

    /// [`cast_front`](Self::cast_front) for a ball moving away from the plane, its centre
    /// starting in front within `r` of it: the face cannot be met (a ball that overlaps it
    /// leaves), but an edge or vertex the ball passes within `r` of can.
    /// Starting outside the face region, the ball touches the triangle first where it touches
    /// one of them first.
    #[cold]
    #[inline(never)]
    fn cast_rising(&self, p0: Vec3<S>, p1: Vec3<S>, r: S, cut: Cut<S>) -> Option<Touch<S>> {
        let over_face = contains(self, p0.x, p0.z) || self.within_seams(p0.x, p0.z, r);
        if over_face || r == S::ZERO || !self.near_path(p0, p1, r) || self.beyond_an_edge(p0, p1, r)
        {
            return None;
        }
        self.edges_and_vertices(p0, p1 - p0, r, cut)
    }
}

/// The side from which a sweep whose ends lie at heights `y0`, `y1` above a triangle's plane
/// may touch the triangle (true: the back) at alpha `reach` or earlier, or `None` where the
/// heights alone rule that out: [`StandardTriangle::cast_within`]'s first tests, which need
/// no more of the triangle than its plane and sidedness.
#[inline]
pub(crate) fn within_reach<S: Scalar>(
    sweep: &Sweep<S>,
    heights: (S, S),
    two_sided: bool,
    reach: S,
) -> Option<bool> {
    let (back, start, end) = facing(sweep, heights, two_sided)?;
    (!above_at(sweep, (start, end), reach)).then_some(back)
}

/// Whether `q'` from beta as rounded may be off by more than the face allows for: beta's half
/// step times the path's run along the plane beyond four steps (the seam margin's own part, by
/// which the face is widened along its inactive edges), that is a run of 8.5 units or more in
/// fixed point (the product rounded to a step). Never for floats, whose beta rounds relative to
/// itself: a step of it times the run is within the rounding of the run's coordinates.
#[inline]
fn beta_rounding_counts<S: Scalar>(d: Vec3<S>) -> bool {
    // `EPSILON × run > 8 EPSILON`, the product rounded to a step: a run of 8.5 or more, with no
    // product (a Cortex-M0 has no long multiply).
    let most = S::from_int(8) + S::div_pow2(S::ONE, 1);
    let beyond = |v: S| v >= most || v <= -most;
    !S::PRECISION.relative && (beyond(d.x) || beyond(d.z))
}

/// The side the sweep comes from (true: the back) and its heights as seen from that side,
/// or `None` where no contact is possible.
fn facing<S: Scalar>(sweep: &Sweep<S>, (y0, y1): (S, S), two_sided: bool) -> Option<(bool, S, S)> {
    // Towards the back (or along the plane behind it): a one-sided triangle ignores it, a
    // two-sided one mirrors y. Contact needs the centre to start on the side it moves
    // towards, or along, and to come within r of the plane: decided by the heights, before
    // the rest of the transform.
    let back = y1 > y0 || (y1 == y0 && y0 < S::ZERO);
    let (start, end) = if back { (-y0, -y1) } else { (y0, y1) };
    let r = sweep.radius();
    if (back && !two_sided) || start < S::ZERO || end >= r {
        // Moving away from the side the centre starts on, within r of the plane; or, for a
        // one-sided triangle, leaving its plane for the front (a centre in the plane that
        // moves to the back goes further in, and meets what it overlaps at alpha 0).
        let leaves = start == S::ZERO && back && !two_sided;
        let away = (start < S::ZERO && -start < r) || leaves;
        return if away {
            facing_away((start, end), back, two_sided)
        } else {
            None
        };
    }
    Some((back, start, end))
}

/// [`facing`] for a sweep that moves away from the side its centre starts on, within r of
/// the plane (`-r < start < 0` as seen from the side it moves towards), or leaves the plane of
/// a one-sided triangle for its front (`start` zero): that side is the one whose edges and
/// vertices it may still meet.
#[inline(always)]
fn facing_away<S: Scalar>(
    (start, end): (S, S),
    back: bool,
    two_sided: bool,
) -> Option<(bool, S, S)> {
    let side = !back;
    (!side || two_sided).then_some((side, -start, -end))
}

/// Whether the ball's centre is still higher than `r` above the plane (heights `start` to
/// `end`) up to alpha `reach`, by more than any rounding: then every contact with the
/// triangle comes after `reach`. Every contact has the centre within `r` of a point of the plane
/// at its alpha: exactly at the face's, and up to the rounding of the edge and vertex tests (a
/// few steps of the heights' magnitude) plus that of alpha itself (half a step, times the
/// path's length) at theirs; the bound allows for several times each.
fn above_at<S: Scalar>(sweep: &Sweep<S>, (start, end): (S, S), reach: S) -> bool {
    let r = sweep.radius();
    let d = sweep.p1() - sweep.p0();
    let length = d.abs().max_element();
    let m = largest(start.abs(), end.abs(), r);
    let h = S::height_error(largest(m, length, S::ZERO));
    let e = h + h + h + h + tie::<S>().mul(length) + tie::<S>().mul(length);
    // Along or away from the plane the start is the lowest point, and `facing` kept it
    // within r: no contact is excluded.
    end < start && start + reach.mul(end - start) > r + e
}

/// `v` scaled to unit length in `S`; `None` for the zero vector.
pub(crate) fn unit<S: Scalar>(v: Vec3<S>) -> Option<Vec3<S>> {
    S::direction(v).map(|(_, d)| d.map(S::unit_to_scalar))
}
