//! A wall that moves into a ball resting on bumpy ground (a door rebuilt every frame): the
//! push out of the wall must not be stopped by a ridge of the ground the ball rests against.
//! Every scalar.

mod common;

use ballcast::{
    Heightfield, HeightfieldShape, Scalar, Scene, Triangle, Vec3, move_and_slide, penetration,
};
use common::{Tolerance, v};
use fixed::types::{I16F16, I32F32};

/// The overlap a ball may keep after a call: its skin, and the scalar's rounding.
fn allowed<S: Tolerance>(r: S) -> f64 {
    ballcast::slide::skin(r, S::from_f64(10.0)).to_f64()
        + 4.0 * S::PRECISION.height_error(10.0)
        + 1e-9
}

/// A two-sided wall, the plane x = `x`, from below the ground to above the ball.
fn wall<S: Scalar>(x: f64) -> Scene<S, 2> {
    let mut s = Scene::new();
    let q = |y: f64, z: f64| v::<S>([x, y, z]);
    let (a, b, c, d) = (q(-2.0, -8.0), q(-2.0, -4.0), q(3.0, -4.0), q(3.0, -8.0));
    s.push_two_sided(Triangle::new(a, b, c)).unwrap();
    s.push_two_sided(Triangle::new(a, c, d)).unwrap();
    s
}

/// The eight triangles of a terrain around the vertex (-1, 0.27, -6), one-sided, fronts up,
/// with a ball resting on them by the vertex and a wall 0.03 to 0.2 into it from -x: the push
/// along the wall's normal runs into a ridge edge of the ground after 0.01 and was stopped
/// there, so the ball stayed in the wall (found by a game's sliding door, in `f32`). One call
/// with no motion now clears it.
fn a_wall_pushes_the_ball_over_a_ridge_of_the_floor<S: Tolerance>() {
    let tris = [
        [
            [-2.0, 0.3125, -7.0],
            [-2.0, 0.25, -6.0],
            [-1.0, 0.265625, -6.0],
        ],
        [
            [-2.0, 0.3125, -7.0],
            [-1.0, 0.265625, -6.0],
            [-1.0, 0.265625, -7.0],
        ],
        [
            [-1.0, 0.265625, -7.0],
            [-1.0, 0.265625, -6.0],
            [0.0, 0.28125, -6.0],
        ],
        [
            [-1.0, 0.265625, -7.0],
            [0.0, 0.28125, -6.0],
            [0.0, 0.234375, -7.0],
        ],
        [
            [-2.0, 0.25, -6.0],
            [-2.0, 0.21875, -5.0],
            [-1.0, 0.28125, -5.0],
        ],
        [
            [-2.0, 0.25, -6.0],
            [-1.0, 0.28125, -5.0],
            [-1.0, 0.265625, -6.0],
        ],
        [
            [-1.0, 0.265625, -6.0],
            [-1.0, 0.28125, -5.0],
            [0.0, 0.34375, -5.0],
        ],
        [
            [-1.0, 0.265625, -6.0],
            [0.0, 0.34375, -5.0],
            [0.0, 0.28125, -6.0],
        ],
    ];
    let (r, c) = (S::from_f64(0.5), v::<S>([-0.999578, 0.766914, -5.996462]));
    for x in [-1.47, -1.45, -1.4, -1.3] {
        let mut scene: Scene<S, 10> = Scene::new();
        for t in tris {
            scene
                .push(Triangle::new(v(t[0]), v(t[1]), v(t[2])))
                .unwrap();
        }
        for t in wall::<S>(x).sources() {
            scene.push_two_sided(t).unwrap();
        }
        let before = penetration(&scene, c, r)
            .unwrap()
            .map_or(0.0, |p| p.depth.to_f64());
        assert!(
            before > 0.02,
            "{} wall at {x}: starts {before} deep",
            S::NAME
        );
        let out = move_and_slide(&scene, c, Vec3::ZERO, r).unwrap();
        let left = penetration(&scene, out.position, r).unwrap();
        let left = left.map_or(0.0, |p| p.depth.to_f64());
        assert!(
            left <= allowed(r),
            "{} wall at {x}: left {left} deep",
            S::NAME
        );
        // Out of the wall, over the ridge: not lifted off the ground by more than a little.
        let lift = out.pushed_out.y.to_f64();
        assert!(
            (0.0..0.01).contains(&lift),
            "{} wall at {x}: lifted {lift}",
            S::NAME
        );
    }
}

/// A door sliding at 1 unit/s across a bumpy terrain (a heightfield) pushes a ball resting on
/// it for two seconds at 60 Hz: after every frame (gravity's step, the door moved first) the
/// ball overlaps nothing by more than its skin, and it keeps up with the door.
fn a_sliding_door_pushes_a_ball_across_bumpy_ground<S: Tolerance>() {
    let (columns, rows) = (16u32, 16u32);
    let heights: Vec<i16> = (0..(columns + 1) * (rows + 1))
        .map(|n| {
            let (i, k) = ((n % (columns + 1)) as i32, (n / (columns + 1)) as i32);
            (((i * 7 + k * 3) % 5) * 3 - 6 + (i * k) % 4) as i16
        })
        .collect();
    let mut cells = vec![0u8; (columns * rows) as usize];
    let (one, unit) = (S::ONE, S::from_f64(1.0 / 64.0));
    let ground = Heightfield::build(
        HeightfieldShape {
            origin: v([-8.0, 0.0, -8.0]),
            spacing: one,
            unit,
            columns,
            rows,
        },
        &heights,
        |_, _| false,
        &mut cells,
    )
    .unwrap();
    let r = S::from_f64(0.5);
    let (dt, g) = (1.0 / 60.0, 9.81);
    // Dropped onto the ground first.
    let mut c = v::<S>([-3.0, 1.5, -6.0]);
    for _ in 0..60 {
        c = move_and_slide(&ground, c, v([0.0, -g * dt * 0.5, 0.0]), r)
            .unwrap()
            .position;
    }
    let mut worst = 0.0f64;
    for frame in 0..120 {
        let x = -4.0 + f64::from(frame) / 60.0;
        let door = wall::<S>(x);
        let level = ballcast::Compound::new(&ground, &door).unwrap();
        c = move_and_slide(&level, c, v([0.0, -g * dt * dt, 0.0]), r)
            .unwrap()
            .position;
        let left = penetration(&level, c, r)
            .unwrap()
            .map_or(0.0, |p| p.depth.to_f64());
        worst = worst.max(left);
        assert!(left <= allowed(r), "{} frame {frame}: {left} deep", S::NAME);
        // Never behind the door: its centre at least a radius less its skin ahead of it.
        assert!(
            c.x.to_f64() >= x + 0.5 - allowed(r),
            "{} frame {frame}: at {:?}",
            S::NAME,
            c
        );
    }
    // The door went 2 units: the ball with it, from 1 unit ahead of its start.
    assert!(
        c.x.to_f64() > -1.6,
        "{}: ended at {:?} (worst overlap {worst})",
        S::NAME,
        c
    );
}

macro_rules! per_scalar {
    ($($m:ident: $t:ty),*) => {$(mod $m {
        #[allow(unused_imports)]
        use super::*;
        #[test]
        fn a_wall_pushes_the_ball_over_a_ridge_of_the_floor() {
            super::a_wall_pushes_the_ball_over_a_ridge_of_the_floor::<$t>();
        }
        #[test]
        fn a_sliding_door_pushes_a_ball_across_bumpy_ground() {
            super::a_sliding_door_pushes_a_ball_across_bumpy_ground::<$t>();
        }
    })*};
}

per_scalar!(f64_: f64, f32_: f32, i32f32: I32F32, i16f16: I16F16);
