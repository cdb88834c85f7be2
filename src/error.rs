//! The crate's one error type.

use core::fmt;

mod input;

pub use input::Input;

/// Why a constructor or query refused its input, and where. Every fallible call returns one of
/// these instead of panicking; once a value is constructed, every query on it succeeds.
///
/// A plain `Copy` value, no allocation: which argument was refused ([`Input`]), offending
/// values and limits as `f64` (exact for `f32`, `f64` and `I16F16`; `I32F32` values beyond 53
/// significant bits are rounded), and the triangle index where the input was one of many (a
/// [`Scene`](crate::Scene) push, a [`Mesh`](crate::Mesh) build, an index buffer, a level read
/// with serde). [`Display`](fmt::Display) says it in a sentence:
///
/// ```
/// use ballcast::{Error, Input, Scene, Triangle, Vec3, move_and_slide};
/// let mut s: Scene<f32, 4> = Scene::new();
/// let p = Vec3::new(1.0, 2.0, 3.0);
/// let e = s.push(Triangle::new(p, p, p)).unwrap_err();
/// assert_eq!(e, Error::Degenerate { triangle: Some(0) });
/// assert_eq!(e.to_string(), "triangle 0: degenerate (coincident or collinear vertices)");
/// let e = move_and_slide(&s, p, Vec3::new(0.0, f32::NAN, 0.0), 0.5).unwrap_err();
/// assert_eq!(e.input(), Some(Input::Displacement));
/// assert_eq!(e.to_string(), "a coordinate of the displacement is NaN");
/// let mut s: Scene<f32, 4> = Scene::new();
/// let e = s.push(Triangle::new(p, Vec3::new(f32::NAN, 0.0, 0.0), p)).unwrap_err();
/// assert_eq!(e.to_string(), "triangle 0: a coordinate of v1 is NaN");
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
        /// The argument that holds it.
        input: Input,
        /// The triangle's index, where the value was a vertex of one of many.
        triangle: Option<usize>,
    },
    /// A value lies outside the range accepted for it: a coordinate or radius beyond the
    /// scalar's safe range ([`Scalar::LIMIT`](crate::Scalar::LIMIT), or `3.5 * LIMIT` for
    /// coordinates already in a standard frame), an infinity, a skin outside `[0, radius]`,
    /// or a number in a file that the scalar cannot hold.
    OutOfRange {
        /// The argument that holds it.
        input: Input,
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
        /// The coordinates' largest magnitude: of the position and, for a move, its target.
        extent: f64,
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
    ZeroVector {
        /// The argument that is zero.
        input: Input,
    },
}

impl Error {
    /// The argument refused, for [`Error::NaN`], [`Error::OutOfRange`] and
    /// [`Error::ZeroVector`]; [`Input::Radius`] for [`Error::NegativeRadius`] and
    /// [`Error::RadiusTooSmall`] (too small for the coordinates where the ball is or goes).
    pub const fn input(&self) -> Option<Input> {
        match *self {
            Error::NaN { input, .. }
            | Error::OutOfRange { input, .. }
            | Error::ZeroVector { input } => Some(input),
            Error::NegativeRadius { .. } | Error::RadiusTooSmall { .. } => Some(Input::Radius),
            _ => None,
        }
    }

    /// The triangle the error was found in, where the input was one of many.
    pub const fn triangle(&self) -> Option<usize> {
        match *self {
            Error::Degenerate { triangle }
            | Error::NaN { triangle, .. }
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
            Error::NaN { input, .. } => Error::NaN { input, triangle: t },
            Error::OutOfRange {
                input,
                value,
                min,
                max,
                ..
            } => Error::OutOfRange {
                input,
                value,
                min,
                max,
                triangle: t,
            },
            Error::Mismatch { .. } => Error::Mismatch { triangle: t },
            other => other,
        }
    }

    /// The same [`Error::NaN`] or [`Error::OutOfRange`] about `input` (others unchanged): for
    /// a conversion that found the value, named by the caller that knows what it was.
    pub(crate) const fn of(self, input: Input) -> Self {
        match self {
            Error::NaN { triangle, .. } => Error::NaN { input, triangle },
            Error::OutOfRange {
                value,
                min,
                max,
                triangle,
                ..
            } => Error::OutOfRange {
                input,
                value,
                min,
                max,
                triangle,
            },
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
            Error::NaN { input, .. } => write!(f, "{input} is NaN"),
            Error::OutOfRange {
                input,
                value,
                min,
                max,
                ..
            } => {
                let [value, min, max] = typed([value, min, max]);
                if input == Input::Number {
                    write!(f, "{value} is outside the accepted range [{min}, {max}]")?;
                } else {
                    write!(
                        f,
                        "{input} is {value}, outside the accepted range [{min}, {max}]"
                    )?;
                }
                if saturated(value.0) {
                    f.write_str(
                        " (a fixed-point extreme: `Scalar::from_f64` saturates larger numbers, \
                         and NaN, to it)",
                    )?;
                }
                Ok(())
            }
            Error::NegativeRadius { value } => {
                let [value] = typed([value]);
                write!(f, "the radius {value} is negative")
            }
            Error::Full { capacity: 1 } => f.write_str("full: it holds 1 triangle"),
            Error::Full { capacity } => write!(f, "full: it holds {capacity} triangles"),
            Error::RadiusTooSmall {
                radius,
                min,
                extent,
            } => {
                let [radius, min, extent] = typed([radius, min, extent]);
                write!(
                    f,
                    "the radius {radius} is below {min}, the smallest the scalar resolves at \
                     coordinates up to {extent} (where the ball is or goes)"
                )
            }
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
            Error::ZeroVector { input } => write!(f, "{} is the zero vector", input.noun().0),
        }
    }
}

impl core::error::Error for Error {}

/// The values of one message as the caller most likely typed them: each that is an `f32` (zero,
/// or exactly an `f32` between its smallest normal and 2^24 in magnitude) in the shortest
/// digits that give the `f32` back, so an `f32` radius of -0.4 reads -0.4, not the
/// -0.4000000059604645 it widens to, also beside a limit worked out in `f64` (a time step's);
/// the rest in the shortest digits that give the `f64` back. Where a value that is no `f32` is
/// what the digits of one printed so read as in `f64`, the two could read alike (an `f64`
/// radius just above a limit that is an `f32`), and all take their `f64` digits. The error's
/// fields keep the exact values.
fn typed<const N: usize>(values: [f64; N]) -> [Typed; N] {
    const WHOLE: f64 = 16_777_216.0;
    let narrow = |v: f64| {
        let a = v.abs();
        v == 0.0 || (a >= f64::from(f32::MIN_POSITIVE) && a < WHOLE && f64::from(v as f32) == v)
    };
    let clash = values.iter().any(|&w| {
        !narrow(w)
            && values
                .iter()
                .any(|&v| narrow(v) && f32_digits_in_f64(v as f32) == Some(w))
    });
    values.map(|v| Typed(v, !clash && narrow(v)))
}

/// The shortest digits of `v` read back as an `f64`: the one `f64` whose own shortest digits
/// can be the same. (Whether `w` rounds to `v` does not tell: digits next to a midpoint between
/// two `f32`s can read as an `f64` that rounds to the other one, as `7.038531e-26` does.)
fn f32_digits_in_f64(v: f32) -> Option<f64> {
    /// A line of text on the stack: no allocation; a write beyond it fails.
    struct Line {
        bytes: [u8; 32],
        len: usize,
    }
    impl fmt::Write for Line {
        fn write_str(&mut self, s: &str) -> fmt::Result {
            let end = self.len.checked_add(s.len()).ok_or(fmt::Error)?;
            let to = self.bytes.get_mut(self.len..end).ok_or(fmt::Error)?;
            to.copy_from_slice(s.as_bytes());
            self.len = end;
            Ok(())
        }
    }
    let mut line = Line {
        bytes: [0; 32],
        len: 0,
    };
    fmt::write(&mut line, format_args!("{v:e}")).ok()?;
    core::str::from_utf8(line.bytes.get(..line.len)?)
        .ok()?
        .parse()
        .ok()
}

/// `value` as an error message prints it: its shortest digits, in exponent form where plain
/// digits would run long (see [`Typed`]).
pub(crate) fn shown(value: f64) -> impl fmt::Display {
    Typed(value, false)
}

/// A value, printed as the `f32` it is (true) or as itself: in exponent form where plain
/// digits would run long (from 10^21 up, and below 10^-7, where JavaScript switches too), so
/// that a radius of 1e300 reads `1e300`, not a line of 301 digits.
struct Typed(f64, bool);

impl fmt::Display for Typed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let a = self.0.abs();
        let long = a >= 1e21 || (a != 0.0 && a < 1e-7);
        match (self.1, long) {
            (true, false) => write!(f, "{}", self.0 as f32),
            (true, true) => write!(f, "{:e}", self.0 as f32),
            (false, false) => write!(f, "{}", self.0),
            (false, true) => write!(f, "{:e}", self.0),
        }
    }
}

/// Whether `value` is the largest or smallest value of a fixed-point scalar: what a conversion
/// of a larger number, or of NaN, gives ([`Scalar::from_f64`](crate::Scalar::from_f64)).
fn saturated(value: f64) -> bool {
    use fixed::types::{I16F16, I32F32};
    [
        I16F16::MAX.to_num::<f64>(),
        I16F16::MIN.to_num(),
        I32F32::MAX.to_num(),
        I32F32::MIN.to_num(),
    ]
    .contains(&value)
}
