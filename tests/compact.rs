//! `CompactMesh` against the prepared `Mesh` it compacts: the same answers, bit for bit, on
//! heightfields, closed boxes and soups (a fourth of their triangles two-sided); buffers too
//! small, indices beyond `u16` and triangles that are not the mesh's are errors. Every property
//! in every scalar.

mod common;
mod meshes;

use ballcast::bvh::LeafSize;
use ballcast::penetration::penetration;
use ballcast::plan::Memory;
use ballcast::winding::winding;
use ballcast::{
    CompactError, CompactMesh, Degenerates, Geometry, Heightfield, HeightfieldShape, Scalar, Sweep,
    Vec3,
};
use common::{P, Rng, v};
use fixed::types::{I16F16, I32F32};
use meshes::{boxes, build, build_sided, heightfield, indexed, soup, tri};

fn matches_prepared_mesh<S: Scalar>() {
    let mut rng = Rng(0xc0_4ac7);
    let shapes = [
        (heightfield(&mut rng, 12, 1.0, 0.65), 6.0),
        (boxes(&mut rng, 16, 5.0), 6.0),
        (soup(&mut rng, 200, 4.0), 5.0),
    ];
    let mut hits = 0;
    for (src, half) in shapes {
        let (vertices, indices) = indexed::<S>(&src);
        let input: Vec<_> = src.iter().map(|&t| tri::<S>(t)).collect();
        // Every fourth triangle two-sided: the compact form keeps the side in its byte. On the
        // tree with leaves of four, the one a compact mesh is meant to borrow.
        let four = Degenerates::Skip.with_leaf_size(LeafSize::Four);
        let owned = build_sided(&input, |i: usize| i.is_multiple_of(4), four).unwrap();
        let mesh = owned.mesh();
        let n = mesh.len();
        let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
        let compact =
            CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
        assert_eq!(compact.len(), n);
        for k in 0..1000 {
            let (p0, p1, r) = match k % 10 {
                0..6 => (rng.point(half), rng.point(half), rng.range(0.05, 1.0)),
                // Along a triangle's plane, starting on it or near it.
                6 | 7 => meshes::along_plane(&mut rng, &src),
                // A long path grazing an edge or vertex at the radius.
                _ => {
                    let length = rng.range(50.0, 250.0);
                    meshes::grazing(&mut rng, &src, length)
                }
            };
            let r = S::from_f64(r);
            let sweep = Sweep::new(v::<S>(p0), v(p1), r).unwrap();
            let (x, y) = (compact.cast(&sweep), mesh.cast(&sweep));
            assert_eq!(format!("{x:?}"), format!("{y:?}"), "{p0:?} -> {p1:?}");
            hits += x.is_some() as usize;
        }
    }
    assert!(hits > 300, "{hits} hits");
}

fn errors_not_panics<S: Scalar>() {
    let mut rng = Rng(0xc0_4ac8);
    let src = heightfield(&mut rng, 4, 1.0, 0.5);
    let (vertices, indices) = indexed::<S>(&src);
    let input: Vec<_> = src.iter().map(|&t| tri::<S>(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    let n = mesh.len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
    let short = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o[..n - 1], &mut b);
    let capacity = CompactError::Capacity {
        needed: n,
        given: n - 1,
    };
    assert_eq!(short.map(|_| ()), Err(capacity));
    // Another winding of triangle 5: not what the mesh prepared.
    let mut other = indices.clone();
    other[5].swap(1, 2);
    let wrong = CompactMesh::compact(&mesh, &vertices, &other, &mut t, &mut o, &mut b);
    assert_eq!(wrong.map(|_| ()), Err(CompactError::Mismatch { index: 5 }));
    // An index into no vertex, named (it read as a mismatch).
    other[5] = [0, 1, vertices.len() as u32];
    let missing = CompactMesh::compact(&mesh, &vertices, &other, &mut t, &mut o, &mut b);
    let vertex = CompactError::MissingVertex {
        index: 5,
        vertex: vertices.len(),
        given: vertices.len(),
    };
    assert_eq!(missing.map(|_| ()), Err(vertex));
    // Fewer index triples than the mesh's triangles, named (it read as a mismatch).
    let few = CompactMesh::compact(&mesh, &vertices, &indices[..3], &mut t, &mut o, &mut b);
    let e = few.map(|_| ()).unwrap_err();
    assert!(
        matches!(e, CompactError::MissingTriangle { index, given: 3 } if index >= 3),
        "{e:?}"
    );
    assert!(e.to_string().contains("beyond the 3 index triples"), "{e}");
    // More vertices than u16 holds.
    let mut many = vertices.clone();
    many.resize(70_000, Vec3::ZERO);
    let wide = CompactMesh::compact(&mesh, &many, &indices, &mut t, &mut o, &mut b);
    let max = u16::MAX as usize;
    assert_eq!(
        wide.map(|_| ()),
        Err(CompactError::Index { index: 69_999, max })
    );
    // ... which u32 takes.
    let (mut t32, mut o32) = (vec![[0u32; 3]; n], vec![0u32; n]);
    assert!(CompactMesh::compact(&mesh, &many, &indices, &mut t32, &mut o32, &mut b).is_ok());
}

/// The planner's memory figures are the bytes the builds make, for each form.
fn memory_is_what_the_builds_make<S: Scalar>() {
    let mut rng = Rng(0xc0_4ac9);
    let src = heightfield(&mut rng, 12, 1.0, 0.65);
    let (vertices, indices) = indexed::<S>(&src);
    let input: Vec<_> = src.iter().map(|&t| tri::<S>(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    let n = mesh.len();
    // The compact form counted on the tree of leaves of four, the smallest.
    let four = Degenerates::Refuse.with_leaf_size(LeafSize::Four);
    let small = build(&input, four).unwrap();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
    let small = small.mesh();
    let compact =
        CompactMesh::compact(&small, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let (nodes, _, v, tris, order, bytes, _) = compact.parts();
    assert!(size_of_val(nodes) < size_of_val(mesh.nodes()));
    let heights = vec![0i16; 13 * 13];
    let mut cells = vec![0u8; 144];
    let one = S::ONE;
    let field = Heightfield::build(
        HeightfieldShape {
            origin: Vec3::ZERO,
            spacing: one,
            unit: one,
            columns: 12,
            rows: 12,
        },
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let want = Memory::of(S::PRECISION.scalar, n, vertices.len());
    assert_eq!(
        want.mesh,
        size_of_val(mesh.nodes()) + size_of_val(mesh.triangles()) + size_of_val(mesh.order())
    );
    assert_eq!(
        want.compact,
        size_of_val(nodes)
            + size_of_val(v)
            + size_of_val(tris)
            + size_of_val(order)
            + size_of_val(bytes)
    );
    assert_eq!(
        want.heightfield,
        size_of_val(field.heights()) + size_of_val(field.cells())
    );
}

/// `penetration` and `winding` on the compact mesh (the tree's box query, each triangle
/// prepared) give the prepared mesh's answers.
fn box_queries_as_mesh<S: Scalar>() {
    let mut rng = Rng(0xc0_4ac8);
    let shapes = meshes::shapes(&mut rng);
    let mut overlaps = 0;
    for src in shapes {
        let (vertices, indices) = indexed::<S>(&src);
        let input: Vec<_> = src.iter().map(|&t| tri::<S>(t)).collect();
        // Every fourth triangle two-sided: the compact form keeps the side in its byte.
        let owned = build_sided(&input, |i: usize| i.is_multiple_of(4), Degenerates::Skip).unwrap();
        let mesh = owned.mesh();
        let n = mesh.len();
        let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
        let compact =
            CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
        for _ in 0..300 {
            let t = src[(rng.next() * src.len() as f64) as usize];
            let r = rng.range(0.05, 1.0);
            let c = v::<S>([0, 1, 2].map(|a| t[1][a] + rng.range(-r, r)));
            let r = S::from_f64(r);
            let got = penetration(&compact, c, r).unwrap();
            assert_eq!(got, penetration(&mesh, c, r).unwrap(), "{c:?}");
            assert_eq!(winding(&compact, c).unwrap(), winding(&mesh, c).unwrap());
            overlaps += got.is_some() as usize;
        }
    }
    assert!(overlaps > 200, "{overlaps} overlaps");
}

meshes::per_scalar!(
    box_queries_as_mesh,
    matches_prepared_mesh,
    errors_not_panics,
    memory_is_what_the_builds_make
);

/// One sliver as a compact mesh against its prepared mesh and the linear scan, for one sweep.
fn sliver_as_prepared<S: Scalar>(src: [P; 3], p0: P, p1: P, r: f64) {
    let (vertices, indices) = indexed::<S>(&[src]);
    let owned = build(&[tri::<S>(src)], Degenerates::Refuse).unwrap();
    let (mesh, linear) = (owned.mesh(), owned.linear());
    let (mut t, mut o, mut b) = ([[0u16; 3]], [0u16], [0u8]);
    let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let sweep = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
    let want = Geometry::cast(linear.as_slice(), &sweep);
    assert!(want.is_some(), "the case is a hit");
    assert_eq!(mesh.cast(&sweep), want);
    assert_eq!(compact.cast(&sweep), want);
}

/// An `f32` sliver whose prepared normal is tilted by about 1e-3 rad (the most preparation
/// accepts): 40 units from its first vertex, its heights differ from the exact plane's by far
/// more than their rounding, and the culling once took this falling ball for one behind it.
#[test]
fn sliver_tilted_plane_f32() {
    sliver_as_prepared::<f32>(
        [
            [0.45689457654953003, 2.2589194774627686, 3.231290578842163],
            [15.634089469909668, -10.184675216674805, -2.920862913131714],
            [20.189640045166016, -13.920273780822754, -4.767704010009766],
        ],
        [42.73084259033203, 24.824304580688477, 9.174185752868652],
        [12.093356132507324, -7.281008720397949, -1.4882417917251587],
        0.005367415511745251,
    );
}

/// An `f64` sliver hit by a ray at its far end: the culling's plane test took the tilt of the
/// prepared plane for a miss.
#[test]
fn sliver_tilted_plane_f64_ray() {
    sliver_as_prepared::<f64>(
        [
            [-7.210809128199591, -12.220460684168199, 3.530667112362297],
            [9.358364125161426, -17.563310507476963, -1.618124008754043],
            [25.43436531178179, -22.747126282249468, -6.613659358855383],
        ],
        [28.444430855599272, 30.568663504892864, 29.797744859561817],
        [9.193973436247875, -17.510299157964873, -1.567038751749043],
        0.0,
    );
}

/// A ball whose lowest point meets a triangle's top edge to within rounding (`f32`): the
/// prepared triangle's overlap test finds a depth of a step or two, and the compact mesh's box
/// query, grown by the tests' rounding, offers the triangle as the mesh's does, so both answer
/// alike. Its query once took the vertices' bare box and missed it.
#[test]
fn penetration_at_rounding_depth_as_the_mesh() {
    let verts = [
        Vec3::new(-2.985_123_9_f32, -2.214_315_2, -2.855_390_3),
        Vec3::new(-2.985_123_9, 0.858_943_6, -2.855_390_3),
        Vec3::new(-1.934_750_2, 0.858_943_6, -2.855_390_3),
    ];
    let tris = [ballcast::Triangle::new(verts[0], verts[1], verts[2])];
    let owned = build(&tris, Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    let (mut t, mut o, mut b) = ([[0u16; 3]; 1], [0u16; 1], [0u8; 1]);
    let compact =
        CompactMesh::<f32, u16>::compact(&mesh, &verts, &[[0, 1, 2]], &mut t, &mut o, &mut b)
            .unwrap();
    let centre = Vec3::new(-2.459_937, 1.479_974_2, -2.855_390_3);
    let want = penetration(&mesh, centre, 0.621_030_5).unwrap();
    assert!(want.is_some_and(|p| p.depth < 1e-6), "{want:?}");
    assert_eq!(penetration(&compact, centre, 0.621_030_5).unwrap(), want);
}
