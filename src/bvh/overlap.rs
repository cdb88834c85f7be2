//! The box query: the leaves whose boxes meet an axis-aligned box, for the queries that look at
//! what lies around a point rather than along a path (penetration, winding).

use super::traverse::{child_cells, leaf_slots};
use super::{Cells, Grid, Node, PAYLOAD, STACK};
use core::ops::Range;

/// The cells that cover the box from `min` to `max` (world units, `min <= max`) on `grid`:
/// rounded outward, grown by a cell, clamped to `±2^30` (a box far outside the mesh stays outside).
pub(crate) fn query_cells(grid: &Grid, min: [f64; 3], max: [f64; 3]) -> Cells {
    let s = Grid::scale(grid.exponent);
    let limit = (1u64 << 30) as f64;
    let clamp = |v: f64| (v * s).clamp(-limit, limit);
    Grid::cells(0, min.map(clamp), max.map(clamp))
}

/// Calls `leaf` with the slots of every leaf whose box meets `query` (each once). Returns false,
/// having stopped, if the tree is malformed (a stack overflow or a cycle: only possible for parts
/// not made by the build).
pub(crate) fn overlapping(
    nodes: &[Node],
    grid: &Grid,
    query: Cells,
    mut leaf: impl FnMut(Range<usize>),
) -> bool {
    let meets = |(lo, hi): Cells| (0..3).all(|a| lo[a] <= query.1[a] && query.0[a] <= hi[a]);
    if nodes.is_empty() || !meets((grid.lo, grid.hi)) {
        return true;
    }
    let mut stack: heapless::Vec<(u32, [i32; 3]), STACK> = heapless::Vec::new();
    let _ = stack.push((0, grid.lo));
    let mut budget = 5 * nodes.len() + 5;
    while let Some((child, lo)) = stack.pop() {
        budget = match budget.checked_sub(1) {
            Some(b) => b,
            None => return false,
        };
        if let Some(slots) = leaf_slots(child) {
            leaf(slots);
            continue;
        }
        let Some(node) = nodes.get((child & PAYLOAD) as usize) else {
            return false;
        };
        for k in 0..(node.count as usize).min(4) {
            let cells = child_cells(node, k, lo);
            if meets(cells) && stack.push((node.children[k], cells.0)).is_err() {
                return false;
            }
        }
    }
    true
}
