//! `slide::Character`, the README's character loop as a type: jumps only from the floor, an
//! update that fails changes nothing, bad settings are errors, standing on a slope at a high
//! frame rate does not creep. Its walking, stepping and
//! snapping are those of the recipe, tested through it in `tests/steps.rs`,
//! `tests/stairs.rs` and `tests/crests.rs`. Every property in every scalar.

mod common;

use ballcast::{Error, Input, Scalar, Scene, Triangle, Vec3, slide::Character};
use common::{Tolerance, quad, v};
use fixed::types::{I16F16, I32F32};

/// A floor at y = 0, 40 square.
fn floor<S: Scalar>() -> Scene<S, 2> {
    let mut s = Scene::new();
    for t in quad([-20.0, 0.0, -20.0], [0.0, 0.0, 40.0], [40.0, 0.0, 0.0]) {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    s
}

/// Dropped from 1 above the floor, the ball lands within half a second and stays grounded;
/// a jump at 4 units/s from the floor leaves it (true), rises (to about 0.8 above the floor:
/// `v² / 2g`), and asked again in the air does nothing (false); it lands again within a second.
fn jumps_only_from_the_floor<S: Tolerance>() {
    let level = floor::<S>();
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
    let mut me = Character::new(v::<S>([0.0, 1.5, 0.0]), S::from_f64(0.5)).unwrap();
    assert!(
        !me.jump(S::from_f64(4.0)).unwrap(),
        "{}: jumped in the air",
        S::NAME
    );
    let walk = v::<S>([1.0, 0.0, 0.0]);
    let landed = (0..30).position(|_| {
        me.update(&level, walk, gravity, dt).unwrap();
        me.is_grounded()
    });
    assert!(landed.is_some(), "{}: never landed", S::NAME);
    assert!(
        me.jump(S::from_f64(4.0)).unwrap(),
        "{}: no jump from the floor",
        S::NAME
    );
    let mut top = 0.0f64;
    let mut back_down = None;
    for frame in 0..60 {
        me.update(&level, walk, gravity, dt).unwrap();
        top = top.max(me.position.y.to_f64());
        if frame == 5 {
            assert!(
                !me.jump(S::from_f64(4.0)).unwrap(),
                "{}: jumped in the air",
                S::NAME
            );
        }
        if me.is_grounded() {
            back_down = Some(frame);
            break;
        }
    }
    let rise = top - 0.5;
    assert!((0.7..0.9).contains(&rise), "{}: rose {rise}", S::NAME);
    assert!(
        back_down.is_some_and(|f| f > 20),
        "{}: landed at {back_down:?}",
        S::NAME
    );
}

/// A frame whose wish is NaN, or whose walk would leave the range, is an error, and the
/// character is as it was: position, velocity and floor.
fn an_update_that_fails_changes_nothing<S: Tolerance>() {
    let level = floor::<S>();
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
    let mut me = Character::new(v::<S>([0.0, 0.6, 0.0]), S::from_f64(0.5)).unwrap();
    for _ in 0..30 {
        me.update(&level, Vec3::ZERO, gravity, dt).unwrap();
    }
    assert!(me.is_grounded(), "{}", S::NAME);
    let before = me;
    let nan = Vec3::new(S::ZERO, S::ZERO, S::from_f64(f64::NAN));
    if S::from_f64(f64::NAN).to_f64().is_nan() {
        assert!(me.update(&level, nan, gravity, dt).is_err(), "{}", S::NAME);
        assert_eq!(me, before, "{}", S::NAME);
    }
    // Teleported next to the range's edge, a walk over it.
    me.position.z = S::LIMIT - S::ONE;
    let before = me;
    let out = me.update(&level, v::<S>([0.0, 0.0, 2.0]), gravity, S::ONE);
    assert!(out.is_err(), "{}: {out:?}", S::NAME);
    assert_eq!(me, before, "{}", S::NAME);
}

/// Negative or NaN step heights and snap depths, a zero `up`, a slope limit beyond one, a
/// negative radius and a position out of range are errors, not characters.
fn bad_settings_are_errors<S: Tolerance>() {
    let me = Character::new(v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5)).unwrap();
    let minus = S::from_f64(-0.1);
    assert!(
        matches!(me.with_step(minus), Err(Error::OutOfRange { .. })),
        "{}",
        S::NAME
    );
    assert!(
        matches!(me.with_snap(minus), Err(Error::OutOfRange { .. })),
        "{}",
        S::NAME
    );
    assert_eq!(
        me.with_slope(Vec3::ZERO, S::ONE),
        Err(Error::ZeroVector {
            input: ballcast::Input::Up
        }),
        "{}",
        S::NAME
    );
    assert!(
        me.with_slope(Vec3::Y, S::from_f64(1.5)).is_err(),
        "{}",
        S::NAME
    );
    assert!(
        me.with_skin(S::ONE).is_err(),
        "{}: a skin beyond the radius",
        S::NAME
    );
    let r = S::from_f64(-1.0);
    assert_eq!(
        Character::new(Vec3::ZERO, r),
        Err(Error::NegativeRadius { value: -1.0 }),
        "{}",
        S::NAME
    );
    let out = v::<S>([0.0, S::LIMIT.to_f64(), 0.0]) + Vec3::Y;
    if out.y > S::LIMIT {
        let e = Character::new(out, S::ONE);
        assert!(
            matches!(e, Err(Error::OutOfRange { .. })),
            "{}: {e:?}",
            S::NAME
        );
    }
}

/// A time step too long for the range (twice `sqrt(LIMIT / g)`: in `I16F16` 41 s, so a time
/// step in milliseconds) is refused as the time step, with the longest that fits (about 20.4 s
/// in `I16F16`), not blamed on the radius or on a move the caller never made; a jump with a NaN or negative
/// speed, or from a velocity out of range, is refused and changes nothing; a ball too small to
/// move where it stands is refused at construction.
fn mistaken_frames_and_jumps_name_their_argument<S: Tolerance>() {
    let level = floor::<S>();
    let gravity = v::<S>([0.0, -9.81, 0.0]);
    let mut me = Character::new(v::<S>([0.0, 0.6, 0.0]), S::from_f64(0.5)).unwrap();
    let dt = S::from_f64(1.0 / 60.0);
    for _ in 0..30 {
        me.update(&level, Vec3::ZERO, gravity, dt).unwrap();
    }
    assert!(me.is_grounded(), "{}", S::NAME);
    let before = me;
    // At rest the bound is the fall's, sqrt(LIMIT / g); walking at a tenth of LIMIT per second,
    // the time t with (w + g t) t = LIMIT. Twice either is refused with it as the range's end.
    let l = S::LIMIT.to_f64();
    let w = 0.1 * l;
    let walking = (-w + (w * w + 4.0 * 9.81 * l).sqrt()) / (2.0 * 9.81);
    let wish = Vec3::new(S::from_f64(w), S::ZERO, S::ZERO);
    for (wish, longest) in [(Vec3::ZERO, (l / 9.81).sqrt()), (wish, walking)] {
        let e = me.update(&level, wish, gravity, S::from_f64(2.0 * longest));
        match e {
            Err(Error::OutOfRange {
                input: Input::TimeStep,
                max,
                ..
            }) => assert!((max / longest - 1.0).abs() < 1e-3, "{}: {max}", S::NAME),
            other => panic!("{}: {other:?}", S::NAME),
        }
        assert_eq!(me, before, "{}", S::NAME);
    }
    for bad in [f64::NAN, -1.0] {
        let speed = S::from_f64(bad);
        if speed.to_f64().is_nan() == bad.is_nan() {
            let e = me.jump(speed).map_err(|e| e.input());
            assert_eq!(e, Err(Some(Input::JumpSpeed)), "{}: {bad}", S::NAME);
            assert_eq!(me, before, "{}", S::NAME);
        }
    }
    // A velocity already past the range's end is refused; one at its end along `up` is set to
    // the jump's speed (set, not added: nothing to overflow).
    me.velocity = v::<S>([0.0, 2.0 * S::LIMIT.to_f64(), 0.0]);
    let held = me;
    let e = me.jump(S::from_f64(4.0)).map_err(|e| e.input());
    assert_eq!(e, Err(Some(Input::Velocity)), "{}", S::NAME);
    assert_eq!(me, held, "{}", S::NAME);
    me.velocity = v::<S>([1.0, S::LIMIT.to_f64(), 0.0]);
    assert_eq!(me.jump(S::from_f64(4.0)), Ok(true), "{}", S::NAME);
    assert_eq!(me.velocity, v::<S>([1.0, 4.0, 0.0]), "{}", S::NAME);
    let tiny = ballcast::slide::min_radius(S::ZERO).to_f64() / 2.0;
    let e = Character::new(v::<S>([0.0; 3]), S::from_f64(tiny));
    assert!(
        matches!(e, Err(Error::RadiusTooSmall { .. })),
        "{}: {e:?}",
        S::NAME
    );
    // Where floats round coarser, a radius fine at the origin is too small far out: the
    // check is made where the ball stands (fixed point rounds alike everywhere).
    let far = v::<S>([0.5 * S::LIMIT.to_f64(), 0.0, 0.0]);
    let (near_min, far_min) = (
        ballcast::slide::min_radius(S::ZERO),
        ballcast::slide::min_radius(far.x),
    );
    if far_min > near_min + near_min {
        let r = near_min + near_min;
        assert!(Character::new(v::<S>([0.0; 3]), r).is_ok(), "{}", S::NAME);
        let e = Character::new(far, r);
        let extent = far.x.to_f64();
        assert!(
            matches!(e, Err(Error::RadiusTooSmall { extent: x, .. }) if x == extent),
            "{}: {e:?}",
            S::NAME
        );
    }
}

/// A ball standing still jumps (4 units/s up) wishing 3 units/s along x. Without air control
/// it lands where it jumped (the wish steers only on the floor); with an air control of
/// 20 units/s² its speed along x grows by a third of a unit/s a frame (at 60 Hz) up to the wish
/// and no further, its rise is the same frame for frame (the control acts across `up` only),
/// and it lands well ahead. A negative or NaN air control is refused.
fn air_control_steers_a_jump_up_to_the_wish<S: Tolerance>() {
    let level = floor::<S>();
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
    let wish = v::<S>([3.0, 0.0, 0.0]);
    let settled = || {
        let mut me = Character::new(v::<S>([0.0, 0.6, 0.0]), S::from_f64(0.5)).unwrap();
        for _ in 0..30 {
            me.update(&level, Vec3::ZERO, gravity, dt).unwrap();
        }
        assert!(me.is_grounded(), "{}", S::NAME);
        me
    };
    let jump = |mut me: Character<S>| {
        assert!(me.jump(S::from_f64(4.0)).unwrap(), "{}", S::NAME);
        let mut frames = Vec::new();
        for _ in 0..120 {
            me.update(&level, wish, gravity, dt).unwrap();
            frames.push((me.position, me.velocity, me.is_grounded()));
            if me.is_grounded() {
                break;
            }
        }
        frames
    };
    let plain = jump(settled());
    let steered = jump(settled().with_air_control(S::from_f64(20.0)).unwrap());
    let landed = |f: &[(Vec3<S>, Vec3<S>, bool)]| f.last().map(|l| (l.0.x.to_f64(), l.2));
    let (x0, down0) = landed(&plain).unwrap();
    let (x1, down1) = landed(&steered).unwrap();
    assert!(down0 && down1, "{}: never landed", S::NAME);
    assert!(
        x0.abs() < 1e-3,
        "{}: drifted to {x0} without air control",
        S::NAME
    );
    assert!(x1 > 1.0, "{}: only {x1} ahead with air control", S::NAME);
    let step = 20.0 / 60.0;
    let tol = S::EPSILON.to_f64() * 64.0 + 1e-6;
    for (k, ((p0, _, air), (p1, v1, _))) in plain.iter().zip(&steered).enumerate() {
        if *air {
            break;
        }
        let vx = v1.x.to_f64();
        let want = (step * (k + 1) as f64).min(3.0);
        assert!(
            (vx - want).abs() < tol,
            "{}: frame {k}: {vx} not {want}",
            S::NAME
        );
        let (y0, y1) = (p0.y.to_f64(), p1.y.to_f64());
        assert!(
            (y0 - y1).abs() < tol,
            "{}: frame {k}: rose {y1}, not {y0}",
            S::NAME
        );
    }
    for bad in [-1.0, f64::NAN] {
        let a = S::from_f64(bad);
        let e = settled().with_air_control(a).map_err(|e| e.input());
        assert_eq!(e, Err(Some(Input::AirControl)), "{}: {bad}", S::NAME);
    }
}

/// Walking across two floors side by side (x below 0: triangles 0 and 1; above: 2 and 3), the
/// floor it stands on names its triangle, on the side it stands, and its position is the ball's.
fn the_floor_names_its_triangle<S: Tolerance>() {
    let mut level: Scene<S, 4> = Scene::new();
    for x in [-20.0, 0.0] {
        for t in quad([x, 0.0, -20.0], [0.0, 0.0, 40.0], [20.0, 0.0, 0.0]) {
            level
                .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
    }
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 60.0));
    let mut me = Character::new(v::<S>([-3.0, 0.6, 0.0]), S::from_f64(0.5)).unwrap();
    let walk = v::<S>([2.0, 0.0, 0.0]);
    let mut sides = [0, 0];
    for frame in 0..180 {
        me.update(&level, walk, gravity, dt).unwrap();
        let Some(f) = me.floor() else {
            assert!(frame < 10, "{}: off the floor at frame {frame}", S::NAME);
            continue;
        };
        assert_eq!(Some(f.normal), me.floor_normal(), "{}", S::NAME);
        assert_eq!(f.position, me.position, "{}", S::NAME);
        let x = me.position.x.to_f64();
        if x.abs() > 0.5 {
            let side = (x > 0.0) as usize;
            assert_eq!(
                f.index / 2,
                side,
                "{}: at x {x}, on triangle {}",
                S::NAME,
                f.index
            );
            sides[side] += 1;
        }
    }
    assert!(sides[0] > 60 && sides[1] > 60, "{}: {sides:?}", S::NAME);
}

/// Standing on slopes of 5° to 40° at 960 frames a second, wishing for nothing or pushing
/// into the slope (a wish that rejects to nothing along it), and in steep valleys of 60° and
/// 80° at 240 and 960 Hz: after a second the ball stays grounded and does not move for 2 s. In `I16F16` the press into the floor, `g dt²` along the floor's normal,
/// rounded to a step straight down and walked the ball down the slope (0.004 in 3 s on 5°,
/// 0.015 on 20°, up to 0.075 in 2 s in a valley); a wish into the slope, which left a
/// rounding's worth of velocity along it, kept that press.
fn standing_on_a_slope_at_960_hz_does_not_creep<S: Tolerance>() {
    let gravity = v::<S>([0.0, -9.81, 0.0]);
    // What, the level, where the ball starts, its wish, frames a second.
    type Case<S> = (String, Scene<S, 8>, [f64; 3], [f64; 3], f64);
    let mut cases: Vec<Case<S>> = Vec::new();
    for degrees in [5.0f64, 20.0, 40.0] {
        let t = degrees.to_radians();
        let n = [t.sin(), t.cos(), 0.0];
        for wish in [[0.0; 3], common::scale(n, -2.0)] {
            let what = format!("{degrees}° slope, wish {wish:?}");
            cases.push((
                what,
                common::slope::<S>(n),
                common::scale(n, 0.6),
                wish,
                960.0,
            ));
        }
    }
    for (steep, hz) in [(60.0, 240.0), (60.0, 960.0), (80.0, 960.0)] {
        let what = format!("{steep}° valley at {hz} Hz");
        cases.push((
            what,
            common::valley::<S>(steep, 0.0),
            [0.3, 3.0, 0.0],
            [0.0; 3],
            hz,
        ));
    }
    for (what, scene, start, wish, hz) in cases {
        let dt = S::from_f64(1.0 / hz);
        let mut me = Character::new(v(start), S::from_f64(0.5)).unwrap();
        let mut settled = None;
        for frame in 0..(3.0 * hz) as usize {
            me.update(&scene, v(wish), gravity, dt).unwrap();
            if frame as f64 >= hz {
                let what = format!("{}: {what}, frame {frame}", S::NAME);
                assert!(me.is_grounded(), "{what}: in the air");
                let at = *settled.get_or_insert(me.position);
                // Not a step of `I16F16` (a float's wish into the slope leaves it ~1e-20 to walk).
                let moved = common::norm(common::sub(common::back(me.position), common::back(at)));
                assert!(moved < 1e-9, "{what}: moved {moved:e}");
            }
        }
    }
}

/// A slope limit is the cosine of the steepest floor, in `[0, 1]`: a negative one (which would
/// take ceilings for floors, and refuse to walk along them a frame later, naming the floor's
/// facing, which the caller never gave) is refused where it is given, by the character, the
/// slider and a slide's floor.
fn a_negative_slope_cosine_is_refused_where_given<S: Tolerance>() {
    let me = Character::new(v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5)).unwrap();
    let minus = S::from_f64(-0.9);
    let refused = |e: Result<(), Error>| {
        matches!(
            e,
            Err(Error::OutOfRange {
                input: Input::MaxSlope,
                min: 0.0,
                max: 1.0,
                ..
            })
        )
    };
    assert!(
        refused(me.with_slope(Vec3::Y, minus).map(|_| ())),
        "{}",
        S::NAME
    );
    let ball = ballcast::slide::Slider::new(S::from_f64(0.5)).unwrap();
    assert!(
        refused(ball.with_max_slope(Vec3::Y, minus).map(|_| ())),
        "{}",
        S::NAME
    );
    let out = ball.slide(&floor::<S>(), v([0.0, 0.6, 0.0]), v([0.0, -0.2, 0.0]));
    let out = out.unwrap();
    assert!(
        refused(out.floor(Vec3::Y, minus).map(|_| ())),
        "{}",
        S::NAME
    );
    assert!(
        out.floor(Vec3::Y, S::ZERO).unwrap().is_some(),
        "{}",
        S::NAME
    );
}

/// With the slope limit at upright (cosine zero), a wall leaning out over the ball by a tie
/// window (its normal's cosine with up just below zero, within the rounding the limit allows
/// for at other limits) is a wall, as any face facing down: a character thrown against it is
/// not grounded on it and every update goes through. (The allowance once took the limit below zero: grounded on the wall in every
/// scalar, at the third frame.)
fn an_upright_slope_limit_takes_no_wall_leaning_out_for_floor<S: Tolerance>() {
    let lean = 4.0 * 4.0 * S::EPSILON.to_f64(); // a tie window over the wall's height of 4
    let mut s: Scene<S, 2> = Scene::new();
    // At x = 1, facing -x, its top leaning out over the ball by `lean`.
    let (lo, hi) = ([1.0, -2.0], [1.0 - lean, 2.0]);
    let wall = [
        [lo[0], lo[1], -20.0],
        [hi[0], hi[1], -20.0],
        [hi[0], hi[1], 20.0],
        [lo[0], lo[1], 20.0],
    ];
    for t in [[wall[0], wall[2], wall[1]], [wall[0], wall[3], wall[2]]] {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    let n = Triangle::new(v::<S>(wall[0]), v(wall[2]), v(wall[1]));
    let facing = ballcast::StandardTriangle::new(&n)
        .unwrap()
        .normal()
        .y
        .to_f64();
    assert!(facing < 0.0 && facing > -lean, "{}: {facing:e}", S::NAME);
    let mut me = Character::new(v::<S>([0.4, 1.0, 0.0]), S::from_f64(0.5))
        .unwrap()
        .with_slope(Vec3::Y, S::ZERO)
        .unwrap();
    // Thrown at the wall.
    me.velocity = v([2.0, 0.0, 0.0]);
    let (wish, gravity, dt) = (
        v([1.0, 0.0, 0.0]),
        v([0.0, -1.0, 0.0]),
        S::from_f64(1.0 / 64.0),
    );
    for frame in 0..64 {
        let step = me.update(&s, wish, gravity, dt);
        assert!(step.is_ok(), "{} frame {frame}: {step:?}", S::NAME);
        assert!(
            !me.is_grounded(),
            "{} frame {frame}: grounded on the wall",
            S::NAME
        );
    }
}

/// A character rebuilt from what a game saves of it (its settings, `position`, `velocity`
/// and `floor`, put back with `set_floor`) walks on bit for bit as the original, on the floor
/// (saved on the floor, before and after a jump); rebuilt without its floor it starts in the
/// air, and most such copies go another way. A floor facing down is refused and changes
/// nothing.
fn a_character_rebuilt_from_its_state_walks_on_as_the_original<S: Tolerance>() {
    let mut s: Scene<S, 4> = Scene::new();
    for t in quad([-20.0, 0.0, -20.0], [0.0, 0.0, 40.0], [40.0, 0.0, 0.0]) {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    // A ramp up along +x from x = 2.
    for t in quad([2.0, 0.0, -20.0], [0.0, 0.0, 40.0], [20.0, 6.0, 0.0]) {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    let settings = |p: Vec3<S>| {
        Character::new(p, S::from_f64(0.5))
            .unwrap()
            .with_step(S::from_f64(0.2))
            .unwrap()
    };
    let (wish, gravity, dt) = (
        v([2.0, 0.0, 0.5]),
        v([0.0, -9.75, 0.0]),
        S::from_f64(1.0 / 64.0),
    );
    let mut me = settings(v([0.0, 1.0, 0.0]));
    let bits = |c: &Character<S>| format!("{:?} {:?} {:?}", c.position, c.velocity, c.floor());
    // Save points at which the copy rebuilt without its floor went another way.
    let mut bare_differed = 0;
    for frame in 0..160 {
        if frame % 40 == 20 {
            // Saved and rebuilt: with its floor, and without.
            let (saved_floor, grounded) = (me.floor(), me.is_grounded());
            let mut back = settings(me.position);
            back.velocity = me.velocity;
            back.set_floor(saved_floor).unwrap();
            let mut bare = back;
            bare.leave_floor();
            let (mut a, mut b, mut c) = (me, back, bare);
            let mut differed = false;
            for _ in 0..30 {
                for x in [&mut a, &mut b, &mut c] {
                    x.update(&s, wish, gravity, dt).unwrap();
                }
                assert_eq!(bits(&b), bits(&a), "{} frame {frame}", S::NAME);
                differed |= bits(&c) != bits(&a);
            }
            bare_differed += (grounded && differed) as usize;
        }
        me.update(&s, wish, gravity, dt).unwrap();
        if frame == 100 {
            assert!(me.jump(S::from_f64(3.0)).unwrap(), "{}", S::NAME);
        }
    }
    // On the ramp, at least (the copies of frames 100 and 140; on the flat, one of two).
    assert!(bare_differed >= 2, "{}: {bare_differed}", S::NAME);
    let mut other = me;
    let floor = ballcast::slide::Floor {
        normal: v([0.0, -1.0, 0.0]),
        position: me.position,
        index: 0,
        contact: ballcast::Contact::Face,
    };
    let e = other.set_floor(Some(floor)).unwrap_err();
    assert_eq!(e.input(), Some(Input::FloorFacing), "{}", S::NAME);
    assert_eq!(bits(&other), bits(&me), "{}", S::NAME);
}

/// A floor put back with a normal that is not a unit vector (the cross product of a slope's
/// edges, (1, 2, 0) for a slope of 1 in 2) walks as the same floor with its unit normal: it
/// walked straight up at twice the wished speed (the walk rejected the wish from the normal
/// as if it were a unit vector).
fn set_floor_with_a_normal_longer_than_one_walks_as_with_its_unit<S: Tolerance>() {
    let mut s: Scene<S, 2> = Scene::new();
    let y = |x: f64| -0.5 * x;
    let (a, b) = ([-20.0, y(-20.0), -20.0], [20.0, y(20.0), 20.0]);
    s.push(Triangle::new(v(a), v([-20.0, y(-20.0), 20.0]), v(b)))
        .unwrap();
    s.push(Triangle::new(v(a), v(b), v([20.0, y(20.0), -20.0])))
        .unwrap();
    let long = v::<S>([1.0, 2.0, 0.0]);
    let unit = long.try_normalize().unwrap();
    let start = v([0.0, 0.5 * 5f64.sqrt() + 0.001, 0.0]);
    let (wish, gravity, dt) = (
        v([-3.0, 0.0, 0.0]),
        v([0.0, -9.81, 0.0]),
        S::from_f64(1.0 / 60.0),
    );
    let walk = |normal: Vec3<S>| {
        let mut me = Character::new(start, S::from_f64(0.5)).unwrap();
        let floor = ballcast::slide::Floor {
            normal,
            position: start,
            index: 0,
            contact: ballcast::Contact::Face,
        };
        me.set_floor(Some(floor)).unwrap();
        assert_eq!(me.floor_normal(), Some(unit), "{}", S::NAME);
        me.update(&s, wish, gravity, dt).unwrap();
        me
    };
    let (by_unit, by_long) = (walk(unit), walk(long));
    assert_eq!(by_long.position, by_unit.position, "{}", S::NAME);
    assert_eq!(by_long.velocity, by_unit.velocity, "{}", S::NAME);
    // Up the slope at the wish's pace along it, not straight up.
    assert!(
        by_long.velocity.x < S::from_f64(-2.0),
        "{}: {:?}",
        S::NAME,
        by_long.velocity
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn jumps_only_from_the_floor() {
            super::jumps_only_from_the_floor::<$t>();
        }
        #[test]
        fn an_update_that_fails_changes_nothing() {
            super::an_update_that_fails_changes_nothing::<$t>();
        }
        #[test]
        fn mistaken_frames_and_jumps_name_their_argument() {
            super::mistaken_frames_and_jumps_name_their_argument::<$t>();
        }
        #[test]
        fn air_control_steers_a_jump_up_to_the_wish() {
            super::air_control_steers_a_jump_up_to_the_wish::<$t>();
        }
        #[test]
        fn the_floor_names_its_triangle() {
            super::the_floor_names_its_triangle::<$t>();
        }
        #[test]
        fn standing_on_a_slope_at_960_hz_does_not_creep() {
            super::standing_on_a_slope_at_960_hz_does_not_creep::<$t>();
        }
        #[test]
        fn bad_settings_are_errors() {
            super::bad_settings_are_errors::<$t>();
        }
        #[test]
        fn a_character_rebuilt_from_its_state_walks_on_as_the_original() {
            super::a_character_rebuilt_from_its_state_walks_on_as_the_original::<$t>();
        }
        #[test]
        fn set_floor_with_a_normal_longer_than_one_walks_as_with_its_unit() {
            super::set_floor_with_a_normal_longer_than_one_walks_as_with_its_unit::<$t>();
        }
        #[test]
        fn a_negative_slope_cosine_is_refused_where_given() {
            super::a_negative_slope_cosine_is_refused_where_given::<$t>();
        }
        #[test]
        fn an_upright_slope_limit_takes_no_wall_leaning_out_for_floor() {
            super::an_upright_slope_limit_takes_no_wall_leaning_out_for_floor::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
