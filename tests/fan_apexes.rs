//! Long sweeps at the apexes of fans of 9 to 24 triangles (more can tie than the merge keeps,
//! where its second visit runs): the mesh, leaves of four and the linear scan answer alike.
#[macro_use]
mod common;
mod meshes;

use common::{P, Rng};
use meshes::against_linear_by;

fn fans(rng: &mut Rng) -> Vec<[P; 3]> {
    let mut out = Vec::new();
    for f in 0..6 {
        let n = 9 + (rng.next() * 16.0) as usize;
        let c = [
            f as f64 * 7.0 - 20.0,
            rng.range(-2.0, 2.0),
            rng.range(-5.0, 5.0),
        ];
        let h = rng.range(-1.5, 1.5);
        let apex = [c[0], c[1] + h, c[2]];
        let ring: Vec<P> = (0..n)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / n as f64;
                let rad = rng.range(2.0, 3.0);
                [
                    c[0] + rad * a.cos(),
                    c[1] + rng.range(-0.3, 0.3),
                    c[2] + rad * a.sin(),
                ]
            })
            .collect();
        for k in 0..n {
            out.push([apex, ring[(k + 1) % n], ring[k]]);
        }
    }
    out
}

fn at_apexes<S: ballcast::Scalar>() {
    let mut rng = Rng(0xfa_0001);
    let src = fans(&mut rng);
    let apexes: Vec<P> = src.iter().map(|t| t[0]).collect();
    against_linear_by::<S>(&mut rng, &src, 20000, |rng, k| {
        let at = apexes[(rng.next() * apexes.len() as f64) as usize];
        let length = [3.0, 30.0, 120.0, 400.0][k % 4];
        let dir = loop {
            let d = rng.point(1.0);
            let n = common::norm(d);
            if n > 0.2 && n <= 1.0 && d[1] < -0.1 * n {
                break common::scale(d, 1.0 / n);
            }
        };
        let r = [0.0, 0.003, 0.01, 0.1, 0.5][k % 5];
        let aim = common::add(at, rng.point(r * 0.5 + 0.001));
        let aim = common::add(aim, common::scale([0.0, 1.0, 0.0], r));
        let p0 = common::add(aim, common::scale(dir, -0.6 * length));
        let p1 = common::add(aim, common::scale(dir, 0.4 * length));
        (p0, p1, r)
    });
}

every_scalar!(at_apexes);
