//! The precision planner's error model holds case by case: every contact's distance error along
//! the normal stays within `Precision::distance_error` for that case's extent and path length,
//! at scene scales 1 to 1000, in every scalar: random sweeps, sweeps through the triangle's plane
//! and sweeps aimed at its edges and vertices.

mod common;

use ballcast::plan::{Sizes, Verdict};
use ballcast::{Contact, Scalar, Scene, StandardTriangle, Sweep, Triangle, Vec3};
use common::{P, Rng, Tolerance};
use fixed::types::{I16F16, I32F32};

/// The case's distance error along the normal as a share of the prediction for its extent and
/// path length; fails past the prediction.
fn share<S: Tolerance>(c: &common::Case) -> f64 {
    let c = c.rounded::<S>();
    let extent = c
        .tri
        .iter()
        .chain([&c.p0, &c.p1])
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let path = common::norm(common::sub(c.p1, c.p0));
    let p = S::PRECISION;
    assert!(p.fits(extent, c.r), "{}: {c:?} should fit", S::NAME);
    let (Ok(Some((a, _))), Ok(Some((b, m)))) = (c.cast::<S>(c.r), c.cast::<f64>(c.r)) else {
        return 0.0;
    };
    let err = (a - b).abs() * common::dot(common::sub(c.p1, c.p0), m).abs();
    let predicted = p.distance_error(extent, path);
    assert!(
        err <= predicted,
        "{}: error {err:e} > predicted {predicted:e} on {c:?}",
        S::NAME
    );
    err / predicted
}

fn model_holds<S: Tolerance>() {
    let mut rng = Rng(0x91A7);
    let mut worst = 0.0f64;
    for scale in [1.0, 10.0, 100.0, 1000.0] {
        for i in 0..40_000 {
            let c = match i % 4 {
                0 => rng.case(scale),
                1 => rng.falling_case(scale),
                _ => {
                    let size = rng.range(0.05 * scale, scale);
                    rng.feature_case(scale, size, 2.0 * scale)
                }
            };
            worst = worst.max(share::<S>(&c));
        }
    }
    println!(
        "{}: largest error was {:.0}% of the prediction",
        S::NAME,
        100.0 * worst
    );
}

/// Paths up to 1 000 long aimed at the edges and vertices of triangles 1.5 across within ±1 000:
/// two vertices a path meets within a few steps of alpha of each other (in `I16F16`, the later
/// one was once reported, 0.06 inside the ball).
fn long_paths_past_small_triangles<S: Tolerance>() {
    let mut rng = Rng(0x5EED);
    let worst = (0..100_000)
        .map(|_| share::<S>(&rng.feature_case(1000.0, 1.5, 1000.0)))
        .fold(0.0f64, f64::max);
    println!(
        "{}: largest error was {:.0}% of the prediction",
        S::NAME,
        100.0 * worst
    );
}

/// A cast of `c` in `S`: alpha, the position, the normal and the feature, in f64.
fn hit<S: Scalar>(c: &common::Case) -> Option<(f64, P, P, Contact)> {
    let [a, b, t] = c.tri.map(common::v::<S>);
    let st = StandardTriangle::new(&Triangle::new(a, b, t)).ok()?;
    let sweep = Sweep::new(common::v(c.p0), common::v(c.p1), S::from_f64(c.r)).ok()?;
    let h = st.cast(&sweep)?;
    let back = common::back;
    Some((
        h.alpha.to_f64(),
        back(h.position),
        back(h.normal),
        h.contact,
    ))
}

/// Small triangles far from the origin, as a level's are: every contact's error along the
/// normal, and its position's, stay within the planner's figures for the case's sizes with
/// the triangle's own size given (`Sizes::with_triangles`), which for floats are hundreds of
/// times below the figures for triangles as large as the level.
fn small_triangles_far_from_the_origin<S: Tolerance>() {
    let mut rng = Rng(0xFA12);
    let far = (0.9 * S::LIMIT.to_f64()).min(20_000.0);
    let (mut distance, mut position) = (0.0f64, 0.0f64);
    for i in 0..60_000 {
        let (size, path) = ([0.05, 0.5, 5.0][i % 3], [0.2, 2.0, 20.0][i / 3 % 3]);
        let mut c = rng.feature_case(far, size, path);
        c.r = rng.range(0.02, 2.0);
        let c = c.rounded::<S>();
        let (Some((a, p, _, contact)), Some((b, q, m, want))) = (hit::<S>(&c), hit::<f64>(&c))
        else {
            continue;
        };
        let extent = c.tri.iter().chain([&c.p0, &c.p1]).flatten();
        let extent = extent.fold(0.0f64, |m, x| m.max(x.abs()));
        let side = |k: usize| {
            let (lo, hi) = c.tri.iter().fold((f64::MAX, f64::MIN), |(lo, hi), v| {
                (lo.min(v[k]), hi.max(v[k]))
            });
            hi - lo
        };
        let d = common::sub(c.p1, c.p0);
        let sizes = Sizes::new(extent, c.r, common::norm(d))
            .with_triangles(side(0).max(side(1)).max(side(2)));
        let v = Verdict::of_sizes(S::PRECISION, sizes);
        // The error as a share of its prediction; fails past it.
        let share = |what: &str, err: f64, predicted: f64| {
            let name = S::NAME;
            assert!(
                err <= predicted,
                "{name}: {what} {err:e} > predicted {predicted:e} on {c:?}"
            );
            err / predicted
        };
        let err = (a - b).abs() * common::dot(d, m).abs();
        distance = distance.max(share("error", err, v.distance_error));
        if contact == want {
            let along = common::dot(common::sub(p, q), m).abs();
            position = position.max(share("position error", along, v.position_error));
        }
    }
    println!(
        "{}: largest errors {:.0}% (distance), {:.0}% (position) of the predictions",
        S::NAME,
        100.0 * distance,
        100.0 * position
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn planner_error_model_holds() {
            model_holds::<$t>();
        }
        #[test]
        fn long_paths_past_small_triangles() {
            super::long_paths_past_small_triangles::<$t>();
        }
        #[test]
        fn small_triangles_far_from_the_origin() {
            super::small_triangles_far_from_the_origin::<$t>();
        }
    })*};
}

per_scalar!(f32_: f32, i32f32: I32F32, i16f16: I16F16);

/// A review's case: an `f32` edge contact of a sweep from a corner of the extent, 33.5 long,
/// whose offset from the edge's corner is three times the extent: its error (6 steps of the
/// spacing at the extent beyond alpha's rounding) once exceeded the four steps the model gave
/// floats.
#[test]
fn an_edge_contact_from_a_corner_of_the_extent_f32() {
    let c = common::Case {
        tri: [
            [7.686553955078125, -5.366150379180908, -3.4976301193237305],
            [6.272609233856201, -3.65510630607605, -7.314385890960693],
            [6.951900482177734, -8.159939765930176, -0.7202837467193604],
        ],
        p0: [-10.0, 10.0, 10.0],
        p1: [10.0, -8.000432, -10.0],
        r: 1.9738997,
    };
    // Most of the old bound's margin used: the case still measures what it was pinned for.
    assert!(
        share::<f32>(&c) > 0.5,
        "the case no longer comes near the prediction"
    );
}

#[test]
fn planner_refuses_what_overflows() {
    let [i16, f32, i32, f64] = ballcast::plan(5000.0, 1.0, 10.0);
    assert!(!i16.fits && f32.fits && i32.fits && f64.fits);
    assert!(
        !ballcast::plan(1.0, -1.0, 1.0)[3].fits,
        "a negative radius fits nothing"
    );
    // Extent and path are magnitudes too: negative or NaN ones fit nothing, so no scalar is
    // chosen for them (a negative path once made every error negative, and `choose` picked a
    // scalar for any tolerance).
    for (extent, path) in [(-1e30, 1.0), (1e4, -1e9), (f64::NAN, 1.0), (1.0, f64::NAN)] {
        assert!(ballcast::plan(extent, 1.0, path).iter().all(|v| !v.fits));
        assert_eq!(ballcast::choose(extent, 1.0, path, 1e-12), None);
        assert_eq!(ballcast::choose(extent, 1.0, path, 1e9), None);
    }
    // Sizes beyond memory saturate, at once (nodes are counted in O(log² n)).
    let huge = ballcast::plan::Memory::of(ballcast::plan::ScalarType::F64, usize::MAX / 8, 3);
    assert_eq!(huge.mesh, usize::MAX);
    use ballcast::bvh::{LeafSize, nodes_for, nodes_for_leaves};
    for n in (0..5000).chain([1 << 24, (1 << 40) + 12_345]) {
        for leaves in [LeafSize::Two, LeafSize::Four] {
            let by_recursion = nodes_for_by_recursion(n, leaves.triangles());
            assert_eq!(nodes_for_leaves(n, leaves), by_recursion, "{n} {leaves:?}");
        }
        // The default's count is enough for every leaf size.
        assert_eq!(nodes_for(n), nodes_for_leaves(n, LeafSize::Two));
        assert!(nodes_for(n) >= nodes_for_leaves(n, LeafSize::Four), "{n}");
    }
    // Cheaper scalars show larger errors on the same scene.
    let v = ballcast::plan(100.0, 1.0, 10.0);
    assert!(v[0].distance_error > v[1].distance_error && v[1].distance_error > v[2].distance_error);
}

/// Each verdict names its scalar as a value a program can match on to pick the type.
#[test]
fn verdict_selects_a_type() {
    use ballcast::{Scalar, ScalarType};
    let all = ballcast::plan(100.0, 1.0, 10.0).map(|v| v.precision.scalar);
    let order = [
        ScalarType::I16F16,
        ScalarType::F32,
        ScalarType::I32F32,
        ScalarType::F64,
    ];
    assert_eq!(all, order);
    // The value leads back to the type: its precision is the type's own.
    fn same<S: Scalar>(t: ScalarType) {
        assert_eq!(t.precision(), S::PRECISION);
        assert_eq!(S::PRECISION.scalar, t);
    }
    same::<I16F16>(order[0]);
    same::<f32>(order[1]);
    same::<I32F32>(order[2]);
    same::<f64>(order[3]);
    assert_eq!(order.map(|t| t.name()), ["I16F16", "f32", "I32F32", "f64"]);
}

/// `choose` gives the cheapest scalar that fits, accepts the radius and meets the tolerance.
#[test]
fn choose_picks_the_cheapest_that_meets_the_tolerance() {
    use ballcast::{ScalarType, choose};
    let pick = |e, r, p, t| choose(e, r, p, t).map(|v| v.precision.scalar);
    assert_eq!(pick(100.0, 0.5, 2.0, 1e-3), Some(ScalarType::I16F16));
    // f32's heights at 100 round to ~5e-5: too coarse for 1e-6.
    assert_eq!(pick(100.0, 0.5, 2.0, 1e-6), Some(ScalarType::I32F32));
    // 10 km does not fit I16F16.
    assert_eq!(pick(10_000.0, 1.0, 20.0, 1e-2), Some(ScalarType::F32));
    // A ball too small for I16F16's rounding (128 steps of 2^-16) is not given it.
    assert_eq!(pick(100.0, 0.001, 0.01, 1e-2), Some(ScalarType::F32));
    assert_eq!(pick(1e20, 1.0, 1.0, 1.0), None);
    // Triangles at most 4 across, 10 km out: f32 rounds at their size and will do where
    // triangles as large as the level need I32F32 (`small_triangles_far_from_the_origin`
    // measures such contacts against these figures).
    let level = Sizes::new(10_000.0, 0.5, 2.0);
    let by = |s: Sizes, t| s.choose(t).map(|v| v.precision.scalar);
    assert_eq!(by(level, 1e-4), Some(ScalarType::I32F32));
    assert_eq!(by(level.with_triangles(4.0), 1e-4), Some(ScalarType::F32));
    // Fixed point's figures do not depend on the triangles' size.
    let room = Sizes::new(100.0, 0.5, 2.0);
    assert_eq!(room.plan()[0], room.with_triangles(0.1).plan()[0]);
    assert_eq!(room.plan(), ballcast::plan(100.0, 0.5, 2.0));
    for bad in [-1.0, f64::NAN] {
        assert!(room.with_triangles(bad).plan().iter().all(|v| !v.fits));
        assert_eq!(by(room.with_triangles(bad), 1e9), None);
    }
}

/// The constants' share of drift: a ball sliding at speed 3 on a floor for 10 s, stepped with
/// `dt = 1/60` exactly and with `dt` rounded to `I16F16`, both in f64: the second falls behind
/// by speed × time × the relative rounding of dt, as the planner's docs say.
#[test]
fn drift_from_rounded_dt_is_speed_times_time_times_its_rounding() {
    use ballcast::{Scalar, Scene, Triangle, Vec3, move_and_slide};
    let v = Vec3::new;
    let mut floor: Scene<f64, 2> = Scene::new();
    floor
        .push(Triangle::new(
            v(-100.0, 0.0, -100.0),
            v(-100.0, 0.0, 100.0),
            v(100.0, 0.0, 100.0),
        ))
        .unwrap();
    floor
        .push(Triangle::new(
            v(-100.0, 0.0, -100.0),
            v(100.0, 0.0, 100.0),
            v(100.0, 0.0, -100.0),
        ))
        .unwrap();
    let slide = |dt: f64| {
        let (mut p, mut vel) = (v(-50.0, 0.5005, 0.0), v(3.0, 0.0, 0.0));
        for _ in 0..600 {
            vel.y -= 9.81 * dt;
            let out = move_and_slide(&floor, p, vel * dt, 0.5).unwrap();
            p = out.position;
            vel = out.clip(vel).unwrap();
        }
        p
    };
    let exact = 1.0 / 60.0;
    let rounded = I16F16::from_f64(exact).to_f64();
    let relative = (exact - rounded) / exact;
    assert!((relative - 2.44e-4).abs() < 1e-6, "{relative}");
    let behind = slide(exact).x - slide(rounded).x;
    let predicted = 3.0 * 10.0 * relative;
    assert!(
        (behind - predicted).abs() < 0.05 * predicted,
        "fell behind by {behind}, predicted {predicted}"
    );
}

/// `nodes_for_leaves` as the build makes nodes, child by child, for leaves of up to `leaf`
/// triangles: the closed count must agree with it.
fn nodes_for_by_recursion(n: usize, leaf: usize) -> usize {
    if n == 0 {
        return 0;
    }
    let leaves = n.div_ceil(leaf);
    let mut per = 1;
    while per * 4 < leaves {
        per *= 4;
    }
    // Complete children alike: at most three of size `per * leaf`, then the rest.
    let (full, rest) = (per * leaf, n % (per * leaf));
    let k = (n / full).min(4);
    let child = |m: usize| {
        if m > leaf {
            nodes_for_by_recursion(m, leaf)
        } else {
            0
        }
    };
    1 + k * child(full) + if k < 4 { child(rest) } else { 0 }
}

/// Two parallel floors, triangle 0 at height 0 and triangle 1 up to three steps of alpha over
/// the path above it, a ball falling onto both along paths of 2 to 7 000: where the two alphas
/// round alike, the scene reports the contact first along the path, the upper floor's, so its
/// position stays within `Precision::position_error` of that floor's. When the smaller index
/// was reported instead, `I16F16` put it up to a whole step of alpha times the path off (1.1e-2
/// on a path of 1 000: 91 times `position_error`; `I32F32` 106 times).
fn stacked_floors_report_the_upper_floor<S: Tolerance>() {
    let v = |x: f64, y: f64, z: f64| Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z));
    for path in [2.0, 50.0, 1000.0, 7000.0] {
        if path / 2.0 > S::LIMIT.to_f64() {
            continue;
        }
        let (r, p) = (S::from_f64(0.5), S::PRECISION);
        let bound = p.position_error(path / 2.0);
        for i in 1..400 {
            let delta = S::from_f64(i as f64 / 400.0 * 3.0 * p.epsilon * path).to_f64();
            let mut scene: Scene<S, 2> = Scene::new();
            for y in [0.0, delta] {
                let t = Triangle::new(v(-5.0, y, -5.0), v(-5.0, y, 5.0), v(5.0, y, 5.0));
                scene.push(t).unwrap();
            }
            let top = path / 2.0;
            let sweep = Sweep::new(v(0.37, top, 1.3), v(0.37, top - path, 1.3), r).unwrap();
            let hit = scene.cast(&sweep).unwrap();
            let err = (hit.position.y.to_f64() - (delta + r.to_f64())).abs();
            assert!(
                err <= bound,
                "{}: path {path}, floors {delta:e} apart: position off by {err:e} > {bound:e}",
                S::NAME
            );
        }
    }
}

#[test]
fn stacked_floors_report_the_upper_floors_position() {
    stacked_floors_report_the_upper_floor::<f64>();
    stacked_floors_report_the_upper_floor::<f32>();
    stacked_floors_report_the_upper_floor::<I32F32>();
    stacked_floors_report_the_upper_floor::<I16F16>();
}
