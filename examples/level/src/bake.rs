//! The bake: a level's triangles, range-checked for the scalar, built into a [`Mesh`] as at
//! run time, written out as Rust source through `const` constructors, one line per node or
//! triangle.

use super::source::{self, list, point};
use super::{Level, LevelError, Problem};
use ballcast::bvh::{LeafSize, nodes_for_leaves};
use ballcast::{Degenerates, Error, Mesh, Node, Scalar, StandardTriangle, Triangle, Vec3};
use fixed::types::{I2F30, I2F62, I16F16, I32F32};
use std::fmt::{self, Write};

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

/// The form a level was baked into, with what sizes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Form {
    /// A prepared [`Mesh`]: every triangle prepared, under a tree of `nodes` nodes with leaves
    /// of up to `leaf_size` triangles.
    Mesh {
        /// Tree nodes.
        nodes: usize,
        /// The most triangles in a leaf.
        leaf_size: LeafSize,
    },
    /// A [`ballcast::CompactMesh`]: shared vertices and three indices a triangle, under a tree
    /// of `nodes` nodes with leaves of four.
    Compact {
        /// Tree nodes.
        nodes: usize,
        /// Shared vertices.
        vertices: usize,
        /// The index type (`u16` or `u32`).
        index: &'static str,
    },
    /// A [`ballcast::Heightfield`]: a grid of 16-bit heights.
    Heightfield {
        /// Cells along x.
        columns: u32,
        /// Cells along z.
        rows: u32,
        /// Cells left out as holes.
        holes: usize,
    },
}

impl fmt::Display for Form {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Mesh { nodes, leaf_size } => write!(
                f,
                "prepared mesh, {nodes} nodes (leaves of up to {})",
                leaf_size.triangles()
            ),
            Self::Compact {
                nodes,
                vertices,
                index,
            } => write!(
                f,
                "compact mesh, {nodes} nodes (leaves of up to 4), {vertices} vertices, {index} indices"
            ),
            Self::Heightfield {
                columns,
                rows,
                holes,
            } => write!(f, "heightfield, {columns} x {rows} cells, {holes} holes"),
        }
    }
}

/// What a bake made of a level.
#[derive(Clone, Debug, PartialEq)]
pub struct Stats {
    /// The scalar.
    pub scalar: &'static str,
    /// The form and its sizes.
    pub form: Form,
    /// Triangles in the level (a heightfield's: two a cell, holes included).
    pub triangles: usize,
    /// Input indices of the degenerate triangles left out.
    pub skipped: Vec<usize>,
    /// Two-sided triangles kept.
    pub two_sided: usize,
    /// Bytes of the statics.
    pub bytes: usize,
    /// The largest coordinate's magnitude.
    pub extent: f64,
}

impl Stats {
    /// Bytes in flash per triangle kept.
    pub fn per_triangle(&self) -> f64 {
        self.bytes as f64 / (self.triangles - self.skipped.len()).max(1) as f64
    }
}

impl fmt::Display for Stats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {}: {} triangles, {} degenerate skipped{}, {} two-sided, {} bytes in flash ({:.1} per triangle)",
            self.scalar,
            self.form,
            self.triangles,
            self.skipped.len(),
            first_few(&self.skipped),
            self.two_sided,
            self.bytes,
            self.per_triangle()
        )
    }
}

/// Up to eight of `indices` as ` [a, b, …]`, and how many more there are: a level of many
/// degenerate triangles would otherwise make a line of hundreds of kilobytes.
fn first_few(indices: &[usize]) -> String {
    const SHOWN: usize = 8;
    let listed: Vec<String> = indices.iter().take(SHOWN).map(usize::to_string).collect();
    match indices.len() {
        0 => String::new(),
        n if n <= SHOWN => format!(" [{}]", listed.join(", ")),
        n => format!(" [{}, … and {} more]", listed.join(", "), n - SHOWN),
    }
}

/// `x` to four significant figures, trailing zeros dropped (an exponent beyond 10^±6).
fn figures(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return x.to_string();
    }
    let magnitude = x.abs().log10().floor();
    if !(-6.0..6.0).contains(&magnitude) {
        return format!("{x:.3e}");
    }
    let decimals = (3.0 - magnitude).max(0.0) as usize;
    let text = format!("{x:.decimals$}");
    match text.contains('.') {
        true => text.trim_end_matches('0').trim_end_matches('.').to_string(),
        false => text,
    }
}

/// The planner's verdict on every scalar at `extent` for a ball of `radius`, one phrase each.
pub fn verdicts(extent: f64, radius: f64) -> String {
    let v: Vec<String> = ballcast::plan(extent, radius, 2.0 * extent)
        .iter()
        .map(|v| {
            if v.fits {
                format!(
                    "{} fits (position error {:.1e}, radius at least {:.1e})",
                    v.precision.scalar, v.position_error, v.min_radius
                )
            } else {
                format!("{} does not fit", v.precision.scalar)
            }
        })
        .collect();
    let extent = figures(extent);
    format!("plan at extent {extent}, radius {radius}: {}", v.join("; "))
}

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
        let stats = Stats {
            scalar: S::NAME,
            form: Form::Mesh {
                nodes: mesh.nodes().len(),
                leaf_size,
            },
            triangles: sources.len(),
            skipped: skipped(&sources),
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
