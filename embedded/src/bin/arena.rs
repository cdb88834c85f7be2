//! The arena run on bare metal (`../arena.rs`): the 2 168-triangle level baked into flash by
//! `build.rs` as an I16F16 mesh, 10 000 steps of thrown balls; prints `I16F16 hash`, the line
//! the host's `cargo run --release --example arena` (the mesh built at run time) prints, then
//! the mesh's flash size and the RAM the run never touched (the stack is painted first).
//!
//! Run: `cargo m0 arena` in `embedded/`.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use fixed::types::I16F16;
use panic_semihosting as _;

#[path = "../arena.rs"]
mod arena;
#[path = "../lockstep.rs"]
mod lockstep;
#[path = "../stack.rs"]
mod stack;
mod level {
    include!(concat!(env!("OUT_DIR"), "/arena.rs"));
}

#[entry]
fn main() -> ! {
    let painted = stack::paint();
    let o = arena::simulate::<I16F16, _>(&level::MESH, arena::THROWS, arena::STEPS_PER_THROW);
    hprintln!("I16F16 {:016x}", o.hash);
    hprintln!(
        "arena: {} triangles, {} nodes, {} bytes in flash; {} contacts, {} escapes",
        level::MESH.len(),
        level::NODES.len(),
        core::mem::size_of_val(&level::NODES)
            + core::mem::size_of_val(&level::TRIANGLES)
            + core::mem::size_of_val(&level::ORDER),
        o.contacts,
        o.escapes
    );
    hprintln!("stack: {} bytes of RAM never touched", painted.untouched());
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
