//! `Heightfield` against the same triangles in a `Mesh` and a linear scan: the same prepared
//! triangles (active edges included), the same answers bit for bit on terrains with holes,
//! steep cells and flat regions; bad grids are errors, not panics. Every property in every
//! scalar.

mod common;
mod meshes;

use ballcast::{
    Degenerates, Geometry, Heightfield, HeightfieldError, HeightfieldShape, Scalar, SceneHit,
    Sweep, Triangle, Vec3, heightfield::HOLE,
};
use common::{P, Rng, v};
use fixed::types::{I16F16, I32F32};

/// A terrain's inputs: heights, holes and frame.
struct Terrain {
    columns: u32,
    rows: u32,
    heights: Vec<i16>,
    holes: Vec<bool>,
    origin: [f64; 3],
    spacing: f64,
    unit: f64,
}

/// A random terrain of `columns × rows` cells: rolling heights with a flat block, a steep
/// block and holes (about one cell in twelve).
fn terrain(rng: &mut Rng, columns: u32, rows: u32) -> Terrain {
    let (w, h) = (columns as usize + 1, rows as usize + 1);
    let mut heights = Vec::with_capacity(w * h);
    for k in 0..h {
        for i in 0..w {
            let flat = i < w / 3 && k < h / 3;
            let steep = i > w / 2 && k > h / 2;
            let y = match () {
                _ if flat => 8,
                _ if steep => rng.range(-400.0, 400.0) as i16,
                _ => rng.range(-40.0, 40.0) as i16,
            };
            heights.push(y);
        }
    }
    let holes = (0..columns * rows)
        .map(|_| rng.next() < 1.0 / 12.0)
        .collect();
    Terrain {
        columns,
        rows,
        heights,
        holes,
        origin: [-(columns as f64) / 2.0, -0.5, -(rows as f64) / 2.0],
        spacing: [0.5, 1.0, 1.25][(rng.next() * 3.0) as usize],
        unit: 1.0 / 64.0,
    }
}

impl Terrain {
    /// The same terrain with every height `lift` steps higher and the origin as much lower:
    /// the same vertices, heights that no longer straddle zero.
    fn lifted(mut self, lift: i16) -> Self {
        self.heights.iter_mut().for_each(|h| *h += lift);
        self.origin[1] -= lift as f64 * self.unit;
        self
    }

    fn build<'a, S: Scalar>(
        &'a self,
        cells: &'a mut [u8],
    ) -> Result<Heightfield<'a, S>, HeightfieldError> {
        let (c, holes) = (self.columns, &self.holes);
        Heightfield::build(
            HeightfieldShape {
                origin: v(self.origin),
                spacing: S::from_f64(self.spacing),
                unit: S::from_f64(self.unit),
                columns: c,
                rows: self.rows,
            },
            &self.heights,
            |i, k| holes[(k * c + i) as usize],
            cells,
        )
    }
}

/// The heightfield's triangles without holes, in index order, and the index of each.
fn triangles<S: Scalar>(hf: &Heightfield<'_, S>) -> (Vec<Triangle<S>>, Vec<usize>) {
    let kept: Vec<usize> = (0..hf.len())
        .filter(|&t| hf.cells()[t / 2] & HOLE == 0)
        .collect();
    (
        kept.iter().map(|&t| hf.triangle(t).unwrap()).collect(),
        kept,
    )
}

/// Every kept triangle, prepared with its active edges, is the mesh's, byte for byte: the
/// heightfield's edge rule is the mesh's (and `Scene`'s).
fn prepared_as_mesh<S: Scalar>() {
    let mut rng = Rng(0x4f1e_0001);
    let t = terrain(&mut rng, 14, 11);
    let mut cells = vec![0u8; 14 * 11];
    let hf = t.build::<S>(&mut cells).unwrap();
    let (input, kept) = triangles(&hf);
    let owned = meshes::build(&input, Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    let mut inactive = 0;
    for (j, &t) in kept.iter().enumerate() {
        let (a, b) = (hf.prepared(t).unwrap(), *mesh.triangle(j).unwrap());
        assert_eq!(a.to_parts(), b.to_parts(), "triangle {t}");
        inactive += (0..3).filter(|&e| !a.features().edge(e)).count();
    }
    // Not vacuous: the flat block's interior edges are off.
    assert!(inactive > 20, "{inactive} inactive edges");
    assert!(hf.prepared(kept.len() * 4).is_none());
}

fn same_hit<S: Scalar>(a: Option<SceneHit<S>>, b: Option<SceneHit<S>>, what: &str) {
    assert_eq!(format!("{a:?}"), format!("{b:?}"), "{what}");
}

/// Random short moves and long casts over random terrains: the heightfield's answer is the
/// linear scan's (and the mesh's), bit for bit, with indices mapped.
fn matches_linear_scan_n<S: Scalar>(terrains: core::ops::Range<u64>, sweeps: usize) {
    let (mut hits, count) = (0, (terrains.end - terrains.start) as usize * sweeps);
    for seed in terrains {
        let mut rng = Rng(0x4f1e_0100 ^ seed << 16);
        let (c, r) = (
            4 + (rng.next() * 20.0) as u32,
            4 + (rng.next() * 20.0) as u32,
        );
        let t = terrain(&mut rng, c, r);
        // Every other terrain's heights all positive: its box is not stretched down to zero.
        let t = if seed % 2 == 1 { t.lifted(1000) } else { t };
        let mut cells = vec![0u8; (c * r) as usize];
        let hf = t.build::<S>(&mut cells).unwrap();
        let (lo, hi) = (t.heights.iter().min(), t.heights.iter().max());
        assert_eq!(Some(hf.bounds()), lo.zip(hi).map(|(l, h)| [*l, *h]));
        let (input, kept) = triangles(&hf);
        let owned = meshes::build(&input, Degenerates::Refuse).unwrap();
        let linear = owned.linear();
        let half = [c as f64 * t.spacing / 2.0, 4.0, r as f64 * t.spacing / 2.0];
        let points: Vec<[P; 3]> = input
            .iter()
            .map(|t| t.vertices().map(|p| p.to_array().map(S::to_f64)))
            .collect();
        for n in 0..sweeps {
            let p0 = [0, 1, 2].map(|a| rng.range(-half[a] - 1.0, half[a] + 1.0));
            let (p0, p1, radius) = match n % 4 {
                // A short move near where it starts.
                0 | 2 => (p0, [0, 1, 2].map(|a| p0[a] + rng.range(-0.8, 0.8)), None),
                1 => (
                    p0,
                    [0, 1, 2].map(|a| rng.range(-half[a] - 1.0, half[a] + 1.0)),
                    None,
                ),
                // A long path grazing an edge or vertex at the radius.
                _ => {
                    let length = rng.range(50.0, 250.0);
                    let (p0, p1, r) = meshes::grazing(&mut rng, &points, length);
                    (p0, p1, Some(r))
                }
            };
            let radius = S::from_f64(radius.unwrap_or_else(|| rng.range(0.05, 1.0)));
            let sweep = Sweep::new(v::<S>(p0), v(p1), radius).unwrap();
            let mut want = linear.as_slice().cast(&sweep);
            if let Some(h) = want.as_mut() {
                h.index = kept[h.index];
            }
            let got = hf.cast(&sweep);
            same_hit(
                got,
                want,
                &format!("seed {seed} sweep {n}: {p0:?} -> {p1:?}, r {radius:?}"),
            );
            let mut mesh = owned.mesh().cast(&sweep);
            if let Some(h) = mesh.as_mut() {
                h.index = kept[h.index];
            }
            same_hit(got, mesh, "mesh");
            hits += got.is_some() as usize;
        }
    }
    assert!(hits > count / 5, "{hits} hits");
}

fn matches_linear_scan<S: Scalar>() {
    matches_linear_scan_n::<S>(0..6, 400);
}

fn matches_linear_scan_long<S: Scalar>() {
    matches_linear_scan_n::<S>(0..50, 2000);
}

/// Paths along a triangle's plane, starting on it, a few roundings off it or near the radius,
/// in front or behind: the culling's test of the side the ball starts on and moves to allows
/// for the rounding of the heights `cast` decides by.
fn along_a_plane<S: Scalar>() {
    let (mut hits, mut count) = (0, 0);
    for seed in 0..4u64 {
        let mut rng = Rng(0x4f1e_0200 ^ seed << 16);
        let t = terrain(&mut rng, 12, 10);
        let mut cells = vec![0u8; 12 * 10];
        let hf = t.build::<S>(&mut cells).unwrap();
        let (input, kept) = triangles(&hf);
        let linear = meshes::build(&input, Degenerates::Refuse).unwrap().linear();
        let points: Vec<[P; 3]> = input
            .iter()
            .map(|t| t.vertices().map(|p| p.to_array().map(S::to_f64)))
            .collect();
        for n in 0..1500 {
            let (p0, p1, r) = meshes::along_plane(&mut rng, &points);
            let sweep = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
            let mut want = linear.as_slice().cast(&sweep);
            if let Some(h) = want.as_mut() {
                h.index = kept[h.index];
            }
            let got = hf.cast(&sweep);
            same_hit(
                got,
                want,
                &format!("seed {seed} sweep {n}: {p0:?} -> {p1:?}, r {r}"),
            );
            hits += got.is_some() as usize;
            count += 1;
        }
    }
    assert!(hits > count / 10, "{hits} hits of {count}");
}

/// Terrain 10 of the long run, whose sweep 1935 (a 140-unit path grazing a steep cell) meets a
/// second face within the tie window of the first: rejecting a triangle by the reach from its
/// heights alone must allow for the rounding of the contact tests, or that tie is lost.
fn tie_on_a_long_grazing_path<S: Scalar>() {
    matches_linear_scan_n::<S>(10..11, 2000);
}

/// `move_and_slide` runs on a heightfield (it is a `Geometry`) as on the same triangles' mesh.
fn slides_as_mesh<S: Scalar>() {
    let mut rng = Rng(0x4f1e_0003);
    let t = terrain(&mut rng, 10, 10);
    let mut cells = vec![0u8; 100];
    let hf = t.build::<S>(&mut cells).unwrap();
    let (input, _) = triangles(&hf);
    let owned = meshes::build(&input, Degenerates::Refuse).unwrap();
    let r = S::from_f64(0.4);
    let step = v::<S>([0.3, -0.4, 0.2]);
    let (mut a, mut b) = (v::<S>([-3.0, 3.0, -3.0]), v::<S>([-3.0, 3.0, -3.0]));
    let mut touched = 0;
    for _ in 0..40 {
        let (x, y) = (
            ballcast::move_and_slide(&hf, a, step, r).unwrap(),
            ballcast::move_and_slide(&owned.mesh(), b, step, r).unwrap(),
        );
        assert_eq!(x.position, y.position);
        touched += x.contacts.iter().flatten().count();
        (a, b) = (x.position, y.position);
    }
    assert!(touched > 0);
}

/// Bad grids are refused with the error that says why; nothing panics.
fn errors_not_panics<S: Scalar>() {
    let heights = [0i16; 9];
    let mut cells = [0u8; 4];
    let o = Vec3::<S>::ZERO;
    let (one, unit) = (S::ONE, S::from_f64(0.01));
    let build = |sp: S, c: u32, r: u32, h: &[i16], cells: &mut [u8]| {
        Heightfield::build(
            HeightfieldShape {
                origin: o,
                spacing: sp,
                unit,
                columns: c,
                rows: r,
            },
            h,
            |_, _| false,
            cells,
        )
        .map(|_| ())
    };
    let size = |needed, given| Err(HeightfieldError::Size { needed, given });
    assert_eq!(build(one, 2, 2, &heights[..8], &mut cells), size(9, 8));
    // No cells: said so (not as a size that matches).
    let empty = Err(HeightfieldError::Empty {
        columns: 0,
        rows: 2,
    });
    assert_eq!(build(one, 0, 2, &heights[..3], &mut cells), empty);
    let capacity = Err(HeightfieldError::Capacity {
        needed: 4,
        given: 3,
    });
    assert_eq!(build(one, 2, 2, &heights, &mut cells[..3]), capacity);
    assert_eq!(
        build(one, u32::MAX, u32::MAX, &heights, &mut cells),
        Err(HeightfieldError::TooMany)
    );
    for bad in [S::ZERO, S::ZERO - one] {
        assert_eq!(
            build(bad, 2, 2, &heights, &mut cells),
            Err(HeightfieldError::Spacing {
                value: bad.to_f64()
            })
        );
    }
    // Each refusal names the value: the spacing, the unit, the origin's coordinate, the
    // farthest corner.
    let limit = S::LIMIT.to_f64();
    let far = S::from_f64(limit / 1.5);
    let reach = 2.0 * far.to_f64();
    assert_eq!(
        build(far, 2, 2, &heights, &mut cells),
        Err(HeightfieldError::OutOfRange {
            value: reach,
            limit
        })
    );
    if S::PRECISION.relative {
        let nan = S::from_f64(f64::NAN);
        let bad_unit = Heightfield::build(
            HeightfieldShape {
                origin: o,
                spacing: one,
                unit: nan,
                columns: 2,
                rows: 2,
            },
            &heights,
            |_, _| false,
            &mut cells,
        );
        assert!(matches!(bad_unit, Err(HeightfieldError::Unit { value }) if value.is_nan()));
        let origin = v::<S>([0.0, f64::INFINITY, 0.0]);
        let bad_origin = Heightfield::build(
            HeightfieldShape {
                origin,
                spacing: one,
                unit,
                columns: 2,
                rows: 2,
            },
            &heights,
            |_, _| false,
            &mut cells,
        );
        let want = HeightfieldError::Origin {
            value: f64::INFINITY,
        };
        assert_eq!(bad_origin.map(|_| ()), Err(want));
    }
    // Cells one step of the scalar wide, far from the origin: closer than a mesh's T-junction
    // test can tell apart there (a float would not even keep them whole), refused as such.
    // Twice the least side the error names builds.
    let far = |spacing: S, cells: &mut [u8]| {
        let shape = HeightfieldShape {
            origin: v::<S>([S::LIMIT.to_f64() / 2.0, 0.0, 0.0]),
            spacing,
            unit,
            columns: 2,
            rows: 2,
        };
        Heightfield::build(shape, &heights, |_, _| false, cells).map(|_| ())
    };
    let Err(HeightfieldError::Fine { spacing, least }) = far(S::EPSILON, &mut cells) else {
        panic!("one step: {:?}", far(S::EPSILON, &mut cells));
    };
    assert_eq!(spacing, S::EPSILON.to_f64());
    assert!(least > spacing, "{least}");
    assert_eq!(far(S::from_f64(2.0 * least), &mut cells), Ok(()), "{least}");
}

/// A terrain across the scalar's whole safe range: built and queried, edge to edge.
fn range_edges<S: Scalar>() {
    let reach = S::LIMIT.to_f64() * 0.9;
    let mut heights = vec![0i16; 9 * 9];
    heights[40] = 1000;
    let spacing = S::from_f64(2.0 * reach / 8.0);
    let unit = S::from_f64(reach / 2000.0);
    let mut cells = [0u8; 64];
    let origin = v::<S>([-reach, 0.0, -reach]);
    let hf = Heightfield::build(
        HeightfieldShape {
            origin,
            spacing,
            unit,
            columns: 8,
            rows: 8,
        },
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let sweep = Sweep::new(
        v::<S>([0.0, reach * 0.8, 0.0]),
        v::<S>([0.0, -reach * 0.5, 0.0]),
        S::from_f64(reach / 100.0),
    )
    .unwrap();
    let hit = hf.cast(&sweep).expect("lands on the peak");
    let (input, kept) = triangles(&hf);
    let mut want = input
        .iter()
        .map(|t| ballcast::StandardTriangle::new(t).unwrap())
        .collect::<Vec<_>>();
    for (j, &t) in kept.iter().enumerate() {
        want[j] = hf.prepared(t).unwrap();
    }
    let mut want = want.as_slice().cast(&sweep);
    if let Some(h) = want.as_mut() {
        h.index = kept[h.index];
    }
    same_hit(Some(hit), want, "range edge");
}

/// A heightfield from its parts (as a `static` would be made) answers as the built one.
fn from_parts_as_built<S: Scalar>() {
    let mut rng = Rng(0x4f1e_0004);
    let t = terrain(&mut rng, 6, 5);
    let mut cells = vec![0u8; 30];
    let built = t.build::<S>(&mut cells).unwrap();
    let baked = Heightfield::from_parts(
        built.shape(),
        built.heights(),
        built.cells(),
        built.bounds(),
        built.class(),
    );
    assert_eq!(baked, built);
}

/// The heightfield's answer on the linear scan's terms: the scan over its prepared triangles
/// (holes left out), indices mapped back.
/// The linear scan over a heightfield's prepared triangles (holes left out), with its indices.
struct Scan<S: Scalar> {
    kept: Vec<usize>,
    tris: Vec<ballcast::StandardTriangle<S>>,
}

impl<S: Scalar> Scan<S> {
    fn new(hf: &Heightfield<'_, S>) -> Self {
        let (kept, tris) = (0..hf.len())
            .filter_map(|t| Some((t, hf.prepared(t)?)))
            .unzip();
        Self { kept, tris }
    }

    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        let mut want = self.tris.as_slice().cast(sweep);
        if let Some(h) = want.as_mut() {
            h.index = self.kept[h.index];
        }
        want
    }
}

/// A sweep along x whose grown path just reaches the first row it lists, where the row's edge
/// (`origin + spacing k`) and the division that found the row round apart: that row's strip is
/// missed, which once ended the walk before every row the path crosses. Spacings and origins
/// not exact in binary; the grown path's edge placed within a few steps of a row boundary
/// (the pad mirrors the culling's, `src/cull.rs`).
#[test]
fn sweep_along_x_at_a_row_boundary() {
    let mut rng = Rng(7);
    let (w, h) = (8u32, 8u32);
    let (mut differ, mut hits) = (0, 0);
    for trial in 0..400 {
        let o = [rng.range(-50.0, 50.0), 0.0, rng.range(-50.0, 50.0)];
        let sp = [0.1, 0.3, 0.7, 1.1, 0.37][trial % 5];
        let unit = 1.0 / 64.0;
        let heights: Vec<i16> = (0..(w + 1) * (h + 1))
            .map(|_| rng.range(-40.0, 40.0) as i16)
            .collect();
        let mut cells = vec![0u8; (w * h) as usize];
        let origin = Vec3::new(o[0], o[1], o[2]);
        let hf = Heightfield::build(
            HeightfieldShape {
                origin,
                spacing: sp,
                unit,
                columns: w,
                rows: h,
            },
            &heights,
            |_, _| false,
            &mut cells,
        )
        .unwrap();
        let scan = Scan::new(&hf);
        let r = 0.05;
        let (x0, x1) = (o[0] - 0.5, o[0] + sp * w as f64 + 0.5);
        let far = [sp * w as f64, unit * 32768.0, sp * h as f64];
        let extent = (0..3).fold(0.0f64, |m, a| m.max(o[a].abs() + far[a]));
        let base = o[2] + sp * (1 + trial % 5) as f64;
        let magnitude = extent.max(x0.abs()).max(x1.abs()).max(base.abs());
        let eps = f64::EPSILON;
        let seams = f64::from_bits(((1023 + hf.class().min(31) as u32) as u64) << 52);
        let pad = r
            + eps * (64.0 + 8.0 * (x1 - x0))
            + (64.0 * eps + 1.0 / (1u64 << 40) as f64) * 3.0 * magnitude
            + (r / 64.0 + 4.0 * eps) * seams;
        for j in -8i64..=8 {
            let z = f64::from_bits(((base + pad).to_bits() as i64 + j) as u64);
            let sweep = Sweep::new(Vec3::new(x0, 1.0, z), Vec3::new(x1, -1.0, z), r).unwrap();
            let (got, want) = (hf.cast(&sweep), scan.cast(&sweep));
            differ += (format!("{got:?}") != format!("{want:?}")) as usize;
            hits += want.is_some() as usize;
        }
    }
    assert_eq!(differ, 0, "{differ} sweeps differ from the scan");
    assert!(hits > 1000, "{hits} hits");
}

/// I16F16 counts columns only to 32 767: a grid of 32 770 columns would put its last vertices
/// on top of each other. Refused.
#[test]
fn i16f16_beyond_32767_columns() {
    let (w, h) = (32_770u32, 1u32);
    let heights = vec![0i16; ((w + 1) * (h + 1)) as usize];
    let mut cells = vec![0u8; (w * h) as usize];
    let sixteenth = I16F16::from_bits(1 << 12);
    let origin = v::<I16F16>([-2048.0, 0.0, 0.0]);
    let built = Heightfield::build(
        HeightfieldShape {
            origin,
            spacing: sixteenth,
            unit: sixteenth,
            columns: w,
            rows: h,
        },
        &heights,
        |_, _| false,
        &mut cells,
    );
    assert_eq!(
        built.map(|_| ()),
        Err(HeightfieldError::Sides { count: 32_770 })
    );
}

/// An `I16F16` grid whose heights (17 000 steps of 2) are only in range with an origin far
/// below the range (y = -32 000): the product of a height and its step saturates before the
/// origin is added, so the vertices would lie at 768, not at 2 000 where the walk's box
/// expects them (a ball fell through). Refused, as the origin's height is checked too.
#[test]
fn height_products_beyond_the_range_are_refused() {
    let heights = vec![17_000i16; 9];
    let mut cells = vec![0u8; 4];
    let (one, two) = (I16F16::from_num(1), I16F16::from_num(2));
    let origin = v::<I16F16>([0.0, -32_000.0, 0.0]);
    let built = Heightfield::build(
        HeightfieldShape {
            origin,
            spacing: one,
            unit: two,
            columns: 2,
            rows: 2,
        },
        &heights,
        |_, _| false,
        &mut cells,
    );
    assert_eq!(
        built.map(|_| ()),
        Err(HeightfieldError::OutOfRange {
            value: -32_000.0,
            limit: 4096.0
        })
    );
}

/// A terrain reaching below the range names the coordinate with its sign: 200 steps below an
/// `I16F16` origin at y = -4 000 it reaches -4 200 (the error read 4 200, a height above the
/// range that no vertex has).
#[test]
fn a_terrain_below_the_range_reaches_a_negative_coordinate() {
    let heights = vec![0i16, 0, 0, -200];
    let mut cells = vec![0u8; 1];
    let built = Heightfield::build(
        HeightfieldShape {
            origin: v::<I16F16>([0.0, -4000.0, 0.0]),
            spacing: I16F16::from_num(1),
            unit: I16F16::from_num(1),
            columns: 1,
            rows: 1,
        },
        &heights,
        |_, _| false,
        &mut cells,
    );
    let e = built.map(|_| ()).unwrap_err();
    assert_eq!(
        e,
        HeightfieldError::OutOfRange {
            value: -4200.0,
            limit: 4096.0
        }
    );
    assert!(
        e.to_string().starts_with("heightfield reaches -4200 "),
        "{e}"
    );
}

/// Parts from elsewhere with sides whose product overflows: wrong answers allowed, no panic.
#[test]
fn from_parts_huge_sides_do_not_panic() {
    let hf = Heightfield::<f32>::from_parts(
        HeightfieldShape {
            origin: Vec3::ZERO,
            spacing: 1.0,
            unit: 1.0,
            columns: u32::MAX,
            rows: u32::MAX,
        },
        &[],
        &[],
        [0, 0],
        0,
    );
    assert_eq!(hf.len(), 0);
    let sweep = Sweep::new(Vec3::new(0.0, 1.0, 0.0), Vec3::new(3.0, -1.0, 2.0), 0.5).unwrap();
    assert!(hf.cast(&sweep).is_none());
    assert!(hf.triangle(7).is_none() && hf.vertex(5, 5).is_none());
}

/// Negative height steps, holes along the border, sweeps along grid lines, zero-length sweeps
/// and sweeps from below: the walk against the scan.
fn edge_cases_match_the_scan<S: Scalar>() {
    let mut rng = Rng(99);
    let (mut differ, mut hits) = (0, 0);
    for trial in 0..60 {
        let (w, h) = (3 + (rng.next() * 8.0) as u32, 3 + (rng.next() * 8.0) as u32);
        let sp = [0.5, 1.0, 0.75, 0.3][trial % 4];
        let unit = if trial % 2 == 0 {
            -1.0 / 64.0
        } else {
            1.0 / 32.0
        };
        let o = [-(w as f64) * sp / 2.0, 0.25, -(h as f64) * sp / 2.0];
        let heights: Vec<i16> = (0..(w + 1) * (h + 1))
            .map(|_| rng.range(-40.0, 40.0) as i16)
            .collect();
        let holes: Vec<bool> = (0..w * h)
            .map(|c| {
                let p = rng.next();
                (c % w == 0 || c / w == h - 1) && p < 0.5 || p < 0.05
            })
            .collect();
        let mut cells = vec![0u8; (w * h) as usize];
        let f = S::from_f64;
        let hole = |i: u32, k: u32| holes[(k * w + i) as usize];
        let hf = Heightfield::build(
            HeightfieldShape {
                origin: v(o),
                spacing: f(sp),
                unit: f(unit),
                columns: w,
                rows: h,
            },
            &heights,
            hole,
            &mut cells,
        )
        .unwrap();
        let scan = Scan::new(&hf);
        for n in 0..300 {
            let gx = o[0] + sp * (rng.next() * (w + 1) as f64).floor();
            let gz = o[2] + sp * (rng.next() * (h + 1) as f64).floor();
            let (y0, y1) = (rng.range(-1.5, 1.5), rng.range(-1.5, 1.5));
            let (a, b) = (rng.range(-6.0, 6.0), rng.range(-6.0, 6.0));
            let (p0, p1) = match n % 5 {
                0 => ([gx, y0, a], [gx, y1, b]),        // along a column line
                1 => ([a, y0, gz], [b, y1, gz]),        // along a row line
                2 => ([gx, y0, gz], [gx, y0, gz]),      // zero length
                3 => ([a, -3.0, b], [a + 0.1, 3.0, b]), // from below
                _ => ([gx, y0, a], [gx + 0.25, y1, b]),
            };
            let Ok(sweep) = Sweep::new(v(p0), v(p1), f(rng.range(0.05, 0.55))) else {
                continue;
            };
            let (got, want) = (hf.cast(&sweep), scan.cast(&sweep));
            differ += (format!("{got:?}") != format!("{want:?}")) as usize;
            hits += want.is_some() as usize;
        }
    }
    assert_eq!(differ, 0, "{differ} sweeps differ from the scan");
    assert!(hits > 1000, "{hits} hits");
}

/// A height step of zero (what `I16F16::from_f64(1e-6)` gives) would lay every height in the
/// origin's plane, a terrain flat whatever its heights: refused, naming the step.
fn zero_height_unit_is_refused<S: Scalar>() {
    let (heights, mut cells) = ([0i16, 0, 0, 3000], [0u8; 1]);
    let tiny = S::from_f64(S::EPSILON.to_f64() / 4.0);
    for unit in [S::ZERO, tiny] {
        let built = Heightfield::build(
            HeightfieldShape {
                origin: Vec3::ZERO,
                spacing: S::ONE,
                unit,
                columns: 1,
                rows: 1,
            },
            &heights,
            |_, _| false,
            &mut cells,
        );
        let refused = HeightfieldError::Unit {
            value: unit.to_f64(),
        };
        if unit == S::ZERO {
            assert_eq!(built.map(|_| ()), Err(refused));
            assert!(refused.to_string().contains("rounds to zero"), "{refused}");
        } else {
            // A float keeps a tiny step: the top vertex sits at 3000 steps.
            let top = built.unwrap().vertex(1, 1).unwrap().y.to_f64();
            assert_eq!(top, S::from_f64(3000.0 * unit.to_f64()).to_f64());
        }
    }
}

meshes::per_scalar!(
    zero_height_unit_is_refused,
    prepared_as_mesh,
    matches_linear_scan,
    tie_on_a_long_grazing_path,
    along_a_plane,
    slides_as_mesh,
    errors_not_panics,
    range_edges,
    from_parts_as_built,
    edge_cases_match_the_scan,
    matches_linear_scan_long #[ignore = "10^5 sweeps per scalar: run with --release -- --ignored"],
);

/// Cells only a few dozen steps of the scalar wide at their coordinates (`f32` 0.5-unit cells at
/// 400 000; `f64` 32-unit cells at `2^53 - 20`): the mesh keeps the border edges on, as the
/// heightfield does. They once went off in the mesh (and a `Scene`), whose T-junction test
/// could not tell the border edges' lines from their neighbours' there, which let a ball pass
/// through the border vertex the heightfield stops it at.
#[test]
fn far_from_the_origin_as_the_mesh() {
    fn case<S: Scalar>(origin: [f64; 3], spacing: f64, sweep: (P, P)) {
        let heights = vec![0i16; 6];
        let mut cells = [0u8; 2];
        let o = v::<S>(origin);
        let hf = Heightfield::build(
            HeightfieldShape {
                origin: o,
                spacing: S::from_f64(spacing),
                unit: S::from_f64(0.25),
                columns: 2,
                rows: 1,
            },
            &heights,
            |_, _| false,
            &mut cells,
        )
        .unwrap();
        let (input, _) = triangles(&hf);
        let owned = meshes::build(&input, Degenerates::Refuse).unwrap();
        for t in 0..input.len() {
            let (a, b) = (hf.prepared(t).unwrap(), *owned.mesh().triangle(t).unwrap());
            assert_eq!(a.to_parts(), b.to_parts(), "triangle {t}");
        }
        let sweep = Sweep::new(v::<S>(sweep.0), v(sweep.1), S::from_f64(0.5)).unwrap();
        let (got, want) = (hf.cast(&sweep), owned.mesh().cast(&sweep));
        let name = core::any::type_name::<S>();
        assert!(want.is_some(), "{name}: the border vertex stops the ball");
        same_hit(got, want, name);
    }
    let (x, z) = (400_000.0, 400_000.5);
    case::<f32>([x, 0.0, x], 0.5, ([x - 2.0, 0.0, z], [x + 2.0, 0.0, z]));
    let (x, y, z) = (
        -9_007_199_254_740_975.0,
        -9_007_199_254_740_974.0,
        9_007_199_254_740_975.0,
    );
    case::<f64>([x, y, z - 32.0], 32.0, ([x - 1.0, y, z], [x + 2.0, y, z]));
}

/// `f32` cells 32 steps of the scalar wide near `2^24`, their heights rounded by half a unit: a
/// ball moving along a grid line 1 010 units touches the vertex two triangles share at the
/// same alpha, and the heightfield reports the smaller index, as the slice of its prepared
/// triangles does. Its plane cull once took the heights unrounded, tilting a plane by half a
/// unit per unit over the long path, and never offered the smaller (seen with cells of one
/// step, which are now refused).
#[test]
fn tie_near_the_range_edge_as_the_slice() {
    let heights: [i16; 6] = [0, 32767, 0, 1, 32767, 1];
    let mut cells = [0u8; 2];
    let o = Vec3::new(-16_777_199.0f32, 16_777_198.0, 16_777_132.0);
    let hf = Heightfield::build(
        HeightfieldShape {
            origin: o,
            spacing: 32.0,
            unit: 1.0 / 65536.0,
            columns: 1,
            rows: 2,
        },
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let slice: Vec<_> = (0..hf.len()).map(|t| hf.prepared(t).unwrap()).collect();
    let (y, z) = (16_777_198.0, 16_777_164.0);
    let sweep = Sweep::new(
        Vec3::new(-16_776_189.0, y, z),
        Vec3::new(-16_777_199.0, y, z),
        0.5,
    )
    .unwrap();
    let want = Geometry::cast(slice.as_slice(), &sweep);
    assert!(want.is_some());
    same_hit(hf.cast(&sweep), want, "f32");
}
