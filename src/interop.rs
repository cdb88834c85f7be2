//! Conversions to and from other crates' types, each behind its cargo feature (all off by
//! default): `mint` (the math-interop convention), `glam`, and `serde` for scenes, which
//! re-validate every triangle on the way in. `defmt::Format` (feature `defmt`) is derived on the
//! types themselves.

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
mod serde_impls {
    use crate::{Scalar, Scene, Triangle};
    use serde::de::Error as _;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    /// A scene is its triangles in order, each with its sidedness; active edges are recomputed.
    impl<S: Scalar + Serialize, const N: usize> Serialize for Scene<S, N> {
        fn serialize<Z: Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
            z.collect_seq(self.sources().zip(self.sidedness()))
        }
    }

    /// Deserializing pushes every triangle again, so a scene that comes in is as validated as
    /// one built by hand: a degenerate or out-of-range triangle, or too many, is an error.
    impl<'de, S: Scalar + Deserialize<'de>, const N: usize> Deserialize<'de> for Scene<S, N> {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            let list = heapless::Vec::<(Triangle<S>, bool), N>::deserialize(d)?;
            let mut scene = Scene::new();
            for (t, two_sided) in list {
                let pushed = if two_sided {
                    scene.push_two_sided(t)
                } else {
                    scene.push(t)
                };
                pushed.map_err(D::Error::custom)?;
            }
            Ok(scene)
        }
    }
}
