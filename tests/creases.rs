//! A character pushing into a wall where the ground rises towards it, or tilts along it: the walk
//! keeps to the floor it stands on, so what the wall leaves of it runs along the crease of the
//! two, not up the wall (a frame up, pressed back down the next: a jitter) nor along it (a
//! creep). A steep ditch walked up (far from the origin: `tests/far_out.rs`). Every scalar.

mod common;

use ballcast::{Scalar, Scene, Triangle, Vec3, penetration, slide::Character};
use common::{Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// A floor through the origin rising by `rise` per unit of x and `tilt` per unit of z, and a
/// wall through x = 3 (at height 0) facing -x, leaning back by `lean` (its x growing by `lean`
/// per unit of height), from below the floor to well above the ball.
fn crease<S: Scalar>(rise: f64, tilt: f64, lean: f64) -> Scene<S, 4> {
    let mut s = Scene::new();
    let y = |x: f64, z: f64| rise * x + tilt * z;
    let p = |x: f64, z: f64| v::<S>([x, y(x, z), z]);
    let (a, b, c, d) = (p(-6.0, -6.0), p(-6.0, 6.0), p(4.0, 6.0), p(4.0, -6.0));
    s.push(Triangle::new(a, b, c)).unwrap();
    s.push(Triangle::new(a, c, d)).unwrap();
    let w = |y: f64, z: f64| v::<S>([3.0 + lean * y, y, z]);
    let (e, f, g, h) = (w(-5.0, -6.0), w(-5.0, 6.0), w(6.0, 6.0), w(6.0, -6.0));
    s.push(Triangle::new(e, f, g)).unwrap();
    s.push(Triangle::new(e, g, h)).unwrap();
    s
}

/// Walking at 2 units/s straight at the wall of `level` from the origin: once there (two
/// seconds), the ball stays put for four more seconds (each frame moves it by less than 1e-4,
/// and in all by less than 1e-3) and overlaps nothing.
fn walks_into_the_wall_and_stays_put<S: Tolerance>(level: &Scene<S, 4>, case: &str) {
    let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / 60.0));
    let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>([2.0, 0.0, 0.0]));
    let mut me = Character::new(v::<S>([0.0, 0.6, 0.0]), r).unwrap();
    for _ in 0..120 {
        me.update(level, wish, gravity, dt).unwrap();
    }
    let at = me.position;
    assert!(
        at.x.to_f64() > 2.4,
        "{} {case}: at {at:?}, not at the wall",
        S::NAME
    );
    let mut most = 0.0f64;
    for frame in 0..240 {
        let before = me.position;
        me.update(level, wish, gravity, dt).unwrap();
        let moved = (me.position - before).to_array().map(|c| c.to_f64().abs());
        most = most.max(moved[0].max(moved[1]).max(moved[2]));
        let left = penetration(level, me.position, r).unwrap();
        assert!(left.is_none(), "{} {case} frame {frame}: {left:?}", S::NAME);
    }
    assert!(
        most < 1e-4,
        "{} {case}: moved up to {most} a frame",
        S::NAME
    );
    let drift = (me.position - at).to_array().map(|c| c.to_f64().abs());
    assert!(
        drift.iter().all(|d| *d < 1e-3),
        "{} {case}: drifted {drift:?}",
        S::NAME
    );
}

/// On ground rising 10° towards the wall and, in the second case, tilted 8° along it: the walk
/// up the wall moved the ball 6 mm a frame up and down, and the tilt carried it along the wall.
fn pushing_into_a_wall_on_rising_ground_stays_put<S: Tolerance>() {
    let (rise, tilt) = (10f64.to_radians().tan(), 8f64.to_radians().tan());
    for (case, tilt) in [("rising", 0.0), ("rising and tilted", tilt)] {
        walks_into_the_wall_and_stays_put(&crease::<S>(rise, tilt, 0.0), case);
    }
}

/// Walking at 8 units/s into the wall at the top of a 40° slope at 30 Hz: a frame's walk
/// (`Slider::walk`) from against the wall rises less than 0.01, and the character, after a
/// second, is on the floor on every frame, never more than 0.01 higher than where it first
/// stopped. A walk of 0.13 a frame up the slope counted its own rise in the height of a ledge
/// it may step over, took the upright wall for one, climbed it by the rise (0.13), and was
/// launched off it (up to 0.85 high, grounded on 9 % to 12 % of the frames, every scalar).
fn walking_fast_up_a_steep_slope_into_a_wall_stays_put<S: Tolerance>() {
    let level = crease::<S>(40f64.to_radians().tan(), 0.0, 0.0);
    let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / 30.0));
    let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>([8.0, 0.0, 0.0]));
    let mut me = Character::new(v::<S>([0.0, 0.66, 0.0]), r).unwrap();
    for _ in 0..30 {
        me.update(&level, wish, gravity, dt).unwrap();
    }
    // The walk itself, from against the wall a skin off the slope: it keeps to the floor,
    // not up the wall by its rise (which the snap would otherwise hide, pulling it back down).
    let (sin, cos) = 40f64.to_radians().sin_cos();
    let x = 2.4995;
    let at = v::<S>([x, x * sin / cos + 0.5 / cos + 0.0005, 0.0]);
    let floor = v::<S>([-sin, cos, 0.0]);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let step = wish.reject_from_normalized(floor) * dt;
    let walk = me.slider().walk(
        &level,
        at,
        step,
        Some(floor),
        (up, walkable),
        S::from_f64(0.25),
    );
    let rose = walk.unwrap().position.y.to_f64() - at.y.to_f64();
    assert!(rose < 0.01, "{}: the walk rose {rose} up the wall", S::NAME);
    let (low, mut high) = (me.position.y.to_f64(), f64::MIN);
    for frame in 0..150 {
        me.update(&level, wish, gravity, dt).unwrap();
        let at = me.position;
        assert!(
            me.is_grounded(),
            "{} frame {frame}: in the air at {at:?}",
            S::NAME
        );
        high = high.max(at.y.to_f64());
    }
    assert!(
        high - low < 0.01,
        "{}: rose {} above {low}",
        S::NAME,
        high - low
    );
}

/// A wall leaning back 5° to 10° (still a wall: too steep to stand on or step over), on ground
/// tilted 8° along it, level or rising 10° towards it: their crease climbs along the wall with
/// the tilt, into the wall's steep-slope plane by a few hundredths of its length; in `I16F16`
/// that was below the rounding of a product, and the ball crept up the crease by 4e-4 to 8e-4
/// a frame.
fn pushing_into_a_wall_leaning_back_on_tilted_ground_stays_put<S: Tolerance>() {
    let tilt = 8f64.to_radians().tan();
    for rise in [0.0f64, 10.0] {
        for lean in [5.0f64, 8.0, 10.0] {
            let level = crease::<S>(rise.to_radians().tan(), tilt, lean.to_radians().tan());
            walks_into_the_wall_and_stays_put(&level, &format!("rise {rise}°, lean {lean}°"));
        }
    }
}

/// Walking at 2 units/s along +x and 0.6 into a wall (at z = 2, facing -z) across a valley: down
/// a 25° slope, over 2 units of flat floor, up a 15° slope. Where the ground turns up, the
/// walk's next floor takes over from the one it kept to: every frame it makes at least 0.024 of
/// its 0.027 to 0.033 along the wall (keeping to the old floor, a frame there lost most of it).
fn walking_along_a_wall_across_a_valley_keeps_its_pace<S: Tolerance>() {
    let (down, up) = (25f64.to_radians().tan(), 15f64.to_radians().tan());
    let y = |x: f64| match x {
        _ if x < 0.0 => -x * down,
        _ if x > 2.0 => (x - 2.0) * up,
        _ => 0.0,
    };
    let mut level: Scene<S, 8> = Scene::new();
    for (a, b) in [(-8.0, 0.0), (0.0, 2.0), (2.0, 8.0)] {
        let p = |x: f64, z: f64| v::<S>([x, y(x), z]);
        level
            .push(Triangle::new(p(a, -6.0), p(a, 6.0), p(b, 6.0)))
            .unwrap();
        level
            .push(Triangle::new(p(a, -6.0), p(b, 6.0), p(b, -6.0)))
            .unwrap();
    }
    let w = |x: f64, h: f64| v::<S>([x, h, 2.0]);
    level
        .push(Triangle::new(w(-9.0, -2.0), w(-9.0, 9.0), w(9.0, 9.0)))
        .unwrap();
    level
        .push(Triangle::new(w(-9.0, -2.0), w(9.0, 9.0), w(9.0, -2.0)))
        .unwrap();
    let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / 60.0));
    let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>([2.0, 0.0, 0.6]));
    let mut me = Character::new(v::<S>([-3.0, y(-3.0) + 0.7, 1.0]), r).unwrap();
    for frame in 0..250 {
        let before = me.position.x.to_f64();
        me.update(&level, wish, gravity, dt).unwrap();
        let made = me.position.x.to_f64() - before;
        if frame > 20 {
            let at = me.position.to_array().map(|c| c.to_f64());
            assert!(
                made > 0.015,
                "{} frame {frame}: made {made} at {at:?}",
                S::NAME
            );
        }
    }
    assert!(
        me.position.x.to_f64() > 3.0,
        "{}: at {:?}",
        S::NAME,
        me.position
    );
}

/// A rock face leaning back 20° (too steep to stand on, low enough to step over) on ground
/// rising 10° towards it: the wall behind a steep slope stood level, so the walk into it kept
/// its rise and climbed the face by it, pressed back down the next frame (5.7 mm every frame,
/// every scalar). It now stands on the floor, and the ball stays put.
fn pushing_into_a_face_leaning_back_on_rising_ground_stays_put<S: Tolerance>() {
    let (rise, lean) = (10f64.to_radians().tan(), 20f64.to_radians().tan());
    walks_into_the_wall_and_stays_put(&crease::<S>(rise, 0.0, lean), "lean 20°, rise 10°");
}

/// The ground `y(x, z)` over cells from `(x0, z0)`, `cells` of `size` along each axis, two
/// triangles each, counter-clockwise from above (facing up).
fn ground<S: Scalar, const N: usize>(
    y: impl Fn(f64, f64) -> f64,
    (x0, z0): (f64, f64),
    cells: [(usize, f64); 2],
) -> Scene<S, N> {
    let p = |x: f64, z: f64| v::<S>([x, y(x, z), z]);
    let ([(nx, dx), (nz, dz)], mut level) = (cells, Scene::new());
    for i in 0..nx {
        for k in 0..nz {
            let (x, z) = (x0 + dx * i as f64, z0 + dz * k as f64);
            let (a, b, c, d) = (p(x, z), p(x, z + dz), p(x + dx, z + dz), p(x + dx, z));
            level.push(Triangle::new(a, b, c)).unwrap();
            level.push(Triangle::new(a, c, d)).unwrap();
        }
    }
    level
}

/// A ball of radius 0.5 walking at `wish` from `start` for `frames` frames at `hz`: its
/// vertical moves that reverse the one before by more than 1e-4 after the first second, and
/// where it ends.
fn reversals<S: Scalar, const N: usize>(
    level: &Scene<S, N>,
    start: [f64; 3],
    wish: [f64; 3],
    (hz, frames): (usize, usize),
) -> (usize, Vec3<S>) {
    let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / hz as f64));
    let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>(wish));
    let mut me = Character::new(v::<S>(start), r).unwrap();
    let (mut count, mut last) = (0, 0.0f64);
    for frame in 0..frames {
        let before = me.position.y.to_f64();
        me.update(level, wish, gravity, dt).unwrap();
        let dy = me.position.y.to_f64() - before;
        count += (frame >= hz && dy * last < 0.0 && dy.abs() > 1e-4) as usize;
        last = dy;
    }
    (count, me.position)
}

/// A V-shaped ditch of 50° sides (each too steep to stand on; their trough, rising 5° along
/// x, holds the ball as a floor), walked up at 2 units/s along x and 0.4 into one side, at 60
/// and 240 Hz: the sides' walls stood upright, leaning back across the trough's rise, and
/// held the ball back (it made 0.37 in 3 s, or slid back); then, in `I16F16` at 240 Hz, a
/// walk that touched one side only ended off the floor, and the snap's probe slid back down
/// the trough by more than the walk (1.0 in 3 s). Now it walks up the trough at the wished
/// pace: more than 5.5 of the 5.95 along x in 3 s, grounded every frame.
fn walks_up_a_steep_ditch_pushed_into_one_side<S: Tolerance>() {
    let (side, rise) = (50f64.to_radians().tan(), 5f64.to_radians().tan());
    // Unit cells, as a level's mesh has them (x in -8..8, z in -3..3).
    let y = |x: f64, z: f64| side * z.abs() + rise * x;
    let level: Scene<S, 192> = ground(y, (-8.0, -3.0), [(16, 1.0), (6, 1.0)]);
    for hz in [60, 240] {
        let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / hz as f64));
        let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>([2.0, 0.0, 0.4]));
        let y = 0.5 / 50f64.to_radians().cos() + 0.05 - 5.0 * rise;
        let mut me = Character::new(v::<S>([-5.0, y, 0.0]), r).unwrap();
        for _ in 0..hz {
            me.update(&level, wish, gravity, dt).unwrap();
        }
        let from = me.position.x.to_f64();
        for frame in 0..3 * hz {
            me.update(&level, wish, gravity, dt).unwrap();
            assert!(
                me.is_grounded(),
                "{} {hz} Hz frame {frame}: off the floor",
                S::NAME
            );
        }
        let made = me.position.x.to_f64() - from;
        let at = me.position;
        assert!(made > 5.5, "{} {hz} Hz: made {made} at {at:?}", S::NAME);
        let left = penetration(&level, me.position, r).unwrap();
        assert!(left.is_none(), "{} {hz} Hz: {left:?}", S::NAME);
    }
}

/// Walking diagonally into a pocket of steep bumps (slopes near 60°), where the ball is held
/// for good: from its second second on it rests. With walls square on the floor for faces but
/// upright for edges, an edge's upright wall left the walk its rise on one frame and the face
/// beside it its square wall on the next: the ball shook up and down by up to 4 mm every
/// other frame (218 reversals in these 240 frames, every scalar; 59 to 121 with upright walls
/// for all).
fn a_ball_wedged_in_a_pocket_of_steep_bumps_rests<S: Tolerance>() {
    let y = |x: f64, z: f64| {
        0.4 * ((1.7 * x + 0.3).sin() + (2.3 * z + x).cos() + 0.5 * (3.1 * (x + z)).sin())
    };
    let level: Scene<S, 128> = ground(y, (-6.5, -3.5), [(8, 0.5), (8, 0.5)]);
    let (wish, run) = ([1.414, 0.0, 1.414], (60, 300));
    let (count, at) = reversals(&level, [-4.775, 0.06, -1.741], wish, run);
    assert!(count <= 5, "{}: {count} reversals, at {at:?}", S::NAME);
    let left = penetration(&level, at, S::from_f64(0.5)).unwrap();
    assert!(left.is_none(), "{}: {left:?}", S::NAME);
}

/// The pocket above at 960 Hz, from the second second on: the ball stays down in it, its
/// height within 1 cm. Its walk, held by the faces it pressed into, had a velocity along the
/// floor's plane, which the face it met turned up their crease; where rounding lost the floor
/// (`I16F16`), the ball kept that velocity and hopped, 4.4 cm at a time (0.93 units/s up; its
/// height varied by 6.5 cm). A walker that leaves the floor now rises no faster than its walk
/// rose. (The floats rest, at one height; `I16F16` still loses the floor against one face at a
/// time and moves about the pocket's bottom by 5 mm.)
fn a_ball_in_a_pocket_of_steep_bumps_does_not_hop<S: Tolerance>() {
    let y = |x: f64, z: f64| {
        0.4 * ((1.7 * x + 0.3).sin() + (2.3 * z + x).cos() + 0.5 * (3.1 * (x + z)).sin())
    };
    let level: Scene<S, 128> = ground(y, (-6.5, -3.5), [(8, 0.5), (8, 0.5)]);
    let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / 960.0));
    let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>([1.414, 0.0, 1.414]));
    let mut me = Character::new(v::<S>([-4.775, 0.3, -1.741]), r).unwrap();
    let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
    for frame in 0..5 * 960 {
        me.update(&level, wish, gravity, dt).unwrap();
        if frame >= 2 * 960 {
            let y = me.position.y.to_f64();
            (low, high) = (low.min(y), high.max(y));
        }
    }
    assert!(high - low < 0.01, "{}: between {low} and {high}", S::NAME);
}

/// Walking along a ditch with a 20° side (the floor) and a 60° one at 120 Hz, 2 units/s along
/// it and 0.4 into the steep side: the ball keeps to the foot of the steep side, still. In
/// `I16F16` a slide up the steep face ran into its wall (square on the floor) by a few steps,
/// within a height's rounding, and was taken: the ball rose 0.4 mm a frame and was pressed back
/// the next (161 reversals in these 240 frames; `f64`, `f32` and `I32F32` had none).
fn walking_along_the_foot_of_a_steep_side_keeps_still<S: Tolerance>() {
    let (a, b) = (20f64.to_radians().tan(), 60f64.to_radians().tan());
    let y = |_: f64, z: f64| if z < 0.0 { -a * z } else { b * z };
    let level: Scene<S, 192> = ground(y, (-8.0, -1.5), [(16, 1.0), (6, 0.5)]);
    let (count, at) = reversals(&level, [-7.0, 0.62, 0.0], [2.0, 0.0, 0.4], (120, 360));
    assert!(count <= 2, "{}: {count} reversals, at {at:?}", S::NAME);
    assert!(at.x.to_f64() > -2.0, "{}: at {at:?}", S::NAME);
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn pushing_into_a_wall_on_rising_ground_stays_put() {
            super::pushing_into_a_wall_on_rising_ground_stays_put::<$t>();
        }
        #[test]
        fn walking_fast_up_a_steep_slope_into_a_wall_stays_put() {
            super::walking_fast_up_a_steep_slope_into_a_wall_stays_put::<$t>();
        }
        #[test]
        fn pushing_into_a_wall_leaning_back_on_tilted_ground_stays_put() {
            super::pushing_into_a_wall_leaning_back_on_tilted_ground_stays_put::<$t>();
        }
        #[test]
        fn pushing_into_a_face_leaning_back_on_rising_ground_stays_put() {
            super::pushing_into_a_face_leaning_back_on_rising_ground_stays_put::<$t>();
        }
        #[test]
        fn walks_up_a_steep_ditch_pushed_into_one_side() {
            super::walks_up_a_steep_ditch_pushed_into_one_side::<$t>();
        }
        #[test]
        fn a_ball_wedged_in_a_pocket_of_steep_bumps_rests() {
            super::a_ball_wedged_in_a_pocket_of_steep_bumps_rests::<$t>();
        }
        #[test]
        fn a_ball_in_a_pocket_of_steep_bumps_does_not_hop() {
            super::a_ball_in_a_pocket_of_steep_bumps_does_not_hop::<$t>();
        }
        #[test]
        fn walking_along_the_foot_of_a_steep_side_keeps_still() {
            super::walking_along_the_foot_of_a_steep_side_keeps_still::<$t>();
        }
        #[test]
        fn walking_along_a_wall_across_a_valley_keeps_its_pace() {
            super::walking_along_a_wall_across_a_valley_keeps_its_pace::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
