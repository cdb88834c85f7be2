//! Input validation shared by the constructors.

use crate::{Error, Input, Scalar, Vec3};

/// Accepts a value of `input` that is not NaN and lies in `[min, max]` (infinities never do).
pub(crate) fn within<S: Scalar>(v: S, min: S, max: S, input: Input) -> Result<S, Error> {
    if v.partial_cmp(&v).is_none() {
        Err(Error::NaN {
            input,
            triangle: None,
        })
    } else if !v.is_finite() || v > max || v < min {
        Err(Error::OutOfRange {
            input,
            value: v.to_f64(),
            min: min.to_f64(),
            max: max.to_f64(),
            triangle: None,
        })
    } else {
        Ok(v)
    }
}

/// Converts a number to `S`, refusing one that lies outside `S`'s safe range (or is NaN)
/// with the number itself in the error, before any saturation could hide it.
pub(crate) fn convert<S: Scalar>(v: f64) -> Result<S, Error> {
    let l = S::LIMIT.to_f64();
    let input = Input::Number;
    if v.is_nan() {
        Err(Error::NaN {
            input,
            triangle: None,
        })
    } else if !(-l..=l).contains(&v) {
        Err(Error::OutOfRange {
            input,
            value: v,
            min: -l,
            max: l,
            triangle: None,
        })
    } else {
        Ok(S::from_f64(v))
    }
}

/// Accepts a point of `input` whose coordinates are finite and at most `bound` in magnitude.
pub(crate) fn point<S: Scalar>(p: Vec3<S>, bound: S, input: Input) -> Result<Vec3<S>, Error> {
    for c in [p.x, p.y, p.z] {
        within(c, -bound, bound, input)?;
    }
    Ok(p)
}

/// Accepts a radius that is finite, non-negative and at most [`Scalar::LIMIT`]: NaN as NaN, a
/// negative one (an infinity too) as [`Error::NegativeRadius`], the rest against `[0, LIMIT]`.
pub(crate) fn radius<S: Scalar>(r: S) -> Result<S, Error> {
    if r < S::ZERO {
        return Err(Error::NegativeRadius { value: r.to_f64() });
    }
    within(r, S::ZERO, S::LIMIT, Input::Radius)
}

/// The bound on coordinates in a standard frame: world points within `LIMIT` land within
/// `2 * sqrt(3) * LIMIT < 3.5 * LIMIT` of the origin, and fixed-point needs the headroom for
/// differences of two such coordinates.
pub(crate) fn standard_bound<S: Scalar>() -> S {
    S::LIMIT + S::LIMIT + S::LIMIT + S::div_pow2(S::LIMIT, 1)
}
