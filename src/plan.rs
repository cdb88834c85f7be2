//! The precision planner: given a scene's size, which scalars can hold it without overflow, and
//! what error each will show. The error model is the one the accuracy report measures
//! (`cargo run --release --example tradeoff`) and `tests/plan.rs` checks case by case.

use crate::Scalar;
use fixed::types::{I16F16, I32F32};

/// What the planner knows of a scalar type: its safe range and how it rounds.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Precision {
    /// The type's name.
    pub name: &'static str,
    /// [`Scalar::LIMIT`] as `f64`.
    pub limit: f64,
    /// [`Scalar::EPSILON`] as `f64`: the spacing of values near one.
    pub epsilon: f64,
    /// Whether rounding is relative to magnitude (floats) or one absolute step (fixed-point).
    pub relative: bool,
}

impl Precision {
    /// Whether coordinates within `±extent` and radii up to `radius` are inside the safe range,
    /// so that nothing can overflow.
    pub const fn fits(&self, extent: f64, radius: f64) -> bool {
        extent <= self.limit && radius <= self.limit && radius >= 0.0
    }

    /// The largest error expected of a contact's position along the normal, for coordinates
    /// within `±extent` and paths up to `path` long: half a step of alpha over the path (alpha is
    /// reported in the scalar), plus the rounding of the heights: four steps of `extent` for
    /// floats, eight absolute steps for fixed-point (bounds fitted to, and tested against, the
    /// measured errors).
    ///
    /// ```
    /// use ballcast::Scalar;
    /// use fixed::types::I16F16;
    /// // A 100-unit room with 10-unit moves: I16F16 contacts land within ~2e-4.
    /// let e = I16F16::PRECISION.distance_error(100.0, 10.0);
    /// assert!(e > 1e-4 && e < 3e-4);
    /// ```
    pub const fn distance_error(&self, extent: f64, path: f64) -> f64 {
        self.epsilon / 2.0 * path + self.height_error(extent)
    }

    /// The largest error expected of a contact's position (`Hit::position`) along the normal,
    /// for coordinates within `±extent`: the rounding of the heights, since the position is
    /// formed from alpha before alpha is rounded. For floats an edge or vertex contact adds
    /// the rounding of its chord and quotient, in proportion to the coordinates too (up to 4.3
    /// steps of the spacing at `extent` were seen over 10^6 casts at scale 10): six steps.
    ///
    /// ```
    /// use ballcast::Scalar;
    /// use fixed::types::I16F16;
    /// // Eight steps of 2^-16 anywhere in I16F16's range, whatever the path's length.
    /// assert_eq!(I16F16::PRECISION.position_error(100.0), 8.0 / 65536.0);
    /// assert_eq!(f32::PRECISION.position_error(100.0), 600.0 * f32::EPSILON as f64);
    /// ```
    pub const fn position_error(&self, extent: f64) -> f64 {
        if self.relative {
            1.5 * self.height_error(extent)
        } else {
            self.height_error(extent)
        }
    }

    /// The rounding of a height (a coordinate in a triangle's frame) for coordinates within
    /// `±extent`: four steps of the spacing at `extent` (at least 1) for floats, eight absolute
    /// steps for fixed-point.
    pub const fn height_error(&self, extent: f64) -> f64 {
        if self.relative {
            4.0 * self.epsilon * if extent > 1.0 { extent } else { 1.0 }
        } else {
            8.0 * self.epsilon
        }
    }

    /// The smallest radius [`move_and_slide`](crate::move_and_slide) accepts for coordinates
    /// within `±extent`: sixteen times [`height_error`](Self::height_error), as
    /// [`slide::min_radius`](crate::slide::min_radius) computes it in the scalar.
    ///
    /// ```
    /// use ballcast::Scalar;
    /// use fixed::types::I16F16;
    /// assert_eq!(I16F16::PRECISION.min_radius(2048.0), 128.0 / 65536.0);
    /// assert_eq!(f32::PRECISION.min_radius(1000.0), 64.0 * f32::EPSILON as f64 * 1000.0);
    /// ```
    pub const fn min_radius(&self, extent: f64) -> f64 {
        16.0 * self.height_error(extent)
    }
}

/// The planner's verdict on one scalar.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Verdict {
    /// The scalar.
    pub precision: Precision,
    /// Whether the scene fits the safe range.
    pub fits: bool,
    /// Expected largest contact error along the normal (meaningful only if `fits`).
    pub distance_error: f64,
    /// Expected largest error of the contact's position along the normal.
    pub position_error: f64,
    /// The smallest radius [`move_and_slide`](crate::move_and_slide) accepts at the extent.
    pub min_radius: f64,
}

/// Every scalar's verdict for a scene with coordinates within `±extent`, radii up to `radius`
/// and sweeps up to `path` long, cheapest first (`I16F16`, `f32`, `I32F32`, `f64`).
///
/// ```
/// use ballcast::plan;
/// // A 10 km world does not fit I16F16; f32 keeps contacts within ~5 mm there.
/// let [i16, f32, ..] = plan(10_000.0, 1.0, 20.0);
/// assert!(!i16.fits && f32.fits && f32.distance_error < 6e-3);
/// ```
pub const fn plan(extent: f64, radius: f64, path: f64) -> [Verdict; 4] {
    [
        Verdict::of(I16F16::PRECISION, extent, radius, path),
        Verdict::of(f32::PRECISION, extent, radius, path),
        Verdict::of(I32F32::PRECISION, extent, radius, path),
        Verdict::of(f64::PRECISION, extent, radius, path),
    ]
}

impl Verdict {
    /// The verdict on one scalar for a scene as in [`plan`].
    pub const fn of(precision: Precision, extent: f64, radius: f64, path: f64) -> Self {
        Self {
            precision,
            fits: precision.fits(extent, radius),
            distance_error: precision.distance_error(extent, path),
            position_error: precision.position_error(extent),
            min_radius: precision.min_radius(extent),
        }
    }
}
