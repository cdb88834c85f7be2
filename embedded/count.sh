#!/usr/bin/env bash
# Instruction counts and code size of the face test, per scalar, on Cortex-M0 (thumbv6m-none-eabi,
# soft float) and Cortex-M4F (thumbv7em-none-eabihf), from the bare-metal `counts` program.
#
#   embedded/count.sh        # prints two markdown tables
#
# Needs qemu-system-arm, the two rustup targets and llvm-tools (.ci/embedded.sh installs them).
#
# Counting: QEMU runs `counts` one instruction per translation block and logs every executed
# instruction with the symbol it belongs to (`-singlestep -d exec,nochain`). An instruction counts
# from the first one in `face_<scalar>` entered from a `bench_<group>_<scalar>` driver until
# control is back in that driver, so callees (soft-float, 64/128-bit helpers, standard_point)
# are included. The log streams through awk; nothing is written to disk.
#
# Size: `own` is the size of the `face_<scalar>` wrapper (face_collision inlined into it) or of
# `cast_<scalar>`; `with callees` adds every function reachable from it by direct calls and
# branches in the disassembly (each address once): the flash the test needs on its own.
set -euo pipefail
cd "$(dirname "$0")"
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"

host="$(rustc -vV | sed -n 's/^host: //p')"
tools="$(rustc --print sysroot)/lib/rustlib/$host/bin"
targets=(thumbv6m-none-eabi thumbv7em-none-eabihf)
declare -A label=([thumbv6m-none-eabi]="Cortex-M0" [thumbv7em-none-eabihf]="Cortex-M4F")
declare -A machine=(
    [thumbv6m-none-eabi]="-machine microbit"
    [thumbv7em-none-eabihf]="-cpu cortex-m4 -machine mps2-an386"
)
scalars=(f32 f64 i16f16 i32f32)
declare -A pretty=([f32]=f32 [f64]=f64 [i16f16]=I16F16 [i32f32]=I32F32)

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

for t in "${targets[@]}"; do
    cargo build --quiet --release --target "$t" --bin counts
    elf="${CARGO_TARGET_DIR:-target}/$t/release/counts"
    # The program's own output (semihosting) goes to a file, the instruction log through awk.
    # shellcheck disable=SC2086 # machine options are words on purpose
    timeout 120 qemu-system-arm ${machine[$t]} -nographic \
        -semihosting-config enable=on,target=native \
        -singlestep -d exec,nochain -D /dev/stderr -kernel "$elf" \
        2>&1 >"$work/$t.out" |
        awk '
            /^Trace/ {
                s = $NF
                if (!inside && s ~ /^(face|cast)_/ && prev ~ /^bench_/) { inside = 1; drv = prev; calls[drv]++ }
                if (inside) { if (s == drv) inside = 0; else n[drv]++ }
                prev = s
            }
            END { for (d in calls) print d, calls[d], n[d] }
        ' >"$work/$t.counts"
    if ! grep -q "I32F32 full 6 calls 3 hits; early 4 calls 0 hits" "$work/$t.out"; then
        echo "counts on $t did not run as designed:" >&2
        cat "$work/$t.out" >&2
        exit 1
    fi

    "$tools/llvm-nm" --print-size --defined-only "$elf" >"$work/$t.nm"
    "$tools/llvm-objdump" -d --no-show-raw-insn "$elf" >"$work/$t.dis"
    for fs in "${scalars[@]/#/face_}" "${scalars[@]/#/cast_}"; do
        awk -v root="$fs" '
            function hex(h,   v, i) {
                v = 0
                for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
                return v
            }
            FNR == NR { if (NF == 4) { size[$4] = hex($2); addr[$4] = $1 } next }
            /^[0-9a-f]+ <.*>:$/ { cur = substr($2, 2, length($2) - 3); next }
            {
                split($0, f, "\t")
                if (f[2] ~ /^b/ && match($0, /<[^>+]*(\+0x[0-9a-f]+)?>/)) {
                    tgt = substr($0, RSTART + 1, RLENGTH - 2); sub(/\+0x[0-9a-f]+$/, "", tgt)
                    if (tgt != cur) adj[cur] = adj[cur] " " tgt
                }
            }
            END {
                todo[1] = root; k = 1; seen[root] = 1
                while (k > 0) {
                    f0 = todo[k--]
                    if (!(addr[f0] in counted)) { counted[addr[f0]] = 1; total += size[f0] }
                    m = split(adj[f0], next_, " ")
                    for (i = 1; i <= m; i++) if (!(next_[i] in seen)) { seen[next_[i]] = 1; todo[++k] = next_[i] }
                }
                print size[root], total
            }
        ' "$work/$t.nm" "$work/$t.dis" >"$work/$t.$fs.size"
    done
    "$tools/llvm-size" -A "$elf" | awk '$1 == ".text" { print $2 }' >"$work/$t.text"
done

count() { # target driver -> instructions per call
    awk -v d="$2" '$1 == d { printf "%d", $3 / $2 }' "$work/$1.counts"
}

echo "Instructions per face test (\`full\`: reaches the division and the edge tests, 3 hits and"
echo "3 misses; \`early\`: leaves at the height tests), executed under QEMU, callees included:"
echo
echo "| scalar | Cortex-M0 full | Cortex-M0 early | Cortex-M0 cast | Cortex-M4F full | Cortex-M4F early | Cortex-M4F cast |"
echo "|---|---:|---:|---:|---:|---:|---:|"
for s in "${scalars[@]}"; do
    row="| ${pretty[$s]} |"
    for t in "${targets[@]}"; do
        row="$row $(count "$t" "bench_full_$s") | $(count "$t" "bench_early_$s") | $(count "$t" "bench_cast_$s") |"
    done
    echo "$row"
done
echo
echo "(\`cast\`: the full test, face, edges and vertices, on the \`full\` sweeps.)"
echo
echo "Code size in bytes (\`own\`: the face_<scalar> or cast_<scalar> wrapper with face_collision or"
echo "cast inlined into it; \`with callees\`: plus every function it reaches, each once):"
echo
echo "| scalar | function | Cortex-M0 own | Cortex-M0 with callees | Cortex-M4F own | Cortex-M4F with callees |"
echo "|---|---|---:|---:|---:|---:|"
for f in face cast; do
    for s in "${scalars[@]}"; do
        row="| ${pretty[$s]} | \`$f\` |"
        for t in "${targets[@]}"; do
            read -r own total <"$work/$t.${f}_$s.size"
            row="$row $own | $total |"
        done
        echo "$row"
    done
done
echo
for t in "${targets[@]}"; do
    echo "${label[$t]}: .text of the whole counts program (all four scalars, runtime, formatting): $(cat "$work/$t.text") bytes"
done
