//! Collision response: move a ball through a [`Geometry`], sliding along what it touches.
//!
//! The rules are Quake's fly-move (`SV_FlyMove`, id Software, 1996), kept exact enough for
//! fixed point:
//! 1. Sweep the remaining motion; without contact, travel all of it.
//! 2. Travel to the contact, then step a *skin* off along the contact normal ([`skin`]).
//! 3. Collect every plane touched so far in this call, including all planes touched at the same
//!    moment ([`SceneHit::planes`]): a ball pushed into a corner meets both walls at once.
//! 4. Constrain what is left of the motion by all of them at once: remove the part into one
//!    plane if that leaves it clear of the others; else follow the crease of two planes if
//!    that does; else stop. Stop too when what is left points against the requested
//!    displacement: a ball pushed into a corner wider than 90° comes to rest instead of being
//!    bounced back out along the second wall.
//!
//! Every product and quotient rounds to nearest through the [`Scalar`] trait, so a resting ball
//! pushed into a floor does not creep along it.

use crate::merge::{PLANES, same_plane};
use crate::{Error, Geometry, Scalar, SceneHit, Sweep, Vec3, check, contact::unit};
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
    /// Constrains `velocity` by every plane the move touched, with the same rules as the move
    /// itself: what a caller does to its velocity afterwards. Never lengthens it by more than
    /// rounding, and never turns it against itself.
    ///
    /// Errors: [`Error::NonFinite`] or [`Error::OutOfRange`] for a velocity component beyond
    /// `±`[`Scalar::LIMIT`].
    pub fn clip(&self, velocity: Vec3<S>) -> Result<Vec3<S>, Error> {
        let v = check::point(velocity, S::LIMIT)?;
        let mut planes: Planes<S> = Vec::new();
        for hit in self.contacts.iter().flatten() {
            add_planes(&mut planes, hit);
        }
        Ok(constrain(v, &planes, v))
    }
}

/// The planes a call has touched: up to [`PLANES`] per contact.
type Planes<S> = Vec<Vec3<S>, { MAX_SLIDES * PLANES }>;

/// The gap kept between a ball of `radius` and what it touched, for centres within `±extent`:
/// `radius / 1024` plus twice the rounding of a height there, so that the next sweep does not
/// meet the same plane again at once through rounding.
///
/// ```
/// use ballcast::slide::skin;
/// assert_eq!(skin(0.5f64, 1.0), 0.5 / 1024.0 + 8.0 * f64::EPSILON);
/// ```
pub fn skin<S: Scalar>(radius: S, extent: S) -> S {
    let e = S::height_error(extent);
    S::div_pow2(radius, 10) + e + e
}

/// The smallest radius [`move_and_slide`] accepts for centres within `±extent`: sixteen times
/// the rounding of a height there, so that the skin and the seam margins stay well above the
/// rounding of the frames they protect against. Smaller balls are refused with
/// [`Error::RadiusTooSmall`]; [`Precision::min_radius`](crate::Precision::min_radius) gives the
/// same figure for planning.
///
/// ```
/// use ballcast::slide::min_radius;
/// use fixed::types::I16F16;
/// // I16F16: 128 steps of 2^-16 anywhere in its range.
/// assert_eq!(min_radius(I16F16::from_num(2048)), I16F16::from_bits(128));
/// ```
pub fn min_radius<S: Scalar>(extent: S) -> S {
    let e = S::height_error(extent);
    let e4 = e + e + e + e;
    e4 + e4 + e4 + e4
}

/// Moves a ball of `radius` from `position` by `displacement` through `scene` (a
/// [`Scene`](crate::Scene), a mesh, or a slice of prepared triangles), sliding along what it
/// touches by the rules in the [module docs](self), for at most [`MAX_SLIDES`] sweeps.
///
/// Guarantees, in every scalar: the motion's length never grows beyond the skins, so a slide
/// cannot gain speed; it never runs against `displacement` apart from the skins; a ball that
/// starts overlapping geometry is not carried further in (each call lifts it by a skin while
/// the displacement does not move it away).
///
/// Errors, checked before any arithmetic so fixed-point cannot overflow:
/// [`Error::NonFinite`] or [`Error::OutOfRange`] when `position`, `displacement`, the target or
/// `radius` is outside `±`[`Scalar::LIMIT`], [`Error::NegativeRadius`], and
/// [`Error::RadiusTooSmall`] below [`min_radius`] at the larger of the start's and target's
/// coordinates.
///
/// ```
/// use ballcast::{Scene, Triangle, Vec3, move_and_slide, slide::skin};
/// let v = Vec3::new;
/// let mut s: Scene<f64, 4> = Scene::new();
/// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
/// // Thrown down and sideways at a floor: it stops at the floor and slides the rest sideways,
/// // resting a skin above it.
/// let out = move_and_slide(&s, v(0.0, 1.0, 0.0), v(2.0, -2.0, 0.0), 0.5)?;
/// assert_eq!(out.position.x, 2.0);
/// assert!((out.position.y - 0.5 - skin(0.5, 2.0)).abs() < 1e-12);
/// // What the floor took away: the 1.5 below it, and the skin.
/// assert_eq!((out.blocked.x, out.blocked.z), (0.0, 0.0));
/// assert!((out.blocked.y + 1.5 + skin(0.5, 2.0)).abs() < 1e-12);
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
    check::radius(radius)?;
    let target = check::point(position + displacement, S::LIMIT)?;
    let (a, b) = (magnitude(position), magnitude(target));
    let extent = if a > b { a } else { b };
    if radius < min_radius(extent) {
        return Err(Error::RadiusTooSmall);
    }
    let skin = skin(radius, extent);
    let zero = Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    let mut out = Slide {
        position,
        blocked: zero,
        contacts: [None; MAX_SLIDES],
    };
    let mut rest = displacement;
    let mut planes: Planes<S> = Vec::new();
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
        let (alpha, lift) = stand_off(&hit, rest, skin);
        out.position = out.position + rest.scale(alpha) + lift;
        let left = rest.scale(S::ONE - alpha);
        add_planes(&mut planes, &hit);
        rest = constrain(left, &planes, displacement);
        out.blocked = out.blocked + (left - rest);
    }
    out.blocked = out.blocked + rest;
    Ok(out)
}

/// Where to stop short of a contact met along `rest`, as a fraction of it, and a lift to add.
/// A ball that travelled stops a skin short, measured along the normal, by backing off along
/// its own path (never behind its start), so stopping adds no sideways motion and a ball pushed
/// into a corner settles at a skin from both walls instead of being levered from one to the
/// other. One met at once (already touching or overlapping) is lifted by a skin instead.
fn stand_off<S: Scalar>(hit: &SceneHit<S>, rest: Vec3<S>, skin: S) -> (S, Vec3<S>) {
    let into = S::dot(rest, hit.normal);
    if hit.alpha > S::ZERO && into < S::ZERO {
        let back = S::div(skin, -into);
        let alpha = if back < hit.alpha {
            hit.alpha - back
        } else {
            S::ZERO
        };
        return (alpha, Vec3::new(S::ZERO, S::ZERO, S::ZERO));
    }
    (hit.alpha, hit.normal.scale(skin))
}

/// The largest coordinate magnitude of a point.
fn magnitude<S: Scalar>(p: Vec3<S>) -> S {
    crate::scalar::largest(p.x.abs(), p.y.abs(), p.z.abs())
}

/// Adds a contact's planes to those already touched, each distinct plane once.
fn add_planes<S: Scalar>(planes: &mut Planes<S>, hit: &SceneHit<S>) {
    for n in hit.planes.iter().flatten() {
        if !planes.iter().any(|p| same_plane(*p, *n)) {
            // Room for every plane of every contact: cannot fail.
            let _ = planes.push(*n);
        }
    }
}

/// `v` constrained by every plane (unit normals): unchanged if it moves into none; else the
/// first of: `v` without its part into one plane, along the crease of two, that moves into
/// no other plane (beyond rounding); else zero. Zero too if the result runs against `primal`,
/// or is no larger than the rounding of the normals times `v`.
fn constrain<S: Scalar>(v: Vec3<S>, planes: &[Vec3<S>], primal: Vec3<S>) -> Vec3<S> {
    let zero = Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    let slack = -S::height_error(magnitude(v));
    let clear = |w: Vec3<S>| planes.iter().all(|n| S::dot(w, *n) >= slack);
    // What is left after removing a large push into a plane carries the normal's rounding
    // times the push (four steps of resolution of it at most): the same each call, so it would
    // add up to a drift. Less than that is not motion.
    let noise = S::mul(magnitude(v), crate::scalar::tie::<S>());
    let keep = |w: Vec3<S>| {
        if magnitude(w) > noise && S::dot(w, primal) > S::ZERO {
            w
        } else {
            zero
        }
    };
    if clear(v) {
        return v;
    }
    for n in planes {
        let into = S::dot(v, *n);
        let w = if into < S::ZERO { v - n.scale(into) } else { v };
        if clear(w) {
            return keep(w);
        }
    }
    for (i, a) in planes.iter().enumerate() {
        for b in &planes[i + 1..] {
            if let Some(c) = unit(cross_unit(*a, *b)) {
                let w = c.scale(S::dot(v, c));
                if clear(w) {
                    return keep(w);
                }
            }
        }
    }
    zero
}

/// The cross product of two unit vectors, each component rounded once.
fn cross_unit<S: Scalar>(a: Vec3<S>, b: Vec3<S>) -> Vec3<S> {
    let z = S::ZERO;
    let d = |p: S, q: S, r: S, s: S| S::dot(Vec3::new(p, -q, z), Vec3::new(r, s, z));
    Vec3::new(
        d(a.y, a.z, b.z, b.y),
        d(a.z, a.x, b.x, b.z),
        d(a.x, a.y, b.y, b.x),
    )
}
