//! [`Mesh`]: many triangles behind a [`bvh`], borrowed from wherever they live (a
//! `static` in flash, a caller's buffer, `Vec`s on a PC), answering exactly as a linear scan.

mod build;
mod error;

pub use error::{Buffer, MeshError, MeshPart};

use crate::bvh::{self, Grid, LeafSize, Node};
use crate::compound::CompoundPart;
use crate::merge::{Earliest, earliest_of};
use crate::{Features, Geometry, Parts, Scalar, SceneHit, StandardTriangle, Sweep};
use crate::{Triangle, Vec3};

/// A triangle mesh with a bounding volume hierarchy, borrowing its parts.
///
/// `triangles[s]` is the prepared form (with active edges) of input triangle `order[s]`, in the
/// tree's leaf order; `nodes` and `grid` are the [`bvh`]. [`Mesh::build`] makes the
/// parts from a triangle list into caller-provided slices; [`Mesh::from_parts`] (a `const fn`)
/// takes baked ones. The answer of [`cast`](Mesh::cast) is, bit for bit, the one a linear scan of
/// the same prepared triangles in input order gives (the slice [`Geometry`]), including merged
/// simultaneous contacts; `index` is the triangle's index in the input.
///
/// Memory per triangle: the prepared triangle (92 bytes for `f32` and `I16F16`, 184 for `f64`
/// and `I32F32`), 4 bytes of `order`, and 7.3 bytes of nodes (a 44-byte node per about 6
/// triangles; 16 725 for 100 352): the tree adds about 11.3 bytes per triangle in every scalar.
/// With leaves of four ([`LeafSize::Four`]) the nodes take 3.7 bytes per triangle (8 364).
/// The build also needs six scratch words (48 bytes) per triangle while it runs.
///
/// ```
/// use ballcast::{Contact, Degenerates, Mesh, Node, Sweep, Triangle, Vec3};
/// let v = Vec3::new;
/// let tris = [
///     Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0)),
///     Triangle::new(v(0.0, 0.0, 0.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)),
/// ];
/// let mut nodes = [Node::default(); 1];
/// let mut prepared = [Mesh::<f32>::filler(); 2];
/// let mut order = [0u32; 2];
/// let mut scratch = [0u64; 12];
/// let (mesh, skipped) = Mesh::build(&tris, Degenerates::Refuse, &mut nodes, &mut prepared, &mut order, &mut scratch)?;
/// assert_eq!((mesh.len(), skipped), (2, 0));
/// let hit = mesh.cast(&Sweep::new(v(1.0, 3.0, 1.0), v(1.0, -1.0, 1.0), 0.5)?).unwrap();
/// assert_eq!((hit.alpha, hit.normal, hit.contact), (0.625, v(0.0, 1.0, 0.0), Contact::Face));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mesh<'a, S: Scalar> {
    nodes: &'a [Node],
    triangles: &'a [StandardTriangle<S>],
    order: &'a [u32],
    grid: Grid,
}

/// What [`Mesh::build`] does with a degenerate triangle (coincident or collinear vertices).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Degenerates {
    /// Fail with [`MeshError::Triangle`] naming it.
    Refuse,
    /// Leave it out (zero-area fillers are common in exported levels) and count it.
    Skip,
}

/// How [`Mesh::build`] builds: what it does with degenerate triangles, and how many triangles a
/// leaf of its tree holds. A [`Degenerates`] converts to the options with the default
/// [`LeafSize::Two`], so `Mesh::build(&triangles, Degenerates::Skip, ...)` takes it as it is.
///
/// ```
/// use ballcast::{bvh::LeafSize, Degenerates, MeshOptions};
/// // The smallest tree, for a compact mesh that will borrow it.
/// let options = Degenerates::Refuse.with_leaf_size(LeafSize::Four);
/// assert_eq!(options, MeshOptions { degenerates: Degenerates::Refuse, leaf_size: LeafSize::Four });
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MeshOptions {
    /// What to do with a degenerate triangle.
    pub degenerates: Degenerates,
    /// The most triangles in a leaf of the tree.
    pub leaf_size: LeafSize,
}

impl Degenerates {
    /// These options with leaves of `leaf_size`.
    pub const fn with_leaf_size(self, leaf_size: LeafSize) -> MeshOptions {
        MeshOptions {
            degenerates: self,
            leaf_size,
        }
    }
}

impl From<Degenerates> for MeshOptions {
    fn from(degenerates: Degenerates) -> Self {
        degenerates.with_leaf_size(LeafSize::Two)
    }
}

impl<'a, S: Scalar> Mesh<'a, S> {
    /// A mesh from parts made by [`Mesh::build`] (or baked from them), in a `const` context, so
    /// a mesh can be a `static`. Nothing is checked here: check baked parts with
    /// [`verify`](Self::verify) in a test. Parts from elsewhere can give wrong answers, never
    /// undefined behaviour, and no panic in a release build (with overflow checks on, as in a
    /// debug build, out-of-range parts can trip them).
    pub const fn from_parts(
        nodes: &'a [Node],
        triangles: &'a [StandardTriangle<S>],
        order: &'a [u32],
        grid: Grid,
    ) -> Self {
        Self {
            nodes,
            triangles,
            order,
            grid,
        }
    }

    /// A placeholder to fill a buffer of prepared triangles with before [`build`](Self::build):
    /// every byte zero (no active feature), so a `static` buffer of them is zero-initialised
    /// (`.bss` on a microcontroller: RAM only, no copy in flash).
    pub const fn filler() -> StandardTriangle<S> {
        let z = Vec3::ZERO;
        let u = Vec3::new(S::UNIT_ZERO, S::UNIT_ZERO, S::UNIT_ZERO);
        let edge = crate::Edge {
            dir: [S::UNIT_ZERO; 2],
            len: S::ZERO,
        };
        StandardTriangle::from_parts(Parts {
            origin: z,
            axes: [u; 3],
            shape: [S::ZERO; 3],
            normal: z,
            edges: [edge; 3],
            features: Features::FACE_ONLY.bits(),
            two_sided: false,
            world_heights: false,
        })
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Whether the mesh holds no triangle.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The tree's nodes.
    pub fn nodes(&self) -> &'a [Node] {
        self.nodes
    }

    /// The prepared triangles, in leaf order.
    pub fn triangles(&self) -> &'a [StandardTriangle<S>] {
        self.triangles
    }

    /// The input index of each prepared triangle.
    pub fn order(&self) -> &'a [u32] {
        self.order
    }

    /// The grid of the tree's boxes and the root's box.
    pub fn grid(&self) -> Grid {
        self.grid
    }

    /// The prepared triangle of input triangle `index`, if kept (a search, `O(N)`).
    pub fn triangle(&self, index: usize) -> Option<&'a StandardTriangle<S>> {
        let s = self.order.iter().position(|&i| i as usize == index)?;
        self.triangles.get(s)
    }

    /// Checks baked parts against the mesh `Mesh::build` makes of `sources` into the given
    /// buffers (sized as for `build`): the way to test a `static` mesh. `options` must be
    /// those the parts were built with, the leaf size too (parts built with leaves of four
    /// differ from the default's: [`MeshError::Mismatch`]).
    ///
    /// Errors: those of [`build`](Self::build), or [`MeshError::Mismatch`] naming the first
    /// part that differs.
    pub fn verify(
        &self,
        sources: &[Triangle<S>],
        options: impl Into<MeshOptions>,
        nodes: &mut [Node],
        triangles: &mut [StandardTriangle<S>],
        order: &mut [u32],
        scratch: &mut [u64],
    ) -> Result<(), MeshError> {
        self.verify_sided(
            sources,
            |_| false,
            options,
            nodes,
            triangles,
            order,
            scratch,
        )
    }

    /// [`verify`](Self::verify) against the mesh [`build_sided`](Self::build_sided) makes.
    #[allow(clippy::too_many_arguments)]
    pub fn verify_sided(
        &self,
        sources: &[Triangle<S>],
        two_sided: impl Fn(usize) -> bool,
        options: impl Into<MeshOptions>,
        nodes: &mut [Node],
        triangles: &mut [StandardTriangle<S>],
        order: &mut [u32],
        scratch: &mut [u64],
    ) -> Result<(), MeshError> {
        let (built, _) = Mesh::build_sided(
            sources, two_sided, options, nodes, triangles, order, scratch,
        )?;
        match error::first_difference(&built, self) {
            None => Ok(()),
            Some(part) => Err(MeshError::Mismatch { part }),
        }
    }

    /// The earliest contact along the sweep: the answer of the slice [`Geometry`] over the same
    /// prepared triangles in input order, bit for bit, found in `O(log N)` node visits for a
    /// short sweep.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        earliest_of(sweep, |acc, scan| self.offer(sweep, acc, scan))
    }

    /// Offers the contacts of the triangles the tree reaches (all of them with `scan`); false
    /// where the tree proved malformed (never from `build`).
    fn offer(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        if scan {
            for (t, &i) in self.triangles.iter().zip(self.order) {
                if let Some(hit) = t.cast(sweep) {
                    acc.offer(i as usize, hit);
                }
            }
            return true;
        }
        let leaf = |acc: &mut Earliest<S>, slots: core::ops::Range<usize>, exit: f32| {
            // A contact with a triangle of the leaf comes no later than where the segment
            // leaves the leaf's grown box (`0 <= exit`, about 1 at most): a reach for
            // `cast_within`, the next multiple of 2^-14 above it, exact in every scalar.
            let exit = exit
                .is_finite()
                .then(|| S::div_pow2(S::from_int((exit * 16384.0) as i32 + 1), 14));
            for s in slots {
                let reach = match (exit, acc.reach()) {
                    (Some(e), r) if e < r => e,
                    (_, r) => r,
                };
                if let (Some(t), Some(&i)) = (self.triangles.get(s), self.order.get(s))
                    && let Some(hit) = t.cast_within(sweep, reach)
                {
                    acc.offer(i as usize, hit);
                }
            }
        };
        bvh::leaves_along(self.nodes, &self.grid, sweep, acc, leaf)
    }
}

impl<S: Scalar> CompoundPart<S> for Mesh<'_, S> {
    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        self.offer(sweep, acc, scan)
    }

    /// One more than the largest input index kept (the build may have skipped the last).
    fn index_bound(&self) -> usize {
        self.order
            .iter()
            .fold(0, |m, &i| m.max((i as usize).saturating_add(1)))
    }
}

impl<S: Scalar> Geometry<S> for Mesh<'_, S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Mesh::cast(self, sweep)
    }

    /// The triangles of the leaves whose boxes meet the box (the tree's box query).
    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        let [lo, hi] = self.grid.visit_box(min, max);
        let query = bvh::query_cells(&self.grid, lo, hi);
        // A first walk that only checks the tree, so malformed parts (never from `build`) are
        // scanned instead without a triangle given twice.
        if !bvh::overlapping(self.nodes, &self.grid, query, |_| {}) {
            return crate::penetration::each(self.triangles, self.order, f);
        }
        bvh::overlapping(self.nodes, &self.grid, query, |slots| {
            for s in slots {
                if let (Some(t), Some(&i)) = (self.triangles.get(s), self.order.get(s)) {
                    f(i as usize, t);
                }
            }
        });
    }
}
