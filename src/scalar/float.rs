//! The IEEE float implementations: libm's correctly rounded square root, unit vectors in the
//! same type, every operation one IEEE basic operation rounded to nearest (ties to even).

use super::sealed::Kernel;
use super::{Scalar, largest};
use crate::vec3::Vec3;
use core::cmp::Ordering;

macro_rules! float_scalar {
    ($t:ty, $sqrt:path, $limit:expr, $tiny:ident) => {
        /// `direction` of a tiny vector (a tiny radius makes tiny contact offsets): scaled by
        /// its largest component first, dividing, since 1 / m overflows for a subnormal m. Out
        /// of line and cold, so the common path is not made to compute it speculatively.
        #[cold]
        #[inline(never)]
        fn $tiny(v: Vec3<$t>) -> Option<($t, Vec3<$t>)> {
            let m = v.abs().max_element();
            if m.is_nan() || m <= 0.0 {
                return None;
            }
            let s = v.map(|c| c / m);
            let len = $sqrt(crate::vec3::dot3(s, s));
            Some((m * len, s * (1.0 / len)))
        }

        impl Scalar for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const NEG_ONE: Self = -1.0;
            const LIMIT: Self = $limit;
            const EPSILON: Self = <$t>::EPSILON;
            const PRECISION: crate::Precision = crate::Precision {
                scalar: crate::plan::ScalarType::named(stringify!($t)),
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
            #[inline]
            fn mul(self, o: Self) -> Self {
                self * o
            }
            #[inline]
            fn div(self, o: Self) -> Self {
                self / o
            }
        }

        impl Kernel for $t {
            type Unit = $t;
            const UNIT_ZERO: $t = 0.0;

            #[inline]
            fn dot_unit(d: Vec3<Self>, u: Vec3<Self>) -> Self {
                crate::vec3::dot3(d, u)
            }
            #[inline]
            fn dot_unit_xz(d: Vec3<Self>, [ux, uz]: [Self; 2]) -> Self {
                d.x * ux + d.z * uz
            }
            #[inline]
            fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering {
                (a * b).partial_cmp(&(c * d)).unwrap_or(Ordering::Equal)
            }
            #[inline]
            fn scaled(v: Vec3<Self>) -> Option<Vec3<Self>> {
                let m = v.abs().max_element();
                if m.is_nan() || m <= 0.0 {
                    return None;
                }
                Some(v.map(|c| c / m))
            }
            #[inline]
            fn unit_normalize(s: Vec3<Self>) -> Vec3<Self> {
                let len = $sqrt(crate::vec3::dot3(s, s));
                s.map(|c| c / len)
            }
            #[inline(always)]
            fn scaled_cross(a: Vec3<Self>, b: Vec3<Self>) -> Option<Vec3<Self>> {
                let c = crate::vec3::cross(a, b);
                let m = c.abs().max_element();
                if m.is_nan() || m < 1024.0 * <$t>::EPSILON {
                    return None;
                }
                Some(c.map(|x| x / m))
            }
            #[inline]
            fn mul_div(a: Self, n: Self, d: Self) -> Self {
                if d == 0.0 { 0.0 } else { a * n / d }
            }
            #[inline]
            fn scale_fraction(v: Vec3<Self>, n: Self, d: Self, _: Self) -> Vec3<Self> {
                v.map(|c| Self::mul_div(c, n, d))
            }
            #[inline]
            fn div_pow2(v: Self, k: u32) -> Self {
                v / (1u64 << k) as $t
            }
            #[inline]
            fn dot(a: Vec3<Self>, b: Vec3<Self>) -> Self {
                crate::vec3::dot3(a, b)
            }
            #[inline]
            fn dot_sign(a: Vec3<Self>, b: Vec3<Self>) -> Ordering {
                crate::vec3::dot3(a, b)
                    .partial_cmp(&0.0)
                    .unwrap_or(Ordering::Equal)
            }
            #[inline]
            fn height_error(m: Self) -> Self {
                let m = if m > 1.0 { m } else { 1.0 };
                4.0 * <$t>::EPSILON * m
            }
            #[inline]
            fn mul_unit(s: Self, u: Self) -> Self {
                s * u
            }
            #[inline]
            fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<Self>)> {
                let n2 = crate::vec3::dot3(v, v);
                // Squares that underflowed cost at most EPSILON of n2 above this threshold.
                if n2 >= <$t>::MIN_POSITIVE / <$t>::EPSILON && n2.is_finite() {
                    let len = $sqrt(n2);
                    return Some((len, v * (1.0 / len)));
                }
                $tiny(v)
            }
            #[inline]
            fn direction_neg_x(len: Self) -> Self {
                // `direction`'s two paths. On the first, sqrt(len²) is len: the square root of a
                // float's square rounded to nearest is the float itself in radix 2 short of
                // underflow (Boldo, "Stupid is as stupid does: taking the square root of the
                // square of a floating-point number", 2015). The second scales by len first.
                let n2 = len * len;
                if n2 >= <$t>::MIN_POSITIVE / <$t>::EPSILON && n2.is_finite() {
                    -(len * (1.0 / len))
                } else {
                    -1.0
                }
            }
            #[inline]
            fn chord(r: Self, c: Vec3<Self>) -> Option<Self> {
                let k2 = r * r - crate::vec3::dot3(c, c);
                (k2 >= 0.0).then(|| $sqrt(k2))
            }
            #[inline]
            fn beyond(r: Self, c: Vec3<Self>) -> bool {
                crate::vec3::dot3(c, c) > r * r
            }
            #[inline]
            fn line_misses(q: [Self; 2], d: [Self; 2], r: Self, extent: Self) -> bool {
                let (a, b) = (d[0].abs(), d[1].abs());
                let (big, small) = if a < b { (b, a) } else { (a, b) };
                // Paths this short across (or NaN) are left to the full computation: below it
                // the products here could underflow.
                if big.is_nan() || big <= 4.0 * <$t>::EPSILON {
                    return false;
                }
                // The unit direction carries ~5 half-ulps per component and the cross product
                // another two, so `chord`'s offset is off by under 7 EPSILON of the offset's
                // size; the products here add 4 more. 128 EPSILON of the largest of the
                // offset, r and 1 covers both twice over.
                let reach = largest(extent, r, 1.0);
                let m = 128.0 * <$t>::EPSILON * reach;
                (q[0] * d[1] - q[1] * d[0]).abs() > (r + m) * (big + 0.5 * small)
            }
            #[inline]
            fn unit_to_scalar(u: Self) -> Self {
                u
            }
            #[inline]
            fn unit_to_f64(u: Self) -> f64 {
                u as f64
            }
            #[inline]
            fn from_int(n: i32) -> Self {
                n as Self
            }
            #[inline]
            fn fixed_bits(self) -> Option<(i64, u32)> {
                None
            }
        }
    };
}

float_scalar!(f32, libm::sqrtf, 16_777_216.0, tiny_direction_f32);
float_scalar!(f64, libm::sqrt, 9_007_199_254_740_992.0, tiny_direction_f64);
