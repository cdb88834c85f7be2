//! Every scalar against f64 on the same inputs: classification agrees outside the rounding band,
//! contact distance and normal within the tolerance table (`common::tolerance`).

mod common;

use common::{Case, Errors, Rng, Tolerance, compare};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;

fn point(half: f64) -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-half..half)
}

/// Scene scale 10: triangles within ±10, ball paths within ±40, radius 0.1–2.
fn case() -> impl Strategy<Value = Case> {
    (
        prop::array::uniform3(point(10.0)),
        point(40.0),
        point(40.0),
        0.1..2.0f64,
    )
        .prop_map(|(tri, p0, p1, r)| Case { tri, p0, p1, r })
}

/// Downward-biased paths so that a good share of cases are hits.
fn falling_case() -> impl Strategy<Value = Case> {
    (
        prop::array::uniform3(point(10.0)),
        point(10.0),
        point(10.0),
        0.1..2.0f64,
        1.0..30.0f64,
    )
        .prop_map(|(tri, a, b, r, h)| {
            let n = common::cross(common::sub(tri[1], tri[0]), common::sub(tri[2], tri[0]));
            let n = common::scale(n, 1.0 / common::norm(n).max(1e-12));
            Case {
                tri,
                p0: common::add(a, common::scale(n, h)),
                p1: common::add(b, common::scale(n, -h)),
                r,
            }
        })
}

fn check<S: Tolerance>(e: Errors, c: &Case) -> Result<(), TestCaseError> {
    prop_assert!(
        !e.misclassified,
        "hit/miss disagrees outside the band: {c:?}"
    );
    prop_assert!(
        e.excess <= S::DISTANCE,
        "distance error {} on {c:?}",
        e.distance
    );
    prop_assert!(
        e.angle <= S::ANGLE,
        "normal angle error {} on {c:?}",
        e.angle
    );
    Ok(())
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(2000))]
            #[test]
            fn agrees_with_f64_on_random_sweeps(c in case()) {
                if let Some(e) = compare::<$t>(&c) {
                    check::<$t>(e, &c)?;
                }
            }
            #[test]
            fn agrees_with_f64_on_falling_sweeps(c in falling_case()) {
                if let Some(e) = compare::<$t>(&c) {
                    check::<$t>(e, &c)?;
                }
            }
        }

        /// A larger deterministic sample of the same property (half random, half falling sweeps); prints the worst errors seen
        /// (`cargo test --release --test cross_precision -- --ignored --nocapture`).
        #[test]
        #[ignore]
        fn report_worst_errors_on_a_million_sweeps() {
            let mut rng = Rng(0x5EED_0000_0000_0001);
            let (mut worst, mut hits, mut band) = (Errors::default(), 0u64, 0u64);
            for i in 0..1_000_000 {
                let c = if i % 2 == 0 { rng.case(10.0) } else { rng.falling_case(10.0) };
                let Some(e) = compare::<$t>(&c) else { continue };
                assert!(!e.misclassified, "{c:?}");
                hits += e.hit as u64;
                band += e.in_band as u64;
                if e.distance > worst.distance { worst.distance = e.distance; }
                if e.excess > worst.excess { worst.excess = e.excess; }
                if e.angle > worst.angle { worst.angle = e.angle; }
            }
            println!(
                "{}: max distance error {:.3e} ({:.3e} beyond alpha's rounding), max angle {:.3e}; {hits} hits, {band} in band",
                <$t>::NAME, worst.distance, worst.excess, worst.angle);
            assert!(worst.excess <= <$t>::DISTANCE && worst.angle <= <$t>::ANGLE);
        }
    })*};
}

per_scalar!(f64_vs_model: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
