//! Walking over crests with the README's recipe: a walker that stood on the floor when its
//! frame began is snapped down onto the floor within its snap depth wherever its walk left the
//! floor, up a slope as well as down one, so it stays grounded over the top of a ramp, up a
//! ledge and across bumpy ground (a game that lets a character jump only from the floor drops
//! no jump there). Off a ramp's lip over a drop it still flies (`tests/stairs.rs`). Every
//! property in every scalar.

mod common;

use ballcast::{Heightfield, HeightfieldShape, Scalar, Scene, Sweep, Triangle, Vec3};
use common::walker::{Gait, HALF, walk, walk_with, with_and_without_snap};
use common::{P, Rng, Tolerance, back, quad, v};
use fixed::types::{I16F16, I32F32};

/// The top of a 20° ramp 4 long, from x = 2 to 6.
const TOP: f64 = 1.455_880_8;

/// A floor at y = 0 up to x = 2, a 20° ramp up to a landing at `TOP` from x = 6, and at x = 10 a
/// ledge 0.2 higher (its riser two-sided), out to x = 20; 10 wide in z.
fn ramp_and_ledge<S: Scalar>() -> Scene<S, 16> {
    let (z, across) = ([0.0, 0.0, 10.0], -5.0);
    let floor = |x0: f64, y0: f64, x1: f64, y1: f64| [[x0, y0, across], z, [x1 - x0, y1 - y0, 0.0]];
    let mut s = Scene::new();
    for [o, a, b] in [
        floor(-5.0, 0.0, 2.0, 0.0),
        floor(2.0, 0.0, 6.0, TOP),
        floor(6.0, TOP, 10.0, TOP),
        floor(10.0, TOP + 0.2, 20.0, TOP + 0.2),
    ] {
        for t in quad(o, a, b) {
            s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
        }
    }
    for t in quad([10.0, TOP, across], [0.0, 0.2, 0.0], z) {
        s.push_two_sided(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    s
}

/// Walking at 2 units/s (r 0.5, 60 Hz) up the ramp, over its top onto the landing and up the
/// ledge: grounded on every frame, ending on the ledge a skin above it. A recipe that asked the
/// snap only of a ball not moving up left it in the air on 5 frames over the ramp's top (a hop
/// of 7 thousandths) and on 7 to 9 up the ledge.
fn walking_over_a_ramps_top_and_up_a_ledge_stays_grounded<S: Tolerance>() {
    let level = ramp_and_ledge::<S>();
    let mut airborne = Vec::new();
    let mut frame = 0;
    let end = walk(
        &level,
        [0.0, 0.5005, 0.0],
        [2.0, 0.0, 0.0],
        HALF,
        480,
        |p, g| {
            if !g {
                airborne.push((frame, back(p)));
            }
            frame += 1;
        },
    );
    assert!(
        airborne.is_empty(),
        "{}: in the air at {airborne:?}",
        S::NAME
    );
    let [x, y, _] = back(end);
    assert!(
        x > 15.0 && (y - (TOP + 0.7)).abs() < 0.01,
        "{}: ended at {:?}",
        S::NAME,
        back(end)
    );
}

/// Bumpy ground: a heightfield of 24 × 20 cells of side 1 with heights within ±0.2 (slopes up
/// to about 22°). Six balls (r 0.5, 60 Hz) dropped onto it walk at 3 units/s, each second
/// towards a new random point well inside it, for 20 s: from their first landing on, each is
/// grounded on every frame, and never lower than a ball dropped straight down there rests (by
/// more than a few steps). A recipe that asked the snap only of a ball not moving up left them
/// in the air on 16 % of those frames (over the crests they walked across uphill).
fn walking_on_bumpy_ground_stays_grounded<S: Tolerance>() {
    let (columns, rows) = (24u32, 20u32);
    let mut rng = Rng(0xB0_4B5);
    let heights: Vec<i16> = (0..(columns + 1) * (rows + 1))
        .map(|_| rng.range(-4.0, 4.0).round() as i16)
        .collect();
    let mut cells = vec![0u8; (columns * rows) as usize];
    let (origin, unit) = (v::<S>([-12.0, 0.0, -10.0]), S::from_f64(0.05));
    let built = Heightfield::build(
        HeightfieldShape {
            origin,
            spacing: S::ONE,
            unit,
            columns,
            rows,
        },
        &heights,
        |_, _| false,
        &mut cells,
    );
    let ground = built.unwrap();
    let r = S::from_f64(HALF.r);
    // Where a ball dropped straight down at (x, z) rests.
    let rest = |x: f64, z: f64| {
        let drop = Sweep::new(v::<S>([x, 5.0, z]), v::<S>([x, -5.0, z]), r).unwrap();
        back(ground.cast(&drop).unwrap().position)[1]
    };
    let allowed = 4.0 * S::spacing(16.0) + S::DISTANCE;
    for ball in 0..6 {
        let start: P = [rng.range(-6.0, 6.0), 1.5, rng.range(-5.0, 5.0)];
        let mut target = [0.0; 3];
        let mut heading = |frame: usize, p: Vec3<S>| {
            if frame.is_multiple_of(60) {
                target = [rng.range(-8.0, 8.0), 0.0, rng.range(-6.0, 6.0)];
            }
            let [x, _, z] = back(p);
            let (dx, dz) = (target[0] - x, target[2] - z);
            let d = (dx * dx + dz * dz).sqrt().max(1e-9);
            [3.0 * dx / d, 0.0, 3.0 * dz / d]
        };
        let (mut frame, mut landed) = (0, None);
        walk_with(&ground, start, &mut heading, HALF, 1200, |p, on| {
            let [x, y, z] = back(p);
            landed = landed.or(on.then_some(frame));
            assert!(
                landed.is_none() || on,
                "{}: ball {ball} in the air at frame {frame} (landed at {landed:?}), at {:?}",
                S::NAME,
                back(p)
            );
            let below = rest(x, z) - y;
            assert!(
                below <= allowed,
                "{}: ball {ball} at frame {frame} {below:e} below its resting height, at {:?}",
                S::NAME,
                back(p)
            );
            frame += 1;
        });
        assert!(
            landed.is_some_and(|l| l < 60),
            "{}: ball {ball} landed at {landed:?}",
            S::NAME
        );
    }
}

/// A flight of 20 steps 0.18 high on treads of 0.28 (a building's stairs) from x = 0, with a
/// floor before it and a landing after it; 10 wide in z.
fn flight<S: Scalar>() -> Scene<S, 96> {
    let (z, across) = ([0.0, 0.0, 10.0], -5.0);
    let (rise, tread) = (0.18, 0.28);
    let mut quads = vec![[[-5.0, 0.0, across], z, [5.0, 0.0, 0.0]]];
    for k in 0..20 {
        let (x, y) = (k as f64 * tread, k as f64 * rise);
        let long = if k == 19 { 5.0 } else { tread };
        quads.push([[x, y, across], z, [0.0, rise, 0.0]]); // the riser, facing -x
        quads.push([[x, y + rise, across], z, [long, 0.0, 0.0]]);
    }
    let mut s = Scene::new();
    for [o, a, b] in quads {
        for t in quad(o, a, b) {
            s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
        }
    }
    s
}

/// Walking up that flight (r 0.4, stepping and snapping 0.2) at 2 to 8 units/s, 60 and 120
/// Hz: grounded on every frame once landed, and never more than 0.05 above the highest tread
/// within its radius ahead. Past each step's edge, the snap looks for floor a radius and a skin
/// on, and on treads narrower than the ball that point is already in the next step: the cast
/// from there met the riser at once, which the snap took for a drop, so the ball left the floor
/// with its walk's rise over the edge and hopped: in the air on 24 % to 62 % of the frames, up
/// to 0.063 above the tread at 8 units/s, in every scalar.
fn walking_up_a_narrow_flight_stays_grounded<S: Tolerance>() {
    let level = flight::<S>();
    for (speed, hz) in [
        (2.0, 60.0),
        (2.0, 120.0),
        (4.0, 60.0),
        (4.0, 120.0),
        (8.0, 120.0),
    ] {
        let gait = Gait {
            r: 0.4,
            hz,
            step: 0.2,
            snap: 0.2,
        };
        let (mut frame, mut airborne, mut high) = (0, 0, 0.0f64);
        let frames = (3.0 / speed * hz) as usize;
        walk(
            &level,
            [-1.0, 0.41, 0.0],
            [speed, 0.0, 0.0],
            gait,
            frames,
            |p, g| {
                // The highest tread within the ball's reach ahead.
                let [x, y, _] = back(p);
                let ahead = x + 0.4;
                let tread = if ahead < 0.0 {
                    0.0
                } else {
                    0.18 * ((ahead / 0.28).floor() + 1.0).min(20.0)
                };
                (airborne, high) = (
                    airborne + (!g && frame > 5) as usize,
                    high.max(y - 0.4 - tread),
                );
                frame += 1;
            },
        );
        assert!(
            airborne == 0 && high < 0.05,
            "{} {speed} units/s at {hz} Hz: in the air on {airborne} of {frames} frames, up to \
             {high} above the tread",
            S::NAME
        );
    }
}

/// Running up that flight at 10 units/s at 30 Hz and 20 units/s at 30 and 60 Hz (a frame's walk
/// longer than a tread): the ball climbs it, 2 units up in 1 s. The step lifted the ball and
/// carried it across by the whole walk, into the second riser; lowered from there it came down
/// on the first step's nosing too steep to stand on, so the step was dropped, and the walk
/// stopped at the first riser, every frame: the ball stood at the foot of the stairs for good,
/// in every scalar.
fn running_up_a_narrow_flight_climbs_it<S: Tolerance>() {
    let level = flight::<S>();
    for (speed, hz) in [(10.0, 30.0), (20.0, 30.0), (20.0, 60.0)] {
        let gait = Gait {
            r: 0.4,
            hz,
            step: 0.2,
            snap: 0.2,
        };
        let end = walk(
            &level,
            [-1.0, 0.41, 0.0],
            [speed, 0.0, 0.0],
            gait,
            hz as usize,
            |_, _| (),
        );
        let [x, y, _] = back(end);
        assert!(
            y > 2.4,
            "{} {speed} units/s at {hz} Hz: at x {x}, y {y} after 1 s",
            S::NAME
        );
    }
}

/// A floor at y = 0 up to x = 0, a riser `d` high there facing -x, and a floor at y = `d` out
/// to x = 30; 10 wide in z.
fn small_step<S: Scalar>(d: f64) -> Scene<S, 6> {
    let (z, across) = ([0.0, 0.0, 10.0], -5.0);
    let mut s = Scene::new();
    for [o, a, b] in [
        [[-10.0, 0.0, across], z, [10.0, 0.0, 0.0]],
        [[0.0, 0.0, across], z, [0.0, d, 0.0]],
        [[0.0, d, across], z, [30.0, 0.0, 0.0]],
    ] {
        for t in quad(o, a, b) {
            s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
        }
    }
    s
}

/// Running over small steps (3 to 10 cm, r 0.4) at 12 to 24 units/s, 30 and 60 Hz, where a
/// frame's walk is about the radius: the ball stays within 0.2 of the floor it is on (or of the
/// step's top, over the edge). The walk met the step's edge part-way, took its rounded top
/// (within the slope limit) for the floor, and went on up along its tilted plane; the next
/// frame's walk along that plane rose 0.2 more, out of the snap's reach, and the ball flew off
/// with that rise, 1.8 to 7.1 units high, in every scalar. The snap now reaches down by what
/// the walk rose too. (The first frame's walk along the edge's plane still lifts the ball up to
/// 0.16 over the step at 16 units/s and 30 Hz.)
fn running_over_small_steps_stays_on_the_floor<S: Tolerance>() {
    for d in [0.03, 0.05, 0.1] {
        let level = small_step::<S>(d);
        for (speed, hz) in [(12.0, 30.0), (16.0, 30.0), (20.0, 30.0), (24.0, 60.0)] {
            let gait = Gait {
                r: 0.4,
                hz,
                step: 0.2,
                snap: 0.2,
            };
            let mut high = 0.0f64;
            let frames = (1.2 * hz) as usize;
            walk(
                &level,
                [-4.0, 0.401, 0.0],
                [speed, 0.0, 0.0],
                gait,
                frames,
                |p, _| {
                    let [x, y, _] = back(p);
                    // Past the riser, or on its edge.
                    let floor = if x > -0.4 { d } else { 0.0 };
                    high = high.max(y - 0.4 - floor);
                },
            );
            assert!(
                high < 0.2,
                "{} step {d} at {speed} units/s, {hz} Hz: up to {high} above the floor",
                S::NAME
            );
        }
    }
}

/// A 30° or 20° ramp 40 wide rising to a lip at x = 3, beyond it a drop of 0.5 (deeper than
/// the snap, though within a radius more), 3, or 0.28 (deeper than the snap by less than a
/// frame's rise along the ramp, which the snap once added to its depth as for an edge's rounded
/// top; at 60 Hz only, see below): walked at 8 units/s head-on (at 60 and 240 Hz)
/// and at 45° to the lip (60 Hz), the ball flies off the lip, at least 0.1 above it, as it
/// would without the snap, bit for bit, until it lands. Looking past the lip along the heading (a radius and a skin, of which
/// only the part across the lip gets past it at an angle) and a radius deeper than the snap,
/// the snap once found floor there and held the ball onto the lip: it dropped off it instead
/// of flying 4 units.
fn off_a_ramps_lip_over_a_drop_the_ball_flies<S: Tolerance>() {
    for (degrees, drop) in [(30.0f64, 0.5), (20.0, 0.5), (30.0, 3.0), (30.0, 0.28)] {
        let (z, across) = ([0.0, 0.0, 40.0], -20.0);
        let rise = 3.0 * degrees.to_radians().tan();
        let mut level = Scene::<S, 16>::new();
        let flat = [[-10.0, 0.0, across], z, [10.0, 0.0, 0.0]];
        let ramp = [[0.0, 0.0, across], z, [3.0, rise, 0.0]];
        let below = [[3.0, rise - drop, across], z, [20.0, 0.0, 0.0]];
        for [o, a, b] in [flat, ramp, below] {
            for t in quad(o, a, b) {
                level
                    .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                    .unwrap();
            }
        }
        for t in quad([3.0, rise - drop, across], [0.0, drop, 0.0], z) {
            level
                .push_two_sided(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
        for (heading, hz) in [(0.0f64, 60.0), (0.0, 240.0), (45.0, 60.0)] {
            // At 240 Hz the ball leaves the lip's rounded edge with its bottom 0.24 over the
            // floor below a drop of 0.28: within the snap, which takes it there.
            if drop < 0.3 && hz > 60.0 {
                continue;
            }
            let (sin, cos) = heading.to_radians().sin_cos();
            let wish = [8.0 * cos, 0.0, 8.0 * sin];
            let frames = (1.5 * hz) as usize;
            let (start, gait) = ([-3.0, 0.5005, -5.0], Gait { hz, ..HALF });
            let what = format!("{}: {degrees}° over {drop} at {heading}°, {hz} Hz", S::NAME);
            let paths = with_and_without_snap(&level, start, wish, gait, frames);
            let [snapped, plain] = paths.unwrap_or_else(|| panic!("{what}: never left the floor"));
            let top = plain.iter().map(|(p, _)| p[1]).fold(f64::MIN, f64::max);
            assert!(top > rise + 0.5 + 0.1, "{what}: no flight (top {top})");
            assert_eq!(snapped, plain, "{what}: with the snap, and without");
        }
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn walking_over_a_ramps_top_and_up_a_ledge_stays_grounded() {
            super::walking_over_a_ramps_top_and_up_a_ledge_stays_grounded::<$t>();
        }
        #[test]
        fn walking_up_a_narrow_flight_stays_grounded() {
            super::walking_up_a_narrow_flight_stays_grounded::<$t>();
        }
        #[test]
        fn running_up_a_narrow_flight_climbs_it() {
            super::running_up_a_narrow_flight_climbs_it::<$t>();
        }
        #[test]
        fn running_over_small_steps_stays_on_the_floor() {
            super::running_over_small_steps_stays_on_the_floor::<$t>();
        }
        #[test]
        fn off_a_ramps_lip_over_a_drop_the_ball_flies() {
            super::off_a_ramps_lip_over_a_drop_the_ball_flies::<$t>();
        }
        #[test]
        fn walking_on_bumpy_ground_stays_grounded() {
            super::walking_on_bumpy_ground_stays_grounded::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
