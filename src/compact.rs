//! [`CompactMesh`]: a [`Mesh`]'s tree over shared vertices and indexed triangles, about 19
//! bytes per triangle of a terrain in `f32` or `I16F16` (a prepared mesh: 103), answering exactly
//! as the prepared mesh.
//!
//! # Layout
//! The prepared mesh's [`Node`]s and [`Grid`] as they are (build that mesh with leaves of
//! [`LeafSize::Four`](crate::bvh::LeafSize::Four): half the nodes of the default, 3.7 bytes
//! per triangle instead of 7.3, for queries that test more triangles); per triangle, in the tree's leaf
//! order, its three vertex indices, its input index (both [`MeshIndex`]: `u16` for up to 65 535
//! vertices and triangles, else `u32`) and one byte: the [`Features`](crate::Features) bits (active edges and
//! vertices) and bit 6 for a two-sided triangle. The vertices are the caller's, shared.
//!
//! # Query
//! The tree is walked as [`Mesh::cast`] walks it; each triangle of a leaf reached is rebuilt
//! from its vertices, prepared by [`StandardTriangle::new`](crate::StandardTriangle::new) (the prepared mesh's own
//! preparation, so the result is the same, bit for bit) with its stored features, and cast.
//! Where `f64` is software (a Cortex-M) a triangle is culled in integers: its box, then the
//! sweep's heights above its plane bounded from the vertices' exact normal (`cull/heights.rs`);
//! its preparation then comes in two halves, the
//! frame, and the rest only where the frame's heights leave a contact possible. Elsewhere the
//! culls are the `f64` box, plane and edge-line tests, and the triangle is prepared at once
//! (`query.rs`).
//! Preparing costs a few hundred instructions per triangle reached: a query costs more than on
//! the prepared mesh, in exchange for a fifth of the memory.

use crate::bvh::{self, Grid, Node};
use crate::{Mesh, Scalar, Vec3};
use core::fmt;
use query::prepare;

/// The two-sided bit of a triangle's byte.
const TWO_SIDED: u8 = 1 << 6;

/// An index into a compact mesh's vertices or input triangles: `u16` or `u32` (so it is
/// `Default`, zero, for buffers, and `Debug` and `PartialEq` as the mesh that holds it).
pub trait MeshIndex: Copy + Default + fmt::Debug + PartialEq + sealed::Sealed {
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
/// use ballcast::{bvh::LeafSize, CompactMesh, Degenerates, Mesh, Node, Sweep, Triangle, Vec3};
/// let v = Vec3::new;
/// let vertices = [v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)];
/// let indices = [[0u32, 1, 2], [0, 2, 3]];
/// let tris = indices.map(|[a, b, c]| Triangle::new(vertices[a as usize], vertices[b as usize], vertices[c as usize]));
/// let (mut nodes, mut prepared, mut order) = ([Node::default(); 1], [Mesh::<f32>::filler(); 2], [0u32; 2]);
/// // Leaves of four triangles: the smallest tree, which the compact mesh borrows.
/// let options = Degenerates::Refuse.with_leaf_size(LeafSize::Four);
/// let (mesh, _) = Mesh::build(&tris, options, &mut nodes, &mut prepared, &mut order, &mut [0u64; 12])?;
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
        /// Entries the shortest of the three output buffers holds.
        given: usize,
    },
    /// A vertex or triangle index beyond what the index type holds.
    Index {
        /// The index.
        index: usize,
        /// The index type's largest.
        max: usize,
    },
    /// Input triangle `index` is not what the mesh prepared (other vertices or indices than
    /// those it was built from).
    Mismatch {
        /// Its index in the input.
        index: usize,
    },
    /// The mesh holds input triangle `index`, beyond the `given` index triples.
    MissingTriangle {
        /// Its index in the input.
        index: usize,
        /// Index triples given.
        given: usize,
    },
    /// Input triangle `index` refers to vertex `vertex`, beyond the `given` vertices.
    MissingVertex {
        /// The triangle's index in the input.
        index: usize,
        /// The vertex index it holds.
        vertex: usize,
        /// Vertices given.
        given: usize,
    },
}

impl fmt::Display for CompactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Capacity { needed, given } => write!(
                f,
                "an output buffer holds {given} entries, too few: {needed} needed (triangles, \
                 order and bytes: one per triangle of the mesh)"
            ),
            Self::Index { index, max } => {
                write!(f, "index {index} beyond the index type's largest, {max}")
            }
            Self::Mismatch { index } => write!(
                f,
                "triangle {index} differs from the mesh's (other vertices or winding)"
            ),
            Self::MissingTriangle { index, given } => write!(
                f,
                "the mesh holds triangle {index}, beyond the {given} index triples given"
            ),
            Self::MissingVertex {
                index,
                vertex,
                given,
            } => write!(
                f,
                "triangle {index} refers to vertex {vertex}, beyond the {given} vertices given"
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
        let given = triangles.len().min(order.len()).min(bytes.len());
        if given < n {
            return Err(CompactError::Capacity { needed: n, given });
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
            let given = indices.len();
            let corners = indices
                .get(index)
                .ok_or(CompactError::MissingTriangle { index, given })?;
            if let Some(&c) = corners.iter().find(|&&c| c as usize >= vertices.len()) {
                return Err(CompactError::MissingVertex {
                    index,
                    vertex: c as usize,
                    given: vertices.len(),
                });
            }
            let byte = prepared.features().bits() | (TWO_SIDED * prepared.is_two_sided() as u8);
            let again = prepare(vertices, corners.map(|c| c as usize), byte).ok_or(mismatch)?;
            if !again.to_parts().identical(&prepared.to_parts()) {
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
}

#[cfg(feature = "alloc")]
mod buf;
mod query;
#[cfg(test)]
mod tests;

#[cfg(feature = "alloc")]
pub use buf::CompactMeshBuf;
