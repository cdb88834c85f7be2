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

/// A hash of what `StandardTriangle::new` makes of 20 000 triangles (every byte of the parts, or
/// the error): random ones at scales 1e-3 to 1e3, slivers, repeated vertices, coordinates that
/// are exactly zero (of either sign) or equal between vertices, all orders of edge lengths.
fn prepared_hash<S: Scalar>() -> u64 {
    let mut rng = common::Rng(0x9e3a_0012);
    let mut text = String::new();
    for i in 0..20_000 {
        let scale = [1e-3, 1.0, 10.0, 1e3][i % 4];
        let mut p = [0; 3].map(|_| rng.point(scale));
        match i % 7 {
            0 => p[1] = p[0], // coincident vertices
            1 => p[2] = common::add(p[0], common::scale(sub(p[1], p[0]), 0.5)), // collinear
            2 => p.iter_mut().for_each(|q| q[1] = 0.0), // a floor
            3 => p.iter_mut().for_each(|q| q[0] = -0.0), // a wall at x = -0
            4 => p[2][2] = p[0][2], // shared coordinates
            _ => {}
        }
        let t = p.map(v::<S>);
        match StandardTriangle::new(&Triangle::new(t[0], t[1], t[2])) {
            Ok(st) => text += &format!("{:?}", st.to_parts()),
            // The error's kind, as named when the hashes were taken.
            Err(e) if e.is_degenerate() => text += "Degenerate",
            Err(e) => text += &format!("{e:?}"),
        }
    }
    text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ b as u64).wrapping_mul(0x100_0000_01b3)
    })
}

/// Preparing a triangle gives the bits these hashes were taken from: prepared triangles are
/// baked into flash and pinned in meshes, and peers in lockstep prepare their own, so a change
/// to any bit of `new` is a change to every baked level and trajectory. Re-pin only for a
/// deliberate change to the numbers, named in the changelog (the last: which origin a float
/// triangle measures heights from, `Parts::world_heights`).
#[test]
fn prepared_triangles_are_bit_identical() {
    let got = [
        prepared_hash::<f32>(),
        prepared_hash::<f64>(),
        prepared_hash::<I16F16>(),
        prepared_hash::<I32F32>(),
    ];
    assert_eq!(got, PREPARED, "{got:#x?}");
}

const PREPARED: [u64; 4] = [
    0x8fa3d2c9511dbe47,
    0xd16007115d2989b0,
    0x843991d969db8367,
    0xd2196be4b8d258c1,
];
