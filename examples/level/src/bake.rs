//! The bake: a level's triangles, range-checked for the scalar, built into a [`Mesh`] as at
//! run time, written out as Rust source through `const` constructors, one line per node or
//! triangle.

use super::source::{self, list, point};
use super::stats::skipped_origins;
use super::{Form, Level, LevelError, Problem, Stats};
use ballcast::bvh::{LeafSize, nodes_for_leaves};
use ballcast::{Degenerates, Error, Mesh, Node, Scalar, StandardTriangle, Triangle, Vec3};
use fixed::types::{I2F30, I2F62, I16F16, I32F32};
use std::fmt::Write;

/// A scalar the bake can write as source: its type's name and its values as raw bits.
pub trait Emit: Scalar {
    /// The type as written in source (`f32`, `I16F16`, ...).
    const NAME: &'static str;
    /// The unit-vector component type (`f32`, `I2F30`, ...).
    const UNIT: &'static str;
    /// The integer type of the raw bits of `NAME`.
    const BITS: &'static str;
    /// The integer type of the raw bits of `UNIT`.
    const UNIT_BITS: &'static str;
    /// Whether it is a `fixed` type (imported through `ballcast::fixed`).
    const FIXED: bool;
    /// A value's raw bits as a literal.
    fn bits(self) -> String;
    /// A unit component's raw bits as a literal.
    fn unit_bits(u: Self::Unit) -> String;
}

macro_rules! emit {
    ($s:ty, $u:ty, $bits:ty, $ubits:ty, $fixed:expr) => {
        impl Emit for $s {
            const NAME: &'static str = stringify!($s);
            const UNIT: &'static str = stringify!($u);
            const BITS: &'static str = stringify!($bits);
            const UNIT_BITS: &'static str = stringify!($ubits);
            const FIXED: bool = $fixed;
            fn bits(self) -> String {
                self.to_bits().to_string()
            }
            fn unit_bits(u: $u) -> String {
                u.to_bits().to_string()
            }
        }
    };
}
emit!(f32, f32, u32, u32, false);
emit!(f64, f64, u64, u64, false);
emit!(I16F16, I2F30, i32, i32, true);
emit!(I32F32, I2F62, i64, i64, true);

/// A level baked for scalar `S`: the source of the statics and what went into them.
#[derive(Clone, Debug, PartialEq)]
pub struct Baked {
    /// Rust source defining the statics of the form (`MESH: Mesh<'static, S>`,
    /// `MESH: CompactMesh<'static, S, I>` or `HEIGHTFIELD: Heightfield<'static, S>`, and the
    /// parts they borrow); it needs only the `ballcast` crate (fixed-point types are named
    /// through `ballcast::fixed`).
    pub source: String,
    /// What it holds.
    pub stats: Stats,
}

/// The level's triangles in `S`.
///
/// Errors: [`Problem::OutOfRange`] for a coordinate beyond `S::LIMIT`.
pub fn triangles<S: Scalar>(level: &Level) -> Result<Vec<Triangle<S>>, LevelError> {
    let limit = S::LIMIT.to_f64();
    let mut out = Vec::with_capacity(level.triangles.len());
    for (triangle, t) in level.triangles.iter().enumerate() {
        if let Some(&value) = t.iter().flatten().find(|c| c.abs() > limit) {
            let problem = Problem::OutOfRange {
                triangle,
                value,
                scalar: S::PRECISION.scalar.name(),
                limit,
            };
            return Err(LevelError::at(&level.path, problem, level.origin(triangle)));
        }
        let v = t.map(|p| Vec3::new(p[0], p[1], p[2]).map(S::from_f64));
        out.push(Triangle::new(v[0], v[1], v[2]));
    }
    Ok(out)
}

/// Bakes `level` for scalar `S`: builds the mesh as [`Mesh::build_sided`] does at run time
/// (degenerate triangles skipped and listed; the level's two-sided triangles two-sided) and
/// writes it as source.
///
/// Errors: [`Problem::OutOfRange`], [`Problem::AllDegenerate`] when no triangle is left, or
/// [`Problem::Mesh`] when the build refuses a triangle.
pub fn bake<S: Scalar + Emit>(level: &Level) -> Result<Baked, LevelError> {
    bake_with::<S>(level, LeafSize::Two)
}

/// [`bake`] with leaves of up to `leaf_size` triangles: [`LeafSize::Four`] takes 3.6 bytes per
/// triangle less flash for queries that test about 1.6 times the triangles. Check the statics
/// with `Mesh::verify_sided` given the same leaf size.
pub fn bake_with<S: Scalar + Emit>(
    level: &Level,
    leaf_size: LeafSize,
) -> Result<Baked, LevelError> {
    let sources = triangles::<S>(level)?;
    with_mesh(level, &sources, leaf_size, |mesh| {
        let skipped = skipped(&sources);
        let stats = Stats {
            scalar: S::NAME,
            form: Form::Mesh {
                nodes: mesh.nodes().len(),
                leaf_size,
            },
            triangles: sources.len(),
            skipped_origins: skipped_origins(level, &skipped),
            skipped,
            two_sided: mesh.triangles().iter().filter(|t| t.is_two_sided()).count(),
            bytes: size_of_val(mesh.triangles())
                + size_of_val(mesh.order())
                + size_of_val(mesh.nodes()),
            extent: extent(level),
        };
        let source = write::<S>(mesh, level, &stats);
        Baked { source, stats }
    })
}

/// `f` of the mesh [`Mesh::build_sided`] makes of the level's triangles `sources` at run time
/// (degenerate ones skipped, the level's two-sided ones two-sided).
///
/// Errors: [`Problem::Mesh`] when the build refuses a triangle, [`Problem::AllDegenerate`]
/// when none is left.
pub(crate) fn with_mesh<S: Scalar, R>(
    level: &Level,
    sources: &[Triangle<S>],
    leaf_size: LeafSize,
    f: impl FnOnce(&Mesh<S>) -> R,
) -> Result<R, LevelError> {
    let n = sources.len();
    let mut nodes = vec![Node::default(); nodes_for_leaves(n, leaf_size)];
    let mut prepared = vec![Mesh::<S>::filler(); n];
    let mut order = vec![0u32; n];
    let mut scratch = vec![0u64; 6 * n];
    let (mesh, _) = Mesh::build_sided(
        sources,
        |i| level.is_two_sided(i),
        Degenerates::Skip.with_leaf_size(leaf_size),
        &mut nodes,
        &mut prepared,
        &mut order,
        &mut scratch,
    )
    .map_err(|e| mesh_error(level, e))?;
    if mesh.is_empty() {
        return Err(LevelError::new(
            &level.path,
            Problem::AllDegenerate { count: n },
        ));
    }
    Ok(f(&mesh))
}

/// The error for a mesh build that refused: where it names a triangle, with its place.
pub(crate) fn mesh_error(level: &Level, e: ballcast::MeshError) -> LevelError {
    let origin = match e {
        ballcast::MeshError::Triangle { index, .. } => level.origin(index),
        _ => None,
    };
    LevelError::at(&level.path, Problem::Mesh(e), origin)
}

/// The indices of the degenerate triangles among `sources`, which a bake leaves out.
pub(crate) fn skipped<S: Scalar>(sources: &[Triangle<S>]) -> Vec<usize> {
    let degenerate = |t| matches!(StandardTriangle::new(t), Err(Error::Degenerate { .. }));
    (0..sources.len())
        .filter(|&i| degenerate(&sources[i]))
        .collect()
}

/// The largest coordinate's magnitude in the level.
pub(crate) fn extent(level: &Level) -> f64 {
    level
        .triangles
        .iter()
        .flatten()
        .flatten()
        .fold(0.0f64, |m, c| m.max(c.abs()))
}

fn write<S: Scalar + Emit>(mesh: &Mesh<S>, level: &Level, stats: &Stats) -> String {
    let (s, u, b, ub) = (S::NAME, S::UNIT, S::BITS, S::UNIT_BITS);
    let items = "Edge, Grid, Mesh, Node, Parts, StandardTriangle, Vec3";
    let mut o = source::header::<S>(&level.path, stats, items, true);
    let _ = writeln!(o, "const fn u(b: {ub}) -> {u} {{ {u}::from_bits(b) }}");
    let _ = writeln!(
        o,
        "const fn w(p: [{ub}; 3]) -> Vec3<{u}> {{ Vec3::new(u(p[0]), u(p[1]), u(p[2])) }}"
    );
    let _ = writeln!(
        o,
        "const fn e(d: [{ub}; 2], len: {b}) -> Edge<{s}> {{ Edge {{ dir: [u(d[0]), u(d[1])], len: s(len) }} }}"
    );
    let _ = writeln!(
        o,
        "#[allow(clippy::too_many_arguments)]\n\
         const fn t(origin: [{b}; 3], axes: [[{ub}; 3]; 3], shape: [{b}; 3], normal: [{b}; 3], \
         dirs: [[{ub}; 2]; 3], lens: [{b}; 3], features: u8, two_sided: bool, world_heights: bool) -> StandardTriangle<{s}> {{\n    \
         StandardTriangle::from_parts(Parts {{ origin: v(origin), axes: [w(axes[0]), w(axes[1]), w(axes[2])], \
         shape: [s(shape[0]), s(shape[1]), s(shape[2])], normal: v(normal), \
         edges: [e(dirs[0], lens[0]), e(dirs[1], lens[1]), e(dirs[2], lens[2])], features, two_sided, world_heights }})\n}}"
    );
    let ws = |p: Vec3<S::Unit>| list(&[p.x, p.y, p.z].map(S::unit_bits));
    source::nodes(&mut o, mesh.nodes());
    let tris = mesh.triangles();
    let _ = writeln!(
        o,
        "/// The prepared triangles, in leaf order.\npub static TRIANGLES: [StandardTriangle<{s}>; {}] = [",
        tris.len()
    );
    for t in tris {
        let p = t.to_parts();
        let axes: Vec<String> = p.axes.iter().map(|a| ws(*a)).collect();
        let dirs: Vec<String> = p
            .edges
            .iter()
            .map(|e| list(&e.dir.map(S::unit_bits)))
            .collect();
        let lens: Vec<String> = p.edges.iter().map(|e| e.len.bits()).collect();
        let _ = writeln!(
            o,
            "    t({}, {}, {}, {}, {}, {}, {}, {}, {}),",
            point(p.origin),
            list(&axes),
            list(&p.shape.map(S::bits)),
            point(p.normal),
            list(&dirs),
            list(&lens),
            p.features,
            p.two_sided,
            p.world_heights
        );
    }
    let _ = writeln!(o, "];");
    let _ = writeln!(
        o,
        "/// The level's index of each prepared triangle.\npub static ORDER: [u32; {}] = {:?};",
        mesh.order().len(),
        mesh.order()
    );
    let g = mesh.grid();
    let _ = writeln!(
        o,
        "/// The mesh, in flash.\npub static MESH: Mesh<'static, {s}> = Mesh::from_parts(&NODES, &TRIANGLES, &ORDER, Grid {{ exponent: {}, lo: {:?}, hi: {:?} }});",
        g.exponent, g.lo, g.hi
    );
    o
}
