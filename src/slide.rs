//! Collision response: move a ball through a [`Scene`](crate::Scene), sliding along what it touches.

use crate::contact::unit;
use crate::{Error, Geometry, Scalar, SceneHit, Sweep, Vec3, check, vec3::cross};
use heapless::Vec;

/// At most this many sweeps per call: each contact costs one, and a ball pressed into a corner
/// of three planes has nowhere left to go after three.
pub const MAX_SLIDES: usize = 4;

/// The outcome of [`move_and_slide`]: a plain `Copy` struct.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slide<S> {
    /// Where the ball's centre ends.
    pub position: Vec3<S>,
    /// The part of the requested displacement not travelled: what the contacts took away.
    pub blocked: Vec3<S>,
    /// The contacts met, in order (at most [`MAX_SLIDES`]).
    pub contacts: [Option<SceneHit<S>>; MAX_SLIDES],
}

impl<S: Scalar> Slide<S> {
    /// Removes from `velocity` every component pointing into a contact's normal, in contact
    /// order: what a caller does to its velocity after the move. Never lengthens it by more
    /// than rounding.
    ///
    /// Errors: [`Error::NonFinite`] or [`Error::OutOfRange`] for a velocity component beyond
    /// `±`[`Scalar::LIMIT`].
    pub fn clip(&self, velocity: Vec3<S>) -> Result<Vec3<S>, Error> {
        let mut v = check::point(velocity, S::LIMIT)?;
        for hit in self.contacts.iter().flatten() {
            v = remove_into(v, hit.normal);
        }
        Ok(v)
    }
}

/// `v` without its component into `n` (unit): unchanged if `v` does not point into `n`.
fn remove_into<S: Scalar>(v: Vec3<S>, n: Vec3<S>) -> Vec3<S> {
    let into = v.dot(n);
    if into < S::ZERO { v - n * into } else { v }
}

/// Moves a ball of `radius` from `position` by `displacement` through `scene` (a [`Scene`](crate::Scene)
/// or a slice of prepared triangles): it travels to
/// the first contact, loses the part of the remaining motion that points into the contact
/// normal, and continues with the rest, for at most [`MAX_SLIDES`] sweeps.
///
/// Where the new direction would run into a previous contact's plane, the motion follows the
/// crease of the two planes; against a third plane it stops. After each contact the ball is
/// lifted off the surface by a skin of `radius / 1024 + 4 EPSILON` along the normal, so the
/// next sweep does not meet the same plane again at once through rounding. Apart from those
/// skins, the motion's length never grows, so a slide cannot gain speed. A ball that starts overlapping geometry is not pushed out, but
/// cannot move further in (see [`StandardTriangle::cast`](crate::StandardTriangle::cast)).
///
/// Errors: [`Error::NonFinite`] or [`Error::OutOfRange`] when `position`, `displacement` or the
/// target is outside `±`[`Scalar::LIMIT`], [`Error::NegativeRadius`]; checked before any
/// arithmetic, so fixed-point cannot overflow.
///
/// ```
/// use ballcast::{Scene, Triangle, Vec3, move_and_slide};
/// let v = Vec3::new;
/// let mut s: Scene<f64, 4> = Scene::new();
/// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
/// // Thrown down and sideways at a floor: it stops at the floor and slides the rest sideways,
/// // resting a skin (0.5 / 1024 + 4 EPSILON) above it.
/// let out = move_and_slide(&s, v(0.0, 1.0, 0.0), v(2.0, -2.0, 0.0), 0.5)?;
/// assert_eq!(out.position.x, 2.0);
/// assert!((out.position.y - 0.5 - 0.5 / 1024.0).abs() < 1e-12);
/// assert_eq!(out.blocked, v(0.0, -1.5, 0.0));
/// # Ok::<(), ballcast::Error>(())
/// ```
pub fn move_and_slide<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    position: Vec3<S>,
    displacement: Vec3<S>,
    radius: S,
) -> Result<Slide<S>, Error> {
    // Inside these ranges `position + displacement` stays within 2 * LIMIT: no overflow.
    check::point(position, S::LIMIT)?;
    check::point(displacement, S::LIMIT)?;
    let zero = Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    let mut out = Slide {
        position,
        blocked: zero,
        contacts: [None; MAX_SLIDES],
    };
    let four = S::ONE + S::ONE + S::ONE + S::ONE;
    let skin = radius / (four * four * four * four * four) + S::EPSILON * four;
    let mut rest = displacement;
    let mut planes: Vec<Vec3<S>, MAX_SLIDES> = Vec::new();
    for slot in out.contacts.iter_mut() {
        if rest == zero {
            break;
        }
        let sweep = Sweep::new(out.position, out.position + rest, radius)?;
        let Some(hit) = scene.cast(&sweep) else {
            out.position = out.position + rest;
            rest = zero;
            break;
        };
        *slot = Some(hit);
        // Stop a skin's width short along the normal: a slide that starts exactly touching would
        // otherwise meet the same plane again at alpha 0 whenever rounding tilts it inwards.
        out.position = out.position + rest * hit.alpha + hit.normal * skin;
        let left = rest * (S::ONE - hit.alpha);
        rest = remove_into(left, hit.normal);
        // Where the slide runs back into an earlier plane, follow the crease of the two.
        for p in planes.iter() {
            if rest.dot(*p) < S::ZERO {
                rest = match unit(cross(*p, hit.normal)) {
                    Some(c) if planes.len() < 2 => c * rest.dot(c),
                    _ => zero,
                };
                break;
            }
        }
        out.blocked = out.blocked + (left - rest);
        let _ = planes.push(hit.normal);
    }
    out.blocked = out.blocked + rest;
    Ok(out)
}
