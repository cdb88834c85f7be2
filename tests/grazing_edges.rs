//! Paths that run along an edge's line at about the radius: the distance across the edge
//! barely changes, so where the ball comes within `r` of the line is decided by rounding, while
//! the vertex the path reaches is met exactly. A vertex met first must be reported, not dropped
//! behind a rounded edge contact that lands later along the edge (a shortcut that skipped the
//! vertices of an edge met did so, up to the edge's length late, in about 2 000 of 10^6 such
//! sweeps per float scalar).

#[macro_use]
mod common;

use ballcast::{Contact, StandardTriangle, Sweep, Triangle};
use common::{P, Tolerance, v};

/// The triangle, the sweep and its radius, and the first contact by exact arithmetic on these
/// inputs (each coordinate a multiple of 2^-16, so the same in every scalar).
type Case = ([P; 3], P, P, f64, Contact, f64);

const CASES: [Case; 2] = [
    // Along the line of edge 1, from (0, 0, -3) to (0, 0, -1), at exactly r beside it: vertex
    // 2 is touched after 0.5 of the path's 7.75 units.
    (
        [[1.0, 0.0, 2.0], [0.0, 0.0, -3.0], [0.0, 0.0, -1.0]],
        [-0.75, 0.0, -0.5],
        [-0.75, 0.0, -8.25],
        0.75,
        Contact::Vertex(2),
        0.5 / 7.75,
    ),
    // A general triangle passed nearly along edge 2 (found in I16F16; the first contact from
    // 60-digit arithmetic on these inputs).
    (
        [
            [-7.2339935302734375, -11.68536376953125, 22.75762939453125],
            [3.754974365234375, -24.082687377929688, 7.731781005859375],
            [6.47882080078125, -11.18408203125, -18.1697998046875],
        ],
        [9.267181396484375, -11.0697021484375, -26.618194580078125],
        [-3.702301025390625, -11.54925537109375, 12.09820556640625],
        0.040802001953125,
        Contact::Vertex(2),
        0.217_872_547_922_191_27,
    ),
];

fn a_path_along_an_edge_meets_its_vertex_first<S: Tolerance>() {
    for (tri, a, b, r, feature, exact) in CASES {
        let t = Triangle::new(v::<S>(tri[0]), v(tri[1]), v(tri[2]));
        let st = StandardTriangle::new(&t).unwrap().with_two_sided(true);
        let sweep = Sweep::new(v::<S>(a), v(b), S::from_f64(r)).unwrap();
        let hit = st.cast(&sweep).expect("met");
        assert_eq!(hit.contact, feature, "{}: {a:?} -> {b:?}", S::NAME);
        // Along the normal, where the tolerance table measures: the path barely approaches
        // the vertex, so a step of alpha moves the ball little towards it.
        let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let n = hit.normal.to_array().map(|c| c.to_f64());
        let approach = (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]).abs();
        let err = (hit.alpha.to_f64() - exact).abs() * approach;
        assert!(
            err <= S::DISTANCE,
            "{}: alpha {:?}, exact {exact}: {err:e} along the normal",
            S::NAME,
            hit.alpha
        );
    }
}

every_scalar!(a_path_along_an_edge_meets_its_vertex_first);
