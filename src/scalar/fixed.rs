//! The fixed-point implementations: unit vectors with more fractional bits than the
//! coordinates, products taken into a double-width integer and rounded once to nearest (ties away
//! from zero, so results mirror with the sign of their inputs), exact integer square roots
//! rounded to nearest.

use super::isqrt::{isqrt_nearest_64, isqrt_nearest_128};
use super::sealed::Kernel;
use super::wide::*;
use super::{HARDWARE_F64, Scalar, largest};
use crate::vec3::Vec3;
use core::cmp::Ordering;
use fixed::types::{I2F30, I2F62, I16F16, I32F32};

/// Rounds `v / 2^shift` to nearest, ties away from zero, for `shift >= 1`: `-v` rounds to
/// exactly the negation of what `v` rounds to. Needs `|v|` half a step below the type's
/// extremes (a product in its double width always is); [`round_shift_any`] takes any `v`.
macro_rules! round_shift {
    ($v:expr, $shift:expr) => {{
        let (v, half) = ($v, 1 << ($shift - 1));
        if v < 0 {
            -((half - v) >> $shift)
        } else {
            (v + half) >> $shift
        }
    }};
}

/// [`round_shift`] for any `v`, the type's extremes included, where no step can overflow: a
/// positive `v` adds the bit below the shift to the quotient, a negative one adds less than a
/// step before flooring, `ceil((v - half) / 2^shift)`. The same numbers otherwise, for a few
/// more operations. (For `v` in its own width: `slide::skin` of the largest `I16F16`
/// overflowed.)
macro_rules! round_shift_any {
    ($v:expr, $shift:expr) => {{
        let (v, shift) = ($v, $shift);
        if v < 0 {
            (v + ((1 << (shift - 1)) - 1)) >> shift
        } else {
            (v >> shift) + ((v >> (shift - 1)) & 1)
        }
    }};
}

/// A wide integer clamped to the type's bits.
macro_rules! saturate {
    ($t:ty, $bits:ty, $wide:ty, $w:expr) => {
        <$t>::from_bits(($w).clamp(<$bits>::MIN as $wide, <$bits>::MAX as $wide) as $bits)
    };
}

/// One fixed-point scalar: the type, its unit-vector type, the bits' type, the double-width
/// type, the unsigned bits' type, fractional bits of both, the safe range's integer, and the
/// exact widening products (signed, unsigned, a dot product with a unit vector), a division and
/// a scaling by a fraction without the double-width division where the core needs them (`None`
/// elsewhere), and the rounded square root of the double width with its unsigned type.
macro_rules! fixed_scalar {
    (
        $t:ty, $unit:ty, $bits:ty, $wide:ty, $uwide:ty, $frac:expr, $ufrac:expr, $limit_int:expr,
        $wmul:ident, $nmul:ident, $uwmul:ident, $wdot:ident, $ndot:ident, $ndiv:ident, $nscale:ident, $nnorm:ident, $isqrt:ident, $sq:ty
    ) => {
        impl Scalar for $t {
            const ZERO: Self = <$t>::ZERO;
            const ONE: Self = <$t>::ONE;
            const NEG_ONE: Self = <$t>::NEG_ONE;
            const LIMIT: Self = <$t>::from_bits($limit_int << $frac);
            const EPSILON: Self = <$t>::DELTA;
            const PRECISION: crate::Precision = crate::Precision {
                scalar: crate::plan::ScalarType::named(stringify!($t)),
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
                // The bits' conversion rounds to nearest, ties to even, as `to_num` does, and
                // the power-of-two scale is exact: two instructions where `f64` is hardware.
                // Elsewhere `to_num`'s integer code beats two soft-float calls.
                if HARDWARE_F64 {
                    self.to_bits() as f64 * (1.0 / (1u64 << $frac) as f64)
                } else {
                    self.to_num::<f64>()
                }
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
                // sqrt(b / 2^F) * 2^F = sqrt(b * 2^F): an integer square root. Below the
                // largest value the result is at most 2^(BITS/2 + F/2): rounding up cannot overflow.
                let r = $isqrt((b as $uwide as $sq) << $frac);
                <$t>::from_bits(r as $bits)
            }
            #[inline]
            fn mul(self, o: Self) -> Self {
                if let Some(p) = $nmul(self.to_bits(), o.to_bits()) {
                    return <$t>::from_bits(p);
                }
                let p = $wmul(self.to_bits(), o.to_bits());
                saturate!($t, $bits, $wide, round_shift!(p, $frac))
            }
            #[inline]
            fn div(self, o: Self) -> Self {
                if let Some(q) = $ndiv(self.to_bits(), o.to_bits()) {
                    return <$t>::from_bits(q);
                }
                let (n, d) = ((self.to_bits() as $wide) << $frac, o.to_bits() as $wide);
                if d == 0 {
                    return if n == 0 {
                        <$t>::ZERO
                    } else if n > 0 {
                        <$t>::MAX
                    } else {
                        <$t>::MIN
                    };
                }
                let (q, r) = (n / d, n % d);
                let away = if (n < 0) == (d < 0) { 1 } else { -1 };
                saturate!(
                    $t,
                    $bits,
                    $wide,
                    if 2 * r.unsigned_abs() >= d.unsigned_abs() {
                        q + away
                    } else {
                        q
                    }
                )
            }
        }

        impl Kernel for $t {
            type Unit = $unit;
            const UNIT_ZERO: $unit = <$unit>::ZERO;

            #[inline]
            fn dot_unit(d: Vec3<Self>, u: Vec3<$unit>) -> Self {
                let d = [d.x.to_bits(), d.y.to_bits(), d.z.to_bits()];
                let u = [u.x.to_bits(), u.y.to_bits(), u.z.to_bits()];
                if let Some(r) = $ndot(d, u) {
                    return <$t>::from_bits(r);
                }
                <$t>::from_bits(round_shift!($wdot(d, u), $ufrac) as $bits)
            }
            #[inline]
            fn dot_unit_xz(d: Vec3<Self>, [ux, uz]: [$unit; 2]) -> Self {
                // The zero's products are constants the compiler leaves out.
                Self::dot_unit(d, Vec3::new(ux, <$unit>::ZERO, uz))
            }
            #[inline]
            fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering {
                let ab = $wmul(a.to_bits(), b.to_bits());
                let cd = $wmul(c.to_bits(), d.to_bits());
                ab.cmp(&cd)
            }
            fn scaled(v: Vec3<Self>) -> Option<Vec3<$unit>> {
                let b = v.map(|c| c.to_bits());
                let m = largest(b.x.unsigned_abs(), b.y.unsigned_abs(), b.z.unsigned_abs());
                if m == 0 {
                    return None;
                }
                // A power-of-two scale is exact: shift the top bit of `m` to `2^(UFRAC-1)`. Up,
                // in the bits' own width (the unit's: the result is below 2^UFRAC); down, with
                // rounding, in the wide one (a Cortex-M0 shifts 64 bits by a library call).
                let top = (<$bits>::BITS - 1 - m.clz()) as i32;
                let k = ($ufrac - 1) - top;
                Some(b.map(|c| {
                    <$unit>::from_bits(if k >= 0 {
                        c << k
                    } else {
                        round_shift!(c as $wide, -k) as _
                    })
                }))
            }
            fn unit_normalize(s: Vec3<$unit>) -> Vec3<$unit> {
                let sq = |c: $unit| $wmul(c.to_bits(), c.to_bits());
                let w = s.map(|c| c.to_bits() as $wide);
                // Squares carry 2*UFRAC fractional bits; with |s| <= 1 their sum is below 3.
                let len2 = sq(s.x) + sq(s.y) + sq(s.z);
                // Never zero for the inputs described, but a divisor the compiler cannot prove nonzero
                // would leave a panic path in the binary.
                let len = ($isqrt(len2 as $sq) as $wide).max(1);
                let bits = [s.x.to_bits(), s.y.to_bits(), s.z.to_bits()];
                // Along an axis (a level's walls and floors), `len` is the largest component,
                // 2^(UFRAC-1), and each quotient is exactly `2 c`: no division. The cast below
                // wraps likewise.
                if len == 1 << ($ufrac - 1) {
                    return Vec3::new(bits[0], bits[1], bits[2])
                        .map(|c| <$unit>::from_bits(c.wrapping_mul(2)));
                }
                if let Some(q) = $nnorm(bits, len) {
                    return Vec3::new(q[0], q[1], q[2]).map(<$unit>::from_bits);
                }
                w.map(|c| {
                    let num = c << $ufrac;
                    let half = if num < 0 { -(len / 2) } else { len / 2 };
                    <$unit>::from_bits(((num + half) / len) as _)
                })
            }
            fn scaled_cross(a: Vec3<$unit>, b: Vec3<$unit>) -> Option<Vec3<$unit>> {
                let (a, b) = (a.map(|c| c.to_bits()), b.map(|c| c.to_bits()));
                let c = Vec3::new(
                    $wmul(a.y, b.z) - $wmul(a.z, b.y),
                    $wmul(a.z, b.x) - $wmul(a.x, b.z),
                    $wmul(a.x, b.y) - $wmul(a.y, b.x),
                );
                let m = largest(c.x.unsigned_abs(), c.y.unsigned_abs(), c.z.unsigned_abs());
                // `c` carries 2*UFRAC fractional bits; 1024 units of roundoff is 2^(UFRAC+10).
                if m < (1 << ($ufrac + 10)) {
                    return None;
                }
                let shift = (<$wide>::BITS - m.clz()) as i32 - $ufrac;
                Some(c.map(|x| <$unit>::from_bits(round_shift!(x, shift) as _)))
            }
            #[inline]
            fn div_pow2(v: Self, k: u32) -> Self {
                <$t>::from_bits(round_shift_any!(v.to_bits(), k))
            }
            #[inline]
            fn dot(a: Vec3<Self>, b: Vec3<Self>) -> Self {
                let p = |a: $t, b: $t| $wmul(a.to_bits(), b.to_bits());
                let sum = p(a.x, b.x) + p(a.y, b.y) + p(a.z, b.z);
                saturate!($t, $bits, $wide, round_shift!(sum, $frac))
            }
            #[inline]
            fn dot_sign(a: Vec3<Self>, b: Vec3<Self>) -> Ordering {
                let p = |a: $t, b: $t| $wmul(a.to_bits(), b.to_bits());
                (p(a.x, b.x) + p(a.y, b.y) + p(a.z, b.z)).cmp(&0)
            }
            #[inline]
            fn height_error(_: Self) -> Self {
                <$t>::from_bits(8)
            }
            #[inline]
            fn mul_unit(s: Self, u: $unit) -> Self {
                let p = $wmul(s.to_bits(), u.to_bits());
                <$t>::from_bits(round_shift!(p, $ufrac) as $bits)
            }
            fn mul_div(a: Self, n: Self, d: Self) -> Self {
                // The product carries 2F fractional bits; the quotient by d's bits F.
                let (p, d) = ($wmul(a.to_bits(), n.to_bits()), d.to_bits() as $wide);
                if d == 0 {
                    return <$t>::ZERO;
                }
                // |p| < 2^(2 BITS - 2): the quotient cannot overflow, so wrapping is exact.
                let (q, r) = (p.wrapping_div(d), p.wrapping_rem(d));
                let away = if (p < 0) == (d < 0) { 1 } else { -1 };
                let q = if 2 * r.unsigned_abs() >= d.unsigned_abs() {
                    q + away
                } else {
                    q
                };
                saturate!($t, $bits, $wide, q)
            }
            #[inline]
            fn scale_fraction(v: Vec3<Self>, n: Self, d: Self, q: Self) -> Vec3<Self> {
                debug_assert_eq!(q, n.div(d), "the fraction's quotient");
                let bits = [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()];
                match $nscale(bits, n.to_bits(), d.to_bits(), q.to_bits()) {
                    Some(q) => Vec3::new(q[0], q[1], q[2]).map(<$t>::from_bits),
                    None => v.map(|c| Self::mul_div(c, n, d)),
                }
            }
            fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<$unit>)> {
                // Components below 2^(BITS-1) square to below 2^(2 BITS - 2): three fit unsigned.
                let u = v.map(|c| c.to_bits().unsigned_abs());
                let len = $isqrt($uwmul(u.x, u.x) + $uwmul(u.y, u.y) + $uwmul(u.z, u.z));
                // Up to sqrt(3) times the largest value: saturated, not wrapped.
                let len = len.min(<$bits>::MAX as _);
                Some((
                    <$t>::from_bits(len as $bits),
                    Self::unit_normalize(Self::scaled(v)?),
                ))
            }
            #[inline]
            fn direction_neg_x(_: Self) -> $unit {
                // `direction` takes the exact root of len², len itself, and normalises a vector
                // with one nonzero component c to exactly −1: round(c 2^UFRAC / |c|).
                -<$unit>::ONE
            }
            fn chord(r: Self, c: Vec3<Self>) -> Option<Self> {
                if c.x.abs() > r || c.y.abs() > r || c.z.abs() > r {
                    return None;
                }
                // Every square is below r² <= LIMIT², exact with 2F fractional bits.
                let sq = |a: $t| $wmul(a.to_bits(), a.to_bits());
                let k2 = sq(r) - sq(c.x) - sq(c.y) - sq(c.z);
                (k2 >= 0).then(|| <$t>::from_bits($isqrt(k2.unsigned_abs()) as $bits))
            }
            #[inline]
            fn beyond(r: Self, c: Vec3<Self>) -> bool {
                if c.x.abs() > r || c.y.abs() > r || c.z.abs() > r {
                    return true;
                }
                // As in `chord`: every square below r² <= 4 LIMIT², exact.
                let sq = |a: $t| $wmul(a.to_bits(), a.to_bits());
                sq(c.x) + sq(c.y) + sq(c.z) > sq(r)
            }
            #[inline]
            fn line_misses(q: [Self; 2], d: [Self; 2], r: Self, extent: Self) -> bool {
                let (a, b) = (d[0].to_bits().unsigned_abs(), d[1].to_bits().unsigned_abs());
                let (big, small) = if a < b { (b, a) } else { (a, b) };
                // `direction` rounds each unit component by under 2^-(UFRAC-1), so `chord`'s
                // offset is off by under 2^-(UFRAC-4) of the offset's size plus a step; the
                // floors below cost 4 steps more. 16 steps and 2^-(UFRAC-7) of the reach cover
                // both with room.
                let reach = largest(extent.to_bits(), r.to_bits(), 0).unsigned_abs();
                let rm = r.to_bits().unsigned_abs() + 16 + (reach >> ($ufrac - 7));
                // Halved products, so their difference cannot overflow.
                let x = ($wmul(q[0].to_bits(), d[1].to_bits()) >> 1)
                    - ($wmul(q[1].to_bits(), d[0].to_bits()) >> 1);
                x.unsigned_abs() > ($uwmul(rm, big) >> 1) + ($uwmul(rm, small) >> 2)
            }
            #[inline]
            fn unit_to_scalar(u: $unit) -> Self {
                // `round_shift!` in the unit's own width (a unit vector's bits are at most
                // 2^UFRAC in magnitude, so nothing overflows), without a branch: for v < 0,
                // floor((v + half - 1) / 2^K) = -floor((|v| + half) / 2^K), ties away from zero.
                const K: u32 = $ufrac - $frac;
                let v = u.to_bits();
                <$t>::from_bits(v.wrapping_add((1 << (K - 1)) - (v < 0) as $bits) >> K)
            }
            #[inline]
            fn unit_to_f64(u: $unit) -> f64 {
                // A power-of-two scale: exact but for `I2F62`'s bits beyond `f64`'s 53.
                u.to_bits() as f64 * (1.0 / (1u64 << $ufrac) as f64)
            }
            #[inline]
            fn from_int(n: i32) -> Self {
                <$t>::saturating_from_num(n)
            }
            #[inline]
            fn fixed_bits(self) -> Option<(i64, u32)> {
                Some((self.to_bits() as i64, $frac))
            }
        }
    };
}

fixed_scalar!(
    I16F16,
    I2F30,
    i32,
    i64,
    u32,
    16,
    30,
    4096,
    wide_mul_i32,
    narrow_mul_i32,
    wide_mul_u32,
    wide_dot_i32,
    narrow_dot_unit_i32,
    narrow_div_i32,
    narrow_scale_fraction_i32,
    narrow_normalize_i32,
    isqrt_nearest_64,
    u64
);
fixed_scalar!(
    I32F32,
    I2F62,
    i64,
    i128,
    u64,
    32,
    62,
    268_435_456,
    wide_mul_i64,
    no_narrow_mul,
    wide_mul_u64,
    wide_dot_i64,
    no_narrow_dot_unit,
    no_narrow_div,
    no_narrow_scale_fraction,
    no_narrow_normalize,
    isqrt_nearest_128,
    u128
);
