#!/usr/bin/env bash
# Microcontroller CI: the lockstep scene on Cortex-M0 (thumbv6m-none-eabi, soft float) and
# Cortex-M4F (thumbv7em-none-eabihf) under qemu-system-arm with semihosting must print every
# scalar's trajectory hash bit for bit as the host does; the firmware's levels, baked at build
# time (embedded/build.rs), run on the Cortex-M0, the 2 168-triangle arena mesh with the host's
# hash; then the face test's instruction counts and code size per scalar on both
# (embedded/count.sh). Run by .ci/run after `cargo test`.
#
#   bash .ci/embedded.sh
#
# Installs what it needs (qemu-system-arm from Debian's packages, the two rustup targets,
# llvm-tools). Every QEMU run is bounded by `timeout 120`.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"

if ! command -v qemu-system-arm >/dev/null; then
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends qemu-system-arm
fi
rustup target add thumbv6m-none-eabi thumbv7em-none-eabihf
rustup component add llvm-tools

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "== lockstep on the host"
# The pinned hashes (tests/lockstep.rs) hold in release here; .ci/run's `cargo test` checks the
# same constants in debug, so debug and release agree without building the dev-dependencies twice.
cargo test --quiet --release --test lockstep
cargo run --quiet --release --example lockstep >"$work/host.txt" 2>/dev/null
cat "$work/host.txt"
if [ "$(wc -l <"$work/host.txt")" -ne 4 ]; then
    echo "FAIL: the host example should print four scalars" >&2
    exit 1
fi

failed=0
for target in thumbv6m-none-eabi thumbv7em-none-eabihf; do
    echo "== lockstep on $target under QEMU"
    (cd embedded && cargo build --quiet --release --target "$target" --bin lockstep)
    # The runner (embedded/.cargo/config.toml) is QEMU; the build above makes this a pure run.
    (cd embedded && timeout 120 cargo run --quiet --release --target "$target" --bin lockstep) \
        >"$work/$target.txt"
    while read -r name hash; do
        got="$(awk -v n="$name" '$1 == n { print $2 }' "$work/$target.txt")"
        if [ "$got" = "$hash" ]; then
            echo "$name $hash matches the host"
        else
            echo "FAIL: $name on $target: ${got:-nothing} (host $hash)" >&2
            failed=1
        fi
    done <"$work/host.txt"
    # Stack headroom: RAM the run never touched (the firmware paints it first).
    sed -n "s/^stack: /$target stack: /p" "$work/$target.txt"
done
if [ "$failed" -ne 0 ]; then
    exit 1
fi
echo "lockstep: every scalar's hash equals the host's on thumbv6m-none-eabi and thumbv7em-none-eabihf"

echo "== firmware: levels baked at build time (embedded/build.rs) into flash, on thumbv6m-none-eabi"
(cd embedded && cargo build --quiet --release --target thumbv6m-none-eabi \
    --bin firmware --bin arena --bin forms --bin mesh_counts)
(cd embedded && timeout 120 cargo run --quiet --release --target thumbv6m-none-eabi --bin firmware) \
    | tee "$work/firmware.txt"
grep -q "^firmware: " "$work/firmware.txt"
# The 2 168-triangle arena: baked mesh on the Cortex-M0, mesh built at run time on the host.
cargo run --quiet --release --example arena >"$work/arena-host.txt"
(cd embedded && timeout 300 cargo run --quiet --release --target thumbv6m-none-eabi --bin arena) \
    | tee "$work/arena.txt"
if [ "$(head -1 "$work/arena.txt")" = "$(cat "$work/arena-host.txt")" ]; then
    echo "arena: the baked mesh's hash on thumbv6m-none-eabi equals the host's ($(cat "$work/arena-host.txt"))"
else
    echo "FAIL: arena on thumbv6m-none-eabi: $(head -1 "$work/arena.txt") (host $(cat "$work/arena-host.txt"))" >&2
    exit 1
fi
# The compact forms baked into flash: the arena as a compact mesh, the 64 x 64 terrain heightfield,
# and both as one compound level.
cargo run --quiet --release --example forms >"$work/forms-host.txt"
(cd embedded && timeout 300 cargo run --quiet --release --target thumbv6m-none-eabi --bin forms) \
    | tee "$work/forms.txt"
if [ "$(head -5 "$work/forms.txt")" = "$(cat "$work/forms-host.txt")" ]; then
    echo "forms: the compact mesh's, the heightfield's, the compound's and the character's (without and with a static cache) hashes on thumbv6m-none-eabi equal the host's"
else
    echo "FAIL: forms on thumbv6m-none-eabi differ from the host's: $(cat "$work/forms-host.txt")" >&2
    exit 1
fi
# Its cache, a `static mut` made by `TriangleCache::new()`, is zero bytes: zero-initialised data
# (`.bss`, symbol type b), nothing of it in flash.
nm="$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin/llvm-nm"
cache="$("$nm" -C "${CARGO_TARGET_DIR:-embedded/target}/thumbv6m-none-eabi/release/forms" | grep -F '::CACHE::' || true)"
echo "forms' cache: $cache"
if [ "$(echo "$cache" | awk '{ print $2 }')" != "b" ]; then
    echo "FAIL: the forms firmware's TriangleCache static is not zero-initialised (.bss)" >&2
    exit 1
fi
# The mesh-count program's runs (its ramp mesh must agree with the ramp's linear scan); the
# instruction counts themselves come from embedded/mesh_count.sh, run locally (slow).
(cd embedded && timeout 120 cargo run --quiet --release --target thumbv6m-none-eabi --bin mesh_counts)

echo "== face test: instructions and size per scalar"
bash embedded/count.sh
