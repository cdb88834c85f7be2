//! Input validation shared by the constructors.

use crate::{Error, Scalar, Vec3};

/// Accepts a value that is finite and at most `bound` in magnitude.
pub(crate) fn value<S: Scalar>(v: S, bound: S) -> Result<S, Error> {
    if !v.is_finite() {
        Err(Error::NonFinite)
    } else if v > bound || v < -bound {
        Err(Error::OutOfRange)
    } else {
        Ok(v)
    }
}

/// Accepts a point whose coordinates are finite and at most `bound` in magnitude.
pub(crate) fn point<S: Scalar>(p: Vec3<S>, bound: S) -> Result<Vec3<S>, Error> {
    value(p.x, bound)?;
    value(p.y, bound)?;
    value(p.z, bound)?;
    Ok(p)
}

/// Accepts a radius that is finite, non-negative and at most [`Scalar::LIMIT`].
pub(crate) fn radius<S: Scalar>(r: S) -> Result<S, Error> {
    value(r, S::LIMIT)?;
    if r < S::ZERO {
        return Err(Error::NegativeRadius);
    }
    Ok(r)
}

/// The bound on coordinates in a standard frame: world points within `LIMIT` land within
/// `2 * sqrt(3) * LIMIT < 3.5 * LIMIT` of the origin, and fixed-point needs the headroom for
/// differences of two such coordinates.
pub(crate) fn standard_bound<S: Scalar>() -> S {
    S::LIMIT + S::LIMIT + S::LIMIT + S::div_pow2(S::LIMIT, 1)
}
