//! Hand-worked cases of the seed's standardized face test, one per branch.
//! Triangle in standard orientation: v0 = (0,0,0), v1 = (1,0,4), v2 = (4,0,0).

use ballcast::{Scalar, StandardTriangle, Sweep, Triangle, Vec3};
use fixed::types::{I16F16, I32F32};

fn v<S: Scalar>(x: f64, y: f64, z: f64) -> Vec3<S> {
    Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z))
}

fn alpha<S: Scalar>(p0: [f64; 3], p1: [f64; 3], r: f64) -> Option<f64> {
    let t = Triangle::new(v(0.0, 0.0, 0.0), v(1.0, 0.0, 4.0), v(4.0, 0.0, 0.0));
    let st = StandardTriangle::<S>::new(&t).unwrap();
    let s = Sweep::new(
        v(p0[0], p0[1], p0[2]),
        v(p1[0], p1[1], p1[2]),
        S::from_f64(r),
    )
    .unwrap();
    st.face_collision(&s).map(|h| h.alpha.to_f64())
}

macro_rules! seed_cases {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        use super::*;
        #[test]
        fn straight_down_hits_at_half() {
            // y0 = 5, y1 = -3, r = 1: beta = (1 - 5) / (-3 - 5) = 0.5; q' = (2, 0, 1) inside.
            assert_eq!(alpha::<$t>([2.0, 5.0, 1.0], [2.0, -3.0, 1.0], 1.0), Some(0.5));
        }
        #[test]
        fn starts_below_radius_misses() {
            assert_eq!(alpha::<$t>([2.0, 0.5, 1.0], [2.0, -3.0, 1.0], 1.0), None);
        }
    })*};
}

seed_cases!(f32_: f32, f64_: f64, i32f32: I32F32, i16f16: I16F16);
