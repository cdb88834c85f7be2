//! [`Memory`]: the bytes of a level in each form and scalar.

use super::ScalarType;
use crate::bvh::{LeafSize, nodes_for_leaves};
use crate::{Node, StandardTriangle, Vec3};
use core::mem::size_of;
use fixed::types::{I16F16, I32F32};

/// Bytes a level takes in each form, for one scalar: what [`Memory::of`] counts.
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Memory {
    /// A [`Mesh`](crate::Mesh): prepared triangles, their input order and the tree's nodes
    /// (leaves of up to two triangles, the default).
    pub mesh: usize,
    /// A [`CompactMesh`](crate::CompactMesh): the nodes of a tree with leaves of up to four
    /// triangles, the shared vertices, and per
    /// triangle three vertex indices, its input index and a byte (`u16` indices where vertices
    /// and triangles number at most 65 536, else `u32`). A `CompactMeshBuf` (feature `alloc`)
    /// always takes `u32` indices: 8 bytes more per triangle than counted here for a level
    /// within 65 536.
    pub compact: usize,
    /// A [`Heightfield`](crate::Heightfield) of a grid with these vertices and triangles: two
    /// bytes per vertex, one per cell (two triangles). Meaningful only for a grid.
    pub heightfield: usize,
}

impl Memory {
    /// The bytes of a level of `triangles` triangles over `vertices` distinct vertices in each
    /// form, in `scalar`: the sizes the builds make, exactly (the build's scratch not counted);
    /// `usize::MAX` where that does not fit a `usize`.
    pub const fn of(scalar: ScalarType, triangles: usize, vertices: usize) -> Self {
        let (prepared, vertex) = match scalar {
            ScalarType::I16F16 => (
                size_of::<StandardTriangle<I16F16>>(),
                size_of::<Vec3<I16F16>>(),
            ),
            ScalarType::F32 => (size_of::<StandardTriangle<f32>>(), size_of::<Vec3<f32>>()),
            ScalarType::I32F32 => (
                size_of::<StandardTriangle<I32F32>>(),
                size_of::<Vec3<I32F32>>(),
            ),
            ScalarType::F64 => (size_of::<StandardTriangle<f64>>(), size_of::<Vec3<f64>>()),
        };
        let node = size_of::<Node>();
        let (tree, small_tree) = (
            nodes_for_leaves(triangles, LeafSize::Two).saturating_mul(node),
            nodes_for_leaves(triangles, LeafSize::Four).saturating_mul(node),
        );
        let index = if triangles <= 1 << 16 && vertices <= 1 << 16 {
            2
        } else {
            4
        };
        Self {
            mesh: tree.saturating_add(triangles.saturating_mul(prepared + 4)),
            compact: small_tree
                .saturating_add(vertices.saturating_mul(vertex))
                .saturating_add(triangles.saturating_mul(4 * index + 1)),
            heightfield: vertices.saturating_mul(2).saturating_add(triangles / 2),
        }
    }
}
