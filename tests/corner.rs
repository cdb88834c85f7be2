//! A small ball pushed, call after call, into an acute corner of two walls on a floor, by less
//! than a skin a call, or into a wedge of floor and overhanging wall. Every property in every scalar; expected values worked by hand.

mod common;

use ballcast::slide::{Slider, skin};
use ballcast::{Scalar, Scene, Triangle, Vec3, move_and_slide};
use common::{P, Tolerance, add, back, distance_to_triangle, quad, scale, v};
use fixed::types::{I16F16, I32F32};

/// A scene of the triangles `tris`, in the scalar.
fn scene<S: Scalar, const N: usize>(tris: &[[P; 3]]) -> Scene<S, N> {
    let mut scene = Scene::new();
    for t in tris {
        scene
            .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    scene
}

/// The corner: walls from the origin along +x and along `(cos θ, 0, sin θ)`, `len` long and
/// tall, fronts inside the wedge, on a floor at y = 0 under the whole corner.
fn corner(theta: f64, len: f64) -> Vec<[P; 3]> {
    let (up, u2) = ([0.0, len, 0.0], [theta.cos(), 0.0, theta.sin()]);
    let f = [-len, 0.0, -len];
    [
        quad([0.0; 3], [len, 0.0, 0.0], up),
        quad([0.0; 3], up, scale(u2, len)),
        quad(f, [0.0, 0.0, 2.0 * len], [2.0 * len, 0.0, 0.0]),
    ]
    .concat()
}

/// Corners of 20°–60°, balls of r = 0.005–0.05 resting on the floor in the corner, pushed
/// level into it by 0.1–1 skin a call, off the bisector (inside the walls' normal cone, so the
/// ball must stay): over 1 500 calls it never overlaps a wall by more than a quarter of a skin.
/// A slide along one wall as rounded, met because the ball started within rounding of it, was
/// lifted off that wall without a sweep, into the other wall: in `I16F16` the ball passed
/// through it (an overlap of r/2 and more). Later the skin's lift off a wall met at once, also
/// made without a sweep, pushed `I16F16` balls into the other wall by up to 0.15 r.
fn pushed_into_an_acute_corner_stays_out_of_the_walls<S: Tolerance>() {
    let cases = [
        (0.005, 0.1, -0.6),
        (0.02, 0.45, 0.6),
        (0.02, 0.2, -0.6),
        (0.02, 1.0, 0.0),
        (0.05, 0.45, -0.6),
        (0.05, 0.2, -0.6),
    ];
    for degrees in [20.0f64, 30.0, 45.0, 60.0] {
        for (r, skins, uneven) in cases {
            let theta = degrees.to_radians();
            let tris = corner(theta, 6.0 * r / 0.5);
            let scene: Scene<S, 6> = scene(&tris);
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
                    deepest <= skin / 4.0,
                    "{}: {degrees}° corner, r {r}, push {skins} skin: call {call} overlaps a \
                     wall by {deepest:.3e} (skin {skin:.3e}) at {:?}",
                    S::NAME,
                    back(p)
                );
            }
        }
    }
}

/// A ball of r = 0.02 falling into a slot between two walls a quarter of a skin farther apart
/// than it is wide (on each side), running along it: it reaches the floor (centre r above it
/// within two steps) within 60 frames and runs on. Where a lift off one wall meets the other,
/// the ball stops half way: stopped where it was instead, it stayed within rounding of a wall,
/// met it at once on every sweep, and hung in the slot for good (`I16F16`).
fn falling_into_a_slot_reaches_the_floor<S: Tolerance>() {
    let (r, dt) = (0.02, 1.0 / 60.0);
    let rs = S::from_f64(r);
    let w = r + skin(rs, S::from_f64(4.0)).to_f64() / 4.0;
    let tris = [
        quad([-3.2, -0.8, -w], [6.4, 0.0, 0.0], [0.0, 1.6, 0.0]),
        quad([-3.2, -0.8, w], [0.0, 1.6, 0.0], [6.4, 0.0, 0.0]),
        quad([-3.2, -0.4, -0.16], [0.0, 0.0, 0.32], [6.4, 0.0, 0.0]),
    ]
    .concat();
    let scene: Scene<S, 6> = scene(&tris);
    let (mut p, mut vy) = (v::<S>([-1.2, 0.0, 0.0]), 0.0);
    let mut landed = None;
    for frame in 0..120 {
        vy -= 9.81 * dt;
        let d = v::<S>([0.08 * dt, vy * dt, 0.0008 * dt]);
        let out = move_and_slide(&scene, p, d, rs).unwrap();
        vy = out.clip(d).unwrap().y.to_f64() / dt;
        p = out.position;
        if landed.is_none()
            && (back(p)[1] - (r - 0.4)).abs()
                <= 2.0 * S::spacing(1.0) + skin(rs, S::from_f64(4.0)).to_f64()
        {
            landed = Some(frame);
        }
    }
    assert!(
        landed.is_some_and(|f| f < 60) && back(p)[0] > -1.2 + 0.08 * 1.5,
        "{}: landed {landed:?}, at {:?}",
        S::NAME,
        back(p)
    );
}

/// A floor at y = 0 and a wall through the z axis leaning over it towards −x, meeting it in a
/// corner of `degrees` (90: upright), fronts inside.
fn overhang(degrees: f64) -> [[P; 3]; 4] {
    let a = (180.0 - degrees).to_radians();
    let (n, along) = ([-a.sin(), a.cos(), 0.0], [0.0, 0.0, 1.0]);
    let across = common::cross(n, along);
    let wall = |i: f64, j: f64| add(scale(across, 1.6 * i), scale(along, 1.6 * j));
    let f = |x: f64, z: f64| [x, 0.0, z];
    [
        // Fronts along `n`: (b - a) × (c - a) turns from `along` to `across`.
        [wall(-1.0, -1.0), wall(1.0, 1.0), wall(1.0, -1.0)],
        [wall(-1.0, -1.0), wall(-1.0, 1.0), wall(1.0, 1.0)],
        [f(-3.2, -3.2), f(-3.2, 3.2), f(0.5, 3.2)],
        [f(-3.2, -3.2), f(0.5, 3.2), f(0.5, -3.2)],
    ]
}

/// A ball pushed slowly into a wedge of floor and overhang (30°–70°, r 0.01–0.5), by (1e-4,
/// −1e-4, 0) a call: after 1 500 calls, grounded on each of the next 200, by the call's own
/// contacts or by the ground probe. Where there is no room to stand a skin off both planes, a
/// push smaller than the gap misses the floor: in `I16F16`, r 0.5, the calls alone touched it
/// on 125 of the 200 in the 60° wedge and 100 in the 70° one.
fn pushed_into_a_wedge_under_an_overhang_stays_grounded<S: Tolerance>() {
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let push = v::<S>([1e-4, -1e-4, 0.0]);
    for degrees in [30.0, 45.0, 60.0, 70.0] {
        let scene: Scene<S, 4> = scene(&overhang(degrees));
        for r in [0.01, 0.05, 0.5] {
            let ball = Slider::new(S::from_f64(r)).unwrap();
            let mut p = v::<S>([-0.5, r * 1.001, 0.0]);
            for call in 0..1700 {
                let out = ball.slide(&scene, p, push).unwrap();
                p = out.position;
                let floor = match out.floor_normal(up, walkable).unwrap() {
                    Some(n) => Some(n),
                    None => (ball.probe_floor(&scene, p, up, walkable).unwrap()).map(|f| f.normal),
                };
                assert!(
                    call < 1500 || floor == Some(up),
                    "{}: {degrees}° wedge, r {r}, call {call}: floor {floor:?} at {:?}",
                    S::NAME,
                    back(p)
                );
            }
        }
    }
}

/// A ball of r = 0.02 walking along the foot of a wall that leans over the floor at 110°
/// (a 70° corner), nearly along it (5° into it) at 0.08 units/s for 4 s, pressed into the floor
/// each frame as in the README's recipe: it covers at least 90 % of the way. Where a lift off
/// the wall, which points down into the floor, met the floor at once, the ball stopped where it
/// was: it stayed within rounding of the wall, met it at once on every sweep, and stuck
/// (`I16F16`, after 0.04). The lift now slides along the floor.
fn walking_along_the_foot_of_an_overhang_does_not_stick<S: Tolerance>() {
    let (r, dt, g) = (0.02, S::from_f64(1.0 / 60.0), S::from_f64(9.81));
    let rs = S::from_f64(r);
    let scene: Scene<S, 4> = scene(&overhang(70.0));
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let wish = v::<S>(scale(
        [5f64.to_radians().sin(), 0.0, 5f64.to_radians().cos()],
        0.08,
    ));
    let start = [-r - 0.024, r * 1.001, -0.4];
    let (mut p, mut floor) = (v::<S>(start), Some(up));
    for _ in 0..240 {
        let n = floor.unwrap_or(up);
        let press = move_and_slide(&scene, p, Vec3::ZERO - n * g.mul(dt).mul(dt), rs).unwrap();
        let w = wish - n * wish.dot(n);
        let walk = move_and_slide(&scene, press.position, w * dt, rs).unwrap();
        floor = walk.floor_normal(up, walkable).unwrap();
        floor = floor.or(press.floor_normal(up, walkable).unwrap());
        p = walk.position;
    }
    let covered = back(p)[2] - start[2];
    assert!(
        covered >= 0.9 * 0.08 * 4.0 * 5f64.to_radians().cos(),
        "{}: covered {covered} of 0.32, at {:?}",
        S::NAME,
        back(p)
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn falling_into_a_slot() {
            falling_into_a_slot_reaches_the_floor::<$t>();
        }
        #[test]
        fn walking_along_the_foot_of_an_overhang() {
            walking_along_the_foot_of_an_overhang_does_not_stick::<$t>();
        }
        #[test]
        fn pushed_into_a_wedge_under_an_overhang() {
            pushed_into_a_wedge_under_an_overhang_stays_grounded::<$t>();
        }
        #[test]
        fn pushed_into_an_acute_corner() {
            pushed_into_an_acute_corner_stays_out_of_the_walls::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
