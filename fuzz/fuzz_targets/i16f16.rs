//! Arbitrary bytes become a triangle, a sweep and a radius in `I16F16`; see `tests/common/invariant.rs`.
#![no_main]

use fixed::types::I16F16;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    ballcast_fuzz::check_bytes::<I16F16>(data);
});
