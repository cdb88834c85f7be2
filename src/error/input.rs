//! Which argument an [`Error`] is about: [`Input`], named as the calls name it.

#[cfg(doc)]
use super::Error;
use core::fmt;

/// The argument an [`Error::NaN`], [`Error::OutOfRange`] or [`Error::ZeroVector`] is about,
/// named as the calls name it. For a vector, the error is about one of its coordinates (the
/// first refused, in the order x, y, z), whose value [`Error::OutOfRange`] gives.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Input {
    /// Vertex `v0`, `v1` or `v2` of a triangle, by its number (the error gives the triangle's
    /// index where it was one of many; in an index buffer, the triangle's corner, not the
    /// vertex array's index).
    Vertex(u8),
    /// A sweep's start, `p0`.
    Start,
    /// A sweep's end, `p1`.
    End,
    /// A ball's radius.
    Radius,
    /// A ball's centre: where a slide, a character or a query around a ball starts.
    Position,
    /// A slide's displacement.
    Displacement,
    /// Where a slide would end with nothing in its way: its position (after any push out of
    /// an overlap) plus its displacement.
    Target,
    /// A velocity to clip.
    Velocity,
    /// The up direction of a floor rule.
    Up,
    /// The normal of the floor a walk keeps to.
    Floor,
    /// How the floor a walk keeps to faces: the cosine of its normal with up, which must not
    /// be negative (a floor facing down is a ceiling).
    FloorFacing,
    /// The cosine of the steepest slope taken for a floor.
    MaxSlope,
    /// The gap a ball keeps from what it touches.
    Skin,
    /// The highest ledge a ball steps onto.
    Step,
    /// How far below a ball a floor is looked for and snapped to.
    Snap,
    /// The heading given to the snap (the ball's velocity).
    Heading,
    /// A point asked about (by [`winding()`](crate::winding()) or a standard frame).
    Point,
    /// A character's wished velocity.
    Wish,
    /// The speed of a character's jump.
    JumpSpeed,
    /// A character's acceleration towards its wish in the air.
    AirControl,
    /// The acceleration of gravity.
    Gravity,
    /// A time step.
    TimeStep,
    /// A number converted to the scalar (read from a file, or from another scalar).
    Number,
    /// A triangle's [`Features`](crate::Features) bits read back (six: three edges, three
    /// vertices).
    Features,
    /// The number of the edge or vertex of a [`Contact`](crate::Contact) read back (0 to 2).
    FeatureIndex,
    /// A contact's normal, or one of its planes, read back (a [`SceneHit`](crate::SceneHit)
    /// with `serde`): its coordinates.
    Normal,
    /// The squared length of a contact's normal or plane read back, which must be one within
    /// `2e-4` ([`Vec3::is_normalized`](crate::Vec3::is_normalized)).
    NormalLength,
}

impl Input {
    /// What the input is, as the error's sentence names it, and whether it is a vector.
    pub(super) const fn noun(self) -> (&'static str, bool) {
        match self {
            Input::Vertex(0) => ("v0", true),
            Input::Vertex(1) => ("v1", true),
            Input::Vertex(2) => ("v2", true),
            Input::Vertex(_) => ("a vertex", true),
            Input::Start => ("the start", true),
            Input::End => ("the end", true),
            Input::Radius => ("the radius", false),
            Input::Position => ("the position", true),
            Input::Displacement => ("the displacement", true),
            Input::Target => ("the target (position + displacement)", true),
            Input::Velocity => ("the velocity", true),
            Input::Up => ("the up direction", true),
            Input::Floor => ("the floor's normal", true),
            Input::FloorFacing => ("the cosine of the floor's normal with up", false),
            Input::MaxSlope => ("the cosine of the steepest slope", false),
            Input::Skin => ("the skin", false),
            Input::Step => ("the step height", false),
            Input::Snap => ("the snap depth", false),
            Input::Heading => ("the heading", true),
            Input::Point => ("the point", true),
            Input::Wish => ("the wished velocity", true),
            Input::JumpSpeed => ("the jump speed", false),
            Input::AirControl => ("the air control", false),
            Input::Gravity => ("gravity", true),
            Input::TimeStep => ("the time step", false),
            Input::Number => ("the number", false),
            Input::Features => ("the feature bits", false),
            Input::FeatureIndex => ("the edge or vertex number", false),
            Input::Normal => ("a contact's normal", true),
            Input::NormalLength => ("the squared length of a contact's normal", false),
        }
    }
}

impl fmt::Display for Input {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.noun() {
            (noun, true) => write!(f, "a coordinate of {noun}"),
            (noun, false) => f.write_str(noun),
        }
    }
}
