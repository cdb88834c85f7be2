//! Firmware use case: a level kept in flash (`examples/data/ramp.obj`, baked by `build.rs` into
//! a `static` mesh built by `const fn`, no start-up work) and a ball rolled through it in I16F16
//! with `move_and_slide`, on a Cortex-M0 (RP2040 class, no FPU). Prints where the ball comes to
//! rest over semihosting.
//!
//! Run: `cargo m0 firmware` in `embedded/` (QEMU).
#![no_std]
#![no_main]

use ballcast::{Vec3, move_and_slide};
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use fixed::types::I16F16;
use panic_semihosting as _;

mod ramp {
    include!(concat!(env!("OUT_DIR"), "/ramp.rs"));
}

const STEPS: u32 = 600; // 10 s at 60 Hz

#[entry]
fn main() -> ! {
    let c = I16F16::from_num;
    let (dt, r) = (c(1.0 / 60.0), c(0.3));
    let gravity = Vec3::new(I16F16::ZERO, c(-9.81), I16F16::ZERO);
    let mut p = Vec3::new(c(5.5), c(4.5), c(4.5));
    let mut v = Vec3::new(I16F16::ZERO, I16F16::ZERO, I16F16::ZERO);
    let mut contacts = 0;
    for _ in 0..STEPS {
        v = v + gravity * dt;
        // An error means the ball left the safe range: it cannot in this closed corner.
        let Ok(out) = move_and_slide(&ramp::MESH, p, v * dt, r) else {
            break;
        };
        let Ok(clipped) = out.clip(v) else { break };
        contacts += out.contacts.iter().flatten().count();
        p = out.position;
        v = clipped * c(0.98);
    }
    hprintln!(
        "firmware: {} triangles in flash, {} bytes each; after {} steps the ball rests at ({}, {}, {}) with {} contacts",
        ramp::MESH.len(),
        core::mem::size_of_val(&ramp::TRIANGLES[0]),
        STEPS,
        p.x.to_num::<f32>(),
        p.y.to_num::<f32>(),
        p.z.to_num::<f32>(),
        contacts
    );
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
