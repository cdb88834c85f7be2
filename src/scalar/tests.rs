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
