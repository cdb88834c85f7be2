//! glTF primitives the loader refuses or reads where it once cut them short or failed: a
//! partial triangle, a percent-encoded buffer name, a position that is not finite.

use ballcast_level::{Problem, load};

/// A one-node, one-mesh glTF file `name.gltf` in a directory of its own: `positions` (with
/// `indices` if given) drawn in `mode`, its buffer written to the file `bin` and named in the
/// document by `uri`.
fn gltf_file(
    name: &str,
    positions: &[[f32; 3]],
    indices: Option<&[u16]>,
    mode: u32,
    (bin, uri): (&str, &str),
) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("ballcast-gltf-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut data: Vec<u8> = positions
        .iter()
        .flatten()
        .flat_map(|c| c.to_le_bytes())
        .collect();
    let p = data.len();
    data.extend(indices.unwrap_or(&[]).iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join(bin), &data).unwrap();
    let bound = |f: fn(f32, f32) -> f32| {
        let c = |k: usize| {
            positions
                .iter()
                .map(move |v| v[k])
                .filter(|c| c.is_finite())
        };
        format!(
            "[{}, {}, {}]",
            c(0).reduce(f).unwrap(),
            c(1).reduce(f).unwrap(),
            c(2).reduce(f).unwrap()
        )
    };
    let (index_view, index_accessor, indexed) = match indices {
        Some(i) => (
            format!(
                r#", {{"buffer": 0, "byteOffset": {p}, "byteLength": {}}}"#,
                2 * i.len()
            ),
            format!(
                r#", {{"bufferView": 1, "componentType": 5123, "count": {}, "type": "SCALAR"}}"#,
                i.len()
            ),
            r#""indices": 1, "#,
        ),
        None => (String::new(), String::new(), ""),
    };
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
  "nodes": [{{"mesh": 0}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, {indexed}"mode": {mode}}}]}}],
  "buffers": [{{"uri": "{uri}", "byteLength": {}}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": {p}}}{index_view}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": {}, "type": "VEC3", "min": {}, "max": {}}}{index_accessor}]}}"#,
        data.len(),
        positions.len(),
        bound(f32::min),
        bound(f32::max),
    );
    let path = dir.join(format!("{name}.gltf"));
    std::fs::write(&path, json).unwrap();
    path
}

const SQUARE: [[f32; 3]; 4] = [
    [0.0, 0.0, 0.0],
    [0.0, 0.0, 1.0],
    [1.0, 0.0, 1.0],
    [1.0, 0.0, 0.0],
];

/// Triangles, strips and fans whose index (or vertex) count leaves a part of a triangle are
/// refused, naming the mesh, the primitive and the count, where the rest was cut off unsaid.
#[test]
fn gltf_primitive_with_a_partial_triangle_is_refused() {
    let bin = ("buffer.bin", "buffer.bin");
    let cases = [
        (
            "triangles_indexed",
            Some(&[0u16, 1, 2, 0][..]),
            4,
            "4 indices",
        ),
        ("triangles_plain", None, 4, "4 vertices"),
        ("strip", Some(&[0, 1][..]), 5, "2 indices"),
        ("fan", Some(&[0, 1][..]), 6, "2 indices"),
    ];
    for (name, indices, mode, count) in cases {
        let e = load(gltf_file(name, &SQUARE, indices, mode, bin)).expect_err(name);
        let text = e.to_string();
        assert!(
            matches!(e.problem, Problem::Malformed(_))
                && text.contains("mesh 0 primitive 0")
                && text.contains(count),
            "{name}: {text}"
        );
    }
    // Whole triangles load.
    let level = load(gltf_file(
        "whole",
        &SQUARE,
        Some(&[0, 1, 2, 0, 2, 3]),
        4,
        bin,
    ))
    .unwrap();
    assert_eq!(level.triangles.len(), 2);
}

/// A buffer URI is percent-encoded (`my%20level.bin` for the file `my level.bin`, as in the
/// Khronos "Box With Spaces" sample); a file literally named with the escape still loads.
#[test]
fn gltf_percent_encoded_buffer_uri() {
    let fan = Some(&[0u16, 1, 2, 0, 2, 3][..]);
    for (name, files) in [
        ("spaces", ("my level.bin", "my%20level.bin")),
        ("utf8", ("niveau é.bin", "niveau%20%C3%A9.bin")),
        ("literal", ("a%20b.bin", "a%20b.bin")),
    ] {
        let level = load(gltf_file(name, &SQUARE, fan, 4, files)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(level.triangles.len(), 2, "{name}");
    }
}

/// A NaN or infinite position in a glTF primitive is named where it is (node, mesh,
/// primitive, vertex), not as a triangle "counting polygons split into triangles".
#[test]
fn gltf_non_finite_position_is_named_in_its_primitive() {
    for (name, bad) in [("nan", f32::NAN), ("infinite", f32::NEG_INFINITY)] {
        let mut positions = SQUARE;
        positions[2][1] = bad;
        let path = gltf_file(name, &positions, Some(&[0, 1, 2]), 4, ("b.bin", "b.bin"));
        let e = load(path).expect_err(name);
        let text = e.to_string();
        assert!(
            matches!(e.problem, Problem::Malformed(_))
                && text.contains("mesh 0 primitive 0 (node 0)")
                && text.contains("vertex 2")
                && !text.contains("polygons"),
            "{name}: {text}"
        );
    }
}
