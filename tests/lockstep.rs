//! The lockstep scene (`embedded/src/lockstep.rs`): every scalar's trajectory hash is pinned.
//!
//! The same constants must come out of debug and release builds (`cargo test` and
//! `cargo test --release --test lockstep`), and `.ci/embedded.sh` checks that Cortex-M0 and
//! Cortex-M4F under QEMU print them too. A change to the library that moves any trajectory by one
//! bit changes a hash: re-pin after review, from `cargo run --release --example lockstep`.

#[path = "../embedded/src/lockstep.rs"]
mod lockstep;

use fixed::types::{I16F16, I32F32};
use lockstep::{Bits, Fnv, Outcome, simulate};

/// The pinned outcomes: hash, contacts, escapes.
const F64: Outcome = pinned(0x7eab_7baa_52fd_6611, 8381);
const F32: Outcome = pinned(0xb920_942d_e98f_bd9a, 8381);
const I32F32_RUN: Outcome = pinned(0x745b_99ca_6b82_fe87, 8381);
const I16F16_RUN: Outcome = pinned(0x93a3_04b3_e021_cca7, 8376);

const fn pinned(hash: u64, contacts: u32) -> Outcome {
    Outcome {
        hash,
        contacts,
        escapes: 0,
    }
}

fn check<S: Bits>(name: &str, expected: Outcome) {
    let got = simulate::<S>();
    assert_eq!(
        got, expected,
        "{name}: got hash {:016x} ({} contacts, {} escapes)",
        got.hash, got.contacts, got.escapes
    );
}

#[test]
fn f64_trajectory_is_pinned() {
    check::<f64>("f64", F64);
}

#[test]
fn f32_trajectory_is_pinned() {
    check::<f32>("f32", F32);
}

#[test]
fn i32f32_trajectory_is_pinned() {
    check::<I32F32>("I32F32", I32F32_RUN);
}

#[test]
fn i16f16_trajectory_is_pinned() {
    check::<I16F16>("I16F16", I16F16_RUN);
}

#[test]
fn fnv1a_matches_the_reference_vectors() {
    // FNV-1a 64 of the empty input is the offset basis; of the 8 bytes of 0u64 it is the
    // offset basis run through eight (xor 0, multiply) rounds.
    let mut h = Fnv::new();
    assert_eq!(h.0, 0xcbf2_9ce4_8422_2325);
    h.write_u64(0);
    let mut r: u64 = 0xcbf2_9ce4_8422_2325;
    for _ in 0..8 {
        r = r.wrapping_mul(0x100_0000_01b3);
    }
    assert_eq!(h.0, r);
    // "a" as a single byte: the published FNV-1a 64 value.
    let a = (0xcbf2_9ce4_8422_2325u64 ^ 0x61).wrapping_mul(0x100_0000_01b3);
    assert_eq!(a, 0xaf63_dc4c_8601_ec8c);
}

#[test]
fn the_scene_and_throws_stay_inside_the_room() {
    assert_eq!(lockstep::room().len(), lockstep::TRIANGLES);
    assert_eq!(
        lockstep::THROWS * lockstep::STEPS_PER_THROW,
        lockstep::STEPS
    );
    for i in 0..lockstep::THROWS {
        let (p, _) = lockstep::throw(i);
        assert!(
            p.iter().all(|&c| (1.0..19.0).contains(&c)),
            "throw {i}: {p:?}"
        );
        assert!(p[1] + lockstep::RADIUS < 10.0);
    }
}
