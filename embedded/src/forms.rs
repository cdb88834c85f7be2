//! The two compact forms of a level for the Cortex-M0 (`forms`), made on the host: shared by
//! `embedded/build.rs` (which bakes them into flash) and `examples/forms.rs` (which builds them
//! at run time and must print the same hashes).
//!
//! - The arena (`examples/data/arena.obj`, 2 168 triangles) as a `CompactMesh`: its vertices
//!   shared (exact coordinates merged, `ballcast::import::weld`), u16 indices.
//! - A 64 × 64 terrain `Heightfield` (8 192 triangles) over the arena's ground, x and z from 0 to
//!   32: a bowl with ripples, heights in steps of 1/64 from an integer formula.
#![allow(dead_code)]

use ballcast::fixed::types::I16F16;
use ballcast::{HeightfieldShape, Vec3};

/// Cells along x and along z.
pub const CELLS: u32 = 64;
/// Cell side: 0.5 (I16F16 bits).
pub const SPACING_BITS: i32 = 1 << 15;
/// Height step: 1/64 (I16F16 bits).
pub const UNIT_BITS: i32 = 1 << 10;

/// The terrain's height at vertex `(i, k)`, in steps: a bowl centred on the grid, plus ripples
/// from a triangle wave.
pub fn height(i: u32, k: u32) -> i16 {
    let (x, z) = (i as i32 - 32, k as i32 - 32);
    let wave = |t: i32| ((t % 24) - 12).abs() * 2;
    ((x * x + z * z) / 6 + wave(3 * i as i32 + 2 * k as i32)) as i16
}

/// The terrain's grid: cells of 0.5 from the origin, heights in steps of 1/64.
pub fn shape() -> HeightfieldShape<I16F16> {
    HeightfieldShape {
        origin: Vec3::ZERO,
        spacing: I16F16::from_bits(SPACING_BITS),
        unit: I16F16::from_bits(UNIT_BITS),
        columns: CELLS,
        rows: CELLS,
    }
}

/// The terrain's heights, row by row (x fastest).
pub fn heights() -> Vec<i16> {
    (0..=CELLS)
        .flat_map(|k| (0..=CELLS).map(move |i| height(i, k)))
        .collect()
}
