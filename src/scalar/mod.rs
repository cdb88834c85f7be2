//! The [`Scalar`] trait and its four implementations: `f32`, `f64`, `I16F16` and `I32F32`.
//!
//! Everything an algorithm needs to know about a number type lives here, so the algorithms are
//! written once. Two families implement it: IEEE floats (libm square root, unit
//! vectors in the same type) and fixed-point (exact integer square root,
//! unit vectors with more fractional bits than the coordinates, products taken into a
//! double-width integer before rounding once).
//!
//! Rounding is decided here, not by operators. The trait has no `*` or `/`: the fixed-point
//! types' operators round towards −∞ (`*`) or zero (`/`), a bias that feeds back into positions
//! step after step (a ball resting on a tilted floor creeps downhill). Every product, quotient,
//! dot product and square root the algorithms form goes through a kernel that rounds to
//! nearest, with ties away from zero for fixed-point, so results mirror with their inputs'
//! signs, and ties to even for floats (IEEE).

mod fixed;
mod float;
mod isqrt;
mod narrow;
mod wide;

pub(crate) use isqrt::isqrt_nearest_64;
pub(crate) use wide::{LeadingZeros, wide_mul_i32, wide_mul_u32};

use crate::vec3::Vec3;
#[cfg(doc)]
use ::fixed::types::{I16F16, I32F32};
use core::cmp::Ordering;
use core::fmt::Debug;
use core::ops::{Add, Neg, Sub};

/// A number type the crate computes in: `f32`, `f64`, [`I16F16`] or [`I32F32`].
///
/// The trait is sealed: its kernels (widening dot products, scale-safe normalisation, exact
/// product comparison) carry preconditions that only the crate's validated types guarantee.
/// What a user needs is public: constants, conversions, `abs`, `sqrt` and the safe range.
///
/// | scalar | `LIMIT` (largest accepted coordinate or radius) | unit-vector components |
/// |---|---|---|
/// | `f32` | 2^24 = 16 777 216 | `f32` |
/// | `f64` | 2^53 | `f64` |
/// | `I16F16` | 4096 | `I2F30` (30 fractional bits) |
/// | `I32F32` | 2^28 = 268 435 456 | `I2F62` (62 fractional bits) |
///
/// ```
/// use ballcast::Scalar;
/// use fixed::types::I16F16;
/// assert_eq!(I16F16::from_f64(1.5).to_f64(), 1.5);
/// assert_eq!(I16F16::LIMIT.to_f64(), 4096.0);
/// // Conversions saturate; NaN maps to the largest value, which every constructor rejects.
/// assert!(I16F16::from_f64(f64::NAN) > I16F16::LIMIT);
/// ```
pub trait Scalar:
    sealed::Kernel
    + Copy
    + Debug
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// Minus one.
    const NEG_ONE: Self;
    /// The largest magnitude accepted for a world coordinate or a radius.
    ///
    /// Inside this range no intermediate value of any algorithm can overflow: differences of two
    /// points stay below `2 * LIMIT` per component, coordinates in a triangle's standard frame
    /// below `3.5 * LIMIT`, and differences of those below `7 * LIMIT`, all representable.
    const LIMIT: Self;
    /// The spacing of representable values near one (machine epsilon; one LSB for fixed-point).
    const EPSILON: Self;
    /// The same facts as plain numbers, for the precision planner ([`crate::plan()`]).
    const PRECISION: crate::Precision;

    /// Converts from `f64`, rounding to nearest. Fixed-point saturates, and maps NaN to the
    /// largest value so that constructors reject it as out of range rather than read it as zero.
    fn from_f64(v: f64) -> Self;
    /// Converts from `f64` as [`from_f64`](Self::from_f64) does for a value within
    /// `±`[`LIMIT`](Self::LIMIT), and refuses any other: [`Error::NaN`](crate::Error::NaN) for
    /// NaN, [`Error::OutOfRange`](crate::Error::OutOfRange) with the value as given (not
    /// saturated) for the rest, both about [`Input::Number`](crate::Input::Number). For numbers
    /// from outside (an input device, a file, a float part of the game) bound for fixed point.
    ///
    /// ```
    /// use ballcast::{Error, Scalar};
    /// use fixed::types::I16F16;
    /// assert_eq!(I16F16::try_from_f64(2.5), Ok(I16F16::from_num(2.5)));
    /// let e = I16F16::try_from_f64(1e9).unwrap_err();
    /// assert_eq!(e.to_string(), "1000000000 is outside the accepted range [-4096, 4096]");
    /// assert!(matches!(I16F16::try_from_f64(f64::NAN), Err(Error::NaN { .. })));
    /// ```
    fn try_from_f64(v: f64) -> Result<Self, crate::Error> {
        crate::check::convert(v)
    }
    /// Converts to `f64`: exact for `f32`, `f64` and `I16F16`; `I32F32` values with more than 53
    /// significant bits round to nearest.
    fn to_f64(self) -> f64;
    /// False for NaN and infinities; fixed-point values are always finite.
    fn is_finite(self) -> bool;
    /// The absolute value (fixed-point saturates at the most negative value).
    fn abs(self) -> Self;
    /// The square root, correctly rounded: to nearest for fixed-point (exact integer square
    /// root) and by libm for floats. Negative inputs give zero for fixed-point and NaN for floats.
    fn sqrt(self) -> Self;
    /// `self * o`, rounded to nearest. Fixed-point: ties away from zero; the product must be
    /// representable (it saturates otherwise, in every build).
    fn mul(self, o: Self) -> Self;
    /// `self / o`, rounded to nearest. Fixed-point: ties away from zero; a zero divisor or a
    /// quotient beyond the type's range saturates (never panics).
    fn div(self, o: Self) -> Self;
}

pub(crate) mod sealed {
    use super::*;

    /// The per-type kernels the algorithms are written against. Preconditions are stated per
    /// method; callers inside the crate meet them through validated types.
    pub trait Kernel: Sized {
        /// The component type of unit vectors (more fractional bits than `Self` for fixed-point).
        type Unit: Copy + Debug + PartialEq + Neg<Output = Self::Unit>;
        /// Zero as a unit-vector component.
        const UNIT_ZERO: Self::Unit;

        /// `d · u` rounded once. Needs components of `d` within `7 * LIMIT` (an offset between
        /// two points of a standard frame), `u` a unit vector (components within ±1) and a
        /// result in range; `I16F16`'s 32-bit path relies on all three.
        fn dot_unit(d: Vec3<Self>, u: Vec3<Self::Unit>) -> Self;
        /// [`dot_unit`](Self::dot_unit) with the unit vector `(u[0], 0, u[1])` of the x–z plane
        /// (an edge's directions in a standard frame), with no product for the zero: the same
        /// number (fixed point: the same bits; a float's zero may differ in sign).
        fn dot_unit_xz(d: Vec3<Self>, u: [Self::Unit; 2]) -> Self;
        /// Orders `a * b` against `c * d`, exactly for fixed-point. Needs operands below `8 * LIMIT`.
        fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering;
        /// `v` scaled by a positive factor so its largest component has magnitude in `[1/2, 1]`;
        /// `None` for the zero vector. Nothing is squared, so nothing can overflow.
        fn scaled(v: Vec3<Self>) -> Option<Vec3<Self::Unit>>;
        /// Normalises a vector whose largest component has magnitude in `[1/2, 1]`.
        fn unit_normalize(s: Vec3<Self::Unit>) -> Vec3<Self::Unit>;
        /// The cross product of two vectors with components in `[-1, 1]`, scaled by a positive
        /// factor (as [`scaled`](Self::scaled)) so its largest component has magnitude in
        /// `[1/2, 1]`, ready for [`unit_normalize`](Self::unit_normalize); or `None` when its
        /// direction is uncertain: the cross product's largest component is below 1024 units of
        /// roundoff of `Unit`, so the direction error would exceed about 1e-3 rad.
        fn scaled_cross(a: Vec3<Self::Unit>, b: Vec3<Self::Unit>) -> Option<Vec3<Self::Unit>>;
        /// `v / 2^k` rounded to nearest (exact for floats short of underflow), `1 <= k < 32`.
        fn div_pow2(v: Self, k: u32) -> Self;
        /// `a · b` rounded once. Needs components within `2 * LIMIT` and a result in range.
        fn dot(a: Vec3<Self>, b: Vec3<Self>) -> Self;
        /// The sign of `a · b`: exact for fixed-point (the sum of the exact products that
        /// [`dot`](Self::dot) rounds, so a product below half a step still counts), that of the
        /// rounded dot product for floats. Needs the products' magnitudes to sum to within
        /// `128 * LIMIT²`, the wide type's room (e.g. each within `4 * LIMIT²`: both
        /// components within `2 * LIMIT`, or one within `LIMIT` and the other `4 * LIMIT`).
        fn dot_sign(a: Vec3<Self>, b: Vec3<Self>) -> Ordering;
        /// A bound on the rounding of a height (a coordinate in a triangle's frame) for points
        /// within `±m`: four steps of the spacing at `m` for floats, eight steps for fixed-point
        /// (the planner's model, [`crate::Precision::distance_error`]). Needs `m` within `4 * LIMIT`.
        fn height_error(m: Self) -> Self;
        /// `s * u` rounded once.
        fn mul_unit(s: Self, u: Self::Unit) -> Self;
        /// `a * n / d`, the fixed-point product taken exactly and rounded once (floats: two IEEE
        /// operations). Needs `|n| <= |d|`; zero for `d == 0`.
        fn mul_div(a: Self, n: Self, d: Self) -> Self;
        /// [`mul_div`](Self::mul_div) of every component of `v` by the same fraction `n / d`:
        /// the same numbers, for a core that can share the work of the three divisions. Needs
        /// `q == n.div(d)`, the fraction as already rounded, whose division a core may reuse.
        fn scale_fraction(v: Vec3<Self>, n: Self, d: Self, q: Self) -> Vec3<Self>;
        /// The length of `v` and its unit direction; `None` for the zero vector. Within the
        /// tolerance table for components within `8 * LIMIT`; any finite `v` is valid (fixed
        /// point: the length is the exact integer square root of the exact sum of squares,
        /// rounded to nearest, and saturates at the type's largest value).
        fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<Self::Unit>)>;
        /// The x component of [`direction`](Self::direction)'s unit vector for `(−len, 0, 0)`,
        /// whose other components are zero and whose length is `len`: the same numbers with no
        /// square root. Needs `0 < len <= 4 * LIMIT`.
        fn direction_neg_x(len: Self) -> Self::Unit;
        /// `sqrt(r² - |c|²)`, the half chord at distance `|c|` from a sphere's centre, or `None`
        /// when `|c| > r`. Needs `r` within `LIMIT` and `c` within `8 * LIMIT`; fixed-point
        /// forms the squares exactly in the wide type.
        fn chord(r: Self, c: Vec3<Self>) -> Option<Self>;
        /// Whether `|c| > r`, with no square root: exactly for fixed-point (the squares in the
        /// wide type), by the rounded squares for floats. Needs `r` within `2 * LIMIT`.
        fn beyond(r: Self, c: Vec3<Self>) -> bool;
        /// Whether the line through `q` along `d` certainly passes farther than `r` from the
        /// origin: `|q × d| > (r + margin) |d|`, decided with a few products and no square root,
        /// `|d|` bounded above by `max + min / 2` of its components. `q` and `d` are two
        /// coordinates of an offset from a feature and of a path; `extent` is at least the largest
        /// magnitude of the offset's components (all three, when `q` is a projection). The
        /// margin exceeds the rounding of [`direction`](Self::direction) and of the cross
        /// product taken with its result, so when this is true [`chord`](Self::chord) of that
        /// cross product is `None`; false when unsure (tiny float paths). Needs `q`, `d` within
        /// `8 * LIMIT` and `r` within `LIMIT`.
        fn line_misses(q: [Self; 2], d: [Self; 2], r: Self, extent: Self) -> bool;
        /// A unit-vector component rounded to `Self`.
        fn unit_to_scalar(u: Self::Unit) -> Self;
        /// A unit-vector component as `f64` (exact for `f32`, `f64` and `I2F30`; `I2F62`
        /// rounded to nearest).
        fn unit_to_f64(u: Self::Unit) -> f64;
        /// The integer `n`, saturated at the range (exact for fixed-point within it, and for
        /// floats up to their mantissa): a grid index, with no float conversion and no panic.
        fn from_int(n: i32) -> Self;
        /// For fixed point, the value's bits and its fractional bits (the value is
        /// `bits / 2^frac`); `None` for floats.
        fn fixed_bits(self) -> Option<(i64, u32)>;
    }
}

/// Whether `f64` arithmetic is done by hardware on this target (x86 with SSE2, AArch64, wasm32)
/// rather than by library calls, as on the Cortex-M: where to prefer a float path that gives the
/// same result as an integer one.
const HARDWARE_F64: bool = cfg!(any(
    target_feature = "sse2",
    all(target_arch = "aarch64", target_feature = "neon"),
    target_arch = "wasm32"
));

/// Four steps of the scalar's resolution: contacts whose alphas differ by no more are taken to
/// arrive together (their order is rounding).
pub(crate) fn tie<S: Scalar>() -> S {
    S::EPSILON + S::EPSILON + S::EPSILON + S::EPSILON
}

/// The largest of three values: with magnitudes, a vector length that needs no squaring.
/// Plain comparisons (for floats, a NaN after the first value is passed over).
pub(crate) fn largest<T: PartialOrd + Copy>(a: T, b: T, c: T) -> T {
    let ab = if b > a { b } else { a };
    if c > ab { c } else { ab }
}

/// The smallest of three values, as [`largest`]: cheaper than `f64::min`, which handles NaN in
/// either place, where the values are known not to be NaN.
pub(crate) fn smallest<T: PartialOrd + Copy>(a: T, b: T, c: T) -> T {
    let ab = if b < a { b } else { a };
    if c < ab { c } else { ab }
}

#[cfg(test)]
mod tests;
