//! Short sweeps (no longer on any axis than the tree's pad, so `Mesh` and `CompactMesh` walk
//! their trees with integer box tests) against the linear scan over the same prepared
//! triangles, bit for bit: balls that end or pass at the radius (within a few roundings) from a
//! vertex, an edge or a face, falls onto faces, zero-length sweeps, radii from zero to many
//! cells, meshes from tiny to the scalar's range, slivers and duplicates. Every property in
//! every scalar.

mod common;
mod meshes;

use ballcast::{CompactMesh, Degenerates, Scalar, Sweep, Triangle};
use common::{P, Rng, add, cross, norm, scale, sub, v};
use fixed::types::{I16F16, I32F32};
use meshes::{boxes, build, heightfield, indexed, soup, tri};

/// A unit vector square to `u`.
fn square_to(rng: &mut Rng, u: P) -> P {
    let w = cross(u, rng.point(1.0));
    scale(w, 1.0 / norm(w))
}

/// A short sweep near a feature of a random triangle of `src` (`unit`: the mesh's scale):
/// start, end and radius.
fn short_sweep(rng: &mut Rng, src: &[[P; 3]], unit: f64, k: usize) -> (P, P, f64) {
    let t = src[(rng.next() * src.len() as f64) as usize];
    let i = (rng.next() * 3.0) as usize;
    // A vertex, a point of an edge or of the face.
    let f = match k % 3 {
        0 => t[i],
        1 => add(t[i], scale(sub(t[(i + 1) % 3], t[i]), rng.next())),
        _ => {
            let (a, b) = (rng.next(), rng.next());
            let (a, b) = if a + b > 1.0 {
                (1.0 - a, 1.0 - b)
            } else {
                (a, b)
            };
            add(
                t[0],
                add(scale(sub(t[1], t[0]), a), scale(sub(t[2], t[0]), b)),
            )
        }
    };
    let r = unit
        * match (k / 3) % 5 {
            0 => 0.0,
            1 => 10f64.powf(rng.range(-9.0, -3.0)),
            2 | 3 => rng.range(0.01, 1.0),
            _ => rng.range(1.0, 40.0),
        };
    let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    let n = if norm(n) > 0.0 {
        scale(n, 1.0 / norm(n))
    } else {
        [0.0, 1.0, 0.0]
    };
    // How far from the feature the centre comes: the radius, give or take a few roundings.
    let at = |rng: &mut Rng| {
        r * [
            1.0,
            1.0 + 1e-7,
            1.0 - 1e-7,
            rng.range(0.9, 1.1),
            1.0 + 1e-15,
        ][(rng.next() * 5.0) as usize]
    };
    // The move: zero, a step, or up to a little over the radius per axis.
    let length = match (rng.next() * 6.0) as usize {
        0 => 0.0,
        1 => unit * 1e-6 * rng.next(),
        2 => r * 1.2 * rng.next(),
        _ => r * rng.next(),
    };
    match (rng.next() * 4.0) as usize {
        // Passing the feature at the radius, the closest point anywhere on the path.
        0 => {
            let u = scale(rng.point(1.0), 1.0);
            let u = scale(u, 1.0 / norm(u));
            let o = square_to(rng, u);
            let closest = add(f, scale(o, at(rng)));
            let before = length * rng.next();
            (
                sub(closest, scale(u, before)),
                add(closest, scale(u, length - before)),
                r,
            )
        }
        // Ending at the radius from the feature, coming from anywhere.
        1 => {
            let o = rng.point(1.0);
            let o = scale(o, 1.0 / norm(o));
            let p1 = add(f, scale(o, at(rng)));
            let u = rng.point(1.0);
            let u = scale(u, 1.0 / norm(u));
            (sub(p1, scale(u, length)), p1, r)
        }
        // Falling onto the face along its normal (either side), reaching the radius at the end.
        2 => {
            let side = if rng.next() < 0.5 { 1.0 } else { -1.0 };
            let p1 = add(f, scale(n, side * at(rng)));
            (add(p1, scale(n, side * length)), p1, r)
        }
        // Sliding along the plane at the radius.
        _ => {
            let p0 = add(f, scale(n, at(rng)));
            let o = square_to(rng, n);
            (p0, add(p0, scale(o, length)), r)
        }
    }
}

/// The tree's answer (mesh and compact mesh) against the linear scan for `sweeps` short sweeps
/// on `src`, whose scale is `unit`. Returns the number of hits.
fn check<S: Scalar>(rng: &mut Rng, src: &[[P; 3]], unit: f64, sweeps: usize) -> usize {
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Skip).unwrap();
    let (mesh, reference) = (owned.mesh(), owned.reference());
    let (vertices, indices) = indexed::<S>(src);
    let n = mesh.len();
    let (mut t, mut o, mut b) = (vec![[0u32; 3]; n], vec![0u32; n], vec![0u8; n]);
    let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b);
    let compact = compact.ok();
    assert!(compact.is_some(), "compact");
    let mut hits = 0;
    for k in 0..sweeps {
        let (p0, p1, r) = short_sweep(rng, src, unit, k);
        let Ok(sweep) = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)) else {
            continue;
        };
        let (got, want) = (mesh.cast(&sweep), reference(&sweep));
        let what = format!("sweep {k}: {p0:?} -> {p1:?}, r {r:e}");
        assert_eq!(got, want, "mesh, {what}");
        if let Some(c) = &compact {
            let mine = c.cast(&sweep);
            assert_eq!(format!("{mine:?}"), format!("{want:?}"), "compact, {what}");
        }
        hits += got.is_some() as usize;
    }
    hits
}

fn scaled(src: Vec<[P; 3]>, by: f64) -> Vec<[P; 3]> {
    src.into_iter()
        .map(|t| t.map(|p| p.map(|c| c * by)))
        .collect()
}

/// Meshes at several scales, down to the smallest the scalar resolves well and up to its range.
fn short_sweeps_n<S: Scalar>(seeds: core::ops::Range<u64>, sweeps: usize) {
    let limit = S::LIMIT.to_f64();
    let units: Vec<f64> = if S::PRECISION.relative {
        vec![1.0, (-40f64).exp2(), limit / 64.0, 0.1]
    } else {
        vec![1.0, (-5f64).exp2(), limit / 64.0, 0.3]
    };
    let (mut hits, mut total) = (0, 0);
    for seed in seeds {
        let mut rng = Rng(0x5407_0000 ^ seed << 12);
        for &unit in &units {
            let shapes = [
                heightfield(&mut rng, 12, 1.0, 0.65),
                // Flat: every interior edge inactive, seams far reaching.
                heightfield(&mut rng, 8, 1.0, 0.0),
                // Flat slivers 1000 times longer than wide: face contacts far beyond corners.
                heightfield(&mut rng, 8, 1.0, 0.0)
                    .into_iter()
                    .map(|t| t.map(|p| [p[0], p[1], p[2] / 1024.0]))
                    .collect(),
                boxes(&mut rng, 16, 5.0),
                soup(&mut rng, 200, 4.0),
            ];
            for src in shapes {
                let src = scaled(src, unit);
                hits += check::<S>(&mut rng, &src, unit, sweeps);
                total += sweeps;
            }
        }
        // The range's edges: a coarse terrain across the whole range, corners at ±LIMIT.
        let mut src = heightfield(&mut rng, 8, limit / 4.0, limit / 64.0);
        let l = limit;
        src.push([[-l, -l, -l], [-l, -l, l], [l, -l, l]]);
        src.push([[l, l, l], [l, l, -l], [-l, l, -l]]);
        hits += check::<S>(&mut rng, &src, limit / 16.0, sweeps);
        total += sweeps;
    }
    assert!(hits > total / 10, "{hits} hits of {total}");
}

fn short_sweeps_match_linear_scan<S: Scalar>() {
    short_sweeps_n::<S>(0..1, 150);
}

fn short_sweeps_match_linear_scan_long<S: Scalar>() {
    short_sweeps_n::<S>(0..40, 2000);
}

meshes::per_scalar!(
    short_sweeps_match_linear_scan,
    short_sweeps_match_linear_scan_long #[ignore = "10^6 sweeps per scalar: run with --release -- --ignored"],
);
