//! What a bake made of a level, as the statistics line the bake prints (and writes as the
//! baked file's second line): the form and its sizes, the degenerate triangles skipped with
//! the places of the first few in the file, and the planner's verdict at the level's extent.

use super::{Level, Origin};
use ballcast::bvh::LeafSize;
use std::fmt;

/// The form a level was baked into, with what sizes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Form {
    /// A prepared [`ballcast::Mesh`]: every triangle prepared, under a tree of `nodes` nodes with leaves
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
    /// Where the first few of `skipped` came from in the file (up to [`PLACES_SHOWN`], in
    /// the same order), for the statistics line; empty where the level does not know.
    pub skipped_origins: Vec<Origin>,
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
            "{} {}: {} triangles, {} degenerate skipped{}{}, {} two-sided, {} bytes in flash ({:.1} per triangle)",
            self.scalar,
            self.form,
            self.triangles,
            self.skipped.len(),
            first_few(&self.skipped),
            places(&self.skipped, &self.skipped_origins),
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

/// How many of the skipped triangles the statistics line places in the file: a glTF place
/// runs to some sixty characters, and the first few are enough to find the export's fault.
pub const PLACES_SHOWN: usize = 3;

/// ` (4: line 10; 5: line 11, triangle 2 of 2 in its polygon)`: the places of the first
/// skipped triangles, or nothing where they are not known.
fn places(skipped: &[usize], origins: &[Origin]) -> String {
    let each: Vec<String> = (skipped.iter().zip(origins))
        .map(|(i, o)| format!("{i}: {o}"))
        .collect();
    match each.is_empty() {
        true => String::new(),
        false => format!(" ({})", each.join("; ")),
    }
}

/// Where the first [`PLACES_SHOWN`] of `skipped` came from, if the level knows all of them.
pub(crate) fn skipped_origins(level: &Level, skipped: &[usize]) -> Vec<Origin> {
    let first = skipped.iter().take(PLACES_SHOWN);
    first
        .map(|&i| level.origin(i))
        .collect::<Option<_>>()
        .unwrap_or_default()
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
