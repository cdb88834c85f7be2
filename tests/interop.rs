//! The optional interop features: run with `cargo test --all-features --test interop`.
#![allow(unused_imports)]

use ballcast::{Contact, Error, Hit, Scene, Sweep, Triangle, Vec3};

#[cfg(feature = "mint")]
#[test]
fn mint_vectors_convert_both_ways() {
    let m = mint::Vector3 {
        x: 1.5f32,
        y: -2.0,
        z: 3.25,
    };
    let v: Vec3<f32> = m.into();
    assert_eq!(v, Vec3::new(1.5, -2.0, 3.25));
    let back: mint::Vector3<f32> = v.into();
    assert_eq!(back, m);
}

#[cfg(feature = "glam")]
#[test]
fn glam_vectors_convert_both_ways() {
    let v: Vec3<f32> = glam::Vec3::new(1.0, 2.0, 3.0).into();
    assert_eq!(glam::Vec3::from(v), glam::Vec3::new(1.0, 2.0, 3.0));
    let d: Vec3<f64> = glam::DVec3::new(-1.0, 0.5, 8.0).into();
    assert_eq!(d, Vec3::new(-1.0, 0.5, 8.0));
    assert_eq!(glam::DVec3::from(d), glam::DVec3::new(-1.0, 0.5, 8.0));
}

#[cfg(feature = "defmt")]
#[test]
fn public_types_implement_defmt_format() {
    fn format<T: defmt::Format>() {}
    format::<Vec3<f32>>();
    format::<Vec3<fixed::types::I16F16>>();
    format::<Triangle<fixed::types::I32F32>>();
    format::<Hit<f32>>();
    format::<ballcast::SceneHit<f64>>();
    format::<Contact>();
    format::<Error>();
    format::<ballcast::Features>();
}

#[cfg(feature = "serde")]
mod serde_tests {
    use super::*;
    use fixed::types::I16F16;

    fn floor<S: ballcast::Scalar>() -> Scene<S, 4> {
        let v = |x: f64, z: f64| Vec3::new(S::from_f64(x), S::ZERO, S::from_f64(z));
        let mut s = Scene::new();
        s.push(Triangle::new(v(0.0, 0.0), v(0.0, 2.0), v(2.0, 2.0)))
            .unwrap();
        s.push_two_sided(Triangle::new(v(0.0, 0.0), v(2.0, 2.0), v(2.0, 0.0)))
            .unwrap();
        s
    }

    #[test]
    fn scene_round_trips_and_recomputes_active_edges() {
        let scene = floor::<I16F16>();
        let json = serde_json::to_string(&scene).unwrap();
        let back: Scene<I16F16, 4> = serde_json::from_str(&json).unwrap();
        assert_eq!(back.len(), 2);
        for i in 0..2 {
            assert_eq!(back.triangle(i), scene.triangle(i));
        }
        assert!(back.triangle(1).unwrap().is_two_sided());
    }

    #[test]
    fn invalid_scene_is_refused_on_the_way_in() {
        let z = Vec3::new(0.0f32, 0.0, 0.0);
        let bad = [(Triangle::new(z, z, Vec3::new(1.0, 0.0, 0.0)), false)];
        let json = serde_json::to_string(&bad).unwrap();
        let err = serde_json::from_str::<Scene<f32, 4>>(&json).unwrap_err();
        assert!(err.to_string().contains("degenerate"), "{err}");
        let too_many = serde_json::to_string(&[bad[0]; 5]).unwrap();
        assert!(serde_json::from_str::<Scene<f32, 4>>(&too_many).is_err());
    }

    #[test]
    fn results_round_trip() {
        let scene = floor::<f64>();
        let s = Sweep::new(Vec3::new(1.0, 2.0, 0.5), Vec3::new(1.0, -1.0, 0.5), 0.5).unwrap();
        let hit = scene.cast(&s).unwrap();
        let json = serde_json::to_string(&hit).unwrap();
        assert_eq!(
            serde_json::from_str::<ballcast::SceneHit<f64>>(&json).unwrap(),
            hit
        );
        let refused = Error::Full { capacity: 8 };
        let e = serde_json::to_string(&refused).unwrap();
        assert_eq!(serde_json::from_str::<Error>(&e).unwrap(), refused);
    }
}
