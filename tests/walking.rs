//! The README's walking recipe: while grounded, press into the floor along its normal by g dt²,
//! then walk along the floor's plane, as a second, separate move; in the air, fall; where no
//! move touched a floor, ask the ground probe. Standing still on a slope, walking slowly from
//! flat ground onto a ramp, and running across a floor at high frame rates. Every property in
//! every scalar; expected values worked by hand.

mod common;

use ballcast::{Geometry, Scalar, Scene, Triangle, Vec3, slide::Slider};
use common::{Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// A character's state between frames: position, velocity and the floor's normal, if grounded.
type State<S> = (Vec3<S>, Vec3<S>, Option<Vec3<S>>);

/// One frame of the recipe at 60 Hz with r = 0.5, g = 9.81 and slopes up to 45° walkable,
/// the ball held back by steeper slopes if `held`.
fn frame<S: Scalar, G: Geometry<S>>(
    level: &G,
    state: State<S>,
    wish: Vec3<S>,
    held: bool,
) -> State<S> {
    frame_at(level, state, wish, held, 60.0)
}

/// [`frame`] at `hz` frames a second.
fn frame_at<S: Scalar, G: Geometry<S>>(
    level: &G,
    (p, vel, floor): State<S>,
    wish: Vec3<S>,
    held: bool,
    hz: f64,
) -> State<S> {
    let (dt, g) = (S::from_f64(1.0 / hz), S::from_f64(9.81));
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let ball = if held {
        ball.with_max_slope(up, walkable).unwrap()
    } else {
        ball
    };
    let walked = floor.is_some();
    let (p, vel, floor) = match floor {
        Some(n) => {
            // Pressed into the floor first, along its own normal (so it does not slide), then
            // the walk along it. In one move, a slow walk into a ramp points into both the
            // floor and the ramp, and sliding rightly goes nowhere.
            let press = Vec3::ZERO - n * g.mul(dt).mul(dt);
            let pressed = ball.slide(level, p, press).unwrap();
            let vel = wish - n * wish.dot(n);
            let walk = ball.slide(level, pressed.position, vel * dt).unwrap();
            let floor = walk.floor_normal(up, walkable).unwrap();
            let floor = floor.or(pressed.floor_normal(up, walkable).unwrap());
            (walk.position, ball.clip(&walk, vel).unwrap(), floor)
        }
        None => {
            let vel = vel + v::<S>([0.0, -9.81, 0.0]) * dt;
            let out = ball.slide(level, p, vel * dt).unwrap();
            let floor = out.floor_normal(up, walkable).unwrap();
            (out.position, ball.clip(&out, vel).unwrap(), floor)
        }
    };
    // The ground probe, when neither move touched a floor: grounded and snapped down onto the
    // floor it finds, unless the ball was in the air and moves away from it (a jump).
    match floor {
        None => match ball.probe_floor(level, p, up, walkable).unwrap() {
            Some(f) if walked || vel.dot(f.normal) <= S::ZERO => (f.position, vel, Some(f.normal)),
            _ => (p, vel, None),
        },
        _ => (p, vel, floor),
    }
}

/// Standing on a 30° slope for 10 s. Gravity added to the velocity slides a frictionless ball
/// down any slope; pressed in along the floor's normal instead, the ball is grounded on every
/// frame after it lands and does not move at all.
fn standing_still_on_a_slope_pressed_into_it<S: Tolerance>() {
    let t = 30f64.to_radians();
    let n = [t.sin(), t.cos(), 0.0];
    let scene = common::slope::<S>(n);
    let mut state = (v::<S>(common::scale(n, 0.6)), Vec3::ZERO, None);
    let mut settled = None;
    for frame_no in 0..600 {
        state = frame(&scene, state, Vec3::ZERO, false);
        if frame_no >= 60 {
            let p = state.0;
            assert!(
                state.2.is_some(),
                "{}: frame {frame_no} in the air at {p:?}",
                S::NAME
            );
            assert_eq!(
                *settled.get_or_insert(p),
                p,
                "{}: frame {frame_no} moved",
                S::NAME
            );
        }
    }
}

/// Standing still on slopes of 10° to 44° at 240, 480 and 1920 frames a second, where the press
/// (`g dt²`) falls short of the floor a skin below and the ground probe finds it: after half a
/// second the ball stays grounded and within a skin of where it was then, for 1.5 s. The
/// probe's slide once went on down the slope it found by what was left of its two skins: at
/// 1920 Hz, where the press rounds to nothing, an `I16F16` ball slid 0.7 down the 10° slope in
/// those 1.5 s and 2.9 down the 44° one.
fn standing_still_on_a_slope_at_high_frame_rates<S: Tolerance>() {
    let skin = Slider::new(S::from_f64(0.5)).unwrap().skin(S::ONE).to_f64();
    for hz in [240.0, 480.0, 1920.0] {
        for degrees in [10.0f64, 30.0, 44.0] {
            let t = degrees.to_radians();
            let n = [t.sin(), t.cos(), 0.0];
            let scene = common::slope::<S>(n);
            let mut state = (v::<S>(common::scale(n, 0.6)), Vec3::ZERO, None);
            let settle = (hz / 2.0) as usize;
            let mut settled = None;
            for frame_no in 0..4 * settle {
                state = frame_at(&scene, state, Vec3::ZERO, true, hz);
                if frame_no >= settle {
                    let p = common::back(state.0);
                    let what = format!("{}: {hz} Hz, {degrees}°, frame {frame_no}", S::NAME);
                    assert!(state.2.is_some(), "{what}: in the air at {p:?}");
                    let moved = common::norm(common::sub(p, *settled.get_or_insert(p)));
                    assert!(moved <= skin, "{what}: moved {moved} from {settled:?}");
                }
            }
        }
    }
}

/// The ground probe asked again and again from where it snapped the ball, on slopes of 10° to
/// 44°, the ball starting 1.2 skins off the slope: after the first snap it stays within
/// a skin of where it was. The probe's slide once went on down the slope it found by what was
/// left of its two skins: in 2 880 calls (1.5 s at 1920 Hz) the ball slid 0.49 down the 10°
/// slope and 1.95 down the 44° one (`I16F16`: 0.71 and 2.92).
fn the_ground_probe_stops_on_the_slope_it_finds<S: Tolerance>() {
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let skin = ball.skin(S::ONE).to_f64();
    for degrees in [10.0f64, 30.0, 44.0] {
        let t = degrees.to_radians();
        let n = [t.sin(), t.cos(), 0.0];
        let scene = common::slope::<S>(n);
        let mut p = v::<S>(common::scale(n, 0.5 + 1.2 * skin));
        let mut first = None;
        for call in 0..2880 {
            let found = ball.probe_floor(&scene, p, up, walkable).unwrap();
            let what = format!("{}: {degrees}°, call {call}", S::NAME);
            p = found
                .unwrap_or_else(|| panic!("{what}: no floor at {p:?}"))
                .position;
            let moved = common::norm(common::sub(
                common::back(p),
                *first.get_or_insert(common::back(p)),
            ));
            assert!(moved <= skin, "{what}: moved {moved} from {first:?}");
        }
    }
}

/// A ball left overlapping a 25° slope by rounding (by 7e-7, as a press that reached the slope
/// just at its end left an `f32` ball) walks along it: it covers at least half its walk. The
/// walk met the slope half way; the lift off it by the walk's tiny approach was lost to the
/// position's rounding in all but a coordinate near zero (z, by 3e-17), and the ball stayed
/// where it was, call after call.
fn walking_along_a_slope_overlapped_by_rounding<S: Tolerance>() {
    let t = 25f64.to_radians();
    let scene = common::slope::<S>([t.sin(), t.cos(), 0.0]);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let ball = ball.with_max_slope(up, walkable).unwrap();
    let p = [0.27528912, 0.42331874, -1.1571297e-10];
    let walk = [0.006844948, -0.0031918527, -5.2479212e-11];
    let out = ball.slide(&scene, v::<S>(p), v::<S>(walk)).unwrap();
    let moved = common::norm(common::sub(
        common::back(out.position),
        common::back(v::<S>(p)),
    ));
    assert!(
        moved > 0.5 * common::norm(walk),
        "{}: moved {moved} of {}",
        S::NAME,
        common::norm(walk)
    );
}

/// Flat ground (y = 0, x < 0) meeting a 44° ramp at x = 0, walked into at 0.05 units/s from
/// x = -1. With the press in the same move as the walk, the ball stopped for good at the foot
/// (x = -0.2017). Here it reaches the ramp after about 16 s and then climbs it: by 40 s its
/// centre has risen by more than 0.2 (at 0.05 cos 44° along the ramp, about 0.4).
fn walking_slowly_onto_a_ramp<S: Tolerance>() {
    // Held back by slopes steeper than 45° or not: the 44° ramp is walkable either way.
    for held in [false, true] {
        let scene = ramp::<S>(44.0);
        let mut state = (v::<S>([-1.0, 0.5005, 0.0]), Vec3::ZERO, None);
        let wish = v::<S>([0.05, 0.0, 0.0]);
        for _ in 0..2400 {
            state = frame(&scene, state, wish, held);
        }
        let [x, y, _] = common::back(state.0);
        assert!(
            y > 0.7 && x > 0.0,
            "{}: held {held}: stuck at ({x}, {y})",
            S::NAME
        );
    }
}

/// Flat ground (y = 0, x < 0) meeting a ramp rising at `deg` degrees at x = 0, 8 wide in z.
fn ramp<S: Scalar>(deg: f64) -> Scene<S, 4> {
    let top = [8.0, 8.0 * deg.to_radians().tan()];
    let mut scene: Scene<S, 4> = Scene::new();
    let quad = |s: &mut Scene<S, 4>, a: [f64; 2], b: [f64; 2]| {
        let c = [
            [a[0], a[1], -4.0],
            [a[0], a[1], 4.0],
            [b[0], b[1], 4.0],
            [b[0], b[1], -4.0],
        ];
        s.push(Triangle::new(v(c[0]), v(c[1]), v(c[2]))).unwrap();
        s.push(Triangle::new(v(c[0]), v(c[2]), v(c[3]))).unwrap();
    };
    quad(&mut scene, [-8.0, 0.0], [0.0, 0.0]);
    quad(&mut scene, [0.0, 0.0], top);
    scene
}

/// Walking into a 60° ramp from flat ground at 2 units/s for 3 s, held back by slopes steeper
/// than 45°: it stops at the ramp's foot, grounded on every frame and never lifted off the
/// ground by more than a skin. Without the limit, each walk into the ramp carried it up the
/// ramp: in `f32` it bounced at the foot, up to 0.07 off the ground, losing the floor.
fn walking_into_a_steep_ramp_stops_at_its_foot<S: Tolerance>() {
    let scene = ramp::<S>(60.0);
    let mut state = (v::<S>([-1.0, 0.5005, 0.0]), Vec3::ZERO, None);
    for frame_no in 0..180 {
        state = frame(&scene, state, v::<S>([2.0, 0.0, 0.0]), true);
        let [x, y, _] = common::back(state.0);
        assert!(
            frame_no < 10 || (state.2.is_some() && y < 0.5 + 2e-3 && x < 0.0),
            "{}: frame {frame_no}: floor {:?} at ({x}, {y})",
            S::NAME,
            state.2
        );
    }
}

/// Resting in, and walking along, a level valley whose slopes (60° and 80°) are each too
/// steep to stand on: the valley holds the ball, so after landing it is grounded on every
/// frame, in every scalar. Pressed along one slope's normal, the ball touched only that slope
/// and lost the floor on every other frame; the valley's own floor normal presses it into both.
/// (Walking across the valley is the next test's.)
fn grounded_in_a_steep_valley<S: Tolerance>() {
    for (steep, wish) in [
        (60.0, [0.0; 3]),
        (60.0, [0.0, 0.0, 2.0]),
        (80.0, [0.0, 0.0, 2.0]),
    ] {
        let level = common::valley::<S>(steep, 0.0);
        let mut state = (v::<S>([0.3, 3.0, 0.0]), Vec3::ZERO, None);
        for frame_no in 0..480 {
            state = frame(&level, state, v::<S>(wish), false);
            assert!(
                frame_no < 120 || state.2.is_some(),
                "{}: {steep}° valley, walking {wish:?}, frame {frame_no} in the air at {:?}",
                S::NAME,
                state.0
            );
        }
    }
}

/// Walking across a level valley of 50°–80° slopes into one of them, at 2 units/s for 6 s
/// after landing, held back by slopes steeper than 45°: grounded on every frame, never higher
/// than where it landed (a skin above it at most). Without the limit the walk carried the ball
/// up the slope, 0.01 to 0.11 above its rest, and it was grounded on only 30 to 103 of the 360
/// frames (the recipe's press does not bring it back down onto the other slope).
fn walking_across_a_steep_valley_held_by_the_slope_limit<S: Tolerance>() {
    for steep in [50.0, 60.0, 70.0, 80.0] {
        let level = common::valley::<S>(steep, 0.0);
        let mut state = (v::<S>([0.3, 3.0, 0.0]), Vec3::ZERO, None);
        for _ in 0..120 {
            state = frame(&level, state, Vec3::ZERO, true);
        }
        let rest = state.0.y.to_f64();
        for frame_no in 120..480 {
            state = frame(&level, state, v::<S>([2.0, 0.0, 0.0]), true);
            let y = state.0.y.to_f64();
            assert!(
                state.2.is_some() && y - rest < 2e-3,
                "{}: {steep}° valley, frame {frame_no}: floor {:?} at {:?}, rest y {rest}",
                S::NAME,
                state.2,
                common::back(state.0)
            );
        }
    }
}

/// The recipe at 1920 Hz, where gravity's press `g dt²` (2.7e-6) rounds to nothing in
/// `I16F16`: walking down and across a 10° slope, the ball is grounded on every frame after it
/// lands. Without the floor snap (the probe's position), the ball drifted up to two skins off
/// the slope and the probe found it on about two frames in three.
fn walking_on_a_slope_at_1920_hz_stays_grounded<S: Tolerance>() {
    let t = 10f64.to_radians();
    let n = [t.sin(), t.cos(), 0.0];
    let scene = common::slope::<S>(n);
    let mut state = (
        v::<S>(common::scale(n, 0.5005)),
        Vec3::ZERO,
        Some(v::<S>(n)),
    );
    for frame_no in 0..1920 {
        state = frame_at(&scene, state, v::<S>([1.8, 0.0, 0.4]), true, 1920.0);
        assert!(
            state.2.is_some(),
            "{}: frame {frame_no} in the air at {:?}",
            S::NAME,
            common::back(state.0)
        );
    }
}

/// A jump at 1 unit/s from a floor at 1920 Hz in the recipe rises to v² / 2g = 0.051. The
/// ground probe, asked on its first frames, finds the floor within two skins: taken as ground,
/// the recipe's walk replaced the jump's velocity, and the ball rose 0.001.
fn a_jump_at_1920_hz_leaves_the_floor<S: Tolerance>() {
    let scene = common::slope::<S>([0.0, 1.0, 0.0]);
    let up = v::<S>([0.0, 1.0, 0.0]);
    let mut state = (v::<S>([0.0, 0.5, 0.0]), Vec3::ZERO, Some(up));
    for _ in 0..100 {
        state = frame_at(&scene, state, Vec3::ZERO, false, 1920.0);
    }
    let rest = state.0.y.to_f64();
    state = (state.0, up, None);
    let mut peak = rest;
    for _ in 0..400 {
        state = frame_at(&scene, state, Vec3::ZERO, false, 1920.0);
        peak = peak.max(state.0.y.to_f64());
    }
    let rise = peak - rest;
    assert!(
        (rise - 0.051).abs() < 0.005 && state.2.is_some(),
        "{}: rose {rise}, grounded at the end: {}",
        S::NAME,
        state.2.is_some()
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn standing_still_on_a_slope_pressed_into_it() {
            super::standing_still_on_a_slope_pressed_into_it::<$t>()
        }
        #[test]
        fn standing_still_on_a_slope_at_high_frame_rates() {
            super::standing_still_on_a_slope_at_high_frame_rates::<$t>()
        }
        #[test]
        fn the_ground_probe_stops_on_the_slope_it_finds() {
            super::the_ground_probe_stops_on_the_slope_it_finds::<$t>()
        }
        #[test]
        fn walking_along_a_slope_overlapped_by_rounding() {
            super::walking_along_a_slope_overlapped_by_rounding::<$t>()
        }
        #[test]
        fn walking_slowly_onto_a_ramp() { super::walking_slowly_onto_a_ramp::<$t>() }
        #[test]
        fn walking_into_a_steep_ramp_stops_at_its_foot() {
            super::walking_into_a_steep_ramp_stops_at_its_foot::<$t>()
        }
        #[test]
        fn grounded_in_a_steep_valley() { super::grounded_in_a_steep_valley::<$t>() }
        #[test]
        fn walking_on_a_slope_at_1920_hz_stays_grounded() {
            super::walking_on_a_slope_at_1920_hz_stays_grounded::<$t>()
        }
        #[test]
        fn a_jump_at_1920_hz_leaves_the_floor() {
            super::a_jump_at_1920_hz_leaves_the_floor::<$t>()
        }
        #[test]
        fn walking_across_a_steep_valley_held_by_the_slope_limit() {
            super::walking_across_a_steep_valley_held_by_the_slope_limit::<$t>()
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
