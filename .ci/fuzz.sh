#!/usr/bin/env bash
# Bounded fuzzing pass: each cargo-fuzz target (fuzz/fuzz_targets: f32, f64, i16f16, i32f32) for
# RUNS inputs (default 1 000 000) or SECONDS seconds (default 120), whichever comes first.
# Builds with cargo fuzz's defaults (release, debug assertions and overflow checks on) but
# without a sanitizer: the crate is `forbid(unsafe_code)`, so ASan would only slow it down.
# A panic or failed assertion is a finding: libFuzzer stops and writes the input to
# fuzz/artifacts/<target>/; reproduce with `cargo +nightly fuzz run -s none <target> <file>`.
#
# Usage: .ci/fuzz.sh [RUNS] [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"
runs="${1:-1000000}"
seconds="${2:-120}"

# Installs nightly only if missing: `rustup toolchain install nightly` would also update it.
rustup run nightly rustc --version >/dev/null 2>&1 ||
    rustup toolchain install nightly --profile minimal
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --locked

cargo +nightly fuzz build -s none
mkdir -p target
for t in f32 f64 i16f16 i32f32; do
    mkdir -p "corpus/$t"
    log="target/fuzz-$t.log"
    rc=0
    cargo +nightly fuzz run -s none "$t" -- -max_len=133 -runs="$runs" \
        -max_total_time="$seconds" -print_final_stats=1 >"$log" 2>&1 || rc=$?
    grep -E "^stat::(number_of_executed_units|average_exec_per_sec)|panicked|Test unit" "$log" |
        sed "s/^/fuzz [$t] /" || true
    if [ "$rc" != 0 ]; then
        tail -40 "$log"
        echo "fuzz [$t]: FINDING (exit $rc), see fuzz/artifacts/$t/ and fuzz/$log"
        exit 1
    fi
done
