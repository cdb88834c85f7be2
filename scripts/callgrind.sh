#!/usr/bin/env bash
# Instructions per call, counted by callgrind (stable where wall-clock time is noisy):
#   - face_collision, cast and a 256-triangle scene's cast per scalar, on the inputs of
#     benches/cast.rs (examples/callgrind_kernel.rs), face_collision and cast on its
#     near-triangle mix too;
#   - cast on the first $TRADEOFF_N cases of every scale of examples/tradeoff.rs.
# Each run counts only the measured loop: an #[inline(never)], unmangled function, selected with
# --toggle-collect (collection starts off). Prints markdown tables; writes target/callgrind.tsv
# (function, scalar, inputs, calls, instructions, per_call), which `tradeoff` reads.
#
# Usage: scripts/callgrind.sh            (N=6400 and TRADEOFF_N=4096 by default)
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"
N="${N:-6400}"                   # calls per bench run; a multiple of 64
TRADEOFF_N="${TRADEOFF_N:-4096}" # cases per tradeoff scale
SCALARS=(f32 f64 I32F32 I16F16)

cargo build --release --example callgrind_kernel --example tradeoff >&2
bin=target/release/examples
out=target/callgrind
mkdir -p "$out"
tsv=target/callgrind.tsv
tmp="$tsv.tmp"
printf 'function\tscalar\tinputs\tcalls\tinstructions\tper_call\n' >"$tmp"

# measure FUNCTION SCALAR INPUTS SYMBOL COMMAND...: one callgrind run, one tsv row.
measure() {
    local function=$1 scalar=$2 inputs=$3 symbol=$4
    shift 4
    local file="$out/$function-$scalar-$inputs.out"
    local calls
    calls=$(valgrind --tool=callgrind --callgrind-out-file="$file" --collect-atstart=no \
        --toggle-collect="$symbol" "$@" 2>"$file.log" | awk '$1 == "calls" { print $2 }')
    local ir
    ir=$(awk '$1 == "totals:" || $1 == "summary:" { print $2; exit }' "$file")
    if [[ -z "$calls" || -z "$ir" || "$calls" == 0 ]]; then
        echo "callgrind run failed: $function $scalar $inputs (see $file.log)" >&2
        exit 1
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$function" "$scalar" "$inputs" "$calls" "$ir" \
        "$(awk -v i="$ir" -v c="$calls" 'BEGIN { printf "%.1f", i / c }')" >>"$tmp"
    echo "  $function $scalar $inputs: $ir instructions / $calls calls" >&2
}

for scalar in "${SCALARS[@]}"; do
    for function in face cast scene; do
        measure "$function" "$scalar" bench "ck_${function}_${scalar}" \
            "$bin/callgrind_kernel" "$function" "$scalar" "$N"
    done
    for function in face cast; do
        measure "$function" "$scalar" near "ck_${function}_${scalar}" \
            "$bin/callgrind_kernel" "${function}_near" "$scalar" "$N"
    done
    for scale in 1 10 100 1000 far; do
        # Rows a scalar cannot represent (I16F16 far is inside its range; nothing is skipped
        # today) would fail to prepare any case and stop the script here.
        measure cast "$scalar" "tradeoff-$scale" "tradeoff_cast_${scalar}" \
            "$bin/tradeoff" --kernel "$scalar" "$scale" "$TRADEOFF_N"
    done
done
mv "$tmp" "$tsv"

# Markdown: one table for the bench inputs, one for the tradeoff scales.
awk -F'\t' -v n="$N" '
    NR == 1 { next }
    { v[$1, $2, $3] = $6 }
    END {
        split("f32 f64 I32F32 I16F16", s, " ")
        printf "Instructions per call (callgrind, %d calls each, inputs of benches/cast.rs):\n\n", n
        print "| function | f32 | f64 | I32F32 | I16F16 |"
        print "|---|---:|---:|---:|---:|"
        split("face cast scene", f, " ")
        name["face"] = "`face_collision`"; name["cast"] = "`cast`"; name["scene"] = "`Scene::cast` (256 triangles)"
        for (i = 1; i <= 3; i++) {
            line = "| " name[f[i]]
            for (j = 1; j <= 4; j++) line = line " | " v[f[i], s[j], "bench"]
            print line " |"
        }
        for (i = 1; i <= 2; i++) {
            line = "| " name[f[i]] ", near-triangle mix"
            for (j = 1; j <= 4; j++) line = line " | " v[f[i], s[j], "near"]
            print line " |"
        }
        print ""
        print "Instructions per `cast` on the cases of `examples/tradeoff.rs` (first cases of each scale):"
        print ""
        print "| scale | f32 | f64 | I32F32 | I16F16 |"
        print "|---|---:|---:|---:|---:|"
        split("1 10 100 1000 far", sc, " ")
        for (i = 1; i <= 5; i++) {
            line = "| " sc[i]
            for (j = 1; j <= 4; j++) {
                x = v["cast", s[j], "tradeoff-" sc[i]]
                line = line " | " (x == "" ? "n/a" : x)
            }
            print line " |"
        }
    }' "$tsv"
echo >&2
echo "wrote $tsv" >&2
