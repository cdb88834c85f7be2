//! Triangles and their standard frame: the one rigid transform per triangle that the face test
//! (and every later contact test) runs in.

use crate::{Error, Features, Input, Scalar, StandardSweep, Sweep, Vec3, check};

/// A triangle as three world-space vertices: a plain `Copy` struct with no invariant.
///
/// Vertices are counter-clockwise seen from the front, so the front normal points along
/// `(v1 - v0) × (v2 - v0)`. Validate it with [`StandardTriangle::new`].
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Triangle<S> {
    /// First vertex; the origin of the standard frame.
    pub v0: Vec3<S>,
    /// Second vertex; lies in the standard frame's x–z plane with z > 0.
    pub v1: Vec3<S>,
    /// Third vertex; lies on the standard frame's positive x axis.
    pub v2: Vec3<S>,
}

impl<S> Triangle<S> {
    /// Builds a triangle from its vertices, counter-clockwise seen from the front.
    pub const fn new(v0: Vec3<S>, v1: Vec3<S>, v2: Vec3<S>) -> Self {
        Self { v0, v1, v2 }
    }
}

impl<S: Copy> Triangle<S> {
    /// The vertices as an array `[v0, v1, v2]`.
    pub const fn vertices(&self) -> [Vec3<S>; 3] {
        [self.v0, self.v1, self.v2]
    }
}

/// A validated triangle with its precomputed standard frame.
///
/// The frame is the rigid transform that puts `v0` at the origin, `v2` on the positive x axis and
/// `v1` in the x–z plane with z > 0, so the front face looks along +y. It is built from edge
/// vectors and cross products (no trigonometry); every vector is scaled by a power of two or by
/// its largest component before anything is squared, so construction cannot overflow or
/// underflow for any accepted triangle. The normal comes from the two shortest edges, whose
/// cross product suffers the least cancellation, and the axes are then made orthonormal.
///
/// Heights above the plane (standard-frame y) are measured from `v0`, or, for a float triangle
/// whose `v0` lies within twice its longest edge of the world's origin (both measured by their
/// largest coordinate), from that origin less the plane's offset ([`Parts::world_heights`]). A
/// float rounds a height at the size of the offset it is measured along: so the rounding of a
/// ball's height above a large triangle near the origin stays at the ball's own coordinates
/// (where its skin is taken), and a small scene far from the origin keeps the precision of its
/// size. Fixed point rounds alike at every magnitude and always measures from `v0`.
///
/// ```
/// use ballcast::{StandardTriangle, Triangle, Vec3};
/// // A floor triangle facing up (+y): (v1 - v0) × (v2 - v0) = (0, 0, 1) × (1, 0, 0) = (0, 1, 0).
/// let t = Triangle::new(
///     Vec3::new(0.0f32, 0.0, 0.0),
///     Vec3::new(0.0, 0.0, 1.0),
///     Vec3::new(1.0, 0.0, 0.0),
/// );
/// let st = StandardTriangle::new(&t)?;
/// assert_eq!(st.normal(), Vec3::new(0.0, 1.0, 0.0));
/// assert_eq!(st.to_standard(Vec3::new(1.0, 0.0, 0.0))?, Vec3::new(1.0, 0.0, 0.0));
/// # Ok::<(), ballcast::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StandardTriangle<S: Scalar> {
    origin: Vec3<S>,
    ux: Vec3<S::Unit>,
    uy: Vec3<S::Unit>,
    uz: Vec3<S::Unit>,
    x1: S,
    z1: S,
    x2: S,
    /// Edges 0 and 1; edge 2 runs from `v2` back to the origin along −x, with length `x2`
    /// and direction `[neg_x, 0]` (−1, or the float just above it): see [`edge`](Self::edge).
    edges: [Edge<S>; 2],
    neg_x: S::Unit,
    pub(crate) features: Features,
    pub(crate) two_sided: bool,
    /// Heights measured from the world's origin, not from `origin` (see [`Parts::world_heights`]).
    world: bool,
}

/// Everything a [`StandardTriangle`] is made of, as plain data with public fields: the form in
/// which a build step bakes prepared triangles into a `static`, so firmware keeps them in flash
/// and does no work at start-up (see the `bake` example). Two fields are derived and not
/// stored by the triangle: `normal` (the y axis rounded to `S`) and edge 2 but for its
/// direction's x (it runs along −x with length `x2`).
///
/// Parts are meant to come from [`StandardTriangle::to_parts`] on the same scalar type; the
/// `const` [`StandardTriangle::from_parts`] trusts them, and [`Parts::verify`] checks them
/// against the triangle they were made from (recomputing it, bit for bit).
///
/// ```
/// use ballcast::{StandardTriangle, Triangle, Vec3};
/// let t = Triangle::new(Vec3::new(0.0f32, 0.0, 0.0), Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 0.0, 0.0));
/// let st = StandardTriangle::new(&t)?;
/// let parts = st.to_parts();
/// assert_eq!(StandardTriangle::from_parts(parts), st);
/// assert_eq!(parts.verify(&t), Ok(()));
/// # Ok::<(), ballcast::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parts<S: Scalar> {
    /// World position of v0, the frame's origin.
    pub origin: Vec3<S>,
    /// The frame's axes `[x, y, z]` in world orientation (unit-vector precision).
    pub axes: [Vec3<S::Unit>; 3],
    /// Standardized `x1`, `z1`, `x2`.
    pub shape: [S; 3],
    /// Front unit normal in world orientation.
    pub normal: Vec3<S>,
    /// The edges, precomputed in the standard frame.
    pub edges: [Edge<S>; 3],
    /// [`Features::bits`] of the active edges and vertices.
    pub features: u8,
    /// Whether the back face also stops balls.
    pub two_sided: bool,
    /// Whether heights above the plane are measured from the world's origin (less the plane's
    /// offset) rather than from `origin`: set for a float triangle whose first vertex lies
    /// within twice its longest edge of the world's origin (both by their largest coordinate),
    /// so that a height there rounds at the point's own coordinates.
    pub world_heights: bool,
}

impl<S: Scalar> Parts<S> {
    /// Equal bit for bit: `==`, and every zero of the same sign (`-0.0 == 0.0` for floats, and
    /// a triangle made with one where the other had the other can answer with the other
    /// sign's zeros).
    pub(crate) fn identical(&self, o: &Self) -> bool {
        self == o && self.signs() == o.signs()
    }

    /// The sign bits of every component, as `f64`s: what `==` leaves out.
    fn signs(&self) -> u64 {
        let unit = |u: S::Unit| S::unit_to_scalar(u);
        let edges = self
            .edges
            .iter()
            .flat_map(|e| [unit(e.dir[0]), unit(e.dir[1]), e.len]);
        let vectors = [self.origin, self.normal]
            .into_iter()
            .flat_map(Vec3::to_array);
        let axes = self.axes.iter().flat_map(|a| a.to_array().map(unit));
        let all = vectors.chain(axes).chain(self.shape).chain(edges);
        all.fold(0, |m, c| m << 1 | c.to_f64().is_sign_negative() as u64)
    }

    /// Checks that these parts are exactly what [`StandardTriangle::new`] makes of `source`
    /// (with the same features and sidedness): the way to validate a baked scene in a test.
    ///
    /// Errors: those of [`StandardTriangle::new`], or [`Error::Mismatch`] on any difference.
    pub fn verify(&self, source: &Triangle<S>) -> Result<(), Error> {
        let made = StandardTriangle::new(source)?
            .with_features(Features::from_bits(self.features))
            .with_two_sided(self.two_sided);
        if made.to_parts().identical(self) {
            Ok(())
        } else {
            Err(Error::Mismatch { triangle: None })
        }
    }
}

/// Edge `i` of a triangle in its standard frame, precomputed (part of [`Parts`]): it starts at
/// vertex `i` and runs to vertex `i + 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge<S: Scalar> {
    /// Unit direction `[x, z]` in the x–z plane (its y component is zero).
    pub dir: [S::Unit; 2],
    /// Length.
    pub len: S,
}

impl<S: Scalar> Edge<S> {
    /// The unit direction as a vector of the standard frame.
    pub(crate) fn along(&self) -> Vec3<S::Unit> {
        Vec3::new(self.dir[0], S::UNIT_ZERO, self.dir[1])
    }

    /// The unit normal in the triangle's plane pointing away from the triangle: the direction
    /// turned a quarter to the right, seen from the front.
    pub(crate) fn out(&self) -> Vec3<S::Unit> {
        Vec3::new(-self.dir[1], S::UNIT_ZERO, self.dir[0])
    }

    /// `v`'s component along the edge ([`along`](Self::along)), in the standard frame.
    #[inline]
    pub(crate) fn along_of(&self, v: Vec3<S>) -> S {
        S::dot_unit_xz(v, self.dir)
    }

    /// `v`'s component away from the triangle ([`out`](Self::out)), in the standard frame.
    #[inline]
    pub(crate) fn out_of(&self, v: Vec3<S>) -> S {
        S::dot_unit_xz(v, [-self.dir[1], self.dir[0]])
    }
}

impl<S: Scalar> StandardTriangle<S> {
    /// Validates `t` and precomputes its standard frame.
    ///
    /// Errors: [`Error::NaN`] or [`Error::OutOfRange`] for a vertex outside
    /// `±`[`Scalar::LIMIT`]; [`Error::Degenerate`] when two vertices coincide, when the vertices
    /// are collinear at the scalar's precision (the normal's direction would be uncertain by more
    /// than about 1e-3 rad), or when the standardized base `x2` or height `z1` rounds to zero.
    pub fn new(t: &Triangle<S>) -> Result<Self, Error> {
        Frame::of(t)?.finish(t)
    }

    /// The triangle as plain data, e.g. for baking into a `static` (see [`Parts`]).
    pub fn to_parts(&self) -> Parts<S> {
        Parts {
            origin: self.origin,
            axes: [self.ux, self.uy, self.uz],
            shape: [self.x1, self.z1, self.x2],
            normal: self.normal(),
            edges: [self.edge(0), self.edge(1), self.edge(2)],
            features: self.features.bits(),
            two_sided: self.two_sided,
            world_heights: self.world,
        }
    }

    /// Rebuilds a triangle from [`Parts`] made by [`to_parts`](Self::to_parts), in a `const`
    /// context, so a prepared scene can live in a `static` (read-only memory) with no start-up
    /// work. Nothing is re-validated here: parts from anywhere else may give wrong answers (never
    /// undefined behaviour, and no panic in a release build; with overflow checks on, as in a
    /// debug build, out-of-range parts can trip them); check baked parts with
    /// [`Parts::verify`] in a test. The derived
    /// fields (`normal`, edge 2's length and its direction's z) are not read: `to_parts`
    /// computes them again.
    pub const fn from_parts(p: Parts<S>) -> Self {
        let [ux, uy, uz] = p.axes;
        let [x1, z1, x2] = p.shape;
        Self {
            origin: p.origin,
            ux,
            uy,
            uz,
            x1,
            z1,
            x2,
            edges: [p.edges[0], p.edges[1]],
            neg_x: p.edges[2].dir[0],
            features: Features::from_bits(p.features),
            two_sided: p.two_sided,
            world: p.world_heights,
        }
    }

    /// The front unit normal in world orientation (the frame's +y axis).
    pub fn normal(&self) -> Vec3<S> {
        self.uy.map(S::unit_to_scalar)
    }

    /// Edge `i` (0, 1 or 2) in the standard frame; any other `i` gives edge 2.
    pub(crate) fn edge(&self, i: usize) -> Edge<S> {
        match i {
            0 | 1 => self.edges[i],
            _ => Edge {
                dir: [self.neg_x, S::UNIT_ZERO],
                len: self.x2,
            },
        }
    }

    /// The three edges in the standard frame.
    pub(crate) fn edges(&self) -> [Edge<S>; 3] {
        [self.edges[0], self.edges[1], self.edge(2)]
    }

    /// The triangle's first vertex: the world position of the frame's origin.
    pub fn origin(&self) -> Vec3<S> {
        self.origin
    }

    /// The standardized vertices `[v0, v1, v2]`: `(0,0,0)`, `(x1,0,z1)` and `(x2,0,0)`.
    pub fn vertices(&self) -> [Vec3<S>; 3] {
        [
            Vec3::ZERO,
            Vec3::new(self.x1, S::ZERO, self.z1),
            Vec3::new(self.x2, S::ZERO, S::ZERO),
        ]
    }

    /// The frame's axes in world orientation, `[x, y, z]`, each a unit vector rounded to `S`.
    pub fn axes(&self) -> [Vec3<S>; 3] {
        [self.ux, self.uy, self.uz].map(|u| u.map(S::unit_to_scalar))
    }

    /// Transforms a world point into the standard frame.
    ///
    /// Errors: [`Error::NaN`] or [`Error::OutOfRange`] for a point outside
    /// `±`[`Scalar::LIMIT`]. The result lies within `3.5 * LIMIT` of the origin.
    pub fn to_standard(&self, p: Vec3<S>) -> Result<Vec3<S>, Error> {
        Ok(self.standard_point(check::point(p, S::LIMIT, Input::Point)?))
    }

    /// Transforms a validated sweep into the standard frame; the radius is unchanged, and so is
    /// any fraction alpha along the path, since the transform is rigid.
    pub fn standardize(&self, s: &Sweep<S>) -> StandardSweep<S> {
        self.standardize_from(s, self.heights(s))
    }

    /// The heights of the sweep's ends above the triangle's plane (their standard-frame y):
    /// a third of the transform, and all that most rejections need.
    // Inline on cores without a long multiply (a Cortex-M0: 16 fewer instructions per sweep
    // settled by the heights, `embedded/count.sh`); out of line elsewhere, where inlining it
    // costs `I16F16`'s face test on x86-64 about 30 instructions in spilled registers.
    #[cfg_attr(ballcast_no_long_mul, inline(always))]
    pub(crate) fn heights(&self, s: &Sweep<S>) -> (S, S) {
        let y = |p: Vec3<S>| frame::height(self.origin, self.uy, self.world, p);
        (y(s.p0()), y(s.p1()))
    }

    /// [`standardize`](Self::standardize) given the [`heights`](Self::heights) already found.
    pub(crate) fn standardize_from(&self, s: &Sweep<S>, (y0, y1): (S, S)) -> StandardSweep<S> {
        let point = |p: Vec3<S>, y: S| {
            let d = p - self.origin;
            Vec3::new(S::dot_unit(d, self.ux), y, S::dot_unit(d, self.uz))
        };
        StandardSweep {
            p0: point(s.p0(), y0),
            p1: point(s.p1(), y1),
            radius: s.radius(),
        }
    }

    /// The height of a point within `±LIMIT` above the triangle's plane: the y of
    /// [`standard_point`](Self::standard_point), alone.
    pub(crate) fn height_of(&self, p: Vec3<S>) -> S {
        frame::height(self.origin, self.uy, self.world, p)
    }

    /// [`to_standard`](Self::to_standard) for a point already known to lie within `±LIMIT`.
    pub(crate) fn standard_point(&self, p: Vec3<S>) -> Vec3<S> {
        let d = p - self.origin;
        Vec3::new(
            S::dot_unit(d, self.ux),
            self.height_of(p),
            S::dot_unit(d, self.uz),
        )
    }

    /// A standard-frame direction (or offset) turned into world orientation.
    pub(crate) fn world_direction(&self, v: Vec3<S>) -> Vec3<S> {
        let (x, y, z) = (self.ux, self.uy, self.uz);
        Vec3::new(
            S::dot_unit(v, Vec3::new(x.x, y.x, z.x)),
            S::dot_unit(v, Vec3::new(x.y, y.y, z.y)),
            S::dot_unit(v, Vec3::new(x.z, y.z, z.z)),
        )
    }

    /// The frame's y axis (the front normal) in unit-vector precision.
    pub(crate) fn up(&self) -> Vec3<S::Unit> {
        self.uy
    }

    /// Standardized `x1`, `z1`, `x2`, for the face test.
    pub(crate) fn shape(&self) -> (S, S, S) {
        (self.x1, self.z1, self.x2)
    }
}

mod frame;
#[cfg(test)]
mod tests;

pub(crate) use frame::{Frame, prepare_here};
