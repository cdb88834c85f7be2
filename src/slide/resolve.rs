//! The first step of a call: ending a starting overlap.

use super::MAX_SLIDES;
use super::push::{around, push_out};
use super::rules::{magnitude, stand_off};
use crate::merge::same_plane;
use crate::penetration::deepest;
use crate::{Geometry, Scalar, SceneHit, Sweep, Vec3};

/// Where a ball that starts overlapping `scene` by more than `skin` is moved before its
/// motion, at most [`MAX_SLIDES`] pushes (each may uncover the next deepest). Each round tries
/// up to three pushes, each swept like a motion so that it stops a skin short of anything it
/// would run into: the joint push ([`push_out`]: out of the deepest overlap and up to two faces
/// that push would fail, both slopes of a valley at once); if something stops it, the push
/// along the deepest overlap's normal alone, where that differs (another overlap may lie
/// against the joint push and not against that one); and if that is stopped too, the push that
/// meets the deepest overlap's demand and leaves what stopped the last one by a skin
/// ([`around`]: over a ridge of the floor that a wall pushes the ball against). The first that
/// gets through is taken; where none does, the one of the first two that got farther. A push is
/// never longer than twice `radius + skin`, and never farther than
/// `2 * MAX_SLIDES * (radius + skin)` in all.
#[inline(never)] // its frame is live only while it runs, not through the whole motion
pub(super) fn resolve<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    mut centre: Vec3<S>,
    radius: S,
    skin: S,
    rounding: S,
) -> Vec3<S> {
    'rounds: for _ in 0..MAX_SLIDES {
        let Some(p) = deepest(scene, centre, radius) else {
            break;
        };
        if p.depth <= skin {
            break;
        }
        let first = p.normal.scale(p.depth + skin);
        let joint = push_out(
            scene,
            centre,
            (radius, skin),
            (p.normal, p.depth + skin),
            rounding,
        );
        // The joint push; if something stops it, the deepest's own, which may get through;
        // if that is stopped too, the push that also leaves what stopped it by a skin.
        let mut stops = [None, None];
        let mut obstacle = None;
        for k in 0..3 {
            let push = match (k, obstacle) {
                (0, _) => joint,
                (1, _) if first != joint => first,
                (_, Some(m)) => match around((p.normal, p.depth + skin), m, (radius, skin)) {
                    Some(x) => x,
                    None => break,
                },
                _ => break,
            };
            let Ok(sweep) = Sweep::new(centre, centre + push, radius) else {
                break;
            };
            match scene.cast(&sweep) {
                // Into something it does not yet overlap, or deeper into one it does: stop short.
                Some(hit) if S::dot_sign(push, hit.normal).is_lt() => {
                    let Some(stop) = stops.get_mut(k) else {
                        break;
                    };
                    *stop = Some(settle(scene, &hit, centre, push, (radius, skin), rounding));
                    obstacle = Some(hit.normal);
                }
                // Clear, or met at once alongside an overlap the push does not deepen (another
                // face of a corner): the next round sees what is left.
                _ => {
                    centre = sweep.p1();
                    continue 'rounds;
                }
            }
        }
        // All stopped: of the first two tried, the one that got farther, the joint push on a
        // tie. (Depths are no guide: next to an inactive edge they are measured to the face's
        // plane.)
        let moved = |c: Vec3<S>| S::direction(c - centre).map_or(S::ZERO, |(len, _)| len);
        centre = match stops {
            [Some(a), Some(b)] if moved(b) > moved(a) => b,
            [Some(a), _] => a,
            _ => centre,
        };
        break;
    }
    centre
}

/// Where a ball at `from` moving by `rest` comes to rest after meeting `hit` in `scene`: a skin
/// short of it ([`stand_off`]), a lift off it swept ([`lift_from`]).
pub(super) fn settle<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    hit: &SceneHit<S>,
    from: Vec3<S>,
    rest: Vec3<S>,
    (radius, skin): (S, S),
    rounding: S,
) -> Vec3<S> {
    let (alpha, lift) = stand_off(hit, rest, skin, rounding);
    // From the contact's own position (a few steps of `S` off, where alpha's rounding times
    // the path would be more), backed off along the path; or not moved along it at all.
    let at = if alpha == hit.alpha {
        hit.position
    } else if alpha > S::ZERO {
        return hit.position - rest.scale(hit.alpha - alpha);
    } else {
        from
    };
    // A lift (an approach, a skin) smaller than the position's rounding is lost (all of it, or all
    // but a coordinate near zero): the ball would stay touching, met again by every later
    // move. Lifted by a rounding of a height instead. (Fixed-point adds exactly: never.)
    let lift = if S::dot((at + lift) - at, hit.normal) < S::div_pow2(S::dot(lift, hit.normal), 1) {
        hit.normal.scale(rounding)
    } else {
        lift
    };
    lift_from(scene, at, (hit.normal, lift), (radius, skin), rounding)
}

/// Where a ball at `at` ends after a lift (off a plane, a skin or a few steps) that is swept
/// like a motion: in a corner narrower than 90° it points partly into the other wall. Stopped
/// by another plane, it stands a skin short of it along the lift, or, where that is less than
/// half the way (a slot or corner too narrow for a skin on both sides), half way; met by one
/// at once (a ball resting in the corner), or within a position's rounding where the lift can
/// slide along it, the lift slides along it, once; and if that is met at once too by the same
/// plane (within 1e-3 rad), or the first lift is met at once by a plane it runs along or leaves,
/// it becomes the shortest lift that leaves both (the first plane, `normal`, by as much as
/// before, the other by a skin), unless the two are within about 14° of opposed.
fn lift_from<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    at: Vec3<S>,
    (normal, mut lift): (Vec3<S>, Vec3<S>),
    (radius, skin): (S, S),
    rounding: S,
) -> Vec3<S> {
    // What the first lift asks of its plane, and the plane the lift slid along, if it did.
    let first = (normal, S::dot(lift, normal));
    let mut along = None;
    for round in 0..3 {
        if lift == Vec3::ZERO {
            return at;
        }
        let Ok(sweep) = Sweep::new(at, at + lift, radius) else {
            return at;
        };
        let Some(next) = scene.cast(&sweep) else {
            return at + lift;
        };
        // Slid along a plane and met by it again (or by another of its triangles, whose
        // normal rounds a little apart), which only rounding does: a lift of a few steps of
        // the coordinates' rounding (`f32` a thousand units out) rounds into it. Left touching
        // the first plane, the ball met it at once on every later move along the corner (stuck
        // in a ditch): lifted off both instead, a skin off the other.
        if along.take().is_some_and(|a| same_plane(a, next.normal)) {
            let Some(both) = around(first, next.normal, (radius, skin)) else {
                return at;
            };
            lift = both;
            continue;
        }
        let into = S::dot(lift, next.normal);
        let slid = lift - next.normal.scale(into);
        // Met within a position's rounding by a plane the lift can slide along (keeping over
        // half of it: not a slot's other wall, square to it), it is met at once: half that
        // travel left the ball touching (`f32` a thousand units out, lifted off one side of a
        // narrow valley into the other), and the same side met it at once on every sweep.
        let length = magnitude(lift);
        let soon = length.mul(next.alpha) <= rounding && magnitude(slid) > S::div_pow2(length, 1);
        if next.alpha > S::ZERO && !soon {
            let half = at + (next.position - at).map(|c| S::div_pow2(c, 1));
            return match stand_off(&next, lift, skin, rounding) {
                (a, _) if a < next.alpha && a > S::div_pow2(next.alpha, 1) => {
                    next.position - lift.scale(next.alpha - a)
                }
                _ => half,
            };
        }
        if round > 0 {
            return at;
        }
        // Met at once by a plane it runs along or leaves, which only rounding does (the ball
        // within a position's rounding of a floor and a wall square on it, `f32` a few hundred
        // units out): lifted off both, a skin off the other; left touching both, the ball was
        // met by the first at once on every later move (stuck for good against the wall).
        if into >= S::ZERO {
            let Some(both) = around(first, next.normal, (radius, skin)) else {
                return at;
            };
            lift = both;
            continue;
        }
        (lift, along) = (slid, Some(next.normal));
    }
    at
}
