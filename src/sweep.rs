//! The moving ball, validated once so that per-triangle tests need no checks.

use crate::{Error, Input, Scalar, Vec3, check};

/// A ball of radius `radius` moving in a straight line from `p0` to `p1`, validated.
///
/// Construction checks every value once (finite, inside `±`[`Scalar::LIMIT`], radius `>= 0`), so
/// testing the sweep against any number of triangles needs no further checks and cannot fail.
///
/// ```
/// use ballcast::{Error, Input, Sweep, Vec3};
/// let s = Sweep::new(Vec3::new(0.0f32, 2.0, 0.0), Vec3::new(0.0, -2.0, 0.0), 0.5)?;
/// assert_eq!(s.radius(), 0.5);
/// assert_eq!(Sweep::new(s.p0(), s.p1(), -1.0).unwrap_err(), Error::NegativeRadius { value: -1.0 });
/// let nan = Vec3::new(f32::NAN, 0.0, 0.0);
/// let e = Sweep::new(s.p0(), nan, 1.0).unwrap_err();
/// assert_eq!(e, Error::NaN { input: Input::End, triangle: None });
/// assert_eq!(e.to_string(), "a coordinate of the end is NaN");
/// # Ok::<(), Error>(())
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sweep<S> {
    p0: Vec3<S>,
    p1: Vec3<S>,
    radius: S,
}

impl<S: Scalar> Sweep<S> {
    /// Validates a sweep from `p0` to `p1` with the given radius (0 makes it a ray).
    ///
    /// Errors: [`Error::NaN`], [`Error::OutOfRange`] (an infinity, or beyond
    /// `±`[`Scalar::LIMIT`]), [`Error::NegativeRadius`], each with the value refused.
    pub fn new(p0: Vec3<S>, p1: Vec3<S>, radius: S) -> Result<Self, Error> {
        Ok(Self {
            p0: check::point(p0, S::LIMIT, Input::Start)?,
            p1: check::point(p1, S::LIMIT, Input::End)?,
            radius: check::radius(radius)?,
        })
    }

    /// The ball's centre at the start (alpha = 0).
    pub fn p0(&self) -> Vec3<S> {
        self.p0
    }

    /// The ball's centre at the end (alpha = 1).
    pub fn p1(&self) -> Vec3<S> {
        self.p1
    }

    /// The ball's radius.
    pub fn radius(&self) -> S {
        self.radius
    }
}

/// A sweep expressed in a triangle's standard frame, validated: the input of the course notes'
/// standardized face test ([`standard_face`](crate::standard_face)).
///
/// Obtain one from [`StandardTriangle::standardize`](crate::StandardTriangle::standardize), or
/// build one directly from standard-frame coordinates with [`StandardSweep::new`].
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StandardSweep<S> {
    pub(crate) p0: Vec3<S>,
    pub(crate) p1: Vec3<S>,
    pub(crate) radius: S,
}

impl<S: Scalar> StandardSweep<S> {
    /// Validates a sweep given in standard-frame coordinates.
    ///
    /// Coordinates may reach `3.5 * LIMIT` (the farthest a world point within `LIMIT` can land),
    /// the radius `LIMIT`. Errors as for [`Sweep::new`].
    pub fn new(p0: Vec3<S>, p1: Vec3<S>, radius: S) -> Result<Self, Error> {
        let bound = check::standard_bound::<S>();
        Ok(Self {
            p0: check::point(p0, bound, Input::Start)?,
            p1: check::point(p1, bound, Input::End)?,
            radius: check::radius(radius)?,
        })
    }

    /// The start point in the standard frame.
    pub fn p0(&self) -> Vec3<S> {
        self.p0
    }

    /// The end point in the standard frame.
    pub fn p1(&self) -> Vec3<S> {
        self.p1
    }

    /// The ball's radius.
    pub fn radius(&self) -> S {
        self.radius
    }
}
