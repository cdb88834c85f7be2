//! A character's game loop on a level of two parts, in `I16F16` and `f32` side by side: a
//! 32 × 32 terrain heightfield of hills and four crates as a mesh, one `Compound`, held by a
//! `Cached` (its own 32 prepared triangles) beside the `Character`. 20 s at 64 frames a second
//! (a power of two, exact in fixed point; `1/60` is not): walking a circle over the hills and
//! into the crates, a jump every 4 s, standing on the hillside for the last 4 s. Prints each
//! second where the two scalars' characters are and how far apart, whether they stand, and
//! what the cache saved.
//!
//! ```sh
//! cargo run --release --example character
//! ```

use ballcast::bvh::nodes_for;
use ballcast::fixed::types::I16F16;
use ballcast::slide::Character;
use ballcast::{Cached, Compound, Degenerates, Heightfield, HeightfieldShape, Mesh, Node, Scalar};
use ballcast::{Triangle, Vec3};

/// Frames a second, and seconds in all.
const HZ: usize = 64;
const SECONDS: usize = 20;
/// Cells a side, of one unit; heights in steps of 1/64.
const CELLS: u32 = 32;

/// A point in any scalar, from `f64` (saturating in fixed point, so a bad value is refused by
/// the crate's checks rather than wrapped).
fn v<S: Scalar>(x: f64, y: f64, z: f64) -> Vec3<S> {
    Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z))
}

/// The terrain's height at `(x, z)`: hills up to 1.5 high.
fn hill(x: f64, z: f64) -> f64 {
    0.75 * (1.0 + (x / 5.0).sin() * (z / 7.0).cos())
}

/// The heights, row by row along x, in steps of 1/64.
fn heights() -> Vec<i16> {
    let side = CELLS + 1;
    let at = |i: u32| {
        let (x, z) = (f64::from(i % side) - 16.0, f64::from(i / side) - 16.0);
        (hill(x, z) * 64.0).round() as i16
    };
    (0..side * side).map(at).collect()
}

/// Four crates of side 1.5 standing on the terrain around the circle, their five visible
/// faces wound to face out.
fn crates<S: Scalar>() -> Vec<Triangle<S>> {
    let mut out = Vec::new();
    for (cx, cz) in [(6.0, 0.0), (0.0, 6.0), (-6.0, 0.0), (0.0, -6.0)] {
        let (lo, hi) = ([cx - 0.75, -1.0, cz - 0.75], [cx + 0.75, 3.0, cz + 0.75]);
        // Each face: a corner and its two edges, the front normal being their cross product.
        let faces = [
            ([lo[0], hi[1], lo[2]], [0.0, 0.0, 1.5], [1.5, 0.0, 0.0]), // top, +y
            ([lo[0], lo[1], lo[2]], [0.0, 0.0, 1.5], [0.0, 4.0, 0.0]), // -x
            ([hi[0], lo[1], lo[2]], [0.0, 4.0, 0.0], [0.0, 0.0, 1.5]), // +x
            ([lo[0], lo[1], lo[2]], [0.0, 4.0, 0.0], [1.5, 0.0, 0.0]), // -z
            ([lo[0], lo[1], hi[2]], [1.5, 0.0, 0.0], [0.0, 4.0, 0.0]), // +z
        ];
        for (p, a, b) in faces {
            let at = |s: f64, t: f64| {
                v::<S>(
                    p[0] + s * a[0] + t * b[0],
                    p[1] + s * a[1] + t * b[1],
                    p[2] + s * a[2] + t * b[2],
                )
            };
            out.push(Triangle::new(at(0.0, 0.0), at(1.0, 0.0), at(1.0, 1.0)));
            out.push(Triangle::new(at(0.0, 0.0), at(1.0, 1.0), at(0.0, 1.0)));
        }
    }
    out
}

/// Each second of the run: where the character is, whether it stands, the cache's hits and
/// misses so far.
type Trace<S> = Vec<(Vec3<S>, bool, u32, u32)>;

fn run<S: Scalar>() -> Result<Trace<S>, Box<dyn std::error::Error>> {
    // The level's buffers: a game keeps them beside its state (or bakes them into flash).
    let heights = heights();
    let mut cells = vec![0u8; (CELLS * CELLS) as usize];
    let origin = v::<S>(-16.0, 0.0, -16.0);
    let (cell, unit) = (S::ONE, S::from_f64(1.0 / 64.0));
    let no_holes = |_, _| false;
    let terrain = Heightfield::build(
        HeightfieldShape {
            origin,
            spacing: cell,
            unit,
            columns: CELLS,
            rows: CELLS,
        },
        &heights,
        no_holes,
        &mut cells,
    )?;
    let boxes = crates::<S>();
    let n = boxes.len();
    let (mut nodes, mut prepared) = (vec![Node::default(); nodes_for(n)], vec![Mesh::filler(); n]);
    let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
    let (mesh, _) = Mesh::build(
        &boxes,
        Degenerates::Refuse,
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    )?;
    // The whole level cached as one: the terrain's triangles are kept from frame to frame,
    // the crates' are prepared already.
    let level: Cached<_, S, 32> = Cached::new(Compound::new(terrain, mesh)?);

    let (gravity, dt) = (v::<S>(0.0, -9.81, 0.0), S::from_f64(1.0 / HZ as f64));
    let mut me = Character::new(v(5.0, 3.0, -3.0), S::from_f64(0.4))?;
    let mut trace = Vec::new();
    for frame in 0..HZ * SECONDS {
        let t = frame as f64 / HZ as f64;
        let wish = if t < 16.0 {
            // Towards a point running round a circle of radius 6 (through the crates) a little
            // ahead, at 3 units a second.
            let a = t / 2.0 - 0.5;
            let ahead = v::<f64>(6.0 * a.cos(), 0.0, 6.0 * a.sin()) - me.position.cast();
            let flat = Vec3::new(ahead.x, 0.0, ahead.z).normalize_or_zero() * 3.0;
            flat.cast()
        } else {
            Vec3::ZERO
        };
        me.update(&level, wish, gravity, dt)?;
        if frame % (4 * HZ) == 2 * HZ && t < 16.0 && !me.jump(S::from_f64(4.0))? {
            println!(
                "  ({}: no jump at {t} s, in the air)",
                S::PRECISION.scalar.name()
            );
        }
        if (frame + 1) % HZ == 0 {
            let c = level.cache();
            trace.push((me.position, me.is_grounded(), c.hits(), c.misses()));
        }
    }
    Ok(trace)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let (a, b) = (run::<f32>()?, run::<I16F16>()?);
    println!(
        "  s | f32 position               | I16F16 position            | apart  | on the ground | I16F16 cache hits / misses"
    );
    let show = |p: Vec3<f64>| format!("({:7.3}, {:6.3}, {:7.3})", p.x, p.y, p.z);
    for (s, ((pa, ga, ..), (pb, gb, hits, misses))) in a.iter().zip(&b).enumerate() {
        let (pa, pb) = (pa.cast::<f64>(), pb.cast::<f64>());
        let apart = (pa - pb).length();
        println!(
            "{:3} | {} | {} | {apart:.4} | {ga:5} {gb:5}   | {hits} / {misses}",
            s + 1,
            show(pa),
            show(pb)
        );
    }
    Ok(())
}
