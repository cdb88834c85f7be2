//! A step whose move across fills all `MAX_SLIDES` contact slots: the stepped move keeps the
//! move across's last three contacts and the landing (`Slider::step_slide`, `stepped`'s
//! `rotate_left`), in every scalar. No other test makes the move across slide four times.

mod common;

use ballcast::slide::{MAX_SLIDES, Slider};
use ballcast::{Scalar, Scene, Triangle};
use common::{P, Tolerance, angle, back, quad, v};

/// The ledge's height, and the bend's wall segments: their length and how far each turns.
const LEDGE: f64 = 0.2;
const SEGMENT: f64 = 0.25;
const TURN: f64 = 15.0;

/// The unit normal of the bend's `k`-th segment (from 1), facing the ball.
fn normal(k: usize) -> P {
    let b = (TURN * k as f64).to_radians();
    [-b.sin(), 0.0, -b.cos()]
}

/// A floor at y = 0 up to x = 1, a riser `LEDGE` high facing −x, the ledge's floor beyond it,
/// and on the ledge a bend of four upright wall segments, each turned `TURN` further from +x
/// towards −z: a ball lifted over the riser and carried along +x meets the first at its middle
/// and is turned by each into the next, inside the bend, so it touches all four in one move.
fn level<S: Scalar>() -> Scene<S, 14> {
    let mut quads = vec![
        [[-9.0, 0.0, -9.0], [0.0, 0.0, 18.0], [10.0, 0.0, 0.0]],
        [[1.0, 0.0, -9.0], [0.0, 0.0, 18.0], [0.0, LEDGE, 0.0]],
        [[1.0, LEDGE, -9.0], [0.0, 0.0, 18.0], [8.0, 0.0, 0.0]],
    ];
    // The first segment's middle is touched by a centre at x = 1.2 on z = 0.
    let n = normal(1);
    let middle = [1.2 - 0.5 * n[0], -0.5 * n[2]];
    let mut at = [
        middle[0] + 0.5 * SEGMENT * n[2],
        middle[1] - 0.5 * SEGMENT * n[0],
    ];
    for k in 1..=4 {
        let n = normal(k);
        // Along the segment: its normal turned a right angle about +y.
        let along = [-SEGMENT * n[2], SEGMENT * n[0]];
        quads.push([
            [at[0], LEDGE, at[1]],
            [0.0, 2.0, 0.0],
            [along[0], 0.0, along[1]],
        ]);
        at = [at[0] + along[0], at[1] + along[1]];
    }
    let mut s = Scene::new();
    for t in quads.into_iter().flat_map(|[o, a, b]| quad(o, a, b)) {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    s
}

/// Stopped by the riser, the walk steps up; the move across, from where the lift ends, meets
/// the bend's four segments and fills its slots, so the stepped move drops the first (the
/// move across's earliest) and ends with the landing: its contacts are the move across's
/// second to fourth, bit for bit, then a floor contact on the ledge's top. Appended in the
/// fourth slot without the rotation, the landing would replace the fourth segment and keep the
/// first.
fn a_step_across_four_walls_keeps_the_last_three_and_the_landing<S: Tolerance>() {
    let level = level::<S>();
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(0.5)).unwrap();
    let ball = ball.with_max_slope(up, walkable).unwrap();
    let (at, walk, step) = (v::<S>([0.55, 0.5005, 0.0]), v::<S>([1.2, 0.0, 0.0]), 0.25);
    let plain = ball.slide(&level, at, walk).unwrap();
    assert!(back(plain.position)[0] < 0.61, "{}: {plain:?}", S::NAME);
    let out = ball
        .step_slide(&level, at, walk, up, walkable, S::from_f64(step))
        .unwrap();

    // The move across as `stepped` makes it: lifted by the step (a level walk adds no rise,
    // and the start overlaps nothing), then the walk itself (it goes farther into the riser
    // than the ball must be carried past the edge, so it is not lengthened).
    let raised = ball.slide(&level, at, up.scale(S::from_f64(step))).unwrap();
    let across = ball.slide(&level, raised.position, walk).unwrap();
    let what = format!("{}: {out:?}\nacross {across:?}", S::NAME);
    // It touched the four segments in turn: the slots are full.
    let walls = across.contacts.map(|c| c.expect("four contacts across"));
    for (k, c) in walls.iter().enumerate() {
        let off = angle(back(c.hit.normal), normal(k + 1));
        assert!(off < S::ANGLE, "{what}: contact {k}");
    }
    assert!(walls.windows(2).all(|w| w[0].time < w[1].time), "{what}");

    // On the ledge, lowered straight down from where the move across ended.
    let (end, from, start) = (back(out.position), back(across.position), back(at));
    let skin = ball.skin(S::from_f64(2.0)).to_f64();
    assert!(end[1] - start[1] > 2.0 * skin, "{what}");
    assert!((end[1] - (LEDGE + 0.5)).abs() < 2e-3, "{what}");
    assert_eq!((end[0], end[2]), (from[0], from[2]), "{what}");
    // The move across's last three contacts, in order, then the landing.
    let kept = out.contacts.iter().flatten().count();
    assert_eq!(kept, MAX_SLIDES, "{what}");
    assert_eq!(out.contacts[..3], across.contacts[1..], "{what}");
    let landing = out.contacts[3].expect("the landing");
    assert!(landing.hit.normal.dot(up) >= walkable, "{what}");
    assert!((back(landing.point)[1] - LEDGE).abs() < 1e-3, "{what}");
    assert!(out.floor(up, walkable).unwrap() == Some(&landing), "{what}");
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[test]
        fn a_step_across_four_walls_keeps_the_last_three_and_the_landing() {
            super::a_step_across_four_walls_keeps_the_last_three_and_the_landing::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: fixed::types::I32F32, i16f16: fixed::types::I16F16);
