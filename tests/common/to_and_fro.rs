//! A ball slid to and fro along a tilted plane, each call checked to travel all of its step but
//! the press into the plane and rounding: shared by the slide tests on big and far planes.

use super::{P, Rng, Tolerance, add, back, cross, norm, scale, sub, v};
use ballcast::{Geometry, move_and_slide};

/// A random tilt: the plane's unit normal `n` (pointing up, at most about 73° from it) and two
/// unit vectors `a`, `b` across it.
pub fn tilted(rng: &mut Rng) -> [P; 3] {
    let unit = |p: P| scale(p, 1.0 / norm(p));
    let n = unit([
        rng.range(-1.0, 1.0),
        rng.range(0.3, 1.0),
        rng.range(-1.0, 1.0),
    ]);
    let a = unit(cross(n, [0.0, 0.0, 1.0]));
    [n, a, cross(n, a)]
}

/// Slides a ball of radius `r` along the plane `[n, a, b]` from `10 step` behind the origin,
/// `step` a call in a random direction across it, 20 calls forward then 20 back, `calls` calls,
/// each pressed `press` into the plane: every call must travel at least 0.999 of `step`.
pub fn keeps_travel<S: Tolerance, G: Geometry<S>>(
    scene: &G,
    [n, a, b]: [P; 3],
    (r, step, press): (f64, f64, f64),
    calls: usize,
    rng: &mut Rng,
    label: &str,
) {
    let dir = add(a, scale(b, rng.range(-1.0, 1.0)));
    let dir = scale(dir, 1.0 / norm(dir));
    let mut p = v::<S>(add(
        scale(n, r * (1.0 + 1.0 / 1024.0)),
        scale(dir, -10.0 * step),
    ));
    for k in 0..calls {
        let way = if (k / 20) % 2 == 0 { step } else { -step };
        let d = v::<S>(sub(scale(dir, way), scale(n, press)));
        let out = move_and_slide(scene, p, d, S::from_f64(r)).unwrap();
        let moved = norm(sub(back(out.position), back(p)));
        assert!(
            moved >= step * 0.999,
            "{}: {label}, r {r}, press {press}, call {k} moved {moved} of {step} from {:?}",
            S::NAME,
            back(p)
        );
        p = out.position;
    }
}
