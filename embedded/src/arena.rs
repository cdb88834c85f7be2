//! The arena run: the lockstep scene's kind of run over a level of 2 168 triangles
//! (`examples/data/arena.obj`, a rippled bowl closed by four walls) in `I16F16`: [`THROWS`]
//! scripted throws of [`STEPS_PER_THROW`] steps, each step gravity, `move_and_slide` and the
//! velocity clipped, and an FNV-1a 64 hash of every position ([`lockstep`](crate::lockstep)'s
//! step and hash).
//!
//! Shared, like `lockstep.rs`, by the bare-metal program (`embedded/src/bin/arena.rs`, the mesh
//! baked into flash by `embedded/build.rs`) and the host example (`examples/arena.rs`, the mesh
//! built at run time from the same file), which must print the same hash bit for bit.
#![allow(dead_code)]

use crate::lockstep::{Ball, Bits, Fnv, Outcome, Params, step};
use ballcast::{Geometry, Vec3};

/// Throws in a run.
pub const THROWS: usize = 20;
/// Steps per throw (60 Hz).
pub const STEPS_PER_THROW: usize = 500;

/// Throw `i`'s start and velocity: small integers from a fixed formula, exact in every scalar.
/// Starts lie above the bowl, inside the walls (x from 0 to 30, z from 0 to 32).
pub fn throw(i: usize) -> ([f64; 3], [f64; 3]) {
    let f = |v: usize| v as f64;
    let start = [3.0 + f(i * 7 % 24), 9.0, 3.0 + f(i * 11 % 26)];
    let velocity = [
        2.0 * (f(i * 5 % 9) - 4.0),
        f(i * 2 % 5),
        2.0 * (f(i * 7 % 9) - 4.0),
    ];
    (start, velocity)
}

/// Runs `throws` throws of `steps` steps each through `level`.
pub fn simulate<S: Bits, G: Geometry<S> + ?Sized>(
    level: &G,
    throws: usize,
    steps: usize,
) -> Outcome {
    let k = Params::<S>::new();
    let v3 = |p: [f64; 3]| Vec3::new(p[0], p[1], p[2]).map(S::from_f64);
    let mut out = Outcome {
        hash: 0,
        contacts: 0,
        escapes: 0,
    };
    let mut hash = Fnv::new();
    for i in 0..throws {
        let (p, v) = throw(i);
        let start = Ball { p: v3(p), v: v3(v) };
        let mut ball = start;
        for _ in 0..steps {
            match step(level, &k, &mut ball) {
                Ok(n) => out.contacts += n,
                Err(_) => {
                    out.escapes += 1;
                    ball = start;
                }
            }
            for c in ball.p.to_array() {
                hash.write_u64(c.bits());
            }
        }
    }
    out.hash = hash.0;
    out
}
