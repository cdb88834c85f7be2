//! `Vec3`'s building blocks in every scalar: arithmetic that rounds to nearest and mirrors with
//! sign, a dot product and length that do not overflow inside the safe range, conversions.

mod common;

use ballcast::{Scalar, Vec3};
use common::{Rng, Tolerance, back, v};
use fixed::types::{I16F16, I32F32};

fn arithmetic_mirrors_with_sign<S: Tolerance>() {
    let mut rng = Rng(0x5EC3);
    for _ in 0..10_000 {
        let a = v::<S>(rng.point(100.0));
        let s = S::from_f64(rng.range(-2.0, 2.0));
        let d = S::from_f64(rng.range(0.5, 4.0));
        assert_eq!((-a) * s, -(a * s), "{}: scale of {a:?} by {s:?}", S::NAME);
        assert_eq!((-a) / d, -(a / d), "{}: {a:?} / {d:?}", S::NAME);
        // Rounded to nearest: within half a step of the exact product.
        let exact = common::scale(back(a), s.to_f64());
        let err = common::norm(common::sub(back(a * s), exact));
        assert!(err <= 0.87 * S::spacing(200.0), "{}: {err:e}", S::NAME);
        let mut b = a;
        b += a;
        b -= a;
        assert_eq!(b, a);
    }
}

fn dot_cross_and_length_hold_inside_the_safe_range<S: Tolerance>() {
    let big = S::LIMIT.to_f64() / 2.0;
    // (3, 4, 12) has length 13: scaled to the range's edge, still exact for fixed-point.
    let k = (big / 13.0).floor();
    let a = v::<S>([3.0 * k, 4.0 * k, 12.0 * k]);
    let len = a.length().to_f64();
    assert!(
        (len - 13.0 * k).abs() <= S::spacing(13.0 * k),
        "{}: {len}",
        S::NAME
    );
    // A dot product whose partial products leave the range but whose sum does not.
    let b = v::<S>([4.0 * k, -3.0 * k, 0.0]);
    assert_eq!(a.dot(b), S::ZERO, "{}", S::NAME);
    // The cross product of unit axes, and orthogonality on random unit vectors.
    let (x, y) = (v::<S>([1.0, 0.0, 0.0]), v::<S>([0.0, 1.0, 0.0]));
    assert_eq!(x.cross(y), v::<S>([0.0, 0.0, 1.0]));
    let mut rng = Rng(0xC7055);
    for _ in 0..1_000 {
        let (p, q) = (v::<S>(rng.point(1.0)), v::<S>(rng.point(1.0)));
        let c = p.cross(q);
        let scale = common::norm(back(p)) * common::norm(back(q));
        assert!(common::dot(back(c), back(p)).abs() <= 8.0 * S::spacing(1.0) * scale + 1e-12);
        if let Some(u) = c.try_normalize() {
            assert!((common::norm(back(u)) - 1.0).abs() <= 4.0 * S::spacing(1.0));
        }
    }
    assert_eq!(Vec3::<S>::ZERO.try_normalize(), None);
    assert_eq!(Vec3::<S>::ZERO.normalize_or_zero(), Vec3::ZERO);
}

/// `length` of vectors anywhere in the type's range, up to its largest values: the exact length
/// where the type holds it, else the largest value (fixed point saturates, floats give
/// infinity only beyond their range); never a wrapped or negative length.
fn length_saturates_beyond_the_range<S: Tolerance>() {
    let largest = S::from_f64(f64::MAX).to_f64();
    let top = largest.min(1e30);
    let mut rng = Rng(0x1E47);
    let mut cases: Vec<[f64; 3]> = vec![[30000.0, 30000.0, 0.0], [top, top, top], [-top, top, 0.0]];
    for _ in 0..10_000 {
        let scale = top * rng.next().powi(4);
        cases.push(rng.point(1.0).map(|c| c * scale));
    }
    for p in cases {
        let a = v::<S>(p);
        let exact = common::norm(back(a)).min(largest);
        let got = a.length().to_f64();
        let tol = S::spacing(exact) + exact * 4.0 * f32::EPSILON as f64;
        assert!(
            (got - exact).abs() <= tol,
            "{}: |{p:?}| = {got}, not {exact}",
            S::NAME
        );
    }
}

fn conversions_round_trip<S: Tolerance>() {
    let p = [0.5, -2.25, 1000.125];
    let a = v::<S>(p);
    assert_eq!(<[S; 3]>::from(a), [a.x, a.y, a.z]);
    assert_eq!(Vec3::from([a.x, a.y, a.z]), a);
    // Through f64, every scalar's value converts exactly (these are dyadic).
    assert_eq!(back(a.cast::<f64>()), p);
    assert_eq!(a.cast::<f64>().cast::<S>(), a);
    // The checked conversion agrees within range, and beyond it (or for NaN) refuses with the
    // value given, where `cast` would saturate (fixed point) and hide it.
    assert_eq!(Vec3::new(0.5f64, -2.25, 1000.125).try_cast::<S>(), Ok(a));
    let limit = S::LIMIT.to_f64();
    let far = Vec3::new(0.0f64, -3.0 * limit, 0.0).try_cast::<S>();
    let want = ballcast::Error::OutOfRange {
        input: ballcast::Input::Number,
        value: -3.0 * limit,
        min: -limit,
        max: limit,
        triangle: None,
    };
    assert_eq!(far, Err(want), "{}", S::NAME);
    let nan = Vec3::new(f64::NAN, 0.0, 0.0).try_cast::<S>();
    let nan_error = ballcast::Error::NaN {
        input: ballcast::Input::Number,
        triangle: None,
    };
    assert_eq!(nan, Err(nan_error));
    // One number alike: the value given, where `from_f64` would saturate.
    assert_eq!(S::try_from_f64(-2.25), Ok(a.y), "{}", S::NAME);
    assert_eq!(S::try_from_f64(-3.0 * limit), Err(want), "{}", S::NAME);
    assert_eq!(S::try_from_f64(f64::NAN), Err(nan_error), "{}", S::NAME);
}

/// The axes, `distance`, `lerp` and the compound `*=` and `/=`: against `f64` on the same
/// rounded inputs, ends of `lerp` exact.
fn helpers_agree_with_f64<S: Tolerance>() {
    let (x, y, z) = (Vec3::<S>::X, Vec3::<S>::Y, Vec3::<S>::Z);
    assert_eq!(x.cross(y), z, "{}", S::NAME);
    assert_eq!(y.cross(z), x, "{}", S::NAME);
    assert_eq!(x.length(), S::ONE, "{}", S::NAME);
    let mut rng = Rng(0x1E7);
    for _ in 0..10_000 {
        let (a, b) = (v::<S>(rng.point(100.0)), v::<S>(rng.point(100.0)));
        let t = S::from_f64(rng.range(0.0, 1.0));
        let gap = common::norm(common::sub(back(b), back(a)));
        let err = (a.distance(b).to_f64() - gap).abs();
        assert!(
            err <= 2.0 * S::spacing(400.0),
            "{}: distance {err:e}",
            S::NAME
        );
        assert_eq!(
            (a.lerp(b, S::ZERO), a.lerp(b, S::ONE)),
            (a, b),
            "{}",
            S::NAME
        );
        // Between a point and itself, the point (`a (1 - t) + a t` missed it by a rounding).
        assert_eq!(a.lerp(a, t), a, "{}", S::NAME);
        let exact = common::add(
            back(a),
            common::scale(common::sub(back(b), back(a)), t.to_f64()),
        );
        let err = common::norm(common::sub(back(a.lerp(b, t)), exact));
        assert!(err <= 2.0 * S::spacing(400.0), "{}: lerp {err:e}", S::NAME);
        let (mut m, mut d) = (a, a);
        m *= t;
        d /= S::from_f64(rng.range(0.5, 4.0));
        assert_eq!(m, a * t, "{}", S::NAME);
        assert_ne!(d, a, "{}", S::NAME);
    }
}

/// `splat`, `min`, `max`, `abs`, `max_element` exactly as the components are; `length_squared` and the
/// projections onto and across a unit vector and the reflection in its plane against `f64` on
/// the same rounded inputs.
fn components_and_projections_agree_with_f64<S: Tolerance>() {
    let mut rng = Rng(0x9_0C7);
    for _ in 0..10_000 {
        let (a, b) = (v::<S>(rng.point(100.0)), v::<S>(rng.point(100.0)));
        let pick = |f: fn(f64, f64) -> f64| v::<S>([0, 1, 2].map(|i| f(back(a)[i], back(b)[i])));
        assert_eq!(a.min(b), pick(f64::min), "{}", S::NAME);
        assert_eq!(a.max(b), pick(f64::max), "{}", S::NAME);
        assert_eq!(a.abs(), v::<S>(back(a).map(f64::abs)), "{}", S::NAME);
        let most = back(a).into_iter().fold(f64::NEG_INFINITY, f64::max);
        assert_eq!(a.max_element().to_f64(), most, "{}", S::NAME);
        let s = S::from_f64(rng.range(-100.0, 100.0));
        assert_eq!(Vec3::splat(s), Vec3::new(s, s, s), "{}", S::NAME);
        let small = v::<S>(rng.point(10.0));
        let sq = common::dot(back(small), back(small));
        let err = (small.length_squared().to_f64() - sq).abs();
        assert!(
            err <= S::spacing(300.0),
            "{}: length_squared {err:e}",
            S::NAME
        );
        let Some(n) = b.try_normalize() else { continue };
        let (a64, n64) = (back(a), back(n));
        let along = common::scale(n64, common::dot(a64, n64));
        let across = common::sub(a64, along);
        // The dot product's rounding times the unit vector, and each product's.
        let tol = 4.0 * S::spacing(200.0);
        let err = common::norm(common::sub(back(a.project_onto_normalized(n)), along));
        assert!(err <= tol, "{}: project {err:e}", S::NAME);
        let err = common::norm(common::sub(back(a.reject_from_normalized(n)), across));
        assert!(err <= tol, "{}: reject {err:e}", S::NAME);
        // Twice the part along `n` taken away: its rounding twice.
        let bounced = common::sub(a64, common::scale(along, 2.0));
        let err = common::norm(common::sub(back(a.reflect(n)), bounced));
        assert!(err <= 2.0 * tol, "{}: reflect {err:e}", S::NAME);
    }
}

/// What a game developer reaches for from glam: the signed axes and `ONE`, `min_element`,
/// `element_sum`, `with_*`, `distance_squared`, `length_recip`, `normalize_or`,
/// `is_normalized`, projections onto and across any vector, `clamp`, `clamp_length_max`,
/// `move_towards`, `angle_between`, `s * v`, `v * w`, `Sum`, `Display` and tuples: exact where
/// they select or copy components, else against `f64` on the same rounded inputs.
fn glam_helpers_agree_with_f64<S>()
where
    S: Tolerance + core::fmt::Display + core::ops::Mul<Vec3<S>, Output = Vec3<S>>,
{
    let (x, y, z) = (Vec3::<S>::X, Vec3::<S>::Y, Vec3::<S>::Z);
    assert_eq!(
        (Vec3::NEG_X, Vec3::NEG_Y, Vec3::NEG_Z),
        (-x, -y, -z),
        "{}",
        S::NAME
    );
    assert_eq!(Vec3::<S>::ONE, x + y + z, "{}", S::NAME);
    let mut rng = Rng(0x61A3);
    let tol = |m: f64| 4.0 * S::spacing(m);
    for _ in 0..10_000 {
        let (a, b) = (v::<S>(rng.point(100.0)), v::<S>(rng.point(100.0)));
        let (a64, b64) = (back(a), back(b));
        let least = a64.into_iter().fold(f64::INFINITY, f64::min);
        assert_eq!(a.min_element().to_f64(), least, "{}", S::NAME);
        let sum = a64[0] + a64[1] + a64[2];
        let err = (a.element_sum().to_f64() - sum).abs();
        assert!(err <= tol(300.0), "{}: element_sum {err:e}", S::NAME);
        let s = S::from_f64(rng.range(-100.0, 100.0));
        let with = (a.with_x(s), a.with_y(s), a.with_z(s));
        let want = (
            Vec3::new(s, a.y, a.z),
            Vec3::new(a.x, s, a.z),
            Vec3::new(a.x, a.y, s),
        );
        assert_eq!(with, want, "{}", S::NAME);
        assert_eq!(a.clamp(a.min(b), a.max(b)), a, "{}", S::NAME);
        let (lo, hi) = (v::<S>([-10.0; 3]), v::<S>([10.0; 3]));
        let clamped = v::<S>(a64.map(|c| c.clamp(-10.0, 10.0)));
        assert_eq!(a.clamp(lo, hi), clamped, "{}", S::NAME);
        // Squares within I16F16's range: coordinates within ±5.
        let (c, d) = (v::<S>(rng.point(5.0)), v::<S>(rng.point(5.0)));
        let gap = common::sub(back(d), back(c));
        let err = (c.distance_squared(d).to_f64() - common::dot(gap, gap)).abs();
        assert!(err <= tol(300.0), "{}: distance_squared {err:e}", S::NAME);
        let length = common::norm(b64);
        if length > 1.0 {
            let err = (b.length_recip().to_f64() - 1.0 / length).abs();
            assert!(err <= tol(1.0), "{}: length_recip {err:e}", S::NAME);
        }
        let n = b.try_normalize().unwrap();
        assert_eq!(b.normalize_or(x), n, "{}", S::NAME);
        assert_eq!(Vec3::ZERO.normalize_or(x), x, "{}", S::NAME);
        assert!(
            n.is_normalized() && !(n * S::from_f64(1.01)).is_normalized(),
            "{}",
            S::NAME
        );
        let n64 = common::scale(b64, 1.0 / length);
        let along = common::scale(n64, common::dot(a64, n64));
        let err = common::norm(common::sub(back(a.project_onto(b)), along));
        assert!(err <= tol(200.0), "{}: project_onto {err:e}", S::NAME);
        let err = common::norm(common::sub(back(a.reject_from(b)), common::sub(a64, along)));
        assert!(err <= tol(200.0), "{}: reject_from {err:e}", S::NAME);
        let cap = S::from_f64(rng.range(0.5, 200.0));
        let capped = back(a.clamp_length_max(cap));
        let want = common::scale(a64, (cap.to_f64() / common::norm(a64)).min(1.0));
        let err = common::norm(common::sub(capped, want));
        assert!(err <= tol(200.0), "{}: clamp_length_max {err:e}", S::NAME);
        let step = S::from_f64(rng.range(0.0, 200.0));
        let gap = common::norm(common::sub(b64, a64));
        let moved = back(a.move_towards(b, step));
        let t = (step.to_f64() / gap).min(1.0);
        let want = common::add(a64, common::scale(common::sub(b64, a64), t));
        let err = common::norm(common::sub(moved, want));
        assert!(err <= tol(200.0), "{}: move_towards {err:e}", S::NAME);
        let cos = common::dot(a64, b64) / (common::norm(a64) * length);
        let angle = a.angle_between(b).unwrap().to_f64();
        // acos magnifies the cosine's rounding near 0 and π: its square root.
        let err = (angle - cos.clamp(-1.0, 1.0).acos()).abs();
        assert!(
            err <= 4.0 * S::spacing(1.0).sqrt(),
            "{}: angle_between {err:e}",
            S::NAME
        );
        assert_eq!(s * a, a * s, "{}", S::NAME);
        assert_eq!(
            a * b,
            Vec3::new(
                Scalar::mul(a.x, b.x),
                Scalar::mul(a.y, b.y),
                Scalar::mul(a.z, b.z)
            ),
            "{}",
            S::NAME
        );
        assert_eq!([a, b].iter().sum::<Vec3<S>>(), a + b, "{}", S::NAME);
        assert_eq!([a, b].into_iter().sum::<Vec3<S>>(), a + b, "{}", S::NAME);
        let t: (S, S, S) = a.into();
        assert_eq!(Vec3::from(t), a, "{}", S::NAME);
    }
    assert_eq!(Vec3::<S>::ZERO.angle_between(x), None, "{}", S::NAME);
    let shown = Vec3::new(S::ONE, S::from_f64(-2.5), S::ZERO).to_string();
    let want = format!("[{}, {}, {}]", S::ONE, S::from_f64(-2.5), S::ZERO);
    assert_eq!(shown, want, "{}", S::NAME);
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn arithmetic_mirrors() {
            arithmetic_mirrors_with_sign::<$t>();
        }
        #[test]
        fn dot_cross_length() {
            dot_cross_and_length_hold_inside_the_safe_range::<$t>();
        }
        #[test]
        fn length_saturates() {
            length_saturates_beyond_the_range::<$t>();
        }
        #[test]
        fn helpers() {
            helpers_agree_with_f64::<$t>();
        }
        #[test]
        fn components_and_projections() {
            components_and_projections_agree_with_f64::<$t>();
        }
        #[test]
        fn glam_helpers() {
            glam_helpers_agree_with_f64::<$t>();
        }
        #[test]
        fn conversions() {
            conversions_round_trip::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
