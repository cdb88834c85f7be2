//! A three-component vector with public fields, generic over its component type.

use crate::Scalar;
use core::ops::{Add, Mul, Sub};

pub(crate) mod geometry;
mod ops;

/// A point or direction in 3-space: a plain `Copy` struct with no invariant.
///
/// Components are any [`Scalar`] (or the scalar's unit-vector component type inside
/// the crate). Arithmetic is component-wise; `v * s` scales by a scalar.
///
/// Overflow (fixed point only; coordinates within the safe range [`Scalar::LIMIT`] never
/// overflow a sum or difference of two of them): `+`, `-` and unary `-` are the component
/// type's own operators, which, as Rust's integers do, panic in debug builds and wrap in
/// release builds; `*`, `/`, [`dot`](Self::dot), [`cross`](Self::cross) and
/// [`length`](Self::length) round through the scalar and saturate. Check values that may
/// grow without bound (a velocity under gravity) with [`try_cast`](Self::try_cast) or keep
/// them within the range.
///
/// ```
/// use ballcast::Vec3;
/// let v = Vec3::new(1.0f32, 2.0, 3.0) - Vec3::new(1.0, 1.0, 1.0);
/// assert_eq!(v, Vec3::new(0.0, 1.0, 2.0));
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Vec3<T> {
    /// The x component.
    pub x: T,
    /// The y component.
    pub y: T,
    /// The z component.
    pub z: T,
}

impl<T> Vec3<T> {
    /// Builds a vector from its three components.
    pub const fn new(x: T, y: T, z: T) -> Self {
        Self { x, y, z }
    }
}

impl<T: Copy> Vec3<T> {
    /// Applies `f` to every component, e.g. to convert between scalar types.
    ///
    /// ```
    /// use ballcast::{Scalar, Vec3};
    /// let v = Vec3::new(0.5f64, -2.0, 8.0).map(f32::from_f64);
    /// assert_eq!(v, Vec3::new(0.5f32, -2.0, 8.0));
    /// ```
    #[inline]
    pub fn map<U>(self, f: impl Fn(T) -> U) -> Vec3<U> {
        Vec3::new(f(self.x), f(self.y), f(self.z))
    }

    /// The components as an array `[x, y, z]`.
    pub const fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }
}

impl<T> From<[T; 3]> for Vec3<T> {
    fn from([x, y, z]: [T; 3]) -> Self {
        Self::new(x, y, z)
    }
}

impl<T> From<Vec3<T>> for [T; 3] {
    fn from(v: Vec3<T>) -> Self {
        [v.x, v.y, v.z]
    }
}

impl<T> From<(T, T, T)> for Vec3<T> {
    fn from((x, y, z): (T, T, T)) -> Self {
        Self::new(x, y, z)
    }
}

impl<T> From<Vec3<T>> for (T, T, T) {
    fn from(v: Vec3<T>) -> Self {
        (v.x, v.y, v.z)
    }
}

impl<S: Scalar> Vec3<S> {
    /// The zero vector.
    pub const ZERO: Self = Self::new(S::ZERO, S::ZERO, S::ZERO);
    /// The unit vector along x.
    pub const X: Self = Self::new(S::ONE, S::ZERO, S::ZERO);
    /// The unit vector along y (up, in this crate's examples).
    pub const Y: Self = Self::new(S::ZERO, S::ONE, S::ZERO);
    /// The unit vector along z.
    pub const Z: Self = Self::new(S::ZERO, S::ZERO, S::ONE);
    /// Every component one.
    pub const ONE: Self = Self::splat(S::ONE);
    /// The unit vector along −x.
    pub const NEG_X: Self = Self::new(S::NEG_ONE, S::ZERO, S::ZERO);
    /// The unit vector along −y (down, in this crate's examples).
    pub const NEG_Y: Self = Self::new(S::ZERO, S::NEG_ONE, S::ZERO);
    /// The unit vector along −z.
    pub const NEG_Z: Self = Self::new(S::ZERO, S::ZERO, S::NEG_ONE);

    /// A vector with every component `s`.
    pub const fn splat(s: S) -> Self {
        Self::new(s, s, s)
    }

    /// The smaller of each pair of components (a NaN in `o` is passed over: `self`'s is kept).
    pub fn min(self, o: Self) -> Self {
        let m = |a: S, b: S| if b < a { b } else { a };
        Self::new(m(self.x, o.x), m(self.y, o.y), m(self.z, o.z))
    }

    /// The larger of each pair of components (a NaN in `o` is passed over: `self`'s is kept).
    pub fn max(self, o: Self) -> Self {
        let m = |a: S, b: S| if b > a { b } else { a };
        Self::new(m(self.x, o.x), m(self.y, o.y), m(self.z, o.z))
    }

    /// Every component's magnitude (fixed point: the type's own `abs`, which overflows at its
    /// most negative value, far outside the safe range).
    #[inline]
    pub fn abs(self) -> Self {
        Self::new(self.x.abs(), self.y.abs(), self.z.abs())
    }

    /// The largest component (a NaN after `x` is passed over). With [`abs`](Self::abs), the
    /// largest coordinate magnitude: the size this crate measures extents and roundings by.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// assert_eq!(Vec3::new(1.0f32, -4.0, 3.0).abs().max_element(), 4.0);
    /// ```
    #[inline]
    pub fn max_element(self) -> S {
        crate::scalar::largest(self.x, self.y, self.z)
    }

    /// The smallest component (a NaN after `x` is passed over).
    pub fn min_element(self) -> S {
        crate::scalar::smallest(self.x, self.y, self.z)
    }

    /// `x + y + z`, with `+` (see the type's docs on overflow).
    pub fn element_sum(self) -> S {
        self.x + self.y + self.z
    }

    /// The same vector with `x` replaced.
    pub const fn with_x(self, x: S) -> Self {
        Self::new(x, self.y, self.z)
    }

    /// The same vector with `y` replaced (a velocity's vertical part, with `up` along y).
    pub const fn with_y(self, y: S) -> Self {
        Self::new(self.x, y, self.z)
    }

    /// The same vector with `z` replaced.
    pub const fn with_z(self, z: S) -> Self {
        Self::new(self.x, self.y, z)
    }

    /// The squared length: [`dot`](Self::dot) with itself (fixed point saturates beyond the
    /// type's range: in `I16F16` from a length of about 181; [`length`](Self::length) does not).
    pub fn length_squared(self) -> S {
        S::dot(self, self)
    }

    /// Every component times `s`, each rounded to nearest through the scalar
    /// ([`Scalar::mul`]): unlike `*` on fixed-point types, which rounds towards −∞, this has no
    /// bias that could accumulate over many steps. The same as `self * s`.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// use fixed::types::I16F16;
    /// let tiny = I16F16::from_bits(1); // 2^-16
    /// let v = Vec3::new(tiny, -tiny, tiny).scale(I16F16::from_num(0.5));
    /// // Half a step rounds away from zero in both directions, symmetrically.
    /// assert_eq!(v, Vec3::new(tiny, -tiny, tiny));
    /// ```
    pub fn scale(self, s: S) -> Self {
        self.map(|c| c.mul(s))
    }

    /// The dot product, rounded once: fixed-point sums the exact products in a double-width
    /// integer, so nothing overflows until the result itself leaves the type's range (it then
    /// saturates).
    ///
    /// ```
    /// use ballcast::Vec3;
    /// use fixed::types::I16F16;
    /// let big = Vec3::new(I16F16::from_num(100), I16F16::from_num(100), I16F16::ZERO);
    /// let small = Vec3::new(I16F16::from_num(0.01), I16F16::from_num(-0.01), I16F16::ZERO);
    /// // 100 × 100 alone overflows I16F16; the sum of the two products does not.
    /// assert_eq!(big.dot(Vec3::new(big.x, -big.y, big.z)), I16F16::ZERO);
    /// assert!(big.dot(small).abs() < I16F16::from_num(1e-3));
    /// ```
    pub fn dot(self, o: Self) -> S {
        S::dot(self, o)
    }

    /// The cross product, each component a two-term dot product rounded once (fixed-point
    /// saturates where a component leaves the type's range).
    ///
    /// ```
    /// use ballcast::Vec3;
    /// let (x, y) = (Vec3::new(1.0f32, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    /// assert_eq!(x.cross(y), Vec3::new(0.0, 0.0, 1.0));
    /// ```
    pub fn cross(self, o: Self) -> Self {
        let (a, b, z) = (self, o, S::ZERO);
        let d = |p: S, q: S, r: S, s: S| S::dot(Vec3::new(p, -q, z), Vec3::new(r, s, z));
        Vec3::new(
            d(a.y, a.z, b.z, b.y),
            d(a.z, a.x, b.x, b.z),
            d(a.x, a.y, b.y, b.x),
        )
    }

    /// The length, without overflow or underflow for any finite vector (fixed-point: the exact
    /// integer square root of the exact sum of squares, rounded to nearest; it saturates beyond
    /// the type's range).
    ///
    /// ```
    /// use ballcast::Vec3;
    /// assert_eq!(Vec3::new(3.0f64, 4.0, 12.0).length(), 13.0);
    /// assert_eq!(Vec3::new(3e30f32, 4e30, 0.0).length(), 5e30); // no overflow in the squares
    /// ```
    pub fn length(self) -> S {
        if !self.is_finite() {
            // Infinity, or NaN if any component is NaN.
            return self.x.abs() + self.y.abs() + self.z.abs();
        }
        S::direction(self).map_or(S::ZERO, |(len, _)| len)
    }

    /// The unit vector in this direction, or `None` for the zero vector and non-finite ones.
    ///
    /// ```
    /// use ballcast::Vec3;
    /// assert_eq!(Vec3::new(0.0f32, -2.0, 0.0).try_normalize(), Some(Vec3::new(0.0, -1.0, 0.0)));
    /// assert_eq!(Vec3::<f32>::ZERO.try_normalize(), None);
    /// ```
    pub fn try_normalize(self) -> Option<Self> {
        if !self.is_finite() {
            return None;
        }
        crate::contact::unit(self)
    }

    /// The unit vector in this direction, or zero where [`try_normalize`](Self::try_normalize)
    /// gives `None`.
    pub fn normalize_or_zero(self) -> Self {
        self.try_normalize().unwrap_or(Self::ZERO)
    }

    /// Whether every component is finite (always, for fixed-point).
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// The same vector in another scalar, each component rounded to nearest through `f64`
    /// ([`Scalar::from_f64`]: fixed-point saturates, NaN becomes out of range; an error made
    /// later then shows the saturated value: [`try_cast`](Self::try_cast) refuses instead).
    ///
    /// ```
    /// use ballcast::Vec3;
    /// use fixed::types::I16F16;
    /// let v = Vec3::new(0.5f32, -2.25, 8.0).cast::<I16F16>();
    /// assert_eq!(v, Vec3::new(I16F16::from_num(0.5), I16F16::from_num(-2.25), I16F16::from_num(8)));
    /// ```
    pub fn cast<T: Scalar>(self) -> Vec3<T> {
        self.map(|c| T::from_f64(c.to_f64()))
    }

    /// [`cast`](Self::cast), refusing a component that `T` cannot hold within its safe range
    /// rather than saturating it, so the error carries the value given.
    ///
    /// Errors: [`Error::NaN`](crate::Error::NaN); [`Error::OutOfRange`](crate::Error::OutOfRange)
    /// with the component's value and `T`'s range.
    ///
    /// ```
    /// use ballcast::{Error, Vec3};
    /// use fixed::types::I16F16;
    /// let far = Vec3::new(0.0f32, 5000.0, 0.0).try_cast::<I16F16>().unwrap_err();
    /// assert!(matches!(far, Error::OutOfRange { value: 5000.0, .. }));
    /// assert_eq!(far.to_string(), "5000 is outside the accepted range [-4096, 4096]");
    /// ```
    pub fn try_cast<T: Scalar>(self) -> Result<Vec3<T>, crate::Error> {
        let c = |x: S| crate::check::convert::<T>(x.to_f64());
        Ok(Vec3::new(c(self.x)?, c(self.y)?, c(self.z)?))
    }
}

/// The dot product in the component type's own arithmetic, for the float kernels.
pub(crate) fn dot3<T: Mul<Output = T> + Add<Output = T> + Copy>(a: Vec3<T>, b: Vec3<T>) -> T {
    a.x * b.x + a.y * b.y + a.z * b.z
}

/// The cross product `a × b`, in the component type's own arithmetic.
pub(crate) fn cross<T: Mul<Output = T> + Sub<Output = T> + Copy>(
    a: Vec3<T>,
    b: Vec3<T>,
) -> Vec3<T> {
    Vec3::new(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
    )
}
