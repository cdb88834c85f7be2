//! A [`SceneHit`] read back is checked before it is taken: its normal and planes must be unit
//! vectors, as a move's response takes them (a `Slide`'s `clip` and `floor` constrain by them,
//! and a normal of another length gives a wrong velocity, or overflows fixed point).

use crate::merge::PLANES;
use crate::vec3::geometry::SQUARED_LENGTH_TOLERANCE;
use crate::{Contact, Error, Input, Scalar, SceneHit, Vec3, check};

/// A [`SceneHit`] as read, before its normals are checked.
#[derive(serde::Deserialize)]
#[serde(rename = "SceneHit", bound = "S: Scalar")]
pub(crate) struct SceneHitRead<S> {
    #[serde(with = "crate::interop::number")]
    alpha: S,
    position: Vec3<S>,
    normal: Vec3<S>,
    contact: Contact,
    index: usize,
    planes: [Option<Vec3<S>>; PLANES],
}

impl<S: Scalar> TryFrom<SceneHitRead<S>> for SceneHit<S> {
    type Error = Error;
    fn try_from(h: SceneHitRead<S>) -> Result<Self, Error> {
        let normal = unit(h.normal)?;
        for p in h.planes.iter().flatten() {
            unit(*p)?;
        }
        Ok(SceneHit {
            alpha: h.alpha,
            position: h.position,
            normal,
            contact: h.contact,
            index: h.index,
            planes: h.planes,
        })
    }
}

/// `n` if it is a unit vector ([`Vec3::is_normalized`]), else the error that says why.
fn unit<S: Scalar>(n: Vec3<S>) -> Result<Vec3<S>, Error> {
    let n = check::point(n, S::LIMIT, Input::Normal)?;
    if n.is_normalized() {
        return Ok(n);
    }
    Err(Error::OutOfRange {
        input: Input::NormalLength,
        value: n.length_squared().to_f64(),
        min: 1.0 - SQUARED_LENGTH_TOLERANCE,
        max: 1.0 + SQUARED_LENGTH_TOLERANCE,
        triangle: None,
    })
}
