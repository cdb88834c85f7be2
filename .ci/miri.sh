#!/usr/bin/env bash
# The test suite under Miri (nightly): undefined behaviour, out-of-bounds access, overflow
# panics in debug arithmetic and the like, in the library and the tests.
# - libm's x86 inline assembly stops Miri, so libm is built with `force-soft-floats` (feature
#   enabled from the command line; no manifest change).
# - proptest reads its environment and files: `-Zmiri-disable-isolation`.
# - PROPTEST_CASES (default 4) sets the case count of tests that honour it (tests/fuzz_invariants.rs
#   and every proptest with the default config). Proptests with a fixed `with_cases(1000/2000)`
#   ignore it and would take hours under Miri, so they are skipped here by name (20 tests, 32 000
#   cases; one of them, frame's f32 orthonormal test with 1000 cases, took 364 s alone).
# Measured on 2 shared cores: 4 min 3 s wall from a cold Miri sysroot and build (tests ~42 s),
# 2 min 48 s with both already built; everything passed (nightly 2026-10-29 and 2026-05-15).
#
# Usage: .ci/miri.sh [extra cargo test args...]
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"
# Installs nightly only if missing: `rustup toolchain install nightly` would also update it.
rustup run nightly rustc --version >/dev/null 2>&1 ||
    rustup toolchain install nightly --profile minimal
rustup component add --toolchain nightly miri rust-src >/dev/null 2>&1

export MIRIFLAGS="${MIRIFLAGS:--Zmiri-disable-isolation}"
export PROPTEST_CASES="${PROPTEST_CASES:-4}"
cargo +nightly miri test --no-fail-fast --features libm/force-soft-floats "$@" -- \
    --skip agrees_with_f64_on \
    --skip anything_accepted_is_answered_at_the_range_edges \
    --skip frame_is_standard
