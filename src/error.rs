//! The crate's one error type.

use core::fmt;

/// Why a constructor refused its input. Every fallible constructor returns one of these instead of
/// panicking; once a value is constructed, every query on it succeeds.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Error {
    /// Coincident or collinear vertices at the scalar's precision: the triangle has no
    /// well-defined front normal or standard frame.
    Degenerate,
    /// A coordinate or radius is NaN or infinite.
    NonFinite,
    /// A coordinate or radius exceeds the scalar's safe range ([`Scalar::LIMIT`](crate::Scalar::LIMIT),
    /// or `3.5 * LIMIT` for coordinates already in a standard frame).
    OutOfRange,
    /// The ball's radius is negative.
    NegativeRadius,
    /// A fixed-capacity container (a [`Scene`](crate::Scene)) is full.
    Full,
    /// The ball is too small for the scalar's rounding at its coordinates: below
    /// [`slide::min_radius`](crate::slide::min_radius), a response could not keep it out of
    /// geometry.
    RadiusTooSmall,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Error::Degenerate => "degenerate triangle: coincident or collinear vertices",
            Error::NonFinite => "coordinate or radius is NaN or infinite",
            Error::OutOfRange => "coordinate or radius outside the scalar's safe range",
            Error::NegativeRadius => "negative radius",
            Error::Full => "capacity exhausted",
            Error::RadiusTooSmall => {
                "radius below the smallest the scalar resolves at these coordinates"
            }
        })
    }
}

impl core::error::Error for Error {}
