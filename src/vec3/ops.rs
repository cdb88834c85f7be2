//! [`Vec3`]'s operators: component-wise `+`, `-` and `-v` in the component type's own
//! arithmetic; `v * s`, `s * v`, `v * w` and `v / s` rounded to nearest through the scalar.

use super::Vec3;
use crate::Scalar;
use core::fmt;
use core::iter::Sum;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};
use fixed::types::{I16F16, I32F32};

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

impl<T: Add<Output = T> + Copy> AddAssign for Vec3<T> {
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl<T: Sub<Output = T> + Copy> SubAssign for Vec3<T> {
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}

impl<T: Neg<Output = T>> Neg for Vec3<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

/// Scaling rounds to nearest in every scalar (see [`Vec3::scale`]).
impl<S: Scalar> Mul<S> for Vec3<S> {
    type Output = Self;
    fn mul(self, s: S) -> Self {
        self.scale(s)
    }
}

/// `v *= s` is `v = v * s`.
impl<S: Scalar> MulAssign<S> for Vec3<S> {
    fn mul_assign(&mut self, s: S) {
        *self = self.scale(s);
    }
}

/// `v /= s` is `v = v / s`.
impl<S: Scalar> DivAssign<S> for Vec3<S> {
    fn div_assign(&mut self, s: S) {
        *self = *self / s;
    }
}

/// Division rounds to nearest in every scalar ([`Scalar::div`]); fixed-point saturates where a
/// quotient leaves the type's range or the divisor is zero.
impl<S: Scalar> Div<S> for Vec3<S> {
    type Output = Self;
    fn div(self, s: S) -> Self {
        self.map(|c| c.div(s))
    }
}

/// Component by component, each product rounded to nearest through the scalar (glam's `v * w`).
impl<S: Scalar> Mul for Vec3<S> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self::new(self.x.mul(o.x), self.y.mul(o.y), self.z.mul(o.z))
    }
}

/// `s * v` is `v * s` ([`Vec3::scale`]), for each scalar type (`dt * velocity`).
macro_rules! scalar_times_vector {
    ($($t:ty),*) => {$(
        impl Mul<Vec3<$t>> for $t {
            type Output = Vec3<$t>;
            fn mul(self, v: Vec3<$t>) -> Vec3<$t> {
                v.scale(self)
            }
        }
    )*};
}
scalar_times_vector!(f32, f64, I16F16, I32F32);

/// The sum of the vectors, from zero, with `+` (see [`Vec3`] on overflow).
impl<S: Scalar> Sum for Vec3<S> {
    fn sum<I: Iterator<Item = Self>>(iter: I) -> Self {
        iter.fold(Self::ZERO, |a, b| a + b)
    }
}

/// The sum of the vectors referred to, as for owned ones.
impl<'a, S: Scalar> Sum<&'a Vec3<S>> for Vec3<S> {
    fn sum<I: Iterator<Item = &'a Self>>(iter: I) -> Self {
        iter.fold(Self::ZERO, |a, &b| a + b)
    }
}

/// `[x, y, z]`, each component as its type displays it (glam's form).
impl<T: fmt::Display> fmt::Display for Vec3<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{}, {}, {}]", self.x, self.y, self.z)
    }
}
