//! The lockstep scene on bare metal: prints `name hash` for every scalar over semihosting, the
//! same lines as the host's `cargo run --example lockstep`, then exits through semihosting.
//!
//! Run: `cargo m0 lockstep` or `cargo m4 lockstep` in `embedded/`.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;

#[path = "../lockstep.rs"]
mod lockstep;

#[entry]
fn main() -> ! {
    lockstep::run_all(|name, o| {
        hprintln!("{} {:016x}", name, o.hash);
    });
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
