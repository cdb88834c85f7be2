//! `Compound`: geometries cast against as one. A level of four parts (a heightfield terrain with
//! holes, a mesh and a compact mesh of boxes standing in it, a `Scene` wall), nested two by two,
//! answers as one mesh of all their triangles, numbered the same way: the same hits (ties across
//! parts merged as one geometry merges them), the same box queries, the same slides, bit for
//! bit. Every property in every scalar.

mod common;
mod meshes;

use ballcast::{
    CompactMesh, Compound, CompoundPart, Degenerates, Geometry, Heightfield, HeightfieldShape,
    Mesh, PartIndex, Scalar, Scene, StandardTriangle, Sweep, Triangle, Vec3, move_and_slide,
};
use common::{P, Rng, v};
use fixed::types::{I16F16, I32F32};
use meshes::Owned;

const COLUMNS: u32 = 12;
const ROWS: u32 = 10;

/// The level's inputs: the terrain's heights and holes, the two sets of boxes, the wall.
struct Level {
    heights: Vec<i16>,
    holes: Vec<bool>,
    boxes: Vec<[P; 3]>,
    compact: Vec<[P; 3]>,
    wall: [[P; 3]; 2],
}

impl Level {
    fn new(rng: &mut Rng) -> Self {
        let n = ((COLUMNS + 1) * (ROWS + 1)) as usize;
        Self {
            heights: (0..n).map(|_| rng.range(-40.0, 40.0) as i16).collect(),
            holes: (0..COLUMNS * ROWS)
                .map(|_| rng.next() < 1.0 / 12.0)
                .collect(),
            boxes: meshes::boxes(rng, 5, 4.0),
            compact: meshes::boxes(rng, 3, 4.0),
            // A wall across the terrain at x = 2.3, facing -x, from below it to well above.
            wall: common::quad([2.3, -2.0, -6.0], [0.0, 0.0, 12.0], [0.0, 6.0, 0.0]),
        }
    }

    fn terrain<'a, S: Scalar>(&'a self, cells: &'a mut [u8]) -> Heightfield<'a, S> {
        let o = [-(COLUMNS as f64) / 2.0, -0.5, -(ROWS as f64) / 2.0];
        let holes = &self.holes;
        let hole = |i: u32, k: u32| holes[(k * COLUMNS + i) as usize];
        let (one, unit) = (S::ONE, S::from_f64(1.0 / 64.0));
        Heightfield::build(
            HeightfieldShape {
                origin: v(o),
                spacing: one,
                unit,
                columns: COLUMNS,
                rows: ROWS,
            },
            &self.heights,
            hole,
            cells,
        )
        .unwrap()
    }

    fn wall<S: Scalar>(&self) -> Scene<S, 2> {
        let mut scene = Scene::new();
        for t in self.wall {
            scene.push(meshes::tri(t)).unwrap();
        }
        scene
    }
}

/// The reference: one mesh of every part's triangles in the compound's numbering (a hole's
/// two take a degenerate triangle each, which the build skips, so the numbers line up).
fn one_mesh<S: Scalar>(level: &Level, terrain: &Heightfield<'_, S>) -> Owned<S> {
    let mut all: Vec<Triangle<S>> = (0..terrain.len())
        .map(|t| match level.holes[t / 2] {
            true => Triangle::new(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO),
            false => terrain.triangle(t).unwrap(),
        })
        .collect();
    let parts = [&level.boxes[..], &level.compact, &level.wall];
    all.extend(parts.iter().flat_map(|p| p.iter().map(|&t| meshes::tri(t))));
    meshes::build(&all, Degenerates::Skip).unwrap()
}

/// Builds the level's parts and calls `f` with the compound and the one mesh.
fn with_level<S: Scalar>(seed: u64, f: impl FnOnce(&dyn Geometry<S>, &Owned<S>, &Level)) {
    let level = Level::new(&mut Rng(seed));
    let mut cells = vec![0u8; (COLUMNS * ROWS) as usize];
    let terrain = level.terrain::<S>(&mut cells);
    let boxes: Vec<Triangle<S>> = level.boxes.iter().map(|&t| meshes::tri(t)).collect();
    let owned = meshes::build(&boxes, Degenerates::Refuse).unwrap();
    let (vertices, indices) = meshes::indexed::<S>(&level.compact);
    let src: Vec<Triangle<S>> = level.compact.iter().map(|&t| meshes::tri(t)).collect();
    let built = meshes::build(&src, Degenerates::Refuse).unwrap();
    let n = src.len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
    let compact =
        CompactMesh::compact(&built.mesh(), &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let wall = level.wall::<S>();
    let near = Compound::new(terrain, owned.mesh()).unwrap();
    let far = Compound::new(compact, &wall).unwrap();
    let all = Compound::new(near, far).unwrap();
    // The numbering: parts follow each other.
    let cells = (COLUMNS * ROWS) as usize;
    assert_eq!(near.offset(), 2 * cells);
    assert_eq!(all.offset(), 2 * cells + boxes.len());
    assert_eq!(far.offset(), n);
    assert_eq!(all.index_bound(), all.offset() + n + 2);
    assert_eq!(all.locate(all.offset() + n), PartIndex::Second(n));
    assert_eq!(far.locate(n), PartIndex::Second(0));
    let one = one_mesh(&level, &terrain);
    // Every part's triangles, active edges included, are the one mesh's.
    let mut same = 0;
    all.visit(v([-9.0; 3]), v([9.0; 3]), &mut |i, t| {
        let want = one.mesh().triangle(i).map(StandardTriangle::to_parts);
        assert_eq!(Some(t.to_parts()), want, "triangle {i}");
        same += 1;
    });
    assert_eq!(same, one.tris.len());
    f(&all, &one, &level);
}

/// Random sweeps (short moves, long paths, paths aimed at vertices, where triangles of
/// different parts tie) give the one mesh's answer and its linear scan's.
fn answers_as_one_mesh<S: Scalar>() {
    for seed in 0..3u64 {
        with_level::<S>(0xc0_0000 + seed, |all, one, level| {
            let reference = one.reference();
            let mut rng = Rng(0xc0_1000 + seed);
            let points: Vec<P> = (level.boxes.iter().chain(&level.compact))
                .chain(&level.wall)
                .flatten()
                .copied()
                .collect();
            let (mut hits, mut parts, mut ties) = (0, [0; 2], 0);
            for k in 0..3000 {
                let p0 = [
                    rng.range(-7.0, 7.0),
                    rng.range(-2.0, 4.0),
                    rng.range(-6.0, 6.0),
                ];
                let p1 = match k % 3 {
                    0 => [0, 1, 2].map(|a| p0[a] + rng.range(-0.8, 0.8)),
                    1 => [
                        rng.range(-7.0, 7.0),
                        rng.range(-2.0, 4.0),
                        rng.range(-6.0, 6.0),
                    ],
                    _ => {
                        let at = points[(rng.next() * points.len() as f64) as usize];
                        [0, 1, 2].map(|a| p0[a] + 1.5 * (at[a] - p0[a]))
                    }
                };
                let r = S::from_f64(rng.range(0.05, 1.0));
                let Ok(sweep) = Sweep::new(v::<S>(p0), v(p1), r) else {
                    continue;
                };
                let got = all.cast(&sweep);
                assert_eq!(got, reference(&sweep), "sweep {k}: {p0:?} -> {p1:?}");
                assert_eq!(got, one.mesh().cast(&sweep), "sweep {k}: the mesh");
                if let Some(h) = got {
                    hits += 1;
                    parts[(h.index >= 2 * (COLUMNS * ROWS) as usize) as usize] += 1;
                    ties += (h.planes.iter().flatten().count() > 1) as usize;
                }
            }
            // Not vacuous: both the terrain and what stands on it are hit, and planes tie.
            assert!(parts[0] > 300 && parts[1] > 300, "{parts:?} of {hits}");
            assert!(ties > 20, "{ties} ties");
        });
    }
}

/// Slides over the level (falls onto the terrain, runs into the boxes and the wall) end where
/// they end in the one mesh, bit for bit.
fn slides_as_one_mesh<S: Scalar>() {
    with_level::<S>(0xc0_2000, |all, one, _| {
        let mut rng = Rng(0xc0_3000);
        let (mut compared, mut stopped) = (0, 0);
        for k in 0..400 {
            let p = [
                rng.range(-5.0, 5.0),
                rng.range(1.0, 3.0),
                rng.range(-4.0, 4.0),
            ];
            let d = [
                rng.range(-3.0, 3.0),
                rng.range(-4.0, 0.0),
                rng.range(-3.0, 3.0),
            ];
            let r = S::from_f64(rng.range(0.2, 0.6));
            let got = move_and_slide(all, v(p), v(d), r);
            let want = move_and_slide(&one.mesh(), v(p), v(d), r);
            assert_eq!(
                format!("{got:?}"),
                format!("{want:?}"),
                "slide {k}: {p:?} by {d:?}"
            );
            compared += got.is_ok() as usize;
            stopped += got.is_ok_and(|s| s.contacts[0].is_some()) as usize;
        }
        assert!(
            compared > 350 && stopped > 200,
            "{compared} slides, {stopped} touched"
        );
    });
}

/// A sweep across the level from above the terrain, radius 0.05 to 1.
fn across<S: Scalar>(rng: &mut Rng) -> Option<Sweep<S>> {
    let p0 = [
        rng.range(-6.0, 6.0),
        rng.range(-1.0, 3.0),
        rng.range(-5.0, 5.0),
    ];
    let p1 = [
        rng.range(-6.0, 6.0),
        rng.range(-2.0, 3.0),
        rng.range(-5.0, 5.0),
    ];
    Sweep::new(v::<S>(p0), v(p1), S::from_f64(rng.range(0.05, 1.0))).ok()
}

/// A geometry of the user's own: a `Scene` behind a type the crate does not know, a part by
/// `CompoundPart`'s default (its `cast` offered as one contact).
struct Own<S: Scalar>(Scene<S, 2>);

impl<S: Scalar> Geometry<S> for Own<S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<ballcast::SceneHit<S>> {
        self.0.cast(sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.0.visit(min, max, f)
    }
}

impl<S: Scalar> CompoundPart<S> for Own<S> {
    fn index_bound(&self) -> usize {
        self.0.len()
    }
}

/// An empty part changes nothing, and numbers nothing; a user's geometry is a part: alone
/// beside an empty one, it answers as itself; beside the terrain, its hits come numbered after
/// the terrain's and the terrain's hits are the terrain's.
fn empty_and_own_parts<S: Scalar>() {
    let level = Level::new(&mut Rng(0xc0_4000));
    let mut cells = vec![0u8; (COLUMNS * ROWS) as usize];
    let terrain = level.terrain::<S>(&mut cells);
    let empty: Scene<S, 1> = Scene::new();
    let own = Own(level.wall::<S>());
    let (before, after) = (
        Compound::new(&empty, terrain),
        Compound::new(terrain, &empty),
    );
    let (before, after) = (before.unwrap(), after.unwrap());
    let alone = Compound::new(&empty, &own).unwrap();
    let beside = Compound::new(terrain, &own).unwrap();
    assert_eq!((before.offset(), after.offset()), (0, terrain.len()));
    assert_eq!(beside.index_bound(), terrain.len() + 2);
    let mut rng = Rng(0xc0_5000);
    let (mut walls, mut grounds) = (0, 0);
    for k in 0..2000 {
        let Some(sweep) = across::<S>(&mut rng) else {
            continue;
        };
        let ground = terrain.cast(&sweep);
        assert_eq!(before.cast(&sweep), ground, "sweep {k}");
        assert_eq!(after.cast(&sweep), ground, "sweep {k}");
        let wall = own.cast(&sweep);
        assert_eq!(alone.cast(&sweep), wall, "sweep {k}");
        match beside.cast(&sweep) {
            Some(h) if h.index >= terrain.len() => {
                let w = wall.expect("a hit numbered after the terrain's is the wall's");
                assert_eq!(h.index, terrain.len() + w.index, "sweep {k}");
                assert_eq!(h.alpha, w.alpha, "sweep {k}");
                walls += 1;
            }
            Some(h) => {
                assert_eq!(Some(h.alpha), ground.map(|g| g.alpha), "sweep {k}");
                grounds += 1;
            }
            None => assert!(ground.is_none() && wall.is_none(), "sweep {k}"),
        }
    }
    assert!(
        walls > 100 && grounds > 100,
        "{walls} walls, {grounds} grounds"
    );
}

/// A mesh of the level's boxes whose tree is broken (every child that names a node names one
/// that is not there): it answers by testing every triangle, and so does a compound holding
/// it, its other part included.
fn a_malformed_part_is_scanned<S: Scalar>() {
    with_level::<S>(0xc0_6000, |_, _, level| {
        let mut cells = vec![0u8; (COLUMNS * ROWS) as usize];
        let terrain = level.terrain::<S>(&mut cells);
        let boxes: Vec<Triangle<S>> = level.boxes.iter().map(|&t| meshes::tri(t)).collect();
        let good = meshes::build(&boxes, Degenerates::Refuse).unwrap();
        let mut nodes = good.nodes.clone();
        let mut broken = 0;
        for child in nodes.iter_mut().flat_map(|n| n.children.iter_mut()) {
            if *child & (1 << 31) == 0 {
                *child = u32::MAX >> 1;
                broken += 1;
            }
        }
        assert!(broken > 0, "no inner node to break");
        let bad = Mesh::from_parts(&nodes, &good.tris, &good.order, good.grid);
        let (want, got) = (
            Compound::new(terrain, good.mesh()).unwrap(),
            Compound::new(terrain, bad).unwrap(),
        );
        let mut rng = Rng(0xc0_7000);
        let mut boxes_hit = 0;
        for k in 0..1000 {
            let Some(sweep) = across::<S>(&mut rng) else {
                continue;
            };
            let hit = want.cast(&sweep);
            assert_eq!(got.cast(&sweep), hit, "sweep {k}");
            boxes_hit += hit.is_some_and(|h| h.index >= want.offset()) as usize;
        }
        assert!(boxes_hit > 50, "{boxes_hit} hits on the boxes");
    });
}

/// More contacts tie than the accumulator keeps (eight), and the one it had to drop for room
/// (a tilted wall, index 8) is in the final tie once a later, earlier contact (index 9) has
/// narrowed the window: the second visit with the window fixed finds it, across the parts as in
/// one slice. `I16F16`, whose alpha steps the walls are placed by.
#[test]
fn ties_beyond_the_buffer_across_parts() {
    type S = I16F16;
    let st = |t: [P; 3]| StandardTriangle::new(&meshes::tri::<S>(t)).unwrap();
    let step = 1.0 / 65536.0;
    // The plane x = c, facing -x; and one tilted 37° about z, its normal (-0.8, -0.6, 0).
    let wall = |c: f64| st([[c, -1.0, -1.0], [c, -1.0, 1.0], [c, 1.0, 0.0]]);
    let tilted = |c: f64| {
        st([
            [c - 0.6, 0.8, -1.0],
            [c + 0.6, -0.8, 0.0],
            [c - 0.6, 0.8, 1.0],
        ])
    };
    let sweep = Sweep::new(v::<S>([0.0; 3]), v([1.0, 0.0, 0.0]), S::from_f64(0.25)).unwrap();
    // Alpha in steps past 0.25, where the first wall (x = 0.5 + 4 steps) is met 4 steps past.
    let steps = |t: &StandardTriangle<S>| {
        let h = t.cast(&sweep)?;
        Some(((h.alpha.to_f64() - 0.25) / step).round() as i64)
    };
    let placed = (-40..40).find_map(|k| {
        let t = tilted(0.5625 + k as f64 * step);
        steps(&t).filter(|a| (3..=6).contains(a)).map(|_| t)
    });
    let mut tris = vec![wall(0.5 + 4.0 * step)];
    tris.extend((0..7).map(|_| wall(0.5 + 7.0 * step)));
    tris.push(placed.expect("a place for the tilted wall"));
    tris.push(wall(0.5 + 2.0 * step));
    let alphas: Vec<_> = tris.iter().map(steps).collect();
    assert_eq!(alphas[..8].iter().flatten().count(), 8, "{alphas:?}");
    let one = Geometry::cast(tris.as_slice(), &sweep).unwrap();
    // Walls 0 and 9 and the tilted 8 tie: two planes, the tilted one among them.
    assert_eq!(one.planes.iter().flatten().count(), 2, "{one:?}");
    for split in [1, 5, 8, 9] {
        let parts = Compound::new(&tris[..split], &tris[split..]).unwrap();
        assert_eq!(parts.cast(&sweep), Some(one), "split at {split}");
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn answers_as_one_mesh() {
            super::answers_as_one_mesh::<$t>();
        }
        #[test]
        fn slides_as_one_mesh() {
            super::slides_as_one_mesh::<$t>();
        }
        #[test]
        fn empty_and_own_parts() {
            super::empty_and_own_parts::<$t>();
        }
        #[test]
        fn a_malformed_part_is_scanned() {
            super::a_malformed_part_is_scanned::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
