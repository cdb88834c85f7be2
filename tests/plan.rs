//! The precision planner's error model holds case by case: every contact's distance error along
//! the normal stays within `Precision::distance_error` for that case's extent and path length,
//! at scene scales 1 to 1000, in every scalar.

mod common;

use common::{Rng, Tolerance};
use fixed::types::{I16F16, I32F32};

fn model_holds<S: Tolerance>() {
    let mut rng = Rng(0x91A7);
    let mut worst = 0.0f64; // largest error as a share of the prediction
    for scale in [1.0, 10.0, 100.0, 1000.0] {
        for i in 0..10_000 {
            let c = if i % 2 == 0 {
                rng.case(scale)
            } else {
                rng.falling_case(scale)
            };
            let c = c.rounded::<S>();
            let extent = c
                .tri
                .iter()
                .chain([&c.p0, &c.p1])
                .flatten()
                .fold(0.0f64, |m, x| m.max(x.abs()));
            let path = common::norm(common::sub(c.p1, c.p0));
            let p = S::PRECISION;
            assert!(p.fits(extent, c.r), "{}: scale {scale} should fit", S::NAME);
            let (Ok(Some((a, _))), Ok(Some((b, m)))) = (c.cast::<S>(c.r), c.cast::<f64>(c.r))
            else {
                continue;
            };
            let err = (a - b).abs() * common::dot(common::sub(c.p1, c.p0), m).abs();
            let predicted = p.distance_error(extent, path);
            assert!(
                err <= predicted,
                "{}: error {err:e} > predicted {predicted:e} on {c:?}",
                S::NAME
            );
            worst = worst.max(err / predicted);
        }
    }
    println!(
        "{}: largest error was {:.0}% of the prediction",
        S::NAME,
        100.0 * worst
    );
}

#[test]
fn planner_error_model_holds_for_f32() {
    model_holds::<f32>();
}

#[test]
fn planner_error_model_holds_for_i32f32() {
    model_holds::<I32F32>();
}

#[test]
fn planner_error_model_holds_for_i16f16() {
    model_holds::<I16F16>();
}

#[test]
fn planner_refuses_what_overflows() {
    let [i16, f32, i32, f64] = ballcast::plan(5000.0, 1.0, 10.0);
    assert!(!i16.fits && f32.fits && i32.fits && f64.fits);
    assert!(
        !ballcast::plan(1.0, -1.0, 1.0)[3].fits,
        "a negative radius fits nothing"
    );
    // Cheaper scalars show larger errors on the same scene.
    let v = ballcast::plan(100.0, 1.0, 10.0);
    assert!(v[0].distance_error > v[1].distance_error && v[1].distance_error > v[2].distance_error);
}
