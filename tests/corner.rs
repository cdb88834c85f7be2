//! A small ball pushed, call after call, into an acute corner of two walls on a floor, by less
//! than a skin a call. Every property in every scalar; expected values worked by hand.

mod common;

use ballcast::{Scene, Triangle, move_and_slide, slide::skin};
use common::{P, Tolerance, add, back, distance_to_triangle, scale, v};
use fixed::types::{I16F16, I32F32};

/// The corner: walls from the origin along +x and along `(cos θ, 0, sin θ)`, `len` long and
/// tall, fronts inside the wedge, on a floor at y = 0 under the whole corner.
fn corner(theta: f64, len: f64) -> Vec<[P; 3]> {
    let quad = |o: P, a: P, b: P| {
        let (oa, oab) = (add(o, a), add(add(o, a), b));
        [[o, oa, oab], [o, oab, add(o, b)]]
    };
    let (up, u2) = ([0.0, len, 0.0], [theta.cos(), 0.0, theta.sin()]);
    let f = [-len, 0.0, -len];
    [
        quad([0.0; 3], [len, 0.0, 0.0], up),
        quad([0.0; 3], up, scale(u2, len)),
        quad(f, [0.0, 0.0, 2.0 * len], [2.0 * len, 0.0, 0.0]),
    ]
    .concat()
}

/// Corners of 20°–60°, balls of r = 0.02 and 0.05 resting on the floor in the corner, pushed
/// level into it by 0.2 or 0.45 skin a call, off the bisector (inside the walls' normal cone,
/// so the ball must stay): over 1 500 calls it never overlaps a wall by more than four skins
/// (rounding lets `I16F16` overlap the 20° corner's walls by a skin at times). A
/// slide along one wall as rounded, met because the ball started within rounding of it, was
/// lifted off that wall without a sweep, into the other wall: in `I16F16` the ball passed
/// through it (an overlap of r/2 and more).
fn pushed_into_an_acute_corner_stays_out_of_the_walls<S: Tolerance>() {
    for degrees in [20.0f64, 30.0, 45.0, 60.0] {
        for (r, skins, uneven) in [(0.02, 0.45, 0.6), (0.02, 0.2, -0.6), (0.05, 0.45, -0.6)] {
            let theta = degrees.to_radians();
            let tris = corner(theta, 6.0 * r / 0.5);
            let mut scene: Scene<S, 6> = Scene::new();
            for t in &tris {
                scene
                    .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                    .unwrap();
            }
            let half = theta / 2.0;
            let bisector = [half.cos(), 0.0, half.sin()];
            let start = add(
                scale(bisector, r / half.sin() + r / 1024.0),
                [0.0, r * 1.001, 0.0],
            );
            let skin = skin(S::from_f64(r), S::from_f64(8.0 * r)).to_f64();
            let phi = half + uneven * (std::f64::consts::PI - theta) / 2.0;
            let push = v::<S>(scale([-phi.cos(), 0.0, -phi.sin()], skins * skin));
            let mut p = v::<S>(start);
            for call in 0..1500 {
                p = move_and_slide(&scene, p, push, S::from_f64(r))
                    .unwrap()
                    .position;
                let deepest = tris[..4]
                    .iter()
                    .map(|t| r - distance_to_triangle(back(p), *t))
                    .fold(f64::MIN, f64::max);
                assert!(
                    deepest <= 4.0 * skin,
                    "{}: {degrees}° corner, r {r}, push {skins} skin: call {call} overlaps a \
                     wall by {deepest:.3e} (skin {skin:.3e}) at {:?}",
                    S::NAME,
                    back(p)
                );
            }
        }
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn pushed_into_an_acute_corner() {
            pushed_into_an_acute_corner_stays_out_of_the_walls::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
