//! Stepping up: a walk stopped by a low ledge climbs onto it, as Quake's player movement does
//! (`PM_StepSlideMove` in Quake III, `PM_GroundMove` in QuakeWorld): the move is tried as it
//! is, and again lifted by the step's height, across, and lowered back, and the stepped one is
//! kept where it got past what stopped the first.

use super::resolve::settle;
use super::rules::{Walk, magnitude};
use super::{MAX_SLIDES, Slide, SlideContact, Slider, floor_normal, run, slope_limit};
use crate::{Error, Geometry, Input, Scalar, Sweep, Vec3, check};

impl<S: Scalar> Slider<S> {
    /// [`slide`](Self::slide) for a walk on the ground that steps up onto low ledges. Where the
    /// move as it is ran into something too steep to stand on (a riser, a wall: `normal · up <
    /// min_cos`, as for [`Slide::floor`], with the walk pressing into it), the step is tried,
    /// into each such contact in turn, the lowest touched first (in an inside corner the walk
    /// slides along the side wall into the riser's edge): the ball is slid up along `up` by
    /// `height` (less under a ceiling), then across, then back down by what it rose and two
    /// skins. The stepped move is kept if it lands on a floor more than two skins higher than
    /// it started, more than two skins past where the move as it is stopped (level, into what
    /// stopped it: a wall beside an up-slope is no ledge), and farther along the walk (along
    /// the level part of `displacement`); else, and wherever a part of it is refused (near the
    /// edge of the range), the move as it is is returned.
    ///
    /// A ball is round: stopped at a riser, it must be carried some way over the edge before
    /// the edge holds it up as a floor (its contact normal within the slope limit). The move
    /// across is therefore `displacement` plus, level and into the riser, what it lacks of
    /// that distance: for a ledge as high as the ball rose (at most `r`),
    /// `sqrt(h (2r - h)) - r sqrt(1 - min_cos²)` and two skins (0.16 r for `h = r / 2` and 45°;
    /// nothing for ledges up to `r (1 - min_cos)`, which the walk climbs by itself). A step can
    /// so carry the ball farther than `displacement`, once per ledge, as Jolt's `WalkStairs`
    /// steps forward by at least a minimum distance, and a walk that meets a riser at a slant
    /// is carried over it, not along it.
    ///
    /// Which ledges: heights are measured from the ball's lowest point where it stopped (on a
    /// slope running up to a riser, that is below the slope's top). A ledge up to `height`
    /// with a floor beyond it is climbed at any speed. The ball rises by `height` and by what
    /// the walk itself rises (up a ramp to a ledge at its top), and, as the walk alone climbs
    /// `r (1 - min_cos)` (with the ball's own slope limit at `min_cos`, as in the README's
    /// recipe), a move across long enough climbs ledges up to `height + r (1 - min_cos)` above
    /// that; higher ones stop it as a wall would.
    ///
    /// The lowering stops at the first thing below, a skin short of it (a slide would carry a
    /// ball landed on a walkable part of an edge down it, off the ledge). A stepped move's
    /// contacts are the last of the move across and the landing, each `time` a fraction of its
    /// own part; `blocked` is what the move across was denied. Use it for the walk of a
    /// grounded ball (the README's recipe), not for a fall: stepping while falling past a
    /// ledge would catch the ball on it. Quake steps 18 units for a player 32 wide; about half
    /// the radius suits a ball. Cost: a contact touched more than `height + r (1 - c)` above
    /// the ball's lowest point, plus two skins and what the walk itself rises, is no step and
    /// costs nothing more (`c` is the looser of `min_cos` and the ball's own
    /// [`with_max_slope`](Self::with_max_slope) limit, or 0 without one: what the walk climbs
    /// by itself). A ledge too high, or a wall touched at `r` for steps below `r c`, is so
    /// passed over: a walk along or into such walls casts what [`slide`](Self::slide) casts. A
    /// step that is tried and dropped (a ledge within reach with no room or floor above it)
    /// adds three sweeps, or more where the lift or the move across slides.
    ///
    /// ```
    /// use ballcast::{Scene, Triangle, Vec3, slide::Slider};
    /// let v = Vec3::new;
    /// let mut s: Scene<f32, 6> = Scene::new();
    /// // A floor at y = 0 up to x = 1, a riser 0.2 high, and a floor at y = 0.2 beyond it.
    /// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(1.0, 0.0, 9.0)))?;
    /// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(1.0, 0.0, 9.0), v(1.0, 0.0, -9.0)))?;
    /// s.push(Triangle::new(v(1.0, 0.0, -9.0), v(1.0, 0.0, 9.0), v(1.0, 0.2, 9.0)))?;
    /// s.push(Triangle::new(v(1.0, 0.0, -9.0), v(1.0, 0.2, 9.0), v(1.0, 0.2, -9.0)))?;
    /// s.push(Triangle::new(v(1.0, 0.2, -9.0), v(1.0, 0.2, 9.0), v(9.0, 0.2, 9.0)))?;
    /// s.push(Triangle::new(v(1.0, 0.2, -9.0), v(9.0, 0.2, 9.0), v(9.0, 0.2, -9.0)))?;
    /// let (up, walkable) = (v(0.0, 1.0, 0.0), 0.7071);
    /// let ball = Slider::new(0.5)?.with_max_slope(up, walkable)?;
    /// let (at, walk) = (v(0.4, 0.5005, 0.0), v(0.3, 0.0, 0.0));
    /// assert!(ball.slide(&s, at, walk)?.position.x < 0.6); // stopped by the riser
    /// let out = ball.step_slide(&s, at, walk, up, walkable, 0.25)?;
    /// // Up on the ledge's edge, which holds it as a floor: the next walk rolls it over.
    /// assert!(out.position.x > 0.69 && out.position.y > 0.59);
    /// assert!(out.floor(up, walkable)?.is_some());
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    ///
    /// Errors: as [`slide`](Self::slide) (for the move as it is) and [`Slide::floor`];
    /// [`Error::NaN`] or [`Error::OutOfRange`] for a `height` below zero or beyond
    /// `±`[`Scalar::LIMIT`].
    pub fn step_slide<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        position: Vec3<S>,
        displacement: Vec3<S>,
        up: Vec3<S>,
        min_cos: S,
        height: S,
    ) -> Result<Slide<S>, Error> {
        self.walk(scene, position, displacement, None, (up, min_cos), height)
    }

    /// [`step_slide`](Self::step_slide) of a walk along the floor the ball stands on (`floor`,
    /// its normal, of any length: [`Slide::floor_normal`] of the last frame, say), which keeps
    /// to that floor where a wall stops it: what is left of the walk runs along the crease of
    /// the floor and the wall, as Quake III's `PM_SlideMove` starts its planes with the
    /// ground's. A wall is a contact the ball can neither stand on nor step over (by the rule
    /// above). With `step_slide`, a walk up a slope into a wall keeps the walk's rise and
    /// climbs the wall by it, to be pressed back down the next frame: the ball bobs by the
    /// rise every frame, and where the floor also tilts along the wall, creeps along it. A
    /// walkable contact becomes the floor the rest keeps to. Which walls count depends on the
    /// slope limit and the step: with [`with_max_slope`](Self::with_max_slope) at 45° and a
    /// step of half the radius, walls within about 11° of vertical (or leaning over); without a
    /// slope limit of its own the ball climbs anything touched below its centre, so no wall
    /// counts. [`Character`](super::Character) walks this way.
    ///
    /// ```
    /// use ballcast::{Scene, Triangle, Vec3, slide::Slider};
    /// let v = Vec3::new;
    /// // A floor rising 1 in 5 towards a wall at x = 3 (facing -x).
    /// let mut s: Scene<f64, 4> = Scene::new();
    /// s.push(Triangle::new(v(-9.0, -1.8, -9.0), v(-9.0, -1.8, 9.0), v(4.0, 0.8, 9.0)))?;
    /// s.push(Triangle::new(v(-9.0, -1.8, -9.0), v(4.0, 0.8, 9.0), v(4.0, 0.8, -9.0)))?;
    /// s.push(Triangle::new(v(3.0, -5.0, -9.0), v(3.0, -5.0, 9.0), v(3.0, 9.0, 9.0)))?;
    /// s.push(Triangle::new(v(3.0, -5.0, -9.0), v(3.0, 9.0, 9.0), v(3.0, 9.0, -9.0)))?;
    /// let (up, walkable) = (v(0.0, 1.0, 0.0), core::f64::consts::FRAC_1_SQRT_2);
    /// let ball = Slider::new(0.5)?.with_max_slope(up, walkable)?;
    /// let floor = v(-0.2, 1.0, 0.0); // of any length
    /// // Against the wall, a skin off the floor, walking on into it along the floor.
    /// let y = 0.2 * 2.4995 + 0.5 * 1.04f64.sqrt() + 0.0005;
    /// let (at, walk) = (v(2.4995, y, 0.0), v(0.05, 0.01, 0.0));
    /// let bobs = ball.step_slide(&s, at, walk, up, walkable, 0.25)?;
    /// assert!(bobs.position.y > at.y + 0.009); // up the wall by the walk's rise
    /// let keeps = ball.walk(&s, at, walk, Some(floor), (up, walkable), 0.25)?;
    /// assert!((keeps.position - at).length() < 1e-3); // stays in the crease
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    ///
    /// Errors: as [`step_slide`](Self::step_slide); [`Error::NaN`], [`Error::OutOfRange`] or
    /// [`Error::ZeroVector`] for a `floor` that is NaN, beyond `±`[`Scalar::LIMIT`] or zero;
    /// [`Error::OutOfRange`] with [`Input::FloorFacing`](crate::Input::FloorFacing) for one
    /// that faces down (its cosine with `up` negative: a ceiling is no floor).
    #[inline(never)]
    pub fn walk<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        position: Vec3<S>,
        displacement: Vec3<S>,
        floor: Option<Vec3<S>>,
        (up, min_cos): (Vec3<S>, S),
        height: S,
    ) -> Result<Slide<S>, Error> {
        let (up_unit, cos) = slope_limit(up, min_cos)?;
        let floor = floor.map(|n| floor_normal(n, up_unit)).transpose()?;
        let height = check::within(height, S::ZERO, S::LIMIT, Input::Step)?;
        // The walk climbs by itself what its own slope limit lets it (without one, anything
        // touched below the centre): the looser of that limit and `min_cos`.
        let own = self.max_slope.map_or(S::ZERO, |(_, c)| c);
        let own = if own > S::ZERO { own } else { S::ZERO };
        let climbs = if own < cos { own } else { cos };
        // A walk up a ramp carries the lifted ball its own rise higher still. (Not so the move
        // as it is: with that rise in its reach, a walk of 0.13 a frame up a 40° slope, at 30
        // Hz, took the upright wall at its top for a ledge to step over, climbed it by the
        // rise, and was launched off it.)
        let rising = S::dot(displacement, up_unit);
        let rising = if rising > S::ZERO { rising } else { S::ZERO };
        let walk = floor.map(|floor| {
            let skin = self.skin(magnitude(position));
            Walk {
                floor,
                up: up_unit,
                stands: cos,
                climbs,
                reach: height + skin + skin,
            }
        });
        let plain = run(self, scene, position, displacement, None, walk)?;
        if height == S::ZERO {
            return Ok(plain);
        }
        let level = |v: Vec3<S>| v - up_unit.scale(S::dot(v, up_unit));
        let (start, wish) = (position + plain.pushed_out, level(displacement));
        let skin = self.skin(magnitude(start));
        // The contacts too steep to stand on that the walk ran into (risers, walls), each with
        // the level direction into it and the height of its touched point. A contact touched
        // `r (1 - n·up)` above the ball's lowest point, more than `height`, two skins and the
        // walk's own rise above what the walk climbs by itself, `r (1 - climbs)`, is passed
        // over: lifted by `height`, the ball would meet it as too steep again and come back
        // down where it was.
        let mut risers = [None; MAX_SLIDES];
        let within = height + skin + skin + rising;
        let pressed = plain.contacts.iter().flatten().filter(|c| {
            let slope = S::dot(c.hit.normal, up_unit);
            slope < cos
                && S::dot(displacement, c.hit.normal) < S::ZERO
                && self.radius.mul(climbs - slope) <= within
        });
        for (slot, c) in risers.iter_mut().zip(pressed) {
            *slot = S::direction(Vec3::ZERO - level(c.hit.normal))
                .map(|(_, into)| (S::dot(c.point, up_unit), into.map(S::unit_to_scalar)));
        }
        // Lowest touched point first: in an inside corner the walk slides along the side wall
        // (touched at the centre's height) into the riser (touched lower, at its edge).
        for _ in 0..MAX_SLIDES {
            let lowest = (risers.iter().enumerate())
                .filter_map(|(i, r)| r.map(|(h, _)| (i, h)))
                .reduce(|a, b| if b.1 < a.1 { b } else { a });
            let Some((_, into)) = lowest.and_then(|(i, _)| risers.get_mut(i)?.take()) else {
                break;
            };
            // Lifted by the walk's own rise too, which the contacts it may step over allow
            // for: the move across, blocked at the edge, would not rise by it.
            let lift = height + rising;
            let step = |walk| self.stepped(scene, start, walk, into, (up_unit, cos), lift);
            // Past where the walk stopped, across what stopped it (not merely higher: a wall
            // beside an up-slope), and farther along the walk (measured along its unit
            // direction: fixed-point products of two short vectors round to zero).
            let past = |out: &Slide<S>| {
                let ahead = out.position - plain.position;
                let along = S::direction(wish)
                    .is_none_or(|(_, w)| S::dot(level(ahead), w.map(S::unit_to_scalar)) > S::ZERO);
                S::dot(ahead, into) > skin + skin && along
            };
            // A walk that goes farther into the riser than a step must carry the ball, dropped,
            // is tried once more carried only that far (no walk of its own): running up stairs
            // narrower than a frame's walk, the move across ran into the second riser, and
            // lowered from there the ball came down on the first step's nosing, too steep to
            // stand on; dropped every frame, the step held the ball at the foot of the stairs.
            let carry = landing(self.radius, lift, cos) + skin + skin;
            // The second try in the first's place: one slide on the stack, not two.
            let mut out = step(displacement).filter(past);
            if out.is_none() && S::dot(displacement, into) > carry {
                out = step(Vec3::ZERO).filter(past);
            }
            if let Some(out) = out {
                return Ok(Slide {
                    pushed_out: plain.pushed_out,
                    ..out
                });
            }
        }
        Ok(plain)
    }

    /// The move lifted by up to `height` along `up` (a unit vector), across (carried at least
    /// [`landing`] and two skins along `into`, the level unit direction into the riser), and
    /// lowered by what it rose and two skins onto a floor; `None` if it lands on none, or if a
    /// part is refused or cannot rise by more than a skin.
    fn stepped<G: Geometry<S> + ?Sized>(
        &self,
        scene: &G,
        start: Vec3<S>,
        displacement: Vec3<S>,
        into: Vec3<S>,
        (up, min_cos): (Vec3<S>, S),
        height: S,
    ) -> Option<Slide<S>> {
        let skin = self.skin(magnitude(start));
        let raised = self.slide(scene, start, up.scale(height)).ok()?;
        let rise = S::dot(raised.position - start, up);
        if rise <= skin {
            return None;
        }
        let short = landing(self.radius, rise, min_cos) + skin + skin - S::dot(displacement, into);
        let forward = if short > S::ZERO {
            displacement + into.scale(short)
        } else {
            displacement
        };
        let mut out = self.slide(scene, raised.position, forward).ok()?;
        // Lowered onto the first thing below, a skin short of it as a slide stops: a slide
        // would carry on down a walkable edge, back off the ledge.
        let (r, from) = (self.radius, out.position);
        let drop = Vec3::ZERO - up.scale(rise + skin + skin);
        let hit = scene.cast(&Sweep::new(from, from + drop, r).ok()?)?;
        if S::dot(hit.normal, up) < min_cos {
            return None;
        }
        let rounding = S::height_error(magnitude(from));
        let position = settle(scene, &hit, from, drop, (r, skin), rounding);
        // On a ledge, not back where it started.
        if S::dot(position - start, up) <= skin + skin {
            return None;
        }
        // The move across's last contacts (they fill its slots from the first), then the
        // landing; built in the move across's own slide.
        let kept = out.contacts.iter().flatten().count();
        if kept == MAX_SLIDES {
            out.contacts.rotate_left(1);
        }
        out.contacts[kept.min(MAX_SLIDES - 1)] = Some(SlideContact {
            hit,
            point: hit.position - hit.normal.scale(r),
            time: hit.alpha,
        });
        out.position = position;
        out.pushed_out = Vec3::ZERO;
        Some(out)
    }
}

/// How far past a ledge's edge a ball of radius `r` must be carried after rising by `rise` to
/// come down on a walkable part of it: stopped at the riser of a ledge `h = min(rise, r)` high,
/// its centre stands `sqrt(h (2r - h))` short of the edge across the riser, and the edge holds
/// it up as a floor (contact normal within the limit `min_cos` of `up`) only within
/// `r sqrt(1 - min_cos²)` of it. Zero where the first is the smaller (ledges up to
/// `r (1 - min_cos)`, which the walk climbs by itself). Jolt's `WalkStairs` likewise steps
/// forward at least a minimum distance, so that a short step still clears the edge.
fn landing<S: Scalar>(r: S, rise: S, min_cos: S) -> S {
    let h = if rise < r { rise } else { r };
    let z = S::ZERO;
    let at_riser = S::chord(r, Vec3::new(r - h, z, z)).unwrap_or(z);
    let cos = if min_cos > z { min_cos } else { z };
    let held = S::chord(r, Vec3::new(r.mul(cos), z, z)).unwrap_or(z);
    if at_riser > held { at_riser - held } else { z }
}
