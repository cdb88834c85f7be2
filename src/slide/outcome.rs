//! What a move reports: [`Slide`], its contacts ([`SlideContact`]) and the floor it found
//! ([`Floor`]).

use super::rules::{Planes, add_planes, constrain, holds};
use super::{MAX_SLIDES, slope_limit};
use crate::{Contact, Error, Input, Scalar, SceneHit, Vec3, check};
use heapless::Vec;
#[cfg(doc)]
use {super::Slider, super::move_and_slide};

/// The outcome of [`move_and_slide`]: a plain `Copy` struct.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
pub struct Slide<S> {
    /// Where the ball's centre ends.
    pub position: Vec3<S>,
    /// How far the ball was moved out of a starting overlap before it moved (zero unless it
    /// started overlapping geometry by more than the skin; see [`move_and_slide`]).
    pub pushed_out: Vec3<S>,
    /// The part of the requested displacement not travelled: what the contacts took away, so
    /// that `position` is the start, `pushed_out`, `displacement` and `-blocked` added up (to
    /// rounding). (A stepped move's is what the move across was denied: see
    /// [`Slider::step_slide`].)
    pub blocked: Vec3<S>,
    /// The contacts met, in order (at most [`MAX_SLIDES`]).
    pub contacts: [Option<SlideContact<S>>; MAX_SLIDES],
}

/// A floor contact and the normal of the floor it stands for (see [`Slide::floor_normal`]).
type Ground<'a, S> = (&'a SlideContact<S>, Vec3<S>);

/// The floor a ground probe found ([`Slider::probe_floor`], [`Slider::snap_to_floor`]): a
/// plain `Copy` struct.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
pub struct Floor<S> {
    /// Its normal, as [`Slide::floor_normal`] gives it (a valley's: between its two slopes).
    pub normal: Vec3<S>,
    /// Where the probe's slide down ended: the ball's centre moved onto the floor, a skin off
    /// it, or where it was if it was closer (a game's floor snap).
    pub position: Vec3<S>,
    /// The index of the triangle whose contact gave the floor (in a valley, that of the later
    /// of its two slopes): what a game looks its surface up by (a footstep's sound).
    pub index: usize,
    /// The feature of that triangle the contact was with: on [`Contact::Face`] the floor is
    /// the triangle's plane; on an edge or vertex `normal` is that of a tangent plane of the
    /// rounded feature, which the ball leaves as soon as it walks on (in a valley, between
    /// two slopes, it is their blend).
    pub contact: Contact,
}

/// A contact met by [`move_and_slide`], with where and when it happened.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
pub struct SlideContact<S> {
    /// What the sweep met: its `position` is the ball's centre at the moment of contact, its
    /// `alpha` a fraction of that sweep (what was left of the motion at the time), not of the
    /// call: see [`time`](Self::time).
    pub hit: SceneHit<S>,
    /// The touched point: the centre (`hit.position`) less the contact's (merged) normal times
    /// the radius.
    pub point: Vec3<S>,
    /// The fraction of the call's time step elapsed at contact, in `[0, 1)`: the call's
    /// displacement is taken as travelled at constant speed over the step, and each sweep
    /// covers what is left of it (Quake's `time_left`).
    #[cfg_attr(feature = "serde", serde(with = "crate::interop::number"))]
    pub time: S,
}

impl<S: Scalar> Slide<S> {
    /// Constrains `velocity` by every plane the move touched, with the same rules as the move
    /// itself: what a caller does to its velocity afterwards. Never lengthens it by more than
    /// rounding, and never turns it against itself. A ball held back by steep slopes clips with
    /// [`Slider::clip`].
    ///
    /// The contacts are taken as a move gives them, with unit normals and planes (a slide read
    /// with `serde` is checked for that; one built by hand must keep to it).
    ///
    /// Errors: [`Error::NaN`] or [`Error::OutOfRange`] for a velocity component beyond
    /// `±`[`Scalar::LIMIT`].
    pub fn clip(&self, velocity: Vec3<S>) -> Result<Vec3<S>, Error> {
        self.clip_within(velocity, None)
    }

    /// [`clip`](Self::clip), also held back by the vertical walls of slopes steeper than a limit
    /// (see [`Slider::with_max_slope`]).
    pub(super) fn clip_within(
        &self,
        velocity: Vec3<S>,
        limit: Option<(Vec3<S>, S)>,
    ) -> Result<Vec3<S>, Error> {
        let v = check::point(velocity, S::LIMIT, Input::Velocity)?;
        let mut planes: Planes<S> = Vec::new();
        let zero = Vec3::ZERO;
        for c in self.contacts.iter().flatten() {
            if !add_planes(&mut planes, &c.hit, limit, |_| None) {
                return Ok(zero);
            }
        }
        Ok(constrain(v, &planes, v))
    }

    /// The last contact that counts as floor: one whose normal lies within a slope limit of
    /// the direction `up` (of any length: it is normalised here), i.e. `normal · up >= min_cos`
    /// with `min_cos` the cosine of the steepest walkable slope (`FRAC_1_SQRT_2` for 45°), less
    /// the rounding of unit normals (eight steps of the scalar), so that a face exactly at the
    /// limit counts. The
    /// character controllers of engines call a ball with such a contact *grounded* (Unity's
    /// `isGrounded`, Godot's `is_on_floor`).
    ///
    /// A valley holds a ball too, though each of its slopes is too steep to stand on: a contact
    /// also counts when one of its planes and a plane touched at the same time or earlier in
    /// the call meet in a crease that holds the ball up (their normals lie either side of `up`)
    /// and whose own slope is walkable (the steepest line of the pair's span, the direction
    /// between the normals nearest `up`, is within the limit). Jolt's `CharacterVirtual` likewise
    /// calls a character on several steep contacts supported when together they stop it sliding
    /// down; here the valley's trough is held to the same slope limit as a single floor. Whether
    /// the two slopes are touched at exactly the same moment, which depends on rounding, then no
    /// longer matters.
    ///
    /// ```
    /// use ballcast::{Scene, Triangle, Vec3, move_and_slide};
    /// let v = Vec3::new;
    /// let mut s: Scene<f32, 2> = Scene::new();
    /// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
    /// let out = move_and_slide(&s, v(0.0, 0.6, 0.0), v(0.1, -0.2, 0.0), 0.5)?;
    /// let floor = out.floor(v(0.0, 1.0, 0.0), core::f32::consts::FRAC_1_SQRT_2)?.expect("landed");
    /// assert!((floor.time - 0.5).abs() < 1e-3); // half-way through the step
    /// assert!((floor.point.y).abs() < 1e-6); // touching the floor's surface
    /// # Ok::<(), ballcast::Error>(())
    /// ```
    ///
    /// Errors: [`Error::NaN`]; [`Error::OutOfRange`] for a component of `up` beyond
    /// `±`[`Scalar::LIMIT`] or `min_cos` outside `[0, 1]`; [`Error::ZeroVector`] for an `up`
    /// of zero (in the scalar).
    pub fn floor(&self, up: Vec3<S>, min_cos: S) -> Result<Option<&SlideContact<S>>, Error> {
        Ok(self.ground(up, min_cos)?.map(|(c, _)| c))
    }

    /// The normal of the floor [`floor`](Self::floor) finds: that contact's normal, or, where
    /// a valley holds the ball, the direction between its two slopes' normals nearest `up`
    /// (level valley: `up` itself). What a character presses into and walks along (README,
    /// the walking recipe): pressed along one steep slope's normal, a ball resting in a valley
    /// touched only that slope and lost the floor every other frame. A ball walked across the
    /// valley into one slope climbs it a little and can lose the floor for a few frames, unless
    /// it is held back by slopes too steep to stand on ([`Slider::with_max_slope`]).
    ///
    /// Errors: as [`floor`](Self::floor).
    pub fn floor_normal(&self, up: Vec3<S>, min_cos: S) -> Result<Option<Vec3<S>>, Error> {
        Ok(self.ground(up, min_cos)?.map(|(_, n)| n))
    }

    /// [`floor`](Self::floor) as a [`Floor`]: its normal, this slide's end, the triangle.
    pub(crate) fn ground_floor(&self, up: Vec3<S>, min_cos: S) -> Result<Option<Floor<S>>, Error> {
        Ok(self.ground(up, min_cos)?.map(|(c, normal)| Floor {
            normal,
            position: self.position,
            index: c.hit.index,
            contact: c.hit.contact,
        }))
    }

    /// [`floor`](Self::floor) with its normal.
    fn ground(&self, up: Vec3<S>, min_cos: S) -> Result<Option<Ground<'_, S>>, Error> {
        let (up, min_cos) = slope_limit(up, min_cos)?;
        let contacts = || self.contacts.iter().flatten();
        let held = |j: usize, c: &SlideContact<S>| {
            let mut earlier = contacts()
                .take(j + 1)
                .flat_map(|e| e.hit.planes.into_iter().flatten());
            let mine = || c.hit.planes.into_iter().flatten();
            earlier.find_map(|b| mine().find_map(|a| holds(a, b, up, min_cos)))
        };
        Ok(contacts()
            .enumerate()
            .filter_map(|(j, c)| {
                let walkable = S::dot(c.hit.normal, up) >= min_cos;
                let n = if walkable {
                    Some(c.hit.normal)
                } else {
                    held(j, c)
                };
                n.map(|n| (c, n))
            })
            .last())
    }
}
