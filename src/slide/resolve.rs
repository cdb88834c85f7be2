//! The first step of a call: ending a starting overlap.

use super::MAX_SLIDES;
use super::rules::stand_off;
use crate::penetration::{deepest, overlap};
use crate::{Geometry, Scalar, SceneHit, Sweep, Vec3};

/// Where a ball that starts overlapping `scene` by more than `skin` is moved before its
/// motion, at most [`MAX_SLIDES`] pushes (each may uncover the next deepest). Each round tries
/// the joint push ([`push_out`]: the deepest overlap and the one that push would fail most,
/// both slopes of a valley at once), then, if something stops it, the push along the deepest
/// overlap's normal alone (a third overlap may lie against the joint push and not against
/// that one). Each is swept like a motion, so that it stops a skin short of anything it would
/// run into; where both are stopped, the one leaving the shallower overlap is kept. A push is
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
        // The joint push; if something stops it, the deepest's own, which may get through.
        let mut stops = [None, None];
        for (k, push) in [joint, first].into_iter().enumerate() {
            if k == 1 && push == joint {
                break;
            }
            let Ok(sweep) = Sweep::new(centre, centre + push, radius) else {
                break;
            };
            match scene.cast(&sweep) {
                // Into something it does not yet overlap, or deeper into one it does: stop short.
                Some(hit) if S::dot_sign(push, hit.normal).is_lt() => {
                    stops[k] = Some(settle(&hit, centre, push, skin, rounding));
                }
                // Clear, or met at once alongside an overlap the push does not deepen (another
                // face of a corner): the next round sees what is left.
                _ => {
                    centre = sweep.p1();
                    continue 'rounds;
                }
            }
        }
        // Both stopped: where the overlap left is shallower, the joint push's on a tie.
        let left = |c: Vec3<S>| deepest(scene, c, radius).map_or(S::ZERO, |p| p.depth);
        centre = match stops {
            [Some(a), Some(b)] if left(b) < left(a) => b,
            [Some(a), _] => a,
            _ => centre,
        };
        break;
    }
    centre
}

/// The push for a ball at `c` whose deepest overlap is `(normal, depth)`. Moving along that
/// normal alone can leave the ball in, or put it into, another triangle: in a valley narrower
/// than a right angle the push out of one slope runs into the other. Every triangle asks the
/// push `x` for `n · x >= r + skin - distance` (exact for a plane; for an edge or vertex, whose
/// distance grows at least that fast, a sufficient bound). The push is the shortest that meets
/// the deepest's demand and the one it fails most (a least-distance problem on two planes,
/// solved by its active set): along the first normal alone if that fails no other by more than
/// rounding; along the second alone if that also meets the first; else in their span, meeting
/// both exactly. Normals within about 14° of parallel or opposed (a shallow crease, a slot
/// narrower than the ball) keep the first push: the next round sees what is left. The push is
/// at most `2 (r + skin)` long, its direction kept.
fn push_out<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    c: Vec3<S>,
    (r, skin): (S, S),
    (n1, to1): (Vec3<S>, S),
    rounding: S,
) -> Vec3<S> {
    let first = n1.scale(to1);
    let Some((n2, to2)) = most_failed(scene, c, (r, skin), (first, to1), rounding) else {
        return first;
    };
    let cos = S::dot(n1, n2);
    let det = (S::ONE - cos).mul(S::ONE + cos);
    if det < S::div_pow2(S::ONE, 4) {
        return first;
    }
    // In quarters, so that every sum stays within range for a radius up to `LIMIT`.
    let (q1, q2) = (S::div_pow2(to1, 2), S::div_pow2(to2, 2));
    let a = q1 - cos.mul(q2);
    if a <= S::ZERO {
        return n2.scale(to2);
    }
    let Some((len, dir)) = S::direction(n1.scale(a) + n2.scale(q2 - cos.mul(q1))) else {
        return first;
    };
    // A quarter of the push's length, `len / det`, capped at half of `r + skin`.
    let half_cap = S::div_pow2(r + skin, 1);
    let quarter = if len < half_cap.mul(det) {
        len.div(det)
    } else {
        half_cap
    };
    let half = quarter + quarter;
    dir.map(|u| S::mul_unit(half + half, u))
}

/// The triangle that the push `x`, of length `len`, leaves overlapping most: its normal and how
/// far along it the ball must move, `r + skin` less its distance; `None` if every triangle is
/// met within `slack`. Distances are taken with the radius grown by `skin + len`, so that the
/// triangles the push may run into count too. The largest failure wins, the smaller index on a
/// tie, whatever the visiting order.
fn most_failed<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    c: Vec3<S>,
    (r, skin): (S, S),
    (x, len): (Vec3<S>, S),
    slack: S,
) -> Option<(Vec3<S>, S)> {
    let grown = r + skin + len;
    let reach = Vec3::new(grown, grown, grown);
    let mut worst: Option<(S, usize, Vec3<S>, S)> = None;
    scene.visit(c - reach, c + reach, &mut |index, t| {
        let Some(p) = overlap(t, c, grown, index) else {
            return;
        };
        // `p.depth` is `grown - distance`.
        let want = p.depth - len;
        let fails = want - S::dot(p.normal, x);
        let worse = worst.is_none_or(|(f, i, _, _)| fails > f || (fails == f && index < i));
        if fails > slack && worse {
            worst = Some((fails, index, p.normal, want));
        }
    });
    worst.map(|(_, _, n, want)| (n, want))
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
