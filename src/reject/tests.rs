//! `cast_within` against `cast` at reaches a few steps either side of `cast`'s answer, on
//! long paths of small balls that graze an edge or a vertex: what is at the reach or before
//! is `cast`'s answer, whatever the cut passed by. (A vertex shadowed by an edge met a tie
//! window after it is where a cut at the reach itself goes wrong: the edge is passed by and
//! the vertex answers early.)

use crate::xorshift::Rng;
use crate::{Features, Scalar, StandardTriangle, Sweep, Triangle, Vec3};

type P = [f64; 3];

fn at<S: Scalar>(p: P) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}

fn unit(a: P) -> P {
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    a.map(|c| c / n)
}

fn cross(a: P, b: P) -> P {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// A triangle within ±4 (random active features one time in four, two-sided one in four) and
/// a path of 50 to 250 units whose line passes one of its vertices, or a point of one of its
/// edges, at the radius (0.002 to 0.05) give or take 1 %.
fn case<S: Scalar>(rng: &mut Rng) -> Option<(StandardTriangle<S>, Sweep<S>)> {
    let p = |rng: &mut Rng| [0; 3].map(|_| 4.0 * rng.signed());
    let t = [p(rng), p(rng), p(rng)];
    let features = if rng.signed() < -0.5 {
        Features::from_bits((rng.next() % 64) as u8)
    } else {
        Features::ALL
    };
    let st = StandardTriangle::new(&Triangle::new(at(t[0]), at(t[1]), at(t[2])))
        .ok()?
        .with_features(features)
        .with_two_sided(rng.signed() < -0.5);
    let i = (rng.next() % 3) as usize;
    let s = (rng.signed() + 1.0) / 2.0;
    let f = if rng.signed() < -0.33 {
        t[i]
    } else {
        [0, 1, 2].map(|a| t[i][a] + s * (t[(i + 1) % 3][a] - t[i][a]))
    };
    let u = unit(p(rng));
    let across = unit(cross(u, p(rng)));
    let r = 0.002 * 25f64.powf((rng.signed() + 1.0) / 2.0);
    let closest = [0, 1, 2].map(|a| f[a] + across[a] * r * (1.0 + 0.01 * rng.signed()));
    let length = 50.0 + 100.0 * (rng.signed() + 1.0);
    let before = length * (0.55 + 0.45 * rng.signed());
    let p0 = [0, 1, 2].map(|a| closest[a] - u[a] * before);
    let p1 = [0, 1, 2].map(|a| p0[a] + u[a] * length);
    Some((st, Sweep::new(at(p0), at(p1), S::from_f64(r)).ok()?))
}

fn within_reach_answers_as_cast<S: Scalar>() {
    let mut rng = Rng(0x7eac_2001);
    let step = S::EPSILON;
    let (mut checked, mut edges_and_vertices) = (0, 0);
    for _ in 0..40_000 {
        let Some((st, sweep)) = case::<S>(&mut rng) else {
            continue;
        };
        let Some(hit) = st.cast(&sweep) else {
            continue;
        };
        edges_and_vertices += (hit.contact != crate::Contact::Face) as usize;
        // Reaches from twelve steps before the answer to four after it.
        let mut reach = hit.alpha - step.mul(S::from_int(12));
        for _ in 0..17 {
            if reach >= S::ZERO {
                let within = st.cast_within(&sweep, reach);
                if hit.alpha <= reach {
                    assert_eq!(within, Some(hit), "reach {reach:?}: {st:?} {sweep:?}");
                } else if let Some(w) = within {
                    assert!(
                        w.alpha > reach,
                        "reach {reach:?}: {w:?}, cast {hit:?}: {sweep:?}"
                    );
                }
                checked += 1;
            }
            reach = reach + step;
        }
    }
    assert!(
        checked > 100_000 && edges_and_vertices > 2_000,
        "{checked} {edges_and_vertices}"
    );
}

crate::testing::per_scalar!(within_reach_answers_as_cast);
