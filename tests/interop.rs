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

    /// A level as a tool would write it: plain numbers, integers and decimals, a wall two-sided.
    const LEVEL: &str = r#"[
        [{"v0": {"x": -10, "y": 0, "z": -10}, "v1": {"x": -10, "y": 0, "z": 10},
          "v2": {"x": 10, "y": 0, "z": 0}}, false],
        [{"v0": {"x": 3.5, "y": 0, "z": -4}, "v1": {"x": 3.5, "y": 4, "z": 0},
          "v2": {"x": 3.5, "y": 0, "z": 4}}, true]
    ]"#;

    /// The ball falls onto the floor and rolls into the wall, in scalar `S`.
    fn play<S: ballcast::Scalar>(scene: &Scene<S, 4>) -> [f64; 3] {
        let v = |x: f64, y: f64, z: f64| Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z));
        let out = ballcast::move_and_slide(scene, v(0.0, 2.0, 0.0), v(5.0, -3.0, 0.0), S::ONE);
        let p = out.unwrap().position;
        [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()]
    }

    #[test]
    fn one_level_json_loads_into_every_scalar() {
        use fixed::types::I32F32;
        let f64_: Scene<f64, 4> = serde_json::from_str(LEVEL).unwrap();
        let reference = play(&f64_);
        // Stopped by the wall at x = 3.5 - 1, resting on the floor at y = 1 (plus skins).
        assert!((reference[0] - 2.5).abs() < 1e-2 && (reference[1] - 1.0).abs() < 1e-2);
        let others = [
            play(&serde_json::from_str::<Scene<f32, 4>>(LEVEL).unwrap()),
            play(&serde_json::from_str::<Scene<I16F16, 4>>(LEVEL).unwrap()),
            play(&serde_json::from_str::<Scene<I32F32, 4>>(LEVEL).unwrap()),
        ];
        for p in others {
            let d = (0..3)
                .map(|k| (p[k] - reference[k]).abs())
                .fold(0.0, f64::max);
            assert!(d < 1e-3, "{p:?} against {reference:?}");
        }
        // And what one scalar writes, another reads: I16F16 to f32 and back, exactly.
        let i16: Scene<I16F16, 4> = serde_json::from_str(LEVEL).unwrap();
        let json = serde_json::to_string(&i16).unwrap();
        let f32_: Scene<f32, 4> = serde_json::from_str(&json).unwrap();
        let back: Scene<I16F16, 4> =
            serde_json::from_str(&serde_json::to_string(&f32_).unwrap()).unwrap();
        assert!(back.sources().eq(i16.sources()));
    }

    #[test]
    fn fixed_point_serializes_as_plain_numbers() {
        use fixed::types::I32F32;
        let v = Vec3::new(
            I16F16::from_num(1.5),
            I16F16::from_num(-2),
            I16F16::from_bits(1),
        );
        let json = serde_json::to_string(&v).unwrap();
        assert_eq!(json, r#"{"x":1.5,"y":-2.0,"z":0.0000152587890625}"#);
        assert_eq!(serde_json::from_str::<Vec3<I16F16>>(&json).unwrap(), v);
        // f32 as f32: 0.1 reads as 0.1, not 0.10000000149011612.
        let json = serde_json::to_string(&Vec3::new(0.1f32, 0.0, 1e-3)).unwrap();
        assert_eq!(json, r#"{"x":0.1,"y":0.0,"z":0.001}"#);
        // An I32F32 value with more bits than f64 holds: the exact pair, read back bit for bit.
        let big = I32F32::from_bits((1 << 59) + 1); // 2^27 + 2^-32
        let v = Vec3::new(big, I32F32::ZERO, -big);
        let json = serde_json::to_string(&v).unwrap();
        assert_eq!(
            json,
            r#"{"x":[134217728.0,2.3283064365386963e-10],"y":0.0,"z":[-134217728.0,-2.3283064365386963e-10]}"#
        );
        assert_eq!(serde_json::from_str::<Vec3<I32F32>>(&json).unwrap(), v);
        // Integers read too.
        let v: Vec3<I32F32> = serde_json::from_str(r#"{"x":1,"y":-3,"z":0}"#).unwrap();
        assert_eq!(
            v,
            Vec3::new(I32F32::ONE, I32F32::from_num(-3), I32F32::ZERO)
        );
    }

    #[test]
    fn level_value_that_does_not_fit_names_triangle_and_value() {
        let far = LEVEL.replace(r#""x": 3.5, "y": 4"#, r#""x": 100000, "y": 4"#);
        // f32 holds it (the wall turns into a sliver far away, still valid) ...
        assert!(serde_json::from_str::<Scene<f32, 4>>(&far).is_ok());
        // ... I16F16 cannot: refused with the value and its range, not saturated.
        let err = serde_json::from_str::<Scene<I16F16, 4>>(&far).unwrap_err();
        let msg = err.to_string();
        assert!(
            msg.starts_with("triangle 1: 100000 is outside the accepted range [-4096, 4096]"),
            "{msg}"
        );
    }

    /// A vector's component that the scalar cannot hold is refused with its value and where it
    /// stands in the text: the range check ran after the whole vector had been read, and
    /// serde_json's message had no position.
    #[test]
    fn vec3_value_that_does_not_fit_says_where() {
        let text = "{\"x\": 0,\n \"y\": 100000,\n \"z\": 0}";
        assert!(serde_json::from_str::<Vec3<f32>>(text).is_ok());
        let err = serde_json::from_str::<Vec3<I16F16>>(text).unwrap_err();
        assert_eq!((err.line(), err.column()), (2, 12), "{err}");
        let msg = err.to_string();
        assert!(
            msg.starts_with("100000 is outside the accepted range"),
            "{msg}"
        );
    }

    /// A binary format (CBOR: not human-readable) gets every scalar as an exact pair: an
    /// `I32F32` level beyond f64's 53 bits round-trips bit for bit, and an f32 level reads into
    /// I16F16.
    #[test]
    fn binary_format_level_is_exact_and_loads_into_every_scalar() {
        use fixed::types::I32F32;
        let cbor = |s: &Scene<_, 4>| {
            let mut out = Vec::new();
            ciborium::into_writer(s, &mut out).unwrap();
            out
        };
        let mut big: Scene<I32F32, 4> = Scene::new();
        let odd = I32F32::from_bits((1 << 59) + 1); // 2^27 + 2^-32
        let v = |x: I32F32, z: f64| Vec3::new(x, I32F32::ZERO, I32F32::from_num(z));
        big.push(Triangle::new(
            v(odd, 0.0),
            v(odd, 2.0),
            v(odd + I32F32::ONE, 0.0),
        ))
        .unwrap();
        let back: Scene<I32F32, 4> = ciborium::from_reader(cbor(&big).as_slice()).unwrap();
        assert!(back.sources().eq(big.sources()));
        let f32_: Scene<f32, 4> = serde_json::from_str(LEVEL).unwrap();
        let bytes = {
            let mut out = Vec::new();
            ciborium::into_writer(&f32_, &mut out).unwrap();
            out
        };
        let i16: Scene<I16F16, 4> = ciborium::from_reader(bytes.as_slice()).unwrap();
        let json: Scene<I16F16, 4> = serde_json::from_str(LEVEL).unwrap();
        assert!(i16.sources().eq(json.sources()));
    }

    #[test]
    fn bad_triangle_in_level_gives_its_index() {
        let flat = LEVEL.replace(r#""x": 3.5, "y": 4, "z": 0"#, r#""x": 3.5, "y": 0, "z": 0"#);
        let err = serde_json::from_str::<Scene<f32, 4>>(&flat).unwrap_err();
        assert!(
            err.to_string().starts_with("triangle 1: degenerate"),
            "{err}"
        );
        let full = serde_json::from_str::<Scene<f32, 1>>(LEVEL).unwrap_err();
        assert!(
            full.to_string().starts_with("full: it holds 1 triangle "),
            "{full}"
        );
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

    /// Vectors of random bit patterns within each scalar's safe range (subnormals, -0.0 and
    /// `I32F32` values wider than 53 bits among them) come back bit for bit through JSON (with
    /// `serde_json`'s `float_roundtrip`: without it about 30 % of `f64` values came back a
    /// step off) and CBOR.
    #[test]
    fn random_bits_round_trip_exactly() {
        fn check<S: ballcast::Scalar>(from_bits: impl Fn(u64) -> S, bits: impl Fn(S) -> u64)
        where
            Vec3<S>: serde::Serialize + serde::de::DeserializeOwned,
        {
            let mut x = 0x9e37_79b9_7f4a_7c15u64;
            let mut next = move || {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                x
            };
            for k in 0..20_000 {
                let c = |n: u64| {
                    let v = from_bits(n);
                    let inside = v >= -S::LIMIT && v <= S::LIMIT;
                    if inside { v } else { S::ZERO }
                };
                let special = [c(0), from_bits(1), c(next() >> (k % 64))];
                let v = Vec3::new(c(next()), special[k % 3], c(next() >> 11));
                let json = serde_json::to_string(&v).unwrap();
                let back: Vec3<S> = serde_json::from_str(&json).unwrap();
                let same = |a: Vec3<S>, b: Vec3<S>| {
                    [a.x, a.y, a.z].map(&bits) == [b.x, b.y, b.z].map(&bits)
                };
                assert!(same(back, v), "{}: {json}", S::PRECISION.scalar.name());
                let mut cbor = Vec::new();
                ciborium::into_writer(&v, &mut cbor).unwrap();
                let back: Vec3<S> = ciborium::from_reader(cbor.as_slice()).unwrap();
                assert!(
                    same(back, v),
                    "{}: cbor of {json}",
                    S::PRECISION.scalar.name()
                );
            }
        }
        check::<f64>(f64::from_bits, f64::to_bits);
        check::<f32>(|b| f32::from_bits(b as u32), |v| v.to_bits() as u64);
        check::<fixed::types::I32F32>(
            |b| fixed::types::I32F32::from_bits(b as i64),
            |v| v.to_bits() as u64,
        );
        check::<I16F16>(
            |b| I16F16::from_bits(b as i32),
            |v| v.to_bits() as u32 as u64,
        );
    }

    /// A contact's edge or vertex number read back is 0, 1 or 2 (an `Edge(9)` was taken as
    /// it came); every real contact round-trips.
    #[test]
    fn contacts_beyond_the_third_edge_or_vertex_are_refused() {
        use ballcast::Contact;
        let real = [
            Contact::Face,
            Contact::Edge(0),
            Contact::Edge(2),
            Contact::Vertex(1),
        ];
        for c in real {
            let json = serde_json::to_string(&c).unwrap();
            assert_eq!(serde_json::from_str::<Contact>(&json).unwrap(), c, "{json}");
        }
        for bad in [r#"{"Edge":9}"#, r#"{"Vertex":3}"#] {
            let err = serde_json::from_str::<Contact>(bad).unwrap_err();
            assert!(err.to_string().contains("edge or vertex number"), "{err}");
        }
    }

    /// A slide read back carries unit normals, as its `clip` and `floor` take them: a contact's
    /// normal or plane of another length (or NaN) is refused, naming it. (Read as it came, a
    /// normal of (0, -4096, -6.2) overflowed `clip` in `I16F16`, and one of (0, 2, 0) clipped a
    /// velocity to twice what it should.) A real slide round-trips in every scalar.
    #[test]
    fn slides_with_normals_of_other_lengths_are_refused() {
        fn check<S: ballcast::Scalar>() {
            let v =
                |x: f64, y: f64, z: f64| Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z));
            let out = ballcast::move_and_slide(
                &floor::<S>(),
                v(1.0, 0.6, 0.5),
                v(0.3, -0.5, 0.0),
                S::from_f64(0.5),
            )
            .unwrap();
            assert!(out.contacts[0].is_some());
            let json = serde_json::to_string(&out).unwrap();
            assert_eq!(
                serde_json::from_str::<ballcast::Slide<S>>(&json).unwrap(),
                out
            );
            let mut value: serde_json::Value = serde_json::from_str(&json).unwrap();
            value["contacts"][0]["hit"]["normal"]["y"] = serde_json::json!(2.0);
            let err = serde_json::from_value::<ballcast::Slide<S>>(value.clone()).unwrap_err();
            assert!(
                err.to_string()
                    .contains("squared length of a contact's normal"),
                "{err}"
            );
            value["contacts"][0]["hit"]["normal"]["y"] = serde_json::json!(1.0);
            value["contacts"][0]["hit"]["planes"][0]["z"] = serde_json::json!(0.5);
            let err = serde_json::from_value::<ballcast::Slide<S>>(value).unwrap_err();
            assert!(
                err.to_string()
                    .contains("squared length of a contact's normal"),
                "{err}"
            );
        }
        check::<f32>();
        check::<f64>();
        check::<I16F16>();
        check::<fixed::types::I32F32>();
    }

    /// Feature bits read back are those `Features::bits` gives: more than the six features is
    /// refused (it read into a mask that compared unequal to every real one).
    #[test]
    fn feature_bits_beyond_the_six_are_refused() {
        use ballcast::Features;
        for bits in 0..64u8 {
            let f = Features::from_bits(bits);
            let json = serde_json::to_string(&f).unwrap();
            assert_eq!(serde_json::from_str::<Features>(&json).unwrap(), f);
        }
        for bits in [64u8, 128, 255] {
            let err = serde_json::from_str::<Features>(&bits.to_string()).unwrap_err();
            assert!(err.to_string().contains("feature bits"), "{err}");
        }
    }
}
