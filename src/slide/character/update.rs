//! [`Character::update`]: one frame of the character loop.

use super::Character;
use crate::slide::leave::{rising_at_most, rolls_off, snap_depth, walks_off};
use crate::slide::rules::magnitude;
use crate::slide::{Floor, Slide};
use crate::{Contact, Error, Geometry, Input, Scalar, Vec3, check};

impl<S: Scalar> Character<S> {
    /// One frame of `dt` seconds: walking at the `wish`ed velocity (its part along the floor)
    /// where it stands on a floor, falling under `gravity` where it does not. Returns the move
    /// (its contacts: what it hit, where and when in the frame).
    ///
    /// Errors: [`Error::NaN`] or [`Error::OutOfRange`] for a `wish`, `gravity`, `position` or
    /// `velocity` component beyond `±`[`Scalar::LIMIT`] (naming which: [`Input::Wish`],
    /// [`Input::Gravity`], [`Input::Position`], [`Input::Velocity`]), or a `dt`
    /// ([`Input::TimeStep`]) below zero or so long that a move this frame might not fit in the
    /// range: `(|velocity| + |wish| + |gravity| dt) dt` beyond `LIMIT` (the error's `max` is
    /// the longest `dt` that fits, in `f64`; in `I16F16`, whose `LIMIT` is 4 096, about 20 s
    /// for a ball at rest under Earth's gravity). A float's step that fits but carries the ball
    /// out to where its radius is below [`min_radius`](crate::slide::min_radius) (in `f32`, a ball of 0.4 beyond 52 428
    /// units: a fall of 74 s) is refused by the slide as [`Error::RadiusTooSmall`], naming the
    /// coordinates it would reach. Give `dt` in seconds: a time step in
    /// milliseconds is refused only beyond that bound, and below it is obeyed. Then those of the
    /// slides it makes ([`Slider::slide`](crate::Slider::slide), [`Slider::step_slide`](crate::Slider::step_slide), [`Slider::snap_to_floor`](crate::Slider::snap_to_floor)):
    /// a move whose target leaves the range ([`Input::Target`]), a ball too small for the
    /// scalar at its coordinates ([`Error::RadiusTooSmall`]), and a walk whose velocity has a
    /// coordinate beyond `±LIMIT` ([`Input::Velocity`]: along a slope its part along the floor
    /// can have a coordinate larger than any of the wish's, more so at
    /// [constant speed](Self::with_constant_speed)). On an error the character is left as it
    /// was.
    ///
    /// The wish steers in the air only with [`with_air_control`](Self::with_air_control) (or
    /// by changing [`velocity`](Self::velocity) before the update).
    pub fn update<G: Geometry<S> + ?Sized>(
        &mut self,
        level: &G,
        wish: Vec3<S>,
        gravity: Vec3<S>,
        dt: S,
    ) -> Result<Slide<S>, Error> {
        check::point(wish, S::LIMIT, Input::Wish)?;
        check::point(gravity, S::LIMIT, Input::Gravity)?;
        // (The position is checked, and named, by the first slide.)
        check::point(self.velocity, S::LIMIT, Input::Velocity)?;
        // NaN as NaN; anything else outside [0, longest] (infinities too) with that range.
        let (input, triangle) = (Input::TimeStep, None);
        if dt.partial_cmp(&dt).is_none() {
            return Err(Error::NaN { input, triangle });
        }
        let (t, longest) = (dt.to_f64(), longest_step(wish, gravity, self.velocity));
        if !(0.0..=longest).contains(&t) {
            return Err(Error::OutOfRange {
                input,
                value: t,
                min: 0.0,
                max: longest,
                triangle,
            });
        }
        // Worked on a copy, kept only when every slide succeeded.
        let mut me = *self;
        // Where the walk began (after the press): what a walker leaving the floor rose since.
        let mut start = me.position;
        let (ball, up, min_cos) = (me.ball, me.up, me.min_cos);
        let walked = me.floor.is_some();
        // What the walk would rise along its floor's plane (up a ramp: no reason to snap),
        // where that is a face's, not the tangent of an edge it rounds; zero going down.
        let mut planned = S::ZERO;
        let out = match me.floor.map(|f| (f.normal, f.contact)) {
            Some((n, on)) => {
                // Standing (the walk rounds to nothing), the press could only move the ball
                // about its gap above the floor, where, rounded to a step straight down in fixed
                // point, it walks the ball down the slope (`I16F16` at 960 Hz, or in a steep
                // valley from 240 Hz). The probe below finds the floor instead. In fixed
                // point a press no longer than a skin rounds to a few steps along the axes, not
                // along the normal, and as the ball and a level's vertices lie on one grid, it
                // lowered the ball a few steps a frame until it exactly touched and was lifted
                // a skin off along the normal: a sawtooth of one skin that carried a ball
                // walking into a wall down a tilted floor (`I16F16` from 480 Hz, a press of a
                // height's rounding), and shook one pushed into the wedge of a steep slope and
                // a wall (`I16F16` at 200 to 250 Hz, a press of 1.4 roundings: 3e-4 every
                // frame). There the floor is looked for within the press and a skin, and the
                // ball stays where it is. (Floats far out round a press as coarsely, but on no grid
                // shared with the level: there the press still holds a walking ball down
                // against the rounding of its walk, which would lift it off the floor.)
                me.velocity = if me.constant_speed {
                    at_speed(wish.reject_from_normalized(me.unit_up()), n)
                } else {
                    wish.reject_from_normalized(n)
                };
                let walk = me.velocity * dt;
                let rise = S::dot(walk, me.unit_up());
                if on == Contact::Face && rise > S::ZERO {
                    planned = rise;
                }
                let depth = gravity.length().mul(dt).mul(dt);
                let extent = magnitude(me.position);
                let pressed = if walk == Vec3::ZERO {
                    None
                } else if !S::PRECISION.relative && depth <= ball.skin(extent) {
                    let reach = depth + ball.skin(extent);
                    let probe = ball.slide(level, me.position, Vec3::ZERO - n * reach)?;
                    Some(Slide {
                        position: me.position + probe.pushed_out,
                        ..probe
                    })
                } else {
                    Some(ball.slide(level, me.position, Vec3::ZERO - n * depth)?)
                };
                let on = (up, min_cos);
                // Where the press left the ball, and the floor it found (its slide is not kept
                // through the walk: a firmware's stack pays for one slide less).
                let (from, held) = match pressed {
                    Some(p) => (p.position, p.ground_floor(up, min_cos)?),
                    None => (me.position, None),
                };
                start = from;
                let out = ball.walk(level, from, walk, Some(n), on, me.step)?;
                let floor = out.ground_floor(up, min_cos)?;
                // The press's floor holds the ball unless the walk leaves it (`walks_off`).
                let held = held.filter(|f| !walks_off(f, walk, me.unit_up()));
                me.floor = floor.or(held);
                out
            }
            None => {
                if me.air > S::ZERO {
                    let up = me.unit_up();
                    let along = me.velocity.project_onto_normalized(up);
                    let wished = wish.reject_from_normalized(up);
                    let across = (me.velocity - along).move_towards(wished, me.air.mul(dt));
                    me.velocity = along + across;
                }
                me.velocity += gravity * dt;
                let out = ball.slide(level, me.position, me.velocity * dt)?;
                me.floor = out.ground_floor(up, min_cos)?;
                out
            }
        };
        me.position = out.position;
        me.velocity = ball.clip(&out, me.velocity)?;
        // The probe reaches two skins down; a walk that began on the floor and left it reaches
        // the snap's depth further, and what the walk rose beyond what its floor's plane
        // foretold: over a small step's edge, a fast walk (about a radius a frame) took the
        // edge's rounded top for its floor and went on up its tilted plane, out of the snap's
        // reach, and flew off metres high; off a ramp's lip the rise was the ramp's, and the
        // ball flies. A ball that was in the air is not put on a floor it moves away from (a
        // jump's first frames).
        let rose = S::dot(me.position - start, me.unit_up());
        if me.floor.is_none() {
            let unforeseen = rose - planned;
            let depth = if walked {
                snap_depth(me.snap, unforeseen)
            } else {
                S::ZERO
            };
            let (found, probe) =
                ball.snap_or_probe(level, me.position, me.velocity, (up, min_cos), depth)?;
            // Only the probe's edge can be rolled off: the snap holds a ball over a crest.
            let on = |f: &Floor<S>| walked || me.velocity.dot(f.normal) <= S::ZERO;
            let rolls = |f: &Floor<S>| {
                walked && probe && rolls_off(f, me.velocity, gravity, (me.unit_up(), ball.radius()))
            };
            let found = found.filter(|f| on(f) && !rolls(f));
            if let Some(f) = found {
                (me.floor, me.position) = (Some(f), f.position);
            }
        }
        // A walker that left the floor flies on with its walk's velocity (off a ramp's lip), but
        // rises no faster than its walk rose: held in a pocket of steep faces, its walk's
        // velocity along the floor's plane, clipped by the face it pressed into, ran up their
        // crease, and launched the ball once rounding lost it the floor (`I16F16` at 960 Hz).
        if walked && me.floor.is_none() {
            me.velocity = rising_at_most(me.velocity, me.unit_up(), rose, dt);
        }
        *self = me;
        Ok(out)
    }
}

/// [`Character::with_constant_speed`]'s walk: `level` (the wish's part across `up`) turned into
/// the floor's plane (its part along the plane, normal `n`), at `level`'s length. Zero where
/// `level` is (the wish was along `up`, or nothing); the part along the plane is never much
/// shorter than `level` on a walkable floor (by the slope's cosine at most), so the lengthening
/// scales up no rounding noise.
fn at_speed<S: Scalar>(level: Vec3<S>, n: Vec3<S>) -> Vec3<S> {
    level.reject_from_normalized(n).normalize_or_zero() * level.length()
}

/// The longest time step whose moves fit in the range: `(|velocity| + |wish| + |gravity| dt) dt
/// <= LIMIT` (lengths bound every coordinate: a walk is at most `|wish| dt`, a fall with air
/// control at most that), and `LIMIT` itself. Worked out in `f64` (correctly rounded
/// operations: the same bits on every target).
fn longest_step<S: Scalar>(wish: Vec3<S>, gravity: Vec3<S>, velocity: Vec3<S>) -> f64 {
    let length = |v: Vec3<S>| {
        let [x, y, z] = v.to_array().map(S::to_f64);
        libm::sqrt(x * x + y * y + z * z)
    };
    let (l, g) = (S::LIMIT.to_f64(), length(gravity));
    let v = length(velocity) + length(wish);
    // The positive root of g t² + v t = l (v >= 0): 2 l / (v + sqrt(v² + 4 g l)), no
    // cancellation; infinite where nothing moves.
    let fall = 2.0 * l / (v + libm::sqrt(v * v + 4.0 * g * l));
    fall.min(l)
}
