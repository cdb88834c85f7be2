//! The character loop a game runs every frame: gravity, `move_and_slide`, `Slide::clip` of the
//! velocity, grounded, jumping. Where and when each contact happened, the floor's slope limit,
//! and a ball's own skin. Every property in every scalar; expected values worked by hand.

mod common;

use ballcast::{Error, Scalar, Scene, Triangle, Vec3, move_and_slide, slide, slide::Slider};
use common::{Tolerance, back, v};
use fixed::types::{I16F16, I32F32};

/// A 20 × 20 floor at y = 0 facing +y, two triangles.
fn floor<S: Scalar>() -> Scene<S, 8> {
    let mut s = Scene::new();
    let c = [
        [-10.0, 0.0, -10.0],
        [-10.0, 0.0, 10.0],
        [10.0, 0.0, 10.0],
        [10.0, 0.0, -10.0],
    ];
    s.push(Triangle::new(v(c[0]), v(c[1]), v(c[2]))).unwrap();
    s.push(Triangle::new(v(c[0]), v(c[2]), v(c[3]))).unwrap();
    s
}

fn contact_time_and_point_are_where_the_ball_touched<S: Tolerance>() {
    let scene = floor::<S>();
    // Falling 1 from y = 1 with r = 0.5 and moving 1 in x: touches half-way through the step,
    // centre at (0.5, 0.5, 0), touching the floor at (0.5, 0, 0).
    let out = move_and_slide(
        &scene,
        v([0.0, 1.0, 0.0]),
        v([1.0, -1.0, 0.0]),
        S::from_f64(0.5),
    );
    let c = out.unwrap().contacts[0].expect("lands");
    let tol = 1e-3; // alpha's step (2^-16) over paths of length ~1, with room
    assert!(
        (c.time.to_f64() - 0.5).abs() < tol,
        "{}: time {:?}",
        S::NAME,
        c.time
    );
    let (center, point) = (back(c.hit.position), back(c.point));
    for (got, want) in [(center, [0.5, 0.5, 0.0]), (point, [0.5, 0.0, 0.0])] {
        assert!(
            common::norm(common::sub(got, want)) < tol,
            "{}: {got:?}",
            S::NAME
        );
    }
    // Against a wall and then the floor: contact times increase within the step.
    let mut s = floor::<S>();
    // A wall at x = 2 facing -x.
    s.push(Triangle::new(
        v([2.0, -1.0, -5.0]),
        v([2.0, -1.0, 5.0]),
        v([2.0, 5.0, -5.0]),
    ))
    .unwrap();
    let out = move_and_slide(
        &s,
        v([0.0, 2.0, 0.0]),
        v([3.0, -2.0, 0.0]),
        S::from_f64(0.5),
    );
    let times: Vec<f64> = out
        .unwrap()
        .contacts
        .iter()
        .flatten()
        .map(|c| c.time.to_f64())
        .collect();
    assert_eq!(times.len(), 2, "{}: {times:?}", S::NAME);
    // The centre reaches x = 1.5 half-way; then, sliding straight down at the same vertical
    // speed, y = 0.5 three quarters of the way.
    assert!(
        (times[0] - 0.5).abs() < tol && (times[1] - 0.75).abs() < tol,
        "{times:?}"
    );
}

fn grounded_only_on_walkable_slopes<S: Tolerance>() {
    let up = v::<S>([0.0, 1.0, 0.0]);
    let cos45 = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    // Slopes of 0°, 30°, 60° and 90° from the floor, the ball dropped straight onto each.
    for (deg, walkable) in [(0.0f64, true), (30.0, true), (60.0, false), (90.0, false)] {
        let t = deg.to_radians();
        let n = [t.sin(), t.cos(), 0.0];
        let scene = common::slope::<S>(n);
        let start = common::scale(n, 1.0);
        let out = move_and_slide(&scene, v(start), v([-1.0, -1.0, 0.0]), S::from_f64(0.5));
        let out = out.unwrap();
        assert!(out.contacts[0].is_some(), "{}: {deg}° not touched", S::NAME);
        assert_eq!(
            out.floor(up, cos45).unwrap().is_some(),
            walkable,
            "{}: {deg}°",
            S::NAME
        );
    }
}

/// A slope of exactly the default limit, 45° (rising 1 in 1 along x, tiles of 1), as laid out
/// and turned 30° about up: a ball stands on it without sliding (less than 1e-3 in 3 s) and
/// walks up it at 4 units/s grounded on every frame, making at least 3.6 of the 4 the walk along
/// the slope gives in 2 s. A 45° normal came out a unit in the last place below the limit's
/// cosine or above it, tile by tile, so the ball was grounded on some and held back as by a wall
/// on others: in `f64` it slid back down instead of walking up, and slid 1.3 standing.
fn a_slope_at_the_limit_is_walkable<S: Tolerance>() {
    for turn in [0.0f64, 30.0] {
        let (sin, cos) = turn.to_radians().sin_cos();
        let at = |x: f64, z: f64| v::<S>([cos * x - sin * z, x, sin * x + cos * z]);
        let mut level: Scene<S, 128> = Scene::new();
        for i in -4..4 {
            for k in -4..4 {
                let (x, z) = (i as f64, k as f64);
                let (a, b, c, d) = (
                    at(x, z),
                    at(x, z + 1.0),
                    at(x + 1.0, z + 1.0),
                    at(x + 1.0, z),
                );
                level.push(Triangle::new(a, b, c)).unwrap();
                level.push(Triangle::new(a, c, d)).unwrap();
            }
        }
        let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / 60.0));
        let gravity = v::<S>([0.0, -9.81, 0.0]);
        let start = at(-2.0, 0.0) + v::<S>([0.0, 0.5 * 2f64.sqrt() + 0.01, 0.0]);
        let (across, along) = (Vec3::ZERO, v::<S>([4.0 * cos, 0.0, 4.0 * sin]));
        for (wish, frames) in [(across, 180), (along, 120)] {
            let mut me = slide::Character::new(start, r).unwrap();
            for _ in 0..10 {
                me.update(&level, Vec3::ZERO, gravity, dt).unwrap();
            }
            let from = back(me.position);
            for frame in 0..frames {
                me.update(&level, wish, gravity, dt).unwrap();
                let what = format!("{} turned {turn}°, frame {frame}", S::NAME);
                assert!(me.is_grounded(), "{what}: in the air at {:?}", me.position);
            }
            let [x, _, z] = back(me.position);
            let made = (x - from[0]) * cos + (z - from[2]) * sin;
            let what = format!("{} turned {turn}°, wishing {wish:?}", S::NAME);
            if wish == Vec3::ZERO {
                assert!(made.abs() < 1e-3, "{what}: slid {made}");
            } else {
                assert!(made > 3.6, "{what}: made {made}");
            }
        }
    }
}

fn a_ball_keeps_its_own_skin<S: Tolerance>() {
    let scene = floor::<S>();
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let gap = |b: &Slider<S>| {
        let out = b
            .slide(&scene, v([0.0, 2.0, 0.0]), v([0.0, -3.0, 0.0]))
            .unwrap();
        out.position.y.to_f64() - 0.5
    };
    let wide = ball.with_skin(S::from_f64(0.0625)).unwrap();
    assert!(
        (gap(&wide) - 0.0625).abs() < 1e-4,
        "{}: {}",
        S::NAME,
        gap(&wide)
    );
    // The default is r / 1024 and the rounding term.
    assert!(
        (gap(&ball) - 0.5 / 1024.0).abs() < 1e-3,
        "{}: {}",
        S::NAME,
        gap(&ball)
    );
    // A skin below the rounding term is raised to it, never zero.
    assert!(gap(&ball.with_skin(S::ZERO).unwrap()) > 0.0, "{}", S::NAME);
    for bad in [-0.01, 0.51] {
        let e = ball.with_skin(S::from_f64(bad)).unwrap_err();
        let limit = S::from_f64(0.5).to_f64();
        let expected = Error::OutOfRange {
            input: ballcast::Input::Skin,
            value: S::from_f64(bad).to_f64(),
            min: 0.0,
            max: limit,
            triangle: None,
        };
        assert_eq!(e, expected, "{}: skin {bad}", S::NAME);
    }
}

/// Throws a ball onto the floor, walks it, and jumps whenever it is grounded: it lands, leaves
/// the floor on each jump, lands again, and never gets below it.
fn the_character_loop_lands_walks_and_jumps<S: Tolerance>() {
    let scene = floor::<S>();
    let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / 64.0));
    let (up, walkable) = (
        v::<S>([0.0, 1.0, 0.0]),
        S::from_f64(std::f64::consts::FRAC_1_SQRT_2),
    );
    let gravity = v::<S>([0.0, -10.0, 0.0]);
    let (mut p, mut vel) = (v::<S>([0.0, 3.0, 0.0]), v::<S>([1.0, 0.0, 0.0]));
    let (mut jumps, mut airborne_after_jump) = (0, 0);
    for _ in 0..600 {
        vel += gravity.scale(dt);
        let out = move_and_slide(&scene, p, vel.scale(dt), r).unwrap();
        p = out.position;
        vel = out.clip(vel).unwrap();
        assert!(
            p.y.to_f64() >= 0.5 - 1e-3,
            "{}: below the floor at {p:?}",
            S::NAME
        );
        if out.floor(up, walkable).unwrap().is_some() {
            jumps += 1;
            vel.y = S::from_f64(4.0);
        } else if jumps > 0 {
            airborne_after_jump += 1;
        }
    }
    // A jump at 4 under gravity 10 lasts 0.8 s, 51 steps: 600 steps hold several.
    assert!(jumps >= 5, "{}: {jumps} jumps", S::NAME);
    assert!(
        airborne_after_jump >= 5 * 45,
        "{}: {airborne_after_jump}",
        S::NAME
    );
    assert!(p.x.to_f64() > 5.0, "{}: did not walk: {p:?}", S::NAME);
}

/// `up` is a direction: a short or long one finds the floor as a unit one does (it once
/// compared `normal · up` with the cosine unscaled, so a short `up` found none), and the zero
/// vector is refused.
fn floor_with_an_up_of_any_length<S: Tolerance>() {
    let scene = floor::<S>();
    let out = move_and_slide(
        &scene,
        v([0.0, 0.6, 0.0]),
        v([0.1, -0.2, 0.0]),
        S::from_f64(0.5),
    );
    let out = out.unwrap();
    let cos45 = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    let found = |up: [f64; 3]| out.floor(v(up), cos45).unwrap().map(|c| c.time);
    let unit = found([0.0, 1.0, 0.0]);
    assert!(unit.is_some(), "{}: not grounded", S::NAME);
    for up in [[0.0, 0.5, 0.0], [0.0, 100.0, 0.0], [0.0, 0.01, 0.0]] {
        assert_eq!(found(up), unit, "{}: up {up:?}", S::NAME);
    }
    // Tilted beyond the slope limit, whatever its length: not floor.
    assert_eq!(found([2.0, 1.0, 0.0]), None, "{}", S::NAME);
    assert_eq!(
        out.floor(v([0.0; 3]), cos45).unwrap_err(),
        Error::ZeroVector {
            input: ballcast::Input::Up
        },
        "{}",
        S::NAME
    );
}

/// The 20 × 20 floor and a wall at x = 8 facing −x, 4 high: a corner along z.
fn floor_and_wall<S: Scalar>() -> Scene<S, 8> {
    let mut s = floor::<S>();
    let w = |y: f64, z: f64| v::<S>([8.0, y, z]);
    s.push(Triangle::new(w(0.0, -10.0), w(0.0, 10.0), w(4.0, 10.0)))
        .unwrap();
    s.push(Triangle::new(w(0.0, -10.0), w(4.0, 10.0), w(4.0, -10.0)))
        .unwrap();
    s
}

/// A ball resting in the corner of a floor and a wall, walked into the wall at 60 Hz: one
/// frame of gravity (9.81 / 3600, below 2^-8.5, whose square `I16F16` rounds to zero) still
/// brings it down onto the floor every frame, and a sideways step as small slides it along
/// the wall. Both slides are what is left of the step once the wall takes its part; their
/// product with the step was once rounded to zero in `I16F16`, and the slide dropped.
fn slow_slides_along_a_wall_are_kept<S: Tolerance>() {
    let scene = floor_and_wall::<S>();
    let (r, up) = (S::from_f64(0.5), v::<S>([0.0, 1.0, 0.0]));
    let walkable = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    let mut p = v::<S>([7.0, 0.6, 0.0]);
    for _ in 0..60 {
        p = move_and_slide(&scene, p, v([0.05, -0.02, 0.0]), r)
            .unwrap()
            .position;
    }
    let g = 9.81 / 3600.0;
    for frame in 0..60 {
        let out = move_and_slide(&scene, p, v([0.05, -g, 0.0]), r).unwrap();
        p = out.position;
        let grounded = out.floor(up, walkable).unwrap().is_some();
        assert!(grounded, "{}: frame {frame} not grounded at {p:?}", S::NAME);
    }
    for step in [0.002, 0.0027] {
        let out = move_and_slide(&scene, p, v([0.05, 0.0, step]), r).unwrap();
        let moved = out.position.z.to_f64() - p.z.to_f64();
        assert!(
            (moved - step).abs() < 1e-4,
            "{}: slid {moved} of {step} along the wall",
            S::NAME
        );
    }
}

/// A floor and two walls meeting along the y axis at `angle` degrees (wider than a right
/// angle: the walls' normals make an obtuse corner), one facing +x, the other turned about y.
fn wide_corner<S: Scalar>(angle: f64) -> Scene<S, 8> {
    let mut level: Scene<S, 8> = Scene::new();
    let (a, b, c, d) = (
        [-20.0, 0.0, -20.0],
        [-20.0, 0.0, 20.0],
        [20.0, 0.0, 20.0],
        [20.0, 0.0, -20.0],
    );
    level.push(Triangle::new(v(a), v(b), v(c))).unwrap();
    level.push(Triangle::new(v(a), v(c), v(d))).unwrap();
    for turn in [0.0f64, 180.0 - angle] {
        let (sin, cos) = turn.to_radians().sin_cos();
        let p = |u: f64, y: f64| v::<S>([-sin * u, y, cos * u]);
        level
            .push(Triangle::new(p(-20.0, -1.0), p(20.0, 4.0), p(20.0, -1.0)))
            .unwrap();
        level
            .push(Triangle::new(p(-20.0, -1.0), p(-20.0, 4.0), p(20.0, 4.0)))
            .unwrap();
    }
    level
}

/// The character loop standing in a corner of 120° or 150° and pressing into it: grounded on
/// every frame, as in a right-angled corner. It once lost the floor on most frames: the slide
/// along one wall ran against the motion and was dropped, and the crease of the two walls,
/// straight down to the floor, was never tried.
fn pressing_into_a_wide_corner_stays_grounded<S: Tolerance>() {
    let (dt, r, up) = (
        S::from_f64(1.0 / 60.0),
        S::from_f64(0.4),
        v::<S>([0.0, 1.0, 0.0]),
    );
    let walkable = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    for (angle, push) in [(120.0, [-5.2, -3.0]), (150.0, [-5.8, -1.55])] {
        let level = wide_corner::<S>(angle);
        let (mut p, mut vel) = (v::<S>([1.5, 0.41, 0.9]), v::<S>([0.0; 3]));
        for frame in 0..600 {
            let wish = v::<S>([push[0], 0.0, push[1]]);
            vel = Vec3::new(wish.x, vel.y, wish.z) + v::<S>([0.0, -9.81, 0.0]) * dt;
            let out = move_and_slide(&level, p, vel * dt, r).unwrap();
            (p, vel) = (out.position, out.clip(vel).unwrap());
            let grounded = out.floor(up, walkable).unwrap().is_some();
            assert!(
                frame < 120 || grounded,
                "{}: {angle}°, frame {frame} in the air at {p:?}",
                S::NAME
            );
        }
    }
}

/// The character loop resting at the bottom of a level valley whose slopes are each too steep
/// to stand on (60° and 80°): the valley holds it, so it is grounded on every frame once it has
/// landed, in every scalar. It was grounded only on frames where rounding made it touch both
/// slopes at once (their normals merged into a level one). A valley as steep, rising at 60°
/// along its trough, holds nothing: the ball slides down it, never grounded.
fn resting_in_a_steep_valley_is_grounded<S: Tolerance>() {
    let (dt, r, up) = (
        S::from_f64(1.0 / 60.0),
        S::from_f64(0.5),
        v::<S>([0.0, 1.0, 0.0]),
    );
    let walkable = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    for (steep, rise, holds) in [(60.0, 0.0, true), (80.0, 0.0, true), (60.0, 60.0, false)] {
        let level = common::valley::<S>(steep, rise);
        let (mut p, mut vel) = (v::<S>([0.3, 3.0, 0.0]), v::<S>([0.0; 3]));
        let mut grounded_frames = 0;
        for frame in 0..240 {
            vel += v::<S>([0.0, -9.81, 0.0]) * dt;
            let out = move_and_slide(&level, p, vel * dt, r).unwrap();
            (p, vel) = (out.position, out.clip(vel).unwrap());
            let grounded = out.floor(up, walkable).unwrap().is_some();
            grounded_frames += usize::from(grounded);
            assert!(
                frame < 120 || grounded == holds,
                "{}: {steep}° valley rising {rise}°, frame {frame}: grounded {grounded} at {p:?}",
                S::NAME
            );
        }
        assert!(
            holds || grounded_frames == 0,
            "{}: {grounded_frames}",
            S::NAME
        );
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn contact_time_and_point() {
            contact_time_and_point_are_where_the_ball_touched::<$t>();
        }
        #[test]
        fn grounded_on_walkable_slopes() {
            grounded_only_on_walkable_slopes::<$t>();
        }
        #[test]
        fn a_slope_at_the_limit() {
            a_slope_at_the_limit_is_walkable::<$t>();
        }
        #[test]
        fn own_skin() {
            a_ball_keeps_its_own_skin::<$t>();
        }
        #[test]
        fn character_loop() {
            the_character_loop_lands_walks_and_jumps::<$t>();
        }
        #[test]
        fn floor_with_up_of_any_length() {
            floor_with_an_up_of_any_length::<$t>();
        }
        #[test]
        fn slow_slides_along_a_wall() {
            slow_slides_along_a_wall_are_kept::<$t>();
        }
        #[test]
        fn resting_in_a_steep_valley() {
            resting_in_a_steep_valley_is_grounded::<$t>();
        }
        #[test]
        fn pressing_into_a_wide_corner() {
            pressing_into_a_wide_corner_stays_grounded::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
