//! The T-junction test's tolerance against geometry only a few dozen steps of the scalar
//! across (far from the origin in a float): a neighbour counts as covering an edge only where
//! it lies beyond the edge's line, and a terrain's cells are never closer than the test can
//! tell apart, so a mesh switches off exactly the edges the heightfield does.

mod common;
mod meshes;

use ballcast::{
    Degenerates, Heightfield, HeightfieldShape, Scalar, Scene, Sweep, Triangle, Vec3,
    heightfield::HOLE,
};
use common::{Rng, v};

/// Checks every kept triangle of `hf`, prepared with its active edges, against the mesh of the
/// kept triangles (in index order); returns the mesh's parts.
fn same_as_mesh<S: Scalar>(hf: &Heightfield<'_, S>, what: &str) -> meshes::Owned<S> {
    let kept: Vec<usize> = (0..hf.len())
        .filter(|&t| hf.cells()[t / 2] & HOLE == 0)
        .collect();
    let input: Vec<Triangle<S>> = kept.iter().map(|&t| hf.triangle(t).unwrap()).collect();
    let owned = meshes::build(&input, Degenerates::Refuse).unwrap();
    for (j, &t) in kept.iter().enumerate() {
        let (a, b) = (hf.prepared(t).unwrap(), *owned.mesh().triangle(j).unwrap());
        assert_eq!(a.to_parts(), b.to_parts(), "{what}: triangle {t}");
    }
    owned
}

/// The top row of a nearly flat `f32` terrain of 1/7-unit cells at 10^5, where the tolerance
/// was 0.19, more than a cell: the other half of a border cell, its bottom edge 0.15 from the
/// border's line and its apex on it, counted as covering the border edge. The mesh switched the
/// edge off and let a ball falling just outside the border sink 2 mm further, to a vertex,
/// where the heightfield stops it on the edge.
#[test]
fn the_other_half_of_a_border_cell_does_not_cover_its_edge() {
    let heights: [i16; 56] = [
        1, 0, 0, -1, 1, 1, -1, -1, 0, 0, 0, 0, 1, 1, 1, 1, 1, -1, 1, 0, 0, 1, -1, 1, 0, 1, 0, 0,
        -1, -1, 1, 0, 0, 0, 0, 1, 0, 0, 1, -1, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1, -1, 0, -1, -1, 1, 0,
    ];
    let shape = HeightfieldShape {
        origin: Vec3::new(99_999.5f32, 0.0, -100_000.5),
        spacing: (1.0f64 / 7.0) as f32,
        unit: (0.01f64 / 7.0) as f32,
        columns: 7,
        rows: 6,
    };
    let mut cells = [0u8; 42];
    let hf = Heightfield::build(shape, &heights, |_, _| false, &mut cells).unwrap();
    let owned = same_as_mesh(&hf, "border");
    let sweep = Sweep::new(
        Vec3::new(99_999.61f32, 0.691_877_5, -99_999.44),
        Vec3::new(99_999.61, -0.961_153, -99_999.44),
        0.294_747_98,
    )
    .unwrap();
    let (got, want) = (hf.cast(&sweep), owned.mesh().cast(&sweep));
    assert_eq!(got, want);
    // The border edge of triangle 70 stops the ball.
    assert_eq!(
        want.map(|h| (h.index, h.contact)),
        Some((70, ballcast::Contact::Edge(1)))
    );
}

/// A thin neighbour on an edge's own side, its edge within the tolerance of the line and its
/// apex on it (`f32` near 10^5; the apex is the midpoint of the edge's ends, exactly): it hides
/// nothing, so the edge stays on, in a mesh and in a `Scene`. Rounding put the apex a hair
/// beyond the line, and the test once counted it as covering the edge (about one such
/// neighbour in twenty, over random slants and offsets).
#[test]
fn a_neighbour_touching_the_line_from_the_edges_own_side_covers_nothing() {
    let v = |x: f32, z: f32| Vec3::new(x, 0.0, z);
    let t = Triangle::new(
        v(100_004.875, 99_998.12),
        v(100_004.29, 99_998.7),
        v(100_004.66, 99_999.445),
    );
    let n = Triangle::new(
        v(100_004.63, 99_999.44),
        v(100_004.766, 99_998.78),
        v(100_004.85, 99_998.11),
    );
    let owned = meshes::build(&[t, n], Degenerates::Refuse).unwrap();
    let mut scene: Scene<f32, 2> = Scene::new();
    scene.push(t).unwrap();
    scene.push(n).unwrap();
    for f in [
        owned.mesh().triangle(0).unwrap().features(),
        scene.triangle(0).unwrap().features(),
    ] {
        assert!((0..3).all(|e| f.edge(e)), "{f:?}");
    }
}

/// Random small terrains (up to 9 × 9 cells, nearly flat, holes) whose cells are a few dozen
/// steps of the scalar across, in `f32` and `f64`: every kept triangle is the mesh's. With
/// the tolerance of four roundings of a height it once was, a neighbour across a hole one cell
/// wide covered the hole's edges.
fn coarse_cells_prepare_as_the_mesh<S: Scalar>(offsets: &[(f64, f64)]) {
    let mut rng = Rng(0xc0a2_5e00);
    for &(offset, cell) in offsets {
        for n in 0..60 {
            let columns = 1 + (rng.next() * 9.0) as u32;
            let rows = 1 + (rng.next() * 9.0) as u32;
            let spacing = cell * rng.range(0.8, 1.2);
            let amp = (rng.next() * 3.0) as i16;
            let heights: Vec<i16> = (0..(columns + 1) * (rows + 1))
                .map(|_| (rng.range(-1.0, 1.0) * (amp as f64 + 0.99)) as i16)
                .collect();
            let holes: Vec<bool> = (0..columns * rows).map(|_| rng.next() < 0.15).collect();
            let shape = HeightfieldShape {
                origin: v::<S>([offset, 0.0, -offset]),
                spacing: S::from_f64(spacing),
                unit: S::from_f64(spacing / 100.0),
                columns,
                rows,
            };
            let mut cells = vec![0u8; (columns * rows) as usize];
            let hole = |i: u32, k: u32| holes[(k * columns + i) as usize];
            let hf = Heightfield::build(shape, &heights, hole, &mut cells).unwrap();
            let name = core::any::type_name::<S>();
            same_as_mesh(&hf, &format!("{name} at {offset}, terrain {n}"));
        }
    }
}

#[test]
fn coarse_cells_prepare_as_the_mesh_f32() {
    coarse_cells_prepare_as_the_mesh::<f32>(&[(1e5, 0.13), (1e6, 1.3), (4e6, 5.2)]);
}

#[test]
fn coarse_cells_prepare_as_the_mesh_f64() {
    coarse_cells_prepare_as_the_mesh::<f64>(&[(5e13, 0.12), (8e14, 1.9)]);
}
