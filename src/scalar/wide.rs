//! Exact double-width integer arithmetic for the fixed-point kernels (`fixed.rs`): products,
//! dot products with unit vectors, quotients and rounded square roots, each in the form that is
//! cheapest on the target and the same integer on every target.
//!
//! On cores without a 32 × 32 → 64 multiply (`ballcast_no_long_mul`, set by `build.rs` for
//! Armv6-M and Armv8-M Baseline, e.g. the Cortex-M0) `I16F16`'s products are formed from
//! 16 × 16 → 32 multiplies and its quotients from one 32-bit division and shift-and-subtract
//! steps, instead of calls to `__aeabi_lmul` and `__aeabi_ldivmod`.

/// The integer square root rounded to nearest: `r + 1` when `x > r² + r`, i.e. when
/// `sqrt(x) >= r + 1/2` (the two cannot be equal for integers). One per width: `I16F16`'s
/// radicands fit 64 bits, and a 128-bit root costs a Cortex-M0 several times a 64-bit one.
macro_rules! isqrt_nearest {
    ($name:ident, $u:ty) => {
        pub(super) fn $name(x: $u) -> $u {
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
pub(super) fn wide_mul_i32(a: i32, b: i32) -> i64 {
    if cfg!(ballcast_no_long_mul) {
        split_mul_i32(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// `a * b` exactly for unsigned operands, as [`wide_mul_i32`].
#[inline]
pub(super) fn wide_mul_u32(a: u32, b: u32) -> u64 {
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
pub(super) fn wide_dot_i32(a: [i32; 3], b: [i32; 3]) -> i64 {
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
pub(super) fn wide_dot_i64(a: [i64; 3], b: [i64; 3]) -> i128 {
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
pub(super) fn narrow_div_i32(n: i32, d: i32) -> Option<i32> {
    cfg!(ballcast_no_long_mul).then(|| split_div_i32(n, d))
}

/// No narrow division (`I32F32`).
#[inline]
pub(super) fn no_narrow_div(_: i64, _: i64) -> Option<i64> {
    None
}

/// `I16F16`'s `round(a n / d)` for the three components `a` of a vector (bits, `|n| < |d|`) on
/// cores without a long multiply or a divide instruction: one 64-bit division shared by the
/// three, instead of one each ([`split_scale_fraction_i32`]); `None` elsewhere, and for
/// `|n| >= |d|` or `d == 0`, where the per-component path is taken.
#[inline]
pub(super) fn narrow_scale_fraction_i32(a: [i32; 3], n: i32, d: i32) -> Option<[i32; 3]> {
    if cfg!(ballcast_no_long_mul) {
        split_scale_fraction_i32(a, n, d)
    } else {
        None
    }
}

/// No narrow scaling by a fraction (`I32F32`).
#[inline]
pub(super) fn no_narrow_scale_fraction(_: [i64; 3], _: i64, _: i64) -> Option<[i64; 3]> {
    None
}

/// `round(a n / d)` to nearest, ties away from zero, saturating, for each `a`: exactly what
/// `mul_div` gives. `F = floor(|n| 2^32 / |d|)` (one division, `|n| < |d|` so `F < 2^32`)
/// gives an estimate `floor(|a| F / 2^32)` short of `floor(|a n| / |d|)` by at most one
/// (`|a| / 2^32 <= 1/2` lost to F, one to the floor); the exact remainder `|a n| - q |d|`,
/// from 32-bit multiplies, corrects it and decides the rounding. `None` for `|n| >= |d|`.
fn split_scale_fraction_i32(a: [i32; 3], n: i32, d: i32) -> Option<[i32; 3]> {
    let (nm, dm) = (n.unsigned_abs(), d.unsigned_abs());
    if nm >= dm {
        return None;
    }
    let f = ((((nm as u64) << 32) / dm as u64) as u32, dm);
    Some(a.map(|a| scale_one(a, n, d, f)))
}

/// One component of [`split_scale_fraction_i32`], with `(F, |d|)`.
#[inline]
fn scale_one(a: i32, n: i32, d: i32, (f, dm): (u32, u32)) -> i32 {
    let am = a.unsigned_abs();
    let mut q = (split_mul_u32(am, f) >> 32) as u32;
    let exact = split_mul_u32(am, n.unsigned_abs());
    // q <= floor(exact / dm) <= q + 1, so 0 <= rem < 2 dm.
    let mut rem = exact - split_mul_u32(q, dm);
    if rem >= dm as u64 {
        q += 1;
        rem -= dm as u64;
    }
    // Half or more of the divisor left: away from zero. q <= |a| < 2^31 + 1 afterwards.
    let q = q as i64 + (rem >= dm as u64 - rem) as i64;
    let negative = ((a < 0) != (n < 0)) != (d < 0);
    let q = if negative { -q } else { q };
    q.clamp(i32::MIN as i64, i32::MAX as i64) as i32
}

/// `round(n 2^16 / d)` to nearest, ties away from zero, saturating (a zero divisor gives the
/// largest value of `n`'s sign, or zero): exactly what the generic 64-bit path of
/// [`Scalar::div`](super::Scalar::div) gives, from 32-bit operations. The integer part is one 32-bit division (none
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
pub(super) fn wide_mul_i64(a: i64, b: i64) -> i128 {
    a as i128 * b as i128
}

/// `a * b` exactly in 128 bits, unsigned.
#[inline]
pub(super) fn wide_mul_u64(a: u64, b: u64) -> u128 {
    a as u128 * b as u128
}

#[cfg(test)]
mod tests {
    use super::{
        split_div_i32, split_dot_i32, split_mul_i32, split_mul_u32, split_scale_fraction_i32,
    };
    use crate::Scalar;
    use crate::scalar::sealed::Kernel;
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
        let mut x: u64 = 0x6A09_E667_F3BC_C909;
        for k in 0..1_000_000u32 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            // Mixed magnitudes; |n| < |d| (a fraction of a path) for most, any for some.
            let a = [
                (x as i32) >> (k % 31),
                (x >> 8) as i32 >> (k % 29),
                (x >> 24) as i32,
            ];
            let (n, d) = (
                ((x >> 32) as i32) >> (k / 7 % 31),
                (x >> 16) as i32 >> (k / 3 % 29),
            );
            let n = if k % 8 == 0 {
                n
            } else {
                n % d.saturating_abs().max(1)
            };
            let want = a.map(|a| {
                let f = |b: i32| I16F16::from_bits(b);
                <I16F16 as Kernel>::mul_div(f(a), f(n), f(d)).to_bits()
            });
            if let Some(got) = split_scale_fraction_i32(a, n, d) {
                assert_eq!(got, want, "{a:?} * {n} / {d}");
            } else {
                assert!(n.unsigned_abs() >= d.unsigned_abs());
            }
        }
        for a in [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX] {
            for (n, d) in [
                (0, 1),
                (1, 2),
                (-1, 2),
                (i32::MAX - 1, i32::MAX),
                (i32::MIN + 1, i32::MIN),
                (1, -3),
                (-5, -7),
            ] {
                let f = |b: i32| I16F16::from_bits(b);
                let want = <I16F16 as Kernel>::mul_div(f(a), f(n), f(d)).to_bits();
                assert_eq!(
                    split_scale_fraction_i32([a; 3], n, d),
                    Some([want; 3]),
                    "{a} * {n} / {d}"
                );
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
