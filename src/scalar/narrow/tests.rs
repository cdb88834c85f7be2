//! The 32-bit paths against the 64-bit arithmetic they replace, bit for bit.

use super::{
    high_mul_u32, odd_inverse, reciprocal_61, shifted_div, small_mul_i32, split_div_i32,
    split_dot_unit_i32, split_mul_i32, split_mul_u32, split_normalize_i32,
    split_scale_fraction_i32,
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
        let a = a.min(1 << 31);
        assert_eq!(
            high_mul_u32(a, b) as u64,
            (a as u64 * b as u64) >> 32,
            "{a} {b}"
        );
    }
    for (a, b) in [
        (1 << 31, u32::MAX),
        (1 << 31, 0),
        ((1 << 31) - 1, u32::MAX),
        (65535, u32::MAX),
    ] {
        assert_eq!(
            high_mul_u32(a, b) as u64,
            (a as u64 * b as u64) >> 32,
            "{a} {b}"
        );
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
            // Sometimes all three below 2^15: the fraction taken straight from the quotient.
            (x >> 24) as i32 >> (k / 5 % 31),
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
        if let Some(got) = split_scale_fraction_i32(a, n, d, split_div_i32(n, d)) {
            assert_eq!(got, want, "{a:?} * {n} / {d}");
        } else {
            assert!(n.unsigned_abs() >= d.unsigned_abs() || a.contains(&i32::MIN));
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
            // i32::MIN, which may saturate, is left to `mul_div` itself.
            let want = (a != i32::MIN).then_some([want; 3]);
            assert_eq!(
                split_scale_fraction_i32([a; 3], n, d, split_div_i32(n, d)),
                want,
                "{a} * {n} / {d}"
            );
        }
    }
}

/// `round(a · b / 2^30)` from the exact 64-bit sum, where it is representable.
fn dot_unit_64(a: [i32; 3], b: [i32; 3]) -> Option<i32> {
    let s: i64 = (0..3).map(|i| a[i] as i64 * b[i] as i64).sum();
    let r = if s < 0 {
        -((-s + (1 << 29)) >> 30)
    } else {
        (s + (1 << 29)) >> 30
    };
    i32::try_from(r).ok()
}

/// The 32-bit dot product with a unit vector equals the 64-bit one wherever that is
/// representable: pseudo-random vectors of every magnitude, the extremes, and ties.
#[test]
fn split_dot_unit_is_exact() {
    let top = i32::MAX - (1 << 16) + 1;
    let mut x: u64 = 0x243F_6A88_85A3_08D3;
    let mut checked = 0;
    for k in 0..2_000_000u32 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let y = x.rotate_left(23);
        let a = [x as i32, (x >> 21) as i32, y as i32].map(|c| (c >> (k % 31)).clamp(-top, top));
        let b =
            [(x >> 32) as i32, (y >> 32) as i32, (y >> 11) as i32].map(|c| c >> (1 + k / 31 % 30));
        if let Some(want) = dot_unit_64(a, b) {
            assert_eq!(split_dot_unit_i32(a, b), want, "{a:?} · {b:?}");
            checked += 1;
        }
    }
    assert!(checked > 1_000_000, "{checked}");
    let (u, h) = (1 << 30, 1 << 29);
    for a in [top, -top, 1, -1, 0, 3, -3, 1 << 16, -(1 << 16)] {
        for b in [
            [u, 0, 0],
            [-u, 0, 0],
            [h, 0, 0],
            [-h, 0, 0],
            [0, h + 1, 0],
            [h, h, h],
        ] {
            for a in [[a, 0, 0], [a, a, 0], [a, -a, a]] {
                if let Some(want) = dot_unit_64(a, b) {
                    assert_eq!(split_dot_unit_i32(a, b), want, "{a:?} · {b:?}");
                }
            }
        }
    }
}

/// The inverse is right for every odd 16-bit number and for pseudo-random 32-bit ones; the
/// shifted division equals the 64-bit one, with divisors of every trailing-zero count.
#[test]
fn shifted_division_is_exact() {
    for d in (1..1u32 << 16).step_by(2) {
        assert_eq!(d.wrapping_mul(odd_inverse(d, 32)), 1, "{d}");
        assert_eq!(d.wrapping_mul(odd_inverse(d, 20)) & 0xF_FFFF, 1, "{d}");
    }
    let mut x: u64 = 0xB7E1_5162_8AED_2A6B;
    for k in 0..1_000_000u32 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let odd = x as u32 | 1;
        assert_eq!(odd.wrapping_mul(odd_inverse(odd, 32)), 1, "{odd}");
        // 0 < d <= 2^31, of every magnitude and every count of trailing zeros; n < d.
        let d = ((((x >> 32) as u32 | 1) << (k % 32)).min(1 << 31) >> (k / 32 % 31)).max(1);
        let n = (x as u32) % d;
        let (q, r) = shifted_div::<16>(n, d);
        let w = ((n as u64) << 16) / d as u64;
        assert_eq!(
            (q as u64, r as u64),
            (w, ((n as u64) << 16) % d as u64),
            "{n} {d}"
        );
        let (q, r) = shifted_div::<32>(n, d);
        let w = ((n as u64) << 32) / d as u64;
        assert_eq!(
            (q as u64, r as u64),
            (w, ((n as u64) << 32) % d as u64),
            "{n} {d}"
        );
    }
    for d in [1, 2, 3, 1 << 30, (1 << 31) - 1, 1 << 31] {
        for n in [0, 1, d / 2, d - 1].into_iter().filter(|&n| n < d) {
            let w = ((n as u64) << 32) / d as u64;
            assert_eq!(shifted_div::<32>(n, d).0 as u64, w, "{n} {d}");
        }
    }
}

/// The product with a factor below one equals `I16F16`'s generic `mul` (the 64-bit path
/// on this host): pseudo-random
/// pairs of every magnitude, the extremes, and ties.
#[test]
fn small_mul_is_exact() {
    let generic = |s: i32, b: i32| I16F16::from_bits(s).mul(I16F16::from_bits(b)).to_bits();
    let mut x: u64 = 0x1319_8A2E_0370_7344;
    for k in 0..1_000_000u32 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let s = (x as i32) >> (15 + k % 17);
        let b = ((x >> 32) as i32) >> (k / 17 % 31);
        assert_eq!(small_mul_i32(s, b), generic(s, b), "{s} {b}");
    }
    let top = (1 << 16) - 1;
    for s in [top, -top, 1, -1, 0, 1 << 15, -(1 << 15)] {
        for b in [
            i32::MIN,
            i32::MIN + 1,
            i32::MAX,
            -1,
            0,
            1,
            1 << 15,
            -(1 << 15),
            3 << 15,
        ] {
            assert_eq!(small_mul_i32(s, b), generic(s, b), "{s} {b}");
        }
    }
}

/// The generic unit normalisation of `I16F16` (`fixed.rs`): `(c 2^30 ± len/2) / len` in 64 bits.
fn normalize_64(c: i32, len: u32) -> i32 {
    let (num, len) = ((c as i64) << 30, len as i64);
    let half = if num < 0 { -(len / 2) } else { len / 2 };
    ((num + half) / len) as i32
}

/// The shared-reciprocal normalisation equals three 64-bit divisions (no exact ties arise: the
/// power of two in `len < 2^31` is below that of `c 2^31`): on the domain's edges, on 10^6 unit-scaled vectors with their own rounded length and on 10^6
/// components and lengths drawn anywhere in the domain; outside it, it declines.
#[test]
fn split_normalize_is_exact() {
    let check = |c: [i32; 3], len: u32| {
        let want = c.map(|c| normalize_64(c, len));
        assert_eq!(split_normalize_i32(c, len), Some(want), "{c:?} {len}");
    };
    let lens = [
        (1 << 29) + 1,
        (1 << 29) + 2,
        3 << 29,
        (1 << 30) - 1,
        1 << 30,
        (1 << 31) - 1,
    ];
    let cs = [
        -(1 << 30),
        -(1 << 30) + 1,
        -(1 << 29),
        -1,
        0,
        1,
        1 << 29,
        (1 << 30) - 1,
        1 << 30,
    ];
    for len in lens {
        for c in cs {
            check([c, -c, c / 3], len);
        }
    }
    // The nearest approaches to a tie: remainders `(len ± 1) / 2` for odd lengths, from
    // `c = rem / 2^30 (mod len)` (2^30 is invertible modulo an odd length).
    for len in [(1 << 29) + 1, (1 << 29) + 12_345, (1 << 30) - 3] {
        let step = (1u64 << 30) % len as u64;
        for want in [len as u64 / 2, (len as u64).div_ceil(2)] {
            // c 2^30 = want (mod len): c from the extended Euclidean algorithm on (step, len).
            let (mut r0, mut r1, mut t0, mut t1) = (len as i128, step as i128, 0i128, 1i128);
            while r1 != 0 {
                let q = r0 / r1;
                (r0, r1) = (r1, r0 - q * r1);
                (t0, t1) = (t1, t0 - q * t1);
            }
            let c = (t0.rem_euclid(len as i128) * want as i128 % len as i128) as i32;
            assert_eq!(((c as u64) << 30) % len as u64, want);
            check([c, -c, 0], len);
        }
    }
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        x
    };
    for _ in 0..1_000_000 {
        let r = next();
        // A vector scaled as `unit_normalize` receives it: largest magnitude in [2^29, 2^30].
        let big = (1 << 29) + (r as u32 >> 3) as i32 % ((1 << 29) + 1);
        let small = |w: u64| ((w as u32 as i64 % (2 * big as i64 + 1)) - big as i64) as i32;
        let c = [
            big * if r >> 63 == 0 { 1 } else { -1 },
            small(r >> 32),
            small(next()),
        ];
        let len2: u64 = c.iter().map(|&c| (c as i64 * c as i64) as u64).sum();
        check(c, crate::scalar::isqrt::isqrt_nearest_64(len2) as u32);
        let r = next();
        let len = (1 << 29) + 1 + (r as u32) % ((3 << 29) - 1);
        let c = |w: u64| (w as u32 % ((1 << 31) + 1)) as i32 - (1 << 30);
        check([c(r >> 32), c(next()), c(next())], len);
    }
    for (c, len) in [
        ([1 << 29, 0, 0], 1 << 29),
        ([(1 << 30) + 1, 0, 0], 1 << 30),
        ([0; 3], 1 << 31),
    ] {
        assert_eq!(split_normalize_i32(c, len), None, "{c:?} {len}");
    }
}

/// `reciprocal_61` against the 64-bit division: every length near the ends of its domain and
/// near each of the table's intervals' ends, and 10^6 pseudo-random ones.
#[test]
fn reciprocal_is_exact() {
    let check = |len: u32| {
        assert_eq!(
            reciprocal_61(len),
            ((1u64 << 61) / len as u64) as u32,
            "{len}"
        )
    };
    let edges = (0..=256u32).flat_map(|i| {
        // Interval ends of the table, for D = len << 1 and len << 2.
        let a = (1u64 << 30) + i as u64 * (1 << 22);
        let b = (1u64 << 29) + i as u64 * (1 << 21);
        [a, b]
    });
    for base in edges.chain([1 << 29, 1 << 30, (1 << 31) - 1]) {
        for k in -40i64..=40 {
            let len = base as i64 + k;
            if len > 1 << 29 && len < 1 << 31 {
                check(len as u32);
            }
        }
    }
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    for _ in 0..1_000_000 {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let len = (1 << 29) + 1 + (x % ((1 << 31) - (1 << 29) - 1)) as u32;
        check(len);
    }
}
