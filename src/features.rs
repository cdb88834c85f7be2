//! [`Features`]: which edges and vertices of a triangle take part in a cast, and the
//! triangle's sidedness.

use crate::{Scalar, StandardTriangle};

/// Which edges and vertices of a triangle take part in [`StandardTriangle::cast`]; the face
/// always does. Inactive features model a mesh's interior: an edge shared with a coplanar
/// neighbour, or one in a valley, is never the first thing a ball touches, and testing it only
/// adds "ghost" bumps from rounding. [`Scene`](crate::Scene) computes these from adjacency.
///
/// ```
/// use ballcast::Features;
/// let f = Features::ALL.with_edge(1, false);
/// assert!(f.edge(0) && !f.edge(1) && f.vertex(1));
/// assert_eq!(Features::from_bits(f.bits()), f);
/// ```
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(try_from = "u8", into = "u8"))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Features(u8);

/// Read back (with `serde`) from [`Features::bits`]: bits beyond the six features are refused,
/// not masked, so a value read is one `bits` can give.
impl TryFrom<u8> for Features {
    type Error = crate::Error;
    fn try_from(bits: u8) -> Result<Self, crate::Error> {
        if bits & !Self::ALL.0 != 0 {
            return Err(crate::Error::OutOfRange {
                input: crate::Input::Features,
                value: bits as f64,
                min: 0.0,
                max: Self::ALL.0 as f64,
                triangle: None,
            });
        }
        Ok(Self(bits))
    }
}

impl From<Features> for u8 {
    fn from(f: Features) -> u8 {
        f.0
    }
}

impl Features {
    /// Every edge and vertex active: a lone triangle.
    pub const ALL: Self = Self(0b11_1111);
    /// Only the face: a triangle inside a flat mesh.
    pub const FACE_ONLY: Self = Self(0);

    /// From bits: bit `i` (0..3) is edge `i`, bit `3 + i` vertex `i`; other bits are ignored.
    pub const fn from_bits(bits: u8) -> Self {
        Self(bits & Self::ALL.0)
    }
    /// The bits, as taken by [`Features::from_bits`].
    pub const fn bits(self) -> u8 {
        self.0
    }
    /// Whether edge `i` (from vertex `i` to vertex `i + 1`) is active; false for `i > 2`.
    pub const fn edge(self, i: usize) -> bool {
        i < 3 && self.0 & (1 << i) != 0
    }
    /// Whether vertex `i` is active; false for `i > 2`.
    pub const fn vertex(self, i: usize) -> bool {
        i < 3 && self.0 & (8 << i) != 0
    }
    /// The same mask with edge `i` switched on or off (unchanged for `i > 2`).
    pub const fn with_edge(self, i: usize, on: bool) -> Self {
        if i > 2 {
            self
        } else {
            self.with_bit(1 << i, on)
        }
    }
    /// The same mask with vertex `i` switched on or off (unchanged for `i > 2`).
    pub const fn with_vertex(self, i: usize, on: bool) -> Self {
        if i > 2 {
            self
        } else {
            self.with_bit(8 << i, on)
        }
    }
    /// The edges of `edges`' bits 0..3 active, and each vertex with an active edge through
    /// it: vertex `v` while edge `v` or edge `v + 2` is (the active edges of a triangle in a
    /// mesh, or of a heightfield's cell byte).
    pub(crate) const fn of_edges(edges: u8) -> Self {
        let e = edges & 0b111;
        Self(e | ((e | e << 1 | e >> 2) & 0b111) << 3)
    }
    const fn with_bit(self, bit: u8, on: bool) -> Self {
        Self(if on { self.0 | bit } else { self.0 & !bit })
    }
}

impl Default for Features {
    fn default() -> Self {
        Self::ALL
    }
}

impl<S: Scalar> StandardTriangle<S> {
    /// The same triangle with only the given edges and vertices taking part in [`cast`](Self::cast).
    pub fn with_features(mut self, features: Features) -> Self {
        self.features = features;
        self
    }

    /// The edges and vertices that take part in [`cast`](Self::cast) (all, unless changed).
    pub fn features(&self) -> Features {
        self.features
    }

    /// The same triangle, one-sided (`false`, the default) or two-sided (`true`).
    ///
    /// One-sided, only a ball whose centre starts in front of the plane can touch it: the face
    /// when the ball moves towards the front (velocity · front normal < 0), an edge or vertex
    /// whatever the motion, with the centre in front at contact. Two-sided, the back behaves
    /// like a front facing the other way, and the edges and vertices count on either side.
    pub fn with_two_sided(mut self, two_sided: bool) -> Self {
        self.two_sided = two_sided;
        self
    }

    /// Whether the back face also stops balls.
    pub fn is_two_sided(&self) -> bool {
        self.two_sided
    }
}
