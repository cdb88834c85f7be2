//! The compact bake: a level as a [`CompactMesh`], for flash-limited parts. Its vertices are
//! shared (corners equal bit for bit in the scalar welded, [`ballcast::import::weld`]); each
//! triangle keeps three vertex indices, its index in the level and a byte of active edges and
//! sidedness, under the tree of the prepared mesh with leaves of four. The answers are the
//! prepared mesh's, bit for bit ([`CompactMesh::compact`] prepares every triangle again and
//! checks it); the price is a preparation for each triangle a query reaches.

use super::bake::{extent, mesh_error, skipped, triangles, with_mesh};
use super::source::{self, point};
use super::stats::skipped_origins;
use super::{Baked, Emit, Form, Level, LevelError, Problem, Stats};
use ballcast::bvh::LeafSize;
use ballcast::import::{Welded, weld};
use ballcast::{
    CompactError, CompactMesh, Error, Mesh, MeshError, MeshIndex, Scalar, Triangle, Vec3,
};
use std::fmt::Write;

/// Bakes `level` for scalar `S` as a [`CompactMesh`]: `u16` indices where the level's vertices
/// and triangles number at most 65 536, `u32` beyond. The source defines `NODES`, `VERTICES`,
/// `TRIANGLES`, `ORDER`, `BYTES` and `MESH: CompactMesh<'static, S, u16>` (or `u32`); check
/// the statics in a test against [`CompactMesh::compact`] of the run-time build with leaves of
/// four (`CompactMesh` compares as `==`).
///
/// Errors: those of [`bake`](crate::bake), and [`Problem::Compact`] (not expected: the
/// vertices are the mesh's own).
pub fn bake_compact<S: Scalar + Emit>(level: &Level) -> Result<Baked, LevelError> {
    let sources = triangles::<S>(level)?;
    let skipped = skipped(&sources);
    let (vertices, indices) = shared(&sources, &skipped).map_err(|e| mesh_error(level, e))?;
    let small = vertices.len().max(sources.len()) <= u16::MAX as usize + 1;
    let welded = (vertices.as_slice(), indices.as_slice());
    with_mesh(level, &sources, LeafSize::Four, |mesh| {
        if small {
            write::<S, u16>(level, mesh, welded, skipped, "u16")
        } else {
            write::<S, u32>(level, mesh, welded, skipped, "u32")
        }
    })?
    .map_err(|e| {
        let origin = match e {
            CompactError::Mismatch { index }
            | CompactError::MissingTriangle { index, .. }
            | CompactError::MissingVertex { index, .. } => level.origin(index),
            _ => None,
        };
        LevelError::at(&level.path, Problem::Compact(e), origin)
    })
}

/// The vertices of the triangles kept (those not `skipped`), shared by [`weld`], in order of
/// first use, and each triangle's indices (`[0; 3]` for a skipped one, which no query reads).
fn shared<S: Scalar>(sources: &[Triangle<S>], skipped: &[usize]) -> Result<Welded<S>, MeshError> {
    let (all, mut indices) = weld(sources).map_err(|e| match e {
        Error::Full { .. } => MeshError::TooMany,
        error => MeshError::Triangle {
            index: error.triangle().unwrap_or(0),
            error,
        },
    })?;
    for &k in skipped {
        indices[k] = [u32::MAX; 3];
    }
    let mut number = vec![u32::MAX; all.len()];
    let mut vertices = Vec::new();
    for corner in indices.iter_mut().flatten().filter(|c| **c != u32::MAX) {
        let n = &mut number[*corner as usize];
        if *n == u32::MAX {
            *n = vertices.len() as u32;
            vertices.push(all[*corner as usize]);
        }
        *corner = *n;
    }
    for &k in skipped {
        indices[k] = [0; 3];
    }
    Ok((vertices, indices))
}

/// The compact form of `mesh` with indices `I` (named `index`), as source.
fn write<S: Scalar + Emit, I: MeshIndex>(
    level: &Level,
    mesh: &Mesh<S>,
    (vertices, indices): (&[Vec3<S>], &[[u32; 3]]),
    skipped: Vec<usize>,
    index: &'static str,
) -> Result<Baked, CompactError> {
    let k = mesh.len();
    let (mut t, mut o, mut b) = (
        vec![[I::default(); 3]; k],
        vec![I::default(); k],
        vec![0; k],
    );
    let compact = CompactMesh::compact(mesh, vertices, indices, &mut t, &mut o, &mut b)?;
    let (nodes, grid, vertices, triangles, order, bytes, class) = compact.parts();
    let stats = Stats {
        scalar: S::NAME,
        form: Form::Compact {
            nodes: nodes.len(),
            vertices: vertices.len(),
            index,
        },
        triangles: level.triangles.len(),
        skipped_origins: skipped_origins(level, &skipped),
        skipped,
        two_sided: mesh.triangles().iter().filter(|t| t.is_two_sided()).count(),
        bytes: size_of_val(nodes)
            + size_of_val(vertices)
            + size_of_val(triangles)
            + size_of_val(order)
            + size_of_val(bytes),
        extent: extent(level),
    };
    let s = S::NAME;
    let mut out = source::header::<S>(&level.path, &stats, "CompactMesh, Grid, Node, Vec3", false);
    source::nodes(&mut out, nodes);
    let _ = writeln!(
        out,
        "/// The shared vertices.\npub static VERTICES: [Vec3<{s}>; {}] = [",
        vertices.len()
    );
    for &p in vertices {
        let _ = writeln!(out, "    v({}),", point(p));
    }
    let _ = writeln!(out, "];");
    let each = "Per triangle, in the tree's leaf order:";
    let corners = format!("[{index}; 3]");
    source::array(
        &mut out,
        &format!("{each} its vertices."),
        "TRIANGLES",
        &corners,
        triangles,
        8,
    );
    source::array(
        &mut out,
        &format!("{each} its index in the level."),
        "ORDER",
        index,
        order,
        16,
    );
    let doc = format!("{each} its active edges and vertices, and whether it is two-sided.");
    source::array(&mut out, &doc, "BYTES", "u8", bytes, 16);
    let _ = writeln!(
        out,
        "/// The mesh, in flash.\npub static MESH: CompactMesh<'static, {s}, {index}> = CompactMesh::from_parts(&NODES, Grid {{ exponent: {}, lo: {:?}, hi: {:?} }}, &VERTICES, &TRIANGLES, &ORDER, &BYTES, {class});",
        grid.exponent, grid.lo, grid.hi
    );
    Ok(Baked { source: out, stats })
}
