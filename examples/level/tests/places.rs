//! Messages that name a triangle also say where it came from in the file: an OBJ face's line
//! (and which triangle of its polygon), a glTF node, mesh, primitive and triangle. Each test
//! reads the message as a user would, by its words.

use ballcast::fixed::types::I16F16;
use ballcast_level::{Level, LevelError, Problem, bake, bake_compact, load};
use std::path::PathBuf;

/// A file in a temporary directory of its own, removed with it when dropped.
struct Temp(PathBuf);

impl Temp {
    /// `name` written with `bytes` in a fresh directory (with `extra` files beside it).
    fn new(name: &str, bytes: &[u8], extra: &[(&str, &[u8])]) -> Self {
        let pid = std::process::id();
        let dir = std::env::temp_dir().join(format!("ballcast-places-{pid}-{name}"));
        std::fs::create_dir_all(&dir).unwrap();
        for (file, data) in extra {
            std::fs::write(dir.join(file), data).unwrap();
        }
        std::fs::write(dir.join(name), bytes).unwrap();
        Temp(dir.join(name))
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        if let Some(dir) = self.0.parent() {
            let _ = std::fs::remove_dir_all(dir);
        }
    }
}

/// The level in OBJ `text`, written to `name.obj`.
fn obj(name: &str, text: &str) -> Result<Level, LevelError> {
    load(&Temp::new(&format!("{name}.obj"), text.as_bytes(), &[]).0)
}

/// A glTF file `name.gltf` (buffer beside it) of `nodes` (name, mesh), `meshes` (name,
/// primitives) and primitives as lists of separate triangles.
fn gltf(name: &str, nodes: &[(&str, usize)], meshes: &[(&str, Vec<Vec<[f32; 9]>>)]) -> Level {
    let (mut data, mut views, mut accessors, mut json_meshes) = (vec![], vec![], vec![], vec![]);
    for (mesh_name, primitives) in meshes {
        let mut prims = vec![];
        for triangles in primitives {
            let offset = data.len();
            let floats = triangles.iter().flatten();
            data.extend(floats.clone().flat_map(|c| c.to_le_bytes()));
            let bound = |k: usize, f: fn(f32, f32) -> f32| {
                floats
                    .clone()
                    .skip(k)
                    .step_by(3)
                    .copied()
                    .reduce(f)
                    .unwrap()
            };
            let [lo, hi] = [f32::min, f32::max].map(|f| [0, 1, 2].map(|k| bound(k, f)));
            views.push(format!(
                r#"{{"buffer": 0, "byteOffset": {offset}, "byteLength": {}}}"#,
                data.len() - offset
            ));
            accessors.push(format!(
                r#"{{"bufferView": {}, "componentType": 5126, "count": {}, "type": "VEC3", "min": {lo:?}, "max": {hi:?}}}"#,
                views.len() - 1,
                3 * triangles.len()
            ));
            let a = accessors.len() - 1;
            prims.push(format!(r#"{{"attributes": {{"POSITION": {a}}}}}"#));
        }
        json_meshes.push(format!(
            r#"{{"name": {mesh_name:?}, "primitives": [{}]}}"#,
            prims.join(", ")
        ));
    }
    let json_nodes: Vec<String> = (nodes.iter())
        .map(|(n, m)| format!(r#"{{"name": {n:?}, "mesh": {m}}}"#))
        .collect();
    let roots: Vec<usize> = (0..nodes.len()).collect();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": {roots:?}}}],
  "nodes": [{}], "meshes": [{}],
  "buffers": [{{"uri": "b.bin", "byteLength": {}}}],
  "bufferViews": [{}], "accessors": [{}]}}"#,
        json_nodes.join(", "),
        json_meshes.join(", "),
        data.len(),
        views.join(", "),
        accessors.join(", ")
    );
    let file = Temp::new(
        &format!("{name}.gltf"),
        json.as_bytes(),
        &[("b.bin", &data)],
    );
    load(&file.0).unwrap_or_else(|e| panic!("{e}"))
}

/// A floor triangle and a degenerate one (coincident corners).
const FLOOR: [f32; 9] = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 1.0];
const FILLER: [f32; 9] = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0];

const SQUARE: &str = "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\n";

#[test]
fn a_degenerate_filler_on_obj_line_10_is_reported_at_line_10() {
    // Lines 1-4 the square, 5-8 comments and a quad (two triangles), line 10 the filler.
    let text = format!("{SQUARE}# floor\n\nf 1 2 3 4\n# filler\n\nf 1 1 2\nf 1 3 4\n");
    let level = obj("filler", &text).unwrap();
    let line = bake::<f32>(&level).unwrap().stats.to_string();
    assert!(
        line.contains("4 triangles, 1 degenerate skipped [2] (2: line 10), "),
        "{line}"
    );
}

#[test]
fn a_split_polygons_out_of_range_corner_names_its_line_and_which_triangle() {
    // A pentagon on line 9 whose fourth corner is beyond I16F16's ±4096: split as the fan
    // 1 2 3, 1 3 4, 1 4 5, the corner first appears in its second triangle, the level's
    // triangle 2 (after the triangle on line 8).
    let text = "o Room\nv 0 0 0\nv 0 0 1\nv 1 0 2\nv 5000 0 1\nv 1 0 0\ng floor\nf 1 2 5\n\
                f 1 2 3 4 5\n";
    let level = obj("pentagon", text).unwrap();
    let want = "pentagon.obj: triangle 2 (line 9, triangle 2 of 3 in its polygon, object \
                \"Room\", group \"floor\") has the coordinate 5000, outside I16F16's range ±4096";
    for e in [
        bake::<I16F16>(&level).unwrap_err(),
        bake_compact::<I16F16>(&level).unwrap_err(),
    ] {
        assert!(matches!(e.problem, Problem::OutOfRange { triangle: 2, .. }));
        assert!(e.to_string().ends_with(want), "{e}");
    }
}

#[test]
fn a_gltf_primitives_degenerate_triangle_names_node_mesh_primitive_and_local_index() {
    // Node 0 (unnamed) draws mesh 0 (unnamed): a filler. Node 1 "Floor" draws mesh 1
    // "Tiles": primitive 0 two floors, primitive 1 a floor, a filler and a floor.
    let level = gltf(
        "primitives",
        &[("", 0), ("Floor", 1)],
        &[
            ("", vec![vec![FILLER]]),
            ("Tiles", vec![vec![FLOOR; 2], vec![FLOOR, FILLER, FLOOR]]),
        ],
    );
    let line = bake::<f32>(&level).unwrap().stats.to_string();
    let want = "6 triangles, 2 degenerate skipped [0, 4] (0: node 0, mesh 0, primitive 0's \
                triangle 0; 4: node 1 \"Floor\", mesh 1 \"Tiles\", primitive 1's triangle 1), ";
    assert!(line.contains(want), "{line}");
}

#[test]
fn a_gltf_triangle_out_of_range_names_node_mesh_primitive_and_local_index() {
    let far = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 5000.0, 0.0, 1.0];
    let level = gltf(
        "far",
        &[("", 0), ("Bridge", 1)],
        &[
            ("", vec![vec![FLOOR]]),
            ("Span", vec![vec![FLOOR], vec![FLOOR, far]]),
        ],
    );
    let e = bake::<I16F16>(&level).unwrap_err();
    let want = "far.gltf: triangle 3 (node 1 \"Bridge\", mesh 1 \"Span\", primitive 1's triangle \
                1) has the coordinate 5000, outside I16F16's range ±4096";
    assert!(e.to_string().ends_with(want), "{e}");
}

/// A name is quoted with its escapes: a line break in a node's name does not end the baked
/// file's comment that holds the statistics.
#[test]
fn a_gltf_node_name_with_a_line_break_stays_on_the_statistics_line() {
    let level = gltf(
        "break",
        &[("Floor\nB", 0)],
        &[("", vec![vec![FILLER, FLOOR]])],
    );
    let source = bake::<f32>(&level).unwrap().source;
    let comment = source.lines().nth(1).unwrap();
    assert!(
        comment.starts_with("// ") && comment.contains(r#"(0: node 0 "Floor\nB", mesh 0,"#),
        "{comment}"
    );
    assert!(source.lines().nth(2).unwrap().starts_with("use ballcast::"));
}

/// A position whose w divides it past f64's range, or a w that is NaN or infinite, is refused
/// at its own line (it passed the line check and was refused later, at the face using it).
#[test]
fn a_position_divided_into_infinity_by_its_w_is_refused_at_its_line() {
    for w in ["1e-300", "nan", "inf"] {
        let text = format!("{SQUARE}v 1e300 0 0 {w}\nf 1 2 3\n\nf 1 3 5\n");
        let e = obj("w_infinite", &text).unwrap_err();
        assert!(matches!(e.problem, Problem::Malformed(_)), "{e}");
        let want = format!("line 5: `v 1e300 0 0 {w}` has w = ");
        assert!(e.to_string().contains(&want), "{e}");
    }
}

/// A build script that turns a coordinate into NaN after loading: the mesh build refuses the
/// triangle by index, and the message adds its place.
#[test]
fn a_nan_set_after_loading_is_refused_at_its_faces_line() {
    let mut level = obj("nan_later", &format!("{SQUARE}g floor\nf 1 2 3\nf 1 3 4\n")).unwrap();
    level.triangles[1][2][0] = f64::NAN;
    for e in [
        bake::<f32>(&level).unwrap_err(),
        bake_compact::<f32>(&level).unwrap_err(),
    ] {
        assert!(matches!(e.problem, Problem::Mesh(_)), "{e}");
        let text = e.to_string();
        assert!(
            text.contains("triangle 1: a coordinate of v2 is NaN")
                && text.ends_with("; triangle 1 is at line 7, group \"floor\""),
            "{text}"
        );
    }
}

/// Triangles added without their origins leave the level with none, rather than the places
/// of the triangles they pushed along.
#[test]
fn triangles_added_without_their_origins_name_no_place() {
    let mut level = obj("added", &format!("{SQUARE}f 1 2 3\nf 1 3 4\n")).unwrap();
    assert_eq!(level.origin(1).unwrap().to_string(), "line 6");
    let filler = [[0.0; 3], [0.0; 3], [1.0, 0.0, 0.0]];
    level.triangles.insert(1, filler);
    assert_eq!(level.origin(1), None);
    let line = bake::<f32>(&level).unwrap().stats.to_string();
    assert!(line.contains("1 degenerate skipped [1], "), "{line}");
}

/// Many degenerate faces: the line lists eight indices and places the first three, so it
/// stays short.
#[test]
fn many_degenerate_faces_place_only_the_first_three() {
    let text = format!("{SQUARE}f 1 2 3\n{}", "f 1 1 2\n".repeat(20_000));
    let level = obj("many", &text).unwrap();
    let line = bake::<f32>(&level).unwrap().stats.to_string();
    let want = "20000 degenerate skipped [1, 2, 3, 4, 5, 6, 7, 8, … and 19992 more] \
                (1: line 6; 2: line 7; 3: line 8), ";
    assert!(line.contains(want) && line.len() < 300, "{line}");
}
