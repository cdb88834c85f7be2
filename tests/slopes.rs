//! `Character::with_constant_speed`: on a slope the walk keeps the wished speed along the floor
//! (Godot's `floor_constant_speed`); without it, the walk is the wish's part along the floor's
//! plane, `cos θ` of the wish heading straight up or down a slope of `θ`. Expected distances
//! are worked by hand from the slope's angle; each scalar is also held to `f64`'s walk.
//! Every property in every scalar.

mod common;

use ballcast::{Scalar, Scene, Triangle, Vec3, slide::Character};
use common::{P, Tolerance, quad, v};
use fixed::types::{I16F16, I32F32};

/// Frames at 60 Hz walked after landing: one second.
const FRAMES: usize = 60;

/// How far a walk of one second may end from the distance worked by hand: the rounding of 60
/// walks and presses at coordinates up to 20 (`I16F16`: a step of 2^-16 per coordinate and
/// operation, and its unit vectors' 2^-15 of the speed).
fn allowed<S: Tolerance>() -> f64 {
    match S::NAME {
        "f64" => 1e-9,
        "f32" => 1e-4,
        "I32F32" => 1e-6,
        _ => 2e-3,
    }
}

/// A plane rising at `deg` degrees along +x through the origin, 60 square.
fn slope<S: Scalar>(deg: f64) -> Scene<S, 2> {
    let t = deg.to_radians().tan();
    let mut s = Scene::new();
    for q in quad(
        [-30.0, -30.0 * t, -30.0],
        [0.0, 0.0, 60.0],
        [60.0, 60.0 * t, 0.0],
    ) {
        s.push(Triangle::new(v(q[0]), v(q[1]), v(q[2]))).unwrap();
    }
    s
}

/// A ball of 0.5 dropped onto the `deg` slope over `x`, then walked for a second at the
/// `wish`ed velocity: where the walk began and ended. Grounded on every frame of the walk.
fn walked<S: Tolerance>(deg: f64, x: f64, wish: P, constant: bool) -> (P, P) {
    let level = slope::<S>(deg);
    let (sin, cos) = deg.to_radians().sin_cos();
    // Just above the plane along its normal (-sin, cos, 0).
    let at = [x - 0.52 * sin, x * deg.to_radians().tan() + 0.52 * cos, 0.0];
    let mut me = Character::new(v::<S>(at), S::from_f64(0.5))
        .unwrap()
        .with_constant_speed(constant);
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
    let landed = (0..30).any(|_| {
        me.update(&level, Vec3::ZERO, gravity, dt).unwrap();
        me.is_grounded()
    });
    assert!(landed, "{}: never landed on the {deg}° slope", S::NAME);
    let start = common::back(me.position);
    for frame in 0..FRAMES {
        me.update(&level, v::<S>(wish), gravity, dt).unwrap();
        assert!(
            me.is_grounded(),
            "{}: off the {deg}° slope at frame {frame} walking {wish:?}",
            S::NAME
        );
    }
    (start, common::back(me.position))
}

/// [`walked`] in `S`: the displacement, the end, and the end of the same walk in `f64`.
fn walk<S: Tolerance>(deg: f64, x: f64, wish: P, constant: bool) -> (P, P, P) {
    let (start, end) = walked::<S>(deg, x, wish, constant);
    let (_, reference) = walked::<f64>(deg, x, wish, constant);
    (common::sub(end, start), end, reference)
}

/// The distance of `d` along the `deg` slope's rising direction (cos, sin, 0).
fn along_slope(d: P, deg: f64) -> f64 {
    let (sin, cos) = deg.to_radians().sin_cos();
    common::dot(d, [cos, sin, 0.0])
}

/// Each scalar's end within its rounding (its distance's allowance, at these coordinates) of
/// `f64`'s.
fn near_f64<S: Tolerance>(end: P, reference: P, what: &str) {
    let off = common::norm(common::sub(end, reference));
    assert!(
        off <= 2.0 * allowed::<S>(),
        "{}: {what} ends {off:e} from f64's",
        S::NAME
    );
}

/// With constant speed, walking at 2 units/s straight up or down slopes of 15°, 30° and 40°
/// covers 2 units along the slope in a second, whatever the angle: the wish's speed.
fn constant_speed_keeps_the_wished_speed_up_and_down_slopes<S: Tolerance>() {
    for deg in [15.0, 30.0, 40.0] {
        for (x, wish, sign) in [
            (-10.0, [2.0, 0.0, 0.0], 1.0),
            (10.0, [-2.0, 0.0, 0.0], -1.0),
        ] {
            let (d, end, reference) = walk::<S>(deg, x, wish, true);
            let got = sign * along_slope(d, deg);
            assert!(
                (got - 2.0).abs() <= allowed::<S>(),
                "{}: {deg}° walking {wish:?} covered {got} along the slope, not 2",
                S::NAME
            );
            near_f64::<S>(end, reference, "a constant-speed walk");
        }
    }
}

/// Without it (the default), the walk is the wish's part along the plane: `2 cos θ` along the
/// slope heading straight up or down it.
fn by_default_the_walk_is_the_wish_along_the_plane<S: Tolerance>() {
    for deg in [15.0, 30.0, 40.0] {
        for (x, wish, sign) in [
            (-10.0, [2.0, 0.0, 0.0], 1.0),
            (10.0, [-2.0, 0.0, 0.0], -1.0),
        ] {
            let (d, end, reference) = walk::<S>(deg, x, wish, false);
            let want = 2.0 * deg.to_radians().cos();
            let got = sign * along_slope(d, deg);
            assert!(
                (got - want).abs() <= allowed::<S>(),
                "{}: {deg}° walking {wish:?} covered {got} along the slope, not {want}",
                S::NAME
            );
            near_f64::<S>(end, reference, "a default walk");
        }
    }
}

/// Heading across the slope (along z, level on it), both walk the whole wish: 2 units along z
/// and nothing up or down the slope.
fn across_a_slope_both_walk_the_whole_wish<S: Tolerance>() {
    for constant in [false, true] {
        let (d, end, reference) = walk::<S>(30.0, 0.0, [0.0, 0.0, 2.0], constant);
        assert!(
            (d[2] - 2.0).abs() <= allowed::<S>() && along_slope(d, 30.0).abs() <= allowed::<S>(),
            "{}: across the slope (constant speed {constant}) moved {d:?}",
            S::NAME
        );
        near_f64::<S>(end, reference, "a walk across the slope");
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;

        #[test]
        fn constant_speed_up_and_down_slopes() {
            constant_speed_keeps_the_wished_speed_up_and_down_slopes::<$t>();
        }
        #[test]
        fn default_walk_along_the_plane() {
            by_default_the_walk_is_the_wish_along_the_plane::<$t>();
        }
        #[test]
        fn across_a_slope() {
            across_a_slope_both_walk_the_whole_wish::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
