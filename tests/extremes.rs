//! Inputs at the edges: degenerate and sliver triangles, far from the origin, tiny and huge
//! radii, grazing paths, values at and just past the safe range, NaN and infinities. In debug
//! builds (how `cargo test` runs) every fixed-point or integer overflow would panic, so these
//! also show that nothing overflows inside the range.

mod common;

use ballcast::{
    Error, Features, Input, Scalar, StandardSweep, StandardTriangle, Sweep, Triangle, Vec3,
};
use common::{Case, P, Tolerance, model, v};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;

fn tri<S: Scalar>(t: [P; 3]) -> Result<StandardTriangle<S>, Error> {
    StandardTriangle::new(&Triangle::new(v(t[0]), v(t[1]), v(t[2])))
}

/// Runs a case in `S` and checks it against the f64 model on the same rounded inputs, allowing
/// the tolerance table's error plus `slack` (for cases that scale rounding up, e.g. far away).
fn agrees<S: Tolerance>(case: Case, slack: f64) {
    let c = case.rounded::<S>();
    let m = model(&c).expect("well-shaped");
    let got = c.run::<S>().expect("valid input");
    match (got, m.hit) {
        (Some((alpha, n)), Some(beta)) => {
            let err = (alpha - beta).abs() * m.approach;
            let allowed = S::DISTANCE + S::EPSILON.to_f64() / 2.0 * m.approach + slack;
            assert!(
                err <= allowed,
                "distance error {err:e} > {allowed:e} on {c:?}"
            );
            let tilt = common::angle(n, m.normal);
            assert!(tilt <= S::ANGLE + slack, "normal off by {tilt:e} on {c:?}");
        }
        (None, None) => {}
        (got, want) => assert!(
            m.margin <= 2.0 * S::DISTANCE + slack,
            "got {got:?}, model {want:?} on {c:?}"
        ),
    }
}

fn coincident_vertices_are_degenerate<S: Scalar>() {
    let t = [[1.0, 2.0, 3.0], [1.0, 2.0, 3.0], [4.0, 0.0, 0.0]];
    assert_eq!(tri::<S>(t), Err(Error::Degenerate { triangle: None }));
}

fn collinear_vertices_are_degenerate<S: Scalar>() {
    let t = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]];
    assert_eq!(tri::<S>(t), Err(Error::Degenerate { triangle: None }));
    // Nearly collinear, but below the scalar's precision: still refused, never a wild normal.
    let e = S::EPSILON.to_f64() / 4.0;
    let t = [[0.0, 0.0, 0.0], [1.0, 1.0 + e, 1.0], [2.0, 2.0, 2.0]];
    assert_eq!(tri::<S>(t), Err(Error::Degenerate { triangle: None }));
}

/// A long thin triangle (1000 : 1) tilted out of the axes is accepted and behaves like f64.
fn sliver_is_accepted<S: Tolerance>() {
    let t = [[-5.0, 0.0, 0.0], [0.0, 0.004, 0.01], [5.0, 0.002, 0.0]];
    assert!(tri::<S>(t).is_ok());
    // Slivers make the normal ill-conditioned: allow the normal's own rounding over the
    // sliver's sine (~2e-3) on top of the table.
    let slack = 8.0 * S::EPSILON.to_f64() / 2e-3;
    agrees::<S>(
        Case {
            tri: t,
            p0: [0.5, 3.0, 0.004],
            p1: [0.6, -3.0, 0.003],
            r: 0.5,
        },
        slack,
    );
    agrees::<S>(
        Case {
            tri: t,
            p0: [0.5, 3.0, 0.5],
            p1: [0.6, -3.0, 0.5],
            r: 0.5,
        },
        slack,
    );
}

/// The same tilted triangle and path at the far edge of the safe range. Fixed-point keeps its
/// absolute accuracy; floats lose it in proportion to the magnitude.
fn far_from_the_origin<S: Tolerance>() {
    let at = 0.9 * S::LIMIT.to_f64();
    let shift = |p: P| [p[0] + at, p[1] - at, p[2] + at];
    let t = [[0.0, 0.0, 0.0], [1.0, 0.5, 6.0], [7.0, -1.0, 0.5]].map(shift);
    let slack = 64.0 * S::spacing(at);
    for (p0, p1) in [
        ([2.0, 5.0, 2.0], [2.5, -4.0, 1.5]),
        ([3.0, 4.0, 1.0], [3.0, 0.2, 1.0]),
    ] {
        agrees::<S>(
            Case {
                tri: t,
                p0: shift(p0),
                p1: shift(p1),
                r: 1.0,
            },
            slack,
        );
    }
}

/// Radius 0 is a ray: it hits when the centre reaches the face.
fn zero_radius_is_a_ray<S: Scalar>() {
    let st = tri::<S>([[0.0, 0.0, 0.0], [1.0, 0.0, 4.0], [4.0, 0.0, 0.0]]).unwrap();
    let s = Sweep::new(v([2.0, 2.0, 1.0]), v([2.0, -2.0, 1.0]), S::ZERO).unwrap();
    assert_eq!(st.face_collision(&s).unwrap().alpha.to_f64(), 0.5);
}

/// A ball a quarter of the range across, falling across half of it: all exact.
fn huge_radius<S: Scalar>() {
    let l = S::LIMIT.to_f64();
    let st = tri::<S>([[-l, 0.0, -l], [0.0, 0.0, l], [l, 0.0, -l]]).unwrap();
    let s = Sweep::new(
        v([0.0, l / 2.0, 0.0]),
        v([0.0, -l / 2.0, 0.0]),
        S::from_f64(l / 4.0),
    );
    assert_eq!(st.face_collision(&s.unwrap()).unwrap().alpha.to_f64(), 0.25);
}

/// A path whose height changes by two of the scalar's steps over a long run: beta is still
/// computed without overflow and lands where it should.
fn grazing_path<S: Scalar>() {
    let st = tri::<S>([[0.0, 0.0, 0.0], [1.0, 0.0, 4.0], [4.0, 0.0, 0.0]]).unwrap();
    let d = S::EPSILON.to_f64();
    let s = Sweep::new(v([0.5, 1.0 + d, 1.0]), v([3.5, 1.0 - d, 1.0]), S::ONE).unwrap();
    assert_eq!(st.face_collision(&s).unwrap().alpha.to_f64(), 0.5);
    // Nearly parallel and far: q' = (0, 0, 1) lies beyond edge v0-v1.
    let s = Sweep::new(v([-100.0, 1.0 + d, 1.0]), v([100.0, 1.0 - d, 1.0]), S::ONE).unwrap();
    assert_eq!(st.face_collision(&s), None);
}

fn safe_range_is_accepted_and_enforced<S: Scalar>() {
    let l = S::LIMIT.to_f64();
    let past = l * (1.0 + 2.0 * S::EPSILON.to_f64());
    let ok = Sweep::new(v([l, -l, l]), v([-l, l, -l]), S::LIMIT);
    assert!(ok.is_ok());
    // The error names the value and the range it left.
    let e = |input, value: f64| Error::OutOfRange {
        input,
        value: S::from_f64(value).to_f64(),
        min: -l,
        max: l,
        triangle: None,
    };
    let sweep = |p0, p1, r| Sweep::new(v(p0), v(p1), r).unwrap_err();
    let start = sweep([past, 0.0, 0.0], [0.0; 3], S::ONE);
    assert_eq!(start, e(Input::Start, past));
    let end = sweep([0.0; 3], [0.0, -past, 0.0], S::ONE);
    assert_eq!(end, e(Input::End, -past));
    // A radius's range starts at zero (a negative one is its own error).
    let radius = sweep([0.0; 3], [0.0; 3], S::from_f64(past));
    assert_eq!(radius, from_zero(e(Input::Radius, past)));
    let t = tri::<S>([[0.0; 3], [0.0, 0.0, past], [1.0, 0.0, 0.0]]);
    assert_eq!(t.unwrap_err(), e(Input::Vertex(1), past));
    let st = tri::<S>([[0.0; 3], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]).unwrap();
    let point = st.to_standard(v([0.0, past, 0.0])).unwrap_err();
    assert_eq!(point, e(Input::Point, past));
    // Standard-frame coordinates may reach 3.5 * LIMIT, no further.
    let s = 3.5 * l;
    assert!(StandardSweep::new(v([s, -s, s]), v([-s, s, -s]), S::ONE).is_ok());
    let beyond = s * (1.0 + 2.0 * S::EPSILON.to_f64());
    let refused = StandardSweep::new(v::<S>([beyond, 0.0, 0.0]), v([0.0; 3]), S::ONE);
    let max = S::from_f64(s).to_f64();
    assert!(matches!(refused, Err(Error::OutOfRange { max: m, .. }) if m == max));
    // Conversions saturate and map NaN far out of range, so it is refused, not read as zero.
    assert!(Sweep::new(v([f64::NAN, 0.0, 0.0]), v([0.0; 3]), S::ONE).is_err());
    assert!(Sweep::new(v([f64::INFINITY, 0.0, 0.0]), v([0.0; 3]), S::ONE).is_err());
    assert!(tri::<S>([[0.0; 3], [0.0, f64::NEG_INFINITY, 1.0], [1.0, 0.0, 0.0]]).is_err());
}

fn negative_radius_is_refused<S: Scalar>() {
    let e = Sweep::new(v([0.0; 3]), v([1.0, 0.0, 0.0]), S::from_f64(-0.5));
    assert_eq!(e, Err(Error::NegativeRadius { value: -0.5 }));
}

fn non_finite_floats_are_refused<S: Scalar>() {
    let z = Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY].map(S::from_f64) {
        let p = Vec3::new(S::ZERO, bad, S::ZERO);
        // NaN is its own cause; an infinity is a value out of range.
        let expected = |input| {
            if bad.partial_cmp(&bad).is_none() {
                Error::NaN {
                    input,
                    triangle: None,
                }
            } else {
                Error::OutOfRange {
                    input,
                    value: bad.to_f64(),
                    min: -S::LIMIT.to_f64(),
                    max: S::LIMIT.to_f64(),
                    triangle: None,
                }
            }
        };
        assert_eq!(Sweep::new(p, z, S::ONE), Err(expected(Input::Start)));
        // A radius of minus infinity is negative; plus infinity is beyond [0, LIMIT].
        let radius = if bad < S::ZERO {
            Error::NegativeRadius {
                value: bad.to_f64(),
            }
        } else {
            from_zero(expected(Input::Radius))
        };
        assert_eq!(Sweep::new(z, z, bad), Err(radius));
        let t = Triangle::new(z, p, Vec3::new(S::ONE, S::ZERO, S::ZERO));
        assert_eq!(StandardTriangle::new(&t), Err(expected(Input::Vertex(1))));
    }
}

/// The same error with its range starting at zero, as a radius's does.
fn from_zero(e: Error) -> Error {
    match e {
        Error::OutOfRange {
            input, value, max, ..
        } => Error::OutOfRange {
            input,
            value,
            min: 0.0,
            max,
            triangle: None,
        },
        other => other,
    }
}

/// Picks a coordinate at either end of the range or anywhere inside it.
fn coordinate(l: f64) -> impl Strategy<Value = f64> {
    prop_oneof![Just(l), Just(-l), -l..l]
}

fn corner_point(l: f64) -> impl Strategy<Value = P> {
    prop::array::uniform3(coordinate(l))
}

/// Any accepted triangle and sweep, however extreme, gives an answer without overflow, and a
/// hit satisfies 0 <= alpha < 1 with a unit normal.
/// A sliver (0.0018 high) whose two edges at its sharp corners are seams: each moved out by
/// the seam margin, they met 0.6 beyond the corner, and a ball whose path never comes within
/// 0.365 of the triangle (r 0.17) was reported touching its face.
fn widened_sliver_corner_stays_near<S: Tolerance>() {
    let t = [
        [3.8828763259097885, -1.4775439352996464, -2.9486994813149447],
        [3.3954474101151346, -3.098011811628493, -3.9640802851463306],
        [3.599405042514466, -2.4207848943236403, -3.5408750007330485],
    ];
    let st = StandardTriangle::new(&Triangle::new(v::<S>(t[0]), v(t[1]), v(t[2])))
        .unwrap()
        .with_features(Features::from_bits(0b11_0010));
    let (p0, p1) = (
        [4.260809181802298, -3.9962184193367642, -3.681434435710541],
        [4.105157007645481, 2.408867078549952, -1.3315960042265251],
    );
    let s = Sweep::new(v(p0), v(p1), S::from_f64(0.16984595652341705)).unwrap();
    assert_eq!(st.cast(&s), None, "{}", S::NAME);
}

fn anything_accepted_is_answered<S: Tolerance>(t: [P; 3], p0: P, p1: P, r: f64) {
    let Ok(st) = tri::<S>(t) else { return };
    let s = Sweep::new(v(p0), v(p1), S::from_f64(r)).unwrap();
    if let Some(h) = st.face_collision(&s) {
        let a = h.alpha.to_f64();
        assert!((0.0..1.0).contains(&a), "alpha {a}");
        let len = common::norm(common::back(h.normal));
        assert!(
            (len - 1.0).abs() <= 4.0 * S::EPSILON.to_f64(),
            "normal length {len}"
        );
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test] fn coincident_vertices_are_degenerate() { super::coincident_vertices_are_degenerate::<$t>() }
        #[test] fn collinear_vertices_are_degenerate() { super::collinear_vertices_are_degenerate::<$t>() }
        #[test] fn sliver_is_accepted() { super::sliver_is_accepted::<$t>() }
        #[test] fn far_from_the_origin() { super::far_from_the_origin::<$t>() }
        #[test] fn zero_radius_is_a_ray() { super::zero_radius_is_a_ray::<$t>() }
        #[test] fn huge_radius() { super::huge_radius::<$t>() }
        #[test] fn grazing_path() { super::grazing_path::<$t>() }
        #[test] fn safe_range_is_accepted_and_enforced() { super::safe_range_is_accepted_and_enforced::<$t>() }
        #[test] fn negative_radius_is_refused() { super::negative_radius_is_refused::<$t>() }
        #[test] fn widened_sliver_corner_stays_near() { super::widened_sliver_corner_stays_near::<$t>() }
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(2000))]
            #[test]
            fn anything_accepted_is_answered_at_the_range_edges(
                t in prop::array::uniform3(corner_point(<$t>::LIMIT.to_f64())),
                p0 in corner_point(<$t>::LIMIT.to_f64()),
                p1 in corner_point(<$t>::LIMIT.to_f64()),
                r in coordinate(<$t>::LIMIT.to_f64()).prop_map(f64::abs),
            ) {
                super::anything_accepted_is_answered::<$t>(t, p0, p1, r);
            }
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);

#[test]
fn non_finite_f32_is_refused() {
    non_finite_floats_are_refused::<f32>();
}

#[test]
fn non_finite_f64_is_refused() {
    non_finite_floats_are_refused::<f64>();
}
