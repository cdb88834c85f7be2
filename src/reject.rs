//! Cheap rejections for [`StandardTriangle::cast`](crate::StandardTriangle::cast): tests of a
//! few products and compares, made before the edge and vertex contacts and their square roots
//! and divisions. The first two (the path's box against the triangle's, the path beyond an
//! edge's line) decide which sweeps reach the edge and vertex stage at all; the per-vertex ones
//! (and the per-edge slab and line tests in `contact.rs`) only reject what the full test of that
//! feature would reject too (the line tests carry a margin beyond the full test's rounding; see
//! `Scalar`'s `line_misses`), so they change no answer (`tests/near_miss.rs`).

use crate::scalar::largest;
use crate::{Scalar, StandardTriangle, Vec3};

impl<S: Scalar> StandardTriangle<S> {
    /// Whether the bounding box of the segment from `a` to `b`, grown by `r`, meets the
    /// triangle's (in the x–z plane).
    pub(crate) fn near_path(&self, a: Vec3<S>, b: Vec3<S>, r: S) -> bool {
        let (x1, z1, x2) = self.shape();
        let lo = |a: S, b: S| if a < b { a } else { b };
        let hi = |a: S, b: S| if a < b { b } else { a };
        let (xmin, xmax) = (lo(S::ZERO, x1), hi(x1, x2));
        lo(a.x, b.x) - r <= xmax
            && hi(a.x, b.x) + r >= xmin
            && lo(a.z, b.z) - r <= z1
            && hi(a.z, b.z) + r >= S::ZERO
    }

    /// Whether the segment from `a` (at height `r`) to `b` stays more than `r` outside one
    /// edge's line: the whole triangle lies inside that line, so nothing of it can be touched.
    /// Where `b` is below the plane of a one-sided triangle only the part down to the plane
    /// counts (an edge or vertex is touched with the centre in front): see [`clipped_beyond`].
    pub(crate) fn beyond_an_edge(&self, a: Vec3<S>, b: Vec3<S>, r: S) -> bool {
        (0..3).any(|i| {
            let (c, e) = (self.corner(i), self.edge(i));
            let wa = e.out_of(a - c);
            // `b`'s distance only where `a` is beyond the line.
            wa > r && {
                let wb = e.out_of(b - c);
                let one_sided = !self.two_sided;
                wb > r || (b.y < S::ZERO && one_sided && clipped_beyond(a, b, wa, wb, r))
            }
        })
    }

    /// Whether the path's box, grown by `r`, misses vertex `i` in x or z.
    pub(crate) fn vertex_out_of_reach(&self, i: usize, p0: Vec3<S>, d: Vec3<S>, r: S) -> bool {
        let (v, p1) = (self.corner(i), p0 + d);
        let apart = |a: S, b: S, c: S| (a - r > c && b - r > c) || (a + r < c && b + r < c);
        apart(p0.x, p1.x, v.x) || apart(p0.z, p1.z, v.z)
    }

    /// Whether the line of motion passes too far from vertex `i` for contact, seen from above
    /// (in the x–z plane: a projection only shortens distances, so this is conservative).
    pub(crate) fn vertex_line_misses(&self, i: usize, p0: Vec3<S>, d: Vec3<S>, r: S) -> bool {
        let q = p0 - self.corner(i);
        let reach = q.abs().max_element();
        S::line_misses([q.x, q.z], [d.x, d.z], r, reach)
    }
}

/// Where the edge and vertex tests may stop looking. When only contacts by some reach matter
/// (a scene's earliest alpha so far plus the tie window, or where the path leaves the box of a
/// leaf of a tree), those after it can neither come first nor tie, so a feature the ball
/// cannot meet by then need not be solved: a feature whose distance from the centre (for an
/// edge, from its line, in the plane across it) is still falling at `alpha`, four tie windows
/// past the reach (a contact within the reach shadows only contacts within one more tie
/// window, and alpha is rounded by half a step), and still exceeds `r` grown by the rounding
/// [`StandardTriangle::cut`] allows, is met later if at all ([`Cut::short_of`]): along a
/// straight path that distance is convex in alpha. That test only ever follows the whole path's
/// rejections, never replaces them (the path's box, the edge's slab and line): grown by the
/// margin, a replacement could pass a feature those reject by a hair of rounding, and the
/// answer would no longer be the single [`cast`](crate::StandardTriangle::cast)'s. The whole
/// path (`alpha` one), what a single `cast` looks at, stops nowhere.
#[derive(Clone, Copy)]
pub(crate) struct Cut<S> {
    alpha: S,
    /// How far every distance `r` is compared with is grown; zero for the whole path.
    grow: S,
}

impl<S: Scalar> StandardTriangle<S> {
    /// The cut for contacts at alpha `reach` or earlier on the path from `p0` to `p1` (this
    /// triangle's frame) of a ball of radius `r`: four times the heights' rounding bound
    /// (as `cast_within`'s plane test allows for the edge and vertex tests) at the largest of
    /// the coordinates, the triangle's size and `r`.
    #[inline]
    pub(crate) fn cut(&self, reach: S, p0: Vec3<S>, p1: Vec3<S>, r: S) -> Cut<S> {
        let t = crate::scalar::tie::<S>();
        let alpha = reach + t + t + t + t;
        if alpha >= S::ONE {
            return Cut {
                alpha: S::ONE,
                grow: S::ZERO,
            };
        }
        let (x1, z1, x2) = self.shape();
        let size = largest(x1.abs(), x2.abs(), z1);
        let ends = largest(p0.abs().max_element(), p1.abs().max_element(), r);
        let h = S::height_error(largest(ends, size, S::ZERO));
        Cut {
            alpha,
            grow: h + h + h + h,
        }
    }
}

impl<S: Scalar> Cut<S> {
    /// Whether a centre starting at offset `q0` from a feature and moving by `dq` over the
    /// path is, at the cut, still farther than `r` (grown) from it and still approaching it:
    /// its distance then falls all the way to the cut, so it comes within `r` no earlier
    /// (false for the whole path). For a vertex the offset is from the vertex; for an edge, in
    /// the plane across it, from the edge's line, whose distance is at most the edge's.
    #[inline]
    pub(crate) fn short_of(self, q0: Vec3<S>, dq: Vec3<S>, r: S) -> bool {
        self.alpha < S::ONE && farther_and_approaching(q0, dq, self.alpha, r + self.grow)
    }
}

/// [`Cut::short_of`]'s test at `alpha`: `|q| > r` and `q · dq < 0` for `q = q0 + alpha dq`. The
/// offsets lie within `3.5 LIMIT` of the scalar per component (points of the path seen from a
/// corner, in the triangle's frame), as does the path, so fixed point's exact `q · dq` stays
/// within `37 LIMIT²`, far inside the wide type. Out of line on bare-metal Arm, where its wide
/// products would otherwise be inlined at each feature's test; inline elsewhere.
#[cfg_attr(all(target_arch = "arm", target_os = "none"), inline(never))]
fn farther_and_approaching<S: Scalar>(q0: Vec3<S>, dq: Vec3<S>, alpha: S, r: S) -> bool {
    let q = q0 + dq.scale(alpha);
    S::beyond(r, q) && S::dot_sign(q, dq).is_lt()
}

/// Whether the point where the segment from `a` (height `r`) to `b` (height `b.y < 0`) crosses
/// the plane lies more than `r` plus a margin outside an edge's line, given both ends' distances
/// `wa`, `wb` outside it: then so does the whole part at heights `0..=r`. The crossing is
/// `a + λ (b - a)` with `λ = r / (r - b.y)`; multiplied out, with `R = r + margin`, the test
/// is `(wa - R)(-b.y) > r (R - wb)`: one product comparison, no division. The margin (32 steps
/// of the coordinates' spacing for floats, 64 for fixed-point) exceeds the rounding of the full
/// edge and vertex tests, so this drops only sweeps those would miss.
fn clipped_beyond<S: Scalar>(a: Vec3<S>, b: Vec3<S>, wa: S, wb: S, r: S) -> bool {
    let extent = largest(
        largest(a.x.abs(), a.z.abs(), r),
        b.abs().max_element(),
        S::ZERO,
    );
    let h = S::height_error(extent);
    let h4 = h + h + h + h;
    let big = r + h4 + h4;
    S::mul_cmp(wa - big, -b.y, r, big - wb).is_gt()
}

#[cfg(test)]
mod tests;
