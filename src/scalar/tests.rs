//! The hosts' float shortcuts against the integer code the Cortex-M runs, bit for bit.

use fixed::types::{I16F16, I32F32};

use crate::xorshift::Rng;

/// `to_f64` is `to_num::<f64>()`: every `I16F16` is exact either way; `I32F32` values with more
/// than 53 significant bits round, ties to even, the same way in both.
#[test]
fn fixed_to_f64_is_to_num() {
    use crate::Scalar;
    let i16 = |b: i32| {
        let v = I16F16::from_bits(b);
        assert_eq!(v.to_f64().to_bits(), v.to_num::<f64>().to_bits(), "{b}");
    };
    let i32 = |b: i64| {
        let v = I32F32::from_bits(b);
        assert_eq!(v.to_f64().to_bits(), v.to_num::<f64>().to_bits(), "{b}");
    };
    for b in [i32::MIN, i32::MIN + 1, -1, 0, 1, i32::MAX - 1, i32::MAX] {
        i16(b);
    }
    for b in [i64::MIN, i64::MIN + 1, -1, 0, 1, i64::MAX - 1, i64::MAX] {
        i32(b);
    }
    let mut rng = Rng(0x853C_49E6_748F_EA9B);
    for _ in 0..1_000_000 {
        let (x, s) = (rng.next(), rng.next());
        i16((x as i32) >> (s % 32));
        let b = (x as i64) >> (s % 64);
        i32(b);
        // Halfway cases: the bits below a 53-bit significand exactly one half of its last place.
        let top = 63 - b.unsigned_abs().leading_zeros().min(63) as i64;
        if top > 53 {
            let half = 1i64 << (top - 53);
            let tie = (b & !(2 * half - 1)) | half;
            i32(tie);
            i32(tie ^ (2 * half));
        }
    }
}

/// `unit_to_scalar` rounds a unit component to the scalar's step, ties away from zero, in the
/// unit's own width: the integer of the exact quotient, at every tie of `I16F16`'s units of
/// magnitude up to one and beside it, at one and minus one, and at random, and the same for
/// `I32F32` at random and at its ties near zero and one.
#[test]
fn unit_to_scalar_rounds_ties_away() {
    use super::sealed::Kernel;
    use fixed::types::{I2F30, I2F62};
    // round(v / 2^k), ties away from zero, in 128 bits.
    let want = |v: i128, k: u32| {
        let q = (v.abs() + (1 << (k - 1))) >> k;
        if v < 0 { -q } else { q }
    };
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let ties = (-(1i32 << 16)..1 << 16).map(|q| (q << 14) + (1 << 13));
    let random = (0..1_000_000).map(|_| (rng.next() as i32) >> 1);
    for v in ties.chain(random).chain([-(1 << 30), 1 << 30]) {
        for v in [v, v + 1, v - 1] {
            let v = v.clamp(-(1 << 30), 1 << 30);
            let got = I16F16::unit_to_scalar(I2F30::from_bits(v)).to_bits();
            assert_eq!(got as i128, want(v as i128, 14), "{v}");
        }
    }
    let one = 1i64 << 62;
    let ties = (-4..=4)
        .chain([(1 << 32) - 1, -(1 << 32)])
        .map(|q| (q << 30) + (1 << 29));
    let random = (0..1_000_000).map(|_| (rng.next() as i64) >> 1 >> (rng.next() % 62));
    for v in ties.chain(random).chain([-one, one, -one + 1, one - 1]) {
        let v = v.clamp(-one, one);
        for v in [v, -v, v + 1, v - 1] {
            let got = I32F32::unit_to_scalar(I2F62::from_bits(v)).to_bits();
            assert_eq!(got as i128, want(v as i128, 30), "{v}");
        }
    }
}

/// A vector along an axis, as `scaled` leaves it (largest component `2^(UFRAC-1)`), whose other
/// components are too small to move the rounded length off `2^(UFRAC-1)`: `unit_normalize`
/// doubles it without dividing, and gives the quotients `round(c 2^UFRAC / len)` (ties away
/// from zero), worked here in 128 bits.
#[test]
fn axis_vectors_normalise_by_doubling() {
    use super::sealed::Kernel;
    use crate::Vec3;
    use fixed::types::{I2F30, I2F62};
    let quotient = |c: i128, len: i128, ufrac: u32| {
        let q = ((c.abs() << ufrac) + len / 2) / len;
        if c < 0 { -q } else { q }
    };
    // round(sqrt(big² + a² + b²)) stays `big` while a² + b² < big (the root moves by under 1/2).
    let mut rng = Rng(0x6A09_E667_F3BC_C909);
    for _ in 0..100_000 {
        let (w, sign) = (rng.next(), rng.next());
        let small =
            |w: u64, bound: u64| (w % bound) as i64 * if w & sign & 1 == 0 { 1 } else { -1 };
        let big = 1i64 << 29;
        let (a, b) = (small(w, 1 << 14), small(w >> 32, 1 << 14));
        let len = 1i128 << 29;
        let want = [big, a, b].map(|c| quotient(c as i128, len, 30) as i32);
        let v = Vec3::new(big, a, b).map(|c| I2F30::from_bits(c as i32));
        let got = I16F16::unit_normalize(v).map(I2F30::to_bits);
        assert_eq!([got.x, got.y, got.z], want, "{big} {a} {b}");
        let big = 1i64 << 61;
        let (a, b) = (small(w, 1 << 30), small(sign >> 1, 1 << 30));
        let len = 1i128 << 61;
        let want = [a, -big, b].map(|c| quotient(c as i128, len, 62) as i64);
        let v = Vec3::new(a, -big, b).map(I2F62::from_bits);
        let got = I32F32::unit_normalize(v).map(I2F62::to_bits);
        assert_eq!([got.x, got.y, got.z], want, "{a} {big} {b}");
    }
}

/// `scaled` puts the largest magnitude's top bit at `2^(UFRAC-1)` by a power of two, exactly
/// up and rounded to nearest (ties away from zero) down, worked here in 128 bits, for
/// components of every magnitude, the extremes included.
#[test]
fn scaled_shifts_by_a_power_of_two() {
    use super::sealed::Kernel;
    use crate::Vec3;
    let shift = |c: i128, k: i32| {
        if k >= 0 {
            c << k
        } else {
            let q = (c.abs() + (1 << (-k - 1))) >> -k;
            if c < 0 { -q } else { q }
        }
    };
    let want = |c: [i128; 3], ufrac: i32| {
        let m = c.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
        let k = (ufrac - 1) - (127 - m.leading_zeros() as i32);
        c.map(|c| shift(c, k))
    };
    let mut rng = Rng(0xBB67_AE85_84CA_A73B);
    let edges = [i64::MIN, i64::MIN + 1, -1, 1, i64::MAX];
    for i in 0..1_000_000 {
        let mut w = [0i64; 3].map(|_| (rng.next() as i64) >> (rng.next() % 64));
        if i < 125 {
            w = [edges[i % 5], edges[i / 5 % 5], edges[i / 25]];
        }
        let v = Vec3::new(w[0], w[1], w[2]);
        let narrow = v.map(|c| I16F16::from_bits(c as i32));
        if let Some(got) = I16F16::scaled(narrow) {
            let got = got.map(|u| u.to_bits() as i128);
            let c = [narrow.x, narrow.y, narrow.z].map(|c| c.to_bits() as i128);
            assert_eq!([got.x, got.y, got.z], want(c, 30), "{c:?}");
        }
        if let Some(got) = I32F32::scaled(v.map(I32F32::from_bits)) {
            let got = got.map(|u| u.to_bits() as i128);
            assert_eq!(
                [got.x, got.y, got.z],
                want(w.map(|c| c as i128), 62),
                "{w:?}"
            );
        }
    }
}

/// `div_pow2` rounds to nearest, ties away from zero, over every bit pattern's neighbourhood
/// that matters: the type's extremes (where adding half a step before the shift overflowed,
/// `slide::skin` of the largest `I16F16` among them), every tie near zero, and at random, for
/// every shift.
#[test]
fn div_pow2_rounds_ties_away_at_the_extremes() {
    use super::sealed::Kernel;
    let want = |v: i128, k: u32| {
        let q = (v.abs() + (1 << (k - 1))) >> k;
        if v < 0 { -q } else { q }
    };
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for k in 1..32 {
        let edges = [i64::MIN, i64::MIN + 1, -1, 0, 1, i64::MAX - 1, i64::MAX];
        let ties = (-64i64..64).map(|q| (q << k) + (1 << (k - 1)));
        let random = (0..20_000).map(|_| rng.next() as i64);
        for v in edges.into_iter().chain(ties).chain(random) {
            for v in [v, v.wrapping_add(1), v.wrapping_sub(1)] {
                let narrow = v as i32;
                let got = I16F16::div_pow2(I16F16::from_bits(narrow), k).to_bits();
                assert_eq!(
                    got as i128,
                    want(narrow as i128, k),
                    "I16F16 {narrow} >> {k}"
                );
                let got = I32F32::div_pow2(I32F32::from_bits(v), k).to_bits();
                assert_eq!(got as i128, want(v as i128, k), "I32F32 {v} >> {k}");
            }
        }
    }
}

/// `dot_unit_xz` is `dot_unit` with the unit vector's zero y put back: the same number for
/// floats (the zero product only ever changed a zero's sign), the same bits for fixed point,
/// on offsets of every magnitude within `7 LIMIT` and directions all round the x–z plane.
#[test]
fn dot_unit_xz_is_dot_unit_with_a_zero_y() {
    use crate::{Scalar, Vec3};
    fn check<S: Scalar>(seed: u64) {
        let mut rng = Rng(seed);
        let limit = S::LIMIT.to_f64();
        for k in 0..200_000u32 {
            let scale = 7.0 * limit / f64::from(1u32 << (k % 24));
            let d =
                Vec3::new(rng.signed(), rng.signed(), rng.signed()).map(|c| S::from_f64(c * scale));
            let turn = rng.signed() * core::f64::consts::PI;
            let dir = Vec3::new(libm::cos(turn), 0.0, libm::sin(turn)).map(S::from_f64);
            let Some((_, u)) = S::direction(dir) else {
                continue;
            };
            let (full, xz) = (S::dot_unit(d, u), S::dot_unit_xz(d, [u.x, u.z]));
            assert!(full == xz, "{d:?} · {u:?}: {full:?} and {xz:?}");
            if !S::PRECISION.relative {
                assert_eq!(full.to_f64().to_bits(), xz.to_f64().to_bits());
            }
        }
    }
    check::<f32>(0x2545_F491_4F6C_DD1D);
    check::<f64>(0x2545_F491_4F6C_DD1D);
    check::<I16F16>(0x2545_F491_4F6C_DD1D);
    check::<I32F32>(0x2545_F491_4F6C_DD1D);
}
