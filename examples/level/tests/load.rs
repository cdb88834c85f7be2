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
