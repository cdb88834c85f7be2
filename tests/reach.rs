//! Contacts at the edge of the reach of one already found. A mesh that holds a contact passes
//! over the edges and vertices of other triangles that the ball cannot meet by its reach (the
//! earliest alpha plus the tie window, and a few tie windows more); every contact that comes
//! first or ties must still count, as in the linear scan. Each case grazes an edge or vertex of
//! a random triangle (passing it at the radius, give or take a few steps of the scalar or 1 %),
//! and stands a wall across the path where the ball meets it a few steps of alpha before or
//! after that feature, so that the two contacts fall on either side of every boundary the reach
//! draws. In several regimes: the usual scale, near the edge of the scalar's range, tiny radii
//! and paths, two-sided triangles, paths that start within reach of the feature, long paths of
//! small balls. Every scalar;
//! the mesh's answer is the linear scan's, bit for bit. (Growing the radius by nothing for
//! rounding fails here in every scalar; a cut at the reach itself, which the tie windows
//! guard against, fails the triangle-level test in `src/reject/tests.rs`.)

mod common;
mod meshes;

use ballcast::{Degenerates, Scalar, Sweep, Triangle};
use common::{P, Rng, add, cross, norm, scale, sub, v};
use fixed::types::{I16F16, I32F32};
use meshes::{build_sided, soup, tri};

fn unit(a: P) -> P {
    scale(a, 1.0 / norm(a))
}

/// A two-sided triangle of circumradius `size` across the path from `p0` along `d`, which a
/// ball of radius `r` meets at alpha `a`: in the plane square to the path, `r` ahead of the
/// centre there.
fn wall(p0: P, d: P, r: f64, a: f64, size: f64) -> [P; 3] {
    let u = unit(d);
    let side = if u[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let (e1, e2) = (unit(cross(u, side)), unit(cross(u, cross(u, side))));
    let at = add(add(p0, scale(d, a)), scale(u, r));
    [0.0f64, 2.1, 4.2].map(|t| {
        add(
            at,
            add(scale(e1, size * t.cos()), scale(e2, size * t.sin())),
        )
    })
}

/// Where the cases lie and what they look like.
#[derive(Clone, Copy)]
struct Regime {
    /// The soup's centre (on every axis) and half its extent.
    centre: f64,
    half: f64,
    /// Radii and path lengths, drawn evenly in their logarithms.
    radius: (f64, f64),
    length: (f64, f64),
    /// The share of paths that start within about the radius of the grazed feature.
    start_near: f64,
    two_sided: bool,
}

/// The regimes, for a scalar whose step near the origin is `step`, far out at `far`, where the
/// coordinates' spacing is `spacing`.
fn regimes(step: f64, far: f64, spacing: f64) -> [Regime; 6] {
    let usual = Regime {
        centre: 0.0,
        half: 4.0,
        radius: (0.05, 1.0),
        length: (2.0, 40.0),
        start_near: 0.0,
        two_sided: false,
    };
    let tiny = Regime {
        half: 0.05,
        radius: (16.0 * step, 0.01),
        length: (16.0 * step, 0.05),
        start_near: 0.3,
        ..usual
    };
    [
        usual,
        Regime {
            centre: far - 5.0,
            radius: (64.0 * spacing, 1.0),
            length: (256.0 * spacing, 40.0),
            two_sided: true,
            ..usual
        },
        tiny,
        Regime {
            two_sided: true,
            ..tiny
        },
        Regime {
            length: (0.01, 20.0),
            start_near: 0.7,
            ..usual
        },
        // Long paths and small balls: a step of alpha is a long way, far more than the
        // rounding the radius is grown by.
        Regime {
            radius: (0.002, 0.05),
            length: (50.0, 250.0),
            ..usual
        },
    ]
}

fn log_uniform(rng: &mut Rng, (a, b): (f64, f64)) -> f64 {
    (a.ln() + rng.next() * (b.ln() - a.ln())).exp()
}

/// The cases of one regime: how many, and how many the wall and the feature won.
fn walls_beside<S: Scalar>(rng: &mut Rng, g: Regime) -> [usize; 3] {
    let step = S::EPSILON.to_f64()
        * if S::PRECISION.relative {
            g.centre.max(1.0)
        } else {
            1.0
        };
    let src: Vec<[P; 3]> = soup(rng, 30, g.half)
        .into_iter()
        .map(|t| t.map(|p| p.map(|c| c + g.centre)))
        .collect();
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let alone = build_sided(&input, |_| g.two_sided, Degenerates::Skip).unwrap();
    let first_alone = alone.reference();
    let mut counts = [0; 3];
    for k in 0..1500 {
        // A vertex a third of the time, else a point of an edge; passed at the radius.
        let t = src[(rng.next() * src.len() as f64) as usize];
        let i = (rng.next() * 3.0) as usize;
        let f = if rng.next() < 1.0 / 3.0 {
            t[i]
        } else {
            add(t[i], scale(sub(t[(i + 1) % 3], t[i]), rng.next()))
        };
        let (u, r) = (unit(rng.point(1.0)), log_uniform(rng, g.radius));
        let off = if rng.next() < 0.5 {
            r + 40.0 * step * rng.range(-1.0, 1.0)
        } else {
            r * rng.range(0.99, 1.01)
        };
        let closest = add(f, scale(unit(cross(u, rng.point(1.0))), off.max(0.0)));
        let length = log_uniform(rng, g.length);
        let before = if rng.next() < g.start_near {
            r * rng.range(0.0, 1.1)
        } else {
            length * rng.range(0.05, 0.95)
        };
        let (p0, p1) = (
            sub(closest, scale(u, before)),
            add(closest, scale(u, length - before)),
        );
        let Ok(sweep) = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)) else {
            continue;
        };
        let Some(feature) = first_alone(&sweep) else {
            continue;
        };
        let steps = (rng.next() * 25.0) as i32 - 12;
        let a = feature.alpha.to_f64() + steps as f64 * S::EPSILON.to_f64();
        if !(0.0..1.0).contains(&a) {
            continue;
        }
        let w = wall(p0, sub(p1, p0), r, a, 3.0 * r + g.half.min(1.0));
        let mut with_wall = input.clone();
        with_wall.push(tri(w));
        let last = src.len();
        let sided = |i: usize| i == last || g.two_sided;
        // A wall beyond the range, or too thin for the scalar, is no case.
        let Ok(owned) = build_sided(&with_wall, sided, Degenerates::Skip) else {
            continue;
        };
        if owned.order.len() != with_wall.len() {
            continue;
        }
        let (got, want) = (owned.mesh().cast(&sweep), owned.reference()(&sweep));
        assert_eq!(
            got, want,
            "case {k}: {p0:?} -> {p1:?}, r {r}, wall {steps} steps away"
        );
        counts[0] += 1;
        match want {
            Some(h) if h.index == last => counts[1] += 1,
            Some(_) => counts[2] += 1,
            None => {}
        }
    }
    counts
}

fn wall_beside_a_grazed_feature<S: Scalar>() {
    let mut rng = Rng(0x7eac_0001);
    // Far out: as near the edge of the range as a fixed-point scalar allows; for floats where
    // the spacing of the coordinates is 1/128.
    let step = S::EPSILON.to_f64();
    let (far, spacing) = if S::PRECISION.relative {
        ((1.0 / 128.0) / step, 1.0 / 128.0)
    } else {
        (0.97 * S::LIMIT.to_f64(), step)
    };
    for (k, g) in regimes(step, far, spacing).into_iter().enumerate() {
        let [cases, wall, feature] = walls_beside::<S>(&mut rng, g);
        // The cases straddle the boundary: each side wins a fair share.
        println!("regime {k}: {cases} cases, the wall first in {wall}, the feature in {feature}");
        assert!(cases > 200, "regime {k}: only {cases} cases");
        assert!(wall > cases / 10 && feature > cases / 10, "regime {k}");
    }
}

meshes::per_scalar!(wall_beside_a_grazed_feature);
