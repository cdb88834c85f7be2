//! What the `alloc` feature adds: `MeshBuf` and `HeightfieldBuf` (a mesh and a heightfield owning their parts) and `import::weld` (shared
//! vertices from a triangle soup, for `CompactMesh`). Run by CI with
//! `cargo test --all-features --test alloc`; without the feature this file is empty.
#![cfg(feature = "alloc")]

mod common;
mod meshes;

use ballcast::import::weld;
use ballcast::{
    Cached, CompactMesh, CompactMeshBuf, Compound, Degenerates, Error, Heightfield, HeightfieldBuf,
    HeightfieldError, HeightfieldShape, MeshBuf, MeshError, Sweep, Triangle, Vec3,
};
use common::{Rng, Tolerance, v};
use fixed::types::{I16F16, I32F32};
use meshes::{boxes, build_sided, heightfield, soup, tri};

/// A welded soup rebuilds the input's triangles bit for bit, shares the corners equal in value
/// (a `w × w` terrain has `(w + 1)²` vertices), and its compact mesh answers as the prepared
/// mesh; `MeshBuf` builds the parts `Mesh::build` does.
fn welded_soups_compact<S: Tolerance>() {
    let mut rng = Rng(0x0a11_0c0d);
    let w = 10;
    let shapes = [
        (heightfield(&mut rng, w, 1.0, 0.65), Some((w + 1) * (w + 1))),
        (boxes(&mut rng, 8, 5.0), None),
        (soup(&mut rng, 150, 4.0), None),
    ];
    for (src, expected) in shapes {
        let input: Vec<Triangle<S>> = src.iter().map(|&t| tri::<S>(t)).collect();
        let (vertices, indices) = weld(&input).unwrap();
        let rebuilt: Vec<Triangle<S>> = indices
            .iter()
            .map(|c| {
                let [a, b, c] = c.map(|k| vertices[k as usize]);
                Triangle::new(a, b, c)
            })
            .collect();
        assert_eq!(format!("{rebuilt:?}"), format!("{input:?}"), "{}", S::NAME);
        // No two vertices equal.
        for (i, a) in vertices.iter().enumerate() {
            assert!(
                vertices[..i].iter().all(|b| b != a),
                "{}: {a:?} twice",
                S::NAME
            );
        }
        if let Some(n) = expected {
            assert_eq!(vertices.len(), n, "{}", S::NAME);
        }
        // Every third triangle two-sided: `MeshBuf::build_sided` as `Mesh::build_sided`.
        let sided = |i: usize| i.is_multiple_of(3);
        let owned = MeshBuf::build_sided(&input, sided, Degenerates::Skip).unwrap();
        let mesh = owned.mesh();
        let reference = build_sided(&input, sided, Degenerates::Skip).unwrap();
        assert_eq!(mesh.nodes(), reference.mesh().nodes(), "{}", S::NAME);
        assert_eq!(mesh.order(), reference.mesh().order(), "{}", S::NAME);
        let same = mesh.triangles().iter().zip(reference.mesh().triangles());
        assert!(
            same.clone().all(|(a, b)| a.to_parts() == b.to_parts()),
            "{}",
            S::NAME
        );
        assert!(same.clone().any(|(a, _)| a.is_two_sided()), "{}", S::NAME);
        let n = mesh.len();
        let (mut t, mut o, mut b) = (vec![[0u32; 3]; n], vec![0u32; n], vec![0u8; n]);
        let compact =
            CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
        for _ in 0..300 {
            let (p0, p1, r) = (rng.point(6.0), rng.point(6.0), rng.range(0.05, 1.0));
            let sweep = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
            let (x, y) = (compact.cast(&sweep), mesh.cast(&sweep));
            assert_eq!(format!("{x:?}"), format!("{y:?}"), "{}", S::NAME);
        }
    }
}

/// `CompactMeshBuf` (weld, build with leaves of four, compact, in one call) answers as the
/// prepared mesh of the same triangles, two-sided ones and a degenerate one skipped among them,
/// alone and owned by a `Cached`; a NaN corner (out of range in fixed point) is refused naming its triangle.
fn compact_mesh_buf_answers_as_the_mesh<S: Tolerance>() {
    let mut rng = Rng(0x0a11_0c0e);
    let shapes = [
        heightfield(&mut rng, 10, 1.0, 0.65),
        boxes(&mut rng, 8, 5.0),
        soup(&mut rng, 150, 4.0),
    ];
    for src in shapes {
        let mut input: Vec<Triangle<S>> = src.iter().map(|&t| tri::<S>(t)).collect();
        let p = input[0].v0;
        input.insert(7, Triangle::new(p, p, input[0].v1));
        let sided = |i: usize| i.is_multiple_of(3);
        let want = MeshBuf::build_sided(&input, sided, Degenerates::Skip).unwrap();
        let owned = CompactMeshBuf::build_sided(&input, sided, Degenerates::Skip).unwrap();
        assert_eq!(owned.skipped(), 1, "{}", S::NAME);
        assert_eq!(owned.compact_mesh().len(), want.mesh().len());
        let kept: Cached<&CompactMeshBuf<S>, S, 16> = Cached::new(&owned);
        for _ in 0..300 {
            let (p0, p1, r) = (rng.point(6.0), rng.point(6.0), rng.range(0.05, 1.0));
            let sweep = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
            let y = format!("{:?}", want.cast(&sweep));
            assert_eq!(format!("{:?}", owned.cast(&sweep)), y, "{}", S::NAME);
            assert_eq!(format!("{:?}", kept.cast(&sweep)), y, "{}", S::NAME);
        }
    }
    let bad = [tri::<S>([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]); 3];
    let mut bad = bad.to_vec();
    bad[2].v1.y = S::from_f64(f64::NAN);
    let e = CompactMeshBuf::build(&bad, Degenerates::Refuse);
    assert!(
        matches!(e, Err(MeshError::Triangle { index: 2, .. })),
        "{}: {e:?}",
        S::NAME
    );
}

/// Corners equal bit for bit are one vertex; `-0.0` and `0.0` are not, so the rebuilt
/// triangles are the input's bit for bit. A NaN corner, equal to nothing, is refused with its
/// triangle named: it was once kept as a vertex of its own, and 20 000 copies of one such
/// triangle took seconds (each NaN corner compared with every other).
#[test]
fn weld_keeps_signed_zeros_apart_and_refuses_nans() {
    let v = Vec3::new;
    let a = Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 1.0), v(1.0, 0.0, 0.0));
    let b = Triangle::new(v(-0.0, -0.0, 0.0), v(1.0, 0.0, 0.0), v(2.0, 0.0, 0.0));
    let (vertices, indices) = weld(&[a, b, a, b]).unwrap();
    assert_eq!(indices, [[0, 1, 2], [3, 2, 4], [0, 1, 2], [3, 2, 4]]);
    assert_eq!(vertices.len(), 5);
    assert_eq!(vertices[3].x.to_bits(), (-0.0f32).to_bits());
    assert_eq!(weld::<f32>(&[]).unwrap(), (vec![], vec![]));
    let nan = Triangle::new(v(f32::NAN, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 0.0, 1.0));
    let mut soup = vec![a; 5];
    soup.extend(vec![nan; 20_000]);
    let corner = ballcast::Input::Vertex(0);
    let e = Error::NaN {
        input: corner,
        triangle: Some(5),
    };
    assert_eq!(weld(&soup), Err(e));
}

/// `HeightfieldBuf` holds what `Heightfield::build` makes of the same heights (cell bytes,
/// bounds, class) and answers as it, alone, lent out, as a compound's part and owned by a
/// `Cached`; it refuses what `build` refuses, with the same error.
fn heightfield_buf_answers_as_the_borrowed_build<S: Tolerance>() {
    let mut rng = Rng(0x4846_4255);
    let (w, h) = (12u32, 9u32);
    let heights: Vec<i16> = (0..(w + 1) * (h + 1))
        .map(|_| rng.range(-40.0, 40.0) as i16)
        .collect();
    let hole = |i: u32, k: u32| (i + 2 * k).is_multiple_of(7);
    let shape = HeightfieldShape {
        origin: v::<S>([-6.0, 0.5, -4.5]),
        spacing: S::ONE,
        unit: S::from_f64(1.0 / 64.0),
        columns: w,
        rows: h,
    };
    let mut cells = vec![0u8; (w * h) as usize];
    let borrowed = Heightfield::build(shape, &heights, hole, &mut cells).unwrap();
    let owned = HeightfieldBuf::build(shape, heights.clone(), hole).unwrap();
    assert_eq!(owned.heightfield(), borrowed, "{}", S::NAME);
    let kept: Cached<_, S, 16> =
        Cached::new(HeightfieldBuf::build(shape, heights.clone(), hole).unwrap());
    let wall = MeshBuf::build(
        &[tri::<S>([
            [0.0, -2.0, -5.0],
            [0.0, 3.0, 5.0],
            [0.0, 3.0, -5.0],
        ])],
        Degenerates::Refuse,
    )
    .unwrap();
    let (a, b) = (
        Compound::new(&owned, &wall).unwrap(),
        Compound::new(borrowed, &wall).unwrap(),
    );
    let mut hits = 0;
    for _ in 0..500 {
        let (p0, p1, r) = (rng.point(7.0), rng.point(7.0), rng.range(0.05, 1.0));
        let sweep = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
        let x = owned.cast(&sweep);
        assert_eq!(
            format!("{x:?}"),
            format!("{:?}", borrowed.cast(&sweep)),
            "{}",
            S::NAME
        );
        assert_eq!(
            format!("{:?}", a.cast(&sweep)),
            format!("{:?}", b.cast(&sweep))
        );
        assert_eq!(format!("{:?}", kept.cast(&sweep)), format!("{x:?}"));
        hits += x.is_some() as usize;
    }
    assert!(hits > 50, "{hits}");
    assert!(kept.cache().misses() > 0);
    assert_eq!(kept.into_geometry().heightfield(), borrowed);
    let short = HeightfieldBuf::build(shape, heights[1..].to_vec(), hole);
    let needed = ((w + 1) * (h + 1)) as usize;
    let want = HeightfieldError::Size {
        needed,
        given: needed - 1,
    };
    assert_eq!(short.map(|_| ()), Err(want));
    let huge = HeightfieldBuf::build(
        HeightfieldShape {
            columns: u32::MAX,
            rows: u32::MAX,
            ..shape
        },
        vec![],
        hole,
    );
    assert_eq!(huge.map(|_| ()), Err(HeightfieldError::TooMany));
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn welded_soups_compact_as_the_mesh() {
            welded_soups_compact::<$t>();
        }
        #[test]
        fn compact_mesh_buf_answers_as_the_mesh() {
            super::compact_mesh_buf_answers_as_the_mesh::<$t>();
        }
        #[test]
        fn heightfield_buf_answers_as_the_borrowed_build() {
            super::heightfield_buf_answers_as_the_borrowed_build::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);

/// A soup whose shared corner is `-0.0` in one triangle and `0.0` in the next (`f64`): welded
/// and compacted, a resting ball's contact is the prepared mesh's to the sign of every zero.
/// `weld` once merged the two corners, and `CompactMesh::compact`'s check (`==`) let the
/// changed triangle through, answering with zeros of the other sign.
#[test]
fn compact_after_weld_keeps_the_sign_of_zero() {
    let v = Vec3::new;
    let tris = [
        Triangle::new(v(0.0f64, -0.0, 0.0), v(5.0, 0.0, 5.0), v(5.0, 0.0, 0.0)),
        Triangle::new(v(-1.0, 0.0, 2.0), v(0.0, 0.0, 2.0), v(0.0, 0.0, 0.0)),
    ];
    let owned = MeshBuf::build(&tris, Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    let (vertices, indices) = weld(&tris).unwrap();
    let (mut t, mut o, mut b) = (vec![[0u32; 3]; 2], vec![0u32; 2], vec![0u8; 2]);
    let compact =
        CompactMesh::<f64, u32>::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b)
            .unwrap();
    let p = v(0.0, 0.075_568_628_832_092_84, 0.954_599_129_279_815_3);
    let sweep = Sweep::new(p, p, 0.151_137_257_664_185_68).unwrap();
    let (want, got) = (mesh.cast(&sweep).unwrap(), compact.cast(&sweep).unwrap());
    assert_eq!(format!("{got:?}"), format!("{want:?}"));
}
