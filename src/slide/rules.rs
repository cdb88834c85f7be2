//! The response's rules: how far to stop short of a contact, and how what is left of the motion
//! is constrained by the planes touched.

use crate::merge::{PLANES, same_plane};
use crate::{Scalar, SceneHit, Vec3, contact::unit};
use heapless::Vec;

/// The distinct planes a call has touched. Eight is more than a ball ever needs (three stop it);
/// a call that touches more stops where it is (see [`add_planes`]).
pub(super) type Planes<S> = Vec<Vec3<S>, { 2 * PLANES }>;

/// Where a ground probe's slide ends: at the first floor it meets (a contact within the slope
/// limit, or one of whose planes meets a plane touched so far in a crease that holds the ball,
/// as [`Slide::floor`](super::Slide::floor) has it), not carried on down that floor's slope
/// by what is left of the probe's reach. An edge or vertex counts as a face does, also one the
/// ball is walking off: rolling over a stair's edge, a ball snapped back onto the edge every
/// frame was carried on around it by the rest of the reach, two skins a frame, faster than it
/// walked (at 960 Hz, `f64` down stairs at 1.02 times the wished pace, `I16F16` 1.09).
#[derive(Clone, Copy)]
pub(super) struct FloorStop<S> {
    /// `up` as a unit vector.
    pub up: Vec3<S>,
    /// The cosine of the steepest walkable slope.
    pub min_cos: S,
}

impl<S: Scalar> FloorStop<S> {
    /// Whether the probe stops at `hit`, given the planes its contacts touched before it
    /// (`touched`, to which the hit's are added). A probe in a V of steep slopes whose trough
    /// is walkable slid on down the trough by the rest of its reach: in `I16F16` at 240 Hz a
    /// ball walking up a ditch was snapped back down it by more than its walk every frame.
    pub(super) fn stops_at(&self, hit: &SceneHit<S>, touched: &mut Planes<S>) -> bool {
        let mine = || hit.planes.iter().flatten();
        for n in mine() {
            if !touched.iter().any(|p| same_plane(*p, *n)) {
                // A probe touches a handful of planes: one found no room is only not checked.
                let _ = touched.push(*n);
            }
        }
        let floor = S::dot(hit.normal, self.up) >= self.min_cos;
        let crease = || {
            let held = |a: &Vec3<S>| {
                let hold = |b: &Vec3<S>| holds(*a, *b, self.up, self.min_cos).is_some();
                touched.iter().any(hold)
            };
            mine().any(held)
        };
        floor || crease()
    }

    /// The probe's motion after a contact that did not stop it, `rest` (what was `left` of it,
    /// constrained by the planes touched), lengthened so that it still goes as far down as
    /// `left` did: a probe that meets a face or edge too steep to stand on follows it down by
    /// the whole of its reach. Cut to the constrained slope, it went down by only `1 - cos²`
    /// of what was left: past a step's rounded top edge, steeper than the slope limit once the
    /// ball is `r sin θ` past it, a snap of 0.25 stopped 0.2 down and missed the ground of a
    /// step down of 0.24, and the ball flew off the step (all scalars, depending on where in
    /// its frame it crossed the edge). Lengthened by at most twice (a slope at the limit
    /// halves the drop): a crease that runs nearly level is followed as constrained.
    pub(super) fn keeps_depth(&self, rest: Vec3<S>, left: Vec3<S>) -> Vec3<S> {
        let (want, got) = (-S::dot(left, self.up), -S::dot(rest, self.up));
        if got > S::ZERO && want > got && got + got >= want {
            rest.scale(S::div(want, got))
        } else {
            rest
        }
    }
}

/// Where to stop short of a contact met along `rest`, as a fraction of it, and a lift to add.
/// A ball that travelled stops a skin short, measured along the normal, by backing off along
/// its own path (never behind its start), so stopping adds no sideways motion and a ball pushed
/// into a corner settles at a skin from both walls instead of being levered from one to the
/// other. What is left of the travel after backing off, if no more than `rounding` (the
/// rounding of a position), is rounding too: a resting ball does not move at all, so float
/// positions do not walk by an ulp a call. One whose motion runs along the plane as rounded
/// goes on to the contact (unless that travel is rounding too) and is lifted there by its
/// motion's approach: at least `rounding` for floats; for fixed point, at least a step per
/// unit of the motion left (its largest coordinate). Any other that started within a skin of
/// the plane stays where it is (a float ball within a position's rounding of the plane and
/// moving along it within 30° is lifted back to a skin off it). One met at once (already
/// touching or overlapping) is lifted by a skin instead.
pub(super) fn stand_off<S: Scalar>(
    hit: &SceneHit<S>,
    rest: Vec3<S>,
    skin: S,
    rounding: S,
) -> (S, Vec3<S>) {
    let into = S::dot(rest, hit.normal);
    let zero = Vec3::ZERO;
    if hit.alpha > S::ZERO && into < S::ZERO {
        // Along the plane as rounded (it comes closer by no more than the rounding of a height,
        // as `constrain` leaves a slide) yet met: the plane as this contact's frame rounds it
        // lies that much higher than the one slid along (a coplanar neighbour entered at its
        // seam, whose frame rounds the height a few steps apart at hundreds), or the ball
        // started that close (in fixed point at a few hundred hertz, a resting ball pressed by
        // gravity a few steps a frame). It goes on to the contact, with the travel up to it,
        // and is lifted there by its approach, which clears the plane for the rest, and by at
        // least what rounding takes off that: for floats a height's rounding at the ball's
        // coordinates, where the frames round heights; for fixed point, whose heights round at
        // a constant step that an approach adds exactly, a step per unit of the motion left
        // (it slides along the normal rounded to `S`, off the frame's by under a step per unit
        // of length). Put back where it started, it met the same seam on every retry and ended
        // the call short; lifted less, it met the face again a little farther on, and again.
        // Travel to the contact of no more than a position's rounding is rounding too: carried
        // a step sideways every frame, a resting ball crept.
        if into >= -along(rest) {
            let m = magnitude(rest);
            let least = if S::PRECISION.relative {
                rounding
            } else {
                m.mul(S::ONE - hit.alpha).mul(S::EPSILON)
            };
            let lift = if -into > least { -into } else { least };
            let settled = m.mul(hit.alpha) <= rounding;
            return (
                if settled { S::ZERO } else { hit.alpha },
                hit.normal.scale(lift),
            );
        }
        let back = S::div(skin, -into);
        if back >= hit.alpha {
            // Started within a skin: it cannot back off along its path, so it stays. A float
            // ball within a position's rounding of the plane, moving mostly along it, is lifted
            // back to a skin off it: each end of a slide along the plane rounds to coordinates
            // that may lie a little closer every time, until the plane meets the ball at once.
            let gap = (-into).mul(hit.alpha);
            let grazing = || -into <= S::div_pow2(rest.length(), 1);
            let lift = if S::PRECISION.relative && gap <= rounding && grazing() {
                skin - gap
            } else {
                S::ZERO
            };
            return (S::ZERO, hit.normal.scale(lift));
        }
        let alpha = hit.alpha - back;
        let settled = magnitude(rest).mul(alpha) <= rounding;
        return (if settled { S::ZERO } else { alpha }, zero);
    }
    (hit.alpha, hit.normal.scale(skin))
}

/// How far a motion `v`, constrained by planes, may still run into one of them as rounded and
/// count as running along it: the rounding of a height at its magnitude, which for floats is
/// relative and covers a unit normal's rounding times the push taken off too. In fixed point
/// the height's rounding is a constant few steps, so the normal's (a tie of the motion's
/// magnitude) is added: without it a fast landing on a slope (above about 10 units a second in
/// `I16F16`) had its slide refused and stopped dead. Floats get no more: twice their allowance
/// let a crease candidate of rounding size run into a third plane, and a ball pushed hard into
/// a corner crept (`corner_pushed_hard_stays_put`).
pub(super) fn along<S: Scalar>(v: Vec3<S>) -> S {
    let m = magnitude(v);
    let normal = if S::PRECISION.relative {
        S::ZERO
    } else {
        S::mul(m, crate::scalar::tie::<S>())
    };
    S::height_error(m) + normal
}

/// The largest coordinate magnitude of a point.
pub(super) fn magnitude<S: Scalar>(p: Vec3<S>) -> S {
    p.abs().max_element()
}

/// Adds a contact's planes to those already touched, each distinct plane once, and, with a
/// slope limit `(up, min_cos)` (`up` a unit vector), the wall each too-steep plane also stands
/// for on the `floor` a walk keeps to, or upright without one ([`steep_wall`]); false if one
/// found no room, in which case the caller must not move on (it cannot respect that plane).
pub(super) fn add_planes<S: Scalar>(
    planes: &mut Planes<S>,
    hit: &SceneHit<S>,
    limit: Option<(Vec3<S>, S)>,
    floor: impl Fn(Vec3<S>) -> Option<Vec3<S>>,
) -> bool {
    let normals = || hit.planes.iter().flatten().copied();
    let floor = &floor;
    let walls = limit
        .into_iter()
        .flat_map(|limit| normals().filter_map(move |n| steep_wall(n, limit, floor(n))));
    normals()
        .chain(walls)
        .all(|n| planes.iter().any(|p| same_plane(*p, n)) || planes.push(n).is_ok())
}

/// A walk along the floor a ball stands on (`floor`, a unit normal), as
/// [`Slider::step_slide`](super::Slider::step_slide) sees it: `up` a unit vector, and the
/// rule by which a contact may still be stepped over (see [`steps_over`](Self::steps_over)).
#[derive(Clone, Copy, Debug)]
pub(super) struct Walk<S> {
    pub floor: Vec3<S>,
    pub up: Vec3<S>,
    /// The cosine of the steepest slope a ball stands on.
    pub stands: S,
    /// The cosine of the steepest slope the walk climbs by itself.
    pub climbs: S,
    /// The step's height and two skins.
    pub reach: S,
}

impl<S: Scalar> Walk<S> {
    /// Whether a contact of unit normal `n` is touched low enough for a ball of radius `r` to
    /// step over it: `r (climbs - n·up)` above what the walk climbs by itself, within `reach`.
    pub(super) fn steps_over(&self, n: Vec3<S>, r: S) -> bool {
        r.mul(self.climbs - S::dot(n, self.up)) <= self.reach
    }
}

/// For a walk that ran into something it can neither stand on nor step over (a wall): the
/// floor's reverse as a plane too, so that what is left of the walk stays in the floor's plane,
/// along its crease with the wall, and neither climbs the wall by the walk's own rise (a frame
/// up, pressed back the next: a jitter) nor runs along it where the floor tilts (a creep). A
/// walkable contact becomes the floor the walk keeps to (the old floor's reverse is dropped:
/// the walk goes on up the new floor, out of a valley, onto a ramp); a low one the step's rule
/// decides about adds nothing. False if the plane found no room, as for [`add_planes`].
pub(super) fn keep_to_floor<S: Scalar>(
    planes: &mut Planes<S>,
    walk: &mut Option<Walk<S>>,
    hit: &SceneHit<S>,
    r: S,
) -> bool {
    let Some(walk) = walk else {
        return true;
    };
    let under = Vec3::ZERO - walk.floor;
    let normals = || hit.planes.iter().flatten();
    if let Some(&floor) = normals().find(|n| S::dot(**n, walk.up) >= walk.stands) {
        planes.retain(|p| !same_plane(*p, under));
        walk.floor = floor;
        return true;
    }
    let wall = |n: &&Vec3<S>| !walk.steps_over(**n, r);
    normals().find(wall).is_none()
        || planes.iter().any(|p| same_plane(*p, under))
        || planes.push(under).is_ok()
}

/// The wall behind a slope too steep to stand on: for a unit normal `n` that points up
/// (`n · up > 0`) but less than `min_cos`, a plane such that a motion kept out of both cannot
/// be carried up the slope by running into it, while a fall onto the slope, which does not run
/// into the wall, still slides down it (Jolt's `CharacterVirtual` adds the same second
/// constraint beyond its maximum slope angle). Without a floor the wall stands upright: its
/// normal is `n`'s level part. Given the unit normal of the floor a walk keeps to, it stands
/// square on that floor, through the slope's foot: its normal is `n`'s part across `floor`, so
/// what it leaves of a walk along the floor stays in the floor's plane. Upright, it left a walk
/// into a face leaning back on ground rising towards it the walk's rise, which climbed the face
/// by that much every frame, pressed back down the next (a bob); and along a V-shaped ditch of
/// steep sides, whose rising trough holds the ball as a floor, the sides' upright walls leant
/// back across the rise and held the walk back. A slope within 1/32 rad of the floor's plane
/// gives its part across the floor no reliable direction: its wall is upright.
pub(super) fn steep_wall<S: Scalar>(
    n: Vec3<S>,
    (up, min_cos): (Vec3<S>, S),
    floor: Option<Vec3<S>>,
) -> Option<Vec3<S>> {
    let d = S::dot(n, up);
    if !(d > S::ZERO && d < min_cos) {
        return None;
    }
    let across = floor
        .map(|f| n - f.scale(S::dot(n, f)))
        .filter(|a| magnitude(*a) > S::div_pow2(S::ONE, 5));
    across.and_then(unit).or_else(|| unit(n - up.scale(d)))
}

/// `v` constrained by every plane (unit normals): unchanged if it moves into none; else the
/// longest of: `v` without its part into one plane, along the crease of two, that moves into
/// no other plane (beyond rounding), runs along `primal` (the sign of their product taken
/// exactly) and is larger than the rounding of the normals times `v` (in fixed point, plus
/// two steps; for a crease, four times that over the sine of the angle between its planes);
/// else zero. The longest is the motion closest to `v` that runs into none of the planes
/// (with one or two of them in the way), whatever order they were touched in. A
/// candidate that runs against `primal` is passed over: in a corner wider than a right angle,
/// sliding along one wall leads back out of the corner, while the crease of the two walls leads
/// down to the floor. A crease is also passed over where its direction runs into a third plane
/// beyond the normals' rounding: however short the slide (its product with that plane below
/// the rounding of a height, eight steps in fixed point), it would climb a step into it every
/// call (`I16F16`: a ball pushing into a wall that leans back, on ground tilted along it,
/// crept up their crease, which the wall's steep-slope plane forbids).
pub(super) fn constrain<S: Scalar>(v: Vec3<S>, planes: &[Vec3<S>], primal: Vec3<S>) -> Vec3<S> {
    let zero = Vec3::ZERO;
    let slack = -along(v);
    let clear = |w: Vec3<S>| planes.iter().all(|n| S::dot(w, *n) >= slack);
    // What is left after removing a large push into a plane carries the normal's rounding
    // times the push (four steps of resolution of it at most), and in fixed point also the
    // products' own rounding, a step at most whatever the push: the same each call, so it
    // would add up to a drift. Less than that is not motion.
    let steps = if S::PRECISION.relative {
        S::ZERO
    } else {
        S::EPSILON + S::EPSILON
    };
    let noise = S::mul(magnitude(v), crate::scalar::tie::<S>()) + steps;
    // The sign exactly: a slow slide (in `I16F16`, below about 2^-8.5 a component) has a
    // product with the motion below half a step, which would round to zero.
    let keep = |w: &Vec3<S>| clear(*w) && magnitude(*w) > noise && S::dot_sign(*w, primal).is_gt();
    if clear(v) {
        return v;
    }
    // The rounding of a product of unit normals, from those of the frames they come from: the
    // tie window's four steps, twice.
    let tie = crate::scalar::tie::<S>();
    let skew = S::ZERO - (tie + tie);
    // In fixed point, whose allowance above holds a height's rounding of eight steps however
    // short the motion, a slide that runs into another plane beyond the rounding of the
    // normals times the motion and of a product is none: within the allowance, an `I16F16`
    // walk slid up a steep face into the wall square on the floor beside it by a few steps
    // every frame, pressed back down the next (a jitter). Floats' allowance is relative.
    let bound = skew.mul(magnitude(v)) - steps;
    let fixed = !S::PRECISION.relative;
    let slides = planes.iter().map(move |n| {
        let into = S::dot(v, *n);
        let w = if into < S::ZERO { v - n.scale(into) } else { v };
        let dips = fixed && planes.iter().any(|p| p != n && S::dot(w, *p) < bound);
        (if dips { zero } else { w }, None)
    });
    let creases = planes.iter().enumerate().flat_map(|(i, a)| {
        // The planes after `a` (`get`: no indexing, so no panic path for the link check).
        let later = planes.get(i + 1..).unwrap_or_default();
        let lines = later
            .iter()
            .filter_map(|b| Some((S::direction(cross_unit(*a, *b))?, *b)));
        lines.map(move |((sin, c), b)| {
            let c = c.map(S::unit_to_scalar);
            let run = S::dot(v, c);
            let w = c.scale(run);
            // The crease's direction is uncertain by the normals' rounding, that of the frames
            // they come from included (in floats a few ulps of one each, eight seen), over the
            // sine of their angle: a slide along it within four times the noise is noise, and
            // taken call after call it would creep (an ulp a call into a 120° corner, `f64`).
            let twice = noise + noise;
            if S::mul(magnitude(w), sin) > twice + twice {
                // Its heading, to check against the other planes (times the sine: that
                // uncertainty, without a division).
                let heading = if run < S::ZERO { Vec3::ZERO - c } else { c };
                (w, Some((heading.scale(sin), [*a, b])))
            } else {
                (zero, None)
            }
        })
    });
    // Whether a crease heading (times the sine of its planes' angle) runs into a plane other
    // than its own two beyond the rounding of both.
    let heads_in = |(h, own): (Vec3<S>, [Vec3<S>; 2])| {
        planes
            .iter()
            .any(|n| !own.contains(n) && S::dot(h, *n) < skew)
    };
    // Of those kept, the one that removes least: each is a projection of `v`, so `v · w` is
    // `|w|²`, and the largest is the closest motion to `v` that runs into no plane. Only one
    // longer than the best so far is checked against the planes (the first on a tie).
    let mut best: Option<(S, Vec3<S>)> = None;
    for (w, heading) in slides.chain(creases) {
        let d = S::dot(v, w);
        if best.is_none_or(|(b, _)| d > b) && keep(&w) && !heading.is_some_and(heads_in) {
            best = Some((d, w));
        }
    }
    best.map_or(zero, |(_, w)| w)
}

/// The cross product of two unit vectors, each component rounded once.
pub(super) fn cross_unit<S: Scalar>(a: Vec3<S>, b: Vec3<S>) -> Vec3<S> {
    let z = S::ZERO;
    let d = |p: S, q: S, r: S, s: S| S::dot(Vec3::new(p, -q, z), Vec3::new(r, s, z));
    Vec3::new(
        d(a.y, a.z, b.z, b.y),
        d(a.z, a.x, b.x, b.z),
        d(a.x, a.y, b.y, b.x),
    )
}

/// The support of the crease of the planes with unit normals `a` and `b`, if it holds a ball up
/// and is walkable: `up`'s projection onto their span, `p = α a + β b`, has `α, β >= 0` (the
/// normals lie either side of `up`) and `|p| >= min_cos` (`|p|` is the cosine of the steepest
/// line between the normals). Solved over the Gram determinant `1 - (a · b)²` without dividing;
/// the support returned is `p` as a unit vector, the crease's own "floor normal". Weights within
/// eight steps of zero hold nothing: up runs along the crease (two walls), or the normals are
/// parallel.
pub(super) fn holds<S: Scalar>(a: Vec3<S>, b: Vec3<S>, up: Vec3<S>, min_cos: S) -> Option<Vec3<S>> {
    let k = S::dot(a, b);
    let det = (S::ONE - k).mul(S::ONE + k);
    let (au, bu) = (S::dot(a, up), S::dot(b, up));
    let (alpha, beta) = (au - k.mul(bu), bu - k.mul(au));
    // `|p|² det = au α + bu β`.
    let reach = au.mul(alpha) + bu.mul(beta);
    // Each weight carries the rounding of the unit normals and of three products, a few
    // steps: weights within that of zero (up along the crease, or nearly so) hold nothing.
    let steps = crate::scalar::tie::<S>();
    let held = alpha >= steps + steps
        && beta >= steps + steps
        && (min_cos <= S::ZERO || reach >= min_cos.mul(min_cos).mul(det));
    // `p det = α a + β b`, of the same direction.
    held.then(|| unit(a.scale(alpha) + b.scale(beta))).flatten()
}
