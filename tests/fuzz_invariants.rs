//! The fuzzing invariant (`tests/common/invariant.rs`, shared with the cargo-fuzz targets in
//! `fuzz/`) as a proptest over arbitrary bit patterns, in every scalar: constructors refuse bad
//! input with a justified error value, accept exactly the safe range, and whatever they accept
//! `face_collision` and `cast` answer without panicking (debug build: overflow checks on), with
//! `0 <= alpha < 1` and a unit normal.
//!
//! Cases per scalar: `PROPTEST_CASES` if set, else 20 000.

#[path = "common/invariant.rs"]
mod invariant;

use fixed::types::{I16F16, I32F32};
use invariant::WORDS;
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000)
}

macro_rules! per_scalar {
    ($($name:ident: $t:ty),*) => {$(
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(cases()))]
            #[test]
            fn $name(mode in any::<u8>(), sel in any::<u32>(), w in any::<[u64; WORDS]>()) {
                invariant::check::<$t>(mode, sel, &w);
            }
        }
    )*};
}

per_scalar!(
    invariant_f32: f32,
    invariant_f64: f64,
    invariant_i16f16: I16F16,
    invariant_i32f32: I32F32
);

/// The byte decoding the fuzz targets use: short and empty inputs are padded, not refused.
#[test]
fn short_inputs_are_padded() {
    invariant::check_bytes::<f32>(&[]);
    invariant::check_bytes::<I16F16>(&[2, 0, 0, 0, 0, 4, 8]);
}

/// Found by the i16f16 fuzz target once the invariant covered `cast`: a vertex contact whose
/// fraction `t / len` was just below one rounded to alpha = 1 in I16F16.
#[test]
fn regression_fuzz_i16f16_cast_alpha_one() {
    invariant::check_bytes::<I16F16>(include_bytes!("data/fuzz-i16f16-cast-alpha-one.bin"));
}
