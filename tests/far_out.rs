//! A character walking into the corners of steep ditches and along walls far from the origin,
//! where a float's coordinates round to steps of 6e-5 (1 000 units) to 4.9e-4 (8 000), about a
//! frame's walk at high rates: the ball must not come to rest touching two planes within
//! rounding (met at once by every later move: stuck for good). Each scene is built around the
//! origin, turned about y and moved to about `(out, 7, -out)`. Every scalar whose range holds
//! the scene.

mod common;

use ballcast::{Scalar, Scene, Triangle, Vec3, slide::Character};
use common::{P, Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// `tan` of an angle in degrees.
fn tan(degrees: f64) -> f64 {
    degrees.to_radians().tan()
}

/// Turns a point by `degrees` about y.
fn turn(degrees: f64) -> impl Fn(P) -> P {
    let (sin, cos) = degrees.to_radians().sin_cos();
    move |[x, y, z]| [cos * x - sin * z, y, sin * x + cos * z]
}

/// Turns a point by `degrees` about y and moves it to about `(out, 7, -out)`.
fn far(out: f64, degrees: f64) -> impl Fn(P) -> P {
    let turned = turn(degrees);
    move |p| {
        let [x, y, z] = turned(p);
        [out + 0.3 + x, 7.1 + y, -out - 0.7 + z]
    }
}

/// The surface `y = f(x, z)` in `n × m` square cells of side `cell` from `(x0, z0)`, two
/// triangles each, facing up, placed by `place`.
fn tiled<S: Scalar, const N: usize>(
    f: impl Fn(f64, f64) -> f64,
    (x0, z0): (f64, f64),
    (n, m, cell): (usize, usize, f64),
    place: &impl Fn(P) -> P,
) -> Scene<S, N> {
    let p = |x: f64, z: f64| v::<S>(place([x, f(x, z), z]));
    let mut level = Scene::new();
    for i in 0..n {
        for k in 0..m {
            let (x, z) = (x0 + cell * i as f64, z0 + cell * k as f64);
            let (a, b) = (p(x, z), p(x, z + cell));
            let (c, d) = (p(x + cell, z + cell), p(x + cell, z));
            level.push(Triangle::new(a, b, c)).unwrap();
            level.push(Triangle::new(a, c, d)).unwrap();
        }
    }
    level
}

/// How far a ball of radius `r` started at `start`, wishing `wish` at `hz`, walks along the
/// level unit direction `heading` in three seconds after two, and where it ends.
fn progress<S: Scalar, const N: usize>(
    r: f64,
    level: &Scene<S, N>,
    (start, wish, heading): (P, P, P),
    hz: usize,
) -> (f64, Vec3<S>) {
    let (r, dt) = (S::from_f64(r), S::from_f64(1.0 / hz as f64));
    let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>(wish));
    let mut me = Character::new(v::<S>(start), r).unwrap();
    let along = |me: &Character<S>| {
        let q = me.position.to_array().map(|c| c.to_f64());
        q[0] * heading[0] + q[2] * heading[2]
    };
    for _ in 0..2 * hz {
        me.update(level, wish, gravity, dt).unwrap();
    }
    let from = along(&me);
    for _ in 0..3 * hz {
        me.update(level, wish, gravity, dt).unwrap();
    }
    (along(&me) - from, me.position)
}

/// A V-shaped ditch of 70° sides rising 20° along its trough, out 1 000 and turned 23°, walked
/// up at 2 units/s along the trough and 0.3 into one side at 120 to 960 Hz. In `f32` a
/// coordinate rounds to 6e-5 there and a 960 Hz walk is a skin or two: the ball came to rest
/// touching the far side within rounding, the lift off it ran into the near side at once (the
/// trough is narrow), and the half way it then took rounded to no move at all, so the far side
/// met it again at once on every sweep: it stuck (0.0 to 1.4 of `f64`'s 5.3 in 3 s). A lift
/// met within a position's rounding now slides along what met it.
fn walks_up_a_steep_ditch_far_out<S: Tolerance>() {
    let (side, rise) = (tan(70.0), tan(20.0));
    let place = far(1000.0, 23.0);
    let f = |x: f64, z: f64| side * z.abs() + rise * x;
    let level: Scene<S, 192> = tiled(f, (-8.0, -3.0), (16, 6, 1.0), &place);
    let start = place([
        -5.0,
        0.5 / 70f64.to_radians().cos() + 0.05 - 5.0 * rise,
        0.0,
    ]);
    let (wish, heading) = (turn(23.0)([2.0, 0.0, 0.3]), turn(23.0)([1.0, 0.0, 0.0]));
    for hz in [120, 240, 960] {
        let (made, at) = progress(0.5, &level, (start, wish, heading), hz);
        assert!(made > 5.0, "{} {hz} Hz: made {made} at {at:?}", S::NAME);
    }
}

/// A ditch whose sides (a floor of `low`° and a steep side of `high`°) meet along x, tiled in
/// cells of 0.5, placed by `place`, walked along at 2 units/s and 0.4 into the steep side at
/// 240 to 960 Hz: at least 5.8 made in 3 s (`f64` makes 6.0).
fn walks_along_the_foot_of<S: Tolerance>((low, high): (f64, f64), out: f64, degrees: f64) {
    let place = far(out, degrees);
    let f = |_: f64, z: f64| {
        if z < 0.0 {
            -tan(low) * z
        } else {
            tan(high) * z
        }
    };
    let level: Scene<S, 384> = tiled(f, (-8.0, -1.5), (32, 6, 0.5), &place);
    let (wish, heading) = (
        turn(degrees)([2.0, 0.0, 0.4]),
        turn(degrees)([1.0, 0.0, 0.0]),
    );
    for hz in [240, 480, 960] {
        let start = place([-5.0, 0.7, 0.0]);
        let (made, at) = progress(0.5, &level, (start, wish, heading), hz);
        let what = format!("{} {low}°/{high}° at {out}, {hz} Hz", S::NAME);
        assert!(made > 5.8, "{what}: made {made} at {at:?}");
    }
}

/// Sides of 35° (the floor) and 75°, out 1 000 and turned 23°. In `f32` at 480 Hz the ball
/// came to rest touching the steep side within rounding: the lift off it ran into the floor
/// (the corner is 70°), slid along the floor, and that slide, a few steps of the coordinates'
/// rounding long, rounded into the floor and met it again, leaving the ball where it was, so
/// the steep side met every later walk at once: it stuck for good. A lift met again by the
/// plane it slid along now leaves both planes.
fn walks_along_the_foot_of_a_steep_side_far_out<S: Tolerance>() {
    walks_along_the_foot_of::<S>((35.0, 75.0), 1000.0, 23.0);
}

/// Sides of 30° and 60° (a right-angled corner), out 2 143 (3 000 from the origin) and turned
/// 11°: in `f32` the ball stood within a skin of the steep side, which it cannot back off from
/// along its path, and each frame's end, rounded to coordinates 2.4e-4 apart, brought it 8e-5
/// closer, until it touched both sides within rounding and stuck for good (made 0 at 240 Hz).
/// Its lift off the side, running along the floor, met the floor at once and was given up; it
/// now leaves both (and a float ball met within a position's rounding by a plane it started a
/// skin from is lifted back to a skin off it).
fn walks_along_the_foot_of_a_right_angled_ditch_far_out<S: Tolerance>() {
    walks_along_the_foot_of::<S>((30.0, 60.0), 2143.0, 11.0);
}

/// Walking along an upright wall at the side of a floor rising 20° along it (both tiled in
/// unit cells), 2 units/s along and 1 into the wall, turned 23°, out 300 and 3 000, at 240 and
/// 960 Hz. In `f32` at 960 Hz out 300 the ball came within a position's rounding of both, and
/// its lift off the wall, running along the floor, was met by the floor at once and given up:
/// every later walk met the wall at once and the ball stuck for good (3.6 made in 3 s, where
/// `f64` makes 4.98); a lift met at once by a plane it runs along now leaves both planes. Out
/// 3 000, where the walk's ends round closer to the wall each frame, the ball lagged (4.36)
/// until a float ball within a position's rounding of a plane came to be lifted back to a skin
/// off it.
fn walks_along_an_upright_wall_up_a_slope_far_out<S: Tolerance>() {
    for out in [300.0, 3000.0] {
        let place = far(out, 23.0);
        let y = |x: f64| tan(20.0) * x;
        let mut level: Scene<S, 256> = tiled(|x, _| y(x), (-8.0, -3.0), (24, 4, 1.0), &place);
        for i in 0..24 {
            // The wall at z = 1, facing -z, from below the floor to well above the ball.
            let (x0, x1) = (-8.0 + i as f64, -7.0 + i as f64);
            let [a, b, c, d] = [[x0, y(x0) - 1.0], [x1, y(x1) - 1.0], [x1, 20.0], [x0, 20.0]]
                .map(|[x, h]| v::<S>(place([x, h, 1.0])));
            level.push(Triangle::new(a, c, b)).unwrap();
            level.push(Triangle::new(a, d, c)).unwrap();
        }
        let start = place([-5.0, y(-5.0) + 0.5 / 20f64.to_radians().cos() + 0.05, 0.0]);
        let wish = turn(23.0)([2.0, 0.0, 1.0]);
        let heading = turn(23.0)([20f64.to_radians().cos(), 0.0, 0.0]);
        for hz in [240, 960] {
            let (made, at) = progress(0.5, &level, (start, wish, heading), hz);
            let what = format!("{} out {out}, {hz} Hz", S::NAME);
            assert!(made > 4.7, "{what}: made {made} at {at:?}");
        }
    }
}

/// A V-ditch of 35° and 75° sides tiled in unit cells, out 8 000 and turned 45°, walked along
/// at 2 units/s and 0.2 into the steep side by a ball of r 0.3 at 240 Hz. In `f32` the lift
/// off the steep side met the floor's plane, slid along it, and was met again by the floor's
/// next triangle, whose normal rounds 2.5e-4 rad apart that far out: taken for another plane,
/// the ball was left where it was and stuck for good (1.5 made in 3 s, where `f64` makes over
/// 5.5). A lift met again by a plane within 1e-3 rad of the one it slid along leaves both.
/// (`I16F16` vertices stay within ±4096: the scalars whose range reaches 8 000.)
fn walks_along_a_tiled_ditch_eight_thousand_out<S: Tolerance>() {
    let place = far(8000.0, 45.0);
    let f = |_: f64, z: f64| {
        if z < 0.0 {
            -tan(35.0) * z
        } else {
            tan(75.0) * z
        }
    };
    let level: Scene<S, 192> = tiled(f, (-8.0, -3.0), (16, 6, 1.0), &place);
    let start = place([-5.0, 0.3 / 75f64.to_radians().cos() + 0.1, 0.0]);
    let (wish, heading) = (turn(45.0)([2.0, 0.0, 0.2]), turn(45.0)([1.0, 0.0, 0.0]));
    let (made, at) = progress(0.3, &level, (start, wish, heading), 240);
    assert!(made > 5.5, "{}: made {made} at {at:?}", S::NAME);
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn walks_up_a_steep_ditch_far_out() {
            super::walks_up_a_steep_ditch_far_out::<$t>();
        }
        #[test]
        fn walks_along_the_foot_of_a_steep_side_far_out() {
            super::walks_along_the_foot_of_a_steep_side_far_out::<$t>();
        }
        #[test]
        fn walks_along_the_foot_of_a_right_angled_ditch_far_out() {
            super::walks_along_the_foot_of_a_right_angled_ditch_far_out::<$t>();
        }
        #[test]
        fn walks_along_an_upright_wall_up_a_slope_far_out() {
            super::walks_along_an_upright_wall_up_a_slope_far_out::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);

#[test]
fn walks_along_a_tiled_ditch_eight_thousand_out_f64() {
    walks_along_a_tiled_ditch_eight_thousand_out::<f64>();
}

#[test]
fn walks_along_a_tiled_ditch_eight_thousand_out_f32() {
    walks_along_a_tiled_ditch_eight_thousand_out::<f32>();
}

#[test]
fn walks_along_a_tiled_ditch_eight_thousand_out_i32f32() {
    walks_along_a_tiled_ditch_eight_thousand_out::<I32F32>();
}
