//! Contacts at the edge of the reach of one already found. A mesh that holds a contact passes
//! over the edges and vertices of other triangles that the ball cannot meet by its reach (the
//! earliest alpha plus the tie window, and a few tie windows more); every contact that comes
//! first or ties must still count, as in the linear scan. Each case grazes an edge or vertex of
//! a random triangle with a long path, and stands a wall across the path where the ball meets
//! it a few steps of alpha before or after that feature, so that the two contacts fall on
//! either side of every boundary the reach draws. Every scalar; the mesh's answer is the
//! linear scan's, bit for bit.

mod common;
mod meshes;

use ballcast::{Degenerates, Scalar, Sweep, Triangle};
use common::{P, Rng, add, cross, norm, scale, sub, v};
use fixed::types::{I16F16, I32F32};
use meshes::{build_sided, grazing, soup, tri};

fn unit(a: P) -> P {
    scale(a, 1.0 / norm(a))
}

/// A two-sided triangle across the path from `p0` along `d`, which a ball of radius `r` meets
/// at alpha `a`: in the plane square to the path, `r` ahead of the centre there, wide enough
/// that the ball meets its face.
fn wall(p0: P, d: P, r: f64, a: f64) -> [P; 3] {
    let u = unit(d);
    let side = if u[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let (e1, e2) = (unit(cross(u, side)), unit(cross(u, cross(u, side))));
    let at = add(add(p0, scale(d, a)), scale(u, r));
    let size = 3.0 * r + 1.0;
    [0.0f64, 2.1, 4.2].map(|t| {
        add(
            at,
            add(scale(e1, size * t.cos()), scale(e2, size * t.sin())),
        )
    })
}

fn wall_beside_a_grazed_feature<S: Scalar>() {
    let mut rng = Rng(0x7eac_0001);
    let src = soup(&mut rng, 30, 4.0);
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let alone = build_sided(&input, |_| false, Degenerates::Skip).unwrap();
    let (first_alone, step) = (alone.reference(), S::EPSILON.to_f64());
    let (mut cases, mut wall_first, mut feature_first) = (0, 0, 0);
    for k in 0..3000 {
        let length = rng.range(2.0, 40.0);
        let (p0, p1, r) = grazing(&mut rng, &src, length);
        let steps = (rng.next() * 25.0) as i32 - 12;
        let Ok(sweep) = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)) else {
            continue;
        };
        let Some(feature) = first_alone(&sweep) else {
            continue;
        };
        let a = feature.alpha.to_f64() + steps as f64 * step;
        if !(0.0..1.0).contains(&a) {
            continue;
        }
        let mut with_wall = input.clone();
        with_wall.push(tri(wall(p0, sub(p1, p0), r, a)));
        let last = src.len();
        let Ok(owned) = build_sided(&with_wall, |i| i == last, Degenerates::Skip) else {
            continue;
        };
        let (got, want) = (owned.mesh().cast(&sweep), owned.reference()(&sweep));
        assert_eq!(
            got, want,
            "case {k}: {p0:?} -> {p1:?}, r {r}, wall {steps} steps away"
        );
        cases += 1;
        match want {
            Some(h) if h.index == last => wall_first += 1,
            Some(_) => feature_first += 1,
            None => {}
        }
    }
    println!("{cases} cases: the wall first in {wall_first}, the feature in {feature_first}");
    // The cases straddle the boundary: each side wins a fair share.
    assert!(cases > 1000, "only {cases} cases");
    assert!(
        wall_first > cases / 5 && feature_first > cases / 5,
        "{wall_first} / {feature_first}"
    );
}

meshes::per_scalar!(wall_beside_a_grazed_feature);
