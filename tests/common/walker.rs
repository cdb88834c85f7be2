//! The README's walking recipe, shared by the tests of stepping up and down: press into the
//! floor, walk along it (stepping up onto ledges), the ground probe where no move touched a
//! floor, and the floor snap where a walk that began on the floor left it.

use super::{P, v};
use ballcast::{Geometry, Scalar, Vec3, slide::Slider};

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

/// [`walk`] wishing `wish(frame, position)` in each frame.
pub fn walk_with<S: Scalar, G: Geometry<S>>(
    level: &G,
    start: P,
    mut wish: impl FnMut(usize, Vec3<S>) -> P,
    gait: Gait,
    frames: usize,
    mut each: impl FnMut(Vec3<S>, bool),
) -> Vec3<S> {
    let (dt, g) = (S::from_f64(1.0 / gait.hz), S::from_f64(9.81));
    let (up, walkable) = (v::<S>([0.0, 1.0, 0.0]), S::from_f64(0.5f64.sqrt()));
    let ball = Slider::new(S::from_f64(gait.r)).unwrap();
    let ball = ball.with_max_slope(up, walkable).unwrap();
    let (step, snap) = (S::from_f64(gait.step), S::from_f64(gait.snap));
    let (mut p, mut vel, mut floor) = (v::<S>(start), Vec3::ZERO, None);
    for frame in 0..frames {
        let walked = floor.is_some();
        let out = match floor {
            Some(n) => {
                let press = Vec3::ZERO - n * g.mul(dt).mul(dt);
                let pressed = ball.slide(level, p, press).unwrap();
                vel = v::<S>(wish(frame, p)).reject_from_normalized(n);
                let out = ball
                    .step_slide(level, pressed.position, vel * dt, up, walkable, step)
                    .unwrap();
                floor = out.floor_normal(up, walkable).unwrap();
                floor = floor.or(pressed.floor_normal(up, walkable).unwrap());
                out
            }
            None => {
                vel += v::<S>([0.0, -9.81, 0.0]) * dt;
                let out = ball.slide(level, p, vel * dt).unwrap();
                floor = out.floor_normal(up, walkable).unwrap();
                out
            }
        };
        p = out.position;
        vel = ball.clip(&out, vel).unwrap();
        // The probe reaches two skins down; a walk that began on the floor and left it reaches
        // `snap` further (down a step, over a crest, up or down).
        let depth = if walked { snap } else { S::ZERO };
        if floor.is_none()
            && let Some(f) = ball
                .snap_to_floor(level, p, vel, up, walkable, depth)
                .unwrap()
            && (walked || vel.dot(f.normal) <= S::ZERO)
        {
            (floor, p) = (Some(f.normal), f.position);
        }
        each(p, floor.is_some());
    }
    p
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
