//! Every public entry point validates every argument, whatever the others are: with any one
//! argument NaN, infinite, beyond the safe range (or a negative radius), the call is an error,
//! never a silent `Ok`, even when the rest would make it trivial (a zero displacement, an empty
//! scene). A property test per entry point, in every scalar.

mod common;
mod meshes;

use ballcast::{
    Scalar, Scene, StandardSweep, StandardTriangle, Sweep, Triangle, Vec3, move_and_slide,
    penetration, slide::Slider, winding,
};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// An argument and whether it is bad.
type Arg = (f64, bool);

/// A coordinate: usually a good one (zero often), sometimes NaN, an infinity or beyond the
/// range (`4 * LIMIT`, beyond even the standard frame's `3.5 * LIMIT`).
fn coord<S: Scalar>() -> BoxedStrategy<Arg> {
    let l = 2.0 * S::LIMIT.to_f64();
    prop_oneof![
        3 => Just((0.0, false)),
        6 => (-10.0..10.0f64).prop_map(|x| (x, false)),
        1 => Just((f64::NAN, true)),
        1 => Just((f64::INFINITY, true)),
        1 => Just((f64::NEG_INFINITY, true)),
        1 => Just((2.0 * l, true)),
        1 => Just((-2.0 * l, true)),
    ]
    .boxed()
}

/// A radius: usually good, sometimes negative, NaN, infinite or beyond the range.
fn radius<S: Scalar>() -> BoxedStrategy<Arg> {
    let l = S::LIMIT.to_f64();
    prop_oneof![
        8 => (0.1..2.0f64).prop_map(|r| (r, false)),
        1 => Just((-1.0, true)),
        1 => Just((f64::NAN, true)),
        1 => Just((f64::INFINITY, true)),
        1 => Just((2.0 * l, true)),
    ]
    .boxed()
}

fn point<S: Scalar>() -> BoxedStrategy<([f64; 3], bool)> {
    [coord::<S>(), coord::<S>(), coord::<S>()]
        .prop_map(|a| (a.map(|c| c.0), a.iter().any(|c| c.1)))
        .boxed()
}

fn v<S: Scalar>(p: [f64; 3]) -> Vec3<S> {
    common::v(p)
}

/// Runs `body` on arguments from `args`; it returns (whether any was bad, whether the call
/// refused). A bad argument must be refused; for constructors with no other condition, good
/// ones must be accepted (`exact`).
fn holds<T: std::fmt::Debug>(
    args: impl Strategy<Value = T>,
    exact: bool,
    body: impl Fn(&T) -> (bool, bool),
) {
    TestRunner::new(Config::with_cases(256))
        .run(&args, |a| {
            let (bad, refused) = body(&a);
            prop_assert!(!bad || refused, "bad argument accepted: {a:?}");
            prop_assert!(!exact || bad || !refused, "good arguments refused: {a:?}");
            Ok(())
        })
        .unwrap();
}

/// A scene of a floor triangle near the origin.
fn scene<S: Scalar>() -> Scene<S, 2> {
    let mut s = Scene::new();
    let t = Triangle::new(
        v([-5.0, 0.0, -5.0]),
        v([-5.0, 0.0, 5.0]),
        v([5.0, 0.0, 0.0]),
    );
    s.push(t).unwrap();
    s
}

fn move_and_slide_refuses_any_bad_argument<S: Scalar>() {
    let s = scene::<S>();
    holds(
        (point::<S>(), point::<S>(), radius::<S>()),
        false,
        |(p, d, r)| {
            let got = move_and_slide(&s, v(p.0), v(d.0), S::from_f64(r.0));
            (p.1 || d.1 || r.1, got.is_err())
        },
    );
    // The case: a zero displacement in an empty scene.
    let empty: Scene<S, 1> = Scene::new();
    let z = v::<S>([0.0; 3]);
    for r in [-1.0, f64::NAN] {
        assert!(move_and_slide(&empty, z, z, S::from_f64(r)).is_err(), "{r}");
    }
}

fn slider_refuses_any_bad_argument<S: Scalar>() {
    let s = scene::<S>();
    holds((radius::<S>(), coord::<S>()), false, |(r, skin)| {
        let got = Slider::new(S::from_f64(r.0)).and_then(|b| b.with_skin(S::from_f64(skin.0)));
        (r.1 || skin.1, got.is_err())
    });
    let ball = Slider::new(S::ONE).unwrap();
    holds((point::<S>(), point::<S>()), false, |(p, d)| {
        (p.1 || d.1, ball.slide(&s, v(p.0), v(d.0)).is_err())
    });
}

fn clip_refuses_any_bad_velocity<S: Scalar>() {
    let s = scene::<S>();
    let out = move_and_slide(&s, v([0.0, 1.0, 0.0]), v([0.0, -1.0, 0.0]), S::ONE).unwrap();
    holds(point::<S>(), true, |u| (u.1, out.clip(v(u.0)).is_err()));
    let ball = Slider::new(S::ONE).unwrap();
    let ball = ball.with_max_slope(v([0.0, 1.0, 0.0]), S::ZERO).unwrap();
    holds(point::<S>(), true, |u| {
        (u.1, ball.clip(&out, v(u.0)).is_err())
    });
}

/// `floor` and `Slider::with_max_slope` take a direction `up` (components within the safe
/// range, not all zero in the scalar) and a cosine within `[0, 1]` (a floor faces up).
fn floor_refuses_any_bad_argument<S: Scalar>() {
    let s = scene::<S>();
    let out = move_and_slide(&s, v([0.0, 1.0, 0.0]), v([0.0, -1.0, 0.0]), S::ONE).unwrap();
    let limit = S::LIMIT.to_f64();
    let component = prop_oneof![
        4 => (-1.0..=1.0f64).prop_map(|x| (x, false)),
        1 => Just((0.0, false)),
        1 => (-limit..=limit).prop_map(|x| (x, false)),
        1 => Just((f64::NAN, true)),
        1 => Just((f64::INFINITY, true)),
        1 => Just((2.0 * limit, true)),
    ];
    let cosine = prop_oneof![
        4 => (0.0..=1.0f64).prop_map(|x| (x, false)),
        1 => (-1.0..=-1e-3f64).prop_map(|x| (x, true)),
        1 => Just((f64::NAN, true)),
        1 => Just((1.5, true)),
        1 => Just((-3.0, true)),
    ];
    let args = (component.clone(), component.clone(), component, cosine);
    let ball = Slider::new(S::ONE).unwrap();
    holds(args, true, |(x, y, z, c)| {
        let (up, min_cos) = (v([x.0, y.0, z.0]), S::from_f64(c.0));
        let zero = [x.0, y.0, z.0].iter().all(|&a| S::from_f64(a) == S::ZERO);
        let floor = out.floor(up, min_cos).is_err();
        // The slope limit takes the same arguments, with the same contract.
        let limit = ball.with_max_slope(up, min_cos).is_err();
        let bad = x.1 || y.1 || z.1 || c.1 || zero;
        // Refused by both if bad; by either if good (then `holds` fails).
        (bad, if bad { floor && limit } else { floor || limit })
    });
}

fn sweep_new_refuses_any_bad_argument<S: Scalar>() {
    holds(
        (point::<S>(), point::<S>(), radius::<S>()),
        true,
        |(a, b, r)| {
            let got = Sweep::new(v(a.0), v(b.0), S::from_f64(r.0));
            (a.1 || b.1 || r.1, got.is_err())
        },
    );
    holds(
        (point::<S>(), point::<S>(), radius::<S>()),
        true,
        |(a, b, r)| {
            let got = StandardSweep::new(v(a.0), v(b.0), S::from_f64(r.0));
            (a.1 || b.1 || r.1, got.is_err())
        },
    );
}

fn triangle_entry_points_refuse_any_bad_vertex<S: Scalar>() {
    // A good triangle moved by a possibly bad vertex: refused by construction and by the scene.
    holds(
        (point::<S>(), 0..3usize, any::<bool>()),
        false,
        |(p, k, two)| {
            let mut c = [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]];
            c[*k] = if p.1 { p.0 } else { c[*k] };
            let t = Triangle::new(v::<S>(c[0]), v(c[1]), v(c[2]));
            let mut s: Scene<S, 1> = Scene::new();
            let pushed = if *two { s.push_two_sided(t) } else { s.push(t) };
            let refused = StandardTriangle::new(&t).is_err();
            (p.1, refused && pushed.is_err())
        },
    );
    let st = *scene::<S>().triangle(0).unwrap();
    holds(point::<S>(), true, |p| {
        (p.1, st.to_standard(v(p.0)).is_err())
    });
}

fn mesh_build_refuses_any_bad_vertex<S: Scalar>() {
    holds((point::<S>(), 0..3usize, 0..4usize), false, |(p, k, at)| {
        let mut tris: Vec<Triangle<S>> = (0..4)
            .map(|i| {
                let x = 2.0 * i as f64;
                Triangle::new(v([x, 0.0, 0.0]), v([x, 0.0, 1.0]), v([x + 1.0, 0.0, 0.0]))
            })
            .collect();
        let mut c = tris[*at].vertices();
        if p.1 {
            c[*k] = v(p.0);
        }
        tris[*at] = Triangle::new(c[0], c[1], c[2]);
        let built = meshes::build(&tris, ballcast::Degenerates::Skip);
        let named =
            matches!(&built, Err(ballcast::MeshError::Triangle { index, .. }) if index == at);
        (p.1, built.is_err() && named)
    });
}

fn queries_refuse_any_bad_argument<S: Scalar>() {
    let s = scene::<S>();
    holds((point::<S>(), radius::<S>()), true, |(c, r)| {
        let got = penetration(&s, v(c.0), S::from_f64(r.0));
        (c.1 || r.1, got.is_err())
    });
    holds(point::<S>(), true, |p| (p.1, winding(&s, v(p.0)).is_err()));
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)] // the fixed-point types, unused where $t is a float
        use super::*;
        #[test] fn move_and_slide_refuses_any_bad_argument() {
            super::move_and_slide_refuses_any_bad_argument::<$t>()
        }
        #[test] fn slider_refuses_any_bad_argument() {
            super::slider_refuses_any_bad_argument::<$t>()
        }
        #[test] fn clip_refuses_any_bad_velocity() { super::clip_refuses_any_bad_velocity::<$t>() }
        #[test] fn floor_refuses_any_bad_argument() {
            super::floor_refuses_any_bad_argument::<$t>()
        }
        #[test] fn sweep_new_refuses_any_bad_argument() {
            super::sweep_new_refuses_any_bad_argument::<$t>()
        }
        #[test] fn triangle_entry_points_refuse_any_bad_vertex() {
            super::triangle_entry_points_refuse_any_bad_vertex::<$t>()
        }
        #[test] fn mesh_build_refuses_any_bad_vertex() {
            super::mesh_build_refuses_any_bad_vertex::<$t>()
        }
        #[test] fn queries_refuse_any_bad_argument() { super::queries_refuse_any_bad_argument::<$t>() }
    })*};
}
per_scalar!(f32_: f32, f64_: f64, i16f16: I16F16, i32f32: I32F32);
