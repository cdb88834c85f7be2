//! A three-component vector with public fields, generic over its component type.

use crate::Scalar;
use core::ops::{Add, Mul, Neg, Sub};

/// A point or direction in 3-space: a plain `Copy` struct with no invariant.
///
/// Components are any [`Scalar`](crate::Scalar) (or the scalar's unit-vector component type inside
/// the crate). Arithmetic is component-wise; `v * s` scales by a scalar.
///
/// ```
/// use ballcast::Vec3;
/// let v = Vec3::new(1.0f32, 2.0, 3.0) - Vec3::new(1.0, 1.0, 1.0);
/// assert_eq!(v, Vec3::new(0.0, 1.0, 2.0));
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    pub fn map<U>(self, f: impl Fn(T) -> U) -> Vec3<U> {
        Vec3::new(f(self.x), f(self.y), f(self.z))
    }

    /// The components as an array `[x, y, z]`.
    pub const fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }
}

impl<T: Add<Output = T>> Add for Vec3<T> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<T: Sub<Output = T>> Sub for Vec3<T> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<T: Neg<Output = T>> Neg for Vec3<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<T: Mul<Output = T> + Copy> Mul<T> for Vec3<T> {
    type Output = Self;
    fn mul(self, s: T) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

impl<S: Scalar> Vec3<S> {
    /// Every component times `s`, each rounded to nearest through the scalar
    /// ([`Scalar::mul`]): unlike `*` on fixed-point types, which rounds towards −∞, this has no
    /// bias that could accumulate over many steps.
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
}

impl<T: Mul<Output = T> + Add<Output = T> + Copy> Vec3<T> {
    /// The dot product, in the component type's own arithmetic.
    ///
    /// For fixed-point components the caller must keep the products in range; the crate's own
    /// algorithms use the scalar's widening kernels instead.
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
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
