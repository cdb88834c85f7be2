//! The [`Scalar`] trait and its four implementations: `f32`, `f64`, `I16F16` and `I32F32`.
//!
//! Everything an algorithm needs to know about a number type lives here, so the algorithms are
//! written once. Two families implement it: IEEE floats (libm square root, unit vectors in the
//! same type) and fixed-point (exact integer square root, unit vectors with more fractional bits
//! than the coordinates, products taken into a double-width integer before rounding once).

use crate::vec3::Vec3;
use core::cmp::Ordering;
use core::fmt::Debug;
use core::ops::{Add, Div, Mul, Neg, Sub};
use fixed::types::{I2F30, I2F62, I16F16, I32F32};

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
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
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
    /// Converts to `f64`: exact for `f32`, `f64` and `I16F16`; `I32F32` values with more than 53
    /// significant bits round to nearest.
    fn to_f64(self) -> f64;
    /// False for NaN and infinities; fixed-point values are always finite.
    fn is_finite(self) -> bool;
    /// The absolute value (fixed-point saturates at the most negative value).
    fn abs(self) -> Self;
    /// The square root, rounded down for fixed-point (exact integer square root) and correctly
    /// rounded for floats (libm). Negative inputs give zero for fixed-point and NaN for floats.
    fn sqrt(self) -> Self;
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

        /// `d · u` rounded once. Needs components of `d` within `2 * LIMIT`.
        fn dot_unit(d: Vec3<Self>, u: Vec3<Self::Unit>) -> Self;
        /// Orders `a * b` against `c * d`, exactly for fixed-point. Needs operands below `8 * LIMIT`.
        fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering;
        /// `v` scaled by a positive factor so its largest component has magnitude in `[1/2, 1]`;
        /// `None` for the zero vector. Nothing is squared, so nothing can overflow.
        fn scaled(v: Vec3<Self>) -> Option<Vec3<Self::Unit>>;
        /// Normalises a vector whose largest component has magnitude in `[1/2, 1]`.
        fn unit_normalize(s: Vec3<Self::Unit>) -> Vec3<Self::Unit>;
        /// The normalised cross product of two vectors with components in `[-1, 1]`, or `None`
        /// when its direction is uncertain: the cross product's largest component is below
        /// 1024 units of roundoff of `Unit`, so the direction error would exceed about 1e-3 rad.
        fn unit_cross(a: Vec3<Self::Unit>, b: Vec3<Self::Unit>) -> Option<Vec3<Self::Unit>>;
        /// `n / d` rounded to nearest (floats: IEEE division). Needs `|n| <= |d|`, `d != 0`.
        fn ratio(n: Self, d: Self) -> Self;
        /// `s * u` rounded once.
        fn mul_unit(s: Self, u: Self::Unit) -> Self;
        /// The length of `v` and its unit direction; `None` for the zero vector. Needs
        /// components within `8 * LIMIT` (fixed-point: the length is the exact integer square root
        /// of the exact sum of squares, rounded down).
        fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<Self::Unit>)>;
        /// `sqrt(r² - |c|²)`, the half chord at distance `|c|` from a sphere's centre, or `None`
        /// when `|c| > r`. Needs `r` within `LIMIT` and `c` within `8 * LIMIT`; fixed-point
        /// forms the squares exactly in the wide type.
        fn chord(r: Self, c: Vec3<Self>) -> Option<Self>;
        /// A unit-vector component rounded to `Self`.
        fn unit_to_scalar(u: Self::Unit) -> Self;
    }
}

/// Four steps of the scalar's resolution: contacts whose alphas differ by no more are taken to
/// arrive together (their order is rounding).
pub(crate) fn tie<S: Scalar>() -> S {
    S::EPSILON + S::EPSILON + S::EPSILON + S::EPSILON
}

/// The largest of three values: with magnitudes, a vector length that needs no squaring.
pub(crate) fn largest<T: PartialOrd + Copy>(a: T, b: T, c: T) -> T {
    let ab = if b > a { b } else { a };
    if c > ab { c } else { ab }
}

macro_rules! float_scalar {
    ($t:ty, $sqrt:path, $limit:expr) => {
        impl Scalar for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const LIMIT: Self = $limit;
            const EPSILON: Self = <$t>::EPSILON;
            const PRECISION: crate::Precision = crate::Precision {
                name: stringify!($t),
                limit: $limit,
                epsilon: <$t>::EPSILON as f64,
                relative: true,
            };

            #[inline]

            fn from_f64(v: f64) -> Self {
                v as $t
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }
            #[inline]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
        }

        impl sealed::Kernel for $t {
            type Unit = $t;
            const UNIT_ZERO: $t = 0.0;

            #[inline]

            fn dot_unit(d: Vec3<Self>, u: Vec3<Self>) -> Self {
                d.dot(u)
            }
            #[inline]
            fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering {
                (a * b).partial_cmp(&(c * d)).unwrap_or(Ordering::Equal)
            }
            fn scaled(v: Vec3<Self>) -> Option<Vec3<Self>> {
                let m = largest(v.x.abs(), v.y.abs(), v.z.abs());
                if m.is_nan() || m <= 0.0 {
                    return None;
                }
                Some(v.map(|c| c / m))
            }
            fn unit_normalize(s: Vec3<Self>) -> Vec3<Self> {
                let len = $sqrt(s.dot(s));
                s.map(|c| c / len)
            }
            fn unit_cross(a: Vec3<Self>, b: Vec3<Self>) -> Option<Vec3<Self>> {
                let c = crate::vec3::cross(a, b);
                let m = largest(c.x.abs(), c.y.abs(), c.z.abs());
                if m.is_nan() || m < 1024.0 * <$t>::EPSILON {
                    return None;
                }
                Some(Self::unit_normalize(c.map(|x| x / m)))
            }
            #[inline]
            fn ratio(n: Self, d: Self) -> Self {
                n / d
            }
            #[inline]
            fn mul_unit(s: Self, u: Self) -> Self {
                s * u
            }
            #[inline]
            fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<Self>)> {
                let n2 = v.dot(v);
                // Squares that underflowed cost at most EPSILON of n2 above this threshold.
                if n2 >= <$t>::MIN_POSITIVE / <$t>::EPSILON && n2.is_finite() {
                    let len = $sqrt(n2);
                    return Some((len, v * (1.0 / len)));
                }
                // Tiny vectors (a tiny radius makes tiny contact offsets): scale by the largest
                // component first, dividing, since 1 / m overflows for a subnormal m.
                let m = largest(v.x.abs(), v.y.abs(), v.z.abs());
                if m.is_nan() || m <= 0.0 {
                    return None;
                }
                let s = v.map(|c| c / m);
                let len = $sqrt(s.dot(s));
                Some((m * len, s * (1.0 / len)))
            }
            #[inline]
            fn chord(r: Self, c: Vec3<Self>) -> Option<Self> {
                let k2 = r * r - c.dot(c);
                (k2 >= 0.0).then(|| $sqrt(k2))
            }
            #[inline]
            fn unit_to_scalar(u: Self) -> Self {
                u
            }
        }
    };
}

float_scalar!(f32, libm::sqrtf, 16_777_216.0);
float_scalar!(f64, libm::sqrt, 9_007_199_254_740_992.0);

/// Rounds `v / 2^shift` to nearest (ties up), for `shift >= 1`.
macro_rules! round_shift {
    ($v:expr, $shift:expr) => {
        ($v + (1 << ($shift - 1))) >> $shift
    };
}

macro_rules! fixed_scalar {
    ($t:ty, $unit:ty, $bits:ty, $wide:ty, $uwide:ty, $frac:expr, $ufrac:expr, $limit_int:expr) => {
        impl Scalar for $t {
            const ZERO: Self = <$t>::ZERO;
            const ONE: Self = <$t>::ONE;
            const LIMIT: Self = <$t>::from_bits($limit_int << $frac);
            const EPSILON: Self = <$t>::DELTA;
            const PRECISION: crate::Precision = crate::Precision {
                name: stringify!($t),
                limit: $limit_int as f64,
                epsilon: 1.0 / (1u64 << $frac) as f64,
                relative: false,
            };

            #[inline]

            fn from_f64(v: f64) -> Self {
                if v.is_nan() {
                    <$t>::MAX
                } else {
                    <$t>::saturating_from_num(v)
                }
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self.to_num::<f64>()
            }
            #[inline]
            fn is_finite(self) -> bool {
                true
            }
            #[inline]
            fn abs(self) -> Self {
                self.saturating_abs()
            }
            #[inline]
            fn sqrt(self) -> Self {
                let b = self.to_bits();
                if b <= 0 {
                    return <$t>::ZERO;
                }
                // sqrt(b / 2^F) * 2^F = sqrt(b * 2^F): an integer square root, rounded down.
                let r = ((b as $uwide as u128) << $frac).isqrt();
                <$t>::from_bits(r as $bits)
            }
        }

        impl sealed::Kernel for $t {
            type Unit = $unit;
            const UNIT_ZERO: $unit = <$unit>::ZERO;

            #[inline]

            fn dot_unit(d: Vec3<Self>, u: Vec3<$unit>) -> Self {
                let p = |a: $t, b: $unit| a.to_bits() as $wide * b.to_bits() as $wide;
                let sum = p(d.x, u.x) + p(d.y, u.y) + p(d.z, u.z);
                <$t>::from_bits(round_shift!(sum, $ufrac) as $bits)
            }
            #[inline]
            fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering {
                let ab = a.to_bits() as $wide * b.to_bits() as $wide;
                let cd = c.to_bits() as $wide * d.to_bits() as $wide;
                ab.cmp(&cd)
            }
            fn scaled(v: Vec3<Self>) -> Option<Vec3<$unit>> {
                let b = v.map(|c| c.to_bits() as $wide);
                let m = largest(b.x.unsigned_abs(), b.y.unsigned_abs(), b.z.unsigned_abs());
                if m == 0 {
                    return None;
                }
                // A power-of-two scale is exact: shift the top bit of `m` to `2^(UFRAC-1)`.
                let top = (<$wide>::BITS - 1 - m.leading_zeros()) as i32;
                let k = ($ufrac - 1) - top;
                Some(b.map(|c| {
                    <$unit>::from_bits((if k >= 0 { c << k } else { round_shift!(c, -k) }) as _)
                }))
            }
            fn unit_normalize(s: Vec3<$unit>) -> Vec3<$unit> {
                let w = s.map(|c| c.to_bits() as $wide);
                // Squares carry 2*UFRAC fractional bits; with |s| <= 1 their sum is below 3.
                let len2 = w.x * w.x + w.y * w.y + w.z * w.z;
                // Never zero for the inputs described, but a divisor the compiler cannot prove nonzero
                // would leave a panic path in the binary.
                let len = (len2 as u128).isqrt().max(1) as $wide;
                w.map(|c| {
                    let num = c << $ufrac;
                    let half = if num < 0 { -(len / 2) } else { len / 2 };
                    <$unit>::from_bits(((num + half) / len) as _)
                })
            }
            fn unit_cross(a: Vec3<$unit>, b: Vec3<$unit>) -> Option<Vec3<$unit>> {
                let (a, b) = (
                    a.map(|c| c.to_bits() as $wide),
                    b.map(|c| c.to_bits() as $wide),
                );
                let c = crate::vec3::cross(a, b);
                let m = largest(c.x.unsigned_abs(), c.y.unsigned_abs(), c.z.unsigned_abs());
                // `c` carries 2*UFRAC fractional bits; 1024 units of roundoff is 2^(UFRAC+10).
                if m < (1 << ($ufrac + 10)) {
                    return None;
                }
                let shift = (<$wide>::BITS - m.leading_zeros()) as i32 - $ufrac;
                Some(Self::unit_normalize(
                    c.map(|x| <$unit>::from_bits(round_shift!(x, shift) as _)),
                ))
            }
            #[inline]
            fn ratio(n: Self, d: Self) -> Self {
                // The `/` operator truncates; alpha deserves the nearest value.
                let (n, d) = ((n.to_bits() as $wide) << $frac, d.to_bits() as $wide);
                let (q, r) = (n / d, n % d);
                let away = if (n < 0) == (d < 0) { 1 } else { -1 };
                let q = if 2 * r.unsigned_abs() >= d.unsigned_abs() {
                    q + away
                } else {
                    q
                };
                <$t>::from_bits(q as $bits)
            }
            #[inline]
            fn mul_unit(s: Self, u: $unit) -> Self {
                let p = s.to_bits() as $wide * u.to_bits() as $wide;
                <$t>::from_bits(round_shift!(p, $ufrac) as $bits)
            }
            fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<$unit>)> {
                // Components below 2^(BITS-1) square to below 2^(2 BITS - 2): three fit unsigned.
                let u = v.map(|c| (c.to_bits() as $wide).unsigned_abs());
                let len = (u.x * u.x + u.y * u.y + u.z * u.z).isqrt();
                Some((
                    <$t>::from_bits(len as $bits),
                    Self::unit_normalize(Self::scaled(v)?),
                ))
            }
            fn chord(r: Self, c: Vec3<Self>) -> Option<Self> {
                if c.x.abs() > r || c.y.abs() > r || c.z.abs() > r {
                    return None;
                }
                // Every square is below r² <= LIMIT², exact with 2F fractional bits.
                let sq = |a: $t| (a.to_bits() as $wide) * (a.to_bits() as $wide);
                let k2 = sq(r) - sq(c.x) - sq(c.y) - sq(c.z);
                (k2 >= 0).then(|| <$t>::from_bits(k2.unsigned_abs().isqrt() as $bits))
            }
            #[inline]
            fn unit_to_scalar(u: $unit) -> Self {
                <$t>::from_bits(round_shift!(u.to_bits() as $wide, $ufrac - $frac) as $bits)
            }
        }
    };
}

fixed_scalar!(I16F16, I2F30, i32, i64, u32, 16, 30, 4096);
fixed_scalar!(I32F32, I2F62, i64, i128, u64, 32, 62, 268_435_456);
