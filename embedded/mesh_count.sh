#!/usr/bin/env bash
# Instructions per query on the Cortex-M0 (thumbv6m-none-eabi) for baked I16F16 meshes, from
# the bare-metal `mesh_counts` program: the 96-triangle ramp room as a linear scan and as a mesh,
# the 2 168-triangle arena as a mesh and as a compact mesh, the 64 × 64 terrain heightfield, the
# last two also as `Cached` with 32 slots (a query is one `Geometry::cast` of
# `move_and_slide`).
#
#   embedded/mesh_count.sh        # prints a markdown table; several minutes (singlestep log)
#
# Counting as in count.sh: QEMU logs every executed instruction with its symbol
# (`-singlestep -d exec,nochain`); an instruction counts from the first one in a `query_*`
# function until control is back in its caller, callees included. Slow on a loaded machine, so
# not part of CI (.ci/embedded.sh runs the program for its agreement check only).
set -euo pipefail
cd "$(dirname "$0")"
export CARGO_BUILD_JOBS="${CARGO_BUILD_JOBS:-1}"

t=thumbv6m-none-eabi
cargo build --quiet --release --target "$t" --bin mesh_counts
elf="${CARGO_TARGET_DIR:-target}/$t/release/mesh_counts"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
timeout 1800 qemu-system-arm -machine microbit -global nrf51-soc.flash-size=524288 -nographic \
    -semihosting-config enable=on,target=native \
    -singlestep -d exec,nochain -D /dev/stderr -kernel "$elf" \
    2>&1 >"$work/out" |
    LC_ALL=C awk '
        /^Trace/ {
            s = $NF
            if (!inside && s ~ /^query_/ && prev !~ /^query_/) { inside = 1; q = s; drv = prev; calls[q]++ }
            if (inside) { if (s == drv) inside = 0; else n[q]++ }
            prev = s
        }
        END { for (q in calls) print q, calls[q], n[q] }
    ' >"$work/counts"
cat "$work/out"
row() { # query label
    awk -v q="$1" -v l="$2" '$1 == q { printf "| %s | %d | %d |\n", l, $2, $3 / $2 }' "$work/counts"
}
echo
echo "| geometry (I16F16, Cortex-M0) | queries | instructions per query |"
echo "|---|---:|---:|"
row query_ramp_scan "ramp room, 96 triangles, linear scan"
row query_ramp_mesh "ramp room, 96 triangles, mesh"
row query_arena_mesh "arena, 2 168 triangles, mesh"
row query_arena_compact "arena, 2 168 triangles, compact mesh"
row query_terrain_air "terrain, 8 192 triangles, heightfield, falling (steps 1-100)"
row query_terrain_ground "terrain, 8 192 triangles, heightfield, on the ground (steps 101-300)"
row query_arena_compact_cached "arena, compact mesh, with a cache of 32 slots"
row query_terrain_air_cached "terrain heightfield, falling, with a cache of 32 slots"
row query_terrain_ground_cached "terrain heightfield, on the ground, with a cache of 32 slots"
