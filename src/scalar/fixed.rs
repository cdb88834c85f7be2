//! The fixed-point implementations: unit vectors with more fractional bits than the
//! coordinates, products taken into a double-width integer and rounded once to nearest (ties away
//! from zero, so results mirror with the sign of their inputs), exact integer square roots
//! rounded to nearest.

use super::sealed::Kernel;
use super::{Scalar, largest};
use crate::vec3::Vec3;
use core::cmp::Ordering;
use fixed::types::{I2F30, I2F62, I16F16, I32F32};

/// Rounds `v / 2^shift` to nearest, ties away from zero, for `shift >= 1`: `-v` rounds to
/// exactly the negation of what `v` rounds to.
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

/// The integer square root rounded to nearest: `r + 1` when `x > r² + r`, i.e. when
/// `sqrt(x) >= r + 1/2` (the two cannot be equal for integers). One per width: `I16F16`'s
/// radicands fit 64 bits, and a 128-bit root costs a Cortex-M0 several times a 64-bit one.
macro_rules! isqrt_nearest {
    ($name:ident, $u:ty) => {
        fn $name(x: $u) -> $u {
            let r = x.isqrt();
            if x - r * r > r { r + 1 } else { r }
        }
    };
}
isqrt_nearest!(isqrt_nearest_64, u64);
isqrt_nearest!(isqrt_nearest_128, u128);

/// `a * b` exactly in 64 bits. Where the core has a 32 × 32 → 64 multiply this is one
/// instruction; on cores without one (Cortex-M0, `ballcast_no_long_mul`, see `build.rs`) an
/// `i64` product is a call to `__aeabi_lmul`, so the same product is formed from four 32-bit
/// multiplies ([`split_mul_i32`]). Either way it is the exact product: results are
/// bit-identical on every target.
#[inline]
fn wide_mul_i32(a: i32, b: i32) -> i64 {
    if cfg!(ballcast_no_long_mul) {
        split_mul_i32(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// `a * b` exactly for unsigned operands, as [`wide_mul_i32`].
#[inline]
fn wide_mul_u32(a: u32, b: u32) -> u64 {
    if cfg!(ballcast_no_long_mul) {
        split_mul_u32(a, b)
    } else {
        a as u64 * b as u64
    }
}

/// `a · b` exactly, for `b` a unit vector's bits (`|b| <= 2^30`), as [`wide_mul_i32`]: on cores
/// without a long multiply the four kinds of partial product are summed over the three
/// components before they are combined, so the 64-bit additions are paid once per kind.
#[inline]
fn wide_dot_i32(a: [i32; 3], b: [i32; 3]) -> i64 {
    if cfg!(ballcast_no_long_mul) {
        split_dot_i32(a, b)
    } else {
        a[0] as i64 * b[0] as i64 + a[1] as i64 * b[1] as i64 + a[2] as i64 * b[2] as i64
    }
}

/// [`wide_dot_i32`] from 16 × 16 → 32-bit products: with `|b| <= 2^30` the high halves'
/// products are at most 2^29 each, so their sum fits 32 bits; the rest are summed in 64.
#[inline]
fn split_dot_i32(a: [i32; 3], b: [i32; 3]) -> i64 {
    let (mut hh, mut mid, mut ll) = (0i32, 0i64, 0u64);
    for i in 0..3 {
        let (ah, al) = (a[i] >> 16, a[i] & 0xFFFF);
        let (bh, bl) = (b[i] >> 16, b[i] & 0xFFFF);
        hh = hh.wrapping_add(ah * bh);
        mid += (ah * bl) as i64 + (al * bh) as i64;
        ll += (al as u32 * bl as u32) as u64;
    }
    ((hh as i64) << 32) + (mid << 16) + ll as i64
}

/// `a · b` exactly in 128 bits.
#[inline]
fn wide_dot_i64(a: [i64; 3], b: [i64; 3]) -> i128 {
    a[0] as i128 * b[0] as i128 + a[1] as i128 * b[1] as i128 + a[2] as i128 * b[2] as i128
}

/// `a * b` exactly, from four 16 × 16 → 32-bit products (the only multiply a Cortex-M0 has is
/// 32 × 32 → 32).
#[inline]
fn split_mul_i32(a: i32, b: i32) -> i64 {
    // a = ah 2^16 + al with ah in [-2^15, 2^15) and al in [0, 2^16); likewise b.
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    // |ah bh| <= 2^30; |ah bl|, |al bh| < 2^31; al bl < 2^32 (unsigned): none overflows.
    let mid = (ah * bl) as i64 + (al * bh) as i64;
    (((ah * bh) as i64) << 32) + (mid << 16) + (al as u32 * bl as u32) as i64
}

/// `a * b` exactly for unsigned operands, as [`split_mul_i32`].
#[inline]
fn split_mul_u32(a: u32, b: u32) -> u64 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    let mid = (ah * bl) as u64 + (al * bh) as u64;
    (((ah * bh) as u64) << 32) + (mid << 16) + (al * bl) as u64
}

/// `I16F16`'s quotient `round(n 2^16 / d)` (`n`, `d` its bits) on cores without a long multiply,
/// which have no divide instruction either (Armv6-M): `None` elsewhere, where the 64-bit
/// division of the generic path is cheaper.
#[inline]
fn narrow_div_i32(n: i32, d: i32) -> Option<i32> {
    cfg!(ballcast_no_long_mul).then(|| split_div_i32(n, d))
}

/// No narrow division (`I32F32`).
#[inline]
fn no_narrow_div(_: i64, _: i64) -> Option<i64> {
    None
}

/// `round(n 2^16 / d)` to nearest, ties away from zero, saturating (a zero divisor gives the
/// largest value of `n`'s sign, or zero): exactly what the generic 64-bit path of
/// [`Scalar::div`] gives, from 32-bit operations. The integer part is one 32-bit division (none
/// when `|n| < |d|`, as for a fraction of a path), the 16 fractional bits are shifted out one
/// at a time with a remainder below `2 |d| <= 2^32`.
fn split_div_i32(n: i32, d: i32) -> i32 {
    let max = if (n < 0) == (d < 0) {
        i32::MAX
    } else {
        i32::MIN
    };
    if d == 0 {
        return if n == 0 { 0 } else { max };
    }
    let (a, d) = (n.unsigned_abs(), d.unsigned_abs());
    let (whole, mut r) = if a < d { (0, a) } else { (a / d, a % d) };
    // A quotient of 2^31 or more saturates (after rounding, too).
    if whole >= 1 << 15 {
        return max;
    }
    let mut q = whole;
    for _ in 0..16 {
        // r < d <= 2^31, so 2r fits.
        r <<= 1;
        q <<= 1;
        if r >= d {
            r -= d;
            q |= 1;
        }
    }
    // Half or more of the divisor left: away from zero. q <= 2^31 afterwards.
    if r >= d - r {
        q += 1;
    }
    if max > 0 {
        q.min(i32::MAX as u32) as i32
    } else {
        (-(q as i64)) as i32
    }
}

/// `a * b` exactly in 128 bits (`I32F32`: no narrower path; its targets are 64-bit hosts).
#[inline]
fn wide_mul_i64(a: i64, b: i64) -> i128 {
    a as i128 * b as i128
}

/// `a * b` exactly in 128 bits, unsigned.
#[inline]
fn wide_mul_u64(a: u64, b: u64) -> u128 {
    a as u128 * b as u128
}

/// A wide integer clamped to the type's bits.
macro_rules! saturate {
    ($t:ty, $bits:ty, $wide:ty, $w:expr) => {
        <$t>::from_bits(($w).clamp(<$bits>::MIN as $wide, <$bits>::MAX as $wide) as $bits)
    };
}

/// One fixed-point scalar: the type, its unit-vector type, the bits' type, the double-width
/// type, the unsigned bits' type, fractional bits of both, the safe range's integer, and the
/// exact widening products (signed, unsigned, a dot product with a unit vector), a division
/// without the double width where the core needs it (`None` elsewhere), and the rounded square root of the double width
/// with its unsigned type.
macro_rules! fixed_scalar {
    (
        $t:ty, $unit:ty, $bits:ty, $wide:ty, $uwide:ty, $frac:expr, $ufrac:expr, $limit_int:expr,
        $wmul:ident, $uwmul:ident, $wdot:ident, $ndiv:ident, $isqrt:ident, $sq:ty
    ) => {
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
                // sqrt(b / 2^F) * 2^F = sqrt(b * 2^F): an integer square root. Below the
                // largest value the result is at most 2^(BITS/2 + F/2): rounding up cannot overflow.
                let r = $isqrt((b as $uwide as $sq) << $frac);
                <$t>::from_bits(r as $bits)
            }
            #[inline]
            fn mul(self, o: Self) -> Self {
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
                let sum = $wdot(
                    [d.x.to_bits(), d.y.to_bits(), d.z.to_bits()],
                    [u.x.to_bits(), u.y.to_bits(), u.z.to_bits()],
                );
                <$t>::from_bits(round_shift!(sum, $ufrac) as $bits)
            }
            #[inline]
            fn mul_cmp(a: Self, b: Self, c: Self, d: Self) -> Ordering {
                let ab = $wmul(a.to_bits(), b.to_bits());
                let cd = $wmul(c.to_bits(), d.to_bits());
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
                let sq = |c: $unit| $wmul(c.to_bits(), c.to_bits());
                let w = s.map(|c| c.to_bits() as $wide);
                // Squares carry 2*UFRAC fractional bits; with |s| <= 1 their sum is below 3.
                let len2 = sq(s.x) + sq(s.y) + sq(s.z);
                // Never zero for the inputs described, but a divisor the compiler cannot prove nonzero
                // would leave a panic path in the binary.
                let len = $isqrt(len2 as $sq).max(1) as $wide;
                w.map(|c| {
                    let num = c << $ufrac;
                    let half = if num < 0 { -(len / 2) } else { len / 2 };
                    <$unit>::from_bits(((num + half) / len) as _)
                })
            }
            fn unit_cross(a: Vec3<$unit>, b: Vec3<$unit>) -> Option<Vec3<$unit>> {
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
                let shift = (<$wide>::BITS - m.leading_zeros()) as i32 - $ufrac;
                Some(Self::unit_normalize(
                    c.map(|x| <$unit>::from_bits(round_shift!(x, shift) as _)),
                ))
            }
            #[inline]
            fn div_pow2(v: Self, k: u32) -> Self {
                <$t>::from_bits(round_shift!(v.to_bits(), k))
            }
            #[inline]
            fn dot(a: Vec3<Self>, b: Vec3<Self>) -> Self {
                let p = |a: $t, b: $t| $wmul(a.to_bits(), b.to_bits());
                let sum = p(a.x, b.x) + p(a.y, b.y) + p(a.z, b.z);
                saturate!($t, $bits, $wide, round_shift!(sum, $frac))
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
            fn direction(v: Vec3<Self>) -> Option<(Self, Vec3<$unit>)> {
                // Components below 2^(BITS-1) square to below 2^(2 BITS - 2): three fit unsigned.
                let u = v.map(|c| c.to_bits().unsigned_abs());
                let len = $isqrt($uwmul(u.x, u.x) + $uwmul(u.y, u.y) + $uwmul(u.z, u.z));
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
                let sq = |a: $t| $wmul(a.to_bits(), a.to_bits());
                let k2 = sq(r) - sq(c.x) - sq(c.y) - sq(c.z);
                (k2 >= 0).then(|| <$t>::from_bits($isqrt(k2.unsigned_abs()) as $bits))
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
                <$t>::from_bits(round_shift!(u.to_bits() as $wide, $ufrac - $frac) as $bits)
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
    wide_mul_u32,
    wide_dot_i32,
    narrow_div_i32,
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
    wide_mul_u64,
    wide_dot_i64,
    no_narrow_div,
    isqrt_nearest_128,
    u128
);

#[cfg(test)]
mod tests {
    use super::{split_div_i32, split_dot_i32, split_mul_i32, split_mul_u32};
    use crate::Scalar;
    use fixed::types::I16F16;

    /// The split products equal the 64-bit ones: on the extremes and on 10^6 pseudo-random pairs.
    #[test]
    fn split_products_are_exact() {
        let edges = [
            i32::MIN,
            i32::MIN + 1,
            -65537,
            -65536,
            -65535,
            -1,
            0,
            1,
            65535,
            65536,
        ];
        let edges = edges.iter().chain(&[65537, i32::MAX - 1, i32::MAX]);
        for &a in edges.clone() {
            for &b in edges.clone() {
                assert_eq!(split_mul_i32(a, b), a as i64 * b as i64, "{a} {b}");
                let (a, b) = (a as u32, b as u32);
                assert_eq!(split_mul_u32(a, b), a as u64 * b as u64, "{a} {b}");
            }
        }
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..1_000_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let (a, b) = (x as i32, (x >> 32) as i32);
            assert_eq!(split_mul_i32(a, b), a as i64 * b as i64);
            let (a, b) = (a as u32, b as u32);
            assert_eq!(split_mul_u32(a, b), a as u64 * b as u64);
            // A unit vector's bits: |b| <= 2^30.
            let u = [b as i32 >> 1, (b as i32).rotate_left(7) >> 1, a as i32 >> 1];
            let v = [a as i32, b as i32, (x >> 16) as i32];
            let want: i64 = (0..3).map(|i| v[i] as i64 * u[i] as i64).sum();
            assert_eq!(split_dot_i32(v, u), want);
        }
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        for k in 0..1_000_000u32 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Mixed magnitudes: whole numerators and divisors, and small ones.
            let (n, d) = ((x as i32) >> (k % 31), ((x >> 32) as i32) >> (k / 7 % 31));
            let want = I16F16::from_bits(n).div(I16F16::from_bits(d)).to_bits();
            assert_eq!(split_div_i32(n, d), want, "{n} / {d}");
        }
        for n in [
            i32::MIN,
            i32::MIN + 1,
            -65536,
            -1,
            0,
            1,
            65535,
            65536,
            i32::MAX,
        ] {
            for d in [
                i32::MIN,
                -65537,
                -65536,
                -2,
                -1,
                0,
                1,
                2,
                3,
                65536,
                65537,
                i32::MAX,
            ] {
                let want = I16F16::from_bits(n).div(I16F16::from_bits(d)).to_bits();
                assert_eq!(split_div_i32(n, d), want, "{n} / {d}");
            }
        }
        let (m, u) = (i32::MIN, 1 << 30);
        for (v, w) in [
            ([m; 3], [u; 3]),
            ([m; 3], [-u; 3]),
            ([i32::MAX; 3], [-u; 3]),
        ] {
            let want: i64 = (0..3).map(|i| v[i] as i64 * w[i] as i64).sum();
            assert_eq!(split_dot_i32(v, w), want);
        }
    }
}
