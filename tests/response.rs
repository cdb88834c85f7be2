//! Issue 11: `move_and_slide` must never sink, creep or jitter, in any scalar.
//!
//! First the instances, each a regression test named after its case, then long-run
//! properties in every scalar (one `per_scalar!` instantiation per scalar): scenes built in
//! local coordinates and turned by random rigid motions, so no coordinate is exact. Every call
//! is measured against independent f64 geometry (`tests/common/response.rs`, allowances
//! documented on `Monitor`): never deeper into a triangle (front side) than at the start
//! beyond one skin `r / 1024 + 4 res`, never through a surface, never moved back along the push
//! beyond one skin per contact, drift within the push's own part plus `round`, and at rest in a
//! corner after settling (within `round`), where `round = 8 res + 8 EPSILON × path`. `res` is
//! the scalar's spacing at the scene's largest coordinate (one LSB for fixed-point), `path` the
//! longest displacement asked for (a contact is placed to within a step of alpha).
//!
//! `cargo test --test response`: 10^3 steps per run, three fixed seeds plus `PROPTEST_CASES`
//! (default 4) random ones per property and scalar.
//! `cargo test --release --test response -- --ignored --nocapture`: 10^5 steps per run, printing
//! per scalar the largest depth growth, drift and corner motion.

mod common;
#[path = "common/response_scenes.rs"]
mod scenes;
#[path = "common/response.rs"]
mod support;

use ballcast::Scalar;
use common::{P, Tolerance, add, angle, back, scale, sub, v};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use scenes::{
    Corner, box_push, corner, floor_rest, push_run, rng, roll, rolling, stairs, wedge_tris,
};
use support::{
    Maxima, Monitor, Rigid, Tri, World, assert_all, contact_normals, hit_normals, quad, unit,
};

/// Steps per run in `cargo test`, and in the ignored long runs.
const STEPS: usize = 1_000;
const LONG: usize = 100_000;
/// Fixed (seed, size kind, corner angle) triples run before the random ones.
const FIXED: [(u64, u8, f64); 3] = [(1, 0, 135.0), (2, 1, 60.0), (3, 2, 170.0)];

// ---- 1. Sinking ----------------------------------------------------------------------------

/// The two triangles, ball and displacement, repeated from each end for 4000 steps.
fn sinking<S: Tolerance>(steps: usize) -> Monitor {
    let (a, b) = ([2.45004, -6.02063, 0.85945], [0.64485, -7.19725, -2.51053]);
    let (c, d) = ([0.32376, -3.3826, -3.67041], [4.19987, -7.4502, -4.32652]);
    let w = World::<S>::new(&[[a, b, c], [a, d, b]], Rigid::IDENTITY);
    let start = back(v::<S>([0.84146, -7.01332, -2.48203]));
    let mut m = Monitor::new("sinking instance".into(), &w, start, 0.15114);
    // The instance as the issue reads it: about 1e-3 inside the first triangle's plane band.
    let h = w.height(0, start);
    assert!((h - 0.15017).abs() < 1e-4, "height {h}");
    push_run(
        &w,
        &mut m,
        start,
        [0.00032, -0.00253, 0.00098],
        steps,
        |_, _, _| {},
    );
    m
}

#[test]
fn sinking_i16f16_two_triangle_box_instance() {
    assert_all(&[
        sinking::<I16F16>(4000),
        sinking::<f64>(4000),
        sinking::<f32>(4000),
        sinking::<I32F32>(4000),
    ]);
}

// ---- 2. Creeping ---------------------------------------------------------------------------

/// Floors whose normals are Pythagorean quadruples: vertices and a push straight into the floor
/// are exact in every scalar, so the push has no tangential part at all and the allowed drift
/// is `round` (about `8 res`) over the whole run, however long.
fn creeping<S: Tolerance>(steps: usize) -> Vec<Monitor> {
    let mut out = Vec::new();
    for (n, r) in [
        ([1.0, 2.0, 2.0], 0.1),
        ([2.0, 3.0, 6.0], 0.25),
        ([4.0, 4.0, 7.0], 0.5),
    ] {
        let [a, b, c] = n;
        let (u, w2) = ([b, -a, 0.0], [a * c, b * c, -(a * a + b * b)]);
        let o = [3.0, -2.0, 5.0];
        let w = World::<S>::new(&quad(o, u, w2), Rigid::IDENTITY);
        let middle = add(o, scale(add(u, w2), 0.5));
        let start = back(v::<S>(add(middle, scale(unit(n), r + 1.5 * r / 1024.0))));
        let push = scale(n, -1.0 / 64.0);
        let normal = w.normals[0];
        let tangential = common::norm(scenes::across(back(v::<S>(push)), normal));
        assert!(tangential < 1e-15, "push not exact: {tangential}");
        let mut m = Monitor::new(format!("creeping n {n:?} r {r}"), &w, start, r);
        push_run(&w, &mut m, start, push, steps, |m, _, p| {
            m.drift(common::norm(scenes::across(sub(p, start), normal)), 0.0)
        });
        out.push(m);
    }
    out
}

#[test]
fn creeping_resting_ball_pushed_into_tilted_floor() {
    let mut all = creeping::<I16F16>(STEPS);
    all.extend(creeping::<f64>(STEPS));
    all.extend(creeping::<f32>(STEPS));
    all.extend(creeping::<I32F32>(STEPS));
    assert_all(&all);
}

// ---- 3. Corners and T-junctions ------------------------------------------------------------

/// The corner: walls facing +x and +z, the ball 0.0005 off each, pushed into both; also
/// starts a few EPSILON further out (inside f32's and f64's tie windows) and the mirrored push.
/// Neither gap may grow beyond its start (or one skin) by more than `round`.
fn corner_stays<S: Tolerance>() -> Vec<Monitor> {
    let x_wall = [[0.0; 3], [0.0, 3.0, 0.0], [0.0, 3.0, 4.0]];
    let z_wall = [[0.0; 3], [4.0, 3.0, 0.0], [0.0, 3.0, 0.0]];
    let w = World::<S>::new(&[x_wall, z_wall], Rigid::IDENTITY);
    assert!(
        w.normals[0][0] > 0.99 && w.normals[1][2] > 0.99,
        "walls face +x, +z"
    );
    let (r, eps) = (0.5, S::EPSILON.to_f64());
    let skin = r / 1024.0 + 4.0 * w.res;
    let mut starts = vec![[0.5005, 1.5, 0.5005]];
    for k in [1.0, 8.0, 64.0] {
        starts.push([r + skin + k * eps, 1.5, r + skin]);
        starts.push([r + skin, 1.5, r + skin + k * eps]);
    }
    let mut out = Vec::new();
    for start in starts {
        for push in [[-3.0, 0.0, -3.5], [-3.5, 0.0, -3.0]] {
            let start = back(v::<S>(start));
            let label = format!("corner from {start:?} pushed {push:?}");
            let mut m = Monitor::new(label, &w, start, r);
            let allowed = [start[0] - r, start[2] - r].map(|g| g.max(m.skin));
            push_run(&w, &mut m, start, push, 10, |m, _, p| {
                m.motion((p[0] - r - allowed[0]).max(p[2] - r - allowed[1]).max(0.0))
            });
            out.push(m);
        }
    }
    out
}

#[test]
fn corner_i16f16_two_walls_push_stays_put() {
    let mut all = corner_stays::<I16F16>();
    all.extend(corner_stays::<f64>());
    all.extend(corner_stays::<f32>());
    all.extend(corner_stays::<I32F32>());
    assert_all(&all);
}

/// A flat floor over [-2, 2]² at y = 0 with T-junctions along x = 0: the two triangles,
/// their partners, and two more tiles.
fn t_floor() -> Vec<Tri> {
    let t1 = [[-2.0, 0.0, -2.0], [0.0, 0.0, 2.0], [0.0, 0.0, -2.0]];
    let t1b = [[-2.0, 0.0, -2.0], [-2.0, 0.0, 2.0], [0.0, 0.0, 2.0]];
    let (x, z) = ([2.0, 0.0, 0.0], [0.0, 0.0, 2.0]);
    [
        vec![t1, t1b],
        quad([0.0; 3], z, x).to_vec(),
        quad([0.0, 0.0, -2.0], z, x).to_vec(),
    ]
    .concat()
}

/// Every normal met, by the sweep and by balls rolling across the junctions (pressed
/// down a little each step), is the floor's within `tol` radians.
fn t_junction<S: Tolerance>(m: Rigid, tol: f64) -> Monitor {
    let w = World::<S>::new(&t_floor(), m);
    let floor = w.normals[0];
    let (r, at) = (0.5, |p: P| back(v::<S>(m.point(p))));
    let start = at([-0.1002, 0.6, 0.7]);
    let mut mon = Monitor::new(format!("T-junction floor tol {tol:.1e}"), &w, start, r);
    let check = |mon: &mut Monitor, normals: Vec<P>| {
        for n in normals {
            let tilt = angle(n, floor);
            if tilt > tol {
                mon.fail(format!("normal {n:?} tilted {tilt:.2e} rad"));
            }
        }
    };
    match w.cast(start, at([0.0998, 0.4, 0.7]), r) {
        Some(hit) => check(&mut mon, hit_normals(&hit)),
        None => mon.fail("the issue's sweep missed the floor".into()),
    }
    let rs = S::from_f64(r);
    for (z0, dz) in [
        (0.7, 0.0),
        (0.0, 0.0),
        (-0.7, 0.0),
        (1.3, -0.013),
        (-1.3, 0.013),
    ] {
        let mut p = v::<S>(at([-1.5, r + r / 1024.0, z0]));
        let d = v::<S>(m.dir([0.05, -0.01, dz]));
        for _ in 0..60 {
            let out = w.step(p, d, rs).unwrap();
            mon.call(&w, back(p), back(out.position), back(d));
            check(&mut mon, contact_normals(&out));
            p = out.position;
        }
    }
    mon
}

#[test]
fn t_junction_f32_flat_floor_no_ghost_bump() {
    let mut all = Vec::new();
    macro_rules! each {
        ($($t:ty),*) => {$(
            // Axis-aligned, exact: the floor's normal is (0, 1, 0) exactly; allow 4 EPSILON.
            all.push(t_junction::<$t>(Rigid::IDENTITY, 4.0 * <$t>::EPSILON.to_f64()));
            // Turned: the normal as the scalar can hold it (the tolerance table's angle).
            all.push(t_junction::<$t>(Rigid::random(&mut rng(11), 5.0), <$t>::ANGLE));
        )*};
    }
    each!(f32, f64, I32F32, I16F16);
    assert_all(&all);
}

// ---- 4. Wide corners and tiny balls --------------------------------------------------------

fn corners_at<S: Tolerance>(angles: &[f64], floors: bool, steps: usize) -> Vec<Monitor> {
    let mut out = Vec::new();
    for (i, &degrees) in angles.iter().enumerate() {
        let uneven = if i % 2 == 0 { 0.5 } else { -0.5 };
        for floor in [None, Some(0.6)].into_iter().take(1 + floors as usize) {
            let m = if floors {
                Rigid::random(&mut rng(degrees as u64), 10.0)
            } else {
                Rigid::IDENTITY
            };
            let c = Corner {
                degrees,
                r: 0.5,
                push: 0.2,
                uneven,
                gap: 1.0,
                floor,
                m,
            };
            out.push(corner::<S>(&c, steps, 20));
        }
    }
    out
}

#[test]
fn wide_corner_135_degrees_comes_to_rest() {
    let mut all = corners_at::<I16F16>(&[135.0, 135.0], false, 200);
    all.extend(corners_at::<f64>(&[135.0, 135.0], false, 200));
    all.extend(corners_at::<f32>(&[135.0, 135.0], false, 200));
    all.extend(corners_at::<I32F32>(&[135.0, 135.0], false, 200));
    assert_all(&all);
}

const SWEEP: [f64; 9] = [60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0, 160.0, 170.0];

#[test]
fn corners_from_60_to_170_degrees_come_to_rest() {
    let mut all = corners_at::<I16F16>(&SWEEP, true, 200);
    all.extend(corners_at::<f64>(&SWEEP, true, 200));
    all.extend(corners_at::<f32>(&SWEEP, true, 200));
    all.extend(corners_at::<I32F32>(&SWEEP, true, 200));
    assert_all(&all);
}

/// r = 0.001 in a closed box `2 half` wide near (2048, -1843, 1946), turned: pushed into it
/// by `push` radii every step (or, with `push == 0`, rolling and kicked). Each run may end with
/// the response refusing the radius, but the centre never gets behind a wall.
fn tiny_ball<S: Tolerance>(seed: u64, half: f64, push: f64, steps: usize) -> Monitor {
    let mut g = rng(seed);
    let mut m = Rigid::random(&mut g, 0.0);
    m.shift = [2048.0, -1843.0, 1946.0];
    let w = World::<S>::new(&scenes::box_tris(half), m);
    let r = 0.001;
    let start = back(v::<S>(m.point(g.point(half - 2.0 * r))));
    let label = format!("tiny ball seed {seed} half {half} push {push}");
    let mut mon = Monitor::new(label, &w, start, r);
    mon.may_refuse = true;
    if push > 0.0 {
        let d = scale(unit(g.point(1.0)), push * r);
        push_run(&w, &mut mon, start, d, steps, |m, _, p| {
            m.behind(w.behind_convex(p))
        });
    } else {
        let gravity = [0.0, -0.05 * r, 0.0];
        roll(
            &w,
            &mut mon,
            start,
            gravity,
            0.5 * r,
            0.5,
            steps,
            &mut g,
            |p| w.behind_convex(p),
        );
    }
    mon
}

/// Seeds 0-3, and those of 200 searched on the code of commit bcb96e9 whose I16F16 ball escaped
/// (pushed 0.3 or 1 radius a step into the box's corners, centre up to 0.19 behind a wall).
const TINY_SEEDS: [u64; 9] = [0, 1, 2, 3, 19, 86, 141, 174, 180];

fn tiny_balls<S: Tolerance>(steps: usize) -> Vec<Monitor> {
    let mut out = Vec::new();
    for seed in TINY_SEEDS {
        for (half, push) in [(0.003, 0.3), (0.01, 0.3), (0.003, 1.0), (0.01, 0.0)] {
            out.push(tiny_ball::<S>(seed, half, push, steps));
        }
    }
    out
}

#[test]
fn tiny_ball_i16f16_near_range_edge_box() {
    let mut all = tiny_balls::<I16F16>(300);
    all.extend(tiny_balls::<f32>(300));
    all.extend(tiny_balls::<I32F32>(300));
    all.extend(tiny_balls::<f64>(300));
    for m in &all {
        println!("{m}");
    }
    // Only escapes count here: a refusal ends a run and is allowed (see the issue).
    let escaped: Vec<String> = all
        .iter()
        .filter(|m| m.behind > 4.0 * m.res)
        .map(|m| m.to_string())
        .collect();
    assert!(
        escaped.is_empty(),
        "{} escaped:\n{}",
        escaped.len(),
        escaped.join("\n")
    );
}

// ---- Long-run properties, every scalar -----------------------------------------------------

fn config() -> Config {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(4);
    Config {
        cases,
        max_shrink_iters: 0,
        failure_persistence: None,
        ..Config::default()
    }
}

/// The fixed triples, then random ones: (seed, size kind, corner angle in degrees).
fn property(run: impl Fn(u64, u8, f64) -> Monitor) {
    assert_all(&FIXED.map(|(s, k, d)| run(s, k, d)));
    let cases = (any::<u64>(), 0u8..3, 60.0f64..170.0);
    let result = TestRunner::new(config()).run(&cases, |(s, k, d)| {
        let m = run(s, k, d);
        prop_assert!(m.ok(), "{}", m);
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// Every property for one triple: what the long runs measure.
fn properties<S: Tolerance>(seed: u64, kind: u8, degrees: f64, steps: usize) -> Vec<Monitor> {
    vec![
        floor_rest::<S>(seed, kind, steps),
        box_push::<S>(seed, kind, steps),
        corner::<S>(&Corner::random(seed, kind, degrees, false), steps, 50),
        corner::<S>(&Corner::random(seed, kind, degrees, true), steps, 50),
        rolling::<S>(seed, kind, steps, false),
        rolling::<S>(seed, kind, steps, true),
        stairs::<S>(seed, kind, steps),
    ]
}

/// 10^5 steps of every property for the fixed triples, the creeping floors, the sinking
/// instance and the corner sweep: prints the maxima, then asserts as the short runs do.
fn long_runs<S: Tolerance>() {
    let mut all = Vec::new();
    for (s, k, d) in FIXED {
        all.extend(properties::<S>(s, k, d, LONG));
    }
    all.extend(creeping::<S>(LONG));
    all.push(sinking::<S>(LONG));
    all.extend(corners_at::<S>(&SWEEP, true, LONG / 10));
    let groups: [(&str, &[&str]); 5] = [
        ("floors", &["floor", "creeping"]),
        ("corners", &["corner", "box push"]),
        ("rolling", &["rolling"]),
        ("stairs", &["stairs"]),
        ("sinking", &["sinking"]),
    ];
    let mut lines = Vec::new();
    for (name, prefixes) in groups {
        let mut max = Maxima::default();
        for m in &all {
            let scenario = m.label.split_once(' ').map_or("", |(_, rest)| rest);
            if prefixes.iter().any(|p| scenario.starts_with(p)) {
                max.add(m);
            }
        }
        lines.push(format!("{} {name}: {max}", S::NAME));
    }
    for m in &all {
        println!("{m}");
    }
    println!("{}", lines.join("\n"));
    let failed = all.iter().filter(|m| !m.ok()).count();
    assert_eq!(
        failed,
        0,
        "{failed} of {} long runs failed (listed above)",
        all.len()
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn resting_on_a_floor_pushed_into_it() {
            property(|s, k, _| floor_rest::<$t>(s, k, STEPS));
        }
        #[test]
        fn pushed_into_the_walls_of_a_box() {
            property(|s, k, _| box_push::<$t>(s, k, STEPS));
        }
        #[test]
        fn pushed_into_a_corner_of_two_walls() {
            property(|s, k, d| corner::<$t>(&Corner::random(s, k, d, false), STEPS, 50));
        }
        #[test]
        fn pushed_into_a_three_plane_corner() {
            property(|s, k, d| corner::<$t>(&Corner::random(s, k, d, true), STEPS, 50));
        }
        #[test]
        fn rolling_in_a_closed_box() {
            property(|s, k, _| rolling::<$t>(s, k, STEPS, false));
        }
        #[test]
        fn rolling_in_a_closed_wedge() {
            property(|s, k, _| rolling::<$t>(s, k, STEPS, true));
        }
        #[test]
        fn pushed_up_and_down_stairs() {
            property(|s, k, _| stairs::<$t>(s, k, STEPS));
        }
        #[test]
        #[ignore = "10^5 steps per run: cargo test --release --test response -- --ignored --nocapture"]
        fn long_runs_report() {
            long_runs::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);

/// The box and wedge builders make closed solids facing inwards, so that the runs' "behind"
/// measure (the centre behind any face's plane) means what it says.
#[test]
fn solids_face_inwards() {
    let mut tris = wedge_tris(1.0, 6.0, 4.0);
    tris.extend(scenes::box_tris(5.0));
    let inside = [0.0, 3.0, 0.0];
    for t in tris {
        let n = common::cross(sub(t[1], t[0]), sub(t[2], t[0]));
        assert!(common::dot(sub(inside, t[0]), n) > 0.0, "{t:?}");
    }
}
