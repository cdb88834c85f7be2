//! The invariant the targets check, shared with the proptest twin `tests/fuzz_invariants.rs`.

#[path = "../../tests/common/invariant.rs"]
mod invariant;

pub use invariant::{BYTES, Bits, Outcome, WORDS, check, check_bytes};
