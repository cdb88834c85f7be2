//! Exact double-width integer arithmetic for the fixed-point kernels (`fixed.rs`): products,
//! dot products with unit vectors and quotients, each in the form that is cheapest on the target
//! and the same integer on every target (the square roots are in `isqrt.rs`).
//!
//! On cores without a 32 × 32 → 64 multiply (`ballcast_no_long_mul`, set by `build.rs` for
//! Armv6-M and Armv8-M Baseline, e.g. the Cortex-M0) `I16F16`'s products, dot products with
//! unit vectors and quotients are formed from 32-bit operations (`narrow.rs`) instead of calls
//! to `__aeabi_lmul` and `__aeabi_ldivmod`.

use super::narrow::*;

/// `a * b` exactly in 64 bits. Where the core has a 32 × 32 → 64 multiply this is one
/// instruction; on cores without one (Cortex-M0, `ballcast_no_long_mul`, see `build.rs`) an
/// `i64` product is a call to `__aeabi_lmul`, so the same product is formed from four 32-bit
/// multiplies ([`split_mul_i32`]). Either way it is the exact product: results are
/// bit-identical on every target.
#[inline]
pub(crate) fn wide_mul_i32(a: i32, b: i32) -> i64 {
    if cfg!(ballcast_no_long_mul) {
        split_mul_i32(a, b)
    } else {
        a as i64 * b as i64
    }
}

/// `I16F16`'s product `round(a b / 2^16)` on cores without a long multiply, when one factor
/// is below one in magnitude (a fraction of a path, say): two 32-bit products
/// ([`small_mul_i32`]) instead of four and a 64-bit rounding. `None` for other factors, and on
/// other cores, where the generic path runs.
#[inline]
pub(super) fn narrow_mul_i32(a: i32, b: i32) -> Option<i32> {
    if !cfg!(ballcast_no_long_mul) {
        None
    } else if a.unsigned_abs() < 1 << 16 {
        Some(small_mul_i32(a, b))
    } else if b.unsigned_abs() < 1 << 16 {
        Some(small_mul_i32(b, a))
    } else {
        None
    }
}

/// No narrow product (`I32F32`).
#[inline]
pub(super) fn no_narrow_mul(_: i64, _: i64) -> Option<i64> {
    None
}

/// `a * b` exactly for unsigned operands, as [`wide_mul_i32`].
#[inline]
pub(crate) fn wide_mul_u32(a: u32, b: u32) -> u64 {
    if cfg!(ballcast_no_long_mul) {
        split_mul_u32(a, b)
    } else {
        a as u64 * b as u64
    }
}

/// `a · b` exactly, for `b` a unit vector's bits.
#[inline]
pub(super) fn wide_dot_i32(a: [i32; 3], b: [i32; 3]) -> i64 {
    a[0] as i64 * b[0] as i64 + a[1] as i64 * b[1] as i64 + a[2] as i64 * b[2] as i64
}

/// `I16F16`'s `a · b / 2^30` rounded to nearest, ties away from zero, for `b` a unit vector's
/// bits (`|b| <= 2^30`), on cores without a long multiply: from 32-bit products
/// ([`split_dot_unit_i32`]), the integer [`wide_dot_i32`] and the rounding give. `None`
/// elsewhere.
#[inline]
pub(super) fn narrow_dot_unit_i32(a: [i32; 3], b: [i32; 3]) -> Option<i32> {
    cfg!(ballcast_no_long_mul).then(|| split_dot_unit_i32(a, b))
}

/// No narrow dot product (`I32F32`).
#[inline]
pub(super) fn no_narrow_dot_unit(_: [i64; 3], _: [i64; 3]) -> Option<i64> {
    None
}

/// `a · b` exactly in 128 bits.
#[inline]
pub(super) fn wide_dot_i64(a: [i64; 3], b: [i64; 3]) -> i128 {
    a[0] as i128 * b[0] as i128 + a[1] as i128 * b[1] as i128 + a[2] as i128 * b[2] as i128
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

/// `I16F16`'s `round(a n / d)` for the three components `a` of a vector (bits, `|n| < |d|`,
/// `q` the bits of `n / d` as `div` rounds it) on cores without a long multiply or a divide
/// instruction: one 64-bit division shared by the three, instead of one each, and started
/// from `q` ([`split_scale_fraction_i32`]); `None` elsewhere, and for `|n| >= |d|` or
/// `d == 0`, where the per-component path is taken.
#[inline]
pub(super) fn narrow_scale_fraction_i32(a: [i32; 3], n: i32, d: i32, q: i32) -> Option<[i32; 3]> {
    if cfg!(ballcast_no_long_mul) {
        split_scale_fraction_i32(a, n, d, q)
    } else {
        None
    }
}

/// No narrow scaling by a fraction (`I32F32`).
#[inline]
pub(super) fn no_narrow_scale_fraction(_: [i64; 3], _: i64, _: i64, _: i64) -> Option<[i64; 3]> {
    None
}

/// `I16F16`'s unit normalisation `round(c 2^30 / len)` of three components on cores without a
/// long multiply or a divide instruction: one shared reciprocal and 32-bit products
/// ([`split_normalize_i32`]) instead of three 64-bit divisions; `None` elsewhere, and outside
/// its domain, where the generic path runs.
#[inline]
pub(super) fn narrow_normalize_i32(c: [i32; 3], len: i64) -> Option<[i32; 3]> {
    if cfg!(ballcast_no_long_mul) {
        split_normalize_i32(c, u32::try_from(len).ok()?)
    } else {
        None
    }
}

/// No narrow normalisation (`I32F32`).
#[inline]
pub(super) fn no_narrow_normalize(_: [i64; 3], _: i128) -> Option<[i64; 3]> {
    None
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

/// `leading_zeros` of the fixed-point kernels' magnitudes. Armv6-M (a Cortex-M0, where
/// `ballcast_no_long_mul` is set) has no count-leading-zeros instruction: `leading_zeros` is a
/// call to `__clzsi2` (about 33 instructions there, two calls for 64 bits), made several times
/// per prepared triangle. There the count is a search by halves, bytes and nibbles, the last
/// four bits from a table: the same count, inline. Elsewhere it is the instruction.
pub(crate) trait LeadingZeros {
    fn clz(self) -> u32;
}

/// Leading zeros of a nibble.
const CLZ4: [u8; 16] = [4, 3, 2, 2, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0];

/// `x.leading_zeros()` by halves, a byte and a nibble and the table [`CLZ4`].
#[inline]
fn clz_u32(x: u32) -> u32 {
    let (mut n, mut x) = (0, x);
    if x >> 16 == 0 {
        (n, x) = (n + 16, x << 16);
    }
    if x >> 24 == 0 {
        (n, x) = (n + 8, x << 8);
    }
    if x >> 28 == 0 {
        (n, x) = (n + 4, x << 4);
    }
    n + CLZ4[(x >> 28) as usize] as u32
}

impl LeadingZeros for u32 {
    #[inline]
    fn clz(self) -> u32 {
        if cfg!(ballcast_no_long_mul) {
            clz_u32(self)
        } else {
            self.leading_zeros()
        }
    }
}

/// `x.leading_zeros()` from its two halves' by [`clz_u32`].
#[inline]
fn clz_u64(x: u64) -> u32 {
    if x >> 32 != 0 {
        clz_u32((x >> 32) as u32)
    } else {
        32 + clz_u32(x as u32)
    }
}

impl LeadingZeros for u64 {
    #[inline]
    fn clz(self) -> u32 {
        if cfg!(ballcast_no_long_mul) {
            clz_u64(self)
        } else {
            self.leading_zeros()
        }
    }
}

impl LeadingZeros for u128 {
    #[inline]
    fn clz(self) -> u32 {
        self.leading_zeros()
    }
}

#[cfg(test)]
mod tests {
    use super::{LeadingZeros, clz_u32, clz_u64};

    /// The search gives `leading_zeros` for zero, every power of two, every one less and more,
    /// and 10^6 pseudo-random values of every magnitude, in 32 and 64 bits.
    #[test]
    fn leading_zeros_by_search() {
        let check = |x: u64| {
            assert_eq!(clz_u32(x as u32), (x as u32).leading_zeros(), "{x}");
            assert_eq!(clz_u64(x), x.leading_zeros(), "{x}");
            assert_eq!(x.clz(), x.leading_zeros());
        };
        check(0);
        for k in 0..64 {
            for x in [1u64 << k, (1u64 << k) - 1, (1u64 << k) + 1, u64::MAX >> k] {
                check(x);
            }
        }
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for k in 0..1_000_000u32 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            check(x >> (k % 64));
        }
    }
}
