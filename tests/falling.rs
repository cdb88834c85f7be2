//! Falling with the plain character loop (gravity, `Slider::slide`, `Slider::clip` of the
//! velocity) down a slope too steep to stand on, onto the floor below or into a narrow valley
//! that holds the ball. Every property in every scalar; expected values worked by hand.

mod common;

use ballcast::{Triangle, Vec3, move_and_slide, slide::Slider};
use common::{Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// A ball (r = 0.5) dropped 0.02 from a wall leaning at 80°–89.5° (front normal
/// `(-sin a, cos a, 0)`, through the origin) above a floor at y = -5: it meets the wall on the
/// way down, slides down it and lands on the floor (centre at y = -4.5 less a skin) within
/// 3 s, held back by slopes steeper than 45° ([`Slider::with_max_slope`]) or not. In `I16F16`, at 88° it hovered at y = -1.50 for good: it came to rest
/// closer to the wall than a skin, and its slide down the wall, which rounding made run into the
/// wall by less than a step, was stopped at once on every later call.
fn sliding_down_a_near_vertical_wall_reaches_the_floor<S: Tolerance>() {
    let (dt, r) = (S::from_f64(1.0 / 60.0), S::from_f64(0.5));
    let walkable = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    for angle in [80.0, 85.0, 87.0, 88.0, 88.5, 89.0, 89.5] {
        let a = f64::to_radians(angle);
        let mut level = common::slope::<S>([-a.sin(), a.cos(), 0.0]);
        let f = |x: f64, z: f64| v::<S>([x, -5.0, z]);
        let (p, q, s, t) = (f(-8.0, -8.0), f(-8.0, 8.0), f(8.0, 8.0), f(8.0, -8.0));
        level.push(Triangle::new(p, q, s)).unwrap();
        level.push(Triangle::new(p, s, t)).unwrap();
        // At y = 3 the wall is at x = 3 cot a: start 0.52 from the wall's plane there.
        let x = 3.0 * a.cos() / a.sin() - 0.52 / a.sin();
        let free = Slider::new(r).unwrap();
        let held = free.with_max_slope(v([0.0, 1.0, 0.0]), walkable).unwrap();
        for ball in [free, held] {
            let (mut pos, mut vel) = (v::<S>([x, 3.0, 0.0]), Vec3::ZERO);
            let landed = (0..300).position(|_| {
                vel += v::<S>([0.0, -9.81, 0.0]) * dt;
                let out = ball.slide(&level, pos, vel * dt).unwrap();
                (pos, vel) = (out.position, ball.clip(&out, vel).unwrap());
                (pos.y.to_f64() + 4.5).abs() < 0.01
            });
            // Free fall alone takes 1.24 s (74 frames) from y = 3 to y = -4.5.
            assert!(
                landed.is_some_and(|frame| frame < 180),
                "{}: {angle}° wall, {ball:?}: landed {landed:?}, at {:?}",
                S::NAME,
                common::back(pos)
            );
        }
    }
}

/// Dropped into a level valley of 82°–89° slopes, the ball wedges where the slopes are a ball
/// apart (centre at `r / cos(slope)`), and the valley holds it: it is grounded, in every scalar.
/// Whether it was depended on rounding: the valley's crease was judged only for slopes up to
/// about 83° (normals at least 14° from opposed), steeper ones only where rounding merged the
/// two contacts into one level normal, so
/// from 84° to 88° `f32` and `f64` were grounded on none of the frames and the fixed-point
/// scalars on all. (Resting a skin off both slopes, the ball can drop a frame's fall without
/// touching either, as its gap closes by only `cos(slope)` of the fall: a few frames may pass
/// ungrounded.)
fn wedged_in_a_narrow_valley_is_grounded<S: Tolerance>() {
    let (dt, r, up) = (
        S::from_f64(1.0 / 60.0),
        S::from_f64(0.5),
        v::<S>([0.0, 1.0, 0.0]),
    );
    let walkable = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    for steep in [82.0, 84.0, 85.0, 86.0, 87.0, 88.0, 89.0] {
        let level = common::valley::<S>(steep, 0.0);
        let wedged = 0.5 / f64::to_radians(steep).cos();
        let (mut pos, mut vel) = (v::<S>([0.0, wedged + 2.0, 0.0]), Vec3::ZERO);
        let mut grounded = 0;
        for frame in 0..240 {
            vel += v::<S>([0.0, -9.81, 0.0]) * dt;
            let out = move_and_slide(&level, pos, vel * dt, r).unwrap();
            (pos, vel) = (out.position, out.clip(vel).unwrap());
            let floor = out.floor(up, walkable).unwrap();
            grounded += usize::from(frame >= 120 && floor.is_some());
        }
        let y = pos.y.to_f64();
        assert!(
            grounded >= 115 && (y - wedged).abs() < 0.01,
            "{}: {steep}° valley: grounded on {grounded} of 120 frames, at y {y} (wedged {wedged})",
            S::NAME
        );
    }
}

/// Falling into a valley of 45° or 70° slopes 3 900 from the origin (near the edge of
/// `I16F16`'s range) and running along it: no call moves the ball further than asked, beyond
/// a skin. In `f32` a call moved up to 4 skins further: a contact on a slide almost along a
/// slope put the centre far along the path from alpha's point, and the rest of the slide was
/// taken from alpha's.
fn running_along_a_valley_far_from_the_origin_never_outruns_its_motion<S: Tolerance>() {
    let (dt, r) = (S::from_f64(1.0 / 60.0), S::from_f64(0.5));
    let far = [3900.0, -3900.0, 3900.0];
    for (steep, rise, wish) in [
        (70.0, 0.0, [1.0, 0.5]),
        (70.0, 5.0, [0.0, 2.0]),
        (45.0, 5.0, [1.0, 0.5]),
    ] {
        let level = common::valley_at::<S>(steep, rise, far);
        let mut pos = v::<S>(common::add(far, [0.3, 3.0, 0.0]));
        let mut vel = Vec3::<S>::ZERO;
        for frame in 0..480 {
            vel.y = vel.y - S::from_f64(9.81).mul(dt);
            (vel.x, vel.z) = (S::from_f64(wish[0]), S::from_f64(wish[1]));
            let d = vel * dt;
            let out = move_and_slide(&level, pos, d, r).unwrap();
            let extent = [pos, out.position]
                .iter()
                .flat_map(|p| common::back(*p))
                .fold(0.0f64, |m, x| m.max(x.abs()));
            let skin = ballcast::slide::skin(r, S::from_f64(extent)).to_f64();
            let moved = common::norm(common::sub(common::back(out.position), common::back(pos)));
            let asked = common::norm(common::back(d));
            assert!(
                moved <= asked + skin,
                "{}: {steep}° valley rising {rise}°, frame {frame}: moved {moved} for {asked} (skin {skin})",
                S::NAME
            );
            (pos, vel) = (out.position, out.clip(vel).unwrap());
        }
    }
}

/// A ball (r = 0.5) dropped into the corner of a slope too steep to stand on (50°–80°) and
/// a wall across it at 45°, above a floor at y = -5: held back by slopes steeper than 45°
/// ([`Slider::with_max_slope`]) it lands on the floor on the same frame as without the limit.
/// The slope's vertical wall, added by the limit, only keeps the ball from being carried up the
/// slope; where several ways along the planes were open, the first found was taken, not the
/// one closest to the motion, and the ball slid down the corner half as fast again (95 frames
/// free, 142 held, at 50°).
fn falling_into_a_steep_corner_held_by_the_slope_limit_lands_as_fast<S: Tolerance>() {
    let (dt, r) = (S::from_f64(1.0 / 60.0), S::from_f64(0.5));
    let walkable = S::from_f64(std::f64::consts::FRAC_1_SQRT_2);
    for slope in [50.0f64, 60.0, 70.0, 80.0] {
        let (s, c) = slope.to_radians().sin_cos();
        let w = 45f64.to_radians();
        let (ns, nw) = ([s, c, 0.0], [-w.cos(), 0.0, w.sin()]);
        let mut level = common::slope::<S>(ns);
        for t in common::plane(nw) {
            level
                .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
        let f = |x: f64, z: f64| v::<S>([x, -5.0, z]);
        let (p, q, s2, t) = (f(-8.0, -8.0), f(-8.0, 8.0), f(8.0, 8.0), f(8.0, -8.0));
        level.push(Triangle::new(p, q, s2)).unwrap();
        level.push(Triangle::new(p, s2, t)).unwrap();
        // 0.55 from both planes in y = 0, then 2 up.
        let det = ns[0] * nw[2] - nw[0] * ns[2];
        let start = [
            0.55 * (nw[2] - ns[2]) / det,
            2.0,
            0.55 * (ns[0] - nw[0]) / det,
        ];
        let free = Slider::new(r).unwrap();
        let held = free.with_max_slope(v([0.0, 1.0, 0.0]), walkable).unwrap();
        let landed = [free, held].map(|ball| {
            let (mut pos, mut vel) = (v::<S>(start), Vec3::ZERO);
            (0..300).position(|_| {
                vel += v::<S>([0.0, -9.81, 0.0]) * dt;
                let out = ball.slide(&level, pos, vel * dt).unwrap();
                (pos, vel) = (out.position, ball.clip(&out, vel).unwrap());
                (pos.y.to_f64() + 4.5).abs() < 0.01
            })
        });
        assert!(
            landed[0].is_some() && landed[1] == landed[0],
            "{}: {slope}° slope: landed free {:?}, held {:?}",
            S::NAME,
            landed[0],
            landed[1]
        );
    }
}

/// A ball (r = 0.5) that lands fast on a slope (10° to 70°, several headings) or in a valley
/// of two 60° slopes keeps the part of its velocity along the slope, or along the valley's
/// crease, at every speed up to 1 000 units a second: `clip` gives that part to within the
/// rounding of the normal times the speed. In `I16F16` and `I32F32`, landing faster than
/// about 8 to 40 units a second (the threshold depended on how the normal rounded) gave zero:
/// after taking the push into the plane off, rounding left the slide running into it by more
/// than a fixed allowance of eight steps, though by no more than the normal's rounding times
/// the push, so the slide was refused and the ball stopped dead (falling 4 m onto a ramp).
fn landing_fast_on_a_slope_keeps_its_slide<S: Tolerance>() {
    let r = S::from_f64(0.5);
    let speeds = [1.0, 8.0, 11.118, 16.0, 40.0, 100.0, 1000.0];
    let fits = |got: Vec3<S>, want: common::P, speed: f64| {
        let err = common::norm(common::sub(common::back(got), want));
        // The normal's rounding (a few steps of one) times the speed, and the speed's steps.
        err <= 64.0 * (S::spacing(speed) + speed * S::spacing(1.0))
    };
    for tilt in [10.0f64, 20.0, 35.0, 50.0, 70.0] {
        for heading in [0.0f64, 37.0, 100.0, 200.0] {
            let (t, h) = (tilt.to_radians(), heading.to_radians());
            let n = [t.sin() * h.cos(), t.cos(), t.sin() * h.sin()];
            let level = common::slope::<S>(n);
            // 0.1 from touching, then a fall that meets the slope.
            let start = v::<S>(common::scale(n, 0.6));
            let out = move_and_slide(&level, start, v([0.0, -0.3, 0.0]), r).unwrap();
            assert!(out.contacts[0].is_some(), "{}: {tilt}° {heading}°", S::NAME);
            for speed in speeds {
                let vel = [0.2 * speed, -speed, -0.1 * speed];
                let want = common::sub(vel, common::scale(n, common::dot(vel, n)));
                let got = out.clip(v(vel)).unwrap();
                assert!(
                    fits(got, want, speed),
                    "{}: {tilt}° slope heading {heading}°, speed {speed}: clip {:?}, want {want:?}",
                    S::NAME,
                    common::back(got)
                );
            }
        }
    }
    // A valley along z of two 60° slopes: the crease keeps the motion along the valley.
    for valley in [3.0f64, 10.0, 30.0, 60.0, 80.0] {
        let (s, c) = valley.to_radians().sin_cos();
        let mut level = common::slope::<S>([s, c, 0.0]);
        for t in common::plane([-s, c, 0.0]) {
            level
                .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
        let start = v::<S>([0.0, 0.5 / c + 0.1, 0.0]);
        let out = move_and_slide(&level, start, v([0.0, -0.3, 0.0]), r).unwrap();
        for speed in speeds {
            let got = out.clip(v([0.0, -speed, 0.5 * speed])).unwrap();
            assert!(
                fits(got, [0.0, 0.0, 0.5 * speed], speed),
                "{}: {valley}° valley, speed {speed}: clip {:?}",
                S::NAME,
                common::back(got)
            );
        }
    }
}

/// One `move_and_slide` of (10, -40, 0) onto the slope `4 y = z` from 0.1 above touching ends
/// where the slide along the slope takes it: the motion's part along the slope, at a radius
/// (and a skin) from the plane. In `I16F16` it stopped at the contact, 10 units short.
fn a_steep_fall_onto_a_slope_slides_on<S: Tolerance>() {
    let k = 1.0 / 17f64.sqrt();
    let n = [0.0, 4.0 * k, -k];
    let level = common::slope::<S>(n);
    let (p0, d) = ([0.0, 0.6, 0.0], [10.0, -40.0, 0.0]);
    let out = move_and_slide(&level, v::<S>(p0), v(d), S::from_f64(0.5)).unwrap();
    let along = common::sub(d, common::scale(n, common::dot(d, n)));
    let want = common::add(
        common::add(p0, along),
        common::scale(n, 0.5 - common::dot(p0, n)),
    );
    let err = common::norm(common::sub(common::back(out.position), want));
    assert!(
        err < 0.01,
        "{}: ended at {:?}, want {want:?}",
        S::NAME,
        common::back(out.position)
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn sliding_down_a_near_vertical_wall() {
            sliding_down_a_near_vertical_wall_reaches_the_floor::<$t>();
        }
        #[test]
        fn running_along_a_valley_far_from_the_origin() {
            running_along_a_valley_far_from_the_origin_never_outruns_its_motion::<$t>();
        }
        #[test]
        fn falling_into_a_steep_corner_held_by_the_slope_limit() {
            falling_into_a_steep_corner_held_by_the_slope_limit_lands_as_fast::<$t>();
        }
        #[test]
        fn landing_fast_on_a_slope() {
            landing_fast_on_a_slope_keeps_its_slide::<$t>();
        }
        #[test]
        fn a_steep_fall_onto_a_slope() {
            a_steep_fall_onto_a_slope_slides_on::<$t>();
        }
        #[test]
        fn wedged_in_a_narrow_valley() {
            wedged_in_a_narrow_valley_is_grounded::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
