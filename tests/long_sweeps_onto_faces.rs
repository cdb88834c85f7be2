//! A long sweep that lands on a face just inside one of its edges is met there in every scalar.
//! The face test finds where the centre reaches height `r` from alpha as rounded, which carries
//! half a step of alpha times the path's run along the plane: in `I16F16` 0.011 on a run of
//! 1 442, more than a small ball's radius. That point fell outside the face, the edge test
//! (rightly) found no contact with the edge, and the ball went through the plane (a trial of
//! the planner: a ball of 0.01 thrown 2 000 units across a level ended 0.7 under a terrain that
//! `f64`, `f32` and `I32F32` stopped it on).

mod common;

use ballcast::{Contact, Scalar, StandardTriangle, Sweep, Triangle};
use common::{P, Rng};
use fixed::types::{I16F16, I32F32};

/// The lone cast of `tri` by a ball of `r` from `p0` to `p1`, in `S`: alpha and the feature.
fn cast<S: Scalar>(tri: [P; 3], p0: P, p1: P, r: f64) -> Option<(f64, Contact)> {
    let [a, b, c] = tri.map(common::v::<S>);
    let st = StandardTriangle::new(&Triangle::new(a, b, c)).ok()?;
    let s = Sweep::new(common::v(p0), common::v(p1), S::from_f64(r)).ok()?;
    st.cast(&s).map(|h| (h.alpha.to_f64(), h.contact))
}

/// The trial's case, in `I16F16`: the face at alpha 0.99949 (`f64`), 0.7 before the path's end
/// along the normal.
#[test]
fn a_long_i16f16_sweep_landing_just_inside_an_edge() {
    let tri = [
        [888.0, -499.546875, -894.0],
        [888.0, -499.875, -893.0],
        [889.0, -499.71875, -893.0],
    ];
    let p0 = [-405.2669372558594, 351.2915954589844, 371.5353698730469];
    let p1 = [888.7699737548828, -500.28228759765625, -893.6485595703125];
    let exact = cast::<f64>(tri, p0, p1, 0.01).unwrap();
    assert_eq!(exact.1, Contact::Face);
    let (alpha, contact) = cast::<I16F16>(tri, p0, p1, 0.01).expect("met, as in f64");
    assert_eq!(contact, Contact::Face);
    // Within the planner's figure for the path (half a step of alpha over about 2 000).
    let path = common::norm(common::sub(p1, p0));
    let predicted = I16F16::PRECISION.distance_error(1000.0, path) / path;
    assert!(
        (alpha - exact.0).abs() <= predicted,
        "{alpha} against {}",
        exact.0
    );
}

/// Long sweeps (up to 2 000) from far off onto lone triangles about 1 across near the extent,
/// aimed at points up to 0.03 inside an edge, balls of 0.01 to 0.05: wherever `f64` meets the
/// triangle with more of the path left than the planner's figure, every scalar meets it too.
fn met_like_f64<S: Scalar>() {
    let mut rng = Rng(0x10C5);
    let mut missed = vec![];
    let mut cases = 0;
    for _ in 0..20_000 {
        let o = [
            rng.range(880.0, 890.0),
            rng.range(-500.0, -490.0),
            rng.range(-895.0, -885.0),
        ];
        let tri = [
            o,
            common::add(o, [rng.range(-0.2, 0.2), rng.range(-0.5, 0.5), 1.0]),
            common::add(o, [1.0, rng.range(-0.5, 0.5), rng.range(-0.2, 0.2)]),
        ];
        // A point of edge v1-v2, moved up to 0.03 towards v0 (into the face).
        let t = rng.range(0.1, 0.9);
        let on = common::add(tri[1], common::scale(common::sub(tri[2], tri[1]), t));
        let inward = common::sub(tri[0], on);
        let target = common::add(
            on,
            common::scale(inward, rng.range(0.0, 0.03) / common::norm(inward)),
        );
        let n = common::cross(common::sub(tri[1], tri[0]), common::sub(tri[2], tri[0]));
        let n = common::scale(n, 1.0 / common::norm(n));
        let r = rng.range(0.01, 0.05);
        // From up to 1 000 away, above the plane; on past the target by up to 1 along the path.
        let from = [
            rng.range(-900.0, 0.0),
            rng.range(-300.0, 400.0),
            rng.range(-200.0, 900.0),
        ];
        let goal = common::add(target, common::scale(n, r));
        let d = common::sub(goal, from);
        let p1 = common::add(
            goal,
            common::scale(d, rng.range(0.0, 1.0) / common::norm(d)),
        );
        if common::dot(common::sub(from, tri[0]), n) <= 2.0 * r {
            continue;
        }
        let path = common::norm(common::sub(p1, from));
        let Some((a, _)) = cast::<f64>(tri, from, p1, r) else {
            continue;
        };
        // What is left of the path along the normal at f64's contact: a miss is off by that.
        let left = (1.0 - a) * common::dot(common::sub(p1, from), n).abs();
        if left <= 4.0 * S::PRECISION.distance_error(1000.0, path) {
            continue;
        }
        cases += 1;
        if cast::<S>(tri, from, p1, r).is_none() {
            missed.push((tri, from, p1, r, left));
        }
    }
    assert!(cases > 5_000, "{cases}");
    assert!(
        missed.is_empty(),
        "{}: {} of {cases} missed, e.g. {:?}",
        S::PRECISION.scalar,
        missed.len(),
        missed.first()
    );
}

#[test]
fn long_sweeps_onto_faces_near_edges_are_met_f32() {
    met_like_f64::<f32>();
}

#[test]
fn long_sweeps_onto_faces_near_edges_are_met_i32f32() {
    met_like_f64::<I32F32>();
}

#[test]
fn long_sweeps_onto_faces_near_edges_are_met_i16f16() {
    met_like_f64::<I16F16>();
}
