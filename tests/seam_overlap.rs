//! `penetration` beside a seam (an inactive edge between coplanar triangles): the face's normal
//! stands in for the edge's, and the depth is what clears the triangle along it. (The plane's
//! depth once stood in too, which beyond the seam overstated the overlap: a ball beside the top
//! of a stair's riser, 0.036 into its top edge, was reported 0.108 deep.) Every property in
//! every scalar.

mod common;

use ballcast::{Contact, Scene, Triangle, penetration::penetration};
use common::{P, Rng, Tolerance, back, v};
use fixed::types::{I16F16, I32F32};

/// A quad of two triangles, `o`, `o + a`, `o + a + b`, `o + b` (front along `a × b`), in a scene.
fn quad<S: Tolerance>(o: P, a: P, b: P) -> (Scene<S, 2>, [[P; 3]; 2]) {
    let mut s = Scene::new();
    let tris = common::quad(o, a, b);
    for t in tris {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    (s, tris)
}

/// A review's case: a riser 0.1 high and 20 long, facing -x, its diagonal a seam; a ball of
/// 0.35 beside its top edge and 0.2 above it: 0.036 into the top edge, as f64 measures it.
fn beside_a_riser_the_top_edge_is_deepest<S: Tolerance>() {
    let (scene, tris) = quad::<S>([0.0, 0.0, -10.0], [0.0, 0.0, 20.0], [0.0, 0.1, 0.0]);
    let (c, r) = ([-0.2417, 0.3, 0.0], 0.35);
    let p = penetration(&scene, v(c), S::from_f64(r))
        .unwrap()
        .expect("overlaps");
    let d = tris
        .iter()
        .map(|&t| common::norm(common::sub(c, common::closest_on_triangle(c, t))))
        .fold(f64::MAX, f64::min);
    let slack = 4.0 * S::PRECISION.height_error(10.0);
    let depth = p.depth.to_f64();
    assert!(
        (depth - (r - d)).abs() <= slack,
        "{}: depth {depth}, oracle {}",
        S::NAME,
        r - d
    );
    assert!(
        matches!(p.contact, Contact::Edge(_)),
        "{}: {:?}",
        S::NAME,
        p.contact
    );
}

/// Balls in front of a quad tilted off the axes, anywhere within a radius of it: an overlap is
/// reported exactly where the ball is closer to the quad than its radius (Ericson's closest
/// point, in `f64`), at least as deep as that, and moving the centre by `normal * depth` leaves
/// it touching the triangle named (beside the seam, the face's normal: the depth along it is
/// more than the radius less the distance, the plane's depth more still).
fn moving_out_by_the_depth_leaves_it_touching<S: Tolerance>() {
    let (o, a, b) = ([1.0, -2.0, 0.5], [3.0, 0.4, -1.0], [0.5, 0.3, 2.5]);
    let (scene, tris) = quad::<S>(o, a, b);
    let n = common::cross(a, b);
    let n = common::scale(n, 1.0 / common::norm(n));
    let mut rng = Rng(0x5EA3);
    let slack = 4.0 * S::PRECISION.height_error(10.0) + S::DISTANCE;
    let distance =
        |c: P, t: [P; 3]| common::norm(common::sub(c, common::closest_on_triangle(c, t)));
    let (mut overlaps, mut seams) = (0, 0);
    for _ in 0..4000 {
        let r = rng.range(0.2, 1.5);
        let along = common::add(
            common::scale(a, rng.range(-0.4, 1.4)),
            common::scale(b, rng.range(-0.4, 1.4)),
        );
        let c = back(v::<S>(common::add(
            common::add(o, along),
            common::scale(n, rng.range(0.01, r)),
        )));
        let d = tris
            .iter()
            .map(|&t| distance(c, t))
            .fold(f64::MAX, f64::min);
        let r = S::from_f64(r).to_f64();
        let what = format!("{} at {c:?}, r {r}", S::NAME);
        let Some(p) = penetration(&scene, v(c), S::from_f64(r)).unwrap() else {
            assert!(r - d <= slack, "{what}: missed {}", r - d);
            continue;
        };
        overlaps += 1;
        let depth = p.depth.to_f64();
        assert!(depth >= r - d - slack, "{what}: depth {depth} < {}", r - d);
        let out = common::add(c, common::scale(back(p.normal), depth));
        let left = distance(out, tris[p.index]);
        assert!(
            (left - r).abs() <= slack,
            "{what}: {left} from the triangle after the push"
        );
        seams += (depth > r - d + 1e-3) as usize;
    }
    assert!(
        overlaps > 1000 && seams > 5,
        "{}: {overlaps} overlaps, {seams} by seams",
        S::NAME
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn beside_a_riser() {
            beside_a_riser_the_top_edge_is_deepest::<$t>();
        }
        #[test]
        fn moving_out_by_the_depth() {
            moving_out_by_the_depth_leaves_it_touching::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
