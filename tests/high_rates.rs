//! `slide::Character` walking at 120 to 960 Hz, where the press into the floor, `|g| dt²`, is
//! shorter than a skin in `I16F16`: walking across a floor keeps one height, and walking into a
//! wall on a tilted floor, or into the wedge of a steep slope and a wall, stays put. (Rounded to a step straight down, the
//! press once lowered the ball a step a frame until it touched the floor and was lifted a skin
//! off it: a sawtooth of one skin, which along a tilted floor's normal carried the ball down
//! the floor, 0.2 along the wall in 10^5 frames.) Every property in every scalar.

mod common;

use ballcast::{Scene, Triangle, slide::Character};
use common::{Tolerance, back, plane, quad, v};
use fixed::types::{I16F16, I32F32};

/// The ball's centre over `frames` frames at `hz` after one second walking with `wish`: the
/// lowest and highest of each coordinate.
fn span<S: Tolerance, const N: usize>(
    level: &Scene<S, N>,
    start: [f64; 3],
    wish: [f64; 3],
    hz: f64,
    frames: usize,
) -> ([f64; 3], [f64; 3]) {
    let (dt, gravity) = (S::from_f64(1.0 / hz), v::<S>([0.0, -9.81, 0.0]));
    let mut me = Character::new(v(start), S::from_f64(0.5)).unwrap();
    let (mut lo, mut hi) = ([f64::MAX; 3], [f64::MIN; 3]);
    for frame in 0..hz as usize + frames {
        me.update(level, v(wish), gravity, dt).unwrap();
        if frame >= hz as usize {
            assert!(me.is_grounded(), "{}: in the air at frame {frame}", S::NAME);
            let p = back(me.position);
            for k in 0..3 {
                (lo[k], hi[k]) = (lo[k].min(p[k]), hi[k].max(p[k]));
            }
        }
    }
    (lo, hi)
}

/// Walking at 2 units/s along a level floor for a second: its height never changes by more
/// than a height's rounding (a sawtooth of one skin was 7.3e-4 in `I16F16`).
fn walking_across_a_floor_keeps_its_height<S: Tolerance>() {
    let mut level: Scene<S, 2> = Scene::new();
    for t in quad([-40.0, 0.0, -40.0], [0.0, 0.0, 80.0], [80.0, 0.0, 0.0]) {
        level
            .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    for hz in [480.0, 960.0] {
        let (lo, hi) = span(&level, [0.0, 0.6, 0.0], [2.0, 0.0, 0.0], hz, hz as usize);
        let bob = hi[1] - lo[1];
        let allowed = S::PRECISION.height_error(40.0);
        assert!(bob <= allowed, "{} at {hz} Hz: bobbed {bob:e}", S::NAME);
    }
}

/// Walking into an upright wall on a floor tilted 15° towards it and 8° along it, for 10^4
/// frames at 960 Hz: it moves along neither the wall nor the floor (it crept 0.02 down the
/// floor along the wall in `I16F16`).
fn walking_into_a_wall_on_a_tilted_floor_stays_put<S: Tolerance>() {
    let (a, b) = (15f64.to_radians(), 8f64.to_radians());
    let n = [-a.sin() * b.cos(), a.cos() * b.cos(), b.sin()];
    let mut level: Scene<S, 4> = Scene::new();
    let wall = quad([2.0, -8.0, -8.0], [0.0, 0.0, 16.0], [0.0, 16.0, 0.0]);
    for t in plane(n).into_iter().chain(wall) {
        level
            .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    let (lo, hi) = span(&level, [1.3, 1.0, 0.0], [2.0, 0.0, 0.0], 960.0, 10_000);
    let moved = (0..3).fold(0.0f64, |m, k| m.max(hi[k] - lo[k]));
    let allowed = S::PRECISION.height_error(8.0);
    assert!(moved <= allowed, "{}: moved {moved:e}", S::NAME);
}

/// Walking up slopes of 5° and 15° at 2 units/s for 3 s, at 60 and 240 Hz, on a 60-unit plane
/// moved far from the origin (10^4 units, as far as fits): no frame moves the ball down by more
/// than a quarter of a height's rounding there, a step of its coordinates. (Left in place, not
/// pressed, an `f32` ball was lifted off the slope by its walk's rounding until the snap
/// dropped it: 4.2e-3 on the 5° slope at 240 Hz.)
fn walking_up_a_slope_far_out_holds_to_it<S: Tolerance>() {
    let far = (S::LIMIT.to_f64() / 2.0).min(1e4);
    let at = [far, 0.3 * far, far];
    let allowed = S::PRECISION.height_error(far) / 4.0;
    for (degrees, hz) in [(5.0f64, 240.0), (15.0, 60.0), (15.0, 240.0)] {
        let t = degrees.to_radians();
        let n = [-t.sin(), t.cos(), 0.0];
        let mut level: Scene<S, 2> = Scene::new();
        for tri in plane(n) {
            let [a, b, c] = tri.map(|p| common::add(common::scale(p, 30.0 / 8.0), at));
            level.push(Triangle::new(v(a), v(b), v(c))).unwrap();
        }
        let (dt, gravity) = (S::from_f64(1.0 / hz), v::<S>([0.0, -9.81, 0.0]));
        let start = common::add(at, [0.0, 0.5 / t.cos() + 0.01, 0.0]);
        let mut me = Character::new(v(start), S::from_f64(0.5)).unwrap();
        for frame in 0..(3.5 * hz) as usize {
            let y = back(me.position)[1];
            me.update(&level, v([2.0, 0.0, 0.0]), gravity, dt).unwrap();
            let dy = back(me.position)[1] - y;
            if frame as f64 >= hz / 2.0 {
                let what = format!("{} on {degrees}° at {hz} Hz, frame {frame}", S::NAME);
                assert!(dy >= -allowed, "{what}: down {dy:e}");
            }
        }
    }
}

/// Pushed into the wedge of a 60° slope (too steep to stand on) and an upright wall, held there
/// by the two, at 120 to 250 Hz for 2 000 frames: after a second it does not move at all. At
/// 200 to 250 Hz, where the press is a little longer than a height's rounding in `I16F16`, the
/// ball went up and down by 3e-4 (a cycle of 6 frames at 240 Hz), 2.1 units of path in 10^4
/// frames.
fn pushed_into_a_steep_wedge_stays_put<S: Tolerance>() {
    let tan = 60f64.to_radians().tan();
    // Fronts towards the wedge: the slope's up and along +x, the wall's along −x.
    let slope = quad([3.0, 0.0, -10.0], [-8.0, 8.0 * tan, 0.0], [0.0, 0.0, 20.0]);
    let wall = quad([3.0, -1.0, 10.0], [0.0, 7.0, 0.0], [0.0, 0.0, -20.0]);
    let mut level: Scene<S, 4> = Scene::new();
    for t in slope.into_iter().chain(wall) {
        level
            .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    for hz in [120.0, 200.0, 240.0, 250.0] {
        let (lo, hi) = span(&level, [2.0, 2.0, 0.0], [2.0, 0.0, 0.0], hz, 2000);
        let moved = (0..3).fold(0.0f64, |m, k| m.max(hi[k] - lo[k]));
        assert_eq!(moved, 0.0, "{} at {hz} Hz: moved {moved:e}", S::NAME);
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn walking_across_a_floor() {
            walking_across_a_floor_keeps_its_height::<$t>();
        }
        #[test]
        fn walking_up_a_slope_far_out() {
            walking_up_a_slope_far_out_holds_to_it::<$t>();
        }
        #[test]
        fn walking_into_a_wall_on_a_tilted_floor() {
            walking_into_a_wall_on_a_tilted_floor_stays_put::<$t>();
        }
        #[test]
        fn pushed_into_a_steep_wedge() {
            pushed_into_a_steep_wedge_stays_put::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
