//! Collision response: move a ball through a [`Geometry`], sliding along what it touches.
//!
//! The rules are Quake's fly-move (`SV_FlyMove`, id Software, 1996), kept exact enough for
//! fixed point:
//! 1. Sweep the remaining motion; without contact, travel all of it.
//! 2. Travel to the contact, then step a *skin* off along the contact normal ([`skin`]).
//! 3. Collect every plane touched so far in this call, including all planes touched at the same
//!    moment ([`SceneHit::planes`](crate::SceneHit::planes)): a ball pushed into a corner meets both walls at once.
//! 4. Constrain what is left of the motion by all of them at once: remove the part into one
//!    plane if that leaves it clear of the others; else follow the crease of two planes if
//!    that does; else stop. Stop too when what is left points against the requested
//!    displacement: a ball pushed into a corner wider than 90° comes to rest instead of being
//!    bounced back out along the second wall.
//!
//! Every product and quotient rounds to nearest through the [`Scalar`] trait, so a resting ball
//! pushed into a floor does not creep along it.
//!
//! For a character on top of these rules: [`Slide::floor`] (grounded by the move's contacts),
//! [`Slider::probe_floor`] (a ground probe for a ball resting within a skin of its floor),
//! [`Slider::snap_to_floor`] (the probe reaching further down, for a walk going down stairs)
//! and [`Slider::step_slide`] (a walk that steps up onto low ledges).

mod character;
mod leave;
mod outcome;
mod push;
mod resolve;
mod rules;
mod slider;
mod step;

use crate::contact::unit;
use crate::{Error, Geometry, Input, Scalar, Sweep, Vec3, check};
pub use character::Character;
use heapless::Vec;
pub use outcome::{Floor, Slide, SlideContact};
use resolve::{resolve, settle};
use rules::{FloorStop, Planes, Walk, add_planes, constrain, keep_to_floor, magnitude};
pub use slider::Slider;

/// At most this many sweeps per call: each contact costs one, and a ball pressed into a corner
/// of three planes has nowhere left to go after three.
pub const MAX_SLIDES: usize = 4;

/// A slope limit checked: `up` (components within `±LIMIT`, not zero in the scalar) as a unit
/// vector, and `min_cos` within `[0, 1]` (a floor faces up: with a negative cosine a ceiling
/// would count as floor, and a walk along it is refused), lowered by the rounding of a product
/// of unit normals (eight steps, as [`constrain`](rules::constrain) allows): a face exactly at
/// the limit counts as within it. (A 45° face's normal came out a unit in the last place either
/// side of `FRAC_1_SQRT_2`, tile by tile, and a ball walking up a 45° slope was held back on
/// some tiles as by a wall: in `f64` it slid back down.) Never lowered below zero: a face
/// facing down is no floor, however little (a walk along it is refused), so with a limit
/// within that rounding of upright a wall counts only where its normal rounds level or up.
fn slope_limit<S: Scalar>(up: Vec3<S>, min_cos: S) -> Result<(Vec3<S>, S), Error> {
    let up = check::point(up, S::LIMIT, Input::Up)?;
    let min_cos = check::within(min_cos, S::ZERO, S::ONE, Input::MaxSlope)?;
    let zero = Error::ZeroVector { input: Input::Up };
    let tie = crate::scalar::tie::<S>();
    let lowered = min_cos - (tie + tie);
    let lowered = if lowered > S::ZERO { lowered } else { S::ZERO };
    Ok((unit(up).ok_or(zero)?, lowered))
}

/// A floor's normal `n` (any length) checked and as a unit vector: within `±LIMIT`, not zero,
/// and not facing down from `up_unit` (a ceiling is no floor).
fn floor_normal<S: Scalar>(n: Vec3<S>, up_unit: Vec3<S>) -> Result<Vec3<S>, Error> {
    let n = check::point(n, S::LIMIT, Input::Floor)?;
    let zero = Error::ZeroVector {
        input: Input::Floor,
    };
    let n = crate::contact::unit(n).ok_or(zero)?;
    let facing = S::dot(n, up_unit);
    if facing < S::ZERO {
        return Err(Error::OutOfRange {
            input: Input::FloorFacing,
            value: facing.to_f64(),
            min: 0.0,
            max: 1.0,
            triangle: None,
        });
    }
    Ok(n)
}

/// The gap kept between a ball of `radius` and what it touched, for centres within `±extent`:
/// `radius / 1024` plus twice the rounding of a height there, so that the next sweep does not
/// meet the same plane again at once through rounding. A radius below zero (or NaN) counts as
/// zero: the gap is never less than the rounding term.
///
/// ```
/// use ballcast::slide::skin;
/// assert_eq!(skin(0.5f64, 1.0), 0.5 / 1024.0 + 8.0 * f64::EPSILON);
/// assert_eq!(skin(-0.5f64, 1.0), skin(0.0, 1.0));
/// ```
pub fn skin<S: Scalar>(radius: S, extent: S) -> S {
    let e = S::height_error(extent);
    let radius = if radius > S::ZERO { radius } else { S::ZERO };
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
/// A ball that starts overlapping geometry by more than the skin is first pushed out
/// ([`Slide::pushed_out`]): along the deepest overlap's normal
/// ([`penetration`](crate::penetration::penetration)) to a skin from that triangle, or, where that
/// would leave it in (or push it into) other faces, the shortest push that clears up to three (out
/// of a narrow valley along its bisector, out of a pit). At most [`MAX_SLIDES`] pushes (each may
/// uncover the next), each at most `2 (radius + skin)` and swept like a motion, so that it stops a
/// skin short of other geometry rather than pushing into it. A ball spawned 0.2 inside a floor,
/// overlapping both slopes of a 20° valley or the three faces of a steep pit, comes out in the one
/// call. Overlaps are looked for only where the motion's first sweep meets something at once (alpha
/// 0), so a call that starts clear costs no more than before; a ball that starts overlapping but
/// moves away is left to leave. Shallower overlaps (rounding) are left to the motion: a contact met
/// at once lifts the ball by a skin.
///
/// Guarantees, in every scalar: the motion's length never grows beyond the skins, so a slide
/// cannot gain speed; it never runs against `displacement` apart from the skins; a ball that
/// starts overlapping geometry is not carried further in.
///
/// Errors, checked before any arithmetic so fixed-point cannot overflow: [`Error::NaN`] or
/// [`Error::OutOfRange`] when `position`, `displacement`, the target or `radius` is outside
/// `±`[`Scalar::LIMIT`], [`Error::NegativeRadius`], and [`Error::RadiusTooSmall`] below
/// [`min_radius`] at the larger of the start's and target's coordinates. A slide whose sweep would
/// end outside `±LIMIT` is refused with [`Error::OutOfRange`] as well (a push out of an overlap
/// that would is not made, and the target after the push is checked again). The position returned
/// stands a skin off what it touched, so near the edge of the range it can lie up to a skin beyond
/// `±LIMIT`, and the next call refuses it: keep the world a skin inside the range. (In fixed
/// point the back-off to the skin is a fraction of the motion rounded to a step, so a long call
/// stands off by the skin give or take a step times the motion's length: in `I16F16` a call of 40
/// units stopped by a floor straight ahead ends 6.1e-4 above touching instead of 7.3e-4, one of
/// 100 units touching it. The next call lifts it off; keep calls short, as the README advises.)
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
    Slider::unchecked_size(radius)?.slide(scene, position, displacement)
}

/// [`move_and_slide`] with `ball`, ending at the first contact `stop` (a ground probe's) stops at.
/// A `walk` along the floor the ball stands on keeps to it: the floor is the first plane that
/// constrains the rest of the motion once something stops it (as Quake III's `PM_SlideMove`
/// seeds its planes with the ground's), and once that is a wall (a contact it can neither
/// stand on nor step over), the rest stays in the floor's plane; a walkable contact becomes
/// the floor it keeps to ([`keep_to_floor`](rules::keep_to_floor)).
fn run<S: Scalar, G: Geometry<S> + ?Sized>(
    ball: &Slider<S>,
    scene: &G,
    position: Vec3<S>,
    displacement: Vec3<S>,
    stop: Option<FloorStop<S>>,
    mut walk: Option<Walk<S>>,
) -> Result<Slide<S>, Error> {
    let radius = ball.radius;
    // Inside these ranges `position + displacement` stays within 2 * LIMIT: no overflow.
    check::point(position, S::LIMIT, Input::Position)?;
    check::point(displacement, S::LIMIT, Input::Displacement)?;
    let target = check::point(position + displacement, S::LIMIT, Input::Target)?;
    let (a, b) = (magnitude(position), magnitude(target));
    let extent = if a > b { a } else { b };
    let min = min_radius(extent);
    if radius < min {
        return Err(Error::RadiusTooSmall {
            radius: radius.to_f64(),
            min: min.to_f64(),
            extent: extent.to_f64(),
        });
    }
    let skin = ball.skin(extent);
    let rounding = S::height_error(extent);
    // The motion's first sweep (or, for no motion, one that does not move) reports a starting
    // overlap at alpha 0: only then is the overlap looked for, and the sweep is kept otherwise.
    let mut pending = Some(scene.cast(&Sweep::new(position, target, radius)?));
    let mut start = position;
    if let Some(Some(hit)) = &pending
        && hit.alpha == S::ZERO
    {
        start = resolve(scene, position, radius, skin, rounding);
        if start != position {
            pending = None;
        }
    }
    // The push may carry the target past the range: refused like any other target.
    check::point(start + displacement, S::LIMIT, Input::Target)?;
    let zero = Vec3::ZERO;
    let mut out = Slide {
        position: start,
        pushed_out: start - position,
        blocked: zero,
        contacts: [None; MAX_SLIDES],
    };
    let (mut rest, mut elapsed) = (displacement, S::ZERO);
    let mut planes: Planes<S> = walk.map(|w| w.floor).into_iter().collect();
    let mut touched: Planes<S> = Vec::new();
    for slot in out.contacts.iter_mut() {
        if rest == zero {
            break;
        }
        let sweep = Sweep::new(out.position, out.position + rest, radius)?;
        let found = match pending.take() {
            Some(first) => first,
            None => scene.cast(&sweep),
        };
        let Some(hit) = found else {
            out.position += rest;
            break;
        };
        elapsed = elapsed + (S::ONE - elapsed).mul(hit.alpha);
        *slot = Some(SlideContact {
            hit,
            point: hit.position - hit.normal.scale(radius),
            time: elapsed,
        });
        let alpha = rules::stand_off(&hit, rest, skin, rounding).0;
        out.position = settle(scene, &hit, out.position, rest, (radius, skin), rounding);
        let left = rest.scale(S::ONE - alpha);
        rest = if stop.is_some_and(|s| s.stops_at(&hit, &mut touched)) {
            zero
        } else if add_planes(&mut planes, &hit, ball.max_slope, |n| {
            // A walk's steep contacts low enough to step over have their walls square on its
            // floor. Walls keep upright ones: the walk keeps to the floor's plane against them
            // anyway, and a wall square on ground tilted along a wall leaning back has a
            // skewed foot, along which a push into the wall crept (`tests/creases.rs`).
            walk.filter(|w| w.steps_over(n, radius)).map(|w| w.floor)
        }) && keep_to_floor(&mut planes, &mut walk, &hit, radius)
        {
            let rest = constrain(left, &planes, displacement);
            stop.map_or(rest, |s| s.keeps_depth(rest, left))
        } else {
            zero
        };
    }
    // What the move did not travel of the displacement, whatever took it: the stops short of
    // contacts and the constraints, and the lifts a skin off what was met at once (summed from
    // the stops alone, a ball touching a floor and thrown down into it sideways ended a skin
    // higher than `start + displacement - blocked` said).
    out.blocked = start + displacement - out.position;
    Ok(out)
}
