//! The loader on small files written by hand (`tests/data`), against the triangles expected of
//! them; malformed files of each kind give an error naming the file, not a panic.

use ballcast::{Contact, Geometry, StandardTriangle, Sweep, Vec3};
use ballcast_level::{Level, Problem, Tri, bake, load, triangles};
use fixed::types::I16F16;

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn assert_near(got: &[Tri], want: &[Tri]) {
    assert_eq!(got.len(), want.len(), "{got:?}");
    for (g, w) in got.iter().zip(want) {
        let far = g
            .iter()
            .flatten()
            .zip(w.iter().flatten())
            .any(|(a, b)| (a - b).abs() > 1e-6);
        assert!(!far, "got {g:?}, want {w:?}");
    }
}

/// A ball dropped onto the level from above at (x, z) stops on a face whose normal is +y,
/// and one rising from below passes (front faces are counter-clockwise seen from above).
fn front_faces_up(level: &Level, x: f32, z: f32) {
    let prepared: Vec<StandardTriangle<f32>> = triangles::<f32>(level)
        .unwrap()
        .iter()
        .map(|t| StandardTriangle::new(t).unwrap())
        .collect();
    let down = Sweep::new(Vec3::new(x, 2.0, z), Vec3::new(x, -2.0, z), 0.25).unwrap();
    let hit = prepared[..]
        .cast(&down)
        .expect("the front face stops the ball");
    assert_eq!(
        (hit.normal, hit.contact),
        (Vec3::new(0.0, 1.0, 0.0), Contact::Face)
    );
    let up = Sweep::new(Vec3::new(x, -2.0, z), Vec3::new(x, 2.0, z), 0.25).unwrap();
    assert_eq!(
        prepared[..].cast(&up),
        None,
        "the back face lets the ball through"
    );
}

#[test]
fn obj_quads_and_negative_indices() {
    let level = load(data("quads.obj")).unwrap();
    let (a, b, c, d) = (
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 0.0, 1.0],
        [0.0, 0.0, 1.0],
    );
    let (e, f, g, h) = (
        [0.0, 0.0, 3.0],
        [0.0, 1.0, 3.0],
        [2.0, 1.0, 3.0],
        [2.0, 0.0, 3.0],
    );
    // Quads as fans from their first vertex: `f -4 -1 -2 -3` is a, d, c, b.
    assert_eq!(
        level.triangles,
        vec![[a, d, c], [a, c, b], [e, f, g], [e, g, h]]
    );
    front_faces_up(&level, 0.5, 0.5);
}

#[test]
fn gltf_node_hierarchy_and_indexed_primitive() {
    // Root: translate (10, 0, 0), scale 2; child: rotate 90 degrees about y, with the mesh.
    // Rotation takes (x, y, z) to (z, y, -x).
    let level = load(data("hierarchy.gltf")).unwrap();
    assert_near(
        &level.triangles,
        &[[[10.0, 0.0, 0.0], [12.0, 0.0, 0.0], [10.0, 0.0, -2.0]]],
    );
    front_faces_up(&level, 10.5, -0.5);
}

#[test]
fn glb_mirroring_node_keeps_front_faces() {
    // Scale -1 on x turns the triangle over; the loader reverses its order, as glTF asks.
    let level = load(data("mirrored.glb")).unwrap();
    assert_near(
        &level.triangles,
        &[[[0.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]],
    );
    front_faces_up(&level, -0.25, 0.25);
}

/// The error names the file and says what is wrong.
fn refused(name: &str, what: &str) -> Problem {
    let e = load(data(name)).expect_err(name);
    let text = e.to_string();
    assert!(text.contains(name) && text.contains(what), "{text}");
    e.problem
}

#[test]
fn malformed_obj() {
    // Each names its line.
    assert!(matches!(
        refused(
            "bad_number.obj",
            "malformed: line 3: `v 1 x 0` is not a position"
        ),
        Problem::Malformed(_)
    ));
    assert!(matches!(
        refused(
            "bad_index.obj",
            "line 4: the corner `9` names no vertex of the 3"
        ),
        Problem::Malformed(_)
    ));
    // A texture index beyond those defined, and a material library that would make the
    // parser panic (a colour of two numbers): the first refused, the second never read.
    assert!(matches!(
        refused(
            "bad_texture.obj",
            "line 5: the corner `2/-5` names no texture of the 1"
        ),
        Problem::Malformed(_)
    ));
    assert_eq!(load(data("bad_material.obj")).unwrap().triangles.len(), 1);
    // A face of two corners, after a good one: refused, not dropped without a word.
    assert!(matches!(
        refused(
            "two_corners.obj",
            "line 5: a face needs three corners, this one has 2"
        ),
        Problem::Malformed(_)
    ));
    assert!(matches!(
        refused("no_faces.obj", "no triangles"),
        Problem::NoTriangles
    ));
    assert!(matches!(
        refused(
            "nan.obj",
            "line 2: `v nan 0 0` has a NaN or infinite coordinate"
        ),
        Problem::Malformed(_)
    ));
    // A w of zero: named at its line (the parser's own error named none); six numbers are a
    // position and a colour, a zero among them no w.
    assert!(matches!(
        refused("w_zero.obj", "line 4: `v 1 0 0 0` has w = 0"),
        Problem::Malformed(_)
    ));
    assert_eq!(load(data("coloured.obj")).unwrap().triangles.len(), 1);
    // Text that is no OBJ at all: told so, not "no triangles".
    assert!(matches!(
        refused("not_obj.obj", "line 1: no position (`v`) in the whole file"),
        Problem::Malformed(_)
    ));
}

#[test]
fn malformed_gltf_and_glb() {
    assert!(matches!(
        refused("truncated.gltf", "malformed"),
        Problem::Malformed(_)
    ));
    assert!(matches!(
        refused("outside.gltf", "outside its buffer"),
        Problem::Malformed(_)
    ));
    assert!(matches!(
        refused("truncated.glb", "malformed"),
        Problem::Malformed(_)
    ));
    // A primitive whose POSITION accessor does not exist (the parser's own validation once
    // panicked on it).
    assert!(matches!(
        refused("missing_accessor.gltf", "accessor 0 does not exist"),
        Problem::Malformed(_)
    ));
    // hierarchy.gltf with the root listed as a child of its own child: a cycle, not a tree.
    assert!(matches!(
        refused("cycle.gltf", "not a tree"),
        Problem::Malformed(_)
    ));
}

#[test]
fn missing_file_and_unknown_format() {
    assert!(matches!(
        refused("missing.obj", "cannot read"),
        Problem::Io(_)
    ));
    assert!(matches!(
        refused("missing.gltf", "cannot read"),
        Problem::Io(_)
    ));
    assert!(matches!(
        refused("quads.stl", "unknown format"),
        Problem::UnknownFormat
    ));
}

#[test]
fn coordinates_beyond_the_scalar_range() {
    // 5000 is beyond I16F16's ±4096 but fine in f32.
    let level = load(data("large.obj")).unwrap();
    let e = bake::<I16F16>(&level).expect_err("out of range");
    assert!(
        e.to_string().contains("large.obj") && e.to_string().contains("I16F16"),
        "{e}"
    );
    assert!(matches!(
        e.problem,
        Problem::OutOfRange {
            triangle: 0,
            value: 5000.0,
            ..
        }
    ));
    assert!(bake::<f32>(&level).is_ok());
}

/// A compact bake keeps only the vertices of the triangles it keeps: a degenerate triangle
/// on three vertices of its own (far off the floor) adds none to flash.
#[test]
fn a_compact_bake_keeps_no_vertex_of_a_skipped_triangle() {
    let mut level = load(data("quads.obj")).unwrap();
    let plain = ballcast_level::bake_compact::<f32>(&level).unwrap();
    level
        .triangles
        .insert(1, [[9.0, 9.0, 9.0], [9.0, 9.0, 9.0], [10.0, 9.0, 9.0]]);
    let baked = ballcast_level::bake_compact::<f32>(&level).unwrap();
    assert_eq!(baked.stats.skipped, [1]);
    let vertices = |b: &ballcast_level::Baked| match b.stats.form {
        ballcast_level::Form::Compact { vertices, .. } => vertices,
        _ => unreachable!(),
    };
    assert_eq!(vertices(&baked), vertices(&plain));
    assert!(
        !baked.source.contains("v([1092616192, 1091567616"),
        "the (10, 9, .) corner"
    );
}

#[test]
fn degenerate_triangles_are_skipped_and_named() {
    // The two floor triangles of quads.obj, and a third with coincident vertices between them.
    let mut level = load(data("quads.obj")).unwrap();
    level
        .triangles
        .insert(1, [[0.0; 3], [0.0; 3], [1.0, 0.0, 0.0]]);
    let baked = bake::<f32>(&level).unwrap();
    assert_eq!(
        (baked.stats.triangles, baked.stats.skipped.clone()),
        (5, vec![1])
    );
    // The baked order (leaf order) holds every other input index once.
    let line = baked
        .source
        .lines()
        .find(|l| l.starts_with("pub static ORDER"))
        .unwrap();
    let list = &line[line.find("= [").unwrap() + 3..line.rfind(']').unwrap()];
    let mut order: Vec<usize> = list.split(", ").map(|i| i.parse().unwrap()).collect();
    order.sort();
    assert_eq!(order, vec![0, 2, 3, 4]);
}

/// A level whose every triangle is degenerate (collinear corners here) is refused, naming the
/// file, instead of baking an empty mesh a firmware would fall through.
#[test]
fn a_level_of_only_degenerate_triangles_is_refused() {
    let mut level = load(data("quads.obj")).unwrap();
    level.triangles = vec![[[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]; 3];
    let e = bake::<f32>(&level).expect_err("nothing left");
    assert!(
        matches!(e.problem, Problem::AllDegenerate { count: 3 }),
        "{e}"
    );
    assert!(e.to_string().contains("quads.obj"), "{e}");
}

/// A glTF material's `doubleSided` makes its triangles two-sided, in the level and in the bake
/// (the one-sided material's copy of the same triangle stays one-sided).
#[test]
fn gltf_double_sided_material_bakes_two_sided() {
    let level = load(data("double_sided.gltf")).unwrap();
    assert_eq!(level.triangles.len(), 2);
    assert_eq!(level.two_sided, vec![true, false]);
    let baked = bake::<f32>(&level).unwrap();
    assert_eq!(baked.stats.two_sided, 1);
    assert!(
        baked.stats.to_string().contains("1 two-sided"),
        "{}",
        baked.stats
    );
    // The compact bake keeps the mark in each triangle's byte.
    let compact = ballcast_level::bake_compact::<f32>(&level).unwrap();
    assert_eq!(compact.stats.two_sided, 1);
    // An OBJ file has no such mark.
    let obj = load(data("quads.obj")).unwrap();
    assert!(obj.two_sided.iter().all(|&s| !s) && obj.two_sided.len() == obj.triangles.len());
    assert_eq!(bake::<f32>(&obj).unwrap().stats.two_sided, 0);
}

/// A binary file named `.obj` is refused as not text, at its line, instead of the parser's
/// bare "read error".
#[test]
fn binary_junk_named_obj_is_not_text() {
    let path = std::env::temp_dir().join(format!("ballcast-junk-{}.obj", std::process::id()));
    std::fs::write(&path, b"v 0 0 0\nv 1 0 0\n\xff\xfe\x00\x01junk\n").unwrap();
    let e = load(&path).expect_err("binary");
    std::fs::remove_file(&path).ok();
    let text = e.to_string();
    assert!(
        matches!(e.problem, Problem::Malformed(_)) && text.contains("line 3: not text"),
        "{text}"
    );
}

#[test]
fn a_level_with_its_floors_turned_down_is_told_apart() {
    let level = load(data("quads.obj")).unwrap();
    // quads.obj: a floor quad facing up, a wall quad (neither).
    assert_eq!(level.facing(), (2, 0));
    let flipped = Level {
        triangles: level.triangles.iter().map(|&[a, b, c]| [a, c, b]).collect(),
        ..level.clone()
    };
    assert_eq!(flipped.facing(), (0, 2));
    // Two-sided triangles stop balls either way: not counted.
    let both = Level {
        two_sided: vec![true; flipped.triangles.len()],
        ..flipped
    };
    assert_eq!(both.facing(), (0, 0));
}

/// Loads `text` written to a temporary `.obj` file named after `name`.
fn load_obj_text(name: &str, text: &str) -> Result<Level, ballcast_level::LevelError> {
    let dir = std::env::temp_dir().join(format!("ballcast-load-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.obj"));
    std::fs::write(&path, text).unwrap();
    let level = load(&path);
    std::fs::remove_file(&path).ok();
    level
}

/// `l` lines are polylines, not faces: however many vertices they list, only the `f` line is
/// collision geometry.
#[test]
fn obj_polylines_are_not_faces() {
    let vertices = "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 5 0 5\nv 5 0 6\nv 6 0 6\nv 6 0 5\n\
                    vt 0 0\nvt 1 0\nvt 1 1\n";
    let floor = [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]];
    for line in ["l 4 5 6", "l 4 5 6 7", "l 1/1 2/2 3/3", "l 4 5"] {
        let level = load_obj_text("polyline", &format!("{vertices}f 1 2 3\n{line}\n"))
            .unwrap_or_else(|e| panic!("{line}: {e}"));
        assert_eq!(level.triangles, vec![floor], "{line}");
    }
}

/// A UTF-8 byte-order mark before the first `v` (as some Windows tools write) is no part of
/// the keyword: every index still names the vertex it names without one.
#[test]
fn obj_with_a_byte_order_mark() {
    let text = "\u{feff}v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3\n";
    let level = load_obj_text("bom", text).unwrap();
    assert_eq!(
        level.triangles,
        vec![[[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 1.0]]]
    );
    // Faults are still named at their line.
    let e = load_obj_text("bom_fault", "\u{feff}v 0 0 0\nv 1 x 0\n").unwrap_err();
    assert!(e.to_string().contains("line 2: `v 1 x 0`"), "{e}");
}

/// Where a ball dropped straight down at (x, z) first meets the level, and the normal there.
fn drop_at(level: &Level, x: f32, z: f32) -> Option<Vec3<f32>> {
    let prepared: Vec<StandardTriangle<f32>> = triangles::<f32>(level)
        .unwrap()
        .iter()
        .filter_map(|t| StandardTriangle::new(t).ok())
        .collect();
    let down = Sweep::new(Vec3::new(x, 2.0, z), Vec3::new(x, -2.0, z), 0.01).unwrap();
    prepared[..].cast(&down).map(|hit| hit.normal)
}

/// An L-shaped floor written as one six-corner face: split inside its outline (the fan from
/// its first corner floored the notch and put a triangle face down), with the area of the L.
#[test]
fn obj_concave_polygon_is_split_inside_it() {
    // x, z: (0,0) (0,2) (2,2) (2,1) (1,1) (1,0), counter-clockwise seen from above; the notch
    // is x in (1, 2), z in (0, 1).
    let text = "v 0 0 0\nv 0 0 2\nv 2 0 2\nv 2 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4 5 6\n";
    let level = load_obj_text("l_floor", text).unwrap();
    let mut area = 0.0;
    for [a, b, c] in &level.triangles {
        // Twice the area seen from above, positive for a triangle facing up.
        let up = (c[0] - a[0]) * (b[2] - a[2]) - (b[0] - a[0]) * (c[2] - a[2]);
        assert!(up >= 0.0, "a triangle faces down: {:?}", [a, b, c]);
        area += up / 2.0;
    }
    assert!((area - 3.0).abs() < 1e-12, "area {area}");
    for (x, z) in [(0.5, 0.5), (0.5, 1.5), (1.5, 1.5), (0.9, 0.1), (1.9, 1.1)] {
        let normal = drop_at(&level, x, z).unwrap_or_else(|| panic!("fell through at {x}, {z}"));
        assert!(normal.y > 0.999, "{x}, {z}: {normal:?}");
    }
    for (x, z) in [(1.5, 0.5), (1.5, 0.9), (1.9, 0.1)] {
        assert_eq!(
            drop_at(&level, x, z),
            None,
            "a floor in the notch at {x}, {z}"
        );
    }
}

/// Convex polygons, quads included, stay the fans from their first corner, in that order; so
/// does a concave one whose fan covers it (its reflex corner first).
#[test]
fn obj_polygons_a_fan_covers_stay_fans() {
    let hexagon = "v 0 0 0\nv 0 0 2\nv 1 0 3\nv 2 0 2\nv 2 0 0\nv 1 0 -1\nf 1 2 3 4 5 6\n";
    let level = load_obj_text("hexagon", hexagon).unwrap();
    let v = [
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 2.0],
        [1.0, 0.0, 3.0],
        [2.0, 0.0, 2.0],
        [2.0, 0.0, 0.0],
        [1.0, 0.0, -1.0],
    ];
    let fan = |k: usize| {
        (1..k - 1)
            .map(|i| [v[0], v[i], v[i + 1]])
            .collect::<Vec<_>>()
    };
    assert_eq!(level.triangles, fan(6));
    // The L from its reflex corner (1, 1) on: every fan triangle lies inside.
    let l = "v 1 0 1\nv 1 0 0\nv 0 0 0\nv 0 0 2\nv 2 0 2\nv 2 0 1\nf 1 2 3 4 5 6\n";
    let level = load_obj_text("l_from_reflex", l).unwrap();
    assert_eq!(level.triangles.len(), 4);
    assert!(level.triangles.iter().all(|t| t[0] == [1.0, 0.0, 1.0]));
}

/// A face whose edges cross (a bow tie) is no polygon: refused at its line, where its fan gave
/// one triangle facing up and one facing down.
#[test]
fn obj_polygon_crossing_itself_is_refused() {
    let vertices = "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nv 2 0 2\nv 3 0 0\n";
    // The two halves equal (they cancel) and unequal.
    for face in ["f 1 3 2 4", "f 1 5 4 2", "f 1 5 6 2"] {
        let text = format!("{vertices}f 1 2 3\n{face}\n");
        let e = load_obj_text("bow_tie", &text).expect_err(face);
        assert!(
            e.to_string().contains("line 8: the polygon")
                && e.to_string().contains("triangulate it on export"),
            "{face}: {e}"
        );
    }
}

/// Random star-shaped polygons (simple, mostly concave), one per file line, each split into
/// triangles that face up, lie inside it and add up to its area.
#[test]
fn obj_random_concave_polygons_are_split_inside_them() {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut random = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut text, mut polygons, mut count) = (String::new(), Vec::new(), 0);
    for k in 0..200 {
        let corners = 4 + (random() * 12.0) as usize;
        // Counter-clockwise seen from above (+y): angle decreasing in x, z.
        let outline: Vec<[f64; 2]> = (0..corners)
            .map(|i| {
                let angle = -std::f64::consts::TAU * (i as f64 + 0.8 * random()) / corners as f64;
                let r = 0.3 + 4.0 * random();
                [10.0 * k as f64 + r * angle.cos(), r * angle.sin()]
            })
            .collect();
        let mut face = String::from("f");
        for [x, z] in &outline {
            count += 1;
            text += &format!("v {x} 0 {z}\n");
            face += &format!(" {count}");
        }
        text += &format!("{face}\n");
        polygons.push(outline);
    }
    let level = load_obj_text("stars", &text).unwrap();
    let twice = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        (c[0] - a[0]) * (b[1] - a[1]) - (b[0] - a[0]) * (c[1] - a[1])
    };
    let inside = |p: [f64; 2], poly: &[[f64; 2]]| {
        let mut crossings = 0;
        for (i, a) in poly.iter().enumerate() {
            let b = poly[(i + 1) % poly.len()];
            if (a[1] > p[1]) != (b[1] > p[1])
                && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            {
                crossings += 1;
            }
        }
        crossings % 2 == 1
    };
    let mut areas = vec![0.0; polygons.len()];
    for t in &level.triangles {
        let [a, b, c] = t.map(|p| [p[0], p[2]]);
        let up = twice(a, b, c);
        assert!(up >= 0.0, "{t:?} faces down");
        let centroid = [(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0];
        let k = ((centroid[0] + 5.0) / 10.0).floor() as usize;
        assert!(
            up < 1e-9 || inside(centroid, &polygons[k]),
            "{t:?} outside {k}"
        );
        areas[k] += up / 2.0;
    }
    for (k, poly) in polygons.iter().enumerate() {
        let area: f64 = (1..poly.len() - 1)
            .map(|i| twice(poly[0], poly[i], poly[i + 1]) / 2.0)
            .sum();
        assert!(
            (areas[k] - area).abs() < 1e-9 * area,
            "{k}: {} of {area}",
            areas[k]
        );
    }
}

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

/// The statistics line (stderr, and the baked file's second line) names the first few
/// degenerate triangles and counts the rest, however many there are; the planner's line gives
/// the extent to four figures.
#[test]
fn bake_statistics_stay_short() {
    let mut level = load(data("quads.obj")).unwrap();
    let filler = [[0.0; 3], [0.0; 3], [1.0, 0.0, 0.0]];
    level.triangles.extend(std::iter::repeat_n(filler, 20_000));
    let baked = bake::<f32>(&level).unwrap();
    assert_eq!(baked.stats.skipped.len(), 20_000);
    let line = baked.stats.to_string();
    assert!(
        line.contains("20000 degenerate skipped [4, 5, 6, 7, 8, 9, 10, 11, … and 19992 more]")
            && line.len() < 250,
        "{line}"
    );
    let comment = baked.source.lines().nth(1).unwrap();
    assert!(comment.len() < 250, "{} bytes", comment.len());
    // Few: all of them; none: no list.
    level.triangles.truncate(6);
    let line = bake::<f32>(&level).unwrap().stats.to_string();
    assert!(line.contains("2 degenerate skipped [4, 5],"), "{line}");
    level.triangles.truncate(4);
    let line = bake::<f32>(&level).unwrap().stats.to_string();
    assert!(line.contains("0 degenerate skipped,"), "{line}");
    let plan = ballcast_level::verdicts(17.39230465888977, 0.5);
    assert!(
        plan.starts_with("plan at extent 17.39, radius 0.5: "),
        "{plan}"
    );
    let plan = ballcast_level::verdicts(4096.0, 0.25);
    assert!(
        plan.starts_with("plan at extent 4096, radius 0.25: "),
        "{plan}"
    );
}

/// A `#` comment after data and a `\` continuation are not read by the parser: refused at
/// their line with what to do, not as a bare parse error or a corner naming nothing.
#[test]
fn obj_comment_after_data_and_continuation_are_refused_at_their_line() {
    let cases = [
        (
            "v 0 0 0 # origin\nv 0 0 1\nv 1 0 1\nf 1 2 3\n",
            "line 1: a comment",
        ),
        (
            "v 0 0 0\nv 0 0 1\nv 1 0 1\nf 1 2 3 # floor\n",
            "line 4: a comment",
        ),
        (
            "v 0 0 0\nv 0 0 1\nv 1 0 1\nf 1 2 \\\n  3\n",
            "line 4: a line continued",
        ),
    ];
    for (text, what) in cases {
        let e = load_obj_text("comment", text).expect_err(what);
        assert!(e.to_string().contains(what), "{e}");
    }
    // A comment line of its own is fine.
    assert!(load_obj_text("own_line", "# top\nv 0 0 0\nv 0 0 1\nv 1 0 1\nf 1 2 3\n").is_ok());
}

/// A level exported +Z up (its floors facing +z) is told apart from a +Y-up one, for the
/// bake's warning.
#[test]
fn a_level_exported_z_up_is_told_apart() {
    let level = load(data("quads.obj")).unwrap();
    // (x, y, z) to (x, -z, y) takes +y to +z: quads.obj's floor then faces +z, its wall +y.
    let turn = |level: &Level| Level {
        triangles: (level.triangles.iter())
            .map(|t| t.map(|[x, y, z]| [x, -z, y]))
            .collect(),
        ..level.clone()
    };
    let floor = Level {
        triangles: level.triangles[..2].to_vec(),
        ..level.clone()
    };
    assert!(!floor.looks_z_up() && turn(&floor).looks_z_up());
    // Two triangles along each axis: not clearly either.
    assert_eq!(turn(&level).facing(), (2, 0));
    assert!(!level.looks_z_up() && !turn(&level).looks_z_up());
}
