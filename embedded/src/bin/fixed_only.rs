//! A firmware that uses ballcast in `I16F16` only: `StandardTriangle::new`, `cast`, a `Scene`
//! (push, then `Scene::cast`) and `move_and_slide`, on values the optimiser cannot see. On a
//! Cortex-M0 (no FPU) every `f32`/`f64` operation would be a soft-float routine call, so
//! `.ci/no_float.sh` links it for `thumbv6m-none-eabi` and fails if any soft-float routine
//! (`__aeabi_f*`, `__aeabi_d*`, `__addsf3`, ...) or libm function is in the ELF.
//!
//! Features: `no-float-f32` builds the same firmware in `f32` (for the flash size comparison);
//! `no-float-selftest` adds one `f32` multiply on an opaque value (the check must then fail).
//!
//! Run: `cargo m0 fixed_only` in `embedded/` prints the final position's raw bits.
#![no_std]
#![no_main]

use ballcast::{Scene, StandardTriangle, Sweep, Triangle, Vec3, move_and_slide};
use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;

#[cfg(not(feature = "no-float-f32"))]
type S = fixed::types::I16F16;
#[cfg(feature = "no-float-f32")]
type S = f32;

/// `v / 256` in the scalar, from an integer the optimiser cannot see (no float in I16F16).
fn c(v: i32) -> S {
    let v = black_box(v);
    #[cfg(not(feature = "no-float-f32"))]
    {
        S::from_bits(v << 8)
    }
    #[cfg(feature = "no-float-f32")]
    {
        v as f32 / 256.0
    }
}

/// A point in 1/256 units.
fn p(x: i32, y: i32, z: i32) -> Vec3<S> {
    Vec3::new(c(x), c(y), c(z))
}

/// The raw bits of a scalar, for printing without float formatting.
fn bits(s: S) -> u32 {
    s.to_bits() as u32
}

#[entry]
fn main() -> ! {
    const M: i32 = 256; // one unit
    // A floor and a wall of a small room, counter-clockwise from the inside.
    let floor = [
        Triangle::new(p(0, 0, 0), p(0, 0, 8 * M), p(8 * M, 0, 0)),
        Triangle::new(p(8 * M, 0, 0), p(0, 0, 8 * M), p(8 * M, 0, 8 * M)),
    ];
    let wall = Triangle::new(p(0, 0, 0), p(8 * M, 0, 0), p(0, 4 * M, 0));

    // One prepared triangle and one cast.
    let mut hits = 0u32;
    let radius = c(M / 2);
    if let (Ok(t), Ok(s)) = (
        StandardTriangle::new(&floor[0]),
        Sweep::new(p(M, 2 * M, M), p(M, -M, M), radius),
    ) && t.cast(&s).is_some()
    {
        hits += 1;
    }

    // A scene: push, then cast into it.
    let mut scene: Scene<S, 4> = Scene::new();
    for t in floor.iter().chain([&wall]) {
        let _ = scene.push(*t);
    }
    if let Ok(s) = Sweep::new(p(2 * M, 2 * M, 2 * M), p(3 * M, -M, 2 * M), radius)
        && scene.cast(&s).is_some()
    {
        hits += 1;
    }

    // A ball thrown at the wall and the floor, 120 steps of move_and_slide.
    let (dt, gravity) = (c(4), p(0, -2511, 0)); // 1/64 s, -9.81
    let (mut pos, mut vel) = (p(4 * M, 2 * M, 4 * M), p(-M, 0, -3 * M));
    for _ in 0..black_box(120) {
        vel = vel + gravity.scale(dt);
        let Ok(out) = move_and_slide(&scene, pos, vel.scale(dt), radius) else {
            break;
        };
        let Ok(v) = out.clip(vel) else { break };
        hits += out.contacts.iter().flatten().count() as u32;
        (pos, vel) = (out.position, v);
    }

    #[cfg(feature = "no-float-selftest")]
    {
        // One f32 multiply on an opaque value: `.ci/no_float.sh` must catch it.
        let x: f32 = black_box(1.5);
        hits += black_box(x * x).to_bits() & 1;
    }

    hprintln!(
        "fixed_only: {} contacts; rests at bits ({:08x}, {:08x}, {:08x})",
        hits,
        bits(pos.x),
        bits(pos.y),
        bits(pos.z)
    );
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
