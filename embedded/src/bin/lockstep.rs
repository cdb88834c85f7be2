//! The lockstep scene on bare metal: prints `name hash` for every scalar over semihosting, the
//! same lines as the host's `cargo run --example lockstep`, then exits through semihosting.
//! Last, it prints how much of the RAM below the stack the run never touched (the stack is
//! painted first), so a change that grows the library's stack shows before it overflows.
//!
//! Run: `cargo m0 lockstep` or `cargo m4 lockstep` in `embedded/`.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;

#[path = "../lockstep.rs"]
mod lockstep;
#[path = "../stack.rs"]
mod stack;

#[entry]
fn main() -> ! {
    let painted = stack::paint();
    lockstep::run_all(|name, o| {
        hprintln!("{} {:016x}", name, o.hash);
    });
    hprintln!("stack: {} bytes of RAM never touched", painted.untouched());
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
