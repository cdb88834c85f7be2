//! `Mesh::build` into buffers longer than the mesh (a `static` sized for the largest level, a
//! reused `Vec`): the same parts, byte for byte, as into buffers of the exact size, whatever
//! the leftovers in them, refusing or skipping degenerate triangles, with either leaf size;
//! and `Mesh::verify` through such buffers finds no mismatch.
//! (The build that prepares straight into leaf order once found the active edges over the
//! whole of longer buffers, leftovers included, and gave up: every shared edge stayed active.)

mod common;
mod meshes;

use ballcast::bvh::{LeafSize, nodes_for};
use ballcast::{Degenerates, Mesh, Node, Scalar, StandardTriangle, Triangle};
use common::Rng;
use fixed::types::{I16F16, I32F32};
use meshes::{heightfield, tri};

/// The parts of `src` built into buffers `extra` entries longer than needed, each filled
/// beforehand with `junk` (a prepared triangle and an order entry from another mesh).
fn parts<S: Scalar>(
    src: &[Triangle<S>],
    options: ballcast::MeshOptions,
    extra: usize,
    junk: (StandardTriangle<S>, u32),
) -> String {
    let n = src.len() + extra;
    let mut nodes = vec![Node::default(); nodes_for(n)];
    let mut tris = vec![junk.0; n];
    let mut order = vec![junk.1; n];
    let mut scratch = vec![u64::MAX; 6 * n];
    let (mesh, skipped) = Mesh::build(
        src,
        options,
        &mut nodes,
        &mut tris,
        &mut order,
        &mut scratch,
    )
    .expect("the terrain builds");
    let prepared: Vec<_> = mesh.triangles().iter().map(|t| t.to_parts()).collect();
    format!(
        "{skipped} {:?} {:?} {:?} {prepared:?}",
        mesh.nodes(),
        mesh.order(),
        mesh.grid()
    )
}

fn oversized_buffers_give_the_same_parts<S: Scalar>() {
    let mut rng = Rng(0x5eed_0b0f);
    let src: Vec<Triangle<S>> = heightfield(&mut rng, 8, 1.0, 0.65)
        .iter()
        .map(|&t| tri(t))
        .collect();
    let junk_triangle = StandardTriangle::new(&src[5]).unwrap();
    // Some of the terrain's shared edges are flat or valleys: switched off in every build.
    let exact = Mesh::build(
        &src,
        Degenerates::Refuse,
        &mut vec![Node::default(); nodes_for(src.len())],
        &mut vec![Mesh::filler(); src.len()],
        &mut vec![0; src.len()],
        &mut vec![0; 6 * src.len()],
    )
    .map(|(m, _)| {
        m.triangles()
            .iter()
            .filter(|t| t.features().bits() != 63)
            .count()
    });
    assert!(exact.unwrap() > src.len() / 2);
    for leaves in [LeafSize::Two, LeafSize::Four] {
        for degenerates in [Degenerates::Refuse, Degenerates::Skip] {
            let options = degenerates.with_leaf_size(leaves);
            let want = parts(&src, options, 0, (Mesh::filler(), 0));
            for extra in [1, 3, 40] {
                for junk in [
                    (Mesh::filler(), 0),
                    (junk_triangle, 7),
                    (junk_triangle, u32::MAX),
                ] {
                    let got = parts(&src, options, extra, junk);
                    assert_eq!(got, want, "{leaves:?} {degenerates:?} {extra} more");
                }
            }
            // A mesh checked against the build into longer buffers: no mismatch.
            let n = src.len();
            let mut nodes = vec![Node::default(); nodes_for(n)];
            let (mut tris, mut order) = (vec![Mesh::filler(); n], vec![0; n]);
            let mut scratch = vec![0; 6 * n];
            let (mesh, _) = Mesh::build(
                &src,
                options,
                &mut nodes,
                &mut tris,
                &mut order,
                &mut scratch,
            )
            .unwrap();
            let m = n + 5;
            let checked = mesh.verify(
                &src,
                options,
                &mut vec![Node::default(); nodes_for(m)],
                &mut vec![junk_triangle; m],
                &mut vec![7; m],
                &mut vec![u64::MAX; 6 * m],
            );
            assert_eq!(checked, Ok(()), "{leaves:?} {degenerates:?}");
        }
    }
}

meshes::per_scalar!(oversized_buffers_give_the_same_parts);
