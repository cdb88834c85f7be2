//! A character riding a moving platform (README, *Moving platforms*): carried by the platform's
//! motion each frame before the platform moves and the character updates, every scalar.

#[macro_use]
mod common;

use ballcast::slide::Character;
use ballcast::{Scalar, Scene, Triangle};
use common::{Tolerance, v};

/// The ground at height 0 (triangles 0 and 1) and a lift's top, 4 × 4, at `top` (2 and 3).
fn level<S: Scalar>(top: f64) -> Scene<S, 4> {
    let mut s = Scene::new();
    for y in [0.0, top] {
        let (a, b, c, d) = (
            v::<S>([-2.0, y, -2.0]),
            v([-2.0, y, 2.0]),
            v([2.0, y, 2.0]),
            v([2.0, y, -2.0]),
        );
        let ground = y == 0.0;
        let scale = if ground { 20.0 } else { 1.0 };
        let grow =
            |p: ballcast::Vec3<S>| v([p.x.to_f64() * scale, p.y.to_f64(), p.z.to_f64() * scale]);
        s.push(Triangle::new(grow(a), grow(b), grow(c))).unwrap();
        s.push(Triangle::new(grow(a), grow(c), grow(d))).unwrap();
    }
    s
}

/// A lift rising at `speed` units a second for a second at 60 Hz from 1 above the ground with a
/// character of radius 0.5 walking slowly on it: with `carry`, the character is moved by the
/// lift's motion (a slide, so that walls would stop it) while it stands on the lift, before the
/// lift moves; returns the character's lowest and highest gap above the lift's top over the
/// frames, and whether it stood on the lift after every frame.
fn ride<S: Tolerance>(speed: f64, carry: bool) -> (f64, f64, bool) {
    let dt = 1.0 / 60.0;
    let (r, mut top) = (0.5, 1.0);
    let mut me = Character::new(v::<S>([0.0, top + r, 0.0]), S::from_f64(r)).unwrap();
    let (wish, gravity) = (v::<S>([0.5, 0.0, 0.0]), v::<S>([0.0, -9.81, 0.0]));
    // Settle onto the lift.
    for _ in 0..10 {
        me.update(&level::<S>(top), wish, gravity, S::from_f64(dt))
            .unwrap();
    }
    let (mut low, mut high, mut stood) = (f64::INFINITY, f64::NEG_INFINITY, true);
    for _ in 0..60 {
        let rise = speed * dt;
        let on_lift = me.floor().is_some_and(|f| f.index >= 2);
        if carry && on_lift {
            let lift = v::<S>([0.0, rise, 0.0]);
            let carried = me
                .slider()
                .slide(&level::<S>(top), me.position, lift)
                .unwrap();
            me.position = carried.position;
        }
        top += rise;
        me.update(&level::<S>(top), wish, gravity, S::from_f64(dt))
            .unwrap();
        let gap = me.position.y.to_f64() - r - S::from_f64(top).to_f64();
        (low, high) = (low.min(gap), high.max(gap));
        stood &= me.floor().is_some_and(|f| f.index >= 2);
    }
    (low, high, stood)
}

/// Carried by a lift rising faster than a radius a frame (40 units/s at 60 Hz, r 0.5), the
/// character stays on it, a skin above its top; without the carry the lift's one-sided top
/// passes up through the character's centre, which then lies behind it, and the character
/// falls through (the centre behind a one-sided face is no overlap).
fn a_lift_faster_than_a_radius_a_frame_carries_its_rider<S: Tolerance>() {
    let (low, high, stood) = ride::<S>(40.0, true);
    // A skin above the top (r / 1024 and two height roundings at the lift's 41 units).
    let skin = ballcast::slide::skin(S::from_f64(0.5), S::from_f64(50.0)).to_f64();
    assert!(
        stood,
        "{}: left the lift (gaps {low:e} to {high:e})",
        S::NAME
    );
    assert!(
        low > 0.0 && high < 2.0 * skin,
        "{}: gaps {low:e} to {high:e}, skin {skin:e}",
        S::NAME
    );
    let (low, _, stood) = ride::<S>(40.0, false);
    assert!(
        !stood && low < -0.5,
        "{}: uncarried, lowest gap {low}",
        S::NAME
    );
}

every_scalar!(a_lift_faster_than_a_radius_a_frame_carries_its_rider);
