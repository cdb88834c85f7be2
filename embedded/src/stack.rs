//! Stack headroom for the bare-metal programs: the RAM between the end of static data and (a
//! margin below) the stack pointer is painted before a run; afterwards, the painted words still
//! intact from the bottom up are RAM the run never touched. [`used_by`] gives the stack a call
//! takes, its own frames included.
// Shared by several programs, each of which uses part of it.
#![allow(dead_code)]

const PAINT: u32 = 0xDEAD_BEEF;

unsafe extern "C" {
    /// The end of static data: the stack grows down towards it (cortex-m-rt's link.x).
    static mut __sheap: u32;
}

/// The painted RAM.
pub struct Painted {
    start: *mut u32,
    words: usize,
}

/// Paints the free RAM below the stack.
pub fn paint() -> Painted {
    let start = &raw mut __sheap;
    let sp = cortex_m::register::msp::read() as usize - 256;
    let words = (sp - start as usize) / 4;
    for i in 0..words {
        // SAFETY: the words lie between the end of static data and below the live stack.
        unsafe { start.add(i).write_volatile(PAINT) };
    }
    Painted { start, words }
}

impl Painted {
    /// Bytes of the painted RAM the run never touched.
    pub fn untouched(&self) -> usize {
        // SAFETY: as in `paint`; only read.
        let intact = (0..self.words)
            .take_while(|&i| unsafe { self.start.add(i).read_volatile() } == PAINT)
            .count();
        intact * 4
    }
}

/// `f()` and the bytes of stack it took: from the stack pointer it was called at down to the
/// deepest word it wrote, every frame of it counted (the call runs out of line, below this
/// function's frame). Exact for a call that takes more than the painting's margin (256 bytes).
#[inline(never)]
pub fn used_by<R>(f: impl FnOnce() -> R) -> (R, usize) {
    let painted = paint();
    let top = cortex_m::register::msp::read() as usize;
    let r = out_of_line(f);
    let deepest = painted.start as usize + painted.untouched();
    (r, top - deepest)
}

/// `f()` in a frame of its own.
#[inline(never)]
fn out_of_line<R>(f: impl FnOnce() -> R) -> R {
    f()
}
