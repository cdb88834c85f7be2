//! Starting inside geometry and wrong winding: the penetration query, `move_and_slide`'s
//! push-out of a starting overlap, and the winding check. Every property in every scalar;
//! expected values worked by hand.

mod common;
mod meshes;

use ballcast::{Contact, Geometry, Scalar, Scene, Triangle, move_and_slide, penetration, winding};
use common::{Tolerance, back, v};
use fixed::types::{I16F16, I32F32};

/// Pushes the quad `c` as two triangles sharing the diagonal `c[0]`–`c[2]`, facing as
/// `(c[1] - c[0]) × (c[2] - c[0])`.
fn quad<S: Scalar, const N: usize>(s: &mut Scene<S, N>, c: [[f64; 3]; 4]) {
    s.push(Triangle::new(v(c[0]), v(c[1]), v(c[2]))).unwrap();
    s.push(Triangle::new(v(c[0]), v(c[2]), v(c[3]))).unwrap();
}

/// A 20 × 20 floor at y = 0 facing +y, two triangles sharing the diagonal.
fn floor<S: Scalar, const N: usize>() -> Scene<S, N> {
    let mut s = Scene::new();
    let c = [
        [-10.0, 0.0, -10.0],
        [-10.0, 0.0, 10.0],
        [10.0, 0.0, 10.0],
        [10.0, 0.0, -10.0],
    ];
    quad(&mut s, c);
    s
}

fn near(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Tolerance for a depth or position: the heights' rounding at coordinates up to 10, with room.
fn tol<S: Tolerance>() -> f64 {
    4.0 * S::PRECISION.height_error(10.0) + 1e-9
}

/// A ball 0.2 inside a floor: depth 0.2 straight up, over the face and over the seam alike.
fn penetration_of_ball_spawned_inside_floor<S: Tolerance>() {
    let scene = floor::<S, 2>();
    let r = S::from_f64(0.5);
    for x in [3.0, 0.0, -4.0] {
        let p = penetration(&scene, v([x, 0.3, x]), r)
            .unwrap()
            .expect("overlaps");
        assert_eq!(back(p.normal), [0.0, 1.0, 0.0], "{}", S::NAME);
        assert!(
            near(p.depth.to_f64(), 0.2, tol::<S>()),
            "{}: {:?}",
            S::NAME,
            p.depth
        );
        assert!(near(back(p.point)[1], 0.0, tol::<S>()), "{}", S::NAME);
        assert_eq!(p.contact, Contact::Face);
    }
    // Touching or clear is no overlap; nor is a centre behind the one-sided floor.
    assert_eq!(penetration(&scene, v([0.0, 0.5, 0.0]), r).unwrap(), None);
    assert_eq!(penetration(&scene, v([0.0, -0.3, 0.0]), r).unwrap(), None);
}

/// Beside a floor's open edge, the push-out points from the edge to the centre.
fn penetration_at_an_open_edge_points_from_the_edge<S: Tolerance>() {
    let scene = floor::<S, 2>();
    // Centre 0.3 beyond the edge x = 10 and 0.4 above: 0.5 from the edge, r = 0.6.
    let p = penetration(&scene, v([10.3, 0.4, 2.0]), S::from_f64(0.6))
        .unwrap()
        .unwrap();
    let n = back(p.normal);
    let t = 4.0 * tol::<S>();
    assert!(
        near(n[0], 0.6, t) && near(n[1], 0.8, t) && near(n[2], 0.0, t),
        "{}: {n:?}",
        S::NAME
    );
    assert!(near(p.depth.to_f64(), 0.1, t), "{}: {:?}", S::NAME, p.depth);
    assert!(matches!(p.contact, Contact::Edge(_)), "{:?}", p.contact);
}

/// The same answer from a scene, a slice of its prepared triangles and a mesh.
fn penetration_is_the_same_for_scene_slice_and_mesh<S: Tolerance>() {
    let scene = floor::<S, 2>();
    let tris: Vec<_> = (0..2).map(|i| *scene.triangle(i).unwrap()).collect();
    let sources: Vec<_> = scene.sources().collect();
    let owned = meshes::build(&sources, ballcast::Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    for c in [
        [0.0, 0.3, 0.0],
        [9.9, 0.1, -9.9],
        [10.2, 0.2, 0.0],
        [1.0, 0.7, 1.0],
    ] {
        let r = S::from_f64(0.5);
        let a = penetration(&scene, v(c), r).unwrap();
        assert_eq!(
            penetration(tris.as_slice(), v(c), r).unwrap(),
            a,
            "{}",
            S::NAME
        );
        assert_eq!(penetration(&mesh, v(c), r).unwrap(), a, "{}", S::NAME);
    }
}

/// The case: r = 0.5 at y = 0.3 under gravity comes out in the first call, not a skin
/// per step, and then rests on the floor.
fn ball_spawned_inside_floor_comes_out_at_once<S: Tolerance>() {
    let scene = floor::<S, 2>();
    let r = S::from_f64(0.5);
    let fall = v::<S>([0.0, -9.81 / 3600.0, 0.0]);
    let out = move_and_slide(&scene, v([1.0, 0.3, 1.0]), fall, r).unwrap();
    let y = back(out.position)[1];
    assert!(y >= 0.5 - tol::<S>() && y < 0.51, "{}: y {y}", S::NAME);
    assert!(
        back(out.pushed_out)[1] > 0.19,
        "{}: {:?}",
        S::NAME,
        out.pushed_out
    );
    let mut p = out.position;
    for _ in 0..100 {
        p = move_and_slide(&scene, p, fall, r).unwrap().position;
    }
    let y = back(p)[1];
    assert!(
        y >= 0.5 - tol::<S>() && y < 0.51,
        "{}: y {y} after 100 steps",
        S::NAME
    );
}

/// Moving sideways while embedded: it comes out first, then slides with the floor as contact.
fn embedded_ball_moving_sideways_comes_out_and_slides<S: Tolerance>() {
    let scene = floor::<S, 2>();
    let r = S::from_f64(0.5);
    let out = move_and_slide(&scene, v([0.0, 0.3, 0.0]), v([1.0, -0.1, 0.0]), r).unwrap();
    let p = back(out.position);
    assert!(p[1] >= 0.5 - tol::<S>(), "{}: {p:?}", S::NAME);
    assert!(near(p[0], 1.0, 1e-3), "{}: {p:?}", S::NAME);
    assert!(
        out.contacts[0].is_some(),
        "{}: slides with a contact",
        S::NAME
    );
}

/// Pushed out under a low ceiling: the push stops a skin short of the ceiling, never into it.
fn push_out_stops_short_of_other_geometry<S: Tolerance>() {
    let mut scene = floor::<S, 4>();
    // A ceiling at y = 0.9 facing down: clockwise seen from above.
    let c = [
        [-10.0, 0.9, -10.0],
        [10.0, 0.9, 10.0],
        [-10.0, 0.9, 10.0],
        [10.0, 0.9, -10.0],
    ];
    scene
        .push(Triangle::new(v(c[0]), v(c[1]), v(c[2])))
        .unwrap();
    scene
        .push(Triangle::new(v(c[0]), v(c[3]), v(c[1])))
        .unwrap();
    let r = S::from_f64(0.5);
    let out = move_and_slide(&scene, v([0.0, 0.3, 0.0]), v([0.0, 0.0, 0.0]), r).unwrap();
    let y = back(out.position)[1];
    // Moved up, but the ball's top stays below the ceiling.
    assert!(y > 0.3 && y + 0.5 < 0.9, "{}: y {y}", S::NAME);
    let ceiling: Vec<_> = (2..4).map(|i| *scene.triangle(i).unwrap()).collect();
    assert_eq!(
        penetration(ceiling.as_slice(), out.position, r).unwrap(),
        None
    );
}

/// A floor wound clockwise (seen from above) faces down: the ball falls through it, and the
/// winding check against a point above names it.
fn wrong_winding_is_found_from_a_point_above<S: Tolerance>() {
    let mut scene: Scene<S, 4> = Scene::new();
    let c = [
        [-10.0, 0.0, -10.0],
        [-10.0, 0.0, 10.0],
        [10.0, 0.0, 10.0],
        [10.0, 0.0, -10.0],
    ];
    scene
        .push(Triangle::new(v(c[0]), v(c[1]), v(c[2])))
        .unwrap();
    scene
        .push(Triangle::new(v(c[0]), v(c[3]), v(c[2])))
        .unwrap(); // wrong way round
    let w = winding(&scene, v([0.0, 5.0, 0.0])).unwrap();
    assert_eq!(
        (w.facing, w.away, w.first_away),
        (1, 1, Some(1)),
        "{}",
        S::NAME
    );
    // Through the wrong half it falls with no contact; two-sided, it lands.
    let r = S::from_f64(0.5);
    let fall = |s: &dyn Geometry<S>| {
        move_and_slide(s, v([5.0, 1.0, -5.0]), v([0.0, -2.0, 0.0]), r).unwrap()
    };
    assert!(fall(&scene).contacts[0].is_none(), "{}", S::NAME);
    let mut fixed: Scene<S, 4> = Scene::new();
    fixed
        .push(Triangle::new(v(c[0]), v(c[1]), v(c[2])))
        .unwrap();
    fixed
        .push_two_sided(Triangle::new(v(c[0]), v(c[3]), v(c[2])))
        .unwrap();
    assert!(fall(&fixed).contacts[0].is_some(), "{}", S::NAME);
    let w = winding(&fixed, v([0.0, 5.0, 0.0])).unwrap();
    assert_eq!((w.facing, w.away, w.two_sided), (1, 0, 1), "{}", S::NAME);
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)] // the fixed-point types, unused where $t is a float
        use super::*;
        #[test] fn penetration_of_ball_spawned_inside_floor() {
            super::penetration_of_ball_spawned_inside_floor::<$t>()
        }
        #[test] fn penetration_at_an_open_edge_points_from_the_edge() {
            super::penetration_at_an_open_edge_points_from_the_edge::<$t>()
        }
        #[test] fn penetration_is_the_same_for_scene_slice_and_mesh() {
            super::penetration_is_the_same_for_scene_slice_and_mesh::<$t>()
        }
        #[test] fn ball_spawned_inside_floor_comes_out_at_once() {
            super::ball_spawned_inside_floor_comes_out_at_once::<$t>()
        }
        #[test] fn embedded_ball_moving_sideways_comes_out_and_slides() {
            super::embedded_ball_moving_sideways_comes_out_and_slides::<$t>()
        }
        #[test] fn push_out_stops_short_of_other_geometry() {
            super::push_out_stops_short_of_other_geometry::<$t>()
        }
        #[test] fn penetration_agrees_with_closest_point_oracle() {
            super::penetration_agrees_with_closest_point_oracle::<$t>()
        }
        #[test] fn push_out_of_a_corner_clears_both_faces() {
            super::push_out_of_a_corner_clears_both_faces::<$t>()
        }
        #[test] fn push_out_of_a_v_valley_clears_both_slopes() {
            super::push_out_of_a_v_valley_clears_both_slopes::<$t>()
        }
        #[test] fn push_out_of_a_floor_in_a_slot_narrower_than_the_ball() {
            super::push_out_of_a_floor_in_a_slot_narrower_than_the_ball::<$t>()
        }
        #[test] fn push_out_past_a_third_overlap_in_a_terrain() {
            super::push_out_past_a_third_overlap_in_a_terrain::<$t>()
        }
        #[test] fn push_out_of_a_pit_of_three_steep_faces() {
            super::push_out_of_a_pit_of_three_steep_faces::<$t>()
        }
        #[test] fn push_out_of_a_stair_nosing_is_short() {
            super::push_out_of_a_stair_nosing_is_short::<$t>()
        }
        #[test] fn wrong_winding_is_found_from_a_point_above() {
            super::wrong_winding_is_found_from_a_point_above::<$t>()
        }
    })*};
}
per_scalar!(f32_: f32, f64_: f64, i16f16: I16F16, i32f32: I32F32);

/// Against an independent f64 oracle (Ericson's closest point on a triangle): a ball near a
/// lone two-sided triangle overlaps it exactly when closer than its radius, by the radius less
/// that distance, pushed along the direction from the closest point, at scene scale 10.
fn penetration_agrees_with_closest_point_oracle<S: Tolerance>() {
    let mut rng = common::Rng(0x5EED);
    let slack = 4.0 * S::PRECISION.height_error(40.0) + S::DISTANCE;
    let (mut overlaps, mut checked) = (0, 0);
    while checked < 2000 {
        let c = rng.falling_case(10.0).rounded::<S>();
        let t = Triangle::new(v::<S>(c.tri[0]), v(c.tri[1]), v(c.tri[2]));
        let mut scene: Scene<S, 1> = Scene::new();
        if scene.push_two_sided(t).is_err() {
            continue;
        }
        checked += 1;
        let centre = common::add(c.tri[0], rng.point(3.0));
        let centre = back(v::<S>(centre));
        let r = S::from_f64(rng.range(0.5, 3.0));
        let q = common::closest_on_triangle(centre, c.tri);
        let d = common::norm(common::sub(centre, q));
        let got = penetration(&scene, v(centre), r).unwrap();
        let expected = r.to_f64() - d;
        match got {
            None => assert!(
                expected <= slack,
                "{}: missed depth {expected} at {centre:?} {c:?}",
                S::NAME
            ),
            Some(p) => {
                overlaps += 1;
                let depth = p.depth.to_f64();
                assert!(
                    (depth - expected).abs() <= slack,
                    "{}: depth {depth}, oracle {expected}",
                    S::NAME
                );
                if d > 1e-2 {
                    let n = common::scale(common::sub(centre, q), 1.0 / d);
                    let a = common::angle(back(p.normal), n);
                    assert!(
                        a <= 1e-2,
                        "{}: normal off by {a} rad at {centre:?}",
                        S::NAME
                    );
                }
            }
        }
    }
    assert!(overlaps > 200, "{}: only {overlaps} overlaps", S::NAME);
}

/// Embedded in a corner (floor y = 0 facing up, wall x = 0 facing +x), anywhere: one call with
/// no motion leaves it overlapping neither by more than a skin and rounding, and never deeper
/// into anything than it started.
fn push_out_of_a_corner_clears_both_faces<S: Tolerance>() {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    let mut scene: Scene<S, 4> = floor::<S, 4>();
    let w = [
        [0.0, -10.0, -10.0],
        [0.0, 10.0, -10.0],
        [0.0, 10.0, 10.0],
        [0.0, -10.0, 10.0],
    ];
    quad(&mut scene, w);
    let r = S::from_f64(0.5);
    let cases = (0.05..1.0f64, 0.05..1.0f64, -5.0..5.0f64);
    TestRunner::new(Config::with_cases(200))
        .run(&cases, |(x, y, z)| {
            let c = v::<S>([x, y, z]);
            let before = penetration(&scene, c, r)
                .unwrap()
                .map_or(0.0, |p| p.depth.to_f64());
            let out = move_and_slide(&scene, c, v([0.0; 3]), r).unwrap();
            let after = penetration(&scene, out.position, r).unwrap();
            let left = after.map_or(0.0, |p| p.depth.to_f64());
            let allowed = ballcast::slide::skin(r, S::from_f64(10.0)).to_f64() + tol::<S>();
            prop_assert!(
                left <= allowed,
                "{}: {c:?} left {left} (from {before})",
                S::NAME
            );
            Ok(())
        })
        .unwrap();
}

/// Embedded in a V valley of apex angle 20° to 150° (two slopes along z meeting at y = 0),
/// anywhere above both slopes and overlapping at least one: one call with no motion leaves it
/// overlapping neither by more than a skin and rounding. Pushing along the deepest slope's
/// normal alone runs into the other slope in an acute valley, a little further each call.
fn push_out_of_a_v_valley_clears_both_slopes<S: Tolerance>() {
    let mut rng = common::Rng(0xACE7);
    let r = 0.5;
    let allowed = ballcast::slide::skin(S::from_f64(r), S::from_f64(10.0)).to_f64() + tol::<S>();
    for apex in [20.0f64, 30.0, 40.0, 60.0, 90.0, 150.0] {
        let (s, c) = (apex.to_radians() / 2.0).sin_cos();
        // Each slope runs 10 up from the apex; its front faces into the valley.
        let up = [[-s * 10.0, c * 10.0, 0.0], [s * 10.0, c * 10.0, 0.0]];
        let along = [0.0, 0.0, 20.0];
        let mut scene: Scene<S, 4> = Scene::new();
        for (k, u) in up.iter().enumerate() {
            let o = [0.0, 0.0, -10.0];
            let (a, b) = if k == 0 { (*u, along) } else { (along, *u) };
            let (oa, ob) = (common::add(o, a), common::add(o, b));
            quad(&mut scene, [o, oa, common::add(oa, b), ob]);
        }
        let normals = [[c, s, 0.0], [-c, s, 0.0]];
        let mut tried = 0;
        while tried < 200 {
            let p = [
                rng.range(-2.0, 2.0),
                rng.range(0.0, 3.0),
                rng.range(-2.0, 2.0),
            ];
            let d = normals.map(|n| common::dot(n, p));
            if d.iter().any(|&d| d < 0.02) || d.iter().all(|&d| d >= r) {
                continue;
            }
            tried += 1;
            let centre = v::<S>(p);
            let before = penetration(&scene, centre, S::from_f64(r)).unwrap();
            assert!(
                before.is_some(),
                "{}: apex {apex}° at {p:?} overlaps",
                S::NAME
            );
            let out = move_and_slide(&scene, centre, v([0.0; 3]), S::from_f64(r)).unwrap();
            let after = penetration(&scene, out.position, S::from_f64(r)).unwrap();
            let left = after.map_or(0.0, |p| p.depth.to_f64());
            assert!(
                left <= allowed,
                "{}: apex {apex}° at {p:?} (distances {d:?}) left {left}",
                S::NAME
            );
        }
    }
}

/// Pushed out of a floor between two walls closer than the ball's diameter (x = ±0.45, r 0.5):
/// the push out of the floor meeting the nearer wall as well runs at once into the other
/// wall, so the push straight up is taken instead; one call lifts the ball out of the floor,
/// leaving only the overlap with the walls that no position avoids.
fn push_out_of_a_floor_in_a_slot_narrower_than_the_ball<S: Tolerance>() {
    let mut scene: Scene<S, 8> = floor::<S, 8>();
    let h = 0.45;
    let walls = [
        [
            [-h, -1.0, -10.0],
            [-h, 6.0, -10.0],
            [-h, 6.0, 10.0],
            [-h, -1.0, 10.0],
        ],
        [
            [h, -1.0, -10.0],
            [h, -1.0, 10.0],
            [h, 6.0, 10.0],
            [h, 6.0, -10.0],
        ],
    ];
    for w in walls {
        quad(&mut scene, w);
    }
    let r = S::from_f64(0.5);
    let floor: Vec<_> = (0..2).map(|i| *scene.triangle(i).unwrap()).collect();
    for x in [0.0, -0.02] {
        let out = move_and_slide(&scene, v([x, 0.1, 0.0]), v([0.0; 3]), r).unwrap();
        let left = penetration(floor.as_slice(), out.position, r).unwrap();
        assert_eq!(left, None, "{}: from x {x}, at {:?}", S::NAME, out.position);
    }
}

/// Four triangles of a bumpy terrain around a ball 0.83 deep (one-sided, fronts up): the push
/// meeting the deepest overlap and the one it fails most is stopped by a third; the deepest's
/// own push gets through, and one call clears the ball.
fn push_out_past_a_third_overlap_in_a_terrain<S: Tolerance>() {
    let tris = [
        [
            [4.0, 0.132476806640625, 3.0],
            [4.0, -0.551605224609375, 4.0],
            [5.0, 0.607330322265625, 4.0],
        ],
        [
            [4.0, -0.1515655517578125, 5.0],
            [4.0, 4.57763671875e-5, 6.0],
            [5.0, -0.2940826416015625, 5.0],
        ],
        [
            [4.0, 4.57763671875e-5, 6.0],
            [5.0, -0.1598358154296875, 6.0],
            [5.0, -0.2940826416015625, 5.0],
        ],
        [
            [5.0, 0.607330322265625, 4.0],
            [5.0, -0.2940826416015625, 5.0],
            [6.0, 0.4152679443359375, 4.0],
        ],
    ];
    let mut scene: Scene<S, 4> = Scene::new();
    for t in tris {
        scene
            .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
            .unwrap();
    }
    let r = S::from_f64(0.8587188720703125);
    let c = v::<S>([4.6788482666015625, -0.2072601318359375, 5.0576934814453125]);
    let before = penetration(&scene, c, r)
        .unwrap()
        .map_or(0.0, |p| p.depth.to_f64());
    assert!(before > 0.8, "{}: starts {before} deep", S::NAME);
    let out = move_and_slide(&scene, c, v([0.0; 3]), r).unwrap();
    let left = penetration(&scene, out.position, r).unwrap();
    let allowed = ballcast::slide::skin(r, S::from_f64(10.0)).to_f64() + tol::<S>();
    let left = left.map_or(0.0, |p| p.depth.to_f64());
    assert!(left <= allowed, "{}: left {left} deep", S::NAME);
}

/// Embedded at the bottom of a pit of three faces tilted 50° to 70° from level, meeting at the
/// origin: one call with no motion clears all three. The push out of two of them runs into
/// the third, and pushing out of one at a time took up to 190 calls.
fn push_out_of_a_pit_of_three_steep_faces<S: Tolerance>() {
    let mut rng = common::Rng(0x717);
    let r = 0.5;
    let allowed = ballcast::slide::skin(S::from_f64(r), S::from_f64(10.0)).to_f64() + tol::<S>();
    for tilt in [50.0f64, 60.0, 70.0] {
        let (s, c) = tilt.to_radians().sin_cos();
        let normals: Vec<[f64; 3]> = (0..3)
            .map(|k| {
                let a = f64::from(k) * 2.0 * std::f64::consts::PI / 3.0;
                [-s * a.cos(), c, -s * a.sin()]
            })
            .collect();
        let mut scene: Scene<S, 4> = Scene::new();
        for n in &normals {
            // A triangle of radius 10 about the origin in the plane, wound to face along `n`.
            let a = common::scale(common::cross(*n, [0.0, 1.0, 0.0]), 1.0 / s);
            let b = common::cross(*n, a);
            let at = |u: f64, w: f64| common::add(common::scale(a, u), common::scale(b, w));
            let t = [at(10.0, 0.0), at(-5.0, 8.66), at(-5.0, -8.66)];
            let front = common::cross(common::sub(t[1], t[0]), common::sub(t[2], t[0]));
            let t = if common::dot(front, *n) > 0.0 {
                t
            } else {
                [t[0], t[2], t[1]]
            };
            scene
                .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
        let mut tried = 0;
        while tried < 100 {
            let p = [
                rng.range(-0.3, 0.3),
                rng.range(0.0, 1.5),
                rng.range(-0.3, 0.3),
            ];
            let d = normals
                .iter()
                .map(|n| common::dot(*n, p))
                .collect::<Vec<_>>();
            if d.iter().any(|&d| d < 0.02) || d.iter().filter(|&&d| d < r).count() < 3 {
                continue;
            }
            tried += 1;
            let out = move_and_slide(&scene, v::<S>(p), v([0.0; 3]), S::from_f64(r)).unwrap();
            let after = penetration(&scene, out.position, S::from_f64(r)).unwrap();
            let left = after.map_or(0.0, |p| p.depth.to_f64());
            assert!(
                left <= allowed,
                "{}: tilt {tilt}° at {p:?} (distances {d:?}) left {left}",
                S::NAME
            );
        }
    }
}

/// Overlapping a stair's nosing by 0.11 from above and in front: pushed up out of it, about
/// 0.13, not along a riser's plane as well. Beside the riser, next to the inactive diagonal of
/// its quad, the riser's whole plane stood in for its nosing, and the push met that too
/// (0.41 long, 0.39 of it back along -x).
fn push_out_of_a_stair_nosing_is_short<S: Tolerance>() {
    let mut scene: Scene<S, 16> = Scene::new();
    let (w, rise) = (0.4, 0.25);
    quad(
        &mut scene,
        [
            [-5.0, 0.0, -5.0],
            [-5.0, 0.0, 5.0],
            [0.0, 0.0, 5.0],
            [0.0, 0.0, -5.0],
        ],
    );
    for k in 0..2 {
        let (x, y) = (w * f64::from(k), rise * f64::from(k));
        let (x1, y1) = (x + w, y + rise);
        quad(
            &mut scene,
            [[x, y, -5.0], [x, y, 5.0], [x, y1, 5.0], [x, y1, -5.0]],
        );
        quad(
            &mut scene,
            [[x, y1, -5.0], [x, y1, 5.0], [x1, y1, 5.0], [x1, y1, -5.0]],
        );
    }
    let r = S::from_f64(0.499);
    let c = v::<S>([-0.1113, 0.6238, 0.3132]);
    let before = penetration(&scene, c, r)
        .unwrap()
        .map_or(0.0, |p| p.depth.to_f64());
    assert!(before > 0.1, "{}: starts {before} deep", S::NAME);
    let out = move_and_slide(&scene, c, v([0.0, -9.81 / 3600.0, 0.0]), r).unwrap();
    let pushed = back(out.pushed_out);
    let len = common::norm(pushed);
    assert!(
        len < 0.2 && pushed[0].abs() < 0.05,
        "{}: pushed {pushed:?}",
        S::NAME
    );
    let left = penetration(&scene, out.position, r).unwrap();
    assert_eq!(left, None, "{}: at {:?}", S::NAME, out.position);
}
