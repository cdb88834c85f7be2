//! The crate's one error type.

use core::fmt;

/// Why a constructor or query refused its input, and where. Every fallible call returns one of
/// these instead of panicking; once a value is constructed, every query on it succeeds.
///
/// A plain `Copy` value, no allocation: offending values and limits are carried as `f64`
/// (exact for `f32`, `f64` and `I16F16`; `I32F32` values beyond 53 significant bits are
/// rounded), and the triangle index where the input was one of many (a [`Scene`](crate::Scene)
/// push, a [`Mesh`](crate::Mesh) build, an index buffer, a level read with serde).
/// [`Display`](fmt::Display) says it in a sentence:
///
/// ```
/// use ballcast::{Error, Scene, Triangle, Vec3};
/// let mut s: Scene<f32, 4> = Scene::new();
/// let p = Vec3::new(1.0, 2.0, 3.0);
/// let e = s.push(Triangle::new(p, p, p)).unwrap_err();
/// assert_eq!(e, Error::Degenerate { triangle: Some(0) });
/// assert_eq!(e.to_string(), "triangle 0: degenerate (coincident or collinear vertices)");
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// Coincident or collinear vertices at the scalar's precision: the triangle has no
    /// well-defined front normal or standard frame.
    Degenerate {
        /// The triangle's index, where it was one of many.
        triangle: Option<usize>,
    },
    /// A coordinate, radius or other input is NaN.
    NaN {
        /// The triangle's index, where the value was a vertex of one of many.
        triangle: Option<usize>,
    },
    /// A value lies outside the range accepted for it: a coordinate or radius beyond the
    /// scalar's safe range ([`Scalar::LIMIT`](crate::Scalar::LIMIT), or `3.5 * LIMIT` for
    /// coordinates already in a standard frame), an infinity, a skin outside `[0, radius]`,
    /// or a number in a file that the scalar cannot hold.
    OutOfRange {
        /// The offending value (infinities included).
        value: f64,
        /// The smallest value accepted.
        min: f64,
        /// The largest value accepted.
        max: f64,
        /// The triangle's index, where the value was a vertex of one of many.
        triangle: Option<usize>,
    },
    /// The ball's radius is negative.
    NegativeRadius {
        /// The radius given.
        value: f64,
    },
    /// A fixed-capacity container (a [`Scene`](crate::Scene)) is full.
    Full {
        /// How many it holds.
        capacity: usize,
    },
    /// The ball is too small for the scalar's rounding at its coordinates: below
    /// [`slide::min_radius`](crate::slide::min_radius), a response could not keep it out of
    /// geometry.
    RadiusTooSmall {
        /// The radius given.
        radius: f64,
        /// The smallest accepted at these coordinates.
        min: f64,
    },
    /// Baked [`Parts`](crate::Parts) are not what [`StandardTriangle::new`](crate::StandardTriangle::new)
    /// makes of their source triangle.
    Mismatch {
        /// The triangle's index, where it was one of many.
        triangle: Option<usize>,
    },
    /// An index buffer names a vertex that is not there: an index at or beyond the vertex
    /// count, or a negative one.
    VertexIndex {
        /// The triangle whose corner it is (the index buffer's position divided by three).
        triangle: usize,
        /// The index read, exactly as the buffer holds it (any primitive integer fits).
        index: i128,
        /// How many vertices there are.
        vertices: usize,
    },
    /// An index buffer's length is not a multiple of three.
    IndexCount {
        /// Its length.
        len: usize,
    },
    /// A direction (such as [`Slide::floor`](crate::slide::Slide::floor)'s `up`) is the zero
    /// vector, which points nowhere.
    ZeroVector,
}

impl Error {
    /// The triangle the error was found in, where the input was one of many.
    pub const fn triangle(&self) -> Option<usize> {
        match *self {
            Error::Degenerate { triangle }
            | Error::NaN { triangle }
            | Error::OutOfRange { triangle, .. }
            | Error::Mismatch { triangle } => triangle,
            Error::VertexIndex { triangle, .. } => Some(triangle),
            _ => None,
        }
    }

    /// The same error found in triangle `index` (errors that concern no triangle are unchanged).
    #[must_use]
    pub const fn at(self, index: usize) -> Self {
        let t = Some(index);
        match self {
            Error::Degenerate { .. } => Error::Degenerate { triangle: t },
            Error::NaN { .. } => Error::NaN { triangle: t },
            Error::OutOfRange {
                value, min, max, ..
            } => Error::OutOfRange {
                value,
                min,
                max,
                triangle: t,
            },
            Error::Mismatch { .. } => Error::Mismatch { triangle: t },
            other => other,
        }
    }

    /// Whether this is [`Error::Degenerate`], wherever it was found.
    pub const fn is_degenerate(&self) -> bool {
        matches!(self, Error::Degenerate { .. })
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(t) = self.triangle() {
            write!(f, "triangle {t}: ")?;
        }
        match *self {
            Error::Degenerate { .. } => {
                f.write_str("degenerate (coincident or collinear vertices)")
            }
            Error::NaN { .. } => f.write_str("a coordinate or radius is NaN"),
            Error::OutOfRange {
                value, min, max, ..
            } => write!(f, "{value} is outside the accepted range [{min}, {max}]"),
            Error::NegativeRadius { value } => write!(f, "the radius {value} is negative"),
            Error::Full { capacity: 1 } => f.write_str("full: it holds 1 triangle"),
            Error::Full { capacity } => write!(f, "full: it holds {capacity} triangles"),
            Error::RadiusTooSmall { radius, min } => write!(
                f,
                "the radius {radius} is below {min}, the smallest the scalar resolves at these \
                 coordinates"
            ),
            Error::Mismatch { .. } => {
                f.write_str("baked parts differ from what their source triangle makes")
            }
            Error::VertexIndex { index, .. } if index < 0 => {
                write!(f, "vertex index {index} is negative")
            }
            Error::VertexIndex {
                index, vertices, ..
            } => write!(f, "vertex index {index} is beyond the {vertices} vertices"),
            Error::IndexCount { len } => {
                write!(
                    f,
                    "an index buffer of {len} is not a whole number of triangles"
                )
            }
            Error::ZeroVector => f.write_str("a direction is the zero vector"),
        }
    }
}

impl core::error::Error for Error {}
