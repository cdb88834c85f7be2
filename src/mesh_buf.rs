//! [`MeshBuf`]: a [`Mesh`] that owns its parts in `Vec`s, for PCs (feature `alloc`).

use crate::Triangle;
use crate::Vec3;
use crate::bvh::{Grid, Node, nodes_for_leaves};
use crate::compound::CompoundPart;
use crate::merge::Earliest;
use crate::{Geometry, Mesh, MeshError, MeshOptions, Scalar, SceneHit, StandardTriangle, Sweep};
use alloc::vec;
use alloc::vec::Vec;

/// A mesh owning its nodes, prepared triangles and order on the heap: [`Mesh::build`] with the
/// buffers allocated for you (the scratch is freed before returning). Lend it out with
/// [`mesh`](Self::mesh); it is also a [`Geometry`] itself.
///
/// ```
/// use ballcast::{Degenerates, MeshBuf, Sweep, Triangle, Vec3};
/// let v = Vec3::new;
/// let tris = [Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 0.0))];
/// let buf = MeshBuf::build(&tris, Degenerates::Refuse)?;
/// let hit = buf.mesh().cast(&Sweep::new(v(0.5, 2.0, 0.5), v(0.5, -1.0, 0.5), 0.5)?);
/// assert_eq!(hit.map(|h| h.alpha), Some(0.5));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct MeshBuf<S: Scalar> {
    nodes: Vec<Node>,
    triangles: Vec<StandardTriangle<S>>,
    order: Vec<u32>,
    grid: Grid,
    skipped: usize,
}

impl<S: Scalar> MeshBuf<S> {
    /// Builds the mesh of `sources` as [`Mesh::build`] does, into buffers it allocates.
    ///
    /// Errors: those of [`Mesh::build`] (never [`MeshError::Capacity`]).
    pub fn build(
        sources: &[Triangle<S>],
        options: impl Into<MeshOptions>,
    ) -> Result<Self, MeshError> {
        Self::build_sided(sources, |_| false, options)
    }

    /// [`build`](Self::build) as [`Mesh::build_sided`] builds: the triangles for which
    /// `two_sided(index)` holds stop balls from either side.
    pub fn build_sided(
        sources: &[Triangle<S>],
        two_sided: impl Fn(usize) -> bool,
        options: impl Into<MeshOptions>,
    ) -> Result<Self, MeshError> {
        let options = options.into();
        let n = sources.len();
        let mut nodes = vec![Node::default(); nodes_for_leaves(n, options.leaf_size)];
        let mut triangles = vec![Mesh::<S>::filler(); n];
        let mut order = vec![0u32; n];
        let mut scratch = vec![0u64; 6 * n];
        let (used, kept, grid, skipped) = {
            let (mesh, skipped) = Mesh::build_sided(
                sources,
                two_sided,
                options,
                &mut nodes,
                &mut triangles,
                &mut order,
                &mut scratch,
            )?;
            (mesh.nodes().len(), mesh.len(), mesh.grid(), skipped)
        };
        nodes.truncate(used);
        triangles.truncate(kept);
        order.truncate(kept);
        Ok(Self {
            nodes,
            triangles,
            order,
            grid,
            skipped,
        })
    }

    /// The mesh, borrowing these parts.
    pub fn mesh(&self) -> Mesh<'_, S> {
        Mesh::from_parts(&self.nodes, &self.triangles, &self.order, self.grid)
    }

    /// The earliest contact along the sweep: [`Geometry::cast`] without importing the trait.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.mesh().cast(sweep)
    }

    /// How many degenerate triangles the build skipped.
    pub fn skipped(&self) -> usize {
        self.skipped
    }
}

impl<S: Scalar> Geometry<S> for MeshBuf<S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.mesh().cast(sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.mesh().visit(min, max, f)
    }
}

impl<S: Scalar> CompoundPart<S> for MeshBuf<S> {
    fn index_bound(&self) -> usize {
        self.mesh().index_bound()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        self.mesh().offer_contacts(sweep, acc, scan)
    }
}
