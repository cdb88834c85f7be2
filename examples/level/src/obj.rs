//! Wavefront OBJ through `tobj`: faces triangulated as fans (quads into two triangles),
//! negative indices counted back from the last vertex, materials ignored.

use super::{Problem, Tri};
use std::path::Path;

pub(crate) fn load(path: &Path) -> Result<Vec<Tri>, Problem> {
    // tobj reports a missing file as a generic open error: say which.
    std::fs::metadata(path).map_err(Problem::Io)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    // The material result is dropped: a level needs no .mtl file.
    let (models, _materials) =
        tobj::load_obj(path, &options).map_err(|e| Problem::Malformed(e.to_string()))?;
    let mut out = Vec::new();
    for m in &models {
        let (p, idx) = (&m.mesh.positions, &m.mesh.indices);
        let vertex = |i: u32| -> Result<[f64; 3], Problem> {
            let i = i as usize;
            p.get(3 * i..3 * i + 3)
                .map(|v| [v[0], v[1], v[2]])
                .ok_or_else(|| Problem::Malformed(format!("vertex index {} out of range", i + 1)))
        };
        for f in idx.chunks_exact(3) {
            out.push([vertex(f[0])?, vertex(f[1])?, vertex(f[2])?]);
        }
    }
    Ok(out)
}
