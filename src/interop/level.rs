//! A [`Scene`] with serde: a level file, read into any scalar (see the [module docs](super)).

use super::number::RawVec;
use crate::{Error, Scalar, Scene, Triangle};
use core::fmt;
use core::marker::PhantomData;
use serde::de::{Error as _, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A triangle as read, each coordinate any number.
#[derive(Deserialize)]
#[serde(rename = "Triangle")]
struct RawTriangle {
    v0: RawVec,
    v1: RawVec,
    v2: RawVec,
}

impl RawTriangle {
    fn to<S: Scalar>(&self) -> Result<Triangle<S>, Error> {
        Ok(Triangle::new(self.v0.to()?, self.v1.to()?, self.v2.to()?))
    }
}

/// A scene is its triangles in order, each with its sidedness; active edges are recomputed.
impl<S: Scalar, const N: usize> Serialize for Scene<S, N> {
    fn serialize<Z: Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
        z.collect_seq(self.sources().zip(self.sidedness()))
    }
}

/// Deserializing pushes every triangle again, so a scene that comes in is as validated as one
/// built by hand: a coordinate the scalar cannot hold, a degenerate triangle, or one too many
/// is an error naming the triangle.
impl<'de, S: Scalar, const N: usize> Deserialize<'de> for Scene<S, N> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_seq(Level(PhantomData))
    }
}

struct Level<S, const N: usize>(PhantomData<S>);

impl<'de, S: Scalar, const N: usize> Visitor<'de> for Level<S, N> {
    type Value = Scene<S, N>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a sequence of [triangle, two-sided] pairs")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Scene<S, N>, A::Error> {
        let mut scene = Scene::new();
        while let Some((raw, two_sided)) = seq.next_element::<(RawTriangle, bool)>()? {
            let index = scene.len();
            let t = raw.to().map_err(|e| A::Error::custom(e.at(index)))?;
            scene.push_sided(t, two_sided).map_err(A::Error::custom)?;
        }
        Ok(scene)
    }
}
