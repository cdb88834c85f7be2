//! Wavefront OBJ through `tobj`: faces of four or more corners split into triangles as
//! `polygon` says (a fan from the first corner where that covers the polygon, as for every
//! convex one, ear clipping for a concave one, a polygon crossing itself refused at its line),
//! negative indices counted back from the last vertex, polylines (`l`) and points (`p`)
//! ignored, materials ignored (their `.mtl` files are not read), a leading UTF-8 byte-order
//! mark skipped. Before `tobj` reads it, the file is scanned for the faults a level must not
//! pass over, so that the error names the line: a position that is not three numbers (or has a
//! NaN or infinite one: `nan` and `inf` parse as numbers, or a w of zero, NaN or infinity, or
//! one that divides a coordinate past any float), a face
//! with fewer than three corners (which `tobj` would drop without a word), a corner whose
//! vertex, texture or normal index is not a nonzero integer or names one not defined before it,
//! a `#` comment after a position or face or a `\` continuation (neither is read), text
//! without a single position (not an OBJ file).
//!
//! Each triangle's origin is its face's line, which triangle of the face's polygon it is, and
//! the names of the last `o` and `g` lines before it.

use super::{Origins, Problem, Tri, polygon};
use std::path::Path;

/// A face as the scan finds it: its line, and the numbers of its object's and group's names
/// in the origins.
type FaceAt = (usize, [u32; 2]);

pub(crate) fn load(path: &Path) -> Result<(Vec<Tri>, Origins), Problem> {
    let bytes = std::fs::read(path).map_err(Problem::Io)?;
    // OBJ is text: a binary file (or another encoding) is named as such, at its line.
    if let Err(e) = std::str::from_utf8(&bytes) {
        let at = e.valid_up_to();
        let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
        return Err(Problem::Malformed(format!(
            "line {line}: not text (byte {at} is not UTF-8): is this an OBJ file?"
        )));
    }
    // A byte-order mark (written by some Windows tools) would otherwise be read as part of the
    // first keyword, leaving the first position undefined and every index after it shifted.
    let text = String::from_utf8_lossy(&bytes);
    let text = faces_only(text.strip_prefix('\u{feff}').unwrap_or(&text));
    let mut origins = Origins::default();
    let face_lines = scan(&text, &mut origins).map_err(Problem::Malformed)?;
    // Polygons are split here (`polygon`), where a face's corners and line are known.
    let options = tobj::LoadOptions {
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
        ..Default::default()
    };
    // Every material library "fails to open": a level needs none, and `tobj` panics on some
    // malformed ones (tobj 4.0.5, a colour of two numbers).
    let no_materials = |_: &Path| Err(tobj::LoadError::OpenFileFailed);
    let (models, _materials) = tobj::load_obj_buf(&mut text.as_bytes(), &options, no_materials)
        .map_err(|e| Problem::Malformed(e.to_string()))?;
    let mut out = Vec::new();
    let mut lines = face_lines.iter();
    for m in &models {
        let (p, idx, arities) = (&m.mesh.positions, &m.mesh.indices, &m.mesh.face_arities);
        let vertex = |i: u32| -> Result<[f64; 3], Problem> {
            let i = i as usize;
            p.get(3 * i..3 * i + 3)
                .map(|v| [v[0], v[1], v[2]])
                .ok_or_else(|| Problem::Malformed(format!("vertex index {} out of range", i + 1)))
        };
        // No arities: every face a triangle.
        let faces = if arities.is_empty() {
            idx.len() / 3
        } else {
            arities.len()
        };
        let mut start = 0;
        for f in 0..faces {
            let k = arities.get(f).map_or(3, |&k| k as usize);
            let (Some(&(at, names)), Some(corners)) = (lines.next(), idx.get(start..start + k))
            else {
                return Err(Problem::Malformed(
                    "faces out of step with the parser".into(),
                ));
            };
            start += k;
            let points = corners
                .iter()
                .map(|&i| vertex(i))
                .collect::<Result<Vec<_>, _>>()?;
            let triangles = polygon::triangulate(&points).map_err(|_| {
                Problem::Malformed(format!(
                    "line {at}: the polygon of {k} corners crosses or folds over itself, so no \
                     triangles make it: fix it, or triangulate it on export"
                ))
            })?;
            out.extend(triangles.iter().map(|t| t.map(|i| points[i])));
            for piece in 1..=triangles.len() {
                origins.push_obj(at, (piece, triangles.len()), names);
            }
        }
    }
    if lines.next().is_some() {
        return Err(Problem::Malformed(
            "faces out of step with the parser".into(),
        ));
    }
    Ok((out, origins))
}

/// The text with every `l` (polyline) line left blank, so that line numbers hold: `tobj` reads
/// a polyline of three or more vertices as a face (its `ignore_lines` drops only those of two),
/// and a level's collision is its faces alone.
fn faces_only(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.lines() {
        if line.split_whitespace().next() != Some("l") {
            out.push_str(line);
        }
        out.push('\n');
    }
    out
}

/// Whether a 1-based OBJ index (negative: counted back from the last) names one of `count`.
fn names_one(i: i64, count: i64) -> bool {
    i != 0 && i.unsigned_abs() <= count.unsigned_abs()
}

/// The line of every face (1-based, in file order) with its object's and group's names
/// (stored in `origins`), or the first fault of the kinds in the module docs, as "line N:
/// what".
fn scan(text: &str, origins: &mut Origins) -> Result<Vec<FaceAt>, String> {
    let mut faces = Vec::new();
    // The names of the last `o` and `g` lines, as numbers in `origins` (0 for none).
    let mut names = [0; 2];
    // Positions, texture coordinates and normals defined so far.
    let mut defined = [0i64; 3];
    for (n, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        let at = n + 1;
        // Neither is read by `tobj`: it would fail without a line, or take `#` for a corner.
        if matches!(words.clone().next(), Some("v" | "vt" | "vn" | "f")) {
            if line.trim_end().ends_with('\\') {
                return Err(format!(
                    "line {at}: a line continued with `\\` is not supported: join it to the next"
                ));
            }
            if words.clone().any(|w| w.starts_with('#')) {
                return Err(format!(
                    "line {at}: a comment after data is not supported: put it on a line of its own"
                ));
            }
        }
        match words.next() {
            Some("v") => {
                let numbers: Vec<f64> = words.take(3).filter_map(|w| w.parse().ok()).collect();
                let line = line.trim();
                if numbers.len() < 3 {
                    return Err(format!(
                        "line {at}: `{line}` is not a position of three numbers"
                    ));
                }
                if numbers.iter().any(|c| !c.is_finite()) {
                    return Err(format!(
                        "line {at}: `{line}` has a NaN or infinite coordinate"
                    ));
                }
                // A fourth number alone is w, which divides the position: zero leaves none.
                // (Six are a position and a colour, as `tobj` reads them.)
                let words: Vec<&str> = line.split_whitespace().skip(1).collect();
                let w = (words.len() == 4).then(|| words[3].parse::<f64>());
                if matches!(w, Some(Ok(w)) if w == 0.0) {
                    return Err(format!("line {at}: `{line}` has w = 0 (no position)"));
                }
                // A w that is NaN or infinite, or divides a coordinate past any float, leaves
                // no finite position either.
                if let Some(Ok(w)) = w
                    && (!w.is_finite() || numbers.iter().any(|c| !(c / w).is_finite()))
                {
                    return Err(format!(
                        "line {at}: `{line}` has w = {w}, which divides its position to no \
                         finite one"
                    ));
                }
                defined[0] += 1;
            }
            // The name is the rest of the line (it may hold spaces), as `tobj` reads it.
            Some(keyword @ ("o" | "g")) => {
                let name = line.trim()[1..].trim();
                names[usize::from(keyword == "g")] = origins.name(Some(name));
            }
            Some("vt") => defined[1] += 1,
            Some("vn") => defined[2] += 1,
            Some("f") => {
                let corners: Vec<&str> = words.collect();
                if corners.len() < 3 {
                    let k = corners.len();
                    return Err(format!(
                        "line {at}: a face needs three corners, this one has {k}"
                    ));
                }
                for c in corners {
                    // A corner is `v`, `v/vt`, `v//vn` or `v/vt/vn`; an empty field is absent,
                    // except the vertex's.
                    let kinds = ["vertex", "texture", "normal"];
                    for (k, field) in c.split('/').enumerate().take(3) {
                        let ok = match field.parse::<i64>() {
                            Ok(i) => names_one(i, defined[k]),
                            Err(_) => k > 0 && field.is_empty(),
                        };
                        if !ok {
                            let (what, count) = (kinds[k], defined[k]);
                            return Err(format!(
                                "line {at}: the corner `{c}` names no {what} of the {count} \
                                 defined before it"
                            ));
                        }
                    }
                }
                faces.push((at, names));
            }
            _ => {}
        }
    }
    // Text with no position at all and something other than comments: not an OBJ file.
    let stray = text
        .lines()
        .map(str::trim)
        .position(|l| !l.is_empty() && !l.starts_with('#'));
    match (defined[0], stray) {
        (0, Some(n)) => Err(format!(
            "line {}: no position (`v`) in the whole file: is this an OBJ file?",
            n + 1
        )),
        _ => Ok(faces),
    }
}
