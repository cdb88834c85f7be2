//! Long sweeps of small balls at a mesh's edges and vertices: the contact reported and its
//! normal against `f64`'s on the same rounded triangles, every scalar.

#[macro_use]
mod common;
mod meshes;

use ballcast::{Degenerates, SceneHit, Sweep};
use common::{P, Rng, Tolerance, add, angle, back, norm, scale, sub, v};
use meshes::{build, shot_at_sphere, sphere, tri};

/// Sweeps of a ball of radius `r` along paths `length` long, aimed at a vertex, an edge's
/// middle or a point along an edge of a sphere of radius 10 (512 triangles) from within 60° of
/// its normal there: each sweep with the scalar's answer and `f64`'s on the same triangles.
fn shots<S: Tolerance>(
    r: f64,
    length: f64,
    count: usize,
) -> Vec<(Sweep<f64>, SceneHit<S>, SceneHit<f64>)> {
    // The sphere's corners rounded to `S`, so both meshes hold the same triangles.
    let src: Vec<[P; 3]> = sphere(10.0, 3)
        .into_iter()
        .map(|t| t.map(|p| back(v::<S>(p))))
        .collect();
    let ours = build(
        &src.iter().map(|&t| tri::<S>(t)).collect::<Vec<_>>(),
        Degenerates::Refuse,
    )
    .unwrap();
    let exact = build(
        &src.iter().map(|&t| tri::<f64>(t)).collect::<Vec<_>>(),
        Degenerates::Refuse,
    )
    .unwrap();
    let (ours, exact) = (ours.mesh(), exact.mesh());
    let mut rng = Rng(0x10C5);
    let mut out = Vec::new();
    for i in 0..count {
        let Some((at, dir)) = shot_at_sphere(&mut rng, &src, i) else {
            continue;
        };
        // The point aimed at lies within a radius of the surface point, three fifths along
        // the path: the ball meets the feature, or a face beside it, a little before.
        let aim = add(at, rng.point(r));
        let (p0, p1) = (
            add(aim, scale(dir, 0.6 * length)),
            add(aim, scale(dir, -0.4 * length)),
        );
        let (p0, p1) = (v::<S>(p0), v::<S>(p1));
        let sweep = Sweep::new(p0, p1, S::from_f64(r)).unwrap();
        let twin = Sweep::new(v(back(p0)), v(back(p1)), sweep.radius().to_f64()).unwrap();
        if let (Some(h), Some(e)) = (ours.cast(&sweep), exact.cast(&twin)) {
            out.push((twin, h, e));
        }
    }
    out
}

/// Prints how far the scalar's normals and positions lie from `f64`'s on long sweeps.
fn report<S: Tolerance>() {
    for (r, length) in [(0.01, 8.3), (0.01, 50.0), (0.1, 50.0)] {
        let all = shots::<S>(r, length, 6000);
        let angles: Vec<f64> = all
            .iter()
            .map(|(_, h, e)| angle(back(h.normal), back(e.normal)))
            .collect();
        let apart: Vec<f64> = all
            .iter()
            .map(|(_, h, e)| norm(sub(back(h.position), back(e.position))))
            .collect();
        let over = |x: f64| angles.iter().filter(|&&a| a > x).count();
        let worst = |v: &[f64]| v.iter().cloned().fold(0.0, f64::max);
        println!(
            "{} r {r} path {length}: {} hits, normals > 0.01 rad {}, > 0.1 {}, > 0.2 {}, worst {:.3}; position worst {:.2e}",
            S::NAME,
            all.len(),
            over(0.01),
            over(0.1),
            over(0.2),
            worst(&angles),
            worst(&apart)
        );
    }
}

/// The contact reported is the first along the path, within the position tolerance of `f64`'s,
/// and its normal mixes only the normals of contacts that simultaneous: on a convex mesh, a
/// face met `w` after the first contact along the path has a plane within `r` of the first
/// contact's centre and at most `w` nearer, so its normal lies within `acos(1 - w / r)` of the
/// first's. The window is twice the position's rounding (`Precision::position_error`) at the
/// path's magnitude, plus the position's own tolerance. When the smallest of equally rounded
/// alphas' indices was reported and the normals of contacts four steps of alpha apart were
/// merged, `I16F16` reported positions up to 7.2e-4 from `f64`'s (tolerance 1e-4) and normals
/// up to 0.54 rad off on paths of 50 (bound 0.26 for a ball of 0.01, 0.082 for 0.1).
fn long_sweeps_report_the_first_contact<S: Tolerance>() {
    for (r, length) in [(0.01, 8.3), (0.01, 50.0), (0.1, 50.0)] {
        for (sweep, h, e) in shots::<S>(r, length, 1500) {
            let (p0, p1) = (
                back(v::<S>(back(sweep.p0()))),
                back(v::<S>(back(sweep.p1()))),
            );
            let m = p0.iter().chain(&p1).fold(0.0f64, |m, x| m.max(x.abs()));
            let apart = norm(sub(back(h.position), back(e.position)));
            assert!(
                apart <= S::POSITION,
                "{} r {r} path {length}: position {apart:.2e} from f64's, {p0:?} -> {p1:?}",
                S::NAME
            );
            let window = 2.0 * S::PRECISION.position_error(m) + S::POSITION;
            let bound = (1.0 - window / r).acos() + S::ANGLE;
            let off = angle(back(h.normal), back(e.normal));
            assert!(
                off <= bound,
                "{} r {r} path {length}: normal {off:.3} rad from f64's (bound {bound:.3}), {p0:?} -> {p1:?}",
                S::NAME
            );
        }
    }
}

#[test]
#[ignore]
fn report_all() {
    report::<f32>();
    report::<fixed::types::I32F32>();
    report::<fixed::types::I16F16>();
}

every_scalar!(long_sweeps_report_the_first_contact);
