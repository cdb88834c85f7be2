//! Walking down with `Slider::snap_to_floor` in the README's recipe: a walker that stood on a
//! floor and walked off it (a stair's step down, a crest) is moved down onto the floor within
//! its snap depth, and stays grounded; a deeper drop, or no walk at all, leaves it to fall.
//! Every property in every scalar; expected values worked by hand.

mod common;

use ballcast::slide::{Character, Slider};
use ballcast::{Error, Scalar, Scene, Triangle, Vec3};
use common::walker::{Gait, HALF, walk, with_and_without_snap};
use common::{P, Tolerance, back, quad, v};
use fixed::types::{I16F16, I32F32};

/// The triangles of `quads` (each `o, a, b` as for [`quad`]: front along `a × b`) in a scene.
fn scene<S: Scalar>(quads: &[[P; 3]]) -> Scene<S, 32> {
    let mut s = Scene::new();
    for &[o, a, b] in quads {
        for t in quad(o, a, b) {
            s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
        }
    }
    s
}

/// A floor at y = 0 up to x = 0, then `steps` steps down along +x, each `rise` lower and 1
/// long, and the last floor out to x = 12.
fn stairs<S: Scalar>(steps: usize, rise: f64) -> Scene<S, 32> {
    flight(steps, rise, 1.0)
}

/// [`stairs`] with treads `tread` long.
fn flight<S: Scalar>(steps: usize, rise: f64, tread: f64) -> Scene<S, 32> {
    let (z, across) = ([0.0, 0.0, 18.0], -9.0);
    let mut quads = vec![[[-9.0, 0.0, across], z, [9.0, 0.0, 0.0]]];
    for k in 1..=steps {
        let (x, y) = ((k - 1) as f64 * tread, -rise * k as f64);
        let long = if k == steps { 12.0 - x } else { tread };
        quads.push([[x, y, across], [0.0, rise, 0.0], z]); // the riser, facing +x
        quads.push([[x, y, across], z, [long, 0.0, 0.0]]);
    }
    scene(&quads)
}

/// Walking at 2 units/s down four steps of 0.2 (r 0.5): with a snap of 0.25 the ball is
/// grounded on every frame, and ends on the bottom floor a skin above it, never inside the
/// level. Without the snap (the ground probe alone) it falls from each step's edge onto the
/// next: grounded on 136 of the 180 frames, in every scalar.
fn walking_down_stairs_stays_grounded<S: Tolerance>() {
    let level = stairs::<S>(4, 0.2);
    for (snap, least) in [(0.25, 180), (0.0, 0)] {
        let gait = Gait { snap, ..HALF };
        let mut grounded = 0;
        let end = walk(
            &level,
            [-0.5, 0.5005, 0.0],
            [2.0, 0.0, 0.0],
            gait,
            180,
            |p, g| {
                let [x, y, _] = back(p);
                // Above the floor under the centre, and clear of the edge of the step before it.
                let k = x.ceil().clamp(0.0, 4.0);
                let (floor, edge) = (-0.2 * k, [k - 1.0, -0.2 * (k - 1.0)]);
                let to_edge = ((x - edge[0]).powi(2) + (y - edge[1]).powi(2)).sqrt();
                let at = back(p);
                assert!(
                    y - floor >= 0.5 - 1e-3 && (k == 0.0 || to_edge >= 0.5 - 1e-3),
                    "{}: snap {snap}: inside the stairs at {at:?}",
                    S::NAME
                );
                grounded += g as usize;
            },
        );
        let [x, y, _] = back(end);
        assert!(
            x > 5.0 && (y - (0.5 - 0.8)).abs() < 2e-3 && grounded >= least,
            "{}: snap {snap}: ended at {:?}, grounded on {grounded} of 180 frames",
            S::NAME,
            back(end)
        );
        if snap == 0.0 {
            assert!(
                grounded < 170,
                "{}: grounded {grounded} without the snap",
                S::NAME
            );
        }
    }
}

/// A drop of 0.6, deeper than the snap of 0.25: the ball walks off the edge and falls (in the
/// air on 20 frames, in every scalar), then walks on, grounded, on the floor below.
fn a_drop_deeper_than_the_snap_is_a_fall<S: Tolerance>() {
    let level = stairs::<S>(1, 0.6);
    let mut airborne = 0;
    let end = walk(
        &level,
        [-0.5, 0.5005, 0.0],
        [2.0, 0.0, 0.0],
        HALF,
        120,
        |_, g| {
            airborne += !g as usize;
        },
    );
    let [x, y, _] = back(end);
    assert!(
        (10..40).contains(&airborne) && x > 3.0 && (y + 0.1).abs() < 2e-3,
        "{}: in the air on {airborne} frames, ended at {:?}",
        S::NAME,
        back(end)
    );
}

/// Walking at 4 units/s from a floor over a crest onto a 30° slope falling away: the walk
/// along the floor's plane carries the ball off the slope each frame, and the snap keeps it
/// on it, grounded on every frame; without the snap it was grounded on 95 of the 120.
fn over_a_crest_onto_a_downhill_slope<S: Tolerance>() {
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let level = scene::<S>(&[
        [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [9.0, 0.0, 0.0]],
        [
            [0.0, 0.0, -9.0],
            [0.0, 0.0, 18.0],
            [9.0 * cos, -9.0 * sin, 0.0],
        ],
    ]);
    for (snap, least) in [(0.25, 120), (0.0, 0)] {
        let gait = Gait { snap, ..HALF };
        let mut grounded = 0;
        walk(
            &level,
            [-0.5, 0.5005, 0.0],
            [4.0, 0.0, 0.0],
            gait,
            120,
            |_, g| {
                grounded += g as usize;
            },
        );
        assert!(
            grounded >= least,
            "{}: snap {snap}: grounded {grounded}",
            S::NAME
        );
        if snap == 0.0 {
            assert!(
                grounded < 115,
                "{}: grounded {grounded} without the snap",
                S::NAME
            );
        }
    }
}

/// Walking from a floor over a crest onto slopes of 20° to 44° falling away, at 4 and 8
/// units/s and 60 to 480 frames a second: grounded on every frame. The recipe once snapped only
/// a ball not moving up at all, and the floor a ball is pressed onto at the crest's edge, touched
/// a hair behind it (within the tie of the face), tilts back: the next walk rose (by 10^-6 of
/// its speed in f32, 10^-3 in I16F16), the snap was not asked, and the ball flew off the crest
/// (in every scalar, on up to 454 frames of 576; f32 at 240 Hz and 8 units/s on 30°: 223).
fn over_crests_at_every_frame_rate<S: Tolerance>() {
    for degrees in [20.0f64, 30.0, 36.0, 40.0, 44.0] {
        let (sin, cos) = degrees.to_radians().sin_cos();
        let level = scene::<S>(&[
            [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [9.0, 0.0, 0.0]],
            [
                [0.0, 0.0, -9.0],
                [0.0, 0.0, 18.0],
                [9.0 * cos, -9.0 * sin, 0.0],
            ],
        ]);
        for hz in [60.0, 144.0, 240.0, 480.0] {
            for speed in [4.0, 8.0] {
                let gait = Gait { hz, ..HALF };
                let mut airborne = 0;
                let frames = (1.2 * hz) as usize;
                walk(
                    &level,
                    [-2.0, 0.5005, 0.0],
                    [speed, 0.0, 0.0],
                    gait,
                    frames,
                    |_, g| airborne += !g as usize,
                );
                assert_eq!(
                    airborne,
                    0,
                    "{}: {degrees}°, {hz} Hz, {speed} units/s: in the air on frames of {frames}",
                    S::NAME
                );
            }
        }
    }
}

/// Where the ball walks off an edge with nothing within the snap's reach below (a cliff 3
/// deep, a trench 1.2 wide over a pit 5 deep, the lip of a 30° ramp up over a drop), the walk
/// with the snap is the walk without it, bit for bit, at 2 and 8 units/s, at 60 and 144 Hz, up
/// to where it lands again (beyond the trench, it is snapped onto the far floor as it rolls up
/// over its edge, where the plain walk hops). Taking the rounded edge it was leaving for a
/// floor, the snap once held a ball at 8 units/s onto the cliff's edge (it landed 0.6 short)
/// and rolled one into the trench it would have flown over; and taking the lip it was rolling
/// over for a floor, it launched no ball off the ramp.
fn leaving_an_edge_over_a_drop_is_a_fall<S: Tolerance>() {
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let top = [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [9.0, 0.0, 0.0]];
    let wall =
        |x: f64, low: f64, high: f64| [[x, low, -9.0], [0.0, high - low, 0.0], [0.0, 0.0, 18.0]];
    let floor = |x0: f64, x1: f64, y: f64| [[x0, y, -9.0], [0.0, 0.0, 18.0], [x1 - x0, 0.0, 0.0]];
    let ramp = [
        [0.0, 0.0, -9.0],
        [0.0, 0.0, 18.0],
        [2.0 * cos, 2.0 * sin, 0.0],
    ];
    let levels = [
        (
            "cliff",
            vec![top, wall(0.0, -3.0, 0.0), floor(0.0, 40.0, -3.0)],
        ),
        ("trench", {
            let far = [[1.2, -5.0, 9.0], [0.0, 5.0, 0.0], [0.0, 0.0, -18.0]];
            vec![
                top,
                wall(0.0, -5.0, 0.0),
                floor(0.0, 1.2, -5.0),
                far,
                floor(1.2, 40.0, 0.0),
            ]
        }),
        (
            "ramp",
            vec![
                top,
                ramp,
                wall(2.0 * cos, -3.0, 2.0 * sin),
                floor(2.0 * cos, 40.0, -3.0),
            ],
        ),
    ];
    for (name, quads) in levels {
        let level = scene::<S>(&quads);
        for (speed, hz) in [(2.0, 60.0), (8.0, 60.0), (8.0, 144.0)] {
            let frames = (3.0 * hz) as usize;
            let (start, wish, gait) = ([-1.0, 0.5005, 0.0], [speed, 0.0, 0.0], Gait { hz, ..HALF });
            let paths = with_and_without_snap(&level, start, wish, gait, frames);
            let what = format!("{}: {name} at {speed} units/s, {hz} Hz", S::NAME);
            let [snapped, plain] = paths.unwrap_or_else(|| panic!("{what}: never left the floor"));
            assert_eq!(snapped, plain, "{what}: with the snap, and without");
        }
    }
}

/// Walking off a cliff 2 deep (r 0.5, the default snap) at 1 and 4 units/s square to its edge
/// and at 20 units/s 80° from square (3.5 across it), at 60, 240 and 960 Hz: the ball lands as
/// far out at every rate (within 0.15). Across the edge faster than gravity can hold it round
/// the edge (`v² > g r`), it flies off level at once; at 1 unit/s it rolls round the edge to
/// the slope limit first. Held by the ground probe two skins below whenever a frame's fall from
/// the edge's tangent was shorter than that, a ball at 4 units/s rolled round the edge at 960
/// Hz (not at 60 or 240), left it at the slope limit with half its speed and landed at 1.25
/// instead of 2.6.
fn walking_off_a_cliff_lands_as_far_at_every_frame_rate<S: Tolerance>() {
    let level = scene::<S>(&[
        [[-9.0, 0.0, -30.0], [0.0, 0.0, 60.0], [9.0, 0.0, 0.0]],
        [[0.0, -2.0, -30.0], [0.0, 2.0, 0.0], [0.0, 0.0, 60.0]],
        [[0.0, -2.0, -30.0], [0.0, 0.0, 60.0], [40.0, 0.0, 0.0]],
    ]);
    for (speed, degrees, from) in [(1.0, 0.0, -2.0), (4.0, 0.0, -2.0), (20.0, 80.0, -1.0)] {
        let (sin, cos) = f64::to_radians(degrees).sin_cos();
        let landed = [60.0, 240.0, 960.0].map(|hz| {
            let mut at = None;
            let gait = Gait { hz, ..HALF };
            let (start, wish) = ([from, 0.5005, -20.0], [speed * cos, 0.0, speed * sin]);
            walk(&level, start, wish, gait, (4.0 * hz) as usize, |p, on| {
                let [x, y, _] = back(p);
                if on && y < -1.0 {
                    at = at.or(Some(x));
                }
            });
            let what = format!("{} at {speed} units/s, {degrees}°, {hz} Hz", S::NAME);
            at.unwrap_or_else(|| panic!("{what}: never landed"))
        });
        let spread = landed
            .iter()
            .fold(0.0f64, |m, a| m.max((a - landed[0]).abs()));
        assert!(
            spread < 0.15,
            "{} at {speed} units/s, {degrees}°: landed at {landed:?} (60, 240, 960 Hz)",
            S::NAME
        );
    }
}

/// The snap finds at least what the ground probe finds: balls resting a skin above the rounded
/// edge of a cliff 3 deep (centres 0 to 0.35 past it, r 0.5), walking off it. With a look-ahead
/// that gave up over the drop, the snap once found nothing where the probe found the edge, in
/// every scalar.
fn the_snap_finds_what_the_probe_finds<S: Tolerance>() {
    let level = scene::<S>(&[
        [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [9.0, 0.0, 0.0]],
        [[0.0, -3.0, -9.0], [0.0, 3.0, 0.0], [0.0, 0.0, 18.0]],
    ]);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let (heading, depth) = (v::<S>([2.0, 0.0, 0.0]), S::from_f64(0.25));
    let mut found = 0;
    for k in 0..36 {
        let x = 0.01 * k as f64;
        let p = v::<S>([x, (0.25 - x * x).sqrt() + 0.0005, 0.0]);
        let probe = ball.probe_floor(&level, p, up, walkable).unwrap();
        let snap = ball
            .snap_to_floor(&level, p, heading, up, walkable, depth)
            .unwrap();
        found += probe.is_some() as usize;
        assert!(
            probe.is_none() || snap.is_some(),
            "{}: centre {x} past the edge: the probe found {probe:?}, the snap nothing",
            S::NAME
        );
    }
    assert!(
        found > 20,
        "{}: the probe found the edge {found} times",
        S::NAME
    );
}

/// Walking at 2 units/s down six steps of 0.2 with `Character` (a snap of 0.25) at 60 to 960
/// Hz: never faster than wished, and as fast at every rate within 1 % (5.77 to 5.79 of the 6
/// units in 3 s, in every scalar: rolling over each step's edge, the walk follows the edge's
/// tilted plane). Rolling over an edge, the ball is snapped back onto it every frame, and the
/// snap's slide took the edge it was walking off for no floor and rolled on around it by what
/// was left of its reach, two skins a frame: at 960 Hz `f64` made 6.10 and `I16F16` 6.54. An
/// edge within the slope limit now holds the snap's slide as a face does. At 60 Hz, held on the
/// edge by the press every other frame (`walking_down_stairs_every_scalar_goes_as_far_as_f64`),
/// it made 5.63.
fn walking_down_stairs_keeps_the_wished_pace<S: Tolerance>() {
    let level = stairs::<S>(6, 0.2);
    let made = [60, 240, 960].map(|hz| {
        let (r, dt) = (S::from_f64(0.5), S::from_f64(1.0 / hz as f64));
        let (gravity, wish) = (v::<S>([0.0, -9.81, 0.0]), v::<S>([2.0, 0.0, 0.0]));
        let mut me = Character::new(v::<S>([-0.5, 0.5005, 0.0]), r).unwrap();
        for _ in 0..3 * hz {
            me.update(&level, wish, gravity, dt).unwrap();
        }
        me.position.x.to_f64() + 0.5
    });
    let (lo, hi) = made
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), &m| (l.min(m), h.max(m)));
    assert!(
        made.iter().all(|m| (5.5..=6.0).contains(m)) && hi - lo < 0.06,
        "{}: made {made:?} of 6 at 60, 240 and 960 Hz",
        S::NAME
    );
}

/// Walking down four steps of 0.15 on treads of 0.4 (r 0.4, stepping and snapping 0.2) at 2 to
/// 8 units/s and 60 to 960 Hz, `f32` and `I16F16` go as far as `f64` within 0.5 %. Rolling
/// over each edge, the ball was held by the press's edge every other frame in `f64` and
/// snapped every frame in `I16F16`, so it left the edge a frame later or sooner: `I16F16` made
/// 0.991 of `f64`'s distance at 144 Hz and 5 units/s, 0.992 at 480 Hz and 8 units/s (0.968 with
/// the walk begun half a unit before the edge instead of one).
#[test]
fn walking_down_stairs_every_scalar_goes_as_far_as_f64() {
    fn made<S: Scalar>(hz: f64, speed: f64) -> f64 {
        let level = flight::<S>(4, 0.15, 0.4);
        let gait = Gait {
            r: 0.4,
            hz,
            step: 0.2,
            snap: 0.2,
        };
        let end = walk(
            &level,
            [-1.0, 0.4004, 0.0],
            [speed, 0.0, 0.0],
            gait,
            (0.9 * hz) as usize,
            |_, _| (),
        );
        back(end)[0] + 1.0
    }
    for (hz, speed) in [
        (60.0, 2.0),
        (120.0, 2.0),
        (144.0, 5.0),
        (480.0, 8.0),
        (960.0, 5.0),
    ] {
        let exact = made::<f64>(hz, speed);
        for (name, other) in [
            ("f32", made::<f32>(hz, speed)),
            ("I16F16", made::<I16F16>(hz, speed)),
        ] {
            assert!(
                (other / exact - 1.0).abs() < 0.005,
                "{speed} units/s at {hz} Hz: {name} made {other}, f64 {exact}"
            );
        }
    }
}

/// Bad snap depths are errors, and a zero one is the ground probe.
fn bad_snaps_are_errors<S: Tolerance>() {
    let level = stairs::<S>(1, 0.2);
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let p = v::<S>([-1.0, 0.5005, 0.0]);
    let negative = ball.snap_to_floor(&level, p, Vec3::ZERO, up, walkable, S::from_f64(-0.1));
    assert!(
        matches!(negative, Err(Error::OutOfRange { .. })),
        "{negative:?}"
    );
    let zero_up = ball.snap_to_floor(&level, p, Vec3::ZERO, Vec3::ZERO, walkable, S::ONE);
    assert_eq!(
        zero_up,
        Err(Error::ZeroVector {
            input: ballcast::Input::Up
        })
    );
    let probe = ball.probe_floor(&level, p, up, walkable);
    assert_eq!(
        ball.snap_to_floor(&level, p, Vec3::ZERO, up, walkable, S::ZERO),
        probe
    );
    assert!(probe.unwrap().is_some());
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn walking_down_stairs_stays_grounded() {
            super::walking_down_stairs_stays_grounded::<$t>();
        }
        #[test]
        fn a_drop_deeper_than_the_snap_is_a_fall() {
            super::a_drop_deeper_than_the_snap_is_a_fall::<$t>();
        }
        #[test]
        fn over_a_crest_onto_a_downhill_slope() {
            super::over_a_crest_onto_a_downhill_slope::<$t>();
        }
        #[test]
        fn over_crests_at_every_frame_rate() {
            super::over_crests_at_every_frame_rate::<$t>();
        }
        #[test]
        fn leaving_an_edge_over_a_drop_is_a_fall() {
            super::leaving_an_edge_over_a_drop_is_a_fall::<$t>();
        }
        #[test]
        fn walking_off_a_cliff_lands_as_far_at_every_frame_rate() {
            super::walking_off_a_cliff_lands_as_far_at_every_frame_rate::<$t>();
        }
        #[test]
        fn the_snap_finds_what_the_probe_finds() {
            super::the_snap_finds_what_the_probe_finds::<$t>();
        }
        #[test]
        fn walking_down_stairs_keeps_the_wished_pace() {
            super::walking_down_stairs_keeps_the_wished_pace::<$t>();
        }
        #[test]
        fn bad_snaps_are_errors() { super::bad_snaps_are_errors::<$t>(); }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
