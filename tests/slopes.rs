//! `Character::with_constant_speed`: on a slope the walk takes the speed and heading of the
//! wish's part across `up` (Godot's `floor_constant_speed`); without it, the walk is the wish's
//! part along the floor's plane, `cos θ` of a level wish heading straight up or down a slope of
//! `θ`. Expected distances are worked by hand from the slope's angle; each scalar is also held to
//! `f64`'s walk. Every property in every scalar.

#[macro_use]
mod common;

use ballcast::{Error, Input, Scalar, Scene, Triangle, Vec3, slide::Character};
use common::{P, Tolerance, quad, v};

/// Frames at 60 Hz walked after landing: one second.
const FRAMES: usize = 60;

/// How far a walk of one second may end from the distance worked by hand: the rounding of 60
/// walks and presses at coordinates up to 20 (`I16F16`: a step of 2^-16 per coordinate and
/// operation, and its unit vectors' 2^-15 of the speed).
fn allowed<S: Tolerance>() -> f64 {
    match S::NAME {
        "f64" => 1e-9,
        "f32" => 3e-5,
        "I32F32" => 1e-6,
        "I16F16" => 1e-3,
        other => panic!("no allowance for {other}"),
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

/// A ball of 0.5 resting on the `deg` slope over `x`, `constant` its option: dropped from just
/// above the plane along its normal (-sin, cos, 0) until it lands.
fn landed<S: Tolerance>(level: &Scene<S, 2>, deg: f64, x: f64, constant: bool) -> Character<S> {
    let (sin, cos) = deg.to_radians().sin_cos();
    let at = [x - 0.52 * sin, x * deg.to_radians().tan() + 0.52 * cos, 0.0];
    let mut me = Character::new(v::<S>(at), S::from_f64(0.5))
        .unwrap()
        .with_constant_speed(constant);
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
    let down = (0..30).any(|_| {
        me.update(level, Vec3::ZERO, gravity, dt).unwrap();
        me.is_grounded()
    });
    assert!(down, "{}: never landed on the {deg}° slope", S::NAME);
    me
}

/// The ball landed on the `deg` slope over `x` and walked for a second at the `wish`ed
/// velocity: where the walk began and ended. Grounded on every frame of the walk.
fn walked<S: Tolerance>(deg: f64, x: f64, wish: P, constant: bool) -> (P, P) {
    let level = slope::<S>(deg);
    let mut me = landed(&level, deg, x, constant);
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
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

/// A walk on a slope: where it starts over x, the wish, and the distances worked by hand
/// (along the slope, along z) with the option off and on.
type Case = (f64, P, (f64, f64), (f64, f64));

/// Walking for a second on slopes of 15°, 30° and 40°, with the option off and on: the distance
/// covered along the slope's rising direction `(cos θ, sin θ, 0)` and along z is the one worked
/// by hand, and each scalar's end is within its rounding of `f64`'s.
///
/// Off, the walk is the wish `w` less its part along the normal, so it covers `w · s` along the
/// slope (`s` its rising direction) and `w_z` along z. On, it covers the length of the wish's
/// level part `(w_x, 0, w_z)`, along the slope as that part heads: here `±2` up or down it
/// whatever `w_y` is, `2` across it, `-2 sin θ` for a wish square to the floor (its level part
/// heads down the slope), nothing for a wish straight up.
fn walks_cover_the_distances_worked_by_hand<S: Tolerance>() {
    for deg in [15.0, 30.0, 40.0] {
        let (sin, cos) = f64::to_radians(deg).sin_cos();
        let cases: [Case; 7] = [
            (-10.0, [2.0, 0.0, 0.0], (2.0 * cos, 0.0), (2.0, 0.0)),
            (10.0, [-2.0, 0.0, 0.0], (-2.0 * cos, 0.0), (-2.0, 0.0)),
            (-10.0, [2.0, 1.0, 0.0], (2.0 * cos + sin, 0.0), (2.0, 0.0)),
            (
                10.0,
                [-2.0, -1.0, 0.0],
                (-2.0 * cos - sin, 0.0),
                (-2.0, 0.0),
            ),
            (0.0, [0.0, 0.0, 2.0], (0.0, 2.0), (0.0, 2.0)),
            (
                0.0,
                [-2.0 * sin, 2.0 * cos, 0.0],
                (0.0, 0.0),
                (-2.0 * sin, 0.0),
            ),
            (0.0, [0.0, 1.0, 0.0], (sin, 0.0), (0.0, 0.0)),
        ];
        for (x, wish, off, on) in cases {
            for (constant, (along, z)) in [(false, off), (true, on)] {
                let (start, end) = walked::<S>(deg, x, wish, constant);
                let d = common::sub(end, start);
                let got = (common::dot(d, [cos, sin, 0.0]), d[2]);
                assert!(
                    (got.0 - along).abs() <= allowed::<S>() && (got.1 - z).abs() <= allowed::<S>(),
                    "{}: {deg}° walking {wish:?} (constant speed {constant}) covered {got:?}, \
                     not {:?}",
                    S::NAME,
                    (along, z)
                );
                let (_, reference) = walked::<f64>(deg, x, wish, constant);
                let off_f64 = common::norm(common::sub(end, reference));
                assert!(
                    off_f64 <= 2.0 * allowed::<S>(),
                    "{}: {deg}° walking {wish:?} (constant speed {constant}) ends {off_f64:e} \
                     from f64's",
                    S::NAME
                );
            }
        }
    }
}

/// A level wish at 0.9765 of `LIMIT` on each axis along a 30° slope: off, the walk's velocity
/// is within range; on, lengthened to the wish's level speed, its z is about 1.044 `LIMIT`
/// (`(3, √3, 4) / √28 · √32`, scaled), which the update refuses as a velocity out of range and
/// leaves the character as it was.
fn a_walk_beyond_the_range_is_refused<S: Tolerance>() {
    let level = slope::<S>(30.0);
    let k = 0.9765 * S::LIMIT.to_f64();
    // A step of 64 of the scalar's steps: the walk goes a few units, where the ball's radius
    // is above every scalar's rounding (a frame at 60 Hz would carry a float ball far out).
    let (wish, gravity, dt) = (
        v::<S>([k, 0.0, k]),
        v::<S>([0.0, -9.81, 0.0]),
        S::from_f64(64.0 * S::EPSILON.to_f64()),
    );
    let mut off = landed(&level, 30.0, 0.0, false);
    let r = off.update(&level, wish, gravity, dt);
    assert!(
        r.is_ok(),
        "{}: the default walk was refused: {r:?}",
        S::NAME
    );
    let mut on = landed(&level, 30.0, 0.0, true);
    let before = on;
    match on.update(&level, wish, gravity, dt) {
        Err(Error::OutOfRange {
            input: Input::Velocity,
            ..
        }) => {}
        other => panic!("{}: {other:?}, not a velocity out of range", S::NAME),
    }
    assert_eq!(
        on,
        before,
        "{}: a refused update changed the character",
        S::NAME
    );
}

every_scalar!(
    walks_cover_the_distances_worked_by_hand,
    a_walk_beyond_the_range_is_refused
);
