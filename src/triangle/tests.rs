//! The precomputed edges against the general computation, for every scalar: edge 2 skips
//! `direction` (its length is `x2` and its direction −x), which must change no bit.

use super::{Edge, StandardTriangle, Triangle};
use crate::{Scalar, Vec3};

use crate::xorshift::Rng;

/// `direction` of `(−len, 0, 0)` is `len` and `(direction_neg_x(len), 0, 0)` for every `len`
/// the frame can hold, from `4 * LIMIT` down to the smallest positive value (floats: down
/// through the subnormals, where `direction` takes its second path).
fn neg_x_direction_is_direction<S: Scalar>() {
    let top = 4.0 * S::LIMIT.to_f64();
    // Halvings of `top` before a value rounds to zero.
    let steps = (0..)
        .find(|&k| S::from_f64(top * 0.5f64.powi(k)) == S::ZERO)
        .unwrap_or(0);
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    for _ in 0..200_000 {
        let k = (rng.next() % steps as u64) as i32;
        let len = S::from_f64(top * rng.signed().abs() * 0.5f64.powi(k));
        if len <= S::ZERO {
            continue;
        }
        let z = S::UNIT_ZERO;
        let want = Some((len, Vec3::new(S::direction_neg_x(len), z, z)));
        assert_eq!(
            S::direction(Vec3::new(-len, S::ZERO, S::ZERO)),
            want,
            "{len:?}"
        );
    }
}

/// Every edge of a prepared triangle is `direction` of its standardized corners, for triangles
/// of every size and place within `LIMIT`, slivers among them.
fn edges_are_directions_of_the_corners<S: Scalar>() {
    let limit = S::LIMIT.to_f64();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut prepared = 0;
    for i in 0..50_000 {
        let scale = limit * 0.5f64.powi((rng.next() % 48) as i32);
        let centre = [0; 3].map(|_| rng.signed() * limit / 2.0);
        let mut corner = || centre.map(|c| c + rng.signed() * scale / 2.0);
        let (a, b, mut c) = (corner(), corner(), corner());
        if i % 4 == 0 {
            // Nearly collinear: c close to the middle of a–b.
            c = [0, 1, 2].map(|k| (a[k] + b[k]) / 2.0 + (c[k] - centre[k]) * 1e-4);
        }
        let v = |p: [f64; 3]| Vec3::new(p[0], p[1], p[2]).map(S::from_f64);
        let Ok(st) = StandardTriangle::new(&Triangle::new(v(a), v(b), v(c))) else {
            continue;
        };
        prepared += 1;
        let [v0, v1, v2] = st.vertices();
        for (i, (from, to)) in [(v0, v1), (v1, v2), (v2, v0)].into_iter().enumerate() {
            let (len, dir) = S::direction(to - from).unwrap();
            let want = Edge {
                dir: [dir.x, dir.z],
                len,
            };
            assert_eq!(st.edge(i), want, "edge {i} of {a:?} {b:?} {c:?}");
        }
    }
    // Most of them are proper triangles.
    assert!(prepared > 25_000, "{prepared}");
}

crate::testing::per_scalar!(
    neg_x_direction_is_direction,
    edges_are_directions_of_the_corners
);
