//! What a walker that leaves the floor does: whether its walk leaves the floor that held it,
//! how far the snap reaches after it, whether it rolls off an edge it walks off, and how fast
//! it may rise (used by
//! [`Character::update`](super::Character::update)).

use super::Floor;
use crate::{Contact, Scalar, Vec3};

/// Whether a walk by `walk` leaves `floor`, an edge or vertex it was pressed onto: the walk
/// goes along the feature's tangent plane and away across it (along the level part of its
/// normal, `up` a unit vector), off the rounded feature, so the press's floor does not hold the
/// ball and the snap finds the floor where the walk ended, as when the press falls short of
/// it. Held by the press every other frame in `f64` (on the frames after a snap, which leave
/// the ball on the edge) and snapped every frame in `I16F16` (whose press is a probe), a ball
/// rolled over each stair's edge two frames or one at a time, left the edge a frame apart, and
/// walked down stairs 1 % to 3 % less far in `I16F16` than in `f64` (steps of 0.15 on 0.4, r
/// 0.4, 5 units/s at 144 Hz, as the walk began a unit or half a unit before the top step's edge).
pub(super) fn walks_off<S: Scalar>(floor: &Floor<S>, walk: Vec3<S>, up: Vec3<S>) -> bool {
    let level = |v: Vec3<S>| v.reject_from_normalized(up);
    floor.contact != Contact::Face && S::dot(level(floor.normal), level(walk)) > S::ZERO
}

/// How far the snap reaches down after a walk that left the floor and rose by `extra` more
/// than its floor's plane foretold: the snap's depth `snap`, and that rise where it is positive,
/// at most `LIMIT` (a snap of zero stays the ground probe alone).
pub(super) fn snap_depth<S: Scalar>(snap: S, extra: S) -> S {
    if snap > S::ZERO && extra > S::ZERO {
        let sum = snap + extra;
        if sum > S::LIMIT { S::LIMIT } else { sum }
    } else {
        snap
    }
}

/// Whether a ball of radius `r` moving at `velocity` leaves `floor` where that is an edge or
/// vertex: it moves away across it faster than gravity can hold its centre on the circle of
/// radius r round it, `v² > g r cos θ`, with `v` the velocity's part along the level part of
/// the contact's normal (across the edge), `g` gravity's part down the unit `up` and θ the
/// normal's angle from `up`: where the push of the floor would have to pull, as a bead sliding
/// over a sphere leaves it (the textbook condition of circular motion, `v² / r = g cos θ`).
/// Held by the probe two skins below instead, the ball rolled round the edge of a drop whenever
/// a frame's fall from the edge's tangent was shorter than that: at 4 units/s at 960 Hz, not at
/// 60 or 240, and it left the edge at the slope limit with half its speed.
pub(super) fn rolls_off<S: Scalar>(
    floor: &Floor<S>,
    velocity: Vec3<S>,
    gravity: Vec3<S>,
    (up, r): (Vec3<S>, S),
) -> bool {
    if floor.contact == Contact::Face {
        return false;
    }
    let Some((_, out)) = S::direction(floor.normal.reject_from_normalized(up)) else {
        return false;
    };
    let across = S::dot(velocity, out.map(S::unit_to_scalar));
    let down = -S::dot(gravity, up);
    let down = if down > S::ZERO { down } else { S::ZERO };
    let hold = r.mul(S::dot(floor.normal, up));
    across > S::ZERO && S::mul_cmp(across, across, down, hold).is_gt()
}

/// `velocity` rising along the unit `up` no faster than `rose` in `dt` (nor at all where that
/// is not above zero).
pub(super) fn rising_at_most<S: Scalar>(velocity: Vec3<S>, up: Vec3<S>, rose: S, dt: S) -> Vec3<S> {
    let rising = S::dot(velocity, up);
    if rising.mul(dt) <= rose {
        return velocity;
    }
    let most = if rose > S::ZERO {
        rose.div(dt)
    } else {
        S::ZERO
    };
    velocity - up.scale(rising - most)
}
