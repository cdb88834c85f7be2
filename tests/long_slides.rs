//! Slides that run a long way along a plane in one call: each keeps its travel, in every
//! scalar.

mod common;

use ballcast::{Scene, Triangle};
use common::{Rng, Tolerance, to_and_fro, v};

/// A ball slid 20 to 50 a call back and forth along a tilted plane of two triangles 2 000
/// across, pressed 1e-2 or 1e-4 into it. Its slide runs along the contact's normal as the
/// scalar rounds it, and in fixed point that normal (16 fractional bits in `I16F16`) is
/// rounded well below the frame's (30): over 40 units of slide the path comes down about 35
/// steps onto the frame's plane. Lifted by the motion's approach as rounded (about nothing), the
/// ball met the face again a tenth of the way on, four times, and the call ended there
/// (`I16F16`, 480 planes of 300 calls each: 176 to 1 173 of 144 000 calls short at r 0.05 to 2).
/// Every call now travels all but the press.
fn a_fast_slide_along_a_tilted_plane_keeps_its_travel<S: Tolerance>(r: f64, press: f64) {
    let mut rng = Rng(0xFA57_511D);
    for plane in 0..48 {
        let [n, a, b] = to_and_fro::tilted(&mut rng);
        let o = common::scale(common::add(a, b), -1000.0);
        let mut scene: Scene<S, 2> = Scene::new();
        for t in common::quad(o, common::scale(a, 2000.0), common::scale(b, 2000.0)) {
            scene
                .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
        let step = rng.range(20.0, 50.0);
        let label = format!("plane {plane}");
        to_and_fro::keeps_travel::<S, _>(
            &scene,
            [n, a, b],
            (r, step, press),
            100,
            &mut rng,
            &label,
        );
    }
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[test]
        fn a_fast_slide_along_a_tilted_plane_keeps_its_travel() {
            for r in [0.05, 0.5, 2.0] {
                for press in [1e-2, 1e-4] {
                    super::a_fast_slide_along_a_tilted_plane_keeps_its_travel::<$t>(r, press);
                }
            }
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: fixed::types::I32F32, i16f16: fixed::types::I16F16);
