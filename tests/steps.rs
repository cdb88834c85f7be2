//! Stepping up onto ledges with `Slider::step_slide`, in the README's walking recipe (press into
//! the floor, walk along it, the ground probe when no move touched a floor): ledges lower than
//! the step are climbed, higher ones stop the ball, a ceiling too low for the step stops it, and
//! walks that meet no ledge (along a wall, on a floor) are the plain slide's, bit for bit. Every
//! property in every scalar; expected values worked by hand.

mod common;

use ballcast::{
    Error, Geometry, Scalar, Scene, SceneHit, StandardTriangle, Sweep, Triangle, Vec3,
    slide::Slider,
};
use common::walker::{Gait, HALF, walk};
use common::{P, Tolerance, back, quad, v};
use fixed::types::{I16F16, I32F32};
use std::cell::Cell;

/// The triangles of `quads` (each `o, a, b` as for [`quad`]) in a scene.
fn scene<S: Scalar>(quads: impl IntoIterator<Item = [P; 3]>) -> Scene<S, 8> {
    let mut s = Scene::new();
    for [o, a, b] in quads {
        for t in quad(o, a, b) {
            s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
        }
    }
    s
}

/// A floor at y = 0 up to x = 1, a riser `h` high facing −x, the ledge's floor at y = `h`
/// beyond it, and the quad `extra` (`o, a, b` as for [`quad`]), if any.
fn ledge<S: Scalar>(h: f64, extra: Option<[P; 3]>) -> Scene<S, 8> {
    let quads = [
        [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [10.0, 0.0, 0.0]],
        [[1.0, 0.0, -9.0], [0.0, 0.0, 18.0], [0.0, h, 0.0]],
        [[1.0, h, -9.0], [0.0, 0.0, 18.0], [8.0, 0.0, 0.0]],
    ];
    scene(quads.into_iter().chain(extra))
}

/// A ceiling facing down at height `y` over the whole level.
fn ceiling(y: f64) -> [P; 3] {
    [[-9.0, y, -9.0], [18.0, 0.0, 0.0], [0.0, 0.0, 18.0]]
}

/// A tall wall in the plane z = 1, facing −z.
const SIDE_WALL: [P; 3] = [[-9.0, -9.0, 1.0], [0.0, 18.0, 0.0], [18.0, 0.0, 0.0]];

/// [`walk`] at 2 units/s along +x from (−0.5, 0.6, 0) for 3 s, with steps of `step`.
fn head_on<S: Scalar, G: Geometry<S>>(
    level: &G,
    step: f64,
    each: impl FnMut(Vec3<S>, bool),
) -> Vec3<S> {
    let gait = Gait { step, ..HALF };
    walk(level, [-0.5, 0.6, 0.0], [2.0, 0.0, 0.0], gait, 180, each)
}

/// Walking at 2 units/s onto ledges 0.1–0.25 high with a step of 0.25 (half the radius): after
/// 3 s the ball is on the ledge, resting a skin above it, and it never went below the floors
/// nor into the riser. With the slope limit and no step, the riser of a ledge higher than
/// `r (1 - cos 45°)` = 0.146 stops it: 0.2 and 0.25 are climbed only by stepping. The recipe's
/// floor snap once slid the ball rolling up onto a ledge of 0.1 back down the edge's slope, on
/// every try: it now stops at the edge, which it can stand on.
fn climbs_ledges_lower_than_the_step<S: Tolerance>() {
    for h in [0.1, 0.2, 0.25] {
        let level = ledge::<S>(h, None);
        let end = head_on(&level, 0.25, |p, _| {
            // Clear of the lower floor, of the riser (the segment x = 1, 0 <= y <= h) and,
            // over the ledge, of its floor, all within rounding.
            let [x, y, _] = back(p);
            let riser = ((1.0 - x).powi(2) + (y - y.clamp(0.0, h)).powi(2)).sqrt();
            let clear = if x < 1.0 { riser } else { y - h };
            assert!(
                y >= 0.5 - 1e-3 && clear >= 0.5 - 1e-3,
                "{}: ledge {h}: inside the level at {:?}",
                S::NAME,
                back(p)
            );
        });
        let [x, y, _] = back(end);
        assert!(
            x > 4.0 && (y - (h + 0.5)).abs() < 2e-3,
            "{}: ledge {h}: ended at {:?}",
            S::NAME,
            back(end)
        );
        if h > 0.15 {
            let held = head_on(&level, 0.0, |_, _| {});
            assert!(back(held)[0] < 0.61, "{}: ledge {h}: {held:?}", S::NAME);
        }
    }
}

/// A ledge of 0.3 with a step of 0.25 stops the ball at its riser, grounded on the lower floor
/// (the stepped move lands on the edge at a contact too steep to stand on, and is dropped).
/// So does a ledge of 0.2 under a ceiling 1.1 high: the ball rises only 0.1 below it, less than
/// the ledge.
fn stopped_by_a_ledge_higher_than_the_step_or_under_a_ceiling<S: Tolerance>() {
    for (h, ceiling) in [(0.3, None), (0.2, Some(1.1))] {
        let level = ledge::<S>(h, ceiling.map(self::ceiling));
        let mut grounded = 0;
        let end = head_on(&level, 0.25, |_, g| {
            grounded += g as usize;
        });
        let [x, y, _] = back(end);
        assert!(
            x < 0.61 && (y - 0.5).abs() < 2e-3 && grounded >= 170,
            "{}: ledge {h}, ceiling {ceiling:?}: ended at {:?}, grounded {grounded}",
            S::NAME,
            back(end)
        );
    }
}

/// Where no ledge is met, `step_slide` is `slide`, bit for bit: on a floor, walking along a
/// wall taller than the step (the stepped move comes back down where it started, so it is
/// dropped, though its forward step is longer than the walk), and into it.
fn without_a_ledge_it_is_the_plain_slide<S: Tolerance>() {
    let level = scene::<S>([
        [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [18.0, 0.0, 0.0]],
        [[1.0, 0.0, -9.0], [0.0, 0.0, 18.0], [0.0, 3.0, 0.0]],
    ]);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let step = S::from_f64(0.25);
    for (start, walk) in [
        ([-2.0, 0.5005, 0.0], [0.03, 0.0, 0.02]),
        ([0.4995, 0.5005, 0.0], [0.001, 0.0, 0.03]),
        ([0.4995, 0.5005, 0.0], [0.02, 0.0, 0.0]),
        ([0.3, 0.5005, 0.0], [0.3, 0.0, 0.1]),
    ] {
        let (p, d) = (v::<S>(start), v::<S>(walk));
        let plain = ball.slide(&level, p, d).unwrap();
        let stepped = ball.step_slide(&level, p, d, up, walkable, step).unwrap();
        assert_eq!(plain, stepped, "{}: from {start:?} by {walk:?}", S::NAME);
    }
}

/// Ledges met at a slant (the walk 15°–75° from head-on) are climbed: r 0.5 onto 0.2 and 0.25
/// in the open and onto 0.2 in an inside corner, sliding along a side wall into the riser; and
/// r 0.05 at 240 Hz, walking at 0.1 and 0.2 units/s, onto 0.0188 with a step of 0.0375. The
/// step once carried the ball over the edge along the walk, not into the riser: it landed on
/// the edge's steep part, was dropped, and the ball stayed at the riser for good (0.25 from
/// 15°, 0.2 from 60°). Taken into the first steep contact, the side wall, it went nowhere
/// (from 40°); and `I16F16`'s product of the two short vectors that measured the small ball's
/// progress rounded to zero.
fn climbs_ledges_met_at_a_slant<S: Tolerance>() {
    let small = Gait {
        r: 0.05,
        hz: 240.0,
        step: 0.0375,
        snap: 0.0375,
    };
    let cases = [
        (0.2, None, HALF, 2.0, [-0.5, 0.6, -8.0]),
        (0.25, None, HALF, 2.0, [-0.5, 0.6, -8.0]),
        (0.2, Some(SIDE_WALL), HALF, 2.0, [-0.5, 0.5005, 0.4995]),
        (0.0188, None, small, 0.2, [0.9, 0.06, -8.0]),
        (0.0188, None, small, 0.1, [0.9, 0.06, -8.0]),
    ];
    for (h, wall, gait, speed, start) in cases {
        let level = ledge::<S>(h, wall);
        for degrees in [0.0f64, 15.0, 30.0, 45.0, 60.0, 75.0] {
            let (sin, cos) = degrees.to_radians().sin_cos();
            let wish = [speed * cos, 0.0, speed * sin];
            let end = walk(&level, start, wish, gait, 4 * gait.hz as usize, |_, _| {});
            let [x, y, _] = back(end);
            assert!(
                x > 1.0 && (y - (h + gait.r)).abs() < 0.1 * gait.r,
                "{}: ledge {h}, wall {}, r {}, {speed} units/s at {degrees}°: ended at {:?}",
                S::NAME,
                wall.is_some(),
                gait.r,
                back(end)
            );
        }
    }
}

/// Walking up a 10°–35° slope beside a tall wall, 10° into the wall: every call touches the
/// wall, so every call tries a step, and the step must be dropped (the plain slide, bit for
/// bit). Its forward push was kept, since on the slope the ball landed higher than it
/// started: 2.7 times the walk's travel a call.
fn a_wall_beside_an_up_slope_is_no_ledge<S: Tolerance>() {
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let ball = ball.with_max_slope(up, walkable).unwrap();
    for degrees in [10.0f64, 20.0, 35.0] {
        let t = degrees.to_radians().tan();
        let slope = [
            [-9.0, -9.0 * t, -9.0],
            [0.0, 0.0, 18.0],
            [18.0, 18.0 * t, 0.0],
        ];
        let level = scene::<S>([slope, SIDE_WALL]);
        let n = [-degrees.to_radians().sin(), degrees.to_radians().cos(), 0.0];
        let (sin, cos) = 10f64.to_radians().sin_cos();
        let wish = [2.0 * cos, 0.0, 2.0 * sin];
        let d = common::scale(
            common::sub(wish, common::scale(n, common::dot(wish, n))),
            1.0 / 60.0,
        );
        let p = [0.0, 0.5005 / n[1], 0.4996];
        let plain = ball.slide(&level, v(p), v(d)).unwrap();
        let stepped = ball.step_slide(&level, v(p), v(d), up, walkable, S::from_f64(0.25));
        assert_eq!(Ok(plain), stepped, "{}: {degrees}° slope", S::NAME);
    }
}

/// A geometry that counts the sweeps cast into it.
struct Counted<'a, G>(&'a G, Cell<usize>);

impl<S: Scalar, G: Geometry<S>> Geometry<S> for Counted<'_, G> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.1.set(self.1.get() + 1);
        self.0.cast(sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.0.visit(min, max, f)
    }
}

/// Walls and ledges too high to step onto cost no step: with r 0.5, a step of 0.25 and 45°
/// walkable, a contact touched more than 0.25 + 0.146 above the ball's lowest point is passed
/// over, and the call casts the sweeps `slide` casts and answers as it does. Into a wall 3
/// high, along it, into an inside corner and into a ledge 0.45 high. Before, every such call
/// lifted, carried and lowered the ball and dropped the result: 4.5 sweeps a frame of the
/// recipe into a wall where the slide cast 2, 9.5 in the inside corner.
fn walls_and_high_ledges_cost_no_step<S: Tolerance>() {
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let ball = ball.with_max_slope(up, walkable).unwrap();
    let cases = [
        (3.0, None, [0.4995, 0.5005, 0.0], [0.03, 0.0, 0.0]),
        (3.0, None, [0.4995, 0.5005, 0.0], [0.03, 0.0, 0.02]),
        (
            3.0,
            Some(SIDE_WALL),
            [0.4995, 0.5005, 0.4995],
            [0.03, 0.0, 0.02],
        ),
        (0.45, None, [0.3, 0.5005, 0.0], [0.3, 0.0, 0.0]),
    ];
    for (h, wall, start, walk) in cases {
        let level = ledge::<S>(h, wall);
        let (plain, stepped) = (Counted(&level, Cell::new(0)), Counted(&level, Cell::new(0)));
        let (p, d) = (v::<S>(start), v::<S>(walk));
        let out = ball.slide(&plain, p, d).unwrap();
        let step = ball.step_slide(&stepped, p, d, up, walkable, S::from_f64(0.25));
        let what = format!("{}: ledge {h}, from {start:?} by {walk:?}", S::NAME);
        assert!(
            out.contacts.iter().flatten().count() > 0,
            "{what}: no contact"
        );
        assert_eq!(Ok(out), step, "{what}");
        assert_eq!(plain.1.get(), stepped.1.get(), "{what}: sweeps");
    }
}

/// Walking at 4 units/s up a 4° ramp into a ledge 0.174 high at its top, stepping 0.05: the
/// walk along the ramp rises, and carries the lifted ball higher than the step alone, so it
/// climbs the ledge. Passing over contacts touched higher than the step and the slope limit
/// reach, without the walk's rise, once left the ball at the riser for good, in every scalar.
fn climbs_a_ledge_at_the_top_of_a_ramp<S: Tolerance>() {
    let t = 4f64.to_radians().tan();
    let level = scene::<S>([
        [
            [-9.0, -10.0 * t, -9.0],
            [0.0, 0.0, 18.0],
            [10.0, 10.0 * t, 0.0],
        ],
        [[1.0, 0.0, -9.0], [0.0, 0.0, 18.0], [0.0, 0.174, 0.0]],
        [[1.0, 0.174, -9.0], [0.0, 0.0, 18.0], [8.0, 0.0, 0.0]],
    ]);
    let gait = Gait {
        step: 0.05,
        snap: 0.05,
        ..HALF
    };
    let end = walk(
        &level,
        [-1.5, 0.35, 0.0],
        [4.0, 0.0, 0.0],
        gait,
        90,
        |_, _| {},
    );
    let [x, y, _] = back(end);
    assert!(
        x > 2.0 && (y - (0.174 + 0.5)).abs() < 2e-3,
        "{}: ended at {:?}",
        S::NAME,
        back(end)
    );
}

/// A ball whose own slope limit (60°) is looser than the step's (45°) climbs by itself what
/// the step's limit calls too steep: stopped at a riser 0.29 high (touched where the normal
/// is 0.42 up, a wall to it), lifted by a step of 0.05 it meets the edge at 0.52 up and rolls
/// over it in a move of 0.3. Passing over contacts with the step's limit alone (0.5 × (0.71 −
/// 0.42) = 0.14 above the step's reach) once left it at the riser.
fn a_looser_own_slope_limit_climbs_more<S: Tolerance>() {
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let ball = ball.with_max_slope(up, S::from_f64(0.5)).unwrap();
    let level = ledge::<S>(0.29, None);
    let at = v::<S>([1.0 - (0.29f64 * 0.71).sqrt() - 5e-4, 0.5005, 0.0]);
    let walk = v::<S>([0.3, 0.0, 0.0]);
    let plain = ball.slide(&level, at, walk).unwrap();
    let out = ball.step_slide(&level, at, walk, up, walkable, S::from_f64(0.05));
    let out = out.unwrap();
    let what = format!(
        "{}: {:?} -> {:?}",
        S::NAME,
        back(plain.position),
        back(out.position)
    );
    assert!(
        back(plain.position)[0] < 0.55,
        "{what}: the riser stops the plain walk"
    );
    assert!(
        back(out.position)[1] > 0.6,
        "{what}: not on the ledge's edge"
    );
    assert!(
        out.floor(up, walkable).unwrap().is_some(),
        "{what}: no floor"
    );
}

/// Walking slowly at 480 Hz onto a ledge as high as the step (0.25), head on and at 30° to 60°:
/// climbed. The step lands the ball on the ledge's rounded edge, and the next walks roll it up
/// over the edge. A recipe that snapped every walk rising less than a skin a frame snapped
/// these (the roll rises about 0.35 units/s, under a skin a frame at 480 Hz) down the edge's
/// steep part, back to the lower floor, on every try. Where a walk up the edge left it more
/// than a skin off, the ground probe once slid it back down the edge by what was left of its
/// reach, as far as the walk had rolled it up: `I16F16` balls stayed on the edge at 0.25 and
/// 0.5 units/s, the other scalars at 0.25 units/s at 45°. (At 0.25 units/s and 60°, 0.125
/// towards the ledge, all four are still rolling up the edge after the 4 s.)
fn climbs_the_step_height_slowly_at_high_frame_rates<S: Tolerance>() {
    let level = ledge::<S>(0.25, None);
    let gait = Gait { hz: 480.0, ..HALF };
    for (speed, degrees) in [
        (0.25, 0.0f64),
        (0.25, 30.0),
        (0.25, 45.0),
        (0.5, 0.0),
        (0.5, 60.0),
    ] {
        let (sin, cos) = degrees.to_radians().sin_cos();
        let wish = [speed * cos, 0.0, speed * sin];
        let end = walk(&level, [0.4, 0.5005, 0.0], wish, gait, 1920, |_, _| {});
        let [x, y, _] = back(end);
        assert!(
            x > 1.0 && (y - 0.75).abs() < 0.05,
            "{}: {speed} units/s at {degrees}°: ended at {:?}",
            S::NAME,
            back(end)
        );
    }
}

/// Bad step heights and a zero `up` are errors.
fn bad_steps_are_errors<S: Tolerance>() {
    let level = ledge::<S>(0.2, None);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let (p, d) = (v::<S>([0.0, 0.6, 0.0]), v::<S>([0.1, 0.0, 0.0]));
    let negative = ball.step_slide(&level, p, d, up, walkable, S::from_f64(-0.1));
    assert!(
        matches!(negative, Err(Error::OutOfRange { .. })),
        "{negative:?}"
    );
    let zero_up = ball.step_slide(&level, p, d, Vec3::ZERO, walkable, S::ONE);
    assert_eq!(
        zero_up,
        Err(Error::ZeroVector {
            input: ballcast::Input::Up
        })
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn climbs_ledges_lower_than_the_step() {
            super::climbs_ledges_lower_than_the_step::<$t>();
        }
        #[test]
        fn stopped_by_a_ledge_higher_than_the_step_or_under_a_ceiling() {
            super::stopped_by_a_ledge_higher_than_the_step_or_under_a_ceiling::<$t>();
        }
        #[test]
        fn without_a_ledge_it_is_the_plain_slide() {
            super::without_a_ledge_it_is_the_plain_slide::<$t>();
        }
        #[test]
        fn a_looser_own_slope_limit_climbs_more() {
            super::a_looser_own_slope_limit_climbs_more::<$t>();
        }
        #[test]
        fn climbs_the_step_height_slowly_at_high_frame_rates() {
            super::climbs_the_step_height_slowly_at_high_frame_rates::<$t>();
        }
        #[test]
        fn climbs_ledges_met_at_a_slant() { super::climbs_ledges_met_at_a_slant::<$t>(); }
        #[test]
        fn a_wall_beside_an_up_slope_is_no_ledge() {
            super::a_wall_beside_an_up_slope_is_no_ledge::<$t>();
        }
        #[test]
        fn walls_and_high_ledges_cost_no_step() {
            super::walls_and_high_ledges_cost_no_step::<$t>();
        }
        #[test]
        fn climbs_a_ledge_at_the_top_of_a_ramp() {
            super::climbs_a_ledge_at_the_top_of_a_ramp::<$t>();
        }
        #[test]
        fn bad_steps_are_errors() { super::bad_steps_are_errors::<$t>(); }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
