//! Errors that say where: the argument refused, the triangle's index, the offending value and
//! the limit it broke, NaN as its own cause, and a sentence from `Display`.

mod common;

use ballcast::slide::Character;
use ballcast::{
    Error, Input, Scalar, Scene, Slider, StandardSweep, Sweep, Triangle, Vec3, move_and_slide,
    penetration, winding,
};
use common::v;
use fixed::types::{I16F16, I32F32};

fn floor<S: Scalar>(x: f64) -> Triangle<S> {
    Triangle::new(v([x, 0.0, 0.0]), v([x, 0.0, 1.0]), v([x + 1.0, 0.0, 0.0]))
}

/// The scene's push of a degenerate triangle after many good ones names the index it would
/// have had, in the value and in the sentence.
fn push_of_degenerate_triangle_names_its_index<S: Scalar>() {
    let mut scene: Scene<S, 64> = Scene::new();
    for i in 0..40 {
        scene.push(floor(2.0 * f64::from(i))).unwrap();
    }
    let p = v::<S>([1.0, 2.0, 3.0]);
    let e = scene.push(Triangle::new(p, p, v([0.0; 3]))).unwrap_err();
    assert_eq!(e, Error::Degenerate { triangle: Some(40) });
    assert_eq!(
        e.to_string(),
        "triangle 40: degenerate (coincident or collinear vertices)"
    );
    // Nothing was added: the next good triangle still gets index 40.
    assert_eq!(scene.push(floor(100.0)), Ok(40));
}

/// A full scene says how many it holds.
fn full_gives_capacity<S: Scalar>() {
    let mut scene: Scene<S, 3> = Scene::new();
    for i in 0..3 {
        scene.push(floor(2.0 * f64::from(i))).unwrap();
    }
    let e = scene.push(floor(10.0)).unwrap_err();
    assert_eq!(e, Error::Full { capacity: 3 });
    assert_eq!(e.to_string(), "full: it holds 3 triangles");
}

/// An out-of-range vertex gives its value, the range, and the triangle.
fn out_of_range_vertex_gives_value_and_limit<S: Scalar>() {
    let mut scene: Scene<S, 4> = Scene::new();
    scene.push(floor(0.0)).unwrap();
    let far = 2.0 * S::LIMIT.to_f64();
    let t = Triangle::new(v([0.0; 3]), v([0.0, 0.0, 1.0]), v([far, 0.0, 0.0]));
    let l = S::LIMIT.to_f64();
    let e = scene.push(t).unwrap_err();
    assert_eq!(
        e,
        Error::OutOfRange {
            input: Input::Vertex(2),
            value: far,
            min: -l,
            max: l,
            triangle: Some(1)
        }
    );
    assert_eq!(
        e.to_string(),
        format!(
            "triangle 1: a coordinate of v2 is {far}, outside the accepted range \
             [-{l}, {l}]"
        )
    );
}

/// Every entry point names the argument it refused: each call below is given one value
/// beyond the range in one argument, all others good.
fn each_argument_is_named<S: Scalar>() {
    let far = S::from_f64(2.0 * S::LIMIT.to_f64());
    let (z, one, half) = (Vec3::<S>::ZERO, S::ONE, S::from_f64(0.5));
    let out = Vec3::new(S::ZERO, far, S::ZERO);
    // Beyond a standard frame's bound (3.5 LIMIT) too, for `StandardSweep`.
    let beyond = Vec3::new(S::ZERO, far + far, S::ZERO);
    let named = |r: Result<(), Error>| match r {
        Err(Error::OutOfRange { input, value, .. })
            if value == far.to_f64() || value == (far + far).to_f64() =>
        {
            Some(input)
        }
        _ => None,
    };
    let scene: Scene<S, 1> = Scene::new();
    let ball = Slider::new(half).unwrap();
    let dt = S::from_f64(1.0 / 60.0);
    let me = Character::new(z, half).unwrap();
    let update = |wish, gravity, dt| me.clone().update(&scene, wish, gravity, dt).map(drop);
    let (mut away, mut rushing) = (me, me);
    (away.position, rushing.velocity) = (out, out);
    let rested = move_and_slide(&scene, z, z, half).unwrap();
    let (three_quarters, half_way) = (
        S::from_f64(0.75 * S::LIMIT.to_f64()),
        S::div_pow2(S::LIMIT, 1),
    );
    let cases = [
        (Sweep::new(out, z, one).map(drop), Input::Start),
        (Sweep::new(z, out, one).map(drop), Input::End),
        (Sweep::new(z, z, far).map(drop), Input::Radius),
        (
            move_and_slide(&scene, out, z, half).map(drop),
            Input::Position,
        ),
        (
            move_and_slide(&scene, z, out, half).map(drop),
            Input::Displacement,
        ),
        (ball.with_skin(far).map(drop), Input::Skin),
        (ball.with_max_slope(out, half).map(drop), Input::Up),
        (ball.with_max_slope(Vec3::Y, far).map(drop), Input::MaxSlope),
        (
            ball.snap_to_floor(&scene, z, out, Vec3::Y, half, one)
                .map(drop),
            Input::Heading,
        ),
        (
            ball.snap_to_floor(&scene, z, z, Vec3::Y, half, far)
                .map(drop),
            Input::Snap,
        ),
        (me.with_step(far).map(drop), Input::Step),
        (
            ball.step_slide(&scene, z, z, Vec3::Y, half, far).map(drop),
            Input::Step,
        ),
        (
            ball.walk(&scene, z, z, Some(out), (Vec3::Y, half), one)
                .map(drop),
            Input::Floor,
        ),
        (
            ball.snap_to_floor(&scene, out, z, Vec3::Y, half, one)
                .map(drop),
            Input::Position,
        ),
        (rested.clip(out).map(drop), Input::Velocity),
        (StandardSweep::new(beyond, z, one).map(drop), Input::Start),
        (StandardSweep::new(z, beyond, one).map(drop), Input::End),
        (away.update(&scene, z, z, dt).map(drop), Input::Position),
        (rushing.update(&scene, z, z, dt).map(drop), Input::Velocity),
        (update(out, z, dt), Input::Wish),
        (update(z, out, dt), Input::Gravity),
        (update(z, z, far), Input::TimeStep),
        (penetration(&scene, out, half).map(drop), Input::Position),
        (winding(&scene, out).map(drop), Input::Point),
        (out.cast::<f64>().try_cast::<S>().map(drop), Input::Number),
    ];
    for (k, (result, input)) in cases.into_iter().enumerate() {
        assert_eq!(
            named(result),
            Some(input),
            "{} case {k}",
            core::any::type_name::<S>()
        );
    }
    // A move whose target (position + displacement) leaves the range, each part within it.
    let e = move_and_slide(
        &scene,
        Vec3::new(S::ZERO, three_quarters, S::ZERO),
        Vec3::new(S::ZERO, half_way, S::ZERO),
        half,
    );
    assert_eq!(e.map(drop).unwrap_err().input(), Some(Input::Target));
    let e = ball.with_max_slope(z, half).unwrap_err();
    assert_eq!(e, Error::ZeroVector { input: Input::Up });
    assert_eq!(e.to_string(), "the up direction is the zero vector");
    let e = ball.walk(&scene, z, z, Some(z), (Vec3::Y, half), one);
    assert_eq!(
        e.unwrap_err().to_string(),
        "the floor's normal is the zero vector"
    );
    // A floor facing down (here straight down) is a ceiling: refused, with its cosine.
    let down = Vec3::new(S::ZERO, S::ZERO - one, S::ZERO);
    let e = ball.walk(&scene, z, z, Some(down), (Vec3::Y, half), one);
    assert_eq!(
        e.unwrap_err().to_string(),
        "the cosine of the floor's normal with up is -1, outside the accepted range [0, 1]"
    );
    let e = Sweep::new(z, out, one).unwrap_err();
    let l = S::LIMIT.to_f64();
    let said = format!(
        "a coordinate of the end is {}, outside the accepted range [-{l}, {l}]",
        far.to_f64()
    );
    assert_eq!(e.to_string(), said);
}

/// A NaN coordinate reads as NaN, not as out of range, for every entry point that takes one.
fn nan_is_its_own_cause<S: Scalar>() {
    let (z, nan) = (Vec3::new(0.0, 0.0, 0.0), S::from_f64(f64::NAN));
    let p: Vec3<S> = z.cast();
    let bad = Vec3::new(S::ZERO, nan, S::ZERO);
    let e = |input| Error::NaN {
        input,
        triangle: None,
    };
    assert_eq!(Sweep::new(p, bad, S::ONE).unwrap_err(), e(Input::End));
    assert_eq!(Slider::new(nan).unwrap_err(), e(Input::Radius));
    let scene: Scene<S, 1> = Scene::new();
    let moved = move_and_slide(&scene, p, bad, S::ONE).unwrap_err();
    assert_eq!(moved, e(Input::Displacement));
    assert_eq!(moved.to_string(), "a coordinate of the displacement is NaN");
    assert_eq!(e(Input::Radius).to_string(), "the radius is NaN");
    let mut scene: Scene<S, 1> = Scene::new();
    let t = Triangle::new(p, bad, v([1.0, 0.0, 0.0]));
    let pushed = scene.push(t).unwrap_err();
    assert_eq!(pushed, e(Input::Vertex(1)).at(0));
    assert_eq!(pushed.to_string(), "triangle 0: a coordinate of v1 is NaN");
}

/// Negative radius and a radius too small for the scalar give the value (and the limit), and
/// name the radius as the argument refused (`Error::input` once gave nothing for them).
fn radius_errors_give_the_radius<S: Scalar>() {
    let scene: Scene<S, 1> = Scene::new();
    let z = v::<S>([0.0; 3]);
    let e = move_and_slide(&scene, z, z, S::from_f64(-1.0)).unwrap_err();
    assert_eq!(e, Error::NegativeRadius { value: -1.0 });
    assert_eq!(e.to_string(), "the radius -1 is negative");
    assert_eq!(e.input(), Some(Input::Radius));
    let e = Sweep::new(z, z, S::from_f64(-1.0)).unwrap_err();
    assert_eq!(e.input(), Some(Input::Radius));
    let tiny = S::EPSILON;
    let e = move_and_slide(&scene, z, z, tiny).unwrap_err();
    let min = ballcast::slide::min_radius(S::ZERO).to_f64();
    assert_eq!(
        e,
        Error::RadiusTooSmall {
            radius: tiny.to_f64(),
            min,
            extent: 0.0
        }
    );
    assert!(e.to_string().starts_with("the radius "), "{e}");
    assert_eq!(e.input(), Some(Input::Radius));
}

/// An `f32` value reads as typed: a radius of -0.4 is -0.4 in the message, not the `f64` it
/// widens to (-0.4000000059604645, as it read), and so is a time step of -0.016 (-0.01600000075995922).
#[test]
fn f32_values_read_as_typed() {
    let scene: Scene<f32, 1> = Scene::new();
    let e = move_and_slide(&scene, Vec3::ZERO, Vec3::ZERO, -0.4).unwrap_err();
    assert_eq!(e.to_string(), "the radius -0.4 is negative");
    let mut me = ballcast::slide::Character::new(Vec3::ZERO, 0.5f32).unwrap();
    let e = me
        .update(&scene, Vec3::ZERO, Vec3::ZERO, -0.016)
        .unwrap_err();
    let said = e.to_string();
    assert!(said.starts_with("the time step is -0.016, "), "{said}");
    // Also under gravity, whose longest step (1307.75...) is worked out in `f64` and is no
    // `f32`: the step read -0.01600000075995922 there.
    let gravity = Vec3::new(0.0, -9.81f32, 0.0);
    let e = me.update(&scene, Vec3::ZERO, gravity, -0.016).unwrap_err();
    let said = e.to_string();
    assert!(said.starts_with("the time step is -0.016, "), "{said}");
    // The limit keeps its `f64` digits: the root of 9.81 t² = 2^24, to the last bit or so.
    let max: f64 = said
        .rsplit_once("[0, ")
        .and_then(|(_, m)| m.strip_suffix(']'))
        .and_then(|m| m.parse().ok())
        .unwrap_or_else(|| panic!("no limit in {said}"));
    let root = (16_777_216.0 / f64::from(9.81f32)).sqrt();
    assert!(
        (max - root).abs() <= 1e-12 * root && max as f32 as f64 != max,
        "{said}"
    );
    // An `f64` that is no `f32` keeps its own digits.
    let scene: Scene<f64, 1> = Scene::new();
    let e = move_and_slide(&scene, Vec3::ZERO, Vec3::ZERO, -0.1).unwrap_err();
    assert_eq!(e.to_string(), "the radius -0.1 is negative");
    // So do all the values of its message: an `f64` radius just below a limit that is an
    // `f32`, typed as that `f32`'s digits, read alike when the limit alone took them.
    let min = 3.0 * 2f64.powi(-46);
    let radius: f64 = (min as f32).to_string().parse().unwrap();
    assert!(radius < min);
    let e = Error::RadiusTooSmall {
        radius,
        min,
        extent: 3.0,
    };
    assert_eq!(
        e.to_string(),
        "the radius 4.2632564e-14 is below 4.263256414560601e-14, the smallest the scalar \
         resolves at coordinates up to 3 (where the ball is or goes)"
    );
    // A subnormal `f32` in its `f64` digits: as an `f32` it printed 1e-45, 40 % off.
    let tiny = -f64::from(f32::from_bits(1));
    let e = Error::NegativeRadius { value: tiny };
    assert_eq!(e.to_string(), format!("the radius {tiny:e} is negative"));
}

/// Two values of one message never read alike: the `f32` whose shortest digits are
/// `7.038531e-26` and the `f64` those digits read as, which rounds to the next `f32` up (the
/// digits lie next to the midpoint between the two), read `7.038531e-26` both when only the
/// `f64` rounding to the `f32` counted as a clash.
#[test]
fn an_f32_and_the_f64_of_its_digits_read_apart() {
    let v = f32::from_bits(0x15ae_43fd);
    let w: f64 = v.to_string().parse().unwrap();
    assert_eq!(v.to_string(), "0.00000000000000000000000007038531");
    assert_ne!(
        w as f32, v,
        "the case: its digits' f64 rounds to another f32"
    );
    let e = Error::RadiusTooSmall {
        radius: f64::from(v),
        min: w,
        extent: 1e-18,
    };
    let said = e.to_string();
    let (radius, rest) = said
        .strip_prefix("the radius ")
        .and_then(|r| r.split_once(" is below "))
        .unwrap_or_else(|| panic!("{said}"));
    let min = rest.split_once(',').map_or(rest, |(m, _)| m);
    assert_ne!(radius, min, "{said}");
    // Each reads back as itself.
    assert_eq!(radius.parse::<f64>().ok(), Some(f64::from(v)), "{said}");
    assert_eq!(min.parse::<f64>().ok(), Some(w), "{said}");
}

/// Huge and tiny values read in exponent form, as JavaScript prints them (from 10^21 up, below
/// 10^-7): a radius of 1e300 read as 301 digits, and f32::MAX as 39.
#[test]
fn huge_and_tiny_values_read_in_exponent_form() {
    let p = Vec3::new(0.0f64, 0.0, 0.0);
    let e = Sweep::new(p, p, 1e300).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the radius is 1e300, outside the accepted range [0, 9007199254740992]"
    );
    let e = Sweep::new(p, p, -1e-300).unwrap_err();
    assert_eq!(e.to_string(), "the radius -1e-300 is negative");
    let q = Vec3::new(f32::MAX, 0.0, 0.0);
    let e = Sweep::new(Vec3::ZERO, q, 0.5f32).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a coordinate of the end is 3.4028234663852886e38, outside the accepted range \
         [-16777216, 16777216]"
    );
    let shape = ballcast::HeightfieldShape {
        origin: Vec3::new(0.0f64, 0.0, 0.0),
        spacing: 1e300,
        unit: 1.0,
        columns: 1,
        rows: 1,
    };
    let e = ballcast::Heightfield::build(shape, &[0; 4], |_, _| false, &mut [0; 1]).unwrap_err();
    assert!(
        e.to_string().starts_with("heightfield reaches 1e300 "),
        "{e}"
    );
}

/// A ball too small at any coordinates is refused when it is made, not at its first slide: a
/// zero radius, or one below the smallest the response accepts at the origin. (`Slider::new`
/// took both, and every slide then failed.) A radius fine at the origin is taken.
fn slider_refuses_a_radius_too_small_anywhere<S: Scalar>() {
    let min = ballcast::slide::min_radius(S::ZERO);
    for r in [S::ZERO, S::EPSILON, min - S::EPSILON] {
        assert_eq!(
            Slider::new(r),
            Err(Error::RadiusTooSmall {
                radius: r.to_f64(),
                min: min.to_f64(),
                extent: 0.0
            })
        );
    }
    let ball = Slider::new(min).unwrap();
    let scene: Scene<S, 1> = Scene::new();
    let z = v::<S>([0.0; 3]);
    assert!(ball.slide(&scene, z, v([1.0, 0.0, 0.0])).is_ok());
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)] // the fixed-point types, unused where $t is a float
        use super::*;
        #[test] fn push_of_degenerate_triangle_names_its_index() {
            super::push_of_degenerate_triangle_names_its_index::<$t>()
        }
        #[test] fn full_gives_capacity() { super::full_gives_capacity::<$t>() }
        #[test] fn out_of_range_vertex_gives_value_and_limit() {
            super::out_of_range_vertex_gives_value_and_limit::<$t>()
        }
        #[test] fn radius_errors_give_the_radius() { super::radius_errors_give_the_radius::<$t>() }
        #[test] fn slider_refuses_a_radius_too_small_anywhere() {
            super::slider_refuses_a_radius_too_small_anywhere::<$t>()
        }
        #[test] fn each_argument_is_named() { super::each_argument_is_named::<$t>() }
    })*};
}
per_scalar!(f32_: f32, f64_: f64, i16f16: I16F16, i32f32: I32F32);

/// Fixed point has no NaN: only the floats can carry one in.
#[test]
fn nan_is_its_own_cause_f32() {
    nan_is_its_own_cause::<f32>();
}
#[test]
fn nan_is_its_own_cause_f64() {
    nan_is_its_own_cause::<f64>();
}

/// A NaN converted to fixed point becomes its largest value (`from_f64` saturates, so the
/// value is refused rather than read as zero): the sentence says that its value is such an
/// extreme, where the number alone (32767.99998474121) would not tell a porter what happened.
/// A value the caller gave is not so marked.
#[test]
fn nan_converted_to_fixed_point_is_named_a_saturated_extreme() {
    fn case<S: Scalar>() {
        let nan = Vec3::new(S::from_f64(f64::NAN), S::ONE, S::ZERO);
        let e = Character::new(nan, S::from_f64(0.5)).unwrap_err();
        assert_eq!(e.input(), Some(Input::Position));
        assert!(e.to_string().contains("saturates"), "{e}");
        let far = Vec3::new(S::from_f64(2.0 * S::LIMIT.to_f64()), S::ONE, S::ZERO);
        let e = Character::new(far, S::from_f64(0.5)).unwrap_err();
        assert!(!e.to_string().contains("saturates"), "{e}");
    }
    case::<I16F16>();
    case::<I32F32>();
}
