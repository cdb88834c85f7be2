//! Scalars as plain numbers with serde (see the [module docs](super)): `serialize` and
//! `deserialize` for `#[serde(with = ...)]`, and [`Vec3`]'s impls built on them.

use crate::{Error, Input, Scalar, Vec3, check};
use core::fmt;
use serde::de::{self, Error as _, SeqAccess, Visitor};
use serde::ser::SerializeStruct;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A number as read: `hi + lo`, where `lo` is zero unless it came as a pair.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Number {
    hi: f64,
    lo: f64,
}

impl Number {
    /// The number in `S`, refused if `S` cannot hold it within its safe range.
    pub(crate) fn to<S: Scalar>(self) -> Result<S, Error> {
        let hi = check::convert::<S>(self.hi)?;
        if self.lo == 0.0 {
            return Ok(hi);
        }
        // Both within the range, so their sum is representable; then checked itself.
        let lo = check::convert::<S>(self.lo)?;
        check::within(hi + lo, -S::LIMIT, S::LIMIT, Input::Number)
    }
}

/// Writes `v` as a number (see the module docs).
pub(crate) fn serialize<S: Scalar, Z: Serializer>(v: &S, z: Z) -> Result<Z::Ok, Z::Error> {
    let hi = v.to_f64();
    let float = S::PRECISION.relative;
    // Fixed point: what rounding to f64 left out, exact in both.
    let lo = if float {
        0.0
    } else {
        (*v - S::from_f64(hi)).to_f64()
    };
    if !z.is_human_readable() {
        (hi, lo).serialize(z)
    } else if float && S::PRECISION.epsilon == f64::from(f32::EPSILON) {
        z.serialize_f32(hi as f32)
    } else if lo == 0.0 {
        z.serialize_f64(hi)
    } else {
        [hi, lo].serialize(z)
    }
}

/// Reads any number into `S` (see the module docs).
pub(crate) fn deserialize<'de, S: Scalar, D: Deserializer<'de>>(d: D) -> Result<S, D::Error> {
    Number::deserialize(d)?.to().map_err(D::Error::custom)
}

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        if d.is_human_readable() {
            d.deserialize_any(NumberVisitor)
        } else {
            d.deserialize_tuple(2, NumberVisitor)
        }
    }
}

struct NumberVisitor;

impl<'de> Visitor<'de> for NumberVisitor {
    type Value = Number;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number, or a pair of numbers to be added")
    }

    fn visit_f64<E: de::Error>(self, hi: f64) -> Result<Number, E> {
        Ok(Number { hi, lo: 0.0 })
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Number, E> {
        self.visit_f64(v as f64)
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Number, E> {
        self.visit_f64(v as f64)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Number, A::Error> {
        let missing = || A::Error::invalid_length(1, &"a pair of numbers");
        let hi = seq.next_element::<f64>()?.ok_or_else(missing)?;
        let lo = seq.next_element::<f64>()?.ok_or_else(missing)?;
        Ok(Number { hi, lo })
    }
}

/// A scalar to be written as a number.
struct Plain<S>(S);

impl<S: Scalar> Serialize for Plain<S> {
    fn serialize<Z: Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
        serialize(&self.0, z)
    }
}

/// A vector as read, each component any number.
#[derive(Deserialize)]
#[serde(rename = "Vec3")]
pub(crate) struct RawVec {
    x: Number,
    y: Number,
    z: Number,
}

impl RawVec {
    /// The vector in `S`, refused if a component does not fit.
    pub(crate) fn to<S: Scalar>(&self) -> Result<Vec3<S>, Error> {
        Ok(Vec3::new(self.x.to()?, self.y.to()?, self.z.to()?))
    }
}

impl<S: Scalar> Serialize for Vec3<S> {
    fn serialize<Z: Serializer>(&self, z: Z) -> Result<Z::Ok, Z::Error> {
        let mut s = z.serialize_struct("Vec3", 3)?;
        s.serialize_field("x", &Plain(self.x))?;
        s.serialize_field("y", &Plain(self.y))?;
        s.serialize_field("z", &Plain(self.z))?;
        s.end()
    }
}

/// A coordinate read straight into `S`: one that does not fit is refused while the reader is
/// at it, so a text format's error says where (serde_json: "at line L column C").
struct Coordinate<S>(S);

impl<'de, S: Scalar> Deserialize<'de> for Coordinate<S> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        deserialize(d).map(Coordinate)
    }
}

/// A vector read straight into `S`, component by component.
#[derive(Deserialize)]
#[serde(rename = "Vec3", bound = "S: Scalar")]
struct TypedVec<S> {
    x: Coordinate<S>,
    y: Coordinate<S>,
    z: Coordinate<S>,
}

impl<'de, S: Scalar> Deserialize<'de> for Vec3<S> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let TypedVec { x, y, z } = TypedVec::deserialize(d)?;
        Ok(Vec3::new(x.0, y.0, z.0))
    }
}
