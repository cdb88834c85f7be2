//! A character's walk over the terrain heightfield of `forms.rs`: `slide::Character` (radius
//! 0.4, the default step, snap and slope limit) dropped above the bowl, then walking at 3
//! units/s round an octagon (a new compass heading every second), [`FRAMES`] frames of 1/64 s,
//! with an FNV-1a 64 hash of every position ([`lockstep`](crate::lockstep)'s hash). Every input
//! is exact in every scalar, so the walk is the same bit for bit wherever it runs.
//!
//! Shared by the bare-metal program (`embedded/src/bin/forms.rs`, the terrain baked into flash,
//! which also prints the stack the walk used) and the host example (`examples/forms.rs`, the
//! terrain built at run time), which must print the same hash.
#![allow(dead_code)]

use crate::lockstep::{Bits, Fnv};
use ballcast::{Geometry, Vec3, slide::Character};

/// Frames in the walk (8 s).
pub const FRAMES: usize = 512;

/// The wished velocity's x and z for each second: the eight compass headings in turn.
const HEADINGS: [(f64, f64); 8] = [
    (3.0, 0.0),
    (2.0, 2.0),
    (0.0, 3.0),
    (-2.0, 2.0),
    (-3.0, 0.0),
    (-2.0, -2.0),
    (0.0, -3.0),
    (2.0, -2.0),
];

/// The walk's hash over `level`, and how many of its frames ended on the ground; an update
/// refused (never expected) ends the walk and is hashed as all ones.
pub fn walk<S: Bits, G: Geometry<S> + ?Sized>(level: &G) -> (u64, usize) {
    let v = |x: f64, y: f64, z: f64| Vec3::new(x, y, z).map(S::from_f64);
    let mut hash = Fnv::new();
    let Ok(mut me) = Character::new(v(16.0, 4.0, 12.0), S::from_f64(0.4)) else {
        return (u64::MAX, 0);
    };
    let (gravity, dt) = (v(0.0, -9.81, 0.0), S::from_f64(1.0 / 64.0));
    let mut grounded = 0;
    for frame in 0..FRAMES {
        let (x, z) = HEADINGS[frame / 64 % HEADINGS.len()];
        if me.update(level, v(x, 0.0, z), gravity, dt).is_err() {
            hash.write_u64(u64::MAX);
            break;
        }
        grounded += me.is_grounded() as usize;
        for c in me.position.to_array() {
            hash.write_u64(c.bits());
        }
    }
    (hash.0, grounded)
}
