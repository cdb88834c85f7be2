//! [`CompactMeshBuf`]: a [`CompactMesh`] that owns its parts, for PCs (feature `alloc`).

use super::{CompactError, CompactMesh};
use crate::SceneHit;
use crate::bvh::{Grid, LeafSize, Node};
use crate::cache::Slots;
use crate::compound::CompoundPart;
use crate::import::weld;
use crate::merge::Earliest;
use crate::{Cacheable, Degenerates, Error, Geometry, MeshBuf, MeshError, MeshPart, Scalar};
use crate::{StandardTriangle, Sweep, Triangle, Vec3};
use alloc::vec;
use alloc::vec::Vec;

/// A compact mesh owning its parts on the heap, made from a triangle soup in one call: the
/// corners welded into shared vertices ([`import::weld`](crate::import::weld)), the tree built
/// with leaves of four ([`MeshBuf`]), the prepared triangles dropped for their vertex indices
/// ([`CompactMesh::compact`], `u32` indices). About a quarter of a prepared mesh's memory
/// (26.7 bytes per triangle on a terrain of 10^5 triangles, against 103.3), for the time of
/// preparing each triangle a query reaches (a [`Cached`](crate::Cached) keeps a character's).
/// Lend it out with [`compact_mesh`](Self::compact_mesh); it is also a [`Geometry`], a
/// [`CompoundPart`] and [`Cacheable`] itself, answering as the prepared mesh of the same
/// triangles, bit for bit.
///
/// ```
/// use ballcast::{CompactMeshBuf, Degenerates, Sweep, Triangle, Vec3};
/// let v = Vec3::new;
/// let floor = [
///     Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0)),
///     Triangle::new(v(0.0, 0.0, 0.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)),
/// ];
/// let level = CompactMeshBuf::build(&floor, Degenerates::Refuse)?;
/// let hit = level.compact_mesh().cast(&Sweep::new(v(1.0, 2.0, 1.5), v(1.0, -1.0, 1.5), 0.5)?);
/// assert_eq!(hit.map(|h| h.alpha), Some(0.5));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CompactMeshBuf<S: Scalar> {
    nodes: Vec<Node>,
    grid: Grid,
    vertices: Vec<Vec3<S>>,
    triangles: Vec<[u32; 3]>,
    order: Vec<u32>,
    bytes: Vec<u8>,
    class: u8,
    skipped: usize,
}

impl<S: Scalar> CompactMeshBuf<S> {
    /// The compact mesh of `sources`, with the active edges and answers of
    /// [`Mesh::build`](crate::Mesh::build) under `degenerates`.
    ///
    /// Errors: those of [`Mesh::build`](crate::Mesh::build) (never [`MeshError::Capacity`]),
    /// a NaN coordinate as [`MeshError::Triangle`] naming its triangle.
    pub fn build(sources: &[Triangle<S>], degenerates: Degenerates) -> Result<Self, MeshError> {
        Self::build_sided(sources, |_| false, degenerates)
    }

    /// [`build`](Self::build) with the triangles for which `two_sided(index)` holds two-sided,
    /// as [`Mesh::build_sided`](crate::Mesh::build_sided) makes them.
    pub fn build_sided(
        sources: &[Triangle<S>],
        two_sided: impl Fn(usize) -> bool,
        degenerates: Degenerates,
    ) -> Result<Self, MeshError> {
        // The build first: its checks name the first bad triangle in input order, and refuse
        // too many before the weld sorts them all.
        let options = degenerates.with_leaf_size(LeafSize::Four);
        let mesh = MeshBuf::build_sided(sources, two_sided, options)?;
        let (mut vertices, indices) = weld(sources).map_err(|error| match error {
            Error::Full { .. } => MeshError::TooMany,
            error => MeshError::Triangle {
                index: error.triangle().unwrap_or(0),
                error,
            },
        })?;
        vertices.shrink_to_fit();
        let n = mesh.mesh().len();
        let (mut triangles, mut order, mut bytes) = (vec![[0u32; 3]; n], vec![0; n], vec![0; n]);
        let (nodes, grid, class) = {
            let m = mesh.mesh();
            let (t, o, b) = (&mut triangles, &mut order, &mut bytes);
            // The mesh was built from these very triangles: nothing can mismatch.
            let compact = CompactMesh::<S, u32>::compact(&m, &vertices, &indices, t, o, b)
                .map_err(|e| MeshError::Mismatch {
                    part: match e {
                        CompactError::Mismatch { index }
                        | CompactError::MissingTriangle { index, .. }
                        | CompactError::MissingVertex { index, .. } => MeshPart::Triangle { index },
                        _ => MeshPart::Len,
                    },
                })?;
            let (nodes, grid, _, _, _, _, class) = compact.parts();
            (nodes.to_vec(), grid, class)
        };
        Ok(Self {
            nodes,
            grid,
            vertices,
            triangles,
            order,
            bytes,
            class,
            skipped: mesh.skipped(),
        })
    }

    /// The compact mesh, borrowing these parts.
    pub fn compact_mesh(&self) -> CompactMesh<'_, S, u32> {
        CompactMesh::from_parts(
            &self.nodes,
            self.grid,
            &self.vertices,
            &self.triangles,
            &self.order,
            &self.bytes,
            self.class,
        )
    }

    /// The earliest contact along the sweep: [`Geometry::cast`] without importing the trait.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.compact_mesh().cast(sweep)
    }

    /// How many degenerate triangles the build skipped.
    pub fn skipped(&self) -> usize {
        self.skipped
    }
}

impl<S: Scalar> Geometry<S> for CompactMeshBuf<S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.compact_mesh().cast(sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.compact_mesh().visit(min, max, f)
    }
}

impl<S: Scalar> CompoundPart<S> for CompactMeshBuf<S> {
    fn index_bound(&self) -> usize {
        self.compact_mesh().index_bound()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        self.compact_mesh().offer_contacts(sweep, acc, scan)
    }
}

impl<S: Scalar> Cacheable<S> for CompactMeshBuf<S> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool {
        self.compact_mesh().offer_cached(sweep, acc, cache)
    }
}
