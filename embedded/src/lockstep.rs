//! The lockstep scene: a fixed room, a scripted sequence of throws, 10 000 steps in each scalar,
//! and a hash of the whole trajectory.
//!
//! One `no_std`, allocation-free module shared by the bare-metal program (`embedded/src/bin/
//! lockstep.rs`), the host example (`examples/lockstep.rs`) and the host test
//! (`tests/lockstep.rs`), which include this file with `#[path]`. Same source, same scene, same
//! order of operations everywhere, so every target must print the same hashes bit for bit.
//!
//! - Scene: a 20 × 10 × 20 room (floor and ceiling split into 8 triangles each, walls into 2,
//!   normals facing inwards) and a ramp of 4 triangles in one corner: 28 triangles.
//! - Throws: [`THROWS`] throws of [`STEPS_PER_THROW`] steps at 60 Hz, each from a start and
//!   velocity given by a fixed formula of the throw's index ([`throw`]): no randomness.
//! - Step ([`step`]): gravity, then `move_and_slide` through the scene (faces, edges and
//!   vertices, sliding along what it touches), then the velocity is clipped by the contacts.
//! - Hash: FNV-1a 64 over the raw bits of the ball's position (x, y, z) after every step, each
//!   component as 8 little-endian bytes ([`Bits`]: the IEEE bits of `f32`/`f64`, the two's
//!   complement bits of `I16F16`/`I32F32`).
//! - A ball that leaves the scalar's range (only possible if it tunnels out of the room) restarts
//!   its throw and counts as an escape; the run never panics once the scene is built.
#![allow(dead_code)]

use ballcast::{Error, Geometry, Scalar, StandardTriangle, Triangle, Vec3, move_and_slide};
use fixed::types::{I16F16, I32F32};

/// Steps in a whole run, over all throws.
pub const STEPS: usize = 10_000;
/// Throws in a run.
pub const THROWS: usize = 20;
/// Steps per throw.
pub const STEPS_PER_THROW: usize = STEPS / THROWS;
/// Triangles in the scene.
pub const TRIANGLES: usize = 28;
/// Step length, seconds.
pub const DT: f64 = 1.0 / 60.0;
/// The ball's radius.
pub const RADIUS: f64 = 0.5;
/// Gravity along y.
pub const GRAVITY: f64 = -9.81;

/// The scene's triangles in `f64`, counter-clockwise seen from the inside; every scalar converts
/// the same list with [`Scalar::from_f64`].
pub fn room() -> [[[f64; 3]; 3]; TRIANGLES] {
    let mut tris = [[[0.0; 3]; 3]; TRIANGLES];
    let mut n = 0;
    // A quad (origin o, edges a and b) split cells × cells, two triangles a cell, facing a × b.
    let mut quad = |o: [f64; 3], a: [f64; 3], b: [f64; 3], cells: usize| {
        let c = cells as f64;
        let at = |i: f64, j: f64| [0, 1, 2].map(|k| o[k] + a[k] * i / c + b[k] * j / c);
        for i in 0..cells {
            for j in 0..cells {
                let (i, j) = (i as f64, j as f64);
                tris[n] = [at(i, j), at(i + 1.0, j), at(i + 1.0, j + 1.0)];
                tris[n + 1] = [at(i, j), at(i + 1.0, j + 1.0), at(i, j + 1.0)];
                n += 2;
            }
        }
    };
    let (w, h) = (20.0, 10.0);
    quad([0.0, 0.0, 0.0], [0.0, 0.0, w], [w, 0.0, 0.0], 2); // floor, faces +y
    quad([0.0, h, 0.0], [w, 0.0, 0.0], [0.0, 0.0, w], 2); // ceiling, faces -y
    quad([0.0, 0.0, 0.0], [w, 0.0, 0.0], [0.0, h, 0.0], 1); // wall z = 0, faces +z
    quad([0.0, 0.0, w], [0.0, h, 0.0], [w, 0.0, 0.0], 1); // wall z = w, faces -z
    quad([0.0, 0.0, 0.0], [0.0, h, 0.0], [0.0, 0.0, w], 1); // wall x = 0, faces +x
    quad([w, 0.0, 0.0], [0.0, 0.0, w], [0.0, h, 0.0], 1); // wall x = w, faces -x
    // A ramp rising towards +x in the far corner, with a bump in the middle.
    let (r0, r1) = ([12.0, 0.01, 12.0], [19.9, 4.0, 12.0]);
    let (r2, r3) = ([12.0, 0.01, 19.9], [19.9, 4.0, 19.9]);
    let bump = [16.0, 2.0, 16.0];
    tris[n] = [r0, r2, r1];
    tris[n + 1] = [r1, r2, r3];
    tris[n + 2] = [r0, r2, bump];
    tris[n + 3] = [bump, r2, r3];
    tris
}

/// Throw `i`'s start position and velocity: small integers from a fixed formula, exact in
/// every scalar. Starts lie inside the room, clear of the walls.
pub fn throw(i: usize) -> ([f64; 3], [f64; 3]) {
    let f = |v: usize| v as f64;
    let start = [
        2.0 + f(i * 7 % 16),
        2.0 + f(i * 3 % 7),
        2.0 + f(i * 11 % 16),
    ];
    let velocity = [
        3.0 * (f(i * 5 % 9) - 4.0),
        2.0 * f(i * 2 % 5),
        3.0 * (f(i * 7 % 9) - 4.0),
    ];
    (start, velocity)
}

/// The constants of a run, converted once to the scalar.
#[derive(Clone, Copy, Debug)]
pub struct Params<S> {
    /// Step length.
    pub dt: S,
    /// The ball's radius.
    pub radius: S,
    /// Gravity vector.
    pub gravity: Vec3<S>,
}

impl<S: Scalar> Params<S> {
    /// The run's constants in `S`.
    pub fn new() -> Self {
        let c = S::from_f64;
        Self {
            dt: c(DT),
            radius: c(RADIUS),
            gravity: Vec3::new(S::ZERO, c(GRAVITY), S::ZERO),
        }
    }
}

/// The ball's state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball<S> {
    /// Centre.
    pub p: Vec3<S>,
    /// Velocity.
    pub v: Vec3<S>,
}

/// One time step: gravity, then `move_and_slide` through the scene (full contacts: faces,
/// edges, vertices), then the velocity loses whatever pointed into the contacts. Returns the
/// number of contacts; an error only if the ball leaves the scalar's range.
pub fn step<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    k: &Params<S>,
    ball: &mut Ball<S>,
) -> Result<u32, Error> {
    ball.v += k.gravity.scale(k.dt);
    let out = move_and_slide(scene, ball.p, ball.v.scale(k.dt), k.radius)?;
    ball.p = out.position;
    ball.v = out.clip(ball.v)?;
    Ok(out.contacts.iter().flatten().count() as u32)
}

/// A scalar's exact bit pattern, for hashing.
pub trait Bits: Scalar {
    /// The raw bits, zero-extended to 64.
    fn bits(self) -> u64;
}

impl Bits for f32 {
    fn bits(self) -> u64 {
        u64::from(self.to_bits())
    }
}

impl Bits for f64 {
    fn bits(self) -> u64 {
        self.to_bits()
    }
}

impl Bits for I16F16 {
    fn bits(self) -> u64 {
        u64::from(self.to_bits() as u32)
    }
}

impl Bits for I32F32 {
    fn bits(self) -> u64 {
        self.to_bits() as u64
    }
}

/// FNV-1a, 64-bit.
#[derive(Clone, Copy, Debug)]
pub struct Fnv(pub u64);

impl Fnv {
    /// The FNV-1a 64 offset basis.
    pub const fn new() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }

    /// Hashes `v` as 8 little-endian bytes.
    pub fn write_u64(&mut self, v: u64) {
        for b in v.to_le_bytes() {
            self.0 = (self.0 ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// What a run produced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// FNV-1a 64 of every position.
    pub hash: u64,
    /// Contacts over the whole run.
    pub contacts: u32,
    /// Throws restarted because the ball left the scalar's range.
    pub escapes: u32,
}

/// Builds the scene in `S`. Panics only if the fixed scene were invalid in `S` (it is not; the
/// host test runs this for every scalar).
/// The triangles are pushed one by one into the caller's storage: no scene-sized temporary on
/// the stack, which a 16 KB Cortex-M0 cannot spare.
pub fn scene<S: Scalar>(tris: &mut Triangles<S>) {
    for t in room() {
        let v = t.map(|p| Vec3::new(p[0], p[1], p[2]).map(S::from_f64));
        let st = StandardTriangle::new(&Triangle::new(v[0], v[1], v[2]));
        let _ = tris.push(st.expect("the scene is valid"));
    }
}

/// Storage for the prepared scene.
pub type Triangles<S> = heapless::Vec<StandardTriangle<S>, TRIANGLES>;

/// Runs the whole scripted sequence in `S`. Never inlined: each scalar's scene (up to 6 KB) then
/// lives in its own stack frame, freed before the next, which a 16 KB Cortex-M0 needs.
#[inline(never)]
pub fn simulate<S: Bits>() -> Outcome {
    let mut tris = Triangles::<S>::new();
    scene(&mut tris);
    let k = Params::<S>::new();
    let v3 = |p: [f64; 3]| Vec3::new(p[0], p[1], p[2]).map(S::from_f64);
    let mut out = Outcome {
        hash: 0,
        contacts: 0,
        escapes: 0,
    };
    let mut hash = Fnv::new();
    for i in 0..THROWS {
        let (p, v) = throw(i);
        let start = Ball { p: v3(p), v: v3(v) };
        let mut ball = start;
        for _ in 0..STEPS_PER_THROW {
            match step(&tris[..], &k, &mut ball) {
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

/// The scalars' names, in the order [`run_all`] reports them.
pub const NAMES: [&str; 4] = ["f64", "f32", "I32F32", "I16F16"];

/// Runs every scalar in [`NAMES`] order and hands each name and outcome to `report`.
pub fn run_all(mut report: impl FnMut(&'static str, Outcome)) {
    report(NAMES[0], simulate::<f64>());
    report(NAMES[1], simulate::<f32>());
    report(NAMES[2], simulate::<I32F32>());
    report(NAMES[3], simulate::<I16F16>());
}
