//! The arena run (`../arena.rs`) on the two compact forms baked into flash by `build.rs`: the
//! 2 168-triangle arena as a `CompactMesh` and a 64 × 64 terrain `Heightfield` (8 192 triangles;
//! `../forms.rs`), each alone and both as one `Compound` level. Prints `compact I16F16 hash`,
//! `heightfield I16F16 hash`, `compound I16F16 hash` and, for a `Character` walking over the
//! terrain (`../walker.rs`), `character I16F16 hash` and, over the terrain with a cache of 16
//! triangles kept in a zero-initialised static (`Cached::with_cache`), `character cached I16F16
//! hash`: the lines
//! the host's
//! `cargo run --release --example forms` (the forms built at run time) prints; then each form's
//! bytes in flash, the RAM the arena runs never touched and the stack the walk used (the
//! stack is painted first, and again before the walk).
//!
//! Run: `cargo m0 forms` in `embedded/`.
#![no_std]
#![no_main]

use ballcast::{Cached, Compound, TriangleCache};
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
#[path = "../walker.rs"]
mod walker;
mod compact {
    include!(concat!(env!("OUT_DIR"), "/compact.rs"));
}
mod terrain {
    include!(concat!(env!("OUT_DIR"), "/terrain.rs"));
}

#[entry]
fn main() -> ! {
    // A cache of 16 prepared triangles for the terrain, in RAM (not on the stack): cortex-m-rt
    // hands a `static mut` of the entry function over as `&'static mut`. Empty, it is zero
    // bytes: zero-initialised (`.bss`), nothing of it in flash.
    static mut CACHE: TriangleCache<I16F16, 16> = TriangleCache::new();
    let cached = Cached::with_cache(terrain::HEIGHTFIELD, CACHE);
    let painted = stack::paint();
    let (throws, steps) = (arena::THROWS, arena::STEPS_PER_THROW);
    let c = arena::simulate::<I16F16, _>(&compact::MESH, throws, steps);
    hprintln!("compact I16F16 {:016x}", c.hash);
    let h = arena::simulate::<I16F16, _>(&terrain::HEIGHTFIELD, throws, steps);
    hprintln!("heightfield I16F16 {:016x}", h.hash);
    // Both as one level: the terrain inside the arena's walls.
    let both = Compound::new(&compact::MESH, &terrain::HEIGHTFIELD);
    let b = both.map(|level| arena::simulate::<I16F16, _>(&level, throws, steps));
    match &b {
        Ok(b) => hprintln!("compound I16F16 {:016x}", b.hash),
        Err(e) => hprintln!("compound I16F16 refused: {}", e),
    }
    let untouched = painted.untouched();
    // The walk's own stack, every frame of it (`Character::update` and all below it).
    let walk = || walker::walk::<I16F16, _>(&terrain::HEIGHTFIELD);
    let ((walked, grounded), used) = stack::used_by(walk);
    hprintln!("character I16F16 {:016x}", walked);
    let ((walked, _), used_cached) = stack::used_by(|| walker::walk::<I16F16, _>(&cached));
    hprintln!("character cached I16F16 {:016x}", walked);
    use core::mem::size_of_val as size;
    let compact_bytes = size(&compact::NODES)
        + size(&compact::VERTICES)
        + size(&compact::TRIANGLES)
        + size(&compact::ORDER)
        + size(&compact::BYTES);
    hprintln!(
        "compact: {} triangles, {} bytes in flash; {} contacts, {} escapes",
        compact::MESH.len(),
        compact_bytes,
        c.contacts,
        c.escapes
    );
    hprintln!(
        "heightfield: {} triangles, {} bytes in flash; {} contacts, {} escapes",
        terrain::HEIGHTFIELD.len(),
        size(&terrain::HEIGHTS) + size(&terrain::CELLS),
        h.contacts,
        h.escapes
    );
    hprintln!(
        "character: {} frames on the heightfield, grounded on {}; {} bytes of stack, {} through the static cache ({} hits, {} misses)",
        walker::FRAMES,
        grounded,
        used,
        used_cached,
        cached.cache().hits(),
        cached.cache().misses()
    );
    hprintln!(
        "stack: {} bytes of RAM never touched by the arena runs",
        untouched
    );
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
