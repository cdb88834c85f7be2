//! What a collision query returns.

use crate::Vec3;

/// Which feature of a triangle the ball touched.
///
/// Edge `i` runs from vertex `i` to vertex `i + 1` (mod 3): edge 0 is v0–v1, edge 1 is v1–v2,
/// edge 2 is v2–v0.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "ContactRead"))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Contact {
    /// The face's interior or boundary, touched by the ball's flat side: the normal is the face's.
    Face,
    /// The interior of edge `i`.
    Edge(u8),
    /// Vertex `i`.
    Vertex(u8),
}

/// A [`Contact`] as read (with `serde`), before its edge or vertex number is checked.
#[cfg(feature = "serde")]
#[derive(serde::Deserialize)]
#[serde(rename = "Contact")]
enum ContactRead {
    Face,
    Edge(u8),
    Vertex(u8),
}

/// An edge or vertex number beyond 2 is refused ([`Input::FeatureIndex`](crate::Input::FeatureIndex)).
#[cfg(feature = "serde")]
impl TryFrom<ContactRead> for Contact {
    type Error = crate::Error;
    fn try_from(c: ContactRead) -> Result<Self, crate::Error> {
        let (contact, i) = match c {
            ContactRead::Face => return Ok(Contact::Face),
            ContactRead::Edge(i) => (Contact::Edge(i), i),
            ContactRead::Vertex(i) => (Contact::Vertex(i), i),
        };
        if i > 2 {
            return Err(crate::Error::OutOfRange {
                input: crate::Input::FeatureIndex,
                value: i as f64,
                min: 0.0,
                max: 2.0,
                triangle: None,
            });
        }
        Ok(contact)
    }
}

/// A contact found along a sweep: a plain `Copy` struct.
///
/// `alpha` is the fraction of the path travelled before contact, `0 <= alpha < 1`; a query that
/// finds nothing returns `None`, the course notes' alpha = 1. `normal` is the unit contact normal in
/// world orientation, from the touched feature towards the ball's centre.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
pub struct Hit<S> {
    /// Fraction of the path from `p0` to `p1` travelled at first contact, in `[0, 1)`.
    #[doc(alias = "time_of_impact")]
    #[cfg_attr(feature = "serde", serde(with = "crate::interop::number"))]
    pub alpha: S,
    /// The ball's centre at first contact, `p0 + alpha (p1 - p0)` computed from alpha before
    /// it is rounded: its error is a few steps of `S`, not alpha's step times the path. For a
    /// float's face contact the centre's height is measured once more where it is and the
    /// centre moved along the plane's normal to height `r`, so the rounding of the path's far
    /// ends does not reach it either: it lies at alpha's point, off it along the normal by what
    /// alpha carries of that rounding, never along the path.
    pub position: Vec3<S>,
    /// Unit contact normal in world orientation, pointing towards the ball's centre.
    pub normal: Vec3<S>,
    /// The feature touched.
    pub contact: Contact,
}
