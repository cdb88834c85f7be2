//! Arbitrary bytes become a triangle, a sweep and a radius in `f64`; see `tests/common/invariant.rs`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    ballcast_fuzz::check_bytes::<f64>(data);
});
