//! The terrain inputs of `benches/mesh.rs`, shared with `examples/callgrind_mesh.rs` so that
//! time and instruction counts are measured on the same sweeps: a bumpy heightfield (1-unit
//! cells, heights within ±0.65 from a fixed sin/cos formula, front faces up), short moves and
//! long casts over it; and the same terrain as one level in every form's inputs (`Level`), for
//! the heightfield and compact-mesh benches.
#![allow(dead_code)] // each bench and example uses a different part

use super::inputs::{P, Path, Rng};

/// Sweeps per query benchmark.
pub const QUERIES: usize = 256;

/// The terrain height at `(x, z)`: within ±0.65.
pub fn height(x: f64, z: f64) -> f64 {
    0.4 * (0.7 * x).sin() * (0.5 * z).cos() + 0.25 * (1.3 * x + 0.9 * z).sin()
}

/// `2 w²` triangles over `[-w/2, w/2]²`, front faces up.
pub fn heightfield(w: usize) -> Vec<[P; 3]> {
    let half = w as f64 / 2.0;
    let p = |i: usize, j: usize| {
        let (x, z) = (i as f64 - half, j as f64 - half);
        [x, height(x, z), z]
    };
    let mut out = Vec::with_capacity(2 * w * w);
    for i in 0..w {
        for j in 0..w {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            out.push([a, b, c]);
            out.push([a, c, d]);
        }
    }
    out
}

/// Frames of the character loop per walk.
pub const FRAMES: usize = 256;

/// A character's walk: a ball of radius 0.4 dropped 1.5 above the terrain's centre, walking at
/// 3 units a second on a slowly turning heading, `FRAMES` frames of 1/64 s (`Character`:
/// slides, the press into the floor, the ground probe and the snap, about five casts a frame).
/// Returns where it ends, and on how many frames it stood on the ground.
pub fn walk<S: ballcast::Scalar, G: ballcast::Geometry<S>>(
    level: &G,
) -> (ballcast::Vec3<S>, usize) {
    let v = |x: f64, y: f64, z: f64| super::inputs::v::<S>([x, y, z]);
    let mut me = ballcast::slide::Character::new(v(0.0, 1.5, 0.0), S::from_f64(0.4)).unwrap();
    let (gravity, dt) = (v(0.0, -9.81, 0.0), S::from_f64(1.0 / 64.0));
    let mut grounded = 0;
    for f in 0..FRAMES {
        let a = f as f64 / 40.0;
        me.update(level, v(3.0 * a.cos(), 0.0, 3.0 * a.sin()), gravity, dt)
            .unwrap();
        grounded += me.is_grounded() as usize;
    }
    (me.position, grounded)
}

/// Short moves: radius 0.2–0.5, starting 0.1–0.3 above the ground, 0.5 forward and 0.5 down.
pub fn short_moves(w: usize, rng: &mut Rng) -> Vec<Path> {
    let half = w as f64 / 2.0 - 1.0;
    (0..QUERIES)
        .map(|_| {
            let r = rng.range(0.2, 0.5);
            let (x, z) = (rng.range(-half, half), rng.range(-half, half));
            let p0 = [x, height(x, z) + r + rng.range(0.1, 0.3), z];
            let a = rng.range(0.0, std::f64::consts::TAU);
            (p0, [x + 0.5 * a.cos(), p0[1] - 0.5, z + 0.5 * a.sin()], r)
        })
        .collect()
}

/// Long casts: radius 0.1–0.5, from 2–5 above the ground to 1 below it, across 0.5–1 terrain
/// widths horizontally.
pub fn long_casts(w: usize, rng: &mut Rng) -> Vec<Path> {
    let (width, half) = (w as f64, w as f64 / 2.0 - 0.5);
    let mut out = Vec::new();
    while out.len() < QUERIES {
        let (x0, z0) = (rng.range(-half, half), rng.range(-half, half));
        let (x1, z1) = (rng.range(-half, half), rng.range(-half, half));
        let dist = ((x1 - x0).powi(2) + (z1 - z0).powi(2)).sqrt();
        if dist < 0.5 * width || dist > width {
            continue;
        }
        let p0 = [x0, height(x0, z0) + rng.range(2.0, 5.0), z0];
        let p1 = [x1, height(x1, z1) - 1.0, z1];
        out.push((p0, p1, rng.range(0.1, 0.5)));
    }
    out
}

/// The sweeps of a terrain of width `w`: short moves, then long casts (one generator, seeded by
/// the width).
pub fn queries(w: usize) -> (Vec<Path>, Vec<Path>) {
    let mut rng = Rng(0x4D45_5348 + w as u64);
    let short = short_moves(w, &mut rng);
    let long = long_casts(w, &mut rng);
    (short, long)
}

/// The terrain's grid: `w × w` cells of side 1 centred on the origin, heights in steps of
/// 1/1024 (so every form holds exactly the same triangles).
fn shape<S: ballcast::Scalar>(w: usize) -> ballcast::HeightfieldShape<S> {
    let half = w as f64 / 2.0;
    ballcast::HeightfieldShape {
        origin: super::inputs::v::<S>([-half, 0.0, -half]),
        spacing: S::ONE,
        unit: S::from_f64(1.0 / 1024.0),
        columns: w as u32,
        rows: w as u32,
    }
}

/// The terrain as one level in every form's inputs (see [`shape`]).
pub struct Level<S: ballcast::Scalar> {
    pub w: usize,
    pub heights: Vec<i16>,
    pub cells: Vec<u8>,
    pub bounds: [i16; 2],
    pub class: u8,
    /// The heightfield's triangles in index order, and its vertices and index triples.
    pub triangles: Vec<ballcast::Triangle<S>>,
    pub vertices: Vec<ballcast::Vec3<S>>,
    pub indices: Vec<[u32; 3]>,
    /// The prepared meshes of the same triangles, with leaves of up to two triangles (the
    /// default) and of four (the tree a compact mesh borrows).
    meshes: [Prepared<S>; 2],
}

/// A prepared mesh's parts: nodes, prepared triangles, order and grid.
struct Prepared<S: ballcast::Scalar> {
    nodes: Vec<ballcast::Node>,
    triangles: Vec<ballcast::StandardTriangle<S>>,
    order: Vec<u32>,
    grid: ballcast::Grid,
}

impl<S: ballcast::Scalar> Prepared<S> {
    fn build(triangles: &[ballcast::Triangle<S>], leaves: ballcast::bvh::LeafSize) -> Self {
        let n = triangles.len();
        let mut nodes = vec![ballcast::Node::default(); ballcast::bvh::nodes_for(n)];
        let mut prepared = vec![ballcast::Mesh::<S>::filler(); n];
        let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
        let options = ballcast::Degenerates::Refuse.with_leaf_size(leaves);
        let (mesh, _) = ballcast::Mesh::build(
            triangles,
            options,
            &mut nodes,
            &mut prepared,
            &mut order,
            &mut scratch,
        )
        .unwrap();
        let (used, grid) = (mesh.nodes().len(), mesh.grid());
        nodes.truncate(used);
        Self {
            nodes,
            triangles: prepared,
            order,
            grid,
        }
    }

    fn mesh(&self) -> ballcast::Mesh<'_, S> {
        ballcast::Mesh::from_parts(&self.nodes, &self.triangles, &self.order, self.grid)
    }
}

impl<S: ballcast::Scalar> Level<S> {
    pub fn new(w: usize) -> Self {
        let half = w as f64 / 2.0;
        let heights: Vec<i16> = (0..(w + 1) * (w + 1))
            .map(|v| {
                let (x, z) = ((v % (w + 1)) as f64 - half, (v / (w + 1)) as f64 - half);
                (height(x, z) * 1024.0).round() as i16
            })
            .collect();
        let mut cells = vec![0u8; w * w];
        let hf = Self::build(w, &heights, &mut cells);
        let (bounds, class) = (hf.bounds(), hf.class());
        let triangles: Vec<ballcast::Triangle<S>> =
            (0..hf.len()).filter_map(|t| hf.triangle(t)).collect();
        let vertices = (0..(w + 1) * (w + 1))
            .map(|v| {
                hf.vertex((v % (w + 1)) as u32, (v / (w + 1)) as u32)
                    .unwrap()
            })
            .collect();
        let grid = |i: usize, k: usize| (k * (w + 1) + i) as u32;
        let indices = (0..2 * w * w)
            .map(|t| {
                let (c, half) = (t / 2, t % 2);
                let (i, k) = (c % w, c / w);
                let (a, d) = (grid(i, k), grid(i + 1, k + 1));
                if half == 0 {
                    [a, grid(i, k + 1), d]
                } else {
                    [a, d, grid(i + 1, k)]
                }
            })
            .collect();
        use ballcast::bvh::LeafSize;
        let meshes = [LeafSize::Two, LeafSize::Four].map(|l| Prepared::build(&triangles, l));
        Self {
            w,
            heights,
            cells,
            bounds,
            class,
            triangles,
            vertices,
            indices,
            meshes,
        }
    }

    /// The prepared mesh of the level's triangles (leaves of up to two triangles).
    pub fn mesh(&self) -> ballcast::Mesh<'_, S> {
        self.meshes[0].mesh()
    }

    /// The prepared mesh with leaves of up to four triangles, whose tree a compact mesh borrows.
    pub fn small_tree_mesh(&self) -> ballcast::Mesh<'_, S> {
        self.meshes[1].mesh()
    }

    fn build<'a>(
        w: usize,
        heights: &'a [i16],
        cells: &'a mut [u8],
    ) -> ballcast::Heightfield<'a, S> {
        ballcast::Heightfield::build(shape(w), heights, |_, _| false, cells).unwrap()
    }

    pub fn heightfield(&self) -> ballcast::Heightfield<'_, S> {
        ballcast::Heightfield::from_parts(
            shape(self.w),
            &self.heights,
            &self.cells,
            self.bounds,
            self.class,
        )
    }
}
