//! The culls pass by only triangles that `cast` would not touch: checked against the full
//! test on random and grazing sweeps, in every scalar.

use super::Path;
use crate::xorshift::Rng;
use crate::{Features, Scalar, StandardTriangle, Sweep, Triangle, Vec3};

fn point<S: Scalar>(p: [f64; 3]) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}

fn add(a: [f64; 3], b: [f64; 3], k: f64) -> [f64; 3] {
    [0, 1, 2].map(|i| a[i] + k * b[i])
}

/// How far from the origin triangles may lie: most of the safe range (fixed point), or as far
/// as a triangle of side one keeps a thousandth of a unit's precision (floats).
fn far<S: Scalar>() -> f64 {
    if S::PRECISION.relative {
        1e-3 / S::PRECISION.epsilon
    } else {
        0.9 * S::PRECISION.limit
    }
}

/// A random triangle of side about one, within 4 of a centre `c`: a terrain-like one, a random
/// one or a sliver.
fn triangle(rng: &mut Rng, k: usize, c: [f64; 3]) -> [[f64; 3]; 3] {
    let c = add(c, [rng.signed(), rng.signed(), rng.signed()], 3.0);
    let mut v = [0, 1, 2].map(|_| add(c, [rng.signed(), rng.signed(), rng.signed()], 1.0));
    match k % 3 {
        // Nearly flat, as a terrain's cells.
        0 => v.iter_mut().for_each(|p| p[1] = c[1] + 0.2 * (p[1] - c[1])),
        // A sliver: the third vertex close to the line of the first two.
        1 => {
            let t = 0.5 + 0.4 * rng.signed();
            v[2] = [0, 1, 2].map(|a| v[0][a] + t * (v[1][a] - v[0][a]) + 0.02 * rng.signed());
        }
        _ => {}
    }
    v
}

/// Whether the culls keep the triangle for this sweep, as the compact mesh asks them: by the
/// plane tests alone, and with the edges too.
fn kept<S: Scalar>(
    sweep: &Sweep<S>,
    v: [[f64; 3]; 3],
    two_sided: bool,
    (extent, class): (f64, u8),
) -> (bool, bool) {
    let path = Path::new(sweep, extent, class);
    let lo = [0, 1, 2].map(|a| v[0][a].min(v[1][a]).min(v[2][a]));
    let hi = [0, 1, 2].map(|a| v[0][a].max(v[1][a]).max(v[2][a]));
    let span = path.clip(lo, hi, 1.0);
    let plane = span.is_some_and(|span| path.near_plane(v, span, !two_sided));
    let edges = span.is_some_and(|span| path.near_triangle(v, span, !two_sided));
    (plane, edges)
}

/// Random sweeps (rays and large balls among them), and sweeps past each edge's line at the
/// radius, at the seam margin and at multiples of them, give or take a few steps: every one the
/// culls pass by misses the prepared triangle (with all features, or none, whose seams widen
/// the face), one- and two-sided, near the origin and far from it.
fn culls_pass_by_only_misses<S: Scalar>() {
    let mut rng = Rng(0xc011_5eed);
    let (mut passed, mut grazing_hits, mut checked) = (0, 0, 0);
    for k in 0..800 {
        let centre = if k % 4 == 1 {
            [0, 1, 2].map(|_| far::<S>() * rng.signed())
        } else {
            [0.0; 3]
        };
        let v = triangle(&mut rng, k, centre);
        let magnitude = v.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs())) + 4.0;
        // A step of the coordinates here.
        let step = if S::PRECISION.relative {
            S::PRECISION.epsilon * magnitude
        } else {
            S::PRECISION.epsilon
        };
        let Ok(st) = StandardTriangle::new(&Triangle::new(point(v[0]), point(v[1]), point(v[2])))
        else {
            continue;
        };
        let exact = v.map(|p| point::<S>(p).to_array().map(S::to_f64));
        let two_sided = k % 4 == 3;
        let features = if k % 2 == 0 {
            Features::ALL
        } else {
            Features::from_bits(0)
        };
        let st = st.with_features(features).with_two_sided(two_sided);
        let class = (magnitude + 8.0, crate::bvh::class_of(&st) as u8);
        let mut check = |p0: [f64; 3], p1: [f64; 3], r: f64, grazing: bool| {
            let Ok(sweep) = Sweep::new(point(p0), point(p1), S::from_f64(r)) else {
                return;
            };
            let hit = st.cast(&sweep);
            checked += 1;
            grazing_hits += (grazing && hit.is_some()) as usize;
            let (plane, edges) = kept(&sweep, exact, two_sided, class);
            if !edges {
                // Only by the edges: what this test is for.
                passed += plane as usize;
                assert!(hit.is_none(), "{v:?} {p0:?} -> {p1:?} r {r}: {hit:?}");
            }
        };
        for _ in 0..40 {
            let mid = [0, 1, 2].map(|a| (v[0][a] + v[1][a] + v[2][a]) / 3.0);
            let p0 = add(mid, [rng.signed(), rng.signed(), rng.signed()], 1.5);
            let p1 = add(p0, [rng.signed(), rng.signed(), rng.signed()], 1.5);
            let r = match k % 7 {
                0 => 0.0,
                1 => 1.0 + rng.signed(),
                _ => 0.05 + 0.5 * (rng.signed() + 1.0),
            };
            check(p0, p1, r, false);
        }
        // Grazing: beside each edge, outward in the plane by the radius (plus the seam
        // margin r / 64 at most) and a few steps, sliding along it or coming down onto it.
        let e = [0, 1, 2].map(|i| add(exact[(i + 1) % 3], exact[i], -1.0));
        let n = super::cross(e[0], add(exact[2], exact[0], -1.0));
        let unit = |a: [f64; 3]| a.map(|x| x / super::dot(a, a).sqrt());
        let n = unit(n);
        for i in 0..3 {
            let out = unit(super::cross(e[i], n));
            let r = 0.1 + 0.2 * (rng.signed() + 1.0);
            let at = add(exact[i], e[i], 0.5 + 0.4 * rng.signed());
            // Distances r (1 + f): the edge's reach, and (f near −1) the seams' r / 64.
            let seams = [-1.0 + 1.0 / 128.0, -1.0 + 1.0 / 64.0, -1.0 + 1.0 / 32.0];
            let reach = [-0.01, -1e-3, -1e-4, 0.0, 1e-4, 1.0 / 64.0, 0.05, 0.1, 0.3];
            for f in seams.into_iter().chain(reach) {
                for s in -3..=3 {
                    let beside = add(at, out, r * (1.0 + f) + s as f64 * step);
                    let along = unit(e[i]);
                    check(add(beside, along, -0.3), add(beside, along, 0.3), r, true);
                    let above = add(beside, n, r + 0.2);
                    check(above, add(add(beside, n, -0.2), along, 0.1), r, true);
                }
            }
        }
    }
    assert!(
        passed > checked / 10 && grazing_hits > 1000,
        "{passed} of {checked} passed by the edges alone, {grazing_hits} grazing hits"
    );
}

crate::testing::per_scalar!(culls_pass_by_only_misses);
