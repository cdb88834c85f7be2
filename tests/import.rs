//! Scenes from what tools export: a vertex array with an index buffer, any iterator of
//! triangles, `clear`; triangles converted between scalars. Every property in every scalar.

mod common;

use ballcast::{Error, Scalar, Scene, Triangle, Vec3};
use common::v;
use fixed::types::{I16F16, I32F32};

/// A 3 × 3 grid of vertices on the floor, and the index buffer of its eight triangles.
fn grid<S: Scalar>() -> (Vec<Vec3<S>>, Vec<u32>) {
    let verts = (0..9)
        .map(|k| v([f64::from(k % 3), 0.0, f64::from(k / 3)]))
        .collect();
    let mut idx = Vec::new();
    for (i, j) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let a = j * 3 + i;
        // Counter-clockwise seen from +y.
        idx.extend([a, a + 3, a + 4, a, a + 4, a + 1]);
    }
    (verts, idx)
}

/// The scene from an index buffer is the scene of the same triangles pushed one by one.
fn index_buffer_scene_equals_pushes<S: Scalar>() {
    let (verts, idx) = grid::<S>();
    let scene: Scene<S, 8> = Scene::from_indexed(&verts, &idx).unwrap();
    let mut pushed: Scene<S, 8> = Scene::new();
    for t in idx.chunks(3) {
        let c = |k: usize| verts[t[k] as usize];
        pushed.push(Triangle::new(c(0), c(1), c(2))).unwrap();
    }
    assert_eq!(scene.len(), 8);
    assert!(scene.sources().eq(pushed.sources()));
    for i in 0..8 {
        assert_eq!(scene.triangle(i), pushed.triangle(i));
    }
    // The same from 16-bit indices.
    let short: Vec<u16> = idx.iter().map(|&i| i as u16).collect();
    let from_short: Scene<S, 8> = Scene::from_indexed(&verts, &short).unwrap();
    assert!(from_short.sources().eq(scene.sources()));
}

/// A bad vertex index names the triangle and the index, before anything is pushed.
fn index_buffer_names_triangle_and_bad_vertex<S: Scalar>() {
    let (verts, mut idx) = grid::<S>();
    idx[16] = 9;
    let mut scene: Scene<S, 16> = Scene::new();
    scene
        .push(Triangle::new(
            v([0.0; 3]),
            v([0.0, 0.0, 1.0]),
            v([1.0, 0.0, 0.0]),
        ))
        .unwrap();
    let e = scene.extend_indexed(&verts, &idx).unwrap_err();
    // Buffer triangle 5 (index 16 / 3) would have been scene triangle 6.
    assert_eq!(
        e,
        Error::VertexIndex {
            triangle: 6,
            index: 9,
            vertices: 9
        }
    );
    assert_eq!(scene.len(), 1);
    assert_eq!(
        Scene::<S, 16>::from_indexed(&verts, &idx[..7]).unwrap_err(),
        Error::IndexCount { len: 7 }
    );
}

/// A degenerate triangle in an index buffer names its triangle.
fn degenerate_in_index_buffer_names_its_triangle<S: Scalar>() {
    let (verts, mut idx) = grid::<S>();
    idx[9..12].copy_from_slice(&[0, 1, 2]); // collinear: the grid's first row
    let e = Scene::<S, 8>::from_indexed(&verts, &idx).unwrap_err();
    assert_eq!(e, Error::Degenerate { triangle: Some(3) });
}

/// Collecting triangles into a scene, extending and clearing it.
fn collect_extend_and_clear<S: Scalar>() {
    let (verts, idx) = grid::<S>();
    let tris = || {
        idx.chunks(3).map(|t| {
            Triangle::new(
                verts[t[0] as usize],
                verts[t[1] as usize],
                verts[t[2] as usize],
            )
        })
    };
    let mut scene: Scene<S, 8> = tris().collect::<Result<_, _>>().unwrap();
    let from_indexed: Scene<S, 8> = Scene::from_indexed(&verts, &idx).unwrap();
    assert!(scene.sources().eq(from_indexed.sources()));
    let small: Result<Scene<S, 5>, _> = tris().collect();
    assert_eq!(small.unwrap_err(), Error::Full { capacity: 5 });
    scene.clear();
    assert!(scene.is_empty());
    scene.try_extend(tris().take(3)).unwrap();
    assert_eq!(scene.len(), 3);
    assert_eq!(scene.try_extend(tris()), Err(Error::Full { capacity: 8 }));
}

/// A triangle converts to every scalar that can hold it, and is refused, with its value and
/// the vertex that holds it, by one that cannot.
fn triangle_try_cast_refuses_what_does_not_fit<S: Scalar>() {
    let t: Triangle<f64> = Triangle::new(v([0.5; 3]), v([-2.25, 0.0, 1.0]), v([1.0, 3.0, 0.0]));
    let c = t.try_cast::<S>().unwrap();
    assert_eq!(c.try_cast::<f64>().unwrap(), t);
    let far = S::LIMIT.to_f64() * 4.0;
    let t: Triangle<f64> = Triangle::new(v([0.5; 3]), v([far, 0.0, 1.0]), v([1.0, 3.0, 0.0]));
    let l = S::LIMIT.to_f64();
    assert_eq!(
        t.try_cast::<S>(),
        Err(Error::OutOfRange {
            input: ballcast::Input::Vertex(1),
            value: far,
            min: -l,
            max: l,
            triangle: None
        })
    );
}

/// A negative index (as OBJ writes relative ones, if passed on unresolved) and one beyond
/// `usize` are named as the buffer holds them, not as a wrapped or saturated number.
#[test]
fn negative_and_huge_indices_are_named_as_read() {
    let (verts, _) = grid::<f32>();
    let e = Scene::<f32, 8>::from_indexed(&verts, &[0i32, 1, 2, 0, -1, 2]).unwrap_err();
    let want = Error::VertexIndex {
        triangle: 1,
        index: -1,
        vertices: 9,
    };
    assert_eq!(e, want);
    assert_eq!(e.to_string(), "triangle 1: vertex index -1 is negative");
    let huge = u128::from(u64::MAX) + 5;
    let e = Scene::<f32, 8>::from_indexed(&verts, &[0, huge, 2]).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!("triangle 0: vertex index {huge} is beyond the 9 vertices")
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)] // the fixed-point types, unused where $t is a float
        use super::*;
        #[test] fn index_buffer_scene_equals_pushes() {
            super::index_buffer_scene_equals_pushes::<$t>()
        }
        #[test] fn index_buffer_names_triangle_and_bad_vertex() {
            super::index_buffer_names_triangle_and_bad_vertex::<$t>()
        }
        #[test] fn degenerate_in_index_buffer_names_its_triangle() {
            super::degenerate_in_index_buffer_names_its_triangle::<$t>()
        }
        #[test] fn collect_extend_and_clear() { super::collect_extend_and_clear::<$t>() }
        #[test] fn triangle_try_cast_refuses_what_does_not_fit() {
            super::triangle_try_cast_refuses_what_does_not_fit::<$t>()
        }
    })*};
}
per_scalar!(f32_: f32, f64_: f64, i16f16: I16F16, i32f32: I32F32);
