//! `Character::jump` sets the velocity's part along `up`: a jump rises as high from a stair's
//! edge, walking up the stairs, as from level ground (added to the walk's rise over the edge,
//! it once went nearly twice as high). Every property in every scalar.

mod common;

use ballcast::{Scalar, Scene, Triangle, slide::Character};
use common::{P, Tolerance, back, quad, v};
use fixed::types::{I16F16, I32F32};

/// How high a jump at 4 units/s rises above where it left the floor (at most 1.5 s in the air).
fn rise<S: Scalar, const N: usize>(me: &Character<S>, level: &Scene<S, N>, hz: f64) -> f64 {
    let (mut me, dt, gravity) = (*me, S::from_f64(1.0 / hz), v::<S>([0.0, -9.81, 0.0]));
    let start = back(me.position)[1];
    assert!(me.jump(S::from_f64(4.0)).unwrap(), "not on the floor");
    let mut top = start;
    for _ in 0..(1.5 * hz) as usize {
        me.update(level, v([0.0; 3]), gravity, dt).unwrap();
        top = top.max(back(me.position)[1]);
    }
    top - start
}

/// A level floor up to x = 0, then stairs 0.2 high on treads 0.6 deep up along +x, 20 wide.
fn stairs<S: Scalar>() -> Scene<S, 64> {
    let mut s = Scene::new();
    let mut add = |o: P, a: P, b: P| {
        for t in quad(o, a, b) {
            s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
        }
    };
    let across = [0.0, 0.0, 20.0];
    add([-10.0, 0.0, -10.0], across, [10.0, 0.0, 0.0]);
    for k in 0..8 {
        let (x, y) = (0.6 * k as f64, 0.2 * k as f64);
        add([x, y, -10.0], across, [0.0, 0.2, 0.0]);
        add([x, y + 0.2, -10.0], across, [0.6, 0.0, 0.0]);
    }
    s
}

/// Walking up the stairs at 3 units/s, a jump from any frame the walker stands rises as high as
/// from level ground (`v² / 2g`, 0.82), within 1/15 of a unit.
fn a_jump_from_a_stair_rises_as_from_level_ground<S: Tolerance>() {
    let (hz, level) = (60.0, stairs::<S>());
    let (dt, gravity) = (S::from_f64(1.0 / hz), v::<S>([0.0, -9.81, 0.0]));
    let mut me = Character::new(v([-2.0, 0.45, 0.0]), S::from_f64(0.4)).unwrap();
    let flat = 16.0 / (2.0 * 9.81);
    let (mut tried, mut lowest, mut highest) = (0, f64::MAX, 0.0f64);
    for _ in 0..120 {
        me.update(&level, v([3.0, 0.0, 0.0]), gravity, dt).unwrap();
        if me.is_grounded() && back(me.position)[0] > -0.5 && back(me.position)[0] < 4.0 {
            let rose = rise(&me, &level, hz);
            (lowest, highest) = (lowest.min(rose), highest.max(rose));
            tried += 1;
        }
    }
    assert!(tried > 60, "{}: jumped from {tried} frames", S::NAME);
    let within = 4.0 / hz;
    assert!(
        lowest >= flat - within && highest <= flat + within,
        "{}: rose {lowest} to {highest} (level ground: {flat})",
        S::NAME
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn a_jump_from_a_stair() {
            a_jump_from_a_stair_rises_as_from_level_ground::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
