//! `I16F16`'s double-width arithmetic from 32-bit operations, for cores without a 32 × 32 → 64
//! multiply or a divide instruction (Armv6-M, e.g. the Cortex-M0; `ballcast_no_long_mul`, see
//! `build.rs`): products from 16 × 16 → 32-bit partial products, quotients from a remainder
//! found by shift-and-subtract and an exact division by the divisor's odd part (or, for a few
//! more bits of one, steps that gather them), a unit vector's reciprocal length by Newton's
//! method. Each function
//! gives exactly the integer of the 64-bit arithmetic it replaces (`wide.rs` chooses per
//! target), so results are bit-identical on every target; the tests compare them bit for bit.

/// `round(a · b / 2^30)` to nearest, ties away from zero, for `|b| <= 2^30` (a unit vector's
/// bits) and `|a| <= 2^31 - 2^16`, where the result is representable: `I16F16`'s `dot_unit`,
/// the same integer as from the exact 64-bit sum `S`, with no 64-bit addition.
///
/// The low 32 bits of `S` are the wrapping sum of the 32-bit products. Above them, an estimate
/// in units of 2^27 from three partial products per component (`a = ah 2^16 + al`,
/// `b = bh 2^15 + bl`, low parts signed: `al` 16 bits, `bl` 15 bits, so `al bl` is small)
/// is short of `S / 2^27` by less than 15 units and over by less than 12 (the dropped `al bl`,
/// below 2^29 each, and three floors); `floor(S / 2^27)` modulo 32, from the low bits, then
/// fixes it exactly.
pub(super) fn split_dot_unit_i32(a: [i32; 3], b: [i32; 3]) -> i32 {
    // `mid` starts 12 units low: the estimate below is then 12 under, and its fix non-negative.
    let (mut low, mut high, mut mid) = (0u32, 0i32, -12i32);
    for i in 0..3 {
        let (a, b) = (a[i], b[i]);
        low = low.wrapping_add((a as u32).wrapping_mul(b as u32));
        let (al, bl) = (a as i16 as i32, (b << 17) >> 17);
        let (ah, bh) = (a.wrapping_sub(al) >> 16, b.wrapping_sub(bl) >> 15);
        // |ah| < 2^15, |bh| <= 2^15, |al| <= 2^15, |bl| <= 2^14: |2 ah bl + al bh| < 2^31.
        high = high.wrapping_add(ah.wrapping_mul(bh));
        mid += (2 * ah * bl).wrapping_add(al.wrapping_mul(bh)) >> 12;
    }
    // S = 2^31 high + 2^15 sum(2 ah bl + al bh) + sum(al bl); in units of 2^27 the estimate
    // 16 high + mid + 12 is off floor(S / 2^27) by -12 to 14, so 16 high + mid by 0 to 26.
    let estimate = high.wrapping_mul(16).wrapping_add(mid);
    let fix = ((low >> 27) as i32).wrapping_sub(estimate) & 31;
    let whole = high.wrapping_mul(2).wrapping_add((mid + fix) >> 3);
    // `whole` is floor(S / 2^30); the low 30 bits of S decide the rounding, ties away from zero.
    let frac = low & ((1 << 30) - 1);
    whole.wrapping_add(((frac + (1 << 29) - (whole < 0) as u32) >> 30) as i32)
}

/// `a * b` exactly, from four 16 × 16 → 32-bit products (the only multiply a Cortex-M0 has is
/// 32 × 32 → 32).
#[inline]
pub(super) fn split_mul_i32(a: i32, b: i32) -> i64 {
    // a = ah 2^16 + al with ah in [-2^15, 2^15) and al in [0, 2^16); likewise b.
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    // |ah bh| <= 2^30; |ah bl|, |al bh| < 2^31; al bl < 2^32 (unsigned): none overflows.
    let mid = (ah * bl) as i64 + (al * bh) as i64;
    (((ah * bh) as i64) << 32) + (mid << 16) + (al as u32 * bl as u32) as i64
}

/// `round(s b / 2^16)` to nearest, ties away from zero, for `|s| < 2^16`: `I16F16`'s `mul`
/// with one factor below one. With `b = bh 2^16 + bl`, `bl` the signed low half (in
/// `[-2^15, 2^15)`, so `bh` is at most `2^15`), both `s bh` and `s bl` fit 32 bits, and
/// `s b + 2^15 - [s b < 0]` shifted right by 16 (a floor) is the rounded quotient: `s bh` whole
/// plus the shifted rest, with no branch on a sign. The rest is shifted in two steps, as
/// `s bl + 2^15` reaches `2^31` (for `s = 1 - 2^16`, `bl = -2^15`).
#[inline]
pub(super) fn small_mul_i32(s: i32, b: i32) -> i32 {
    let bl = b as i16 as i32;
    // (b - bl) / 2^16 without its overflow for b near i32::MAX: bit 15 of b set makes bl
    // negative, and bh one more than b's top half.
    let bh = (b >> 16) - ((b << 16) >> 31);
    // The product's sign; a zero product has `s bl` zero and rounds to zero either way.
    let negative = ((s ^ b) as u32 >> 31) as i32;
    s * bh + ((((s * bl - negative) >> 1) + (1 << 14)) >> 15)
}

/// `a * b` exactly for unsigned operands, as [`split_mul_i32`].
#[inline]
pub(super) fn split_mul_u32(a: u32, b: u32) -> u64 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (bh, bl) = (b >> 16, b & 0xFFFF);
    let mid = (ah * bl) as u64 + (al * bh) as u64;
    (((ah * bh) as u64) << 32) + (mid << 16) + (al * bl) as u64
}

/// `round(a n / d)` to nearest, ties away from zero, saturating, for each `a`: exactly what
/// `mul_div` gives. `F = floor(|n| 2^k / |d|)` (`|n| < |d|` so `F < 2^k`)
/// gives an estimate `floor(|a| F / 2^k)` short of `floor(|a n| / |d|)` by at most one
/// (`|a| / 2^k < 1/2` lost to F, one to the floor) once `|a| < 2^(k-1)`: `k` is 16, or more in
/// steps of 4 up to 32 for longer vectors. The exact remainder `|a n| - q |d|` corrects the
/// estimate and decides the rounding. `q` is `round(n 2^16 / d)`, the fraction as
/// [`split_div_i32`] rounds it, which gives `F` for `k = 16` ([`floor_of_rounded`]) with no
/// division steps; [`quotient_steps`] extend it four bits at a time. `None` for `|n| >= |d|`
/// and for an `a` of `i32::MIN`, the only one whose result can saturate (no sweep's motion
/// reaches it): so that no other pays for the test.
pub(super) fn split_scale_fraction_i32(a: [i32; 3], n: i32, d: i32, q: i32) -> Option<[i32; 3]> {
    let (nm, dm) = (n.unsigned_abs(), d.unsigned_abs());
    let top = a.iter().fold(0, |m, c| m | c.unsigned_abs());
    if nm >= dm || top >> 31 != 0 {
        return None;
    }
    let (mut f, mut r) = floor_of_rounded(nm, dm, q.unsigned_abs());
    let mut k = 16;
    while k < 32 && top >> (k - 1) != 0 {
        (f, r) = quotient_steps::<4>(f, r, dm);
        k += 4;
    }
    Some(a.map(|a| scale_one(a, n, d, (f << (32 - k), dm))))
}

/// `floor(n 2^16 / d)` and its remainder for `n < d <= 2^31`, given `q`, that quotient rounded
/// to nearest (so the floor or one more): `n 2^16 - q d` is then the remainder or the remainder
/// less `d`, within `(-d, d)`, and its value modulo 2^32 tells the two apart (the second wraps
/// to `2^32 - d` or more, at least `d`).
#[inline]
fn floor_of_rounded(n: u32, d: u32, q: u32) -> (u32, u32) {
    let r = (n << 16).wrapping_sub(q.wrapping_mul(d));
    if r >= d {
        (q.wrapping_sub(1), r.wrapping_add(d))
    } else {
        (q, r)
    }
}

/// One component of [`split_scale_fraction_i32`], with `(F, |d|)`.
#[inline]
fn scale_one(a: i32, n: i32, d: i32, (f, dm): (u32, u32)) -> i32 {
    let am = a.unsigned_abs();
    let mut q = high_mul_u32(am, f);
    // q <= floor(|a n| / dm) <= q + 1, so 0 <= rem < 2 dm <= 2^32: the remainder is its own
    // value modulo 2^32, which 32-bit products give.
    let mut rem = am
        .wrapping_mul(n.unsigned_abs())
        .wrapping_sub(q.wrapping_mul(dm));
    if rem >= dm {
        q += 1;
        rem -= dm;
    }
    // Half or more of the divisor left: away from zero. q <= |a| < 2^31 afterwards: it and
    // its negation fit.
    let q = (q + (rem >= dm - rem) as u32) as i32;
    if (a ^ n ^ d) < 0 { -q } else { q }
}

/// `floor(a f / 2^32)`, from four 16 × 16 → 32-bit products: `ah fl` plus the carry of the low
/// product is at most `(2^16 − 1)² + 2^16 − 1 < 2^32`, and the two middle products are added
/// in halves. (The textbook form, one middle sum with a carry, is recognised by LLVM as a
/// 64-bit multiply and becomes a call to `__aeabi_lmul`.)
#[inline]
pub(super) fn high_mul_u32(a: u32, f: u32) -> u32 {
    let (ah, al) = (a >> 16, a & 0xFFFF);
    let (fh, fl) = (f >> 16, f & 0xFFFF);
    let hl = ah * fl + ((al * fl) >> 16);
    let lh = al * fh;
    let carry = ((hl & 0xFFFF) + (lh & 0xFFFF)) >> 16;
    ah * fh + (hl >> 16) + (lh >> 16) + carry
}

/// `round(n 2^16 / d)` to nearest, ties away from zero, saturating (a zero divisor gives the
/// largest value of `n`'s sign, or zero): exactly what the generic 64-bit path of
/// [`Scalar::div`](super::Scalar::div) gives, from 32-bit operations. The integer part is one
/// 32-bit division (none when `|n| < |d|`, as for a fraction of a path), the 16 fractional
/// bits are [`shifted_div`].
pub(super) fn split_div_i32(n: i32, d: i32) -> i32 {
    let max = if (n < 0) == (d < 0) {
        i32::MAX
    } else {
        i32::MIN
    };
    if d == 0 {
        return if n == 0 { 0 } else { max };
    }
    let (a, d) = (n.unsigned_abs(), d.unsigned_abs());
    let (whole, r) = if a < d { (0, a) } else { (a / d, a % d) };
    // A quotient of 2^31 or more saturates (after rounding, too).
    if whole >= 1 << 15 {
        return max;
    }
    let (frac, r) = shifted_div::<16>(r, d);
    let mut q = (whole << 16) | frac;
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

/// `round(c 2^30 / len)` to nearest, ties away from zero, for each `c`: exactly what `I16F16`'s
/// generic unit normalisation gives (`(c 2^30 ± len/2) / len` in 64 bits) for a vector whose
/// largest component lies in `[1/2, 1]` (`|c| <= 2^30`, so `2^29 < len < 2^31` but for an
/// exact `±2^29` alone). One reciprocal `F = floor(2^61 / len)` is shared by the three: with it
/// `floor(|c| F / 2^32)` is short of `Q = floor(|c| 2^29 / len)` by at most one, which the
/// exact remainder (below `2 len`, so right modulo 2^32) fixes; `2 Q` plus one more bit of the
/// remainder is the quotient by `2^30`, and the rest decides the rounding. `None` outside that
/// domain, where the generic path runs.
pub(super) fn split_normalize_i32(c: [i32; 3], len: u32) -> Option<[i32; 3]> {
    const HALF: u32 = 1 << 29;
    if len <= HALF || len >= 1 << 31 || c.iter().any(|c| c.unsigned_abs() > 1 << 30) {
        return None;
    }
    let f = reciprocal_61(len);
    Some(c.map(|c| {
        let a = c.unsigned_abs();
        let mut q = high_mul_u32(a, f);
        let mut rem = (a << 29).wrapping_sub(q.wrapping_mul(len));
        if rem >= len {
            q += 1;
            rem -= len;
        }
        // |c| 2^30 = (2 q) len + 2 rem, with 2 rem < 2 len < 2^32.
        let (mut q, mut rem) = (2 * q, 2 * rem);
        if rem >= len {
            q += 1;
            rem -= len;
        }
        // At most 2^31 (|c| <= 2^30 < 2 len); the casts wrap as the generic path's do.
        let q = (q + (rem >= len - rem) as u32) as i32;
        if c < 0 { q.wrapping_neg() } else { q }
    }))
}

/// `2^63 / D` to about 8 bits, for `D` in `[2^31, 2^32)` by its 7 bits after the leading one
/// (`i`), at the middle of their interval: `⌊2^63 / (2^31 + (i + 1/2) 2^24)⌋`, its top 16 of
/// 32 bits.
const RECIPROCAL: [u16; 128] = {
    let mut table = [0; 128];
    let mut i = 0;
    while i < 128 {
        table[i] = (((1u64 << 63) / ((1 << 31) + (2 * i as u64 + 1) * (1 << 23))) >> 16) as u16;
        i += 1;
    }
    table
};

/// `⌊2^61 / len⌋` for `2^29 < len < 2^31`: the reciprocal [`split_normalize_i32`] shares among
/// a vector's components, from 32-bit multiplies and no division. `len` shifted to
/// `D` in `[2^31, 2^32)` gives `x ≈ 2^63 / D` from [`RECIPROCAL`] and two Newton steps
/// `x (2 − D x / 2^63)`, each of two high products (Newton–Raphson on the reciprocal: Ercegovac
/// and Lang, *Digital Arithmetic*, 2004); the exact remainder `2^63 − D x` then corrects `x` one
/// unit at a time. Thirty-two shift-and-subtract steps and an exact division cost a Cortex-M0
/// about half as much again.
pub(super) fn reciprocal_61(len: u32) -> u32 {
    // At len = 2^30 the quotient 2^63 / D would be 2^32.
    if len == 1 << 30 {
        return 1 << 31;
    }
    let z = if len < 1 << 30 { 2 } else { 1 };
    let d = len << z;
    let mut x = (RECIPROCAL[((d >> 24) & 0x7F) as usize] as u32) << 16;
    for _ in 0..2 {
        // D x / 2^32 is 2^31 within the estimate's error; the step scales x by 1 + e / 2^31.
        let e = (1i64 << 31) - high_mul_u32(d, x) as i64;
        let step = high_mul_u32(x, e.unsigned_abs() as u32) << 1;
        x = if e < 0 {
            x.saturating_sub(step)
        } else {
            x.saturating_add(step)
        };
    }
    // A few units from ⌊2^63 / D⌋ (below 2^32: D > 2^31 here), so the remainder is small.
    let product = ((high_mul_u32(d, x) as u64) << 32) | d.wrapping_mul(x) as u64;
    let mut rem = (1u64 << 63).wrapping_sub(product) as i64;
    while rem < 0 {
        x -= 1;
        rem += d as i64;
    }
    while rem >= d as i64 {
        x += 1;
        rem -= d as i64;
    }
    // ⌊2^61 / len⌋ = ⌊2^(61 + z) / D⌋: the quotient by 2^63, or half of it, floored.
    x >> (2 - z)
}

/// `(q, r)` with `n 2^K = q d + r` and `0 <= r < d`, for `n < d <= 2^31` (so `q < 2^K`),
/// `K <= 32`: [`remainder_steps`], then [`exact_quotient`].
fn shifted_div<const K: u32>(n: u32, d: u32) -> (u32, u32) {
    let r = remainder_steps::<K>(n, d);
    (exact_quotient(n, r, d, K), r)
}

/// `(r 2^S) mod d` for `r < d <= 2^31`: `S` shift-and-subtract steps that keep only the
/// remainder (three or four instructions a step on a Cortex-M0; gathering the quotient's bits
/// as well, [`quotient_steps`], costs about twice that).
#[inline]
fn remainder_steps<const S: u32>(mut r: u32, d: u32) -> u32 {
    for _ in 0..S {
        // r < d <= 2^31, so 2r fits.
        r <<= 1;
        if r >= d {
            r -= d;
        }
    }
    r
}

/// `S` more bits of a quotient `q` with remainder `r < d <= 2^31`: `(2^S q + Q, R)` where
/// `r 2^S = Q d + R`, by shift-and-subtract steps that gather the quotient's bits, branch-free
/// (eight instructions a step on a Cortex-M0). For a few bits (a fraction extended by 4 to 16)
/// this beats [`remainder_steps`] and an [`exact_quotient`], whose inverse alone costs about
/// as much as six steps.
#[inline]
fn quotient_steps<const S: u32>(mut q: u32, mut r: u32, d: u32) -> (u32, u32) {
    for _ in 0..S {
        // 2r - d lies in (-d, d), so its sign bit says whether 2r < d (all ones: keep 2r).
        let t = (r << 1).wrapping_sub(d);
        let short = ((t as i32) >> 31) as u32;
        r = t.wrapping_add(d & short);
        q = (q << 1).wrapping_add(1).wrapping_add(short);
    }
    (q, r)
}

/// The quotient `q` of `n 2^k = q d + r` (`n < d <= 2^31`, `k <= 32`) from the remainder `r`:
/// an exact division, `q d = n 2^k - r`, shifted right by the trailing zeros `t` of `d` and
/// multiplied by the inverse of the odd `d / 2^t` modulo 2^32.
#[inline]
fn exact_quotient(n: u32, r: u32, d: u32, k: u32) -> u32 {
    // Both terms of (n 2^k - r) / 2^t are whole: r = n 2^k - q d is a multiple of 2^t, so is
    // n 2^k. Their difference is q (d / 2^t), taken modulo 2^32 without a 64-bit shift.
    let t = d.trailing_zeros();
    let high = if t < k {
        (n << (k - 1 - t)) << 1
    } else {
        n >> (t - k)
    };
    let exact = high.wrapping_sub(r >> t);
    // q < 2^k: its low k bits are all of it, and they need the inverse only modulo 2^k.
    let q = exact.wrapping_mul(odd_inverse(d >> t, k));
    q & (u32::MAX >> (32 - k))
}

/// The inverse of an odd `d` modulo 2^bits (`bits <= 32`; the result is right in at least its
/// low `bits` bits): `3d XOR 2` is one modulo 2^5, and each Newton step `x (2 - d x)` doubles
/// the bits that are right (Montgomery; Warren, Hacker's Delight, 10-16), two steps for 20
/// bits, three for 40.
#[inline]
fn odd_inverse(d: u32, bits: u32) -> u32 {
    let mut x = d.wrapping_mul(3) ^ 2;
    for _ in 0..if bits <= 20 { 2 } else { 3 } {
        x = x.wrapping_mul(2u32.wrapping_sub(d.wrapping_mul(x)));
    }
    x
}

#[cfg(test)]
mod tests;
