//! What a collision query returns.

use crate::Vec3;

/// A contact found along a sweep: a plain `Copy` struct.
///
/// `alpha` is the fraction of the path travelled before contact, `0 <= alpha < 1`; a query that
/// finds nothing returns `None`, the notes' alpha = 1. `normal` is the unit contact normal in
/// world orientation, facing the ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit<S> {
    /// Fraction of the path from `p0` to `p1` travelled at first contact, in `[0, 1)`.
    pub alpha: S,
    /// Unit contact normal in world orientation, pointing towards the ball's centre.
    pub normal: Vec3<S>,
}
