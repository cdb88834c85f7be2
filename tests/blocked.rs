//! `Slide::blocked` is the part of the displacement not travelled: `position` is the start,
//! `pushed_out`, the displacement and `-blocked` added up, to rounding, in every scalar.

mod common;

use ballcast::{Scene, Triangle, move_and_slide};
use common::{Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// A ball resting exactly on a floor (met at once, lifted a skin off it) and thrown down into
/// it and sideways into a wall: the lift was left out of `blocked`, which put the ball a skin
/// (4.9e-4) lower than it ended.
fn blocked_includes_the_lift_off_a_floor_met_at_once<S: Tolerance>() {
    let mut s: Scene<S, 4> = Scene::new();
    let (a, b) = ([-9.0, 0.0, -9.0], [9.0, 0.0, 9.0]);
    s.push(Triangle::new(v(a), v([-9.0, 0.0, 9.0]), v(b)))
        .unwrap();
    s.push(Triangle::new(v(a), v(b), v([9.0, 0.0, -9.0])))
        .unwrap();
    // A wall at x = 2 facing -x.
    let (c, d) = ([2.0, -1.0, -9.0], [2.0, 9.0, 9.0]);
    s.push(Triangle::new(v(c), v([2.0, -1.0, 9.0]), v(d)))
        .unwrap();
    s.push(Triangle::new(v(c), v(d), v([2.0, 9.0, -9.0])))
        .unwrap();
    let (p, shove) = (v::<S>([1.36, 0.5, 0.0]), v::<S>([1.8, -0.7, 0.7]));
    let out = move_and_slide(&s, p, shove, S::from_f64(0.5)).unwrap();
    // Lifted off the floor, against the wall.
    assert!(out.position.y > S::from_f64(0.5), "{}", S::NAME);
    let said = p + out.pushed_out + shove - out.blocked;
    let gap = (said - out.position).abs().max_element().to_f64();
    let round = 8.0 * S::EPSILON.to_f64() * 4.0;
    assert!(gap <= round, "{}: {gap:e} > {round:e}", S::NAME);
}

#[test]
fn blocked_includes_the_lift_off_a_floor_met_at_once_f64() {
    blocked_includes_the_lift_off_a_floor_met_at_once::<f64>();
}
#[test]
fn blocked_includes_the_lift_off_a_floor_met_at_once_f32() {
    blocked_includes_the_lift_off_a_floor_met_at_once::<f32>();
}
#[test]
fn blocked_includes_the_lift_off_a_floor_met_at_once_i32f32() {
    blocked_includes_the_lift_off_a_floor_met_at_once::<I32F32>();
}
#[test]
fn blocked_includes_the_lift_off_a_floor_met_at_once_i16f16() {
    blocked_includes_the_lift_off_a_floor_met_at_once::<I16F16>();
}
