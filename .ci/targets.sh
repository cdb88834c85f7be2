#!/usr/bin/env bash
# Lockstep where games ship: the lockstep scene (embedded/src/lockstep.rs, as the std program
# .ci/lockstep) built for aarch64-unknown-linux-gnu (run under qemu-aarch64) and wasm32-wasip1
# (run under Node's WASI, .ci/lockstep/wasi.mjs) must print every scalar's trajectory hash bit
# for bit as the host does (`cargo run --release --example lockstep`). Prints
# `TARGET SCALAR HASH` per target and scalar. Run by .ci/run after .ci/embedded.sh.
#
#   bash .ci/targets.sh
#
# Installs what it needs: qemu-user and the aarch64 cross linker and C library from Debian's
# packages, the two rustup targets, and Debian's `nodejs` if there is no `node` (these machines
# have Node 20; the WASI flag below is needed by Node 18 and accepted by later ones). Every
# build and run is bounded by `timeout`.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"

need=()
command -v qemu-aarch64 >/dev/null || need+=(qemu-user)
command -v aarch64-linux-gnu-gcc >/dev/null || need+=(gcc-aarch64-linux-gnu)
[ -e /usr/aarch64-linux-gnu/lib/crt1.o ] || need+=(libc6-dev-arm64-cross)
command -v node >/dev/null || need+=(nodejs)
if [ "${#need[@]}" -gt 0 ]; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    timeout 300 $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive timeout 600 \
        $sudo apt-get install -y -qq --no-install-recommends "${need[@]}"
fi
targets=(aarch64-unknown-linux-gnu wasm32-wasip1)
timeout 300 rustup target add "${targets[@]}"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The host's hashes (.ci/embedded.sh has built the example already; tests/lockstep.rs pins them).
if ! timeout 600 cargo run --quiet --release --example lockstep >"$work/host" 2>"$work/host.err"; then
    cat "$work/host.err" >&2
    exit 1
fi
if [ "$(wc -l <"$work/host")" -ne 4 ]; then
    echo "FAIL: the host example should print four scalars" >&2
    exit 1
fi
while read -r name hash; do
    echo "$(rustc -vV | sed -n 's/^host: //p') $name $hash"
done <"$work/host"

dir=target/lockstep
for target in "${targets[@]}"; do
    (cd .ci/lockstep && timeout 900 cargo build --quiet --release --target "$target" \
        --target-dir "../../$dir")
done
timeout 120 qemu-aarch64 -L /usr/aarch64-linux-gnu \
    "$dir/aarch64-unknown-linux-gnu/release/ballcast-lockstep" >"$work/aarch64-unknown-linux-gnu"
timeout 120 node --no-warnings --experimental-wasi-unstable-preview1 .ci/lockstep/wasi.mjs \
    "$dir/wasm32-wasip1/release/ballcast-lockstep.wasm" >"$work/wasm32-wasip1"

failed=0
for target in "${targets[@]}"; do
    while read -r name hash; do
        got="$(awk -v n="$name" '$1 == n { print $2 }' "$work/$target")"
        echo "$target $name ${got:-nothing}"
        if [ "$got" != "$hash" ]; then
            echo "FAIL: $name on $target: ${got:-nothing} (host $hash)" >&2
            failed=1
        fi
    done <"$work/host"
done
if [ "$failed" -ne 0 ]; then
    exit 1
fi
echo "lockstep: every scalar's hash equals the host's on ${targets[*]}"
