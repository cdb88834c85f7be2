//! Hand-worked cases of the seed's face test, one per branch, on the standard triangle
//! v0 = (0,0,0), v1 = (1,0,4), v2 = (4,0,0); then the same cases after cyclic relabelling of the
//! vertices and after random rigid transforms. All hand values are dyadic, so exact in every
//! scalar.

mod common;

use ballcast::{Scalar, StandardSweep, StandardTriangle, Triangle, standard_face};
use common::{P, Tolerance, angle, back, v};
use fixed::types::{I16F16, I32F32};
use proptest::prelude::*;

const TRI: [P; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 4.0], [4.0, 0.0, 0.0]];

/// One hand-worked case: path, radius, the expected alpha, and whether it lies exactly on a
/// decision boundary (then rounding after a transform may decide either way).
struct Seed {
    name: &'static str,
    p0: P,
    p1: P,
    r: f64,
    alpha: Option<f64>,
    boundary: bool,
}

const fn seed(
    name: &'static str,
    p0: P,
    p1: P,
    r: f64,
    alpha: Option<f64>,
    boundary: bool,
) -> Seed {
    Seed {
        name,
        p0,
        p1,
        r,
        alpha,
        boundary,
    }
}

/// y0 = 5, y1 = -3, r = 1 gives beta = (1 - 5) / (-3 - 5) = 1/2 unless stated otherwise.
const SEEDS: [Seed; 16] = [
    seed(
        "falls_straight_onto_interior",
        [2.0, 5.0, 1.0],
        [2.0, -3.0, 1.0],
        1.0,
        Some(0.5),
        false,
    ),
    // q = (1, 1, 1) + 1/2 (2, -8, 2) = (2, -3, 2) → q' = (2, 0, 2), inside.
    seed(
        "falls_obliquely_onto_interior",
        [1.0, 5.0, 1.0],
        [3.0, -3.0, 3.0],
        1.0,
        Some(0.5),
        false,
    ),
    seed(
        "starts_below_radius",
        [2.0, 0.5, 1.0],
        [2.0, -3.0, 1.0],
        1.0,
        None,
        false,
    ),
    seed(
        "starts_behind_the_face",
        [2.0, -2.0, 1.0],
        [2.0, -5.0, 1.0],
        1.0,
        None,
        false,
    ),
    seed(
        "moves_parallel_to_the_face",
        [2.0, 3.0, 1.0],
        [3.0, 3.0, 1.0],
        1.0,
        None,
        false,
    ),
    seed(
        "moves_away_from_the_front",
        [2.0, 2.0, 1.0],
        [2.0, 6.0, 1.0],
        1.0,
        None,
        false,
    ),
    seed(
        "touching_and_moving_away",
        [2.0, 1.0, 1.0],
        [2.0, 6.0, 1.0],
        1.0,
        None,
        true,
    ),
    // q' = (2, 0, -1): beyond edge v0-v2 (z < 0).
    seed(
        "outside_edge_v0_v2",
        [2.0, 5.0, -1.0],
        [2.0, -3.0, -1.0],
        1.0,
        None,
        false,
    ),
    // q' = (0.25, 0, 2): beyond edge v0-v1 (z1 x - x1 z = 1 - 2 < 0).
    seed(
        "outside_edge_v0_v1",
        [0.25, 5.0, 2.0],
        [0.25, -3.0, 2.0],
        1.0,
        None,
        false,
    ),
    // q' = (3.5, 0, 2): beyond edge v1-v2 ((x1 - x2) z - z1 (x - x2) = -6 + 2 < 0).
    seed(
        "outside_edge_v1_v2",
        [3.5, 5.0, 2.0],
        [3.5, -3.0, 2.0],
        1.0,
        None,
        false,
    ),
    // Ends at height 1.5 > r: beta = 4/3.5 > 1.
    seed(
        "stops_short_beta_above_one",
        [2.0, 5.0, 1.0],
        [2.0, 1.5, 1.0],
        1.0,
        None,
        false,
    ),
    // Ends exactly touching: beta = 1 is not a hit (0 <= beta < 1).
    seed(
        "ends_exactly_touching_beta_one",
        [2.0, 5.0, 1.0],
        [2.0, 1.0, 1.0],
        1.0,
        None,
        true,
    ),
    seed(
        "touching_at_the_start",
        [2.0, 1.0, 1.0],
        [2.0, -3.0, 1.0],
        1.0,
        Some(0.0),
        true,
    ),
    seed(
        "lands_on_edge_v0_v2",
        [2.0, 5.0, 0.0],
        [2.0, -3.0, 0.0],
        1.0,
        Some(0.5),
        true,
    ),
    // (2.5, 0, 2) is the midpoint of v1-v2.
    seed(
        "lands_on_edge_v1_v2",
        [2.5, 5.0, 2.0],
        [2.5, -3.0, 2.0],
        1.0,
        Some(0.5),
        true,
    ),
    seed(
        "lands_on_vertex_v1",
        [1.0, 5.0, 4.0],
        [1.0, -3.0, 4.0],
        1.0,
        Some(0.5),
        true,
    ),
];

/// A rigid transform: rotation (Z·Y·X Euler angles) then translation.
#[derive(Clone, Copy, Debug)]
struct Rigid {
    m: [P; 3],
    t: P,
}

impl Rigid {
    fn new(a: f64, b: f64, c: f64, t: P) -> Self {
        let (sa, ca, sb, cb, sc, cc) = (a.sin(), a.cos(), b.sin(), b.cos(), c.sin(), c.cos());
        let m = [
            [ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc],
            [sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc],
            [-sb, cb * sc, cb * cc],
        ];
        Rigid { m, t }
    }
    fn rotate(&self, p: P) -> P {
        self.m.map(|row| common::dot(row, p))
    }
    fn apply(&self, p: P) -> P {
        common::add(self.rotate(p), self.t)
    }
}

/// Runs every seed case in scalar `S` with the triangle's vertices relabelled `shift` times
/// cyclically and everything moved by `rigid`; checks each against its hand-worked answer.
fn check_seeds<S: Tolerance>(shift: usize, rigid: Option<Rigid>) {
    let place = |p: P| rigid.map_or(p, |g| g.apply(p));
    let tri = [0, 1, 2].map(|i| v::<S>(place(TRI[(i + shift) % 3])));
    let st = StandardTriangle::new(&Triangle::new(tri[0], tri[1], tri[2])).unwrap();
    let up = rigid.map_or([0.0, 1.0, 0.0], |g| g.rotate([0.0, 1.0, 0.0]));
    for s in &SEEDS {
        let (p0, p1) = (place(s.p0), place(s.p1));
        let sweep = ballcast::Sweep::new(v::<S>(p0), v::<S>(p1), S::from_f64(s.r)).unwrap();
        let got = st.face_collision(&sweep);
        let exact = shift == 0 && rigid.is_none();
        if exact || !s.boundary {
            assert_eq!(got.is_some(), s.alpha.is_some(), "{}: {got:?}", s.name);
        }
        if let (Some(hit), Some(alpha)) = (got, s.alpha) {
            let approach = (s.p0[1] - s.p1[1]).abs();
            // Each rounded input coordinate (up to ~16 in magnitude) moves a height by at most
            // half its ulp; allow 64 of S's epsilon for them on top of the tolerance table.
            let allowed = S::DISTANCE + S::EPSILON.to_f64() * (approach / 2.0 + 64.0);
            let err = (hit.alpha.to_f64() - alpha).abs() * approach;
            assert!(
                err <= allowed,
                "{}: alpha {:?}, error {err:e}",
                s.name,
                hit.alpha
            );
            let tilt = angle(back(hit.normal), up);
            assert!(
                tilt <= S::ANGLE + S::EPSILON.to_f64(),
                "{}: normal off by {tilt:e}",
                s.name
            );
            if exact {
                assert_eq!(hit.alpha.to_f64(), alpha, "{}", s.name);
                assert_eq!(back(hit.normal), [0.0, 1.0, 0.0], "{}", s.name);
            }
        }
    }
}

/// The standardized test on its own (`standard_face`), on the untransformed seeds.
fn check_standardized<S: Scalar>() {
    let tri = TRI.map(v::<S>);
    let st = StandardTriangle::new(&Triangle::new(tri[0], tri[1], tri[2])).unwrap();
    for s in &SEEDS {
        let sweep = StandardSweep::new(v::<S>(s.p0), v::<S>(s.p1), S::from_f64(s.r)).unwrap();
        let got = standard_face(&st, &sweep).map(S::to_f64);
        assert_eq!(got, s.alpha, "{}", s.name);
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn seed_cases_in_standard_orientation() {
            check_seeds::<$t>(0, None);
            check_standardized::<$t>();
        }
        #[test]
        fn seed_cases_after_cyclic_relabelling() {
            check_seeds::<$t>(1, None);
            check_seeds::<$t>(2, None);
        }
        proptest! {
            #[test]
            fn seed_cases_after_rigid_transforms(
                a in -3.2..3.2f64, b in -3.2..3.2f64, c in -3.2..3.2f64,
                t in prop::array::uniform3(-10.0..10.0f64), shift in 0..3usize,
            ) {
                check_seeds::<$t>(shift, Some(Rigid::new(a, b, c, t)));
            }
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
