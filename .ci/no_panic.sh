#!/usr/bin/env bash
# No panic paths: links a release build of .ci/no_panic (wrappers around StandardTriangle::new,
# Sweep::new, face_collision, cast, and the scene-level casts and box queries (penetration,
# winding) of a slice, a Mesh, a CompactMesh and a Heightfield, the cast of a Compound of the
# four, and a frame of slide::Character
# on a slice (the whole response), for f32, f64, I16F16 and I32F32) for thumbv6m-none-eabi with
# `panic = "abort"` and a panic handler that calls a function that does not exist. If any panic
# path (core::panicking::*, panic_bounds_check, panic_const_*, unwrap_failed, ...) survives
# optimisation, the link fails; then a build with a real handler is disassembled to show which
# wrapper reaches which panic and by what call path.
#
# Usage: .ci/no_panic.sh [face|all]
#   face: the face test and Sweep::new only (triangles come from an opaque static)
#   all:  also StandardTriangle::new (default)
# Also runs a self-test: a wrapper with an unchecked index must make the link fail.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"

scope="${1:-all}"
target=thumbv6m-none-eabi
manifest=.ci/no_panic/Cargo.toml
dir=target/no_panic
rustup target add "$target" >/dev/null 2>&1
rustup component add llvm-tools >/dev/null 2>&1
tools="$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin"

build() {
    cargo build --quiet --release --manifest-path "$manifest" --target "$target" --target-dir "$dir" "$@"
}

# Shows where the panic paths are: a build whose panic handler exists, disassembled.
locate() {
    build --features locate "$@"
    "$tools/llvm-objdump" -d -C --no-show-raw-insn "$dir/$target/release/ballcast-no-panic" |
        python3 .ci/no_panic/callgraph.py || true
}

# check NAME CARGO-ARGS...: passes if the build links.
status=0
check() {
    local name="$1"
    shift
    if build "$@" 2>"$dir/$name.log"; then
        echo "no-panic [$name]: PASS (linked; no panic path reachable from the wrappers)"
    elif grep -q ballcast_has_a_panic_path "$dir/$name.log"; then
        echo "no-panic [$name]: FAIL (a panic path survives; where it is:)"
        locate "$@"
        status=1
    else
        cat "$dir/$name.log"
        echo "no-panic [$name]: build error"
        status=1
    fi
}

mkdir -p "$dir"
check face --no-default-features
if [ "$scope" = all ]; then
    check all
fi

# Self-test: a panic path must be caught.
if build --no-default-features --features selftest 2>"$dir/selftest.log"; then
    echo "no-panic [self-test]: FAIL (a wrapper that can panic linked; the check is blind)"
    status=1
elif grep -q ballcast_has_a_panic_path "$dir/selftest.log"; then
    echo "no-panic [self-test]: PASS (a wrapper with an unchecked index fails the link)"
else
    cat "$dir/selftest.log"
    echo "no-panic [self-test]: build error"
    status=1
fi
exit "$status"
