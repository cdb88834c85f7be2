//! Two-sided triangles stop balls either way, at their edges and vertices too: a ball that
//! crosses the plane beside a two-sided wall and then reaches its edge or corner from the other
//! side touches it. An f64 check against the distance oracle along the path, and the cases a
//! game trial found, in every scalar.

mod common;

use ballcast::{Scalar, Scene, StandardTriangle, Sweep, Triangle};
use common::{Case, P, Rng, Tolerance, add, distance_to_triangle, v};
use fixed::types::{I16F16, I32F32};

/// A two-sided 4 × 4 wall in the plane x = 0, |y| <= 2, |z| <= 2: a fence panel.
fn panel<S: Scalar>() -> Scene<S, 2> {
    let c = [
        [0.0, -2.0, -2.0],
        [0.0, 2.0, -2.0],
        [0.0, 2.0, 2.0],
        [0.0, -2.0, 2.0],
    ];
    let mut s = Scene::new();
    s.push_two_sided(Triangle::new(v(c[0]), v(c[1]), v(c[2])))
        .unwrap();
    s.push_two_sided(Triangle::new(v(c[0]), v(c[2]), v(c[3])))
        .unwrap();
    s
}

/// The walls of the trial, with r = 0.5: a step that grazes the plane beyond the top corner
/// (x = 0.000555, beyond z = 2) and ends 0.41 from the corner, and a step up from below the
/// panel, crossing its plane beneath it, that ends 0.2 behind its bottom edge. Both passed into
/// the wall; the same bottom-edge path with a shallower crossing was caught.
fn crossing_the_plane_beside_a_two_sided_wall<S: Tolerance>() {
    let scene = panel::<S>();
    let r = 0.5;
    let steps: [(P, P); 3] = [
        ([0.000555, 1.96265, 2.50214], [-0.0510, 0.1592, -0.1164]),
        ([-0.1, -5.0, 0.0], [0.3, 6.0, 0.0]),
        ([-0.1, -5.0, 0.0], [0.2, 6.0, 0.0]),
    ];
    for (p0, d) in steps {
        let s = Sweep::new(v::<S>(p0), v(add(p0, d)), S::from_f64(r)).unwrap();
        assert!(
            scene.cast(&s).is_some(),
            "{}: passed into the wall from {p0:?} by {d:?}",
            S::NAME
        );
    }
}

/// Grazing contacts a rounding step beyond r, near the edge of the triangle's box: a `Scene`
/// must report what its triangle reports (it dropped these in `I16F16`, its box test allowing
/// for no rounding).
fn a_scene_keeps_a_grazing_contact_beside_its_box<S: Tolerance>() {
    let cases: [([P; 3], P, P, f64); 2] = [
        (
            [
                [-5.0, -0.27184620762230277, 4.0],
                [-5.0, -0.041501171734483644, 5.0],
                [-4.0, 0.6211411670526762, 5.0],
            ],
            [-5.381487792402268, -10.00764403025049, 9.593277817941825],
            [-5.381487792402268, 3.8712349619827333, 1.6197734971422562],
            0.38147109136043333,
        ),
        (
            [
                [3.0, 0.8403562517349514, 2.0],
                [3.0, -0.2635905132049068, 3.0],
                [4.0, 0.6263185920850143, 3.0],
            ],
            [4.758863809880672, 18.951080471170595, 0.0961400157950183],
            [4.758863809880672, -1.5572977646568673, 3.34602993485199],
            0.758843517005393,
        ),
    ];
    for (t, p0, p1, r) in cases {
        let tri = Triangle::new(v::<S>(t[0]), v(t[1]), v(t[2]));
        let mut scene: Scene<S, 1> = Scene::new();
        scene.push_two_sided(tri).unwrap();
        let s = Sweep::new(v(p0), v(p1), S::from_f64(r)).unwrap();
        let alone = StandardTriangle::new(&tri)
            .unwrap()
            .with_two_sided(true)
            .cast(&s);
        let got = scene.cast(&s);
        assert_eq!(
            got.map(|h| (h.alpha, h.contact)),
            alone.map(|h| (h.alpha, h.contact)),
            "{}",
            S::NAME
        );
    }
}

/// Random sweeps (half of them falling past a triangle's plane) at random triangles, in f64,
/// each cast by `cast` (which gives the prepared triangle and the contact's alpha, or `None`
/// to pass the triangle over): the centre stays at least r from the whole triangle up to the
/// reported alpha, and is r from it there. Starts within r are left to
/// `tests/start_overlap.rs`. Returns the hits, those touched from the side the centre did not
/// start on, and those that started behind the triangle.
fn against_distance_oracle(
    seed: u64,
    count: usize,
    cast: impl Fn(Triangle<f64>, &Sweep<f64>) -> Option<(StandardTriangle<f64>, Option<f64>)>,
) -> (usize, usize, usize) {
    let mut rng = Rng(seed);
    let (mut hits, mut crossing, mut behind) = (0, 0, 0);
    for i in 0..count {
        let c: Case = if i % 2 == 0 {
            rng.case(10.0)
        } else {
            rng.falling_case(10.0)
        };
        if distance_to_triangle(c.p0, c.tri) < c.r {
            continue;
        }
        let [a, b, t] = c.tri.map(v::<f64>);
        let sweep = Sweep::new(v(c.p0), v(c.p1), c.r).unwrap();
        let Some((st, hit)) = cast(Triangle::new(a, b, t), &sweep) else {
            continue;
        };
        let end = hit.unwrap_or(1.0);
        for k in 0..=64 {
            let t = end * k as f64 / 64.0;
            let d = distance_to_triangle(c.at(t), c.tri);
            assert!(d >= c.r - 1e-9, "missed contact at {t}: {d} in {c:?}");
        }
        if let Some(alpha) = hit {
            hits += 1;
            let d = distance_to_triangle(c.at(alpha), c.tri);
            assert!((d - c.r).abs() <= 1e-9, "distance {d} at contact in {c:?}");
            let side = |p: P| st.to_standard(v(p)).unwrap().y;
            crossing += (side(c.p0) * side(c.at(alpha)) < 0.0) as usize;
            behind += (side(c.p0) < 0.0) as usize;
        }
    }
    (hits, crossing, behind)
}

/// Two-sided triangles against the distance oracle: balls met from either side, a few at an
/// edge or vertex from the side they did not start on.
#[test]
fn two_sided_f64_cast_matches_distance_oracle() {
    let (hits, crossing, _) = against_distance_oracle(23, 100_000, |t, sweep| {
        let st = StandardTriangle::new(&t).ok()?.with_two_sided(true);
        Some((st, st.cast(sweep).map(|h| h.alpha)))
    });
    assert!(
        hits > 5_000 && crossing > 10,
        "{hits} hits, {crossing} from the far side"
    );
}

/// A two-sided triangle in a `Mesh` (`Mesh::build_sided`) against the distance oracle, from
/// either side. Before `build_sided` a mesh's triangles were one-sided only, and a triangle
/// added a second time reversed missed balls that pass its plane beside it and come back at an
/// edge from behind (this seed's first: a triangle about (4, -5, 7), (0.6, -3.7, 1.6),
/// (-7.7, -0.2, -0.9) and r 1.41).
#[test]
fn a_two_sided_triangle_in_a_mesh_matches_distance_oracle() {
    use ballcast::{Degenerates, Mesh, Node, bvh::nodes_for};
    let (hits, _, behind) = against_distance_oracle(29, 20_000, |t, sweep| {
        let (mut nodes, mut tris) = ([Node::default(); nodes_for(1)], [Mesh::filler(); 1]);
        let (mut order, mut scratch) = ([0u32; 1], [0u64; 6]);
        let (refuse, both) = (Degenerates::Refuse, |_| true);
        let (mesh, _) = Mesh::build_sided(
            &[t],
            both,
            refuse,
            &mut nodes,
            &mut tris,
            &mut order,
            &mut scratch,
        )
        .ok()?;
        Some((mesh.triangles()[0], mesh.cast(sweep).map(|h| h.alpha)))
    });
    assert!(
        hits > 1_000 && behind > 100,
        "{hits} hits, {behind} from behind"
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn a_scene_keeps_a_grazing_contact_beside_its_box() {
            super::a_scene_keeps_a_grazing_contact_beside_its_box::<$t>()
        }
        #[test]
        fn crossing_the_plane_beside_a_two_sided_wall() {
            super::crossing_the_plane_beside_a_two_sided_wall::<$t>()
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
