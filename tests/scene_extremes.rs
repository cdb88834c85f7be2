//! Scene-level extremes, each named after its case: slivers inside a mesh, meshes far from the
//! origin, balls starting in contact, zero-length sweeps, NaN and infinities, rays (radius 0)
//! and very large radii, in every scalar.

mod common;

use ballcast::{Error, Input, Scalar, Scene, Sweep, Triangle, move_and_slide};
use common::{P, Rng, Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// A floor at height `at[1]` facing +y over [at - 8, at + 8]² in x and z: 4 × 4 quads, two
/// triangles each, one quad's triangle split into a 1000 : 1 sliver and the rest.
fn floor<S: Scalar>(at: P) -> Scene<S, 40> {
    let mut s = Scene::new();
    let p = |x: f64, z: f64| v::<S>([at[0] + x, at[1], at[2] + z]);
    for i in 0..4 {
        for j in 0..4 {
            let (x, z) = (-8.0 + 4.0 * i as f64, -8.0 + 4.0 * j as f64);
            let (a, b, c, d) = (p(x, z), p(x, z + 4.0), p(x + 4.0, z + 4.0), p(x + 4.0, z));
            if (i, j) == (1, 1) {
                // a-c-d split at a point 1/256 off the diagonal's midpoint: a sliver a-m-c.
                let m = p(x + 2.0 + 1.0 / 256.0, z + 2.0 - 1.0 / 256.0);
                s.push(Triangle::new(a, b, c)).unwrap();
                s.push(Triangle::new(a, c, m)).unwrap();
                s.push(Triangle::new(a, m, d)).unwrap();
                s.push(Triangle::new(m, c, d)).unwrap();
            } else {
                s.push(Triangle::new(a, b, c)).unwrap();
                s.push(Triangle::new(a, c, d)).unwrap();
            }
        }
    }
    s
}

/// Drops onto the floor at `at` (a share of them on seams and on the sliver); none passes.
fn drops_hold<S: Tolerance>(at: P, r: f64) {
    let scene = floor::<S>(at);
    let mut rng = Rng(0xF1005);
    for k in 0..5_000 {
        let (mut x, mut z) = (rng.range(-6.0, 6.0), rng.range(-6.0, 6.0));
        match k % 3 {
            0 => x = (x / 4.0).round() * 4.0,
            1 => {
                // On the sliver between the diagonal (-4,-4)-(0,0) and the point just off it.
                let t = rng.range(0.0, 1.0);
                let d = rng.range(0.0, 2.0 / 256.0) * t.min(1.0 - t);
                (x, z) = (-4.0 + 4.0 * t + d, -4.0 + 4.0 * t - d);
            }
            _ => {}
        }
        let p0 = [at[0] + x, at[1] + r + rng.range(0.5, 3.0), at[2] + z];
        let p1 = [
            at[0] + x + rng.range(-0.5, 0.5),
            at[1] - 2.0,
            at[2] + z + rng.range(-0.5, 0.5),
        ];
        let s = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
        let hit = scene.cast(&s);
        assert!(
            hit.is_some(),
            "{}: {p0:?} -> {p1:?} r {r} passed through",
            S::NAME
        );
    }
}

fn sliver_inside_a_mesh<S: Tolerance>() {
    drops_hold::<S>([0.0; 3], 0.25);
}

fn mesh_far_from_the_origin<S: Tolerance>() {
    let far = if S::RELATIVE {
        1e4
    } else {
        S::LIMIT.to_f64() - 16.0
    };
    drops_hold::<S>([far, -far, far], 0.25);
}

fn ray_radius_zero<S: Tolerance>() {
    drops_hold::<S>([0.0; 3], 0.0);
}

fn very_large_radius<S: Tolerance>() {
    // A ball half the floor wide, dropped from high above: it lands on the floor's face.
    let r = 8.0;
    let scene = floor::<S>([0.0; 3]);
    let s = Sweep::new(
        v::<S>([0.5, 40.0, 0.5]),
        v([0.5, -1.0, 0.5]),
        S::from_f64(r),
    )
    .unwrap();
    let hit = scene.cast(&s).unwrap();
    let want = (40.0 - r) / 41.0;
    assert!((hit.alpha.to_f64() - want).abs() * 41.0 <= S::DISTANCE + 41.0 * S::EPSILON.to_f64());
}

fn ball_starting_in_contact<S: Tolerance>() {
    let scene = floor::<S>([0.0; 3]);
    let r = 0.5;
    // Resting exactly on the floor, and a hair inside it: pushed down and sideways, it slides
    // sideways and sinks no further.
    for start in [r, r - 16.0 * S::EPSILON.to_f64()] {
        let out = move_and_slide(
            &scene,
            v::<S>([1.0, start, 1.0]),
            v([1.5, -0.5, 0.0]),
            S::from_f64(r),
        );
        let p = common::back(out.unwrap().position);
        assert!(p[1] >= start - S::DISTANCE, "{}: sank to {}", S::NAME, p[1]);
        assert!(
            (p[0] - 2.5).abs() <= 1e-2,
            "{}: did not slide: {p:?}",
            S::NAME
        );
    }
}

fn zero_length_sweep<S: Tolerance>() {
    let scene = floor::<S>([0.0; 3]);
    // A ball overlapping the floor that does not move away is touching it at alpha 0, pushed
    // straight up; one clear of it touches nothing.
    let p = v::<S>([1.0, 0.25, 1.0]);
    let hit = scene
        .cast(&Sweep::new(p, p, S::from_f64(0.5)).unwrap())
        .unwrap();
    assert_eq!((hit.alpha, hit.normal), (S::ZERO, v::<S>([0.0, 1.0, 0.0])));
    let clear = v::<S>([1.0, 0.75, 1.0]);
    assert_eq!(
        scene.cast(&Sweep::new(clear, clear, S::from_f64(0.5)).unwrap()),
        None
    );
    let z = v::<S>([0.0; 3]);
    // Standing still while overlapping by 0.25, the response first pushes it straight out.
    let out = move_and_slide(&scene, p, z, S::from_f64(0.5)).unwrap();
    assert_eq!((out.position.x, out.position.z), (p.x, p.z));
    let y = out.position.y.to_f64();
    assert!(y >= 0.5 - S::DISTANCE && y < 0.51, "{}: y {y}", S::NAME);
    assert_eq!(out.pushed_out, out.position - p);
}

fn nan_and_infinity_are_refused_at_the_boundary<S: Tolerance>() {
    let mut scene = floor::<S>([0.0; 3]);
    let p = v::<S>([1.0, 1.0, 1.0]);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let d = v::<S>([0.0, bad, 0.0]);
        let e = move_and_slide(&scene, p, d, S::ONE).unwrap_err();
        // Fixed point has no NaN: conversion maps it beyond the range.
        if S::RELATIVE && bad.is_nan() {
            let input = Input::Displacement;
            assert_eq!(
                e,
                Error::NaN {
                    input,
                    triangle: None
                }
            );
        } else {
            assert!(matches!(e, Error::OutOfRange { .. }), "{e:?}");
        }
        // The scene names the triangle the value was found in (the one it would have been)
        // and its vertex: the same value, found in another input.
        let index = scene.len();
        let pushed = scene.push(Triangle::new(p, d, v([2.0, 0.0, 0.0])));
        let (input, triangle) = (Input::Vertex(1), Some(index));
        let want = match e {
            Error::NaN { .. } => Error::NaN { input, triangle },
            Error::OutOfRange {
                value, min, max, ..
            } => Error::OutOfRange {
                input,
                value,
                min,
                max,
                triangle,
            },
            other => other,
        };
        assert_eq!(pushed, Err(want));
        assert_eq!(pushed.unwrap_err().triangle(), Some(index));
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)] // the fixed-point types, unused where $t is a float
        use super::*;
        #[test] fn sliver_inside_a_mesh() { super::sliver_inside_a_mesh::<$t>() }
        #[test] fn mesh_far_from_the_origin() { super::mesh_far_from_the_origin::<$t>() }
        #[test] fn ray_radius_zero() { super::ray_radius_zero::<$t>() }
        #[test] fn very_large_radius() { super::very_large_radius::<$t>() }
        #[test] fn ball_starting_in_contact() { super::ball_starting_in_contact::<$t>() }
        #[test] fn zero_length_sweep() { super::zero_length_sweep::<$t>() }
        #[test] fn nan_and_infinity_are_refused_at_the_boundary() {
            super::nan_and_infinity_are_refused_at_the_boundary::<$t>()
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
