//! The lockstep scene (`embedded/src/lockstep.rs`, included with `#[path]`) as a plain `std`
//! program with no host-only dependency, so it cross-compiles to any target with `std`: prints
//! `scalar hash` for every scalar, the lines `cargo run --release --example lockstep` prints on
//! the host. `.ci/targets.sh` runs it on aarch64 (under `qemu-aarch64`) and wasm32-wasip1 (under
//! Node's WASI, `wasi.mjs`) and compares.
//!
//! On your own target: `cargo run --release --target <triple>` here, then compare with the
//! host's lines (or the hashes pinned in `tests/lockstep.rs`).

#[path = "../../../embedded/src/lockstep.rs"]
mod lockstep;

fn main() {
    lockstep::run_all(|name, o| {
        println!("{name} {:016x}", o.hash);
    });
}
