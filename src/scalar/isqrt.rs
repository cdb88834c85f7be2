//! Integer square roots rounded to nearest, for the fixed-point kernels (`fixed.rs`): the same
//! integer on every target, found the way that is cheapest there.
//!
//! `round(√x)` follows from any estimate `r` with `round(√x) − 1 <= r <= round(√x)`: it is
//! `r + 1` exactly when `x − r² > r`, i.e. when `√x > r + 1/2` (`√x` is never a half-integer).
//! With `r = ⌊√x⌋` this is the usual rounding of an integer square root; the integer square root
//! itself and its Newton iteration are in Warren, *Hacker's Delight* (2nd ed., §11–1).
//!
//! Where `libm::sqrt` is a hardware instruction (x86 with SSE2, AArch64: libm's own condition),
//! the estimate comes from the `f64` square root: IEEE 754 rounds the conversion to `f64` and
//! the square root once each, so the estimate is off `√x` by a relative `1.5 · 2^-53` at most.
//! For a 64-bit `x` that is under 2^-20 (`√x < 2^32`), so its integer part is a valid `r`, with
//! room to spare for a cheaper conversion. For a 128-bit `x` it is up to 2^12, and one Newton
//! step `r + (x − r²) / 2r`, its residual exact in integers and its quotient in `f64`, brings it
//! within 1/2 of `√x`. Elsewhere (Cortex-M, whose FPUs have no `f64` square root, and wasm32,
//! where libm's square root is software on stable Rust) `r = ⌊√x⌋` comes from core's `isqrt`,
//! or, for a 64-bit `x` on a core without a long multiply or a divide (Cortex-M0), from 32-bit
//! operations. Every way gives the same integer; the tests compare them bit for bit.

use super::narrow::split_mul_u32;

/// Whether `libm::sqrt` is one instruction on this target: libm's own condition for it.
const HARDWARE_SQRT: bool = cfg!(any(
    target_feature = "sse2",
    all(target_arch = "aarch64", target_feature = "neon")
));

/// `round(√x)` from core's exact `⌊√x⌋`.
macro_rules! exact_isqrt_nearest {
    ($name:ident, $u:ty) => {
        pub(super) fn $name(x: $u) -> $u {
            let r = x.isqrt();
            if x - r * r > r { r + 1 } else { r }
        }
    };
}
exact_isqrt_nearest!(exact_isqrt_nearest_64, u64);
exact_isqrt_nearest!(exact_isqrt_nearest_128, u128);

/// `round(√x)` for a 64-bit `x`. `I16F16`'s radicands fit 64 bits, and a 128-bit root costs a
/// Cortex-M0 several times a 64-bit one.
#[inline]
pub(super) fn isqrt_nearest_64(x: u64) -> u64 {
    if HARDWARE_SQRT {
        float_isqrt_nearest_64(x)
    } else if cfg!(ballcast_no_long_mul) {
        split_isqrt_nearest_64(x)
    } else {
        exact_isqrt_nearest_64(x)
    }
}

/// `⌊√x⌋` and `x − ⌊√x⌋²` digit by digit: each step takes two more bits of `x` and gives one
/// more bit of the root, by a shift, a compare and a subtraction (Warren, §11–1, the same
/// section). The remainder is at most `2 root`, below 2^17.
fn sqrtrem_32(mut x: u32) -> (u32, u32) {
    let (mut root, mut rem) = (0u32, 0u32);
    for _ in 0..16 {
        // (2 root + 1)² = 4 root² + 4 root + 1: the next bit is one if 4 rem + bits covers
        // 4 root + 1.
        rem = (rem << 2) | (x >> 30);
        x <<= 2;
        root <<= 1;
        let trial = (root << 1) | 1;
        if rem >= trial {
            rem -= trial;
            root |= 1;
        }
    }
    (root, rem)
}

/// `round(√x)` for a 64-bit `x` from 32-bit operations and one 32-bit division, for cores with
/// neither a 32 × 32 → 64 multiply nor a divide (`ballcast_no_long_mul`), where core's `isqrt`
/// calls software routines for both several times. Zimmermann's Karatsuba square root
/// (*Karatsuba Square Root*, INRIA RR-3805, 1999), one level: `x` shifted left by an even
/// `2k` until one of its top two bits is set; the root `s1` and remainder `r1` of its top half
/// digit by digit (`2^15 <= s1 < 2^16`); then the low half's 16 root bits `q` and remainder `u`
/// from `(r1 2^16 + a1) / 2 s1` (`a1`, `a0`: the low half's 16-bit halves), and the remainder
/// `u 2^16 + a0 − q²`, which one correction makes non-negative. The root shifted back by `k`
/// is `⌊√x⌋`.
pub(super) fn split_isqrt_nearest_64(x: u64) -> u64 {
    let round = |root: u32, rem: u64| root as u64 + (rem > root as u64) as u64;
    if x >> 32 == 0 {
        let (root, rem) = sqrtrem_32(x as u32);
        return round(root, rem as u64);
    }
    let (mut n, mut k) = (x, 0);
    while n >> 56 == 0 {
        n <<= 8;
        k += 4;
    }
    while n >> 62 == 0 {
        n <<= 2;
        k += 1;
    }
    let (s1, r1) = sqrtrem_32((n >> 32) as u32);
    let (a1, a0) = ((n as u32) >> 16, n as u32 & 0xFFFF);
    // (r1 2^16 + a1) / (2 s1) as ⌊(r1 2^15 + ⌊a1 / 2⌋) / s1⌋, which fits 32 bits (r1 < 2^17);
    // q <= 2^16 (r1 <= 2 s1 and 2 s1 >= 2^16).
    // `s1` is at least 2^15; a divisor the compiler cannot prove nonzero would leave a panic.
    let (half, s1d) = ((r1 << 15) | (a1 >> 1), s1.max(1));
    let (q, u) = (half / s1d, ((half % s1d) << 1) | (a1 & 1));
    let mut s = ((s1 as u64) << 16) + q as u64;
    let mut r = ((u as u64) << 16 | a0 as u64) as i64 - split_mul_u32(q, q) as i64;
    while r < 0 {
        r += 2 * s as i64 - 1;
        s -= 1;
    }
    // s = ⌊√n⌋ = ⌊√x 2^k⌋, so ⌊√x⌋ = ⌊s / 2^k⌋ (k <= 15, s < 2^32).
    let root = (s as u32) >> k;
    round(root, x - split_mul_u32(root, root))
}

/// `round(√x)` for a 128-bit `x`.
#[inline]
pub(super) fn isqrt_nearest_128(x: u128) -> u128 {
    if HARDWARE_SQRT {
        float_isqrt_nearest_128(x)
    } else {
        exact_isqrt_nearest_128(x)
    }
}

/// `round(√x)` from a float estimate of `√x`, made cheap to convert: `x` rounded down to even
/// fits an `i64` (one instruction to `f64`, where `u64` takes six), and the estimate is capped
/// at `u32::MAX` (four instructions back, where a `u64` takes fourteen).
pub(super) fn float_isqrt_nearest_64(x: u64) -> u64 {
    // Dropping the last bit moves √x down by under 0.42 for x >= 2 (and makes 0 of 1, whose
    // root rounds to 1); the conversion and the square root add under 2^-20. The floor is then
    // within [round(√x) − 1, round(√x)], and so is the cap: it applies only when
    // round(√x) = 2^32.
    let r = libm::sqrt((x >> 1) as i64 as f64 * 2.0) as u32 as u64;
    // |x − r²| <= 2r + 1 < 2^34: the wrapped difference is the exact one.
    let d = x.wrapping_sub(r * r) as i64;
    if d > r as i64 { r + 1 } else { r }
}

/// `round(√x)` from a float estimate within 2^13 of `√x` and one Newton step (module docs).
pub(super) fn float_isqrt_nearest_128(x: u128) -> u128 {
    const P32: f64 = (1u64 << 32) as f64;
    const P64: f64 = P32 * P32;
    // `x` to `f64` in two halves, three roundings (core's conversion is a library call): the
    // estimate is off √x by at most 2.5 · 2^-53 · 2^64 + 1 < 2^13; the cast saturates.
    let r0 = libm::sqrt((x >> 64) as u64 as f64 * P64 + x as u64 as f64) as u64;
    // x − r0² = (√x − r0)(√x + r0), below 2^13 · 2^65 in magnitude: exact as a wrapped `i128`,
    // and its halves exact in `f64`, so their sum rounds once.
    let d0 = x.wrapping_sub(r0 as u128 * r0 as u128) as i128;
    let d0 = (d0 >> 32) as i64 as f64 * P32 + d0 as u32 as f64;
    // The step lands at √x + (√x − r0)² / 2r0, above √x by less than 1/2 for every x (by under
    // 2^-26 where the estimate is off by more than one), give or take 2^-37 of rounding: its
    // floor is a valid estimate. Offset by 2^14 the step is positive and below 2^15, so `as`
    // takes the floor (`u32`: a shorter conversion than `u64`).
    let step = (d0 / (2.0 * r0.max(1) as f64) + 16384.0) as u32;
    let r = (r0 as u128 + step as u128).wrapping_sub(16384);
    // |x − r²| <= 2r + 1: exact as a wrapped `i128`.
    let d = x.wrapping_sub(r.wrapping_mul(r)) as i128;
    if d > r as i128 { r + 1 } else { r }
}

#[cfg(test)]
mod tests;
