//! Bytes per triangle of every form of the benchmark terrain in every scalar: the prepared
//! `Mesh`, the `CompactMesh` (u16 indices where vertices and triangles fit, else u32) and the
//! `Heightfield`, measured with `size_of_val` on the built parts.
//!
//! Run: `cargo run --release --example memory`

use ballcast::{CompactMesh, Mesh, MeshIndex, Scalar};
use fixed::types::{I16F16, I32F32};

mod inputs;
mod terrain;

/// Bytes of the prepared mesh, the compact mesh and the heightfield.
fn bytes<S: Scalar>(w: usize) -> [usize; 3] {
    let level = terrain::Level::<S>::new(w);
    let n = level.triangles.len();
    let mesh = level.mesh();
    let prepared =
        size_of_val(mesh.nodes()) + size_of_val(mesh.triangles()) + size_of_val(mesh.order());
    let compact = if level.vertices.len().max(n) <= u16::MAX as usize + 1 {
        compact::<S, u16>(&level, &mesh)
    } else {
        compact::<S, u32>(&level, &mesh)
    };
    let hf = level.heightfield();
    [
        prepared,
        compact,
        size_of_val(hf.heights()) + size_of_val(hf.cells()),
    ]
}

fn compact<S: Scalar, I: MeshIndex + Default>(
    level: &terrain::Level<S>,
    mesh: &Mesh<'_, S>,
) -> usize {
    let n = mesh.len();
    let (mut t, mut o, mut b) = (
        vec![[I::default(); 3]; n],
        vec![I::default(); n],
        vec![0u8; n],
    );
    let (v, i) = (&level.vertices, &level.indices);
    // The compact mesh borrows the tree with leaves of four, the smallest.
    let small = level.small_tree_mesh();
    let c = CompactMesh::compact(&small, v, i, &mut t, &mut o, &mut b).unwrap();
    let (nodes, _, vertices, triangles, order, bytes, _) = c.parts();
    size_of_val(nodes)
        + size_of_val(vertices)
        + size_of_val(triangles)
        + size_of_val(order)
        + size_of_val(bytes)
}

fn main() {
    println!("| triangles | scalar | prepared mesh | compact mesh | heightfield |");
    println!("|---|---|---|---|---|");
    for w in [16, 64, 224] {
        let n = (2 * w * w) as f64;
        let rows = [
            ("f32", bytes::<f32>(w)),
            ("f64", bytes::<f64>(w)),
            ("I16F16", bytes::<I16F16>(w)),
            ("I32F32", bytes::<I32F32>(w)),
        ];
        for (name, [p, c, h]) in rows {
            println!(
                "| {} | {name} | {:.1} | {:.1} | {:.2} |",
                2 * w * w,
                p as f64 / n,
                c as f64 / n,
                h as f64 / n
            );
        }
    }
}
