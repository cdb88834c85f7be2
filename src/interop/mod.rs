//! Conversions to and from other crates' types, each behind its cargo feature (all off by
//! default): `mint` (the math-interop convention), `glam` (0.33 and 0.34), and `serde`.
//! `defmt::Format` (feature `defmt`) is derived on the types themselves.
//!
//! With `serde`, every scalar is written as a plain number, so one level file serves every
//! scalar: `f32` as `f32`, `f64` and fixed point as `f64` (exact for `I16F16`, and for `I32F32`
//! within `±2^21`; an `I32F32` value with more than 53 significant bits is written as the pair
//! `[rounded, rest]`, both exact, so it still reads back bit for bit). Any number (integer,
//! float, or such a pair) reads into any scalar; one the scalar cannot hold within its safe
//! range is refused with [`Error::OutOfRange`](crate::Error::OutOfRange) or
//! [`Error::NaN`](crate::Error::NaN), never saturated. Binary formats (not human-readable, such
//! as postcard) get every scalar as the pair, exact in every scalar. Bit for bit needs a reader
//! that rounds decimal numbers correctly: `serde_json` does with its `float_roundtrip` feature,
//! and without it reads some `f64` (and so some `I32F32`) values a step off, silently: a
//! lockstep game that sends state as JSON must turn that feature on. A [`Scene`](crate::Scene)
//! is its triangles in order, each with its sidedness; reading one pushes every triangle again
//! (active edges are recomputed), and an error names the triangle's index. A
//! [`SceneHit`](crate::SceneHit) (and so a [`Slide`](crate::Slide) or a saved floor contact)
//! read back must carry unit normals and planes, as the response takes them: another length is
//! refused ([`Input::NormalLength`](crate::Input::NormalLength)).

#[cfg(feature = "mint")]
mod mint_impls {
    use crate::Vec3;

    impl<T> From<mint::Vector3<T>> for Vec3<T> {
        fn from(v: mint::Vector3<T>) -> Self {
            Vec3::new(v.x, v.y, v.z)
        }
    }

    impl<T> From<Vec3<T>> for mint::Vector3<T> {
        fn from(v: Vec3<T>) -> Self {
            mint::Vector3 {
                x: v.x,
                y: v.y,
                z: v.z,
            }
        }
    }
}

#[cfg(feature = "glam")]
mod glam_impls {
    use crate::Vec3;

    impl From<glam::Vec3> for Vec3<f32> {
        fn from(v: glam::Vec3) -> Self {
            Vec3::new(v.x, v.y, v.z)
        }
    }

    impl From<Vec3<f32>> for glam::Vec3 {
        fn from(v: Vec3<f32>) -> Self {
            glam::Vec3::new(v.x, v.y, v.z)
        }
    }

    impl From<glam::DVec3> for Vec3<f64> {
        fn from(v: glam::DVec3) -> Self {
            Vec3::new(v.x, v.y, v.z)
        }
    }

    impl From<Vec3<f64>> for glam::DVec3 {
        fn from(v: Vec3<f64>) -> Self {
            glam::DVec3::new(v.x, v.y, v.z)
        }
    }
}

#[cfg(feature = "serde")]
pub(crate) mod hit;
#[cfg(feature = "serde")]
mod level;
#[cfg(feature = "serde")]
pub(crate) mod number;
