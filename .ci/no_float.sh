#!/usr/bin/env bash
# No float code in a fixed-point build: links embedded/src/bin/fixed_only.rs (StandardTriangle::new,
# cast, a Scene push and Scene::cast, move_and_slide, all in I16F16) in release for
# thumbv6m-none-eabi, where the Cortex-M0 has no FPU so every f32/f64 operation is a call into
# compiler-builtins' soft float, and fails if the ELF holds any soft-float routine (__aeabi_f*,
# __aeabi_d*, __aeabi_i2f, __addsf3, __adddf3, __fixdfsi, __floatsisf, ...), any libm function,
# or any symbol instantiated for f32 or f64. For each call into one, it names the calling
# function and the source line of the call (llvm-objdump's line table).
#
#   bash .ci/no_float.sh
#
# Self-test: the same firmware with one f32 multiply on an opaque value (feature
# no-float-selftest) must fail the check. Then prints the firmware's flash size (.text, llvm-size)
# next to the same firmware in f32 (feature no-float-f32). Run by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"

target=thumbv6m-none-eabi
timeout 300 rustup target add "$target" >/dev/null 2>&1
timeout 300 rustup component add llvm-tools >/dev/null 2>&1
tools="$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin"
elf=embedded/target/$target/release/fixed_only
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Soft-float routines (ARM EABI and libgcc names), then C libm names.
soft='^(__aeabi_([fd]|u?[il]2[fd])|__(add|sub|mul|div|neg|pow)[sdtx]f[23]|__powi[sdtx]f2|__fix(uns)?[sdtx]f[sdt]i|__float(un)?[sdt]i[sdtx]f|__(eq|ne|lt|le|gt|ge|un|cmp)[sdtx]f2|__(extend|trunc)[sdtxh]f[sdtxh]f2)'
libm='^(sqrt|fabs|floor|ceil|trunc|round|rint|fma|fmin|fmax|fmod|hypot|sin|cos|tan|asin|acos|atan|atan2|exp|exp2|expm1|log|log2|log10|log1p|pow|cbrt|copysign)f?$'
# Demangled: the libm crate, compiler-builtins' float modules, anything named for or instantiated
# with f32/f64 (`<f32 as Scalar>`, `from_f64`, `core::f64::is_nan`, ...).
rust='(libm::|compiler_builtins::(float|math)::|(^|[^0-9A-Za-z])f(32|64)([^0-9A-Za-z]|$))'

build() {
    (cd embedded && timeout 900 cargo build --quiet --release --target "$target" --bin fixed_only "$@")
}

# floats ELF: prints the float symbols in ELF, one a line; nothing if there are none.
floats() {
    {
        "$tools/llvm-nm" --defined-only "$1" | awk '{ print $NF }' | grep -E "$soft|$libm" || true
        "$tools/llvm-nm" --defined-only -C "$1" | cut -d' ' -f3- | grep -E "$rust" || true
    } | sort -u
}

# callers ELF SYMBOLS-FILE: every call into one of the symbols, with the calling function and
# the source line of the call (the innermost inlined frame, from the line table).
callers() {
    "$tools/llvm-objdump" -d -l -C --no-show-raw-insn "$1" |
        awk -v list="$2" 'BEGIN { while ((getline s < list) > 0) want[s] = 1 }
            /^[0-9a-f]+ <.*>:$/ { fn = substr($0, index($0, "<")); line = "?" }
            /^; / { line = substr($0, 3) }
            /\t(b|bl|blx)\t/ && match($0, /<[^>]+>/) {
                callee = substr($0, RSTART + 1, RLENGTH - 2)
                if (callee in want) print "  " callee ", called from " fn " at " line
            }'
}

status=0
build
cp "$elf" "$work/i16f16.elf"
floats "$work/i16f16.elf" >"$work/found"
if [ -s "$work/found" ]; then
    echo "no-float [I16F16 firmware]: FAIL (float code linked:)"
    sed 's/^/  /' "$work/found"
    callers "$work/i16f16.elf" "$work/found"
    status=1
else
    echo "no-float [I16F16 firmware]: PASS (no soft-float routine, no libm, no f32/f64 code linked)"
fi

# Self-test: one f32 multiply must be caught.
build --features no-float-selftest
floats "$elf" >"$work/selftest"
if [ -s "$work/selftest" ]; then
    echo "no-float [self-test]: PASS (one f32 multiply is caught: $(paste -sd' ' "$work/selftest"))"
    callers "$elf" "$work/selftest" | grep fixed_only || true
else
    echo "no-float [self-test]: FAIL (an f32 multiply went unnoticed; the check is blind)"
    status=1
fi

# The same firmware in f32, for the size comparison.
build --features no-float-f32
cp "$elf" "$work/f32.elf"
text() { "$tools/llvm-size" -A "$1" | awk '$1 == ".text" { print $2 }'; }
echo "fixed_only flash (.text, thumbv6m-none-eabi release): I16F16 $(text "$work/i16f16.elf") bytes, f32 $(text "$work/f32.elf") bytes"
exit "$status"
