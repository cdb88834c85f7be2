//! Why a heightfield's build refused, with the value that decided it.

use crate::Error;
use crate::error::shown;
use core::fmt;

/// Why [`Heightfield::build`](super::Heightfield::build) refused.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HeightfieldError {
    /// `heights` does not hold `(columns + 1) (rows + 1)` values.
    Size {
        /// Heights expected.
        needed: usize,
        /// Heights given.
        given: usize,
    },
    /// `columns` or `rows` is zero: a grid needs at least one cell.
    Empty {
        /// The columns given.
        columns: u32,
        /// The rows given.
        rows: u32,
    },
    /// `cells` holds fewer than `columns × rows` bytes.
    Capacity {
        /// Bytes needed.
        needed: usize,
        /// Bytes given.
        given: usize,
    },
    /// More than [`MAX_TRIANGLES`](super::MAX_TRIANGLES) triangles.
    TooMany,
    /// `spacing` is not positive and finite.
    Spacing {
        /// The spacing given.
        value: f64,
    },
    /// `unit`, the height step, is zero, NaN or infinite.
    Unit {
        /// The unit given.
        value: f64,
    },
    /// A coordinate of `origin` is NaN or infinite.
    Origin {
        /// The first such coordinate.
        value: f64,
    },
    /// A corner of the grid (or its lowest or highest height) lies beyond the scalar's safe
    /// range, `±`[`Scalar::LIMIT`](crate::Scalar::LIMIT).
    OutOfRange {
        /// The coordinate farthest out.
        value: f64,
        /// The scalar's limit.
        limit: f64,
    },
    /// More columns or rows than the scalar counts exactly (`I16F16`: 32 767).
    Sides {
        /// The larger of the two.
        count: u32,
    },
    /// The cells are too small for the scalar at the grid's coordinates: their sides lie
    /// within a few steps of the scalar's rounding there, closer than the test for edges
    /// inside a mesh's surface can tell apart (nearer the origin, or a wider scalar, fits).
    Fine {
        /// The cell side given.
        spacing: f64,
        /// The side cells need there (they must be larger).
        least: f64,
    },
    /// A triangle was refused by [`StandardTriangle::new`](crate::StandardTriangle::new) (out of the scalar's range, or
    /// degenerate at its precision).
    Triangle {
        /// Its index (cell `index / 2`).
        index: usize,
        /// Why.
        error: Error,
    },
}

impl fmt::Display for HeightfieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Size { needed, given } => write!(
                f,
                "heightfield needs (columns + 1) x (rows + 1) = {needed} heights, got {given}"
            ),
            Self::Empty { columns, rows } => write!(
                f,
                "heightfield of {columns} x {rows} cells: it needs at least one column and one row"
            ),
            Self::Capacity { needed, given } => write!(
                f,
                "the cell buffer holds {given} bytes, too few: {needed} needed (one per cell)"
            ),
            Self::TooMany => f.write_str("more than 2^31 triangles"),
            Self::Spacing { value } => {
                let value = shown(*value);
                write!(f, "heightfield spacing {value} is not positive and finite")
            }
            Self::Unit { value: 0.0 } => f.write_str(
                "heightfield height unit is zero (in fixed point, a step finer than the \
                 scalar's resolution rounds to zero)",
            ),
            Self::Unit { value } => write!(
                f,
                "heightfield height unit {} is not a finite nonzero step",
                shown(*value)
            ),
            Self::Origin { value } => {
                let value = shown(*value);
                write!(f, "heightfield origin coordinate {value} is not finite")
            }
            Self::OutOfRange { value, limit } => {
                let (value, limit) = (shown(*value), shown(*limit));
                write!(
                    f,
                    "heightfield reaches {value} (origin plus cells times spacing, or heights times \
                 the height unit), beyond the scalar's safe range [-{limit}, {limit}]"
                )
            }
            Self::Sides { count } => write!(
                f,
                "heightfield of {count} cells along a side: more than the scalar counts exactly"
            ),
            Self::Fine { spacing, least } => {
                let (spacing, least) = (shown(*spacing), shown(*least));
                write!(
                    f,
                    "heightfield cells of side {spacing} are within the scalar's rounding at the \
                 grid's coordinates: they need a side above {least} there (move the grid \
                 nearer the origin, or use a wider scalar)"
                )
            }
            Self::Triangle { error, .. } => write!(f, "heightfield {error}"),
        }
    }
}

impl core::error::Error for HeightfieldError {}
