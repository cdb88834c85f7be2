//! glTF 2.0 (`.gltf` with its buffers in files beside it or in `data:` URIs) and GLB through
//! the `gltf` crate: every triangle primitive of every mesh in the default scene (or the first
//! scene when none is marked default), with the node hierarchy's transforms applied. Only
//! `POSITION` is read, as 32-bit floats: skins and morph targets are ignored (the bind pose),
//! quantized (`KHR_mesh_quantization`) or compressed (Draco, meshopt) positions and sparse
//! accessors are refused, by the `gltf` crate's check of required extensions or here.
//! Each triangle's origin is its node, mesh, primitive and place in the primitive.

use super::{Origins, Problem, Tri};
use base64::Engine;
use gltf::accessor::{DataType, Dimensions};
use gltf::mesh::Mode;
use gltf::{Accessor, Gltf, Node};
use std::path::Path;

/// Deeper node hierarchies are refused (they would exhaust the stack).
const MAX_DEPTH: usize = 256;

fn malformed(m: impl Into<String>) -> Problem {
    Problem::Malformed(m.into())
}

/// The triangles, whether each is two-sided, and where each came from.
type Loaded = (Vec<Tri>, Vec<bool>, Origins);

pub(crate) fn load(path: &Path) -> Result<Loaded, Problem> {
    let bytes = std::fs::read(path).map_err(Problem::Io)?;
    let unchecked =
        Gltf::from_slice_without_validation(&bytes).map_err(|e| malformed(e.to_string()))?;
    // `gltf`'s validation reads a primitive's POSITION accessor before checking that it
    // exists, and panics if it does not (gltf-json 1.4.1): every attribute is checked first.
    let root = unchecked.document.as_json();
    let accessors = root.accessors.len();
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let used = primitive.attributes.values().map(|a| a.value());
            if let Some(a) = used.into_iter().find(|&a| a >= accessors) {
                return Err(malformed(format!(
                    "mesh {m}, primitive {p}: accessor {a} does not exist ({accessors} accessors)"
                )));
            }
        }
    }
    let blob = unchecked.blob;
    let document = gltf::Document::from_json(unchecked.document.into_json())
        .map_err(|e| malformed(e.to_string()))?;
    let gltf = Gltf { document, blob };
    let buffers = buffers(&gltf, path)?;
    let scene = gltf
        .default_scene()
        .or_else(|| gltf.scenes().next())
        .ok_or_else(|| malformed("no scene"))?;
    let mut out = (Vec::new(), Vec::new(), Origins::default());
    let mut seen = vec![false; gltf.nodes().count()];
    for node in scene.nodes() {
        walk(&node, IDENTITY, &buffers, &mut out, &mut seen, 0)?;
    }
    Ok(out)
}

/// The data of every buffer: the GLB's binary chunk, a `data:` URI, or a file beside `path`.
fn buffers(gltf: &Gltf, path: &Path) -> Result<Vec<Vec<u8>>, Problem> {
    let mut out = Vec::new();
    for b in gltf.buffers() {
        let data = match b.source() {
            gltf::buffer::Source::Bin => gltf
                .blob
                .clone()
                .ok_or_else(|| malformed(format!("buffer {} has no binary chunk", b.index())))?,
            gltf::buffer::Source::Uri(uri) if uri.starts_with("data:") => {
                let (_, payload) = uri.split_once(";base64,").ok_or_else(|| {
                    malformed(format!("buffer {}: not a base64 data URI", b.index()))
                })?;
                base64::engine::general_purpose::STANDARD
                    .decode(payload)
                    .map_err(|e| malformed(format!("buffer {}: {e}", b.index())))?
            }
            gltf::buffer::Source::Uri(uri) => {
                // A URI is percent-encoded (`my%20level.bin`); some tools write the file name
                // as it is, so the name read literally is the fallback.
                let dir = path.parent().unwrap_or(Path::new("."));
                let decoded = dir.join(percent_decoded(uri));
                let literal = dir.join(uri);
                let file = if !decoded.exists() && literal.exists() {
                    literal
                } else {
                    decoded
                };
                std::fs::read(&file).map_err(|e| {
                    malformed(format!("buffer {} ({}): {e}", b.index(), file.display()))
                })?
            }
        };
        if data.len() < b.length() {
            return Err(malformed(format!(
                "buffer {} holds {} bytes, declares {}",
                b.index(),
                data.len(),
                b.length()
            )));
        }
        out.push(data);
    }
    Ok(out)
}

/// `uri` with its `%XX` escapes decoded (RFC 3986), or as it is where they do not make UTF-8.
fn percent_decoded(uri: &str) -> String {
    let (b, mut out, mut i) = (uri.as_bytes(), Vec::with_capacity(uri.len()), 0);
    let hex = |k: usize| b.get(k).and_then(|&c| char::from(c).to_digit(16));
    while i < b.len() {
        match (b[i], hex(i + 1), hex(i + 2)) {
            (b'%', Some(high), Some(low)) => {
                out.push((16 * high + low) as u8);
                i += 3;
            }
            (c, _, _) => {
                out.push(c);
                i += 1;
            }
        }
    }
    String::from_utf8(out).unwrap_or_else(|_| uri.to_string())
}

/// A column-major 4 × 4 matrix, as glTF stores them.
type Mat = [[f64; 4]; 4];
const IDENTITY: Mat = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

fn mul(a: &Mat, b: &Mat) -> Mat {
    let mut m = [[0.0; 4]; 4];
    for (c, col) in m.iter_mut().enumerate() {
        for (r, v) in col.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    m
}

fn apply(m: &Mat, p: [f32; 3]) -> [f64; 3] {
    let p = p.map(f64::from);
    [0, 1, 2].map(|r| m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r])
}

/// The determinant of the linear part: negative for a mirroring transform.
fn det3(m: &Mat) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2])
        - m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2])
        + m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2])
}

fn walk(
    node: &Node,
    parent: Mat,
    buffers: &[Vec<u8>],
    out: &mut Loaded,
    seen: &mut [bool],
    depth: usize,
) -> Result<(), Problem> {
    if depth > MAX_DEPTH {
        return Err(malformed("node hierarchy deeper than 256"));
    }
    // Nodes form trees (glTF 2.0, 3.5.3): a node reached twice is a cycle or a shared child.
    match seen.get_mut(node.index()) {
        Some(s) if !*s => *s = true,
        _ => {
            let m = format!(
                "node {} reached twice: the hierarchy is not a tree",
                node.index()
            );
            return Err(malformed(m));
        }
    }
    let local = node.transform().matrix().map(|c| c.map(f64::from));
    let world = mul(&parent, &local);
    if let Some(mesh) = node.mesh() {
        let mirrored = det3(&world) < 0.0;
        let node_at = (node.index(), out.2.name(node.name()));
        let mesh_at = (mesh.index(), out.2.name(mesh.name()));
        for prim in mesh.primitives() {
            let what = || {
                let (m, p, n) = (mesh.index(), prim.index(), node.index());
                format!("mesh {m} primitive {p} (node {n})")
            };
            if !matches!(
                prim.mode(),
                Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
            ) {
                continue; // points and lines are no surface
            }
            let positions = prim
                .get(&gltf::Semantic::Positions)
                .ok_or_else(|| malformed(format!("{}: no positions", what())))?;
            if positions.data_type() != DataType::F32 || positions.dimensions() != Dimensions::Vec3
            {
                return Err(malformed(format!("{}: positions are not 3 floats", what())));
            }
            check(&positions, buffers)?;
            let reader = prim.reader(|b| buffers.get(b.index()).map(Vec::as_slice));
            let mut points = Vec::with_capacity(positions.count());
            let read = reader
                .read_positions()
                .ok_or_else(|| malformed(format!("{}: unreadable positions", what())))?;
            for (v, p) in read.enumerate() {
                // Named here, where the file's own terms (node, mesh, primitive) are known.
                let (raw, world) = (p.iter().all(|c| c.is_finite()), apply(&world, p));
                if !raw || world.iter().any(|c| !c.is_finite()) {
                    let by = if raw {
                        " under the node's transform"
                    } else {
                        ""
                    };
                    return Err(malformed(format!(
                        "{}: vertex {v} (position accessor {}) has a NaN or infinite \
                         coordinate{by}",
                        what(),
                        positions.index()
                    )));
                }
                points.push(world);
            }
            let indices: Vec<u32> = match prim.indices() {
                Some(acc) => {
                    if acc.dimensions() != Dimensions::Scalar
                        || !matches!(
                            acc.data_type(),
                            DataType::U8 | DataType::U16 | DataType::U32
                        )
                    {
                        return Err(malformed(format!(
                            "{}: indices are not unsigned integers",
                            what()
                        )));
                    }
                    check(&acc, buffers)?;
                    reader
                        .read_indices()
                        .ok_or_else(|| malformed(format!("{}: unreadable indices", what())))?
                        .into_u32()
                        .collect()
                }
                None => (0..points.len() as u32).collect(),
            };
            let corner = |i: u32| {
                points.get(i as usize).copied().ok_or_else(|| {
                    malformed(format!(
                        "{}: index {i} beyond {} vertices",
                        what(),
                        points.len()
                    ))
                })
            };
            // A count that leaves part of a triangle is a broken export, not one to cut short.
            let n = indices.len();
            let listed = if prim.indices().is_some() {
                "indices"
            } else {
                "vertices"
            };
            let count = match prim.mode() {
                Mode::Triangles if n.is_multiple_of(3) => n / 3,
                Mode::Triangles => {
                    return Err(malformed(format!(
                        "{}: {n} {listed} for separate triangles, not a multiple of 3",
                        what()
                    )));
                }
                _ if n < 3 => {
                    return Err(malformed(format!(
                        "{}: {n} {listed} for a triangle strip or fan, fewer than 3",
                        what()
                    )));
                }
                _ => n - 2,
            };
            for t in 0..count {
                // glTF 2.0 specification, 3.7.2.1 (primitive topologies).
                let [a, b, c] = match prim.mode() {
                    Mode::Triangles => [3 * t, 3 * t + 1, 3 * t + 2],
                    Mode::TriangleStrip => [t, t + 1 + t % 2, t + 2 - t % 2],
                    _ => [t + 1, t + 2, 0],
                };
                let tri = [
                    corner(indices[a])?,
                    corner(indices[b])?,
                    corner(indices[c])?,
                ];
                out.0.push(if mirrored {
                    [tri[0], tri[2], tri[1]]
                } else {
                    tri
                });
                // A material's `doubleSided` (glTF 2.0, 3.9.6): seen from both sides.
                out.1.push(prim.material().double_sided());
                out.2.push_gltf(node_at, mesh_at, prim.index(), t);
            }
        }
    }
    for child in node.children() {
        walk(&child, world, buffers, out, seen, depth + 1)?;
    }
    Ok(())
}

/// Refuses an accessor whose elements do not lie inside its view and buffer (the reader would
/// panic on them), or a sparse one.
fn check(acc: &Accessor, buffers: &[Vec<u8>]) -> Result<(), Problem> {
    let bad = || malformed(format!("accessor {} lies outside its buffer", acc.index()));
    if acc.sparse().is_some() {
        return Err(malformed(format!(
            "accessor {} is sparse (not supported)",
            acc.index()
        )));
    }
    let view = acc
        .view()
        .ok_or_else(|| malformed(format!("accessor {} has no buffer view", acc.index())))?;
    let data = buffers.get(view.buffer().index()).ok_or_else(bad)?;
    let stride = view.stride().unwrap_or(acc.size());
    let end = match acc.count() {
        0 => Some(acc.offset()),
        n => stride
            .checked_mul(n - 1)
            .and_then(|s| s.checked_add(acc.offset()))
            .and_then(|s| s.checked_add(acc.size())),
    };
    let view_end = view.offset().checked_add(view.length());
    match (end, view_end) {
        (Some(e), Some(v)) if e <= view.length() && v <= data.len() => Ok(()),
        _ => Err(bad()),
    }
}
