//! Shared by the tests of meshes and their forms: a mesh's parts in `Vec`s, the generators of
//! heightfields, closed boxes and soups, indexed vertices, and the check of a mesh against the
//! linear scan.

#![allow(dead_code)] // each test binary uses a different part

use crate::common::{P, Rng, add, cross, dot, norm, scale, sub, v};
use ballcast::bvh::{LeafSize, nodes_for};
use ballcast::{
    Degenerates, Geometry, Grid, Mesh, MeshError, MeshOptions, Node, Scalar, SceneHit,
    StandardTriangle, Sweep, Triangle, Vec3,
};
use std::collections::HashMap;

/// A mesh's parts in `Vec`s.
pub struct Owned<S: Scalar> {
    pub nodes: Vec<Node>,
    pub tris: Vec<StandardTriangle<S>>,
    pub order: Vec<u32>,
    pub grid: Grid,
}

impl<S: Scalar> Owned<S> {
    pub fn mesh(&self) -> Mesh<'_, S> {
        Mesh::from_parts(&self.nodes, &self.tris, &self.order, self.grid)
    }

    /// The linear scan's reference: the same prepared triangles in input order (kept ones only).
    pub fn linear(&self) -> Vec<StandardTriangle<S>> {
        let mut by_input: Vec<(u32, StandardTriangle<S>)> = self
            .order
            .iter()
            .copied()
            .zip(self.tris.iter().copied())
            .collect();
        by_input.sort_by_key(|p| p.0);
        by_input.into_iter().map(|p| p.1).collect()
    }

    /// The linear scan's answer to `sweep`, with the input index (of the kept triangles).
    pub fn reference(&self) -> impl Fn(&Sweep<S>) -> Option<SceneHit<S>> {
        let linear = self.linear();
        let mut kept = self.order.clone();
        kept.sort();
        move |sweep: &Sweep<S>| {
            Geometry::cast(linear.as_slice(), sweep).map(|h| SceneHit {
                index: kept[h.index] as usize,
                ..h
            })
        }
    }
}

pub fn build<S: Scalar>(
    src: &[Triangle<S>],
    options: impl Into<MeshOptions>,
) -> Result<Owned<S>, MeshError> {
    build_sided(src, |_| false, options)
}

/// [`build`] with the triangles for which `sided(index)` holds two-sided.
pub fn build_sided<S: Scalar>(
    src: &[Triangle<S>],
    sided: impl Fn(usize) -> bool,
    options: impl Into<MeshOptions>,
) -> Result<Owned<S>, MeshError> {
    let n = src.len();
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut tris = vec![Mesh::<S>::filler(); n];
    let mut order = vec![0u32; n];
    let mut scratch = vec![0u64; 6 * n];
    let (mesh, _) = Mesh::build_sided(
        src,
        sided,
        options,
        &mut nodes,
        &mut tris,
        &mut order,
        &mut scratch,
    )?;
    let (used, kept, grid) = (mesh.nodes().len(), mesh.len(), mesh.grid());
    nodes.truncate(used);
    tris.truncate(kept);
    order.truncate(kept);
    Ok(Owned {
        nodes,
        tris,
        order,
        grid,
    })
}

/// Shared vertices (exact coordinates merged) and index triples of a triangle list.
pub fn indexed<S: Scalar>(src: &[[P; 3]]) -> (Vec<Vec3<S>>, Vec<[u32; 3]>) {
    let (mut vertices, mut seen) = (Vec::new(), HashMap::new());
    let indices = src
        .iter()
        .map(|t| {
            t.map(|p| {
                *seen.entry(p.map(f64::to_bits)).or_insert_with(|| {
                    vertices.push(v::<S>(p));
                    vertices.len() as u32 - 1
                })
            })
        })
        .collect();
    (vertices, indices)
}

pub fn tri<S: Scalar>(t: [P; 3]) -> Triangle<S> {
    Triangle::new(v(t[0]), v(t[1]), v(t[2]))
}

/// A heightfield of `w × w` cells of side `cell`, heights within ±`bump`, two triangles per cell
/// facing +y, with the cell's diagonal chosen at random.
pub fn heightfield(rng: &mut Rng, w: usize, cell: f64, bump: f64) -> Vec<[P; 3]> {
    let h: Vec<f64> = (0..(w + 1) * (w + 1))
        .map(|_| rng.range(-bump, bump))
        .collect();
    let p = |i: usize, j: usize| {
        let half = w as f64 * cell / 2.0;
        [
            i as f64 * cell - half,
            h[i * (w + 1) + j],
            j as f64 * cell - half,
        ]
    };
    let mut out = Vec::new();
    for i in 0..w {
        for j in 0..w {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            if rng.next() < 0.5 {
                out.push([a, b, c]);
                out.push([a, c, d]);
            } else {
                out.push([a, b, d]);
                out.push([b, c, d]);
            }
        }
    }
    out
}

/// A floor on one tilted plane with T-junctions: `w` × `w` unit cells (`w` even), those with
/// `x` below the middle merged into 2 × 2 cells, so the big cells' edges along the middle and
/// the small cells' meet in T-junctions; each cell split in two along a random diagonal.
pub fn t_junctions(rng: &mut Rng, w: usize) -> Vec<[P; 3]> {
    let (a, b) = (rng.range(-0.3, 0.3), rng.range(-0.3, 0.3));
    let half = w as f64 / 2.0;
    let p = |i: usize, j: usize| {
        let (x, z) = (i as f64 - half, j as f64 - half);
        [x, a * x + b * z, z]
    };
    let mut out = Vec::new();
    let mut cell = |i: usize, j: usize, n: usize, rng: &mut Rng| {
        let (c0, c1, c2, c3) = (p(i, j), p(i, j + n), p(i + n, j + n), p(i + n, j));
        if rng.next() < 0.5 {
            out.extend([[c0, c1, c2], [c0, c2, c3]]);
        } else {
            out.extend([[c0, c1, c3], [c1, c2, c3]]);
        }
    };
    for i in (0..w / 2).step_by(2) {
        for j in (0..w).step_by(2) {
            cell(i, j, 2, rng);
        }
    }
    for i in w / 2..w {
        for j in 0..w {
            cell(i, j, 1, rng);
        }
    }
    out
}

/// The plane `y = a x + b z + c` of a floor, from its first triangle: `[a, b, c]`.
pub fn plane_of(floor: &[[P; 3]]) -> [f64; 3] {
    let [p, q, w] = floor[0];
    let det = (q[0] - p[0]) * (w[2] - p[2]) - (w[0] - p[0]) * (q[2] - p[2]);
    let a = ((q[1] - p[1]) * (w[2] - p[2]) - (w[1] - p[1]) * (q[2] - p[2])) / det;
    let b = ((q[0] - p[0]) * (w[1] - p[1]) - (w[0] - p[0]) * (q[1] - p[1])) / det;
    [a, b, p[1] - a * p[0] - b * p[2]]
}

/// `2 n` long thin triangles side by side along a diagonal, each strip's ends offset from its
/// neighbours' so that no edge is shared: every triangle's box overlaps nearly every other's.
pub fn diagonal_strips(n: usize) -> Vec<[P; 3]> {
    let (side, w) = (100.0, 100.0 / n as f64);
    let mut out = Vec::new();
    for k in 0..n {
        let off = if k % 2 == 0 { 0.0 } else { 0.5 * w };
        let len = side - (k as f64 + 3.0) * w;
        if len <= 0.0 {
            break;
        }
        let a = [k as f64 * w + off, 0.0, off];
        let b = [a[0] + w, 0.0, off];
        let (c, d) = ([a[0] + len, 0.0, a[2] + len], [b[0] + len, 0.0, b[2] + len]);
        out.extend([[a, c, b], [b, c, d]]);
    }
    out
}

/// `count` closed boxes (12 triangles each, facing out), possibly overlapping.
pub fn boxes(rng: &mut Rng, count: usize, half: f64) -> Vec<[P; 3]> {
    let mut out = Vec::new();
    for _ in 0..count {
        let c = rng.point(half);
        let e = [0; 3].map(|_| rng.range(0.2, half / 3.0));
        let corner =
            |k: usize| [0, 1, 2].map(|a| c[a] + if k >> a & 1 == 1 { e[a] } else { -e[a] });
        // Faces as corner bit patterns, counter-clockwise seen from outside.
        for f in [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ] {
            let q = f.map(corner);
            out.push([q[0], q[1], q[2]]);
            out.push([q[0], q[2], q[3]]);
        }
    }
    out
}

/// Random triangles overlapping in a cube, with slivers (one vertex near the opposite edge) and
/// duplicates (exact copies, some with the winding reversed).
pub fn soup(rng: &mut Rng, count: usize, half: f64) -> Vec<[P; 3]> {
    let mut out: Vec<[P; 3]> = Vec::new();
    while out.len() < count {
        let roll = rng.next();
        if roll < 0.15 && !out.is_empty() {
            let t = out[(rng.next() * out.len() as f64) as usize];
            out.push(if rng.next() < 0.5 {
                t
            } else {
                [t[0], t[2], t[1]]
            });
        } else if roll < 0.3 {
            let (a, b) = (rng.point(half), rng.point(half));
            let s = rng.range(0.0, 1.0);
            let m = [0, 1, 2].map(|k| a[k] + s * (b[k] - a[k]) + rng.range(-1e-3, 1e-3));
            out.push([a, b, m]);
        } else {
            let c = rng.point(half);
            let s = rng.range(0.3, half / 2.0);
            out.push([0; 3].map(|_| {
                let o = [0; 3].map(|_| rng.range(-s, s));
                [c[0] + o[0], c[1] + o[1], c[2] + o[2]]
            }));
        }
    }
    out
}

/// The three test shapes, in this order: a 12 × 12 heightfield, 16 closed boxes and a soup of
/// 200 triangles.
pub fn shapes(rng: &mut Rng) -> [Vec<[P; 3]>; 3] {
    [
        heightfield(rng, 12, 1.0, 0.65),
        boxes(rng, 16, 5.0),
        soup(rng, 200, 4.0),
    ]
}

/// Builds the mesh of `src` (skipping degenerates) and checks `sweeps` random sweeps within
/// ±`half` against the linear scan; long paths, short moves, and paths aimed at vertices.
pub fn against_linear<S: Scalar>(rng: &mut Rng, src: &[[P; 3]], sweeps: usize, half: f64) {
    against_linear_sided::<S>(rng, src, |_| false, sweeps, half);
}

/// [`against_linear`] on the mesh whose triangles `sided(index)` picks are two-sided.
pub fn against_linear_sided<S: Scalar>(
    rng: &mut Rng,
    src: &[[P; 3]],
    sided: fn(usize) -> bool,
    sweeps: usize,
    half: f64,
) {
    against_linear_by_sided::<S>(rng, src, sided, sweeps, |rng, k| {
        let r = match k % 4 {
            0 => 0.0,
            1 => rng.range(0.01, 0.2),
            _ => rng.range(0.2, 1.0),
        };
        let p0 = rng.point(half);
        let p1 = match k % 3 {
            0 => rng.point(half),
            1 => {
                let d = rng.point(0.7);
                [p0[0] + d[0], p0[1] + d[1] - 0.3, p0[2] + d[2]]
            }
            _ => {
                // Aimed at a vertex, where many triangles tie.
                let t = src[(rng.next() * src.len() as f64) as usize];
                let at = t[(rng.next() * 3.0) as usize];
                let e = rng.range(1.0, 2.0);
                [0, 1, 2].map(|a| p0[a] + e * (at[a] - p0[a]))
            }
        };
        (p0, p1, r)
    });
}

/// Checks `sweeps` sweeps made by `sweep(rng, k)` (start, end, radius) against the linear scan.
pub fn against_linear_by<S: Scalar>(
    rng: &mut Rng,
    src: &[[P; 3]],
    sweeps: usize,
    sweep: impl FnMut(&mut Rng, usize) -> (P, P, f64),
) {
    against_linear_by_sided::<S>(rng, src, |_| false, sweeps, sweep);
}

/// [`against_linear_by`] on the mesh whose triangles `sided(index)` picks are two-sided.
pub fn against_linear_by_sided<S: Scalar>(
    rng: &mut Rng,
    src: &[[P; 3]],
    sided: fn(usize) -> bool,
    sweeps: usize,
    mut sweep: impl FnMut(&mut Rng, usize) -> (P, P, f64),
) {
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build_sided(&input, sided, Degenerates::Skip).unwrap();
    // The same triangles under a tree of leaves of four: the same answers.
    let four = Degenerates::Skip.with_leaf_size(LeafSize::Four);
    let small = build_sided(&input, sided, four).unwrap();
    let (mesh, reference) = (owned.mesh(), owned.reference());
    let mut hits = 0;
    for k in 0..sweeps {
        let (p0, p1, r) = sweep(rng, k);
        let Ok(sweep) = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)) else {
            continue;
        };
        let (got, want) = (mesh.cast(&sweep), reference(&sweep));
        assert_eq!(got, want, "sweep {k}: {p0:?} -> {p1:?}, r {r}");
        let leaves_of_four = small.mesh().cast(&sweep);
        assert_eq!(leaves_of_four, want, "leaves of four, sweep {k}");
        hits += got.is_some() as usize;
    }
    // The sweeps must exercise the tree: a fair share of them hit something.
    assert!(hits > sweeps / 10, "only {hits} of {sweeps} sweeps hit");
}

/// A long path (`length` units) that grazes a feature of a random triangle of `src`: its line
/// passes a vertex or a point of an edge at the radius, within ±1 %, so the answer hangs on
/// the last steps of rounding (what the culling's pad must allow for). Half of them pass the
/// mesh's extreme vertex along an axis, square to it, where every box holding it ends: a box
/// grown by the radius alone would cut them off. Returns start, end and radius.
pub fn grazing(rng: &mut Rng, src: &[[P; 3]], length: f64) -> (P, P, f64) {
    use crate::common::{add, cross, norm, scale, sub};
    let t = src[(rng.next() * src.len() as f64) as usize];
    let unit = |a: P| scale(a, 1.0 / norm(a));
    let (f, u, o) = if rng.next() < 0.5 {
        let (a, up) = ((rng.next() * 3.0) as usize, rng.next() < 0.5);
        let sign = if up { 1.0 } else { -1.0 };
        let f = *src
            .iter()
            .flatten()
            .max_by(|p, q| (sign * p[a]).total_cmp(&(sign * q[a])))
            .unwrap();
        let mut u = rng.point(1.0);
        u[a] = 0.0;
        let mut o = [0.0; 3];
        o[a] = sign;
        (f, unit(u), o)
    } else {
        let i = (rng.next() * 3.0) as usize;
        // A vertex a third of the time, else a point of an edge.
        let f = if rng.next() < 1.0 / 3.0 {
            t[i]
        } else {
            add(t[i], scale(sub(t[(i + 1) % 3], t[i]), rng.next()))
        };
        let u = unit(rng.point(1.0));
        (f, u, unit(cross(u, rng.point(1.0))))
    };
    let r = rng.range(0.05, 1.0);
    let closest = add(f, scale(o, r * rng.range(0.99, 1.01)));
    let before = length * rng.range(0.05, 0.95);
    (
        sub(closest, scale(u, before)),
        add(closest, scale(u, length - before)),
        r,
    )
}

/// A path along (or nearly along) the plane of a random triangle of `src`, starting over a point
/// of it at a height of a few roundings to a little over the radius, in front or behind: whether
/// the ball starts behind the plane or moves away from its front hangs on the heights' last
/// steps. Returns start, end and radius.
pub fn along_plane(rng: &mut Rng, src: &[[P; 3]]) -> (P, P, f64) {
    use crate::common::{add, cross, norm, scale, sub};
    let t = src[(rng.next() * src.len() as f64) as usize];
    let (e, f) = (sub(t[1], t[0]), sub(t[2], t[0]));
    let n = cross(e, f);
    let n = scale(n, 1.0 / norm(n));
    let (a, b) = (rng.next(), rng.next());
    let (a, b) = if a + b > 1.0 {
        (1.0 - a, 1.0 - b)
    } else {
        (a, b)
    };
    let on = add(t[0], add(scale(e, a), scale(f, b)));
    let r = rng.range(0.05, 1.0);
    let height = match (rng.next() * 4.0) as usize {
        0 => 0.0,
        1 => rng.range(-1e-5, 1e-5),
        2 => r * rng.range(-0.2, 1.2),
        _ => r * rng.range(0.9, 1.1),
    };
    let p0 = add(on, scale(n, height));
    let tilt = [0.0, 1e-6, -1e-6, rng.range(-1e-3, 1e-3)][(rng.next() * 4.0) as usize];
    let d = add(
        add(
            scale(e, rng.range(-1.0, 1.0)),
            scale(f, rng.range(-1.0, 1.0)),
        ),
        scale(n, tilt),
    );
    (p0, add(p0, d), r)
}

/// One test module per property, with a test per scalar: `per_scalar!(a, b #[ignore = ".."])`
/// runs `a::<f32>()`, `a::<f64>()`, `a::<I16F16>()` and `a::<I32F32>()` as `a::f32` and so on
/// (the test file imports `I16F16` and `I32F32`).
#[allow(unused_macros)] // not every test that shares this module has per-scalar properties
macro_rules! per_scalar {
    ($($test:ident $(#[$attr:meta])*),* $(,)?) => {$(
        mod $test {
            $(#[$attr])*
            #[test]
            fn f32() {
                super::$test::<f32>()
            }
            $(#[$attr])*
            #[test]
            fn f64() {
                super::$test::<f64>()
            }
            $(#[$attr])*
            #[test]
            fn i16f16() {
                super::$test::<super::I16F16>()
            }
            $(#[$attr])*
            #[test]
            fn i32f32() {
                super::$test::<super::I32F32>()
            }
        }
    )*};
}
#[allow(unused_imports)]
pub(crate) use per_scalar;

/// A closed sphere of radius `radius` about the origin: an octahedron's faces split `n` times
/// into four, the new vertices put on the sphere. Fronts outward.
pub fn sphere(radius: f64, n: usize) -> Vec<[P; 3]> {
    let on = |p: P| scale(p, radius / norm(p));
    let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let neg = |p: P| scale(p, -1.0);
    let mut tris: Vec<[P; 3]> = Vec::new();
    for (a, b) in [(x, z), (z, neg(x)), (neg(x), neg(z)), (neg(z), x)] {
        tris.push([a, b, y]);
        tris.push([b, a, neg(y)]);
    }
    for _ in 0..n {
        let mut finer = Vec::new();
        for [a, b, c] in tris {
            let mid = |p: P, q: P| scale(add(p, q), 0.5);
            let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
            finer.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        tris = finer;
    }
    let tris: Vec<[P; 3]> = tris.into_iter().map(|t| t.map(on)).collect();
    // Fronts outward: `(b - a) × (c - a)` along the centre's direction.
    tris.into_iter()
        .map(|[a, b, c]| {
            let n = cross(sub(b, a), sub(c, a));
            if dot(n, add(add(a, b), c)) < 0.0 {
                [a, c, b]
            } else {
                [a, b, c]
            }
        })
        .collect()
}

/// A shot at the closed sphere `src` (about the origin, as [`sphere`] makes it): the `i`-th
/// kind of point where its faces meet (by `i % 3`: a vertex, an edge's middle, a random point
/// along an edge) and a unit direction within 60° of the outward normal there, along which a
/// shot comes in; `None` where the draw fell outside that cone.
pub fn shot_at_sphere(rng: &mut Rng, src: &[[P; 3]], i: usize) -> Option<(P, P)> {
    let [a, b, _] = src[(rng.next() * src.len() as f64) as usize % src.len()];
    let at = match i % 3 {
        0 => a,
        1 => scale(add(a, b), 0.5),
        _ => add(a, scale(sub(b, a), rng.range(0.05, 0.95))),
    };
    let out = scale(at, 1.0 / norm(at));
    let tilt = loop {
        let t = rng.point(1.0);
        if norm(t) <= 1.0 {
            break t;
        }
    };
    let dir = add(out, scale(tilt, 1.7));
    let dir = scale(dir, 1.0 / norm(dir));
    (dot(dir, out) >= 0.5).then_some((at, dir))
}
