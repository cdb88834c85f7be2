//! The box walk: the leaves whose boxes meet an axis-aligned box, in integer cells. It serves
//! the queries that look at what lies around a point (penetration, winding), and short sweeps,
//! whose padded segment is hardly smaller than its box: there it replaces the slab test's
//! floating point by a few integer comparisons per child, which matters most on cores without
//! a floating-point unit.

use super::decode::{child_cells, leaf_slots};
use super::{CLASS_SHIFT, Cells, Grid, LEAF_FLAG, MAX_CLASS, Node, PAYLOAD, STACK};
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
    let walk = Walk {
        toward: [0; 3],
        seam: 0,
    };
    walk.run(nodes, grid, &mut (), |_| query, |_, slots| leaf(slots))
}

/// How a walk orders and grows the children it meets.
pub(crate) struct Walk {
    /// Per axis, the sign of the motion: children are visited by `toward · (lo + hi)` of their
    /// boxes, smallest first, so along a path the nearest come first (all zero: tree order).
    pub(crate) toward: [i32; 3],
    /// The seam margin in whole cells, rounded up: a child's box is grown by `seam << class`
    /// for the seam class of its subtree (see the [module docs](super)).
    pub(crate) seam: i64,
}

impl Walk {
    /// Calls `leaf` with the slots of every leaf whose box, grown by its seam margins, meets
    /// the box `query` gives for `acc` when the leaf's parent is visited; `query` may shrink as
    /// `leaf` changes `acc` (a sweep's reach), never grow. Returns false, having stopped, if
    /// the tree is malformed.
    pub(crate) fn run<A>(
        &self,
        nodes: &[Node],
        grid: &Grid,
        acc: &mut A,
        mut query: impl FnMut(&A) -> Cells,
        mut leaf: impl FnMut(&mut A, Range<usize>),
    ) -> bool {
        if nodes.is_empty() {
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
                leaf(acc, slots);
                continue;
            }
            let Some(node) = nodes.get((child & PAYLOAD) as usize) else {
                return false;
            };
            let (qlo, qhi) = query(acc);
            // Children that meet, by key, largest first: the stack pops the smallest first.
            let mut met = [(0i64, 0usize); 4];
            let mut n = 0;
            for k in 0..(node.count as usize).min(4) {
                let (clo, chi) = child_cells(node, k, lo);
                let class = ((node.children[k] & !LEAF_FLAG) >> CLASS_SHIFT).min(MAX_CLASS);
                // At most 2^31 << 31: no overflow, and more than any box's reach.
                let g = self.seam.clamp(0, 1 << 31) << class;
                let meets = (0..3).all(|a| {
                    clo[a] as i64 - g <= qhi[a] as i64 && qlo[a] as i64 <= chi[a] as i64 + g
                });
                // `n < 4` always holds (one entry per child at most); said here so that no
                // bounds check, and no panic path, is left in the insertion below.
                if meets && n < met.len() {
                    // The sign applied by a choice, not a product: a 64-bit multiply is a
                    // library call on a Cortex-M0.
                    let key = (0..3)
                        .map(|a| {
                            let centre = clo[a] as i64 + chi[a] as i64;
                            match self.toward[a].signum() {
                                1 => centre,
                                -1 => -centre,
                                _ => 0,
                            }
                        })
                        .sum::<i64>();
                    let mut at = n;
                    while at > 0 && met[at - 1].0 < key {
                        met[at] = met[at - 1];
                        at -= 1;
                    }
                    met[at] = (key, k);
                    n += 1;
                }
            }
            for &(_, k) in met.iter().take(n) {
                let cells = child_cells(node, k, lo);
                if stack.push((node.children[k & 3], cells.0)).is_err() {
                    return false;
                }
            }
        }
        true
    }
}
