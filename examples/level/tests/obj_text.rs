//! OBJ text the loader reads as a modelling tool writes it: polylines and a byte-order mark
//! passed over, polygons split inside their outline (convex ones as fans), and what is not
//! read (a crossing polygon, a comment after data, a continuation) refused at its line.

use ballcast::{Geometry, StandardTriangle, Sweep, Vec3};
use ballcast_level::{Level, load, triangles};

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
