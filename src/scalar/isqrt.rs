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
//! or, for a 64-bit `x` on a core without a long multiply or a divide (Cortex-M0), from a
//! reciprocal square root found by Newton's method in 32-bit multiplies. Every way gives the
//! same integer; the tests compare them bit for bit.

use super::narrow::{high_mul_u32, split_mul_u32};

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
pub(crate) fn isqrt_nearest_64(x: u64) -> u64 {
    if HARDWARE_SQRT {
        float_isqrt_nearest_64(x)
    } else if cfg!(ballcast_no_long_mul) {
        newton_isqrt_nearest_64(x)
    } else {
        exact_isqrt_nearest_64(x)
    }
}

/// `2^47 / √t` to 8 bits, for `t` in `[2^30, 2^32)` by its top 8 bits `i` (64 to 255), at the
/// middle of their interval: `⌊√(2^94 / (i + 1/2) 2^24)⌋`, its top 16 of 32 bits.
const RSQRT: [u16; 192] = {
    let mut table = [0; 192];
    let mut i = 0;
    while i < 192 {
        table[i] = (((1u128 << 71) / (2 * i as u128 + 129)).isqrt() >> 16) as u16;
        i += 1;
    }
    table
};

/// `round(√x)` for a 64-bit `x` from 32-bit multiplies, for cores with neither a 32 × 32 → 64
/// multiply nor a divide (`ballcast_no_long_mul`), where core's `isqrt` calls software routines
/// for both several times. `x` shifted left by an even `2k` until one of its top two bits is
/// set, `n`; its top half `t` gives `y ≈ 2^47 / √t` from [`RSQRT`] and two Newton steps
/// `y (3 − t y² / 2^94) / 2`, each of three high products (Newton–Raphson on the reciprocal
/// square root needs no division: Ercegovac and Lang, *Digital Arithmetic*, 2004); then
/// `t y / 2^31 ≈ √n`, shifted back by `k`. That estimate is off by a few units (the steps'
/// products are truncated), which the exact remainder `x − r²` corrects one unit at a time;
/// the remainder then gives the rounding.
pub(super) fn newton_isqrt_nearest_64(x: u64) -> u64 {
    if x == 0 {
        return 0;
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
    let t = (n >> 32) as u32;
    let mut y = (RSQRT[(t >> 24) as usize - 64] as u32) << 16;
    for _ in 0..2 {
        // t y² / 2^64 is 2^30 within the estimate's error: 3 2^30 less it stays positive. At
        // t = 2^30 the step would reach 2^32: capped a unit short.
        let e = high_mul_u32(t, high_mul_u32(y, y));
        y = high_mul_u32(y, (3 << 30) - e).min(u32::MAX >> 1) << 1;
    }
    // t y / 2^31 shifted back by k, in 32 bits: √x < 2^32, so the cap only brings it nearer.
    let s = high_mul_u32(t, y);
    let mut r = if k == 0 {
        s.saturating_add(s)
    } else {
        s >> (k - 1)
    };
    // A few units from √x, so x − r² is far inside an i64; (r + 1)² − r² = 2r + 1.
    let mut d = x.wrapping_sub(split_mul_u32(r, r)) as i64;
    while d < 0 {
        r -= 1;
        d += 2 * r as i64 + 1;
    }
    while d > 2 * r as i64 {
        d -= 2 * r as i64 + 1;
        r += 1;
    }
    r as u64 + (d > r as i64) as u64
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
