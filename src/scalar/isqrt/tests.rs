//! The float-estimate and 32-bit square roots against core's exact integer square
//! root, bit for bit: every target must give the same integer.

use super::{
    exact_isqrt_nearest_64, exact_isqrt_nearest_128, float_isqrt_nearest_64,
    float_isqrt_nearest_128, newton_isqrt_nearest_64,
};

use crate::xorshift::Rng;

/// `k² + j` for `j` in `-2..=2`, and the rounding boundaries `k² + k` and `k² + k + 1`, kept
/// to those that fit: the operands where an estimate off by one would show.
fn near_squares(k: u128) -> impl Iterator<Item = u128> {
    let sq = k.checked_mul(k);
    let around = (0..5).filter_map(move |j| sq?.checked_add(j)?.checked_sub(2));
    let bounds = (0..2).filter_map(move |j| sq?.checked_add(k)?.checked_add(j));
    around.chain(bounds)
}

fn check_64(x: u64) {
    let exact = exact_isqrt_nearest_64(x);
    assert_eq!(float_isqrt_nearest_64(x), exact, "float {x}");
    assert_eq!(newton_isqrt_nearest_64(x), exact, "newton {x}");
}

fn check_128(x: u128) {
    assert_eq!(
        float_isqrt_nearest_128(x),
        exact_isqrt_nearest_128(x),
        "{x}"
    );
}

#[test]
fn isqrt_64_is_exact_at_the_extremes() {
    let top = u64::MAX as u128;
    let roots = (0..70).map(|k| k as u128).chain((0..=32).flat_map(|b| {
        let p = 1u128 << b;
        [p - 1, p, p + 1]
    }));
    for k in roots.chain([u32::MAX as u128, (1 << 32) - 2]) {
        for x in near_squares(k).filter(|&x| x <= top) {
            check_64(x as u64);
        }
    }
    for x in (0..64).flat_map(|b| [(1u64 << b) - 1, 1 << b, (1 << b) + 1]) {
        check_64(x);
    }
    for j in 0..100_000 {
        check_64(j);
        check_64(u64::MAX - j);
    }
}

#[test]
fn isqrt_64_is_exact_on_random_operands() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for _ in 0..1_000_000 {
        let (x, s) = (rng.next(), rng.next());
        // Every magnitude, and squares and rounding boundaries of random roots.
        check_64(x >> (s % 64));
        let k = (x >> 32) >> ((s >> 8) % 32);
        for y in near_squares(k as u128).filter(|&y| y <= u64::MAX as u128) {
            check_64(y as u64);
        }
    }
}

#[test]
fn float_isqrt_128_is_exact_at_the_extremes() {
    let roots = (0..70).map(|k| k as u128).chain((0..=64).flat_map(|b| {
        let p = 1u128 << b;
        [p - 1, p, p + 1]
    }));
    for k in roots.chain([u64::MAX as u128 - 1, (1 << 52) + 1, 3 << 62]) {
        for x in near_squares(k) {
            check_128(x);
        }
    }
    for x in (0..128).flat_map(|b| [(1u128 << b) - 1, 1 << b, (1 << b) + 1]) {
        check_128(x);
    }
    for j in 0..100_000 {
        check_128(j);
        check_128(u128::MAX - j);
        // Past the last square (2^64 − 1)², whose nearest root is 2^64 for the upper half.
        check_128(u128::MAX - (1 << 64) - j);
    }
}

#[test]
fn float_isqrt_128_is_exact_on_random_operands() {
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    for _ in 0..1_000_000 {
        let (x, s) = ((rng.next() as u128) << 64 | rng.next() as u128, rng.next());
        check_128(x >> (s % 128));
        let k = (x >> 64) >> ((s >> 8) % 64);
        for y in near_squares(k) {
            check_128(y);
        }
    }
}
