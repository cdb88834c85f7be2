//! The seam class against the angles themselves.

use super::{MAX_CLASS, seam_class};
use crate::xorshift::Rng;
use crate::{Features, Scalar, StandardTriangle, Triangle, Vec3};

/// `2 max(F, 1)` for the triangle with standardized shape `[x1, z1, x2]`, from its corners'
/// angles by `atan2` (independent of both ways [`seam_class`] computes it): `F` the largest of
/// `1 / sin(θ/2)` and `1 / sin θ` over the corners.
fn twice_worst(x1: f64, z1: f64, x2: f64) -> f64 {
    let c = [(0.0, 0.0), (x1, z1), (x2, 0.0)];
    let angle = |k: usize| {
        let (p, a, b) = (c[k], c[(k + 1) % 3], c[(k + 2) % 3]);
        let (ux, uz, wx, wz) = (a.0 - p.0, a.1 - p.1, b.0 - p.0, b.1 - p.1);
        libm::atan2(ux * wz - uz * wx, ux * wx + uz * wz).abs()
    };
    let worst = (0..3).fold(1.0f64, |m, k| {
        let t = angle(k);
        m.max(1.0 / libm::sin(t / 2.0)).max(1.0 / libm::sin(t))
    });
    2.0 * worst
}

/// On triangles of every shape, from equilateral to slivers of a few millionths of a radian:
/// `2^class` is at least twice the worst corner's displacement (to within this test's own
/// `f64` rounding), and less than twice that but for the margin (no class wasted); zero with
/// every edge active.
fn class_bounds_the_corners<S: Scalar>() {
    let mut rng = Rng(0x5eed_c1a5);
    let v = |x: f64, z: f64| Vec3::new(S::from_f64(x), S::ZERO, S::from_f64(z));
    let mut slivers = 0;
    for k in 0..24_000 {
        // Thinner and thinner: the apex's height down to 2^-20 of the base; then isosceles
        // triangles whose apex puts `2 / sin(θ/2)` within a few parts in 10^7 of `2^c`.
        let thin = libm::exp2(-20.0 * (k % 64) as f64 / 63.0);
        let (x1, x2, z1) = if k < 20_000 {
            (4.0 * rng.signed(), 2.0 + rng.signed(), 4.0 * thin)
        } else {
            let half =
                libm::asin(libm::exp2(-((k % 8) as f64 + 1.0))) * (1.0 + 3e-7 * rng.signed());
            (1.0, 2.0, 1.0 / libm::tan(half))
        };
        let t = Triangle::new(v(0.0, 0.0), v(x1, z1), v(x2, 0.0));
        let Ok(st) = StandardTriangle::new(&t) else {
            continue;
        };
        assert_eq!(seam_class(true, &st), 0);
        let none = st.with_features(Features::from_bits(0));
        let class = seam_class(false, &none);
        let [_, b, c] = st.vertices();
        let f = twice_worst(b.x.to_f64(), b.z.to_f64(), c.x.to_f64());
        if class == MAX_CLASS {
            assert!(f > 1e9, "{t:?}: class {class} for {f}");
            continue;
        }
        slivers += (f > 1e4) as usize;
        let (top, below) = (libm::exp2(class as f64), libm::exp2(class as f64 - 1.0));
        assert!(top >= f * (1.0 - 1e-12), "{t:?}: class {class} for {f}");
        assert!(
            below < f * (1.0 + 1.0 / 512.0),
            "{t:?}: class {class} for {f}"
        );
    }
    assert!(slivers > 1000, "{slivers} slivers");
}

crate::testing::per_scalar!(class_bounds_the_corners);
