//! [`Character`]: the README's character loop as a type, one call a frame.

use super::leave::{rising_at_most, rolls_off, snap_depth, walks_off};
use super::rules::magnitude;
use super::{Floor, Slide, Slider, min_radius};
use crate::{Contact, Error, Geometry, Input, Scalar, Vec3, check};

/// A walking ball: the character loop of game engines, one [`update`](Self::update) a frame.
///
/// On the floor, it presses into the floor along the floor's normal by `|gravity| dt²` (so it
/// does not slide down a walkable slope; not when it stands, its walk rounding to nothing:
/// the press could then only move it about its gap, and in fixed point down the slope; nor,
/// in fixed point, where the press is no longer than the rounding of a height, `I16F16` from
/// about 285 Hz under a gravity of 9.81, where rounded it would not point along the normal:
/// there it looks for the floor within the press and a skin without moving), then
/// walks by the wished velocity's part along the floor's plane times `dt`, stepping onto
/// ledges up to its step height
/// ([`Slider::step_slide`], Quake's `PM_StepSlideMove`); in the air, gravity adds to its
/// velocity and it moves by that (the wish steers in the air only with
/// [`with_air_control`](Self::with_air_control)). Its velocity then keeps what the contacts allow
/// ([`Slider::clip`]), and off the floor after a walk it rises no faster than the walk
/// rose. Where no move touched a floor it probes two skins down
/// ([`Slider::probe_floor`]), and a walk that began on the floor and left it (down a step,
/// over a crest, up a ramp's top) is snapped down onto the floor within its snap depth and
/// what the walk rose beyond its floor's plane (over an edge's rounded top, all of its rise)
/// ([`Slider::snap_to_floor`]; Source's `StayOnGround`, Godot's floor
/// snap), while off a cliff or a ramp's lip over a deeper drop it falls or flies (rolling
/// round the drop's edge first only if it is slow enough for gravity to hold it there, `v² <=
/// g r cos θ`, at any frame rate). Slopes
/// steeper than the slope limit hold it back as walls ([`Slider::with_max_slope`]). It has no
/// friction and no inertia on the floor: it walks at the wished speed at once.
///
/// Defaults: `up` along +y, slopes up to 45° walkable, a step height and a snap depth of half
/// the radius each, the default [`skin`](super::skin). The fields are the state a game keeps:
/// [`position`](Self::position) and [`velocity`](Self::velocity) may be set between frames
/// (a teleport; a knock-back, with [`leave_floor`](Self::leave_floor)). To save a character
/// (a saved game, a lockstep peer joining late) keep them and its [`floor`](Self::floor), and
/// rebuild it with the same settings and [`set_floor`](Self::set_floor): it walks on bit for
/// bit.
///
/// ```
/// use ballcast::{Scene, Triangle, Vec3, slide::Character};
/// let v = Vec3::new;
/// let mut level: Scene<f32, 2> = Scene::new();
/// level.push(Triangle::new(v(-50.0, 0.0, -50.0), v(-50.0, 0.0, 50.0), v(50.0, 0.0, 50.0)))?;
/// level.push(Triangle::new(v(-50.0, 0.0, -50.0), v(50.0, 0.0, 50.0), v(50.0, 0.0, -50.0)))?;
/// let mut me = Character::new(v(0.0, 2.0, 0.0), 0.5)?;
/// let (gravity, dt) = (v(0.0, -9.81, 0.0), 1.0 / 60.0);
/// for frame in 0..120 {
///     me.update(&level, v(2.0, 0.0, 0.0), gravity, dt)?;
///     if frame == 90 {
///         assert!(me.jump(4.0)?); // only from the floor
///     }
/// }
/// assert!(me.position.x > 2.0 && !me.is_grounded());
/// # Ok::<(), ballcast::Error>(())
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Character<S> {
    ball: Slider<S>,
    up: Vec3<S>,
    min_cos: S,
    step: S,
    snap: S,
    air: S,
    floor: Option<Floor<S>>,
    /// The ball's centre.
    pub position: Vec3<S>,
    /// Its velocity, units per second: on the floor, the wished velocity along it as the
    /// contacts left it; in the air, what gravity and the contacts made of it.
    pub velocity: Vec3<S>,
}

impl<S: Scalar> Character<S> {
    /// A ball of `radius` at rest at `position`, in the air until its first update finds a
    /// floor, with the defaults above.
    ///
    /// Errors: as [`Slider::new`], [`Error::NaN`] or [`Error::OutOfRange`] for a `position`
    /// outside `±`[`Scalar::LIMIT`], and [`Error::RadiusTooSmall`] for a radius below
    /// [`min_radius`] at `position` (a ball that could not move from there).
    pub fn new(position: Vec3<S>, radius: S) -> Result<Self, Error> {
        let up = Vec3::Y;
        let min_cos = S::from_f64(core::f64::consts::FRAC_1_SQRT_2);
        let ball = Slider::new(radius)?;
        let position = check::point(position, S::LIMIT, Input::Position)?;
        let (extent, half) = (magnitude(position), S::div_pow2(ball.radius(), 1));
        let min = min_radius(extent);
        if ball.radius() < min {
            return Err(Error::RadiusTooSmall {
                radius: radius.to_f64(),
                min: min.to_f64(),
                extent: extent.to_f64(),
            });
        }
        Ok(Self {
            ball: ball.with_max_slope(up, min_cos)?,
            up,
            min_cos,
            step: half,
            snap: half,
            air: S::ZERO,
            floor: None,
            position,
            velocity: Vec3::ZERO,
        })
    }

    /// The same character with `up` (any length) and the cosine of the steepest walkable slope.
    ///
    /// Errors: as [`Slider::with_max_slope`].
    pub fn with_slope(self, up: Vec3<S>, min_cos: S) -> Result<Self, Error> {
        let ball = self.ball.with_max_slope(up, min_cos)?;
        Ok(Self {
            ball,
            up,
            min_cos,
            ..self
        })
    }

    /// The same character stepping onto ledges up to `height` (zero: none).
    ///
    /// Errors: [`Error::NaN`], or [`Error::OutOfRange`] outside `[0, LIMIT]`.
    pub fn with_step(self, height: S) -> Result<Self, Error> {
        let step = check::within(height, S::ZERO, S::LIMIT, Input::Step)?;
        Ok(Self { step, ..self })
    }

    /// The same character snapped down onto the floor up to `depth` below it where its walk
    /// left the floor (zero: the ground probe alone, which lets a walker fly off any convex
    /// edge it crosses faster than gravity holds it round the edge). Choose about the highest
    /// step down, and at least the drop of a walk down the steepest walkable slope in a frame:
    /// a drop within it is stepped down at any speed, and a walker already rolled round an
    /// edge's top when it needs the snap may step down a deeper one (README, *The character
    /// loop*).
    ///
    /// Errors: [`Error::NaN`], or [`Error::OutOfRange`] outside `[0, LIMIT]`.
    pub fn with_snap(self, depth: S) -> Result<Self, Error> {
        let snap = check::within(depth, S::ZERO, S::LIMIT, Input::Snap)?;
        Ok(Self { snap, ..self })
    }

    /// The same character steering in the air: each frame off the floor, its velocity across
    /// `up` moves towards the wish's part across `up` by up to `acceleration · dt`
    /// (units per second squared), never past it, before gravity adds; its velocity along `up`
    /// is gravity's and the contacts' alone. Quake's air acceleration (`PM_AirMove`), without
    /// its speed gain. Zero, the default, steers not at all.
    ///
    /// Errors: [`Error::NaN`], or [`Error::OutOfRange`] outside `[0, LIMIT]`.
    pub fn with_air_control(self, acceleration: S) -> Result<Self, Error> {
        let air = check::within(acceleration, S::ZERO, S::LIMIT, Input::AirControl)?;
        Ok(Self { air, ..self })
    }

    /// The same character keeping a gap of `skin` from what it touches (see
    /// [`Slider::with_skin`]).
    ///
    /// Errors: as [`Slider::with_skin`].
    pub fn with_skin(self, skin: S) -> Result<Self, Error> {
        let ball = self.ball.with_skin(skin)?;
        Ok(Self { ball, ..self })
    }

    /// `up` as a unit vector (validated nonzero when set).
    fn unit_up(&self) -> Vec3<S> {
        self.up.try_normalize().unwrap_or(Vec3::Y)
    }

    /// The ball's settings, for queries of one's own (a probe, a cast ahead).
    pub fn slider(&self) -> Slider<S> {
        self.ball
    }

    /// The normal of the floor it stands on, if any ([`Slide::floor_normal`]'s, or the probe's).
    pub fn floor_normal(&self) -> Option<Vec3<S>> {
        self.floor.map(|f| f.normal)
    }

    /// The floor it stands on, if any: its normal (as [`floor_normal`](Self::floor_normal)),
    /// the index of its triangle in the level (what a game looks the surface up by: a
    /// footstep's sound, a material), and where the ball stands on it (its position).
    pub fn floor(&self) -> Option<Floor<S>> {
        let position = self.position;
        self.floor.map(|f| Floor { position, ..f })
    }

    /// Whether it stands on a floor: the engines' `is_on_floor`.
    pub fn is_grounded(&self) -> bool {
        self.floor.is_some()
    }

    /// Leaves the floor (a knock-back, a launch): the next update moves it as in the air.
    pub fn leave_floor(&mut self) {
        self.floor = None;
    }

    /// Puts it back on a floor [`floor`](Self::floor) gave (or in the air, `None`): with
    /// [`position`](Self::position) and [`velocity`](Self::velocity), all it keeps from one
    /// frame to the next besides its settings, so a character rebuilt with the same settings
    /// from a saved game or a lockstep peer's state walks on bit for bit. (A rebuilt character
    /// without its floor starts in the air, and its next frames differ.) The floor's normal,
    /// contact and index are taken; its position is the character's own. A normal of any
    /// other length than one (a cross product of the floor's edges, say) is taken as its unit
    /// vector; one that is a unit vector already ([`Vec3::is_normalized`], as `floor` gives
    /// it) is kept bit for bit.
    ///
    /// Errors: [`Error::NaN`], [`Error::OutOfRange`] or [`Error::ZeroVector`] for a normal that
    /// is NaN, beyond `±`[`Scalar::LIMIT`] or zero ([`Input::Floor`]); [`Error::OutOfRange`]
    /// with [`Input::FloorFacing`] for one facing down from `up`. The character is left as it
    /// was.
    pub fn set_floor(&mut self, floor: Option<Floor<S>>) -> Result<(), Error> {
        let floor = match floor {
            Some(f) => {
                let unit = super::floor_normal(f.normal, self.unit_up())?;
                // The walk takes the floor's normal as a unit vector (it rejects the wish from
                // it): with the normal (1, 2, 0) of a 27° slope, a walk up it went straight up
                // at twice the wished speed.
                let normal = if f.normal.is_normalized() {
                    f.normal
                } else {
                    unit
                };
                Some(Floor { normal, ..f })
            }
            None => None,
        };
        self.floor = floor;
        Ok(())
    }

    /// A jump: where it stands on a floor, sets its velocity's part along `up` to `speed`
    /// (units per second, as the velocity; keeping the rest), leaves the floor and returns true; in the air, does nothing and
    /// returns false. Set, not added, as Quake III's `PM_CheckJump` does: walking along a
    /// tilted floor gives the velocity a part along `up` (up a ramp, over a stair's edge), and
    /// added to it the jump rose from a stair's edge nearly twice as high as from level ground.
    ///
    /// Errors: [`Error::NaN`] or [`Error::OutOfRange`] for a `speed` outside
    /// `[0, `[`Scalar::LIMIT`]`]` ([`Input::JumpSpeed`]) or a velocity beyond `±LIMIT`, before
    /// the jump or after ([`Input::Velocity`]); the character is left as it was.
    pub fn jump(&mut self, speed: S) -> Result<bool, Error> {
        let speed = check::within(speed, S::ZERO, S::LIMIT, Input::JumpSpeed)?;
        if self.floor.is_none() {
            return Ok(false);
        }
        // Velocity and speed within `±LIMIT`: the terms below stay within three times that,
        // inside every scalar's range, until the result is checked.
        let up = self.unit_up();
        let level =
            check::point(self.velocity, S::LIMIT, Input::Velocity)?.reject_from_normalized(up);
        let velocity = level + up * speed;
        self.velocity = check::point(velocity, S::LIMIT, Input::Velocity)?;
        self.floor = None;
        Ok(true)
    }

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
    /// out to where its radius is below [`min_radius`] (in `f32`, a ball of 0.4 beyond 52 428
    /// units: a fall of 74 s) is refused by the slide as [`Error::RadiusTooSmall`], naming the
    /// coordinates it would reach. Give `dt` in seconds: a time step in
    /// milliseconds is refused only beyond that bound, and below it is obeyed. Then those of the
    /// slides it makes ([`Slider::slide`], [`Slider::step_slide`], [`Slider::snap_to_floor`]):
    /// a move whose target leaves the range ([`Input::Target`]), a ball too small for the
    /// scalar at its coordinates ([`Error::RadiusTooSmall`]). On an error the character is left
    /// as it was.
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
                me.velocity = wish.reject_from_normalized(n);
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
