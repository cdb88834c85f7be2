//! Why a mesh was refused: [`MeshError`], with the [`Buffer`] too small or the [`MeshPart`]
//! that differs from the build.

use super::Mesh;
use crate::{Error, Scalar};
use core::fmt;

/// Which buffer given to [`Mesh::build`] was too small.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Buffer {
    /// The nodes: [`nodes_for_leaves`](crate::bvh::nodes_for_leaves) of the triangles kept.
    Nodes,
    /// The prepared triangles: one per input triangle.
    Triangles,
    /// The order: one per input triangle.
    Order,
    /// The scratch words: six per input triangle.
    Scratch,
}

impl fmt::Display for Buffer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Buffer::Nodes => "nodes (bvh::nodes_for_leaves of the triangles kept)",
            Buffer::Triangles => "triangles (one per input triangle)",
            Buffer::Order => "order (one per input triangle)",
            Buffer::Scratch => "scratch (six words per input triangle)",
        })
    }
}

/// Why [`Mesh::build`] or [`Mesh::verify`] refused.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MeshError {
    /// Input triangle `index` was refused by
    /// [`StandardTriangle::new`](crate::StandardTriangle::new) for `error` (a degenerate one
    /// only under [`Degenerates::Refuse`](super::Degenerates::Refuse)).
    Triangle {
        /// Its index in the input.
        index: usize,
        /// Why.
        error: Error,
    },
    /// A buffer holds fewer than `needed` elements.
    Capacity {
        /// Which one.
        buffer: Buffer,
        /// How many it must hold.
        needed: usize,
        /// How many it holds.
        given: usize,
    },
    /// More than 2^24 triangles.
    TooMany,
    /// [`Mesh::verify`]: the parts are not what the build makes of the given triangles; `part`
    /// is the first that differs.
    Mismatch {
        /// Which.
        part: MeshPart,
    },
}

/// The first part of a mesh found to differ from the build of its triangles
/// ([`MeshError::Mismatch`]), in the order [`Mesh::verify`] compares them.
#[non_exhaustive]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MeshPart {
    /// The number of triangles kept.
    Len,
    /// The grid of the tree's boxes.
    Grid,
    /// Node `index` of the tree, or the number of nodes (`index` the shorter count).
    Node {
        /// The node's index.
        index: usize,
    },
    /// Slot `slot` of the leaf order: the input triangle it holds.
    Order {
        /// The slot.
        slot: usize,
    },
    /// The prepared triangle of input triangle `index`: its frame, active edges or sidedness.
    Triangle {
        /// Its index in the input.
        index: usize,
    },
}

impl fmt::Display for MeshError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshError::Triangle { error, .. } => write!(f, "{error}"),
            MeshError::Capacity {
                buffer,
                needed,
                given,
            } => write!(
                f,
                "the buffer of {buffer} holds {given}, too few: {needed} needed"
            ),
            MeshError::TooMany => f.write_str("more than 2^24 triangles"),
            MeshError::Mismatch { part } => {
                f.write_str("mesh parts differ from the build of its triangles: ")?;
                match part {
                    MeshPart::Len => f.write_str("another number of triangles"),
                    MeshPart::Grid => f.write_str("the grid"),
                    MeshPart::Node { index } => write!(f, "node {index}"),
                    MeshPart::Order { slot } => write!(f, "the order, at slot {slot}"),
                    MeshPart::Triangle { index } => write!(f, "triangle {index}"),
                }
            }
        }
    }
}

impl core::error::Error for MeshError {}

/// The first part in which `baked` differs from `built` (the build of its triangles), if any.
pub(super) fn first_difference<S: Scalar>(built: &Mesh<S>, baked: &Mesh<S>) -> Option<MeshPart> {
    let first = |a: usize, b: usize, same: &dyn Fn(usize) -> bool| {
        (0..a.min(b))
            .find(|&k| !same(k))
            .or((a != b).then_some(a.min(b)))
    };
    if built.triangles.len() != baked.triangles.len() {
        return Some(MeshPart::Len);
    }
    if built.grid != baked.grid {
        return Some(MeshPart::Grid);
    }
    let (a, b) = (built.nodes, baked.nodes);
    if let Some(index) = first(a.len(), b.len(), &|k| a[k] == b[k]) {
        return Some(MeshPart::Node { index });
    }
    let (a, b) = (built.order, baked.order);
    if let Some(slot) = first(a.len(), b.len(), &|k| a[k] == b[k]) {
        return Some(MeshPart::Order { slot });
    }
    let (a, b) = (built.triangles, baked.triangles);
    let same = |k: usize| a[k].to_parts().identical(&b[k].to_parts());
    let slot = first(a.len(), b.len(), &same)?;
    let index = built.order.get(slot).map_or(slot, |&i| i as usize);
    Some(MeshPart::Triangle { index })
}
