//! The README's walking recipe, shared by the tests of stepping up and down: press into the
//! floor, walk along it (stepping up onto ledges), the ground probe where no move touched a
//! floor, and the floor snap where a walk that began on the floor left it.

use super::{P, v};
use ballcast::{Geometry, Scalar, Vec3, slide::Character};

/// A walker's radius, frames a second, step height (up) and snap depth (down).
#[derive(Clone, Copy)]
pub struct Gait {
    pub r: f64,
    pub hz: f64,
    pub step: f64,
    pub snap: f64,
}

/// r = 0.5 at 60 Hz, stepping up half the radius, snapping down as far (Source's
/// `StayOnGround` traces down by the step height).
pub const HALF: Gait = Gait {
    r: 0.5,
    hz: 60.0,
    step: 0.25,
    snap: 0.25,
};

/// The README's recipe with slopes up to 45° walkable and held back by steeper ones, walking
/// at `wish` for `frames` frames from `start`; calls `each(position, grounded)` after every
/// frame.
pub fn walk<S: Scalar, G: Geometry<S>>(
    level: &G,
    start: P,
    wish: P,
    gait: Gait,
    frames: usize,
    each: impl FnMut(Vec3<S>, bool),
) -> Vec3<S> {
    walk_with(level, start, |_, _| wish, gait, frames, each)
}

/// [`walk`] wishing `wish(frame, position)` in each frame: the recipe is
/// [`Character::update`], which the README spells out.
pub fn walk_with<S: Scalar, G: Geometry<S>>(
    level: &G,
    start: P,
    mut wish: impl FnMut(usize, Vec3<S>) -> P,
    gait: Gait,
    frames: usize,
    mut each: impl FnMut(Vec3<S>, bool),
) -> Vec3<S> {
    let (dt, gravity) = (S::from_f64(1.0 / gait.hz), v::<S>([0.0, -9.81, 0.0]));
    let me = Character::new(v::<S>(start), S::from_f64(gait.r)).unwrap();
    let mut me = me.with_step(S::from_f64(gait.step)).unwrap();
    me = me.with_snap(S::from_f64(gait.snap)).unwrap();
    for frame in 0..frames {
        let w = v::<S>(wish(frame, me.position));
        me.update(level, w, gravity, dt).unwrap();
        each(me.position, me.is_grounded());
    }
    me.position
}

/// A frame of a walk: the ball's centre and whether it is grounded.
pub type Frame = (P, bool);

/// [`walk`] with `gait`'s snap and without any (the ground probe alone), frame by frame, cut to
/// where the walk without the snap, having left the floor, stands on one again (the whole walk
/// if it does not land). `None` if the walk without the snap never leaves the floor.
pub fn with_and_without_snap<S: Scalar, G: Geometry<S>>(
    level: &G,
    start: P,
    wish: P,
    gait: Gait,
    frames: usize,
) -> Option<[Vec<Frame>; 2]> {
    let [snapped, plain] = [gait.snap, 0.0].map(|snap| {
        let mut path = Vec::new();
        let gait = Gait { snap, ..gait };
        walk(level, start, wish, gait, frames, |p, on| {
            path.push((super::back(p), on))
        });
        path
    });
    let flew = plain.iter().position(|&(_, on)| !on)?;
    let landed = plain[flew..].iter().position(|&(_, on)| on);
    let n = landed.map_or(frames, |l| flew + l + 1);
    Some([snapped, plain].map(|mut path| {
        path.truncate(n);
        path
    }))
}
