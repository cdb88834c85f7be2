//! Which way a scene's triangles face, seen from a point: the check for a level exported with
//! the wrong winding.
//!
//! Triangles are one-sided by default ([`Scene::push`](crate::Scene::push)): their front is
//! where `(v1 - v0) × (v2 - v0)` points, i.e. vertices counter-clockwise seen from the front, and a
//! ball moving in from behind passes through. A level wound the other way (clockwise, as some
//! tools export) therefore stops nothing: a ball falls through its floor with no contact. Given a
//! point known to lie above a floor or inside a room, [`winding`] counts the triangles that face
//! it and those that turn their back to it; any of the latter in a closed room is a triangle
//! wound the wrong way. Either flip those (swap `v1` and `v2`) or push them with
//! [`Scene::push_two_sided`](crate::Scene::push_two_sided).

use crate::{Error, Geometry, Input, Scalar, Vec3, check};

/// How a scene's triangles face a point: see [`winding`].
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Winding {
    /// One-sided triangles whose front faces the point: they stop a ball coming from it.
    pub facing: usize,
    /// One-sided triangles that turn their back to the point: a ball coming from it passes
    /// through them.
    pub away: usize,
    /// The smallest index among those turned away.
    pub first_away: Option<usize>,
    /// Triangles whose plane holds the point (to rounding), either sidedness.
    pub edge_on: usize,
    /// Two-sided triangles not edge-on: they stop balls from either side.
    pub two_sided: usize,
}

/// Counts how the triangles of `scene` face the point `from` (one known to lie above the floor
/// or inside the room), by the sign of its height above each triangle's plane.
///
/// Errors: [`Error::NaN`] or [`Error::OutOfRange`] for a point outside `±`[`Scalar::LIMIT`].
///
/// ```
/// use ballcast::{Scene, Triangle, Vec3, winding::winding};
/// let v = Vec3::new;
/// let mut s: Scene<f32, 2> = Scene::new();
/// // Counter-clockwise seen from above: faces up.
/// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
/// // Clockwise seen from above: faces down, a ball from above falls through it.
/// s.push(Triangle::new(v(20.0, 0.0, -9.0), v(40.0, 0.0, 0.0), v(20.0, 0.0, 9.0)))?;
/// let w = winding(&s, v(0.0, 5.0, 0.0))?;
/// assert_eq!((w.facing, w.away, w.first_away), (1, 1, Some(1)));
/// # Ok::<(), ballcast::Error>(())
/// ```
pub fn winding<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    from: Vec3<S>,
) -> Result<Winding, Error> {
    let p = check::point(from, S::LIMIT, Input::Point)?;
    let l = Vec3::new(S::LIMIT, S::LIMIT, S::LIMIT);
    let mut w = Winding::default();
    scene.visit(-l, l, &mut |i, t| {
        let y = t.standard_point(p).y;
        if y == S::ZERO {
            w.edge_on += 1;
        } else if t.is_two_sided() {
            w.two_sided += 1;
        } else if y > S::ZERO {
            w.facing += 1;
        } else {
            w.away += 1;
            w.first_away = Some(w.first_away.map_or(i, |f: usize| f.min(i)));
        }
    });
    Ok(w)
}
