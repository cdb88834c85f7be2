//! [`CompactMesh`]: a [`Mesh`]'s tree over shared vertices and indexed triangles, about 19
//! bytes per triangle of a terrain in `f32` or `I16F16` (a prepared mesh: 100), answering exactly
//! as the prepared mesh.
//!
//! # Layout
//! The prepared mesh's [`Node`]s and [`Grid`] as they are; per triangle, in the tree's leaf
//! order, its three vertex indices, its input index (both [`MeshIndex`]: `u16` for up to 65 535
//! vertices and triangles, else `u32`) and one byte: the [`Features`] bits (active edges and
//! vertices) and bit 6 for a two-sided triangle. The vertices are the caller's, shared.
//!
//! # Query
//! The tree is walked as [`Mesh::cast`] walks it; each triangle of a leaf reached is rebuilt
//! from its vertices, prepared by [`StandardTriangle::new`] (the prepared mesh's own
//! preparation, so the result is the same, bit for bit) with its stored features, and cast.
//! Behind the integer box (where `f64` is software) the preparation comes in two halves: the
//! triangle's frame, and the rest only where the sweep's heights above its plane leave a
//! contact possible.
//! Preparing costs a few hundred instructions per triangle reached: a query costs more than on
//! the prepared mesh, in exchange for a sixth of the memory.

use crate::bvh::{self, Grid, Node};
use crate::contact::within_reach;
use crate::cull::{Path, SOFT_F64, UnitBox, UnitHeights};
use crate::merge::{Earliest, earliest};
use crate::scalar::{largest, smallest};
use crate::triangle::Frame;
use crate::{
    Features, Geometry, Hit, Mesh, Scalar, SceneHit, StandardTriangle, Sweep, Triangle, Vec3,
};
use core::fmt;

/// The two-sided bit of a triangle's byte.
const TWO_SIDED: u8 = 1 << 6;

/// An index into a compact mesh's vertices or input triangles: `u16` or `u32`.
pub trait MeshIndex: Copy + sealed::Sealed {
    /// The largest index this type holds.
    const MAX: usize;
    /// The index as a `usize`.
    fn get(self) -> usize;
}

mod sealed {
    /// Made only by [`CompactMesh::compact`](super::CompactMesh::compact), which checks the
    /// range first.
    pub trait Sealed {
        fn from_usize(i: usize) -> Self;
    }
    impl Sealed for u16 {
        fn from_usize(i: usize) -> Self {
            i as u16
        }
    }
    impl Sealed for u32 {
        fn from_usize(i: usize) -> Self {
            i as u32
        }
    }
}

impl MeshIndex for u16 {
    const MAX: usize = u16::MAX as usize;
    fn get(self) -> usize {
        self as usize
    }
}

impl MeshIndex for u32 {
    const MAX: usize = u32::MAX as usize;
    fn get(self) -> usize {
        self as usize
    }
}

/// A mesh of shared vertices and indexed triangles behind a [`Mesh`]'s tree, borrowing its
/// parts. See the [module docs](self).
///
/// ```
/// use ballcast::{CompactMesh, Degenerates, Mesh, Node, Sweep, Triangle, Vec3};
/// let v = Vec3::new;
/// let vertices = [v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)];
/// let indices = [[0u32, 1, 2], [0, 2, 3]];
/// let tris = indices.map(|[a, b, c]| Triangle::new(vertices[a as usize], vertices[b as usize], vertices[c as usize]));
/// let (mut nodes, mut prepared, mut order) = ([Node::default(); 1], [Mesh::<f32>::filler(); 2], [0u32; 2]);
/// let (mesh, _) = Mesh::build(&tris, Degenerates::Refuse, &mut nodes, &mut prepared, &mut order, &mut [0u64; 12])?;
/// let (mut triangles, mut input, mut bytes) = ([[0u16; 3]; 2], [0u16; 2], [0u8; 2]);
/// let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut triangles, &mut input, &mut bytes)?;
/// let ball = Sweep::new(v(1.0, 3.0, 1.0), v(1.0, -1.0, 1.0), 0.5)?;
/// assert_eq!(compact.cast(&ball), mesh.cast(&ball));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompactMesh<'a, S: Scalar, I: MeshIndex = u16> {
    nodes: &'a [Node],
    grid: Grid,
    vertices: &'a [Vec3<S>],
    triangles: &'a [[I; 3]],
    order: &'a [I],
    bytes: &'a [u8],
    class: u8,
}

/// Why [`CompactMesh::compact`] refused.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompactError {
    /// An output buffer holds fewer than `needed` entries (one per triangle of the mesh).
    Capacity {
        /// Entries needed.
        needed: usize,
    },
    /// A vertex or triangle index beyond what the index type holds.
    Index {
        /// The index.
        index: usize,
        /// The index type's largest.
        max: usize,
    },
    /// Input triangle `index` is not what the mesh prepared (other vertices or indices than
    /// those it was built from), or refers to a vertex that does not exist.
    Mismatch {
        /// Its index in the input.
        index: usize,
    },
}

impl fmt::Display for CompactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Capacity { needed } => write!(f, "buffer too small: {needed} entries needed"),
            Self::Index { index, max } => {
                write!(f, "index {index} beyond the index type's largest, {max}")
            }
            Self::Mismatch { index } => write!(
                f,
                "triangle {index} differs from the mesh's (other vertices, or a vertex missing)"
            ),
        }
    }
}

impl core::error::Error for CompactError {}

impl<'a, S: Scalar, I: MeshIndex> CompactMesh<'a, S, I> {
    /// A compact mesh from parts made by [`compact`](Self::compact) (or baked from them), in
    /// a `const` context, so it can be a `static`. Nothing is checked here; parts from
    /// elsewhere can give wrong answers, never undefined behaviour, and no panic in a release
    /// build (with overflow checks on, as in a debug build, out-of-range parts can trip them).
    pub const fn from_parts(
        nodes: &'a [Node],
        grid: Grid,
        vertices: &'a [Vec3<S>],
        triangles: &'a [[I; 3]],
        order: &'a [I],
        bytes: &'a [u8],
        class: u8,
    ) -> Self {
        Self {
            nodes,
            grid,
            vertices,
            triangles,
            order,
            bytes,
            class,
        }
    }

    /// The compact form of `mesh`, built from the triangles `indices` (input order) over
    /// `vertices`: writes each triangle's vertex indices, input index and feature byte in the
    /// mesh's leaf order into the three buffers (one entry per triangle of the mesh) and borrows
    /// the mesh's tree. Every triangle is prepared again and checked against the mesh's, so the
    /// answers are the prepared mesh's. Time `O(N)`, no allocation.
    ///
    /// Errors: [`CompactError`]: a buffer too small, an index beyond `I`, a triangle that is
    /// not the mesh's.
    pub fn compact(
        mesh: &Mesh<'a, S>,
        vertices: &'a [Vec3<S>],
        indices: &[[u32; 3]],
        triangles: &'a mut [[I; 3]],
        order: &'a mut [I],
        bytes: &'a mut [u8],
    ) -> Result<Self, CompactError> {
        let n = mesh.len();
        if triangles.len() < n || order.len() < n || bytes.len() < n {
            return Err(CompactError::Capacity { needed: n });
        }
        let fits = |index: usize| {
            (index <= I::MAX)
                .then_some(())
                .ok_or(CompactError::Index { index, max: I::MAX })
        };
        fits(vertices.len().saturating_sub(1))?;
        let mut class = 0;
        for (s, (prepared, &input)) in mesh.triangles().iter().zip(mesh.order()).enumerate() {
            let index = input as usize;
            fits(index)?;
            let mismatch = CompactError::Mismatch { index };
            let corners = indices.get(index).ok_or(mismatch)?;
            let rebuilt = triangle(vertices, corners.map(|c| c as usize)).ok_or(mismatch)?;
            let byte = prepared.features().bits() | (TWO_SIDED * prepared.is_two_sided() as u8);
            let again = prepare(&rebuilt, byte).ok_or(mismatch)?;
            if again.to_parts() != prepared.to_parts() {
                return Err(mismatch);
            }
            class = class.max(bvh::class_of(prepared) as u8);
            triangles[s] = corners.map(|c| I::from_usize(c as usize));
            order[s] = I::from_usize(index);
            bytes[s] = byte;
        }
        let (triangles, order, bytes): (&'a [[I; 3]], &'a [I], &'a [u8]) =
            (&triangles[..n], &order[..n], &bytes[..n]);
        Ok(Self::from_parts(
            mesh.nodes(),
            mesh.grid(),
            vertices,
            triangles,
            order,
            bytes,
            class,
        ))
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Whether the mesh holds no triangle.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The tree's nodes and grid, the vertices, per triangle in leaf order its vertex indices,
    /// input index and feature byte, and the worst seam class: what
    /// [`from_parts`](Self::from_parts) takes.
    #[allow(clippy::type_complexity)]
    pub fn parts(
        &self,
    ) -> (
        &'a [Node],
        Grid,
        &'a [Vec3<S>],
        &'a [[I; 3]],
        &'a [I],
        &'a [u8],
        u8,
    ) {
        (
            self.nodes,
            self.grid,
            self.vertices,
            self.triangles,
            self.order,
            self.bytes,
            self.class,
        )
    }

    /// The earliest contact along the sweep: the prepared mesh's answer, bit for bit.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.cast_culled(sweep, SOFT_F64)
    }

    /// [`cast`](Self::cast), passing triangles by before preparing them with the `f64` box and
    /// plane tests, or (`integer`, for a fixed-point sweep) with its box in integers alone: where
    /// `f64` is software (a Cortex-M) the `f64` tests cost more than the preparations they
    /// save. Either way the answer is the same.
    fn cast_culled(&self, sweep: &Sweep<S>, integer: bool) -> Option<SceneHit<S>> {
        let cells = self.grid.lo.iter().chain(&self.grid.hi);
        let extent =
            cells.fold(0.0f64, |m, &c| m.max((c as f64).abs())) / Grid::scale(self.grid.exponent);
        // The `f64` path only where it is used: its reciprocals are software on a Cortex-M.
        let units = integer
            .then(|| UnitBox::new(sweep, Path::pad(sweep, extent, self.class)))
            .flatten();
        // Behind the integer box, the heights bounded in integers too (see `cull::heights`).
        let heights = units.as_ref().and_then(|_| UnitHeights::new(sweep));
        let cull = match units {
            Some(b) => Err(b),
            None => Ok(Path::new(sweep, extent, self.class)),
        };
        let corners = |s: usize| Some(self.triangles.get(s)?.map(I::get));
        let slot = |s: usize| -> Option<(usize, StandardTriangle<S>)> {
            let t = triangle(self.vertices, corners(s)?)?;
            Some((self.order.get(s)?.get(), prepare(&t, *self.bytes.get(s)?)?))
        };
        // Slot `s`'s contact within the reach. Behind the integer box (whose triangles the
        // heights often pass by: it tests no plane) the triangle's frame comes first, and the
        // rest of its preparation only where the heights leave a contact possible; behind the
        // `f64` plane test they seldom do, and the triangle is prepared at once.
        let cast_slot = |s: usize, reach: S| -> Option<(usize, Hit<S>)> {
            let (t, byte) = (triangle(self.vertices, corners(s)?)?, *self.bytes.get(s)?);
            let hit = if cull.is_err() {
                cast_lazily(&t, byte, sweep, reach)
            } else {
                prepare(&t, byte)?.cast_within(sweep, reach)
            };
            Some((self.order.get(s)?.get(), hit?))
        };
        // Whether slot `s` may hold a contact within the reach (preparing costs far more).
        let near = |acc: &Earliest<S>, s: usize| -> Option<()> {
            let c = corners(s)?;
            let path = match &cull {
                Ok(path) => path,
                Err(b) => {
                    let v = triangle(self.vertices, c)?.vertices();
                    let one_sided = self.bytes.get(s).is_some_and(|b| b & TWO_SIDED == 0);
                    let out = b.misses(v)
                        || heights
                            .as_ref()
                            .is_some_and(|h| h.rule_out(sweep, v, acc.reach(), one_sided));
                    return (!out).then_some(());
                }
            };
            let limit = S::to_f64(acc.reach()) + 1.0 / (1u64 << 50) as f64;
            let v = world(self.vertices, c)?;
            // Coordinates of validated vertices: never NaN.
            let lo = [0, 1, 2].map(|a| smallest(v[0][a], v[1][a], v[2][a]));
            let hi = [0, 1, 2].map(|a| largest(v[0][a], v[1][a], v[2][a]));
            let two_sided = self.bytes.get(s).is_some_and(|b| b & TWO_SIDED != 0);
            let span = path.clip(lo, hi, limit)?;
            path.near_triangle(v, span, !two_sided).then_some(())
        };
        let mut sound = true;
        let hit = earliest(|acc: &mut Earliest<S>| {
            sound &= bvh::leaves_along(self.nodes, &self.grid, sweep, acc, |acc, slots, _| {
                for s in slots {
                    if near(acc, s).is_some()
                        && let Some((i, hit)) = cast_slot(s, acc.reach())
                    {
                        acc.offer(i, hit);
                    }
                }
            });
        });
        if sound {
            return hit;
        }
        // Malformed parts (never from `compact`): test every triangle.
        earliest(|acc| {
            for s in 0..self.triangles.len() {
                if let Some((i, t)) = slot(s)
                    && let Some(hit) = t.cast(sweep)
                {
                    acc.offer(i, hit);
                }
            }
        })
    }
}

/// The corners of `vertices` at `corners` in `f64`, if they exist.
fn world<S: Scalar>(vertices: &[Vec3<S>], corners: [usize; 3]) -> Option<[[f64; 3]; 3]> {
    let v = |k: usize| vertices.get(corners[k]);
    Some([v(0)?, v(1)?, v(2)?].map(|p| p.to_array().map(S::to_f64)))
}

/// The triangle of `vertices` at `corners`, if they exist.
fn triangle<S: Scalar>(vertices: &[Vec3<S>], corners: [usize; 3]) -> Option<Triangle<S>> {
    let v = |k: usize| vertices.get(corners[k]).copied();
    Some(Triangle::new(v(0)?, v(1)?, v(2)?))
}

/// `t` prepared with the features and sidedness of `byte`.
fn prepare<S: Scalar>(t: &Triangle<S>, byte: u8) -> Option<StandardTriangle<S>> {
    Some(with_byte(StandardTriangle::new(t).ok()?, byte))
}

/// The contact of `t` (a triangle with `byte`) with the sweep at alpha `reach` or earlier, its
/// preparation finished only if the heights of the sweep above its plane leave one possible.
#[inline(never)]
fn cast_lazily<S: Scalar>(t: &Triangle<S>, byte: u8, sweep: &Sweep<S>, reach: S) -> Option<Hit<S>> {
    let frame = Frame::of(t).ok()?;
    let heights = frame.heights(sweep);
    within_reach(sweep, heights, byte & TWO_SIDED != 0, reach)?;
    with_byte(frame.finish(t).ok()?, byte).cast_within_heights(sweep, heights, reach)
}

/// A prepared triangle with the active edges and sidedness of its byte.
fn with_byte<S: Scalar>(st: StandardTriangle<S>, byte: u8) -> StandardTriangle<S> {
    let features = Features::from_bits(byte & Features::ALL.bits());
    st.with_features(features)
        .with_two_sided(byte & TWO_SIDED != 0)
}

impl<S: Scalar, I: MeshIndex> Geometry<S> for CompactMesh<'_, S, I> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        CompactMesh::cast(self, sweep)
    }

    /// Every triangle of the leaves whose boxes meet the box (the tree's box query) whose
    /// vertices' box meets it too, prepared.
    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        let (lo, hi) = (min.to_array().map(S::to_f64), max.to_array().map(S::to_f64));
        let query = bvh::query_cells(&self.grid, lo, hi);
        // A first walk that only checks the tree, so malformed parts (never from `compact`)
        // are scanned instead without a triangle given twice.
        if bvh::overlapping(self.nodes, &self.grid, query, |_| {}) {
            bvh::overlapping(self.nodes, &self.grid, query, |slots| {
                slots.for_each(|s| self.visit_slot(s, lo, hi, f))
            });
        } else {
            (0..self.triangles.len()).for_each(|s| self.visit_slot(s, lo, hi, f));
        }
    }
}

impl<S: Scalar, I: MeshIndex> CompactMesh<'_, S, I> {
    /// Calls `f` with triangle slot `s`, prepared, if its vertices' box meets `lo..hi`.
    fn visit_slot(
        &self,
        s: usize,
        lo: [f64; 3],
        hi: [f64; 3],
        f: &mut dyn FnMut(usize, &StandardTriangle<S>),
    ) {
        let Some(corners) = self.triangles.get(s) else {
            return;
        };
        let Some(v) = world(self.vertices, corners.map(I::get)) else {
            return;
        };
        let apart = (0..3).any(|a| {
            let (l, u) = (
                v[0][a].min(v[1][a]).min(v[2][a]),
                v[0][a].max(v[1][a]).max(v[2][a]),
            );
            u < lo[a] || l > hi[a]
        });
        if apart {
            return;
        }
        let t = triangle(self.vertices, corners.map(I::get));
        let byte = self.bytes.get(s).copied();
        if let (Some(t), Some(b), Some(i)) = (t, byte, self.order.get(s))
            && let Some(st) = prepare(&t, b)
        {
            f(i.get(), &st);
        }
    }
}

#[cfg(test)]
mod tests;
