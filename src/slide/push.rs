//! The push out of a starting overlap: the shortest move that leaves the deepest overlap, and
//! up to two faces that this move would fail, a skin clear.
//!
//! A face near the ball asks the push `x` for `n · x >= r + skin - distance`, with `n` its
//! normal: exactly what clears it, so the shortest push meeting several is a least-distance
//! problem over half-spaces. It is solved by growing its active set from the deepest overlap:
//! the push along its normal; if that fails a face by more than rounding, the push meeting
//! both exactly (in a valley narrower than a right angle, along its bisector); if that fails a
//! third (a pit), the push meeting all three, where each normal has a positive weight in it.
//! Only faces the centre lies over take part: for an edge or vertex the same demand is only a
//! bound (its distance grows at least that fast), and meeting it can send the ball far along
//! a slot between two edges that the push along the deepest normal clears; beside a face, next
//! to an inactive edge, its whole plane would stand in for the edge (a stair's riser for its
//! nosing). The sweep of the push still stops short of them. Pushes are at most `2 (r + skin)` long, their direction kept.

use crate::penetration::nearest;
use crate::{Geometry, Scalar, Vec3};

use super::rules::cross_unit;

/// A constraint on the push: a unit normal and how far along it the ball must move.
type Demand<S> = (Vec3<S>, S);

/// The push for a ball at `c` of radius `r` whose deepest overlap asks for `first`: its normal
/// and depth plus skin. Constraints whose normals are within about 14° of parallel or opposed
/// (a shallow crease, a slot narrower than the ball), or three that nearly share a line, add
/// nothing: the push found so far is kept, and the next round sees what is left.
pub(super) fn push_out<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    c: Vec3<S>,
    (r, skin): (S, S),
    first: Demand<S>,
    rounding: S,
) -> Vec3<S> {
    let alone = first.0.scale(first.1);
    let fails = |x: Vec3<S>, len: S| most_failed(scene, c, (r, skin), (x, len), rounding);
    let Some(second) = fails(alone, first.1) else {
        return alone;
    };
    let Some((joint, len)) = pair(first, second, r + skin) else {
        return alone;
    };
    match fails(joint, len) {
        Some(third) => triple([first, second, third], r + skin).map_or(joint, |(x, _)| x),
        None => joint,
    }
}

/// The shortest push meeting the deepest overlap's demand `first` and moving a skin off the
/// obstacle (unit normal `obstacle`, facing against the push along `first`'s normal) that
/// stopped that push: over a ridge of the floor that a wall pushes the ball against. `None`
/// where the two normals are within about 14° of opposed (a slot no push gets out of).
pub(super) fn around<S: Scalar>(
    first: Demand<S>,
    obstacle: Vec3<S>,
    (r, skin): (S, S),
) -> Option<Vec3<S>> {
    pair(first, (obstacle, skin), r + skin).map(|(x, _)| x)
}

/// The shortest push meeting two demands with the first failed by the push along its normal
/// alone: along the second's normal alone if that meets the first, else meeting both exactly.
fn pair<S: Scalar>((n1, to1): Demand<S>, (n2, to2): Demand<S>, reach: S) -> Option<(Vec3<S>, S)> {
    let cos = S::dot(n1, n2);
    let det = (S::ONE - cos).mul(S::ONE + cos);
    if det < S::div_pow2(S::ONE, 4) {
        return None;
    }
    // In quarters, so that every sum stays within range for a radius up to `LIMIT`.
    let (q1, q2) = (S::div_pow2(to1, 2), S::div_pow2(to2, 2));
    let a = q1 - cos.mul(q2);
    if a <= S::ZERO {
        return Some((n2.scale(to2), to2));
    }
    capped(n1.scale(a) + n2.scale(q2 - cos.mul(q1)), det, reach)
}

/// The push meeting three demands exactly: `Σ toᵢ (nⱼ × nₖ) / det(n₁, n₂, n₃)` (Cramer's rule),
/// if it is the shortest push meeting them: a sum of the three normals with no negative
/// weight (else one of them is met without being pushed on, and the pair is the answer).
fn triple<S: Scalar>(d: [Demand<S>; 3], reach: S) -> Option<(Vec3<S>, S)> {
    let [(n1, to1), (n2, to2), (n3, to3)] = d;
    let (c23, c31, c12) = (cross_unit(n2, n3), cross_unit(n3, n1), cross_unit(n1, n2));
    let det = S::dot(n1, c23);
    if det.abs() < S::div_pow2(S::ONE, 4) {
        return None;
    }
    let q = |to: S| S::div_pow2(to, 2);
    let u = c23.scale(q(to1)) + c31.scale(q(to2)) + c12.scale(q(to3));
    // The push is `4 u / det`; the weight of `nᵢ` in it is `4 u · (nⱼ × nₖ) / det²`.
    if [c23, c31, c12].iter().any(|c| S::dot_sign(u, *c).is_lt()) {
        return None;
    }
    capped(if det < S::ZERO { -u } else { u }, det.abs(), reach)
}

/// `4 quarter / det`, the push whose quarter is `quarter` over a positive determinant, and its
/// length, at most `2 reach`: the division is made only where the quotient is in range.
fn capped<S: Scalar>(quarter: Vec3<S>, det: S, reach: S) -> Option<(Vec3<S>, S)> {
    let (len, dir) = S::direction(quarter)?;
    let half_cap = S::div_pow2(reach, 1);
    let q = if len < half_cap.mul(det) {
        len.div(det)
    } else {
        half_cap
    };
    let length = q + q + q + q;
    Some((dir.map(|u| S::mul_unit(length, u)), length))
}

/// The face that the push `x`, of length `len`, leaves overlapping most: its normal and how
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
        // Over a face only: an edge's or vertex's demand is a bound, and a push that meets it
        // exactly can run far along a slot between two edges the deepest's push would clear;
        // next to an inactive edge, the face's whole plane would stand in for the edge.
        let Some((p, true)) = nearest(t, c, grown, index) else {
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
