//! The integer culling of fixed-point sweeps, which only targets with software `f64` take
//! (`cull::SOFT_F64`), against the `f64` culling every other target takes: the same answers.

use super::CompactMesh;
use crate::bvh::nodes_for;
use crate::cull::{Path, UnitBox};
use crate::merge::earliest_of;
use crate::xorshift::Rng;
use crate::{Degenerates, Mesh, Node, Scalar, Sweep, Triangle, TriangleCache, Vec3};
use fixed::types::{I16F16, I32F32};

/// Uniform in `[0, 1)`.
fn unit(rng: &mut Rng) -> f64 {
    (rng.signed() + 1.0) / 2.0
}

/// A bumpy 10 × 10 terrain (cells of side 1 around the origin, counter-clockwise from above)
/// and 120 random triangles above it: indexed vertices and triangles.
fn level(rng: &mut Rng) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let w = 10;
    let mut vertices: Vec<[f64; 3]> = (0..(w + 1) * (w + 1))
        .map(|k| {
            let (i, j) = ((k % (w + 1)) as f64 - 5.0, (k / (w + 1)) as f64 - 5.0);
            [i, 0.6 * unit(rng) - 0.3, j]
        })
        .collect();
    let mut indices = Vec::new();
    let at = |i: usize, j: usize| (j * (w + 1) + i) as u32;
    for j in 0..w {
        for i in 0..w {
            indices.push([at(i, j), at(i, j + 1), at(i + 1, j + 1)]);
            indices.push([at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    for _ in 0..120 {
        let c = [
            10.0 * unit(rng) - 5.0,
            3.0 * unit(rng),
            10.0 * unit(rng) - 5.0,
        ];
        let first = vertices.len() as u32;
        for _ in 0..3 {
            vertices.push(c.map(|x| x + 1.6 * unit(rng) - 0.8));
        }
        indices.push([first, first + 1, first + 2]);
    }
    (vertices, indices)
}

fn integer_culling_answers_alike<S: Scalar>() {
    let mut rng = Rng(0x1e7_b0c5);
    let (points, indices) = level(&mut rng);
    let vertices: Vec<Vec3<S>> = points
        .iter()
        .map(|p| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2])))
        .collect();
    let src: Vec<Triangle<S>> = indices
        .iter()
        .map(|t| {
            Triangle::new(
                vertices[t[0] as usize],
                vertices[t[1] as usize],
                vertices[t[2] as usize],
            )
        })
        .collect();
    let n = src.len();
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let (mut tris, mut order) = (vec![Mesh::<S>::filler(); n], vec![0u32; n]);
    let mut scratch = vec![0u64; 6 * n];
    let (mesh, _) = Mesh::build(
        &src,
        Degenerates::Skip,
        &mut nodes,
        &mut tris,
        &mut order,
        &mut scratch,
    )
    .unwrap();
    let m = mesh.len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; m], vec![0u16; m], vec![0u8; m]);
    let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let (mut hits, mut passed) = (0, 0);
    let cache: TriangleCache<S, 8> = TriangleCache::new();
    for k in 0..3000 {
        let p0 = [
            10.0 * unit(&mut rng) - 5.0,
            4.0 * unit(&mut rng) - 0.5,
            10.0 * unit(&mut rng) - 5.0,
        ];
        // Short moves (as a slide makes) and long casts.
        let reach = if k % 2 == 0 { 0.6 } else { 12.0 };
        let p1 = p0.map(|x| x + reach * (2.0 * unit(&mut rng) - 1.0));
        let point =
            |p: [f64; 3]| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
        let sweep = Sweep::new(
            point(p0),
            point(p1),
            S::from_f64(0.05 + 0.5 * unit(&mut rng)),
        )
        .unwrap();
        let (x, y) = (
            compact.cast_culled(&sweep, true),
            compact.cast_culled(&sweep, false),
        );
        assert_eq!(format!("{x:?}"), format!("{y:?}"), "{p0:?} -> {p1:?}");
        assert_eq!(format!("{x:?}"), format!("{:?}", mesh.cast(&sweep)));
        hits += x.is_some() as usize;
        // With a cache of a few slots (triangles evict each other), behind either cull, twice:
        // once preparing and keeping, once from what was kept.
        for integer in [true, false, true, false] {
            let c = cache.slots();
            let z = earliest_of(&sweep, |acc, scan| {
                compact.offer(&sweep, acc, scan, integer, c)
            });
            assert_eq!(format!("{z:?}"), format!("{x:?}"), "cached");
        }
        // The integer box does pass triangles by (the test would prove nothing otherwise).
        let units = UnitBox::new(&sweep, Path::pad(&sweep, 16.0, 0)).unwrap();
        passed += src.iter().filter(|t| units.misses(t.vertices())).count();
    }
    assert!(
        hits > 600 && passed > 1000 * n && cache.hits() > 5000,
        "{hits} hits, {passed} passed by, {} from the cache",
        cache.hits()
    );
    // Grazing: a short move beside each lone triangle's extreme vertex along an axis, at the
    // radius plus -3 to 3 steps of the scalar, where a box grown by a step too little would
    // pass by a contact the `f64` tests keep.
    let step = 1.0 / (1u64 << S::ONE.fixed_bits().map_or(0, |(_, f)| f)) as f64;
    let point = |p: [f64; 3]| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
    let mut grazed = 0;
    for t in &indices[200..] {
        let t = t.map(|i| points[i as usize]);
        for (a, side) in (0..3).flat_map(|a| [(a, 1.0), (a, -1.0)]) {
            let v = t
                .iter()
                .fold(t[0], |m, p| if side * p[a] > side * m[a] { *p } else { m });
            for k in -3..=3 {
                let mut mid = v;
                mid[a] += side * (0.25 + k as f64 * step);
                let (mut p0, mut p1) = (mid, mid);
                p0[(a + 1) % 3] -= 0.35;
                p1[(a + 1) % 3] += 0.35;
                let sweep = Sweep::new(point(p0), point(p1), S::from_f64(0.25)).unwrap();
                let (x, y) = (
                    compact.cast_culled(&sweep, true),
                    compact.cast_culled(&sweep, false),
                );
                assert_eq!(format!("{x:?}"), format!("{y:?}"), "{p0:?} -> {p1:?} {k}");
                grazed += x.is_some() as usize;
            }
        }
    }
    assert!(grazed > 1000, "{grazed} grazing hits");
}

#[test]
fn integer_culling_answers_alike_i16f16() {
    integer_culling_answers_alike::<I16F16>();
}

#[test]
fn integer_culling_answers_alike_i32f32() {
    integer_culling_answers_alike::<I32F32>();
}
