//! The shape of a mesh's tree where it decides how many triangles a query tests: a leaf cut out
//! of a grid's column (triangles whose centres tie on the split axis) is a stretch of the column,
//! not triangles from all along it.

mod common;
mod meshes;

use ballcast::bvh::LeafSize;
use ballcast::{Degenerates, Node, Triangle};
use common::Rng;
use meshes::{build, heightfield, tri};

/// The largest extent, in units along x and along z, of any leaf's box (as its parent stores
/// it) in the tree `nodes`, whose cells are `cell` units.
fn widest_leaf(nodes: &[Node], cell: f64) -> [f64; 2] {
    let mut widest = [0.0f64; 2];
    for node in nodes {
        for k in 0..node.count as usize {
            if node.children[k] & (1 << 31) == 0 {
                continue;
            }
            for (w, a) in widest.iter_mut().zip([0, 2]) {
                let steps = (node.boxes[3 + a][k] - node.boxes[a][k]) as f64;
                *w = w.max(steps * f64::from(1u32 << node.shift[a]) * cell);
            }
        }
    }
    widest
}

/// A terrain of 30 × 30 cells (1 800 triangles), its diagonals at random: splits by count fall
/// inside columns whose centres tie on the split axis. Ordered there by height (as the key's
/// next field once was), a column's leaves took triangles from anywhere along it: leaves of two
/// up to 2 × 4 units, queries near them testing triangles they could not reach. Ordered by the
/// next longest axis, z, a leaf of two is one cell and a leaf of four at most two.
#[test]
fn leaves_cut_from_a_grids_column_are_compact() {
    for (leaves, cells) in [(LeafSize::Two, 1.0), (LeafSize::Four, 2.0)] {
        let src: Vec<Triangle<f32>> = heightfield(&mut Rng(0x5eed_0005), 30, 1.0, 0.65)
            .iter()
            .map(|&t| tri(t))
            .collect();
        let mesh = build(&src, Degenerates::Refuse.with_leaf_size(leaves)).unwrap();
        let cell = 2f64.powi(mesh.grid.exponent);
        let [x, z] = widest_leaf(&mesh.nodes, cell);
        // Plus the grid cell a triangle's box grows by and the rounding of the node's steps.
        let most = cells + 0.1;
        assert!(
            x <= most && z <= most,
            "{leaves:?}: widest leaf {x} × {z} units"
        );
    }
}
