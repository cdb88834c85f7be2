//! A ball's settings: its radius, its skin and the steepest slope it can be carried up.

use super::rules::{FloorStop, magnitude};
use super::{Floor, Slide, min_radius, run, skin, slope_limit};
use crate::{Contact, Error, Geometry, Input, Scalar, SceneHit, Sweep, Vec3, check};

/// A ball's settings for [`Slider::slide`]: its radius and, optionally, its own skin and a
/// slope limit beyond which slopes hold it back like walls.
///
/// ```
/// use ballcast::{Scene, Triangle, Vec3, slide::Slider};
/// let v = Vec3::new;
/// let mut s: Scene<f32, 2> = Scene::new();
/// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
/// let ball = Slider::new(0.5)?.with_skin(0.01)?;
/// let out = ball.slide(&s, v(0.0, 1.0, 0.0), v(0.0, -1.0, 0.0))?;
/// assert!((out.position.y - 0.51).abs() < 1e-6);
/// # Ok::<(), ballcast::Error>(())
/// ```
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slider<S> {
    pub(super) radius: S,
    skin: Option<S>,
    /// `up` as a unit vector and the cosine of the steepest slope the ball can be carried up.
    pub(super) max_slope: Option<(Vec3<S>, S)>,
}

impl<S: Scalar> Slider<S> {
    /// A ball of `radius` with the default [`skin`] and no slope limit.
    ///
    /// Errors: [`Error::NaN`], [`Error::OutOfRange`], [`Error::NegativeRadius`], and
    /// [`Error::RadiusTooSmall`] (with `extent` zero) for a radius too small at any coordinates:
    /// below [`min_radius`] at the origin, zero among them. A radius that is only too small
    /// where the ball goes is refused by the slide that takes it there.
    pub fn new(radius: S) -> Result<Self, Error> {
        let ball = Self::unchecked_size(radius)?;
        let min = min_radius(S::ZERO);
        if ball.radius < min {
            return Err(Error::RadiusTooSmall {
                radius: radius.to_f64(),
                min: min.to_f64(),
                extent: 0.0,
            });
        }
        Ok(ball)
    }

    /// [`new`](Self::new) without the check of the radius's size, for
    /// [`move_and_slide`](super::move_and_slide), which reports a radius too small at the
    /// ball's coordinates.
    pub(super) fn unchecked_size(radius: S) -> Result<Self, Error> {
        Ok(Self {
            radius: check::radius(radius)?,
            skin: None,
            max_slope: None,
        })
    }

    /// The same ball keeping a gap of `skin` from what it touches, for a ground probe sized to
    /// match, say. It is never less than the rounding term of the default [`skin`] (twice the
    /// rounding of a height at the ball's coordinates), which keeps the response exact.
    ///
    /// Errors: [`Error::NaN`], or [`Error::OutOfRange`] for a skin below zero or above
    /// the radius.
    pub fn with_skin(self, skin: S) -> Result<Self, Error> {
        let skin = check::within(skin, S::ZERO, self.radius, Input::Skin)?;
        Ok(Self {
            skin: Some(skin),
            ..self
        })
    }

    /// The same ball held back by slopes too steep to stand on: a contact whose normal `n`
    /// points up (`n · up > 0`, `up` of any length) but is steeper than the limit
    /// (`n · up < min_cos`, as for [`Slide::floor`]) also constrains the rest of the motion
    /// like a vertical wall through the contact (normal: `n`'s horizontal part). Walking or
    /// sliding into such a slope no longer carries the ball up it, while a fall onto it still
    /// slides down. Jolt's `CharacterVirtual` adds the same second constraint beyond its
    /// maximum slope angle, and Godot's `CharacterBody3D` calls it not sliding up steep slopes.
    /// Use [`Slider::clip`] to constrain a velocity the same way. In a walk along a floor
    /// ([`walk`](Self::walk)), a steep contact touched low enough to step over has its wall
    /// stand square on that floor instead (normal: `n`'s part across the floor's normal), so
    /// that what is left of the walk stays on the floor: it neither climbs a face leaning back
    /// by the rise of the ground towards it nor is held back walking up a steep-sided ditch.
    ///
    /// A step's edge is such a slope where the ball rounds it: a riser higher than
    /// `radius * (1 - min_cos)` (0.29 r for 45°) stops a ball it would otherwise lift onto the
    /// step. A grounded ball's walk climbs such ledges with [`step_slide`](Self::step_slide).
    ///
    /// ```
    /// use ballcast::{Scene, Triangle, Vec3, slide::Slider};
    /// let v = Vec3::new;
    /// let mut s: Scene<f32, 2> = Scene::new();
    /// // A 60° slope rising towards +x from x = 0.
    /// let (c, t) = (0.5f32, 3f32.sqrt());
    /// s.push(Triangle::new(v(0.0, 0.0, -9.0), v(0.0, 0.0, 9.0), v(9.0 * c, 9.0 * t * c, 0.0)))?;
    /// let (start, walk) = (v(-0.5, 0.5, 0.0), v(1.0, 0.0, 0.0));
    /// let free = Slider::new(0.5)?.slide(&s, start, walk)?;
    /// assert!(free.position.y > 0.8); // walked into the slope, carried up it
    /// let held = Slider::new(0.5)?.with_max_slope(v(0.0, 1.0, 0.0), 0.7071)?;
    /// let out = held.slide(&s, start, walk)?;
    /// assert_eq!(out.position.y, 0.5); // stopped against it
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    ///
    /// Errors: [`Error::NaN`]; [`Error::OutOfRange`] for a component of `up` beyond
    /// `±`[`Scalar::LIMIT`] or `min_cos` outside `[0, 1]` (a floor faces up); [`Error::ZeroVector`] for an `up`
    /// of zero (in the scalar).
    pub fn with_max_slope(self, up: Vec3<S>, min_cos: S) -> Result<Self, Error> {
        Ok(Self {
            max_slope: Some(slope_limit(up, min_cos)?),
            ..self
        })
    }

    /// The radius.
    pub fn radius(&self) -> S {
        self.radius
    }

    /// The skin used for centres within `±extent`.
    pub fn skin(&self, extent: S) -> S {
        let floor = skin(S::ZERO, extent);
        match self.skin {
            Some(s) if s > floor => s,
            Some(_) => floor,
            None => skin(self.radius, extent),
        }
    }

    /// [`move_and_slide`](super::move_and_slide) with this ball.
    pub fn slide<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        position: Vec3<S>,
        displacement: Vec3<S>,
    ) -> Result<Slide<S>, Error> {
        run(self, scene, position, displacement, None, None)
    }

    /// A ground probe: the floor a ball at `position` rests on, found by a slide of this ball
    /// down along `up` by two skins ([`skin`](Self::skin) at `position`) that ends at the first
    /// floor it meets (not carried on down that floor's slope by the rest of its reach): that
    /// slide's [`Slide::floor_normal`] with the same `up` and `min_cos`, and where it ended
    /// ([`Floor::position`]: at most a skin off the floor, a game's *floor snap*). The ball
    /// itself is not moved. It stops on a rounded edge within the slope limit whether the ball
    /// walks onto it or off it.
    ///
    /// Why: the response keeps a ball a skin off what it touched, and lifts one met at once (a
    /// ball left exactly touching a floor, say) by a skin. A ball resting on a floor is then up
    /// to a skin above it, and a move that presses it down by less than that gap (gravity's
    /// `g dt²` at a high frame rate: 3 steps of `I16F16` at 480 Hz, against a skin of 48 for
    /// r = 0.5) touches nothing, so [`Slide::floor`] of that move finds no floor. A game asks
    /// this probe when the move touched no floor, as Quake III's player movement traces a
    /// quarter unit down each frame (`PM_GroundTrace`) and Godot's `CharacterBody3D` snaps to a
    /// floor within its snap length: running across a level floor at 480 Hz with gravity, an
    /// `I16F16` ball's moves touched the floor on 120 of 480 frames, and with the probe it was
    /// grounded on all of them (at 1920 Hz, on 33 of the first 480 frames, and on all; `f32` and
    /// `f64` on 456, and on all). Where even the press rounds to nothing (`I16F16` from 960 Hz),
    /// a ball on a slope drifts up to two skins off it; moved to [`Floor::position`], it stays
    /// within one.
    ///
    /// Do not take a floor the ball moves away from (`velocity · normal > 0`: a jump's first
    /// frames, still within two skins of the ground) as ground, as Quake III does not.
    /// Two skins reach a walkable floor a skin off along its normal up to 60° steep. In a
    /// valley of slopes too steep to stand on, a ball a skin off both is further above them
    /// than that (80° slopes: 5.8 skins): there the move's own contacts find the valley.
    /// Cost: one slide (one to four sweeps).
    ///
    /// ```
    /// use ballcast::{Scene, Triangle, Vec3, slide::Slider};
    /// let v = Vec3::new;
    /// let mut s: Scene<f32, 2> = Scene::new();
    /// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
    /// let (ball, up, walkable) = (Slider::new(0.5)?, v(0.0, 1.0, 0.0), 0.7071);
    /// let skin = ball.skin(1.0);
    /// // 1.5 skins above the floor: a small press misses it, the probe finds it.
    /// let at = v(0.0, 0.5 + 1.5 * skin, 0.0);
    /// let pressed = ball.slide(&s, at, v(0.0, -skin / 4.0, 0.0))?;
    /// assert!(pressed.floor(up, walkable)?.is_none());
    /// let floor = ball.probe_floor(&s, at, up, walkable)?.expect("within two skins");
    /// assert_eq!(floor.normal, up);
    /// assert!((floor.position.y - (0.5 + skin)).abs() < 1e-6); // snapped to a skin off it
    /// // Three skins above it: in the air.
    /// assert_eq!(ball.probe_floor(&s, v(0.0, 0.5 + 3.0 * skin, 0.0), up, walkable)?, None);
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    ///
    /// Errors: as [`Slider::slide`] (for the probe's move, so keep the world two skins inside
    /// `±`[`Scalar::LIMIT`]) and [`Slide::floor`].
    pub fn probe_floor<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        position: Vec3<S>,
        up: Vec3<S>,
        min_cos: S,
    ) -> Result<Option<Floor<S>>, Error> {
        self.snap_to_floor(scene, position, Vec3::ZERO, up, min_cos, S::ZERO)
    }

    /// [`probe_floor`](Self::probe_floor) reaching `depth` further down: a slide of the ball
    /// `depth` and two skins down along `up`, not kept, and the floor it finds there with
    /// where it ended. A walker that stood on a floor when its frame began and touched none
    /// in the walk (it walked off a stair's step going down, or over a crest faster than
    /// its walk follows the slope beyond) asks this with about its step height and is moved
    /// onto the floor found, as Source's `StayOnGround` traces down by the step height, Godot's
    /// `CharacterBody3D` snaps within its floor snap length and Jolt's `CharacterVirtual`
    /// sticks to the floor. Without it, a ball walking down stairs is in the air from each
    /// step's edge until it lands on the next.
    ///
    /// The slide stops at the first thing below that can be stood on (a ball rolling up over a
    /// ledge's edge stays on the edge, not carried down its slope to the floor below; one rolling
    /// off a step's edge stays on it until the edge's slope passes the limit, not carried around it
    /// by the rest of the reach), and goes on past what is too steep (around the edge of a step,
    /// beyond that). An edge or vertex it meets is one the ball walks off (behind it: its normal
    /// leans along the level part of `heading`, the ball's velocity or the walk's displacement) or
    /// over (ahead of it, the heading crossing it at more than about 15°, or right under it): it is
    /// snapped to only if, clear of it (a radius and a skin past the touched point, level: away
    /// from it, or across it), a cast finds something to stand on (or ground at once below the
    /// centre: the next step of a flight narrower than the ball), a radius deeper than the snap for
    /// one walked off level or down (a step down; a crest, beyond which a slope at the limit lies
    /// up to `0.59 r` lower), no deeper than the snap for one walked over or off moving up (the
    /// landing at a ramp's top, a ledge's top, a step down within the snap). Over a deeper drop (a
    /// cliff, a trench, the lip of a ramp) the snap is the ground probe, so the ball falls or flies
    /// at any speed as it would without the snap. An edge walked along, or met with no heading, is
    /// snapped to as a face is. Rolling around an edge uses up some of the reach: choose `depth` a
    /// quarter more than the highest step down, and at least the drop of a walk down the steepest
    /// walkable slope in a frame (`speed dt tan(slope)`). Do not snap a ball that was not on the
    /// ground (a jump, a fall).
    ///
    /// Walking at 2 units/s down steps of 0.2, a ball of r 0.5 snapping 0.25 was grounded on
    /// every frame, against 136 of 180 with the probe alone; up a 20° ramp, over its top and up
    /// a ledge of 0.2, on every frame, and walking about bumpy ground from its first landing on
    /// (`tests/crests.rs`). Cost: one sweep and one slide, and a second sweep where the ball
    /// meets an edge (one slide for a `depth` of zero, which is
    /// [`probe_floor`](Self::probe_floor), and never finds less).
    ///
    /// ```
    /// use ballcast::{Scene, Triangle, Vec3, slide::Slider};
    /// let v = Vec3::new;
    /// let mut s: Scene<f32, 2> = Scene::new();
    /// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
    /// let (ball, up, walkable) = (Slider::new(0.5)?, v(0.0, 1.0, 0.0), 0.7071);
    /// // 0.2 above the floor (a step down): out of the probe's reach, within the snap's.
    /// let (at, heading) = (v(0.0, 0.7, 0.0), v(2.0, 0.0, 0.0));
    /// assert_eq!(ball.probe_floor(&s, at, up, walkable)?, None);
    /// let floor = ball.snap_to_floor(&s, at, heading, up, walkable, 0.25)?.expect("within 0.25");
    /// assert!((floor.position.y - 0.5).abs() < 1e-3); // moved down onto it, a skin off
    /// assert_eq!(ball.snap_to_floor(&s, v(0.0, 0.8, 0.0), heading, up, walkable, 0.25)?, None);
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    ///
    /// Errors: as [`probe_floor`](Self::probe_floor) (where a sweep `depth` down would leave
    /// the range, the snap is the probe); [`Error::NaN`] or [`Error::OutOfRange`] for a
    /// `depth` below zero or beyond `±`[`Scalar::LIMIT`], or a `heading` outside
    /// `±`[`Scalar::LIMIT`].
    pub fn snap_to_floor<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        position: Vec3<S>,
        heading: Vec3<S>,
        up: Vec3<S>,
        min_cos: S,
        depth: S,
    ) -> Result<Option<Floor<S>>, Error> {
        let snap = self.snap_or_probe(scene, position, heading, (up, min_cos), depth)?;
        Ok(snap.0)
    }

    /// [`snap_to_floor`](Self::snap_to_floor), and whether what it found is the ground probe's
    /// alone (a `depth` of zero, nothing within it, or a drop past an edge): no ground beyond
    /// the ball's floor was found to hold it to.
    pub(super) fn snap_or_probe<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        position: Vec3<S>,
        heading: Vec3<S>,
        (up, min_cos): (Vec3<S>, S),
        depth: S,
    ) -> Result<Snapped<S>, Error> {
        let probe_alone = || {
            let floor = self.snap_to_floor(scene, position, heading, up, min_cos, S::ZERO)?;
            Ok((floor, true))
        };
        let (up_unit, cos) = slope_limit(up, min_cos)?;
        let depth = check::within(depth, S::ZERO, S::LIMIT, Input::Snap)?;
        let heading = check::point(heading, S::LIMIT, Input::Heading)?;
        let skin = self.skin(magnitude(check::point(
            position,
            S::LIMIT,
            Input::Position,
        )?));
        let mut reach = depth + skin + skin;
        let level = |v: Vec3<S>| v - up_unit.scale(S::dot(v, up_unit));
        if depth > S::ZERO {
            let down = |from: Vec3<S>, by: S| {
                let sweep = Sweep::new(from, from - up_unit.scale(by), self.radius).ok()?;
                scene.cast(&sweep)
            };
            // Nothing within reach (or a sweep refused near the range's edge): the probe.
            let Some(hit) = down(position, reach) else {
                return probe_alone();
            };
            // An edge or vertex the ball walks off or over: a step down, a crest or a landing
            // if, clear of it (a radius and a skin past the touched point, level), a cast finds
            // something to stand on; else a drop, where the snap is the ground probe. Walking
            // off it level or down, the cast reaches a radius deeper (a slope at the slope
            // limit lies `0.59 r` below the crest); walking over it, or off it moving up (by
            // more than 1/256 of the speed: more than a walk over a crest's edge, touched a hair
            // behind it, rises), no deeper than the snap itself, so that a ramp's lip over any
            // deeper drop launches the ball.
            if hit.contact != Contact::Face
                && let Some((away, off)) = past_edge(level(hit.normal), level(heading))
            {
                let touched = hit.position - hit.normal.scale(self.radius);
                let clear = self.radius + skin - S::dot(position - touched, away);
                let ahead = position + away.scale(if clear > S::ZERO { clear } else { S::ZERO });
                let rising = S::dot(heading, up_unit) > S::div_pow2(heading.length(), 8);
                let look = if off && !rising {
                    reach + self.radius
                } else {
                    reach
                };
                // Met at once there by something below the centre, the ground rises at least as
                // high as the ball just past the edge (the next step of a flight too narrow for
                // the ball): no drop. (A side wall met at once is no ground: beside a cliff.)
                let below = down(ahead, look);
                let ground = |h: SceneHit<S>| {
                    let slope = S::dot(h.normal, up_unit);
                    slope >= cos || (h.alpha == S::ZERO && slope > S::ZERO)
                };
                if !below.is_some_and(ground) {
                    return probe_alone();
                }
            }
            if S::dot(hit.normal, up_unit) >= cos {
                let near = hit.alpha.mul(reach) + skin + skin;
                reach = if near < reach { near } else { reach };
            }
        }
        let stop = FloorStop {
            up: up_unit,
            min_cos: cos,
        };
        let slide = run(
            self,
            scene,
            position,
            Vec3::ZERO - up_unit.scale(reach),
            Some(stop),
            None,
        )?;
        Ok((slide.ground_floor(up, min_cos)?, depth == S::ZERO))
    }

    /// [`Slide::clip`] of `velocity` by what `slide` (a move of this ball) touched, held back
    /// by the steep slopes' walls as the move was (see [`with_max_slope`](Self::with_max_slope)).
    ///
    /// Errors: as [`Slide::clip`].
    pub fn clip(&self, slide: &Slide<S>, velocity: Vec3<S>) -> Result<Vec3<S>, Error> {
        slide.clip_within(velocity, self.max_slope)
    }
}

/// A snap's floor, and whether it is the ground probe's alone (see
/// [`Slider::snap_or_probe`]).
type Snapped<S> = (Option<Floor<S>>, bool);

/// Where to look past an edge or vertex met by a snap, given the level parts of its normal and
/// of the ball's heading: away from it, with `true`, where the ball walks off it (behind the
/// ball: the normal leans along the heading); across it, with `false`, where the ball walks over
/// it (ahead of the ball, the heading crossing it at more than about 15°: a lip met at an angle
/// is looked across, not along; or right under it, along the heading). `None` where the ball
/// walks along it or has no heading: it is snapped to as a face is.
fn past_edge<S: Scalar>(normal: Vec3<S>, heading: Vec3<S>) -> Option<(Vec3<S>, bool)> {
    let unit = |v: Vec3<S>| S::direction(v).map(|(_, u)| u.map(S::unit_to_scalar));
    let h = unit(heading)?;
    let Some(n) = unit(normal) else {
        return Some((h, false));
    };
    let lean = S::dot(n, h);
    if lean > S::ZERO {
        Some((n, true))
    } else if lean < -S::div_pow2(S::ONE, 2) {
        Some((-n, false))
    } else {
        None
    }
}
