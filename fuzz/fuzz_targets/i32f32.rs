//! Arbitrary bytes become a triangle, a sweep and a radius in `I32F32`; see `tests/common/invariant.rs`.
#![no_main]

use fixed::types::I32F32;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    ballcast_fuzz::check_bytes::<I32F32>(data);
});
