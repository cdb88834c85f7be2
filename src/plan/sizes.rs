//! [`Sizes`]: a level as the planner takes it.

use super::{ScalarType, Verdict};

/// A level's sizes as the planner takes them, in units. Each is a magnitude: a negative or NaN
/// one fits no scalar.
///
/// A float rounds a contact test at the size of the offsets it works with (between the
/// triangle's corners and the ball's positions, or the world's origin near a triangle as
/// large as its distance from there), not at the size of the coordinates: on a level of
/// small triangles far from the origin, telling the planner the triangles' size
/// ([`with_triangles`](Self::with_triangles)) shrinks the floats' predicted error by up to
/// `extent / span` ([`span`](Self::span)). Fixed point rounds alike everywhere: its figures do
/// not change. What is left is the contact position's own rounding at `extent`, and alpha's
/// over the path.
///
/// ```
/// use ballcast::plan::{ScalarType, Sizes};
/// // 10 km across, balls of 0.5 moving up to 2 a step, contact distances (where along its
/// // path a ball stops) within 0.1 mm: with triangles as large as the level, only I32F32 will
/// // do; with triangles at most 4 across, f32 does. Its positions, coordinates near 10 000,
/// // still round as f32 does there (`position_error`: 1.2e-3).
/// let level = Sizes::new(10_000.0, 0.5, 2.0);
/// assert_eq!(level.choose(1e-4).map(|v| v.precision.scalar), Some(ScalarType::I32F32));
/// let small = level.with_triangles(4.0);
/// assert_eq!(small.choose(1e-4).map(|v| v.precision.scalar), Some(ScalarType::F32));
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sizes {
    /// Coordinates lie within `±extent`.
    pub extent: f64,
    /// Balls' radii are at most this.
    pub radius: f64,
    /// Sweeps are at most this long.
    pub path: f64,
    /// Triangles are at most this long along any axis (the longest side of a triangle's box;
    /// its longest edge will do, being never shorter). [`new`](Self::new) takes them as large
    /// as the level: `2 × extent`.
    pub triangle: f64,
}

impl Sizes {
    /// A level with coordinates within `±extent`, radii up to `radius` and sweeps up to `path`
    /// long, its triangles as large as the level (as [`plan`](super::plan) takes them).
    pub const fn new(extent: f64, radius: f64, path: f64) -> Self {
        Self {
            extent,
            radius,
            path,
            triangle: 2.0 * extent,
        }
    }

    /// The same level with triangles at most `triangle` long along any axis.
    pub const fn with_triangles(self, triangle: f64) -> Self {
        Self { triangle, ..self }
    }

    /// How far apart, on any axis, the points of one contact can lie: the triangle, the path
    /// and the ball on either side of it, `triangle + path + 2 × radius` (a path that touches
    /// a triangle comes within a radius of it).
    pub const fn span(&self) -> f64 {
        self.triangle + self.path + 2.0 * self.radius
    }

    /// Every scalar's verdict, in [`plan`](super::plan)'s order.
    pub const fn plan(&self) -> [Verdict; 4] {
        let [a, b, c, d] = ScalarType::ALL;
        [
            Verdict::of_sizes(a.precision(), *self),
            Verdict::of_sizes(b.precision(), *self),
            Verdict::of_sizes(c.precision(), *self),
            Verdict::of_sizes(d.precision(), *self),
        ]
    }

    /// The first scalar in [`plan`](super::plan)'s order that fits, accepts the radius in
    /// [`move_and_slide`](crate::move_and_slide) and keeps a contact's expected distance error
    /// along the normal ([`Verdict::distance_error`]) within `tolerance`, as
    /// [`choose`](super::choose) picks; `None` if none does. A position is a coordinate and
    /// rounds as one at `extent` too: where positions must be within `tolerance`, check the
    /// verdict's [`position_error`](Verdict::position_error) as well.
    pub const fn choose(&self, tolerance: f64) -> Option<Verdict> {
        let all = self.plan();
        let mut i = 0;
        while i < all.len() {
            let v = all[i];
            if v.fits && v.distance_error <= tolerance && self.radius >= v.min_radius {
                return Some(v);
            }
            i += 1;
        }
        None
    }
}
