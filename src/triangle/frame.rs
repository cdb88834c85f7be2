//! [`StandardTriangle::new`] in two halves: the frame (origin and axes), which is all the
//! heights of a sweep need, and the rest (the standardized shape and edges). A triangle
//! prepared on the spot (a compact mesh's, behind its integer box) can then be passed by on its
//! heights alone before the second half: two square roots, two normalisations and three dot
//! products saved for each triangle the ball cannot reach, bit for bit the same triangle for
//! those it can.

use super::{Edge, StandardTriangle, Triangle};
use crate::scalar::largest;
use crate::{Error, Features, Input, Scalar, Sweep, Vec3, check};

const DEGENERATE: Error = Error::Degenerate { triangle: None };

/// The first half of a prepared triangle: the validated source and its frame.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame<S: Scalar> {
    origin: Vec3<S>,
    ux: Vec3<S::Unit>,
    uy: Vec3<S::Unit>,
    uz: Vec3<S::Unit>,
    /// Whether heights are measured from the world's origin (see [`height`]).
    world: bool,
}

impl<S: Scalar> Frame<S> {
    /// Validates `t` and finds its frame; the errors of [`StandardTriangle::new`] but those of
    /// the shape, which [`finish`](Self::finish) gives.
    #[inline(always)]
    pub(crate) fn of(t: &Triangle<S>) -> Result<Self, Error> {
        // Two comparisons per coordinate, which NaN and infinities fail; the checks then name
        // the first offender.
        let (lo, hi) = (-S::LIMIT, S::LIMIT);
        let within = |c: S| lo <= c && c <= hi;
        let inside = |p: Vec3<S>| within(p.x) && within(p.y) && within(p.z);
        if !(inside(t.v0) && inside(t.v1) && inside(t.v2)) {
            for (k, v) in [t.v0, t.v1, t.v2].into_iter().enumerate() {
                check::point(v, S::LIMIT, Input::Vertex(k as u8))?;
            }
        }
        let edges = [t.v1 - t.v0, t.v2 - t.v1, t.v0 - t.v2];
        // (v1-v0)×(v2-v0) = e0×e1 = e1×e2 = e2×e0: use the pair that leaves out the longest edge.
        // Only that pair is scaled: a zero edge is always in it (the other two are then equal
        // and opposite, so the longest is the one after it), and gives `Degenerate`.
        let [l0, l1, l2] = edges.map(|e| e.abs().max_element());
        let world = S::PRECISION.relative && {
            let longest = largest(l0, l1, l2);
            t.v0.abs().max_element() < longest + longest
        };
        // The pair taken by value, not by indices into `edges`: a load at a computed index
        // from the array just stored waits for those stores to drain (on x86-64 it took a
        // quarter of a preparation's time), a choice between registers does not.
        let [e0, e1, e2] = edges;
        let (first, second) = (l2 >= l0 && l2 >= l1, l0 >= l1);
        let pick = |x: Vec3<S>, y: Vec3<S>, z: Vec3<S>| {
            if first {
                x
            } else if second {
                y
            } else {
                z
            }
        };
        let (ea, eb) = (pick(e0, e1, e2), pick(e1, e2, e0));
        let scaled = |v: Vec3<S>| S::scaled(v).ok_or(DEGENERATE);
        let cross = |a, b| S::scaled_cross(a, b).ok_or(DEGENERATE);
        // The axes are found as scaled directions (largest component in [1/2, 1]) and are
        // normalised at the end, each on its own: no normalisation waits for another.
        let n = cross(scaled(ea)?, scaled(eb)?)?;
        let x = scaled(t.v2 - t.v0)?;
        let z = cross(x, n)?;
        let y = cross(z, x)?;
        let (ux, uy, uz) = (
            S::unit_normalize(x),
            S::unit_normalize(y),
            S::unit_normalize(z),
        );
        Ok(Self {
            origin: t.v0,
            ux,
            uy,
            uz,
            world,
        })
    }

    /// The heights of the sweep's ends above the plane, as the finished triangle's
    /// [`heights`](StandardTriangle::heights).
    pub(crate) fn heights(&self, s: &Sweep<S>) -> (S, S) {
        let y = |p: Vec3<S>| height(self.origin, self.uy, self.world, p);
        (y(s.p0()), y(s.p1()))
    }

    /// The rest of [`StandardTriangle::new`] for the triangle `t` this frame was found for.
    #[inline(always)]
    pub(crate) fn finish(self, t: &Triangle<S>) -> Result<StandardTriangle<S>, Error> {
        let Self {
            origin,
            ux,
            uy,
            uz,
            world,
        } = self;
        let (base, side) = (t.v2 - t.v0, t.v1 - t.v0);
        let (x1, z1, x2) = (
            S::dot_unit(side, ux),
            S::dot_unit(side, uz),
            S::dot_unit(base, ux),
        );
        if !(x2 > S::ZERO && z1 > S::ZERO) {
            return Err(DEGENERATE);
        }
        let z = S::ZERO;
        let (v0, v1, v2) = (
            Vec3::new(z, z, z),
            Vec3::new(x1, z, z1),
            Vec3::new(x2, z, z),
        );
        let mut edges = [Edge {
            dir: [S::UNIT_ZERO; 2],
            len: S::ZERO,
        }; 2];
        for (edge, (from, to)) in edges.iter_mut().zip([(v0, v1), (v1, v2)]) {
            let (len, dir) = S::direction(to - from).ok_or(DEGENERATE)?;
            *edge = Edge {
                dir: [dir.x, dir.z],
                len,
            };
        }
        Ok(StandardTriangle {
            origin,
            ux,
            uy,
            uz,
            x1,
            z1,
            x2,
            edges,
            neg_x: S::direction_neg_x(x2),
            features: Features::ALL,
            two_sided: false,
            world,
        })
    }
}

/// The height of `p` above the plane through `origin` with unit normal `uy`.
///
/// A height is a dot product of an offset, which a float rounds at the offset's magnitude.
/// Measured from the frame's origin (v0), that is the point's distance from v0, and heights near
/// a triangle keep the precision of its size wherever it lies. A ball near the world's origin on
/// a triangle about as large as its distance from there may be hundreds of units from v0,
/// though: a lift by its skin (taken at the ball's own coordinates) would vanish in that
/// rounding, and a ball met again at once would never leave. So a float triangle whose v0 lies
/// within twice its longest edge of the world's origin (both measured by their largest
/// coordinate; `world`) measures from there, less the plane's offset `dot(v0, uy)`: a height
/// then rounds at the point's coordinates, plus a constant per triangle (the offset's rounding,
/// at v0's). Farther out, a ball touching the triangle is no nearer the world's origin than it
/// is to v0, less twice its radius, and the rounding at v0 stays within its skin. Neither choice
/// removes the plane's own error: its rounded normal through v0 strays from the true plane by
/// the normal's rounding times the distance from v0, and coplanar neighbours with different
/// first vertices disagree by that much. Fixed point rounds a product alike at every magnitude,
/// and always measures from v0.
#[inline(always)]
pub(crate) fn height<S: Scalar>(origin: Vec3<S>, uy: Vec3<S::Unit>, world: bool, p: Vec3<S>) -> S {
    // (Fixed point never sets `world`; asking the scalar first lets its code drop the test.)
    if S::PRECISION.relative && world {
        S::dot_unit(p, uy) - S::dot_unit(origin, uy)
    } else {
        S::dot_unit(p - origin, uy)
    }
}

/// [`StandardTriangle::new`] inlined where it is called, for a caller that has just made `t`
/// (a call would read it back from memory before the stores complete: a store-forwarding wait
/// on x86-64) or that prepares many in a row (`Mesh::build`: the result is not returned
/// through the stack and copied again, 3 % to 4 % off the build of 10^5 triangles); a call on
/// bare-metal targets, which have no such wait and whose flash the copy would cost (about
/// 2.7 KB on a Cortex-M0).
#[inline(always)]
pub(crate) fn prepare_here<S: Scalar>(t: &Triangle<S>) -> Result<StandardTriangle<S>, Error> {
    if cfg!(target_os = "none") {
        StandardTriangle::new(t)
    } else {
        Frame::of(t)?.finish(t)
    }
}
