//! The first step of a call: ending a starting overlap.

use super::MAX_SLIDES;
use super::rules::stand_off;
use crate::penetration::deepest;
use crate::{Geometry, Scalar, SceneHit, Sweep, Vec3};

/// Where a ball that starts overlapping `scene` by more than `skin` is moved before its
/// motion: along the deepest overlap's normal by its depth plus the skin, at most
/// [`MAX_SLIDES`] times (each push may uncover the next deepest: a ball in a corner is pushed
/// out of the floor, then out of the wall), each push swept like a motion so that it stops a
/// skin short of anything it would run into. Never farther than
/// `MAX_SLIDES * (radius + skin)` in all.
#[inline(never)] // its frame is live only while it runs, not through the whole motion
pub(super) fn resolve<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    mut centre: Vec3<S>,
    radius: S,
    skin: S,
    rounding: S,
) -> Vec3<S> {
    for _ in 0..MAX_SLIDES {
        let Some(p) = deepest(scene, centre, radius) else {
            break;
        };
        if p.depth <= skin {
            break;
        }
        let push = p.normal.scale(p.depth + skin);
        let Ok(sweep) = Sweep::new(centre, centre + push, radius) else {
            break;
        };
        match scene.cast(&sweep) {
            // Into something it does not yet overlap, or deeper into one it does: stop short.
            Some(hit) if S::dot_sign(push, hit.normal).is_lt() => {
                centre = settle(&hit, centre, push, skin, rounding);
                break;
            }
            // Clear, or met at once alongside an overlap the push does not deepen (another
            // face of a corner): the next round sees what is left.
            _ => centre = sweep.p1(),
        }
    }
    centre
}

/// Where a ball at `from` moving by `rest` comes to rest after meeting `hit`: a skin short of
/// it ([`stand_off`]).
pub(super) fn settle<S: Scalar>(
    hit: &SceneHit<S>,
    from: Vec3<S>,
    rest: Vec3<S>,
    skin: S,
    rounding: S,
) -> Vec3<S> {
    let (alpha, lift) = stand_off(hit, rest, skin, rounding);
    // From the contact's own position (a few steps of `S` off, where alpha's rounding times
    // the path would be more), backed off along the path; or not moved at all.
    if alpha == hit.alpha {
        hit.position + lift
    } else if alpha > S::ZERO {
        hit.position - rest.scale(hit.alpha - alpha)
    } else {
        from
    }
}
