//! The precision planner: given a scene's size, which scalars can hold it without overflow, and
//! what error each will show. The error model is the one the accuracy report measures
//! (`cargo run --release --example tradeoff`) and `tests/plan.rs` checks case by case.
//!
//! [`Memory::of`] gives the bytes a level of so many triangles and vertices takes in each form
//! (prepared mesh, compact mesh, heightfield) and scalar.
//!
//! A verdict names its scalar as a [`ScalarType`], so a program can pick the type it runs with:
//!
//! ```
//! use ballcast::{Scalar, plan::{ScalarType, choose}};
//! use fixed::types::{I16F16, I32F32};
//! fn simulate<S: Scalar>() -> &'static str { S::PRECISION.scalar.name() }
//! // A 100-unit room, balls of 0.5, moves up to 2 per step, contacts within 1 mm: I16F16 will do.
//! let v = choose(100.0, 0.5, 2.0, 1e-3).expect("some scalar fits");
//! let ran = match v.precision.scalar {
//!     ScalarType::I16F16 => simulate::<I16F16>(),
//!     ScalarType::F32 => simulate::<f32>(),
//!     ScalarType::I32F32 => simulate::<I32F32>(),
//!     ScalarType::F64 => simulate::<f64>(),
//! };
//! assert_eq!(ran, "I16F16");
//! ```
//!
//! ## Error over a simulation
//!
//! The planner's figures are per contact. Over a simulation, errors add up step by step, and the
//! user's own constants often weigh more than the crate's arithmetic: `1/60` in `I16F16` is
//! `1092/65536`, 2.44e-4 short, so every step advances the simulated clock 2.44e-4 too little
//! and a body moving at speed `v` falls behind by `v × t × 2.44e-4` (7.3 mm after 10 s at 3
//! units/s), before any collision is computed. `cargo run --release --example drift` measures
//! both shares for a ball thrown across a 200 × 200 floor under gravity (landing, then
//! sliding; 60 steps a second): *constants* is an exact (`f64`) run with the time step, gravity
//! and throw rounded to the scalar, against the exact run; *arithmetic* is the scalar's own
//! run against that rounded-constants run. Distances in units; this machine printed:
//!
//! | scalar | dt's relative rounding | constants 1 s | arithmetic 1 s | constants 10 s | arithmetic 10 s | constants 60 s | arithmetic 60 s |
//! |---|---|---|---|---|---|---|---|
//! | f32 | 5.22e-8 | 2.5e-7 | 1.1e-4 | 2.5e-6 | 6.6e-4 | 1.5e-5 | 2.1e-3 |
//! | I32F32 | 3.73e-9 | 1.1e-8 | 7.3e-9 | 1.1e-7 | 6.3e-8 | 6.7e-7 | 3.7e-7 |
//! | I16F16 | 2.44e-4 | 7.3e-4 | 4.8e-4 | 7.3e-3 | 4.1e-3 | 4.4e-2 | 2.5e-2 |
//!
//! Both shares grow about linearly with time. In `I16F16` the constants are the larger share
//! throughout; `f32`'s arithmetic share (positions near 100 round to 7.6e-6, and its skin differs
//! from `f64`'s by the heights' rounding) dwarfs its constants'. To keep the constants' share
//! out, pick a time step the scalar holds exactly (`1/64` s in any scalar here) or compare runs
//! against a reference that uses the same rounded constants; `tests/plan.rs` checks the
//! `speed × time × rounding of dt` figure against a run.

use crate::Scalar;
use fixed::types::{I16F16, I32F32};

mod memory;
mod sizes;

pub use memory::Memory;
pub use sizes::Sizes;

/// The four scalar types, as a value: what a [`Verdict`] selects.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ScalarType {
    /// [`I16F16`]: 16 integer and 16 fractional bits.
    I16F16,
    /// `f32`.
    F32,
    /// [`I32F32`]: 32 integer and 32 fractional bits.
    I32F32,
    /// `f64`.
    F64,
}

impl ScalarType {
    /// The four, cheapest first (as [`plan`] orders its verdicts).
    pub const ALL: [ScalarType; 4] = [
        ScalarType::I16F16,
        ScalarType::F32,
        ScalarType::I32F32,
        ScalarType::F64,
    ];

    /// The type's name as Rust spells it.
    pub const fn name(self) -> &'static str {
        match self {
            ScalarType::I16F16 => "I16F16",
            ScalarType::F32 => "f32",
            ScalarType::I32F32 => "I32F32",
            ScalarType::F64 => "f64",
        }
    }

    /// What the planner knows of it.
    pub const fn precision(self) -> Precision {
        match self {
            ScalarType::I16F16 => I16F16::PRECISION,
            ScalarType::F32 => f32::PRECISION,
            ScalarType::I32F32 => I32F32::PRECISION,
            ScalarType::F64 => f64::PRECISION,
        }
    }

    /// The type a [`Scalar`] implementation names itself by (set once, where each implements
    /// the trait).
    pub(crate) const fn named(name: &str) -> Self {
        match name.as_bytes() {
            b"I16F16" => ScalarType::I16F16,
            b"f32" => ScalarType::F32,
            b"I32F32" => ScalarType::I32F32,
            _ => ScalarType::F64,
        }
    }
}

impl core::fmt::Display for ScalarType {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

/// What the planner knows of a scalar type: its safe range and how it rounds.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Precision {
    /// The type.
    pub scalar: ScalarType,
    /// [`Scalar::LIMIT`] as `f64`.
    pub limit: f64,
    /// [`Scalar::EPSILON`] as `f64`: the spacing of values near one.
    pub epsilon: f64,
    /// Whether rounding is relative to magnitude (floats) or one absolute step (fixed-point).
    pub relative: bool,
}

impl Precision {
    /// Whether coordinates within `±extent` and radii up to `radius` are inside the safe range,
    /// so that nothing can overflow. Both are magnitudes: a negative or NaN one fits nothing.
    pub const fn fits(&self, extent: f64, radius: f64) -> bool {
        extent >= 0.0 && extent <= self.limit && radius >= 0.0 && radius <= self.limit
    }

    /// The largest error expected of a contact's position along the normal, for coordinates
    /// within `±extent` and paths up to `path` long: half a step of alpha over the path (alpha is
    /// reported in the scalar), plus the rounding of the contact tests: eight steps of `extent`
    /// for floats (twice [`height_error`](Self::height_error): an edge or vertex contact is
    /// solved from the ball's offset from a corner, up to three times `extent` long; six steps
    /// were seen), eight absolute steps for fixed-point (bounds fitted to, and tested against,
    /// the measured errors).
    ///
    /// ```
    /// use ballcast::Scalar;
    /// use fixed::types::I16F16;
    /// // A 100-unit room with 10-unit moves: I16F16 contacts land within ~2e-4.
    /// let e = I16F16::PRECISION.distance_error(100.0, 10.0);
    /// assert!(e > 1e-4 && e < 3e-4);
    /// ```
    pub const fn distance_error(&self, extent: f64, path: f64) -> f64 {
        self.distance_error_within(extent, extent, path)
    }

    /// [`distance_error`](Self::distance_error) where a contact's points (the triangle and
    /// the path's ends) lie within `span` of each other on every axis ([`Sizes::span`]): a
    /// float rounds its contact tests at the offsets between those points, so the tests' share
    /// is eight steps of the smaller of `span` and `extent`. Fixed point: as
    /// `distance_error`.
    ///
    /// ```
    /// use ballcast::Scalar;
    /// // Triangles and moves a few units across, 5 000 units out: f32 rounds at their size.
    /// let far = f32::PRECISION.distance_error(5000.0, 2.0);
    /// let near = f32::PRECISION.distance_error_within(5000.0, 5.0, 2.0);
    /// assert!(far > 4e-3 && near < 6e-6);
    /// ```
    pub const fn distance_error_within(&self, extent: f64, span: f64, path: f64) -> f64 {
        let within = if self.relative && span < extent {
            span
        } else {
            extent
        };
        self.epsilon / 2.0 * path + self.position_error(within)
    }

    /// The largest error expected of a contact's position (`Hit::position`) along the normal,
    /// for coordinates within `±extent`: the rounding of the heights, since the position is
    /// formed from alpha before alpha is rounded. For floats an edge or vertex contact adds
    /// the rounding of its chord and quotient, in proportion to its offset from a corner (up
    /// to 4.3 steps of the spacing at `extent` were seen over 10^6 casts at scale 10, 7 on a
    /// sweep from a corner of the extent): eight steps.
    ///
    /// Where two features meet the ball within [`distance_error`](Self::distance_error) of each
    /// other (two edges, an edge and the face), rounding may pick either, and the position is
    /// the one picked: then its error along the exact contact's normal is bounded by
    /// `distance_error` alone. Through a scene or mesh, of triangles whose contacts' alphas
    /// round alike the one whose position comes first along the path is reported, so a
    /// second triangle a step of alpha behind adds nothing (two floors a fraction of a step
    /// apart, a ball falling 1 000 onto them: within this bound in every scalar).
    ///
    /// ```
    /// use ballcast::Scalar;
    /// use fixed::types::I16F16;
    /// // Eight steps of 2^-16 anywhere in I16F16's range, whatever the path's length.
    /// assert_eq!(I16F16::PRECISION.position_error(100.0), 8.0 / 65536.0);
    /// assert_eq!(f32::PRECISION.position_error(100.0), 800.0 * f32::EPSILON as f64);
    /// ```
    pub const fn position_error(&self, extent: f64) -> f64 {
        if self.relative {
            2.0 * self.height_error(extent)
        } else {
            self.height_error(extent)
        }
    }

    /// [`position_error`](Self::position_error) where a contact's points lie within `span` of
    /// each other on every axis ([`Sizes::span`]): for floats the contact tests' eight steps
    /// of the smaller of `span` and `extent`, plus the position's own rounding to the scalar
    /// at `extent` (half a step per coordinate: along a unit normal at most one step of
    /// `extent`), and never more than `position_error`. Fixed point: as `position_error`.
    pub const fn position_error_within(&self, extent: f64, span: f64) -> f64 {
        let whole = self.position_error(extent);
        // A NaN span leaves the figure as it is.
        if self.relative && span < extent {
            let near = self.position_error(span) + self.epsilon * extent;
            if near < whole {
                return near;
            }
        }
        whole
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
    /// Whether the scene fits the safe range. The radius is checked against the range only:
    /// [`move_and_slide`](crate::move_and_slide) also refuses a ball below `min_radius` (as
    /// [`choose`] does).
    pub fits: bool,
    /// Expected largest contact error along the normal (meaningful only if `fits`).
    pub distance_error: f64,
    /// Expected largest error of the contact's position along the normal.
    pub position_error: f64,
    /// The smallest radius [`move_and_slide`](crate::move_and_slide) (and the [`Slider`](crate::Slider)
    /// and [`Character`](crate::slide::Character) built on it) accepts at the extent; a single
    /// cast takes any radius, but the error figures assume at least this one (smaller balls'
    /// edge and vertex contacts round by more than the ball).
    pub min_radius: f64,
}

/// Every scalar's verdict for a scene with coordinates within `±extent`, radii up to `radius`
/// and sweeps up to `path` long, cheapest first on a core without a floating-point unit (a
/// Cortex-M0): `I16F16`, `f32`, `I32F32`, `f64`. Elsewhere the order differs: on a PC or a
/// Cortex-M4F an `f32` query costs less than an `I16F16` one, and on a PC `f64` less than
/// `I32F32` (README, *Speed*); choose from these verdicts by your target's costs there.
///
/// The triangles are taken as large as the level: for floats, whose contact tests round at
/// the size of a contact's offsets, [`Sizes::with_triangles`] gives far smaller figures on a
/// level of small triangles far from the origin.
///
/// ```
/// use ballcast::plan;
/// // A 10 km world does not fit I16F16; f32 keeps contacts within ~1 cm there.
/// let [i16, f32, ..] = plan(10_000.0, 1.0, 20.0);
/// assert!(!i16.fits && f32.fits && f32.distance_error < 1e-2);
/// ```
pub const fn plan(extent: f64, radius: f64, path: f64) -> [Verdict; 4] {
    Sizes::new(extent, radius, path).plan()
}

/// The first scalar in [`plan`]'s order (the cheapest on a core without a floating-point
/// unit) that fits a scene with coordinates within
/// `±extent`, radii up to `radius` and sweeps up to `path` long, accepts that radius in
/// [`move_and_slide`](crate::move_and_slide), and keeps a contact's expected error along the
/// normal within `tolerance`; `None` if no scalar does. [`Sizes::choose`] takes the
/// triangles' size into account too.
pub const fn choose(extent: f64, radius: f64, path: f64, tolerance: f64) -> Option<Verdict> {
    Sizes::new(extent, radius, path).choose(tolerance)
}

impl Verdict {
    /// The verdict on one scalar for a scene as in [`plan`]; it does not fit where `extent`,
    /// `radius` or `path` is negative or NaN (each is a magnitude).
    pub const fn of(precision: Precision, extent: f64, radius: f64, path: f64) -> Self {
        Self::of_sizes(precision, Sizes::new(extent, radius, path))
    }

    /// The verdict on one scalar for a level of these [`Sizes`]; it does not fit where one of
    /// them is negative or NaN.
    pub const fn of_sizes(precision: Precision, sizes: Sizes) -> Self {
        let Sizes {
            extent,
            radius,
            path,
            triangle,
        } = sizes;
        let span = sizes.span();
        Self {
            precision,
            fits: precision.fits(extent, radius) && path >= 0.0 && triangle >= 0.0,
            distance_error: precision.distance_error_within(extent, span, path),
            position_error: precision.position_error_within(extent, span),
            min_radius: precision.min_radius(extent),
        }
    }
}
