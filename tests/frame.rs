//! Properties of the standard frame, for every scalar: v0 → origin, v2 → (x2, 0, 0) with
//! x2 > 0, v1 → (x1, 0, z1) with z1 > 0, axes orthonormal and right-handed, y along the front
//! normal (v1 - v0) × (v2 - v0).

mod common;

use ballcast::{Scalar, StandardTriangle, Triangle};
use common::{P, back, cross, dot, norm, sub, v};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;

fn check_frame<S: Scalar>(tri: [P; 3]) -> Result<(), TestCaseError> {
    let t = tri.map(v::<S>);
    let tri = t.map(back); // the rounded inputs
    let sin = norm(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0])))
        / (norm(sub(tri[1], tri[0])) * norm(sub(tri[2], tri[0])));
    prop_assume!(sin > 1e-3);
    let st = StandardTriangle::new(&Triangle::new(t[0], t[1], t[2])).unwrap();
    let eps = S::EPSILON.to_f64();
    let size = norm(sub(tri[1], tri[0])).max(norm(sub(tri[2], tri[0])));
    // A standard coordinate is a dot product rounded once in S: allow a few of S's steps at the
    // triangle's size.
    let near = |a: f64, b: f64| (a - b).abs() <= 4.0 * eps * size.max(1.0);

    let [o, a, b] = t.map(|p| back(st.to_standard(p).unwrap()));
    prop_assert_eq!(o, [0.0, 0.0, 0.0]);
    let [_, sv1, sv2] = st.vertices().map(back);
    prop_assert!(
        sv2[0] > 0.0 && sv1[2] > 0.0,
        "x2 = {}, z1 = {}",
        sv2[0],
        sv1[2]
    );
    prop_assert!(
        near(b[0], sv2[0]) && near(b[1], 0.0) && near(b[2], 0.0),
        "v2 → {b:?}"
    );
    prop_assert!(
        near(a[0], sv1[0]) && near(a[1], 0.0) && near(a[2], sv1[2]),
        "v1 → {a:?}"
    );

    let [ux, uy, uz] = st.axes().map(back);
    for (p, q, want) in [
        (ux, ux, 1.0),
        (uy, uy, 1.0),
        (uz, uz, 1.0),
        (ux, uy, 0.0),
        (uy, uz, 0.0),
        (uz, ux, 0.0),
    ] {
        prop_assert!(
            (dot(p, q) - want).abs() <= 4.0 * eps,
            "axes {ux:?} {uy:?} {uz:?}"
        );
    }
    prop_assert!(common::angle(cross(ux, uy), uz) <= 8.0 * eps, "left-handed");
    let n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]));
    prop_assert!(
        common::angle(n, uy) <= 8.0 * eps / sin,
        "y is not the front normal"
    );
    prop_assert_eq!(back(st.normal()), uy);
    Ok(())
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(1000))]
            #[test]
            fn frame_is_standard_orthonormal_and_right_handed(
                tri in prop::array::uniform3(prop::array::uniform3(-10.0..10.0f64))
            ) {
                check_frame::<$t>(tri)?;
            }
            #[test]
            fn frame_is_standard_far_from_the_origin(
                tri in prop::array::uniform3(prop::array::uniform3(-10.0..10.0f64)),
                at in prop::array::uniform3(-4000.0..4000.0f64),
            ) {
                check_frame::<$t>(tri.map(|p| common::add(p, at)))?;
            }
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
