//! The peer in every comparison: parry3d's ball shape cast (`cast_shapes`), on the same paths
//! as ballcast, shared by the benches.

use super::inputs::{P, Path};
use parry3d::math::{Pose, Vector};
use parry3d::query::{ShapeCastOptions, cast_shapes};
use parry3d::shape::{Ball, Shape};
use std::hint::black_box;

/// A point as parry's `f32` vector.
pub fn point(a: P) -> Vector {
    Vector::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

/// Paths as parry takes them: start, motion, ball.
pub fn sweeps(raw: &[Path]) -> Vec<(Vector, Vector, Ball)> {
    raw.iter()
        .map(|&(a, b, r)| (point(a), point(b) - point(a), Ball::new(r as f32)))
        .collect()
}

/// How many of the sweeps hit `shape` (at rest at the origin) within their motion.
pub fn hits(shape: &dyn Shape, sweeps: &[(Vector, Vector, Ball)]) -> usize {
    let opts = ShapeCastOptions {
        max_time_of_impact: 1.0,
        target_distance: 0.0,
        stop_at_penetration: false,
        compute_impact_geometry_on_penetration: false,
    };
    sweeps
        .iter()
        .filter(|(p0, d, ball)| {
            let from = Pose::translation(p0.x, p0.y, p0.z);
            let shape = black_box(shape);
            let hit = cast_shapes(&from, *d, ball, &Pose::IDENTITY, Vector::ZERO, shape, opts);
            matches!(hit, Ok(Some(_)))
        })
        .count()
}
