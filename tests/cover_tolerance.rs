//! The T-junction test's tolerance against geometry only a few dozen steps of the scalar
//! across (far from the origin in a float): a neighbour counts as covering an edge only where
//! it lies beyond the edge's line, and a terrain's cells are never closer than the test can
//! tell apart, so a mesh switches off exactly the edges the heightfield does.

mod common;
mod meshes;

use ballcast::{
    Degenerates, Heightfield, HeightfieldShape, Scalar, Scene, StandardTriangle, Sweep, Triangle,
    Vec3, heightfield::HOLE,
};
use common::{Rng, v};
use fixed::types::{I16F16, I32F32};

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
            same_as_mesh(&hf, &format!("{} at {offset}, terrain {n}", name::<S>()));
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

/// T-junctions in tilted planes at magnitudes up to 10^5 (within each scalar's range): a
/// triangle whose long edge two flat neighbours cover, meeting at a vertex on it, the triangle
/// down to a sliver a hundred-thousandth as thin as it is long. The vertices are rounded to the
/// scalar, so the meeting vertex lies off the edge's line by that rounding: the tolerance must
/// still take it as on the line (an eighth of it misses some of these in `f32`, `f64` and
/// `I32F32`), and the edge goes off.
fn tilted_t_junctions_are_covered<S: Scalar>() {
    let mut rng = Rng(0x7e1a_0b0d);
    let limit = S::LIMIT.to_f64();
    let mut tried = 0;
    for n in 0..4000 {
        let magnitude = [1.0, 1e2, 1e4, 1e5][n % 4];
        if magnitude * 2.0 > limit {
            continue;
        }
        let (e1, e2) = plane(&mut rng);
        let o = [0; 3].map(|_| magnitude * rng.range(-1.0, 1.0));
        let len = rng.range(0.5, 10.0);
        let thin = len * [1e-3, 1e-4, 1e-5, 0.1][n / 4 % 4];
        let p = |u: f64, w: f64| v::<S>([0, 1, 2].map(|k| o[k] + u * e1[k] + w * e2[k]));
        let (a, b) = (p(0.0, 0.0), p(len, 0.0));
        let (m, d) = (p(len * rng.range(0.3, 0.7), 0.0), p(len * 0.5, len));
        let t = Triangle::new(a, b, p(len * 0.5, -thin));
        let tris = [t, Triangle::new(m, a, d), Triangle::new(b, m, d)];
        let prepared: Vec<_> = tris
            .iter()
            .filter_map(|t| StandardTriangle::new(t).ok())
            .collect();
        // Only triangles the scalar keeps whole, and flat together as the test asks.
        let flat = |u: &StandardTriangle<S>| {
            let d = u.normal() - prepared[0].normal();
            d.abs().max_element().to_f64() <= 1.0 / 1024.0
        };
        if prepared.len() < 3 || !prepared.iter().all(flat) {
            continue;
        }
        tried += 1;
        let owned = meshes::build(&tris, Degenerates::Refuse).unwrap();
        let f = owned.mesh().triangle(0).unwrap().features();
        assert!(
            !f.edge(0),
            "{} at {magnitude}, case {n}: {tris:?}",
            name::<S>()
        );
    }
    assert!(tried > 500, "{tried} cases");
}

/// Two orthonormal directions of a random plane.
fn plane(rng: &mut Rng) -> ([f64; 3], [f64; 3]) {
    let unit = |a: [f64; 3]| {
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        a.map(|x| x / l)
    };
    let e1 = unit([0; 3].map(|_| rng.range(-1.0, 1.0)));
    let b = [0; 3].map(|_| rng.range(-1.0, 1.0));
    let d = e1[0] * b[0] + e1[1] * b[1] + e1[2] * b[2];
    (e1, unit([0, 1, 2].map(|k| b[k] - d * e1[k])))
}

fn name<S>() -> &'static str {
    core::any::type_name::<S>()
}

meshes::per_scalar!(tilted_t_junctions_are_covered);
