//! [`Character`]: the README's character loop as a type, one call a frame.

mod update;

use super::rules::magnitude;
use super::{Floor, Slider, min_radius};
use crate::{Error, Input, Scalar, Vec3, check};

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
/// friction and no inertia on the floor: it takes the wished velocity at once, as its part
/// along the floor (or at the speed of its part across `up`,
/// [`with_constant_speed`](Self::with_constant_speed)).
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
    constant_speed: bool,
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
            constant_speed: false,
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

    /// The same character walking at the same speed on every slope (Godot's
    /// `floor_constant_speed`): on a floor, its walk takes the wish's part across `up` (the
    /// heading and speed a map shows) and turns it into the floor's plane at that speed; the
    /// wish's component along `up` is ignored. Off, the default, the walk is the wish's part along
    /// the floor's plane as it is: for a level wish heading straight up or down a slope of angle
    /// `θ`, `cos θ` of the wished speed (`cos² θ` of it across `up`); heading across the slope,
    /// all of it. In the air the option changes nothing.
    ///
    /// Rounding: the heading is a unit vector in the scalar (`I16F16`: of length within about
    /// `2^-15` of one) times the speed, each rounded once; over a second at 2 units/s on 15° to
    /// 40° slopes the distance walked was within 1e-3 of 2 (`I16F16`), 3e-5 (`f32`). A wish
    /// near the range's edge can give a walk beyond it (see [`update`](Self::update)'s errors).
    pub const fn with_constant_speed(self, on: bool) -> Self {
        Self {
            constant_speed: on,
            ..self
        }
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

    /// The normal of the floor it stands on, if any ([`Slide::floor_normal`](crate::Slide::floor_normal)'s, or the probe's).
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
}
