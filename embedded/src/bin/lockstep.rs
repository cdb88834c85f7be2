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

const PAINT: u32 = 0xDEAD_BEEF;

unsafe extern "C" {
    /// The end of static data: the stack grows down towards it (cortex-m-rt's link.x).
    static mut __sheap: u32;
}

/// The free RAM from the end of static data up to (a margin below) the current stack pointer.
fn free_ram() -> (*mut u32, usize) {
    let start = &raw mut __sheap;
    let sp = cortex_m::register::msp::read() as usize - 256;
    (start, (sp - start as usize) / 4)
}

#[entry]
fn main() -> ! {
    let (start, words) = free_ram();
    for i in 0..words {
        // SAFETY: the words lie between the end of static data and below the live stack.
        unsafe { start.add(i).write_volatile(PAINT) };
    }
    lockstep::run_all(|name, o| {
        hprintln!("{} {:016x}", name, o.hash);
    });
    // SAFETY: as above; only read.
    let untouched = (0..words)
        .take_while(|&i| unsafe { start.add(i).read_volatile() } == PAINT)
        .count();
    hprintln!("stack: {} bytes of RAM never touched", untouched * 4);
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
