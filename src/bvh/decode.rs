//! Reading a node: its children's boxes from the node's minimum and per-axis shifts, and a
//! leaf reference's triangle slots (layout in the [module docs](super)).

use super::{Cells, LEAF_FLAG, Node, PAYLOAD};

/// Decodes child `k` of `node`, whose own box has minimum `lo`.
#[inline]
pub(super) fn child_cells(node: &Node, k: usize, lo: [i32; 3]) -> Cells {
    let at = |b: usize| {
        let (a, v) = (b % 3, node.boxes[b][k & 3]);
        lo[a].wrapping_add((v as i32).wrapping_shl(node.shift[a].min(31) as u32))
    };
    ([at(0), at(1), at(2)], [at(3), at(4), at(5)])
}

/// A node's steps per axis as shifts, at most 31.
#[inline]
pub(super) fn shifts(node: &Node) -> [u32; 3] {
    node.shift.map(|s| s.min(31) as u32)
}

/// The minimum of child `k`'s box (`child_cells`' first half), given the node's [`shifts`].
#[inline]
pub(super) fn child_lo(node: &Node, shift: [u32; 3], k: usize, lo: [i32; 3]) -> [i32; 3] {
    core::array::from_fn(|a| lo[a].wrapping_add((node.boxes[a][k & 3] as i32) << shift[a]))
}

/// The triangle slots of a leaf reference: `first .. first + count`.
#[inline]
pub(crate) fn leaf_slots(child: u32) -> Option<core::ops::Range<usize>> {
    (child & LEAF_FLAG != 0).then(|| {
        let first = ((child & PAYLOAD) >> 2) as usize;
        first..first + (child & 3) as usize + 1
    })
}
