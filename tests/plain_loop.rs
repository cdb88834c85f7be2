//! The plain character loop at high frame rates: each frame gravity is added to the velocity,
//! the horizontal part is the player's wish, one move is made, the velocity is clipped, and the
//! ground probe is asked when the move touched no floor. Every property in every scalar.

mod common;

use ballcast::slide::Slider;
use common::{Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// The plain loop (gravity added to the velocity, one move, the velocity clipped) running at
/// (2, 0, 0.3) units/s across a level floor at high frame rates, asking the ground probe when
/// the move touched no floor: grounded on every frame. Gravity's `g dt²` is then smaller than a
/// skin, and a move ending exactly touching the floor (fixed point) is lifted a skin off it on
/// the next: the moves alone touched the floor on 120 of 480 frames in `I16F16` at 480 Hz, and
/// on 33 of the first 480 at 1920 Hz (`f32` and `f64`: 456). The probe must not find a floor in the air: after a
/// jump, the ball is airborne until it falls back.
fn running_on_a_floor_at_480_hz_stays_grounded<S: Tolerance>() {
    let level = common::slope::<S>([0.0, 1.0, 0.0]);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    for hz in [480.0, 1920.0] {
        let dt = S::from_f64(1.0 / hz);
        let (mut p, mut vel) = (v::<S>([0.0, 0.5, 0.0]), v::<S>([2.0, 0.0, 0.3]));
        let mut airborne = 0;
        // One second: a jump half-way.
        let (frames, jump) = (hz as usize, hz as usize / 2);
        for frame_no in 0..frames {
            vel += v::<S>([0.0, -9.81, 0.0]) * dt;
            let out = ball.slide(&level, p, vel * dt).unwrap();
            p = out.position;
            vel = ball.clip(&out, vel).unwrap();
            let probe = || ball.probe_floor(&level, p, up, walkable).unwrap();
            let grounded = match out.floor_normal(up, walkable).unwrap() {
                Some(n) => Some(n),
                None => probe().map(|f| f.normal).filter(|&n| vel.dot(n) <= S::ZERO),
            };
            if frame_no == jump {
                // A jump at 1 unit/s clears two skins within a frame or two and lands after
                // 0.204 s.
                vel.y = S::ONE;
            } else if frame_no > jump && frame_no < jump + (0.25 * hz) as usize {
                airborne += grounded.is_none() as usize;
                continue;
            }
            assert!(
                grounded == Some(up),
                "{}: {hz} Hz, frame {frame_no}: floor {grounded:?} at {:?}",
                S::NAME,
                common::back(p)
            );
        }
        let expected = (0.2 * hz) as usize - 2;
        assert!(
            airborne >= expected,
            "{}: {hz} Hz: airborne on {airborne} frames",
            S::NAME
        );
    }
}

/// Walking by `wish` (horizontal, units/s) for 2 s at `hz` on a slope whose normal leans
/// `degrees` from up towards +x, from 0.6 along its normal: after a quarter second the ball
/// covers at least a tenth of its walk on every frame. In `f32`, rounding brought the ball into contact with the slope along
/// its plane; the lift off it by that tiny approach was lost to the position's rounding, every
/// later move met the slope at once, and the ball froze for good (19 of 320 such runs at
/// 120 to 1920 Hz had still frames, 10 of them hundreds to thousands in a row).
fn walking_on_a_slope_at_high_frame_rates_never_freezes<S: Tolerance>() {
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    for (hz, degrees, wish) in [
        (480.0, 20.0f64, [2.0, 0.0, 0.0]),
        (960.0, 20.0, [1.0, 0.0, 1.0]),
        (960.0, 40.0, [0.0, 0.0, 2.0]),
        (1920.0, 10.0, [-1.0, 0.0, 1.0]),
        (1920.0, 10.0, [0.3, 0.0, 0.3]),
        (1920.0, 20.0, [0.5, 0.0, 0.0]),
        (1920.0, 40.0, [-2.0, 0.0, 0.0]),
    ] {
        let t = degrees.to_radians();
        let n = [t.sin(), t.cos(), 0.0];
        let level = common::slope::<S>(n);
        let dt = S::from_f64(1.0 / hz);
        let (mut p, mut vel) = (v::<S>(common::scale(n, 0.6)), v::<S>(wish));
        for frame_no in 0..(2.0 * hz) as usize {
            vel += v::<S>([0.0, -9.81, 0.0]) * dt;
            let out = ball.slide(&level, p, vel * dt).unwrap();
            let moved = common::norm(common::sub(common::back(out.position), common::back(p)));
            (p, vel) = (out.position, ball.clip(&out, vel).unwrap());
            if out.floor_normal(up, walkable).unwrap().is_none()
                && let Some(f) = ball.probe_floor(&level, p, up, walkable).unwrap()
            {
                p = f.position;
            }
            (vel.x, vel.z) = (S::from_f64(wish[0]), S::from_f64(wish[2]));
            assert!(
                frame_no < (hz / 4.0) as usize || moved > 0.1 * common::norm(wish) / hz,
                "{}: {hz} Hz, {degrees}°, wish {wish:?}: moved {moved} on frame {frame_no} at {:?}",
                S::NAME,
                common::back(p)
            );
        }
    }
}

/// A ball resting on a tilted plane far from the origin, pressed onto it by gravity along its
/// normal at 480 Hz (the plain loop: gravity added, one move, the velocity clipped). In
/// `I16F16` each frame's press is a few steps, rounded to a vector a step or so off the normal,
/// and it meets the plane partway: carried to that contact (the travel a step of rounding
/// sideways) and lifted, it crept down the plane a step every few frames, 3 mm/s (n (0.3, 1,
/// -0.2), r 0.05, centre (300, 7, -201): 0.157 in 30 000 frames). It stays put.
fn pressed_onto_a_far_tilted_plane_at_480_hz_stays_put<S: Tolerance>() {
    let unit = |p: common::P| common::scale(p, 1.0 / common::norm(p));
    let n = unit([0.3, 1.0, -0.2]);
    let a = unit(common::cross(n, [0.0, 0.0, 1.0]));
    let b = common::cross(n, a);
    let centre = [300.3, 7.1, -200.7];
    let corner = common::add(centre, common::scale(common::add(a, b), -30.0));
    let mut level: ballcast::Scene<S, 2> = ballcast::Scene::new();
    for t in common::quad(corner, common::scale(a, 60.0), common::scale(b, 60.0)) {
        level
            .push(ballcast::Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    let r = 0.05;
    let ball = Slider::new(S::from_f64(r)).unwrap();
    let (dt, g) = (S::from_f64(1.0 / 480.0), v::<S>(common::scale(n, -9.81)));
    let mut p = v::<S>(common::add(centre, common::scale(n, r + 0.01)));
    let mut vel = v::<S>([0.0; 3]);
    let mut settled = common::back(p);
    for frame_no in 0..3_500 {
        vel += g * dt;
        let out = ball.slide(&level, p, vel * dt).unwrap();
        p = out.position;
        vel = ball.clip(&out, vel).unwrap();
        if frame_no == 500 {
            settled = common::back(p);
        }
    }
    let d = common::sub(common::back(p), settled);
    let along = common::norm(common::sub(d, common::scale(n, common::dot(d, n))));
    assert!(
        along <= 2.0 * S::spacing(400.0),
        "{}: crept {along:e} along the plane in 3 000 frames",
        S::NAME
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn running_on_a_floor_at_480_hz_stays_grounded() {
            super::running_on_a_floor_at_480_hz_stays_grounded::<$t>()
        }
        #[test]
        fn pressed_onto_a_far_tilted_plane_at_480_hz_stays_put() {
            super::pressed_onto_a_far_tilted_plane_at_480_hz_stays_put::<$t>()
        }
        #[test]
        fn walking_on_a_slope_at_high_frame_rates_never_freezes() {
            super::walking_on_a_slope_at_high_frame_rates_never_freezes::<$t>()
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
