//! The scenes and runs of `tests/response.rs` (issue 11): floors, boxes, corners of two walls
//! or of two walls and a floor, wedges and stairs, built in local coordinates, turned by a rigid
//! motion and rounded to the scalar; each run checks every call with a [`Monitor`].
#![allow(dead_code)]

use crate::common::{P, Rng, Tolerance, add, back, cross, dot, norm, scale, sub, v};
use crate::support::{Monitor, Rigid, Tri, World, quad, unit};

/// A generator from a seed (xorshift needs a nonzero state).
pub fn rng(seed: u64) -> Rng {
    Rng((seed ^ 0x9E37_79B9_7F4A_7C15).max(1))
}

/// A radius for a size kind (0 ordinary, 1 tiny, 2 huge) and how far the scene is shifted.
pub fn sizes(kind: u8, rng: &mut Rng) -> (f64, f64) {
    match kind % 3 {
        0 => (rng.range(0.1, 1.0), 20.0),
        1 => (rng.range(0.002, 0.01), 20.0),
        _ => (rng.range(20.0, 60.0), 1500.0),
    }
}

/// The part of `d` perpendicular to the unit vector `n`.
pub fn across(d: P, n: P) -> P {
    sub(d, scale(n, dot(d, n)))
}

/// A random unit vector with every component at least 0.3 in magnitude before normalising.
fn oblique(rng: &mut Rng) -> P {
    unit([0; 3].map(|_| {
        let m = rng.range(0.3, 1.0);
        if rng.next() < 0.5 { -m } else { m }
    }))
}

/// Pushes a ball from `start` by the same (local) displacement every step; `each` sees the
/// step's index and the new centre.
pub fn push_run<S: Tolerance>(
    w: &World<S>,
    m: &mut Monitor,
    start: P,
    push: P,
    steps: usize,
    mut each: impl FnMut(&mut Monitor, usize, P),
) {
    let (d, r) = (v::<S>(w.m.dir(push)), S::from_f64(m.r));
    let mut p = v::<S>(start);
    for k in 0..steps {
        match w.step(p, d, r) {
            Ok(out) => {
                m.call(w, back(p), back(out.position), back(d));
                p = out.position;
                each(m, k, back(p));
            }
            Err(e) => return m.refused(e),
        }
    }
}

/// Rolls a ball: gravity added to its velocity each step, the velocity clipped by the
/// response (`Slide::clip`) and bounced with restitution `e`, a kick every 97 steps. `behind`
/// says how far a centre lies behind the surfaces that enclose it.
#[allow(clippy::too_many_arguments)]
pub fn roll<S: Tolerance>(
    w: &World<S>,
    m: &mut Monitor,
    start: P,
    gravity: P,
    kick: f64,
    e: f64,
    steps: usize,
    rng: &mut Rng,
    behind: impl Fn(P) -> f64,
) {
    let r = S::from_f64(m.r);
    let (mut p, mut vel) = (v::<S>(start), [0.0; 3]);
    let gravity = w.m.dir(gravity);
    for k in 0..steps {
        vel = add(vel, gravity);
        if k % 97 == 0 {
            vel = add(vel, scale(unit(rng.point(1.0)), kick));
        }
        if norm(vel) > 2.0 * m.r {
            vel = scale(vel, 2.0 * m.r / norm(vel));
        }
        let d = v::<S>(vel);
        match w.step(p, d, r) {
            Ok(out) => {
                m.call(w, back(p), back(out.position), back(d));
                p = out.position;
                m.behind(behind(back(p)));
                let c = back(out.clip(d).unwrap());
                vel = add(c, scale(sub(c, back(d)), e));
            }
            Err(err) => return m.refused(err),
        }
    }
}

/// The six inward faces of the box `[-h, h]³`.
pub fn box_tris(h: f64) -> Vec<Tri> {
    let w = 2.0 * h;
    let o = [-h; 3];
    let (x, y, z) = ([w, 0.0, 0.0], [0.0, w, 0.0], [0.0, 0.0, w]);
    [
        quad(o, z, x),
        quad(add(o, y), x, z),
        quad(o, x, y),
        quad(add(o, z), y, x),
        quad(o, y, z),
        quad(add(o, x), z, y),
    ]
    .concat()
}

/// A closed triangular prism, inward faces: a V of two slopes meeting at the origin at angle
/// `alpha` (radians), `h` high, a lid, two end caps at `z = ±l`.
pub fn wedge_tris(alpha: f64, h: f64, l: f64) -> Vec<Tri> {
    let w = h * (alpha / 2.0).tan();
    let (a0, b0, c0) = ([-w, h, -l], [w, h, -l], [0.0, 0.0, -l]);
    let (a1, b1, c1) = ([-w, h, l], [w, h, l], [0.0, 0.0, l]);
    let along = [0.0, 0.0, 2.0 * l];
    [
        quad(c0, sub(a0, c0), along).to_vec(),
        quad(c0, along, sub(b0, c0)).to_vec(),
        quad(a0, [2.0 * w, 0.0, 0.0], along).to_vec(),
        vec![[c0, b0, a0], [c1, a1, b1]],
    ]
    .concat()
}

/// Two vertical walls meeting along the y axis at angle `theta` (radians): the first along +x
/// facing +z, the second along `(cos θ, 0, sin θ)` facing into the wedge; `len` long, from
/// `y0` to `y0 + tall`. With `floor`, a floor at y = 0 under the whole corner.
pub fn corner_tris(theta: f64, len: f64, y0: f64, tall: f64, floor: bool) -> Vec<Tri> {
    let o = [0.0, y0, 0.0];
    let u2 = [theta.cos(), 0.0, theta.sin()];
    let up = [0.0, tall, 0.0];
    let mut t = [quad(o, [len, 0.0, 0.0], up), quad(o, up, scale(u2, len))].concat();
    if floor {
        let f = [-len, 0.0, -len];
        t.extend(quad(f, [0.0, 0.0, 2.0 * len], [2.0 * len, 0.0, 0.0]));
    }
    t
}

/// Stairs rising along +x: `k` treads `w` deep and risers `rise` high, `2 half` wide, closed by
/// a wall at each end.
pub fn stairs_tris(k: usize, w: f64, rise: f64, half: f64, tall: f64) -> Vec<Tri> {
    let (across, up) = ([0.0, 0.0, 2.0 * half], [0.0, tall, 0.0]);
    let mut t = Vec::new();
    t.extend(quad([0.0, 0.0, -half], up, across));
    for i in 0..k {
        let (x, y) = (i as f64 * w, i as f64 * rise);
        t.extend(quad([x, y, -half], across, [w, 0.0, 0.0]));
        if i + 1 < k {
            t.extend(quad([x + w, y, -half], across, [0.0, rise, 0.0]));
        }
    }
    let top = (k - 1) as f64 * rise;
    t.extend(quad([k as f64 * w, top, -half], across, up));
    t
}

/// A ball resting on a turned floor of 2 × 2 tiles, pushed straight into it every step: never
/// deeper, never back, lateral drift within the push's own tangential part (as the scalar holds
/// the push) per step.
pub fn floor_rest<S: Tolerance>(seed: u64, kind: u8, steps: usize) -> Monitor {
    let mut g = rng(seed);
    let (r, shift) = sizes(kind, &mut g);
    let f = 4.0 * r;
    let mut tris = Vec::new();
    for (i, j) in [(-1.0, -1.0), (-1.0, 0.0), (0.0, -1.0), (0.0, 0.0)] {
        tris.extend(quad([i * f, 0.0, j * f], [0.0, 0.0, f], [f, 0.0, 0.0]));
    }
    let w = World::<S>::new(&tris, Rigid::random(&mut g, shift));
    let gap = g.range(0.0, 2.0) * r / 1024.0;
    let local = [g.range(-f, f) / 2.0, r + gap, g.range(-f, f) / 2.0];
    let start = back(v::<S>(w.m.point(local)));
    let push = [0.0, -r * g.range(0.05, 0.5), 0.0];
    let n = w.normals[0];
    let tangential = norm(across(back(v::<S>(w.m.dir(push))), n));
    let mut m = Monitor::new(format!("floor seed {seed} kind {kind}"), &w, start, r);
    push_run(&w, &mut m, start, push, steps, |m, k, p| {
        m.drift(norm(across(sub(p, start), n)), tangential * (k + 1) as f64)
    });
    m
}

/// A ball in a closed box pushed obliquely (into three walls): it slides into a corner of the
/// box and must then stay there.
pub fn box_push<S: Tolerance>(seed: u64, kind: u8, steps: usize) -> Monitor {
    let mut g = rng(seed);
    let (r, shift) = sizes(kind, &mut g);
    let h = r * g.range(1.5, 4.0);
    let w = World::<S>::new(&box_tris(h), Rigid::random(&mut g, shift));
    let room = h - r - r / 256.0;
    let start = back(v::<S>(w.m.point(g.point(room))));
    let push = scale(oblique(&mut g), r * g.range(0.1, 0.5));
    let mut m = Monitor::new(format!("box push seed {seed} kind {kind}"), &w, start, r);
    let mut rest = start;
    push_run(&w, &mut m, start, push, steps, |m, k, p| {
        m.behind(w.behind_convex(p));
        if k == steps / 2 {
            rest = p;
        } else if k > steps / 2 {
            m.motion(norm(sub(p, rest)));
        }
    });
    m
}

/// One corner run's shape.
#[derive(Clone, Copy, Debug)]
pub struct Corner {
    /// Angle between the walls, degrees.
    pub degrees: f64,
    pub r: f64,
    /// Push length, in radii.
    pub push: f64,
    /// How uneven the push is: its angle from the bisector, as a fraction of the half-width of
    /// the walls' normal cone, `(180° - degrees) / 2`.
    pub uneven: f64,
    /// Start off the resting place along the bisector, in skins (r / 1024).
    pub gap: f64,
    /// With a floor (a three-plane corner) and the push's downward angle, radians.
    pub floor: Option<f64>,
    pub m: Rigid,
}

impl Corner {
    pub fn random(seed: u64, kind: u8, degrees: f64, floor: bool) -> Corner {
        let mut g = rng(seed);
        let (r, shift) = sizes(kind, &mut g);
        Corner {
            degrees,
            r,
            push: g.range(0.05, 0.5),
            uneven: g.range(-0.7, 0.7),
            gap: g.range(0.0, 3.0),
            floor: floor.then(|| g.range(0.2, 1.2)),
            m: Rigid::random(&mut g, shift),
        }
    }
}

/// A ball in the corner of two walls (and a floor), pushed into it every step: after `settle`
/// steps it must not move across the crease any more (nor at all, with a floor); along the
/// crease it may slide by the push's own part along it.
pub fn corner<S: Tolerance>(c: &Corner, steps: usize, settle: usize) -> Monitor {
    let (theta, r) = (c.degrees.to_radians(), c.r);
    let (len, tall) = (6.0 * r, 8.0 * r);
    let y0 = if c.floor.is_some() { 0.0 } else { -tall / 2.0 };
    let w = World::<S>::new(&corner_tris(theta, len, y0, tall, c.floor.is_some()), c.m);
    let b = [(theta / 2.0).cos(), 0.0, (theta / 2.0).sin()];
    let lift = c.floor.map_or(0.0, |_| 1.0);
    let gap = c.gap * r / 1024.0;
    let local = add(
        scale(b, r / (theta / 2.0).sin() + gap),
        [0.0, lift * (r + gap), 0.0],
    );
    let start = back(v::<S>(w.m.point(local)));
    // Uneven, but inside the cone of the two wall normals (half-width (180° - θ) / 2 around
    // the bisector): only then do the walls' reactions balance the push, so the ball must
    // rest; outside it, sliding out along one wall is the right answer.
    let phi = theta / 2.0 + c.uneven * (std::f64::consts::PI - theta) / 2.0;
    let flat = [-phi.cos(), 0.0, -phi.sin()];
    let dir = match c.floor {
        Some(psi) => add(scale(flat, psi.cos()), [0.0, -psi.sin(), 0.0]),
        None => flat,
    };
    let push = scale(dir, c.push * r);
    let crease = unit(cross(w.normals[0], w.normals[2]));
    // Each wall is two triangles whose rounded vertices need not be coplanar: the push's part
    // along the crease is the largest over the creases the ball can be held in.
    let pushed = back(v::<S>(w.m.dir(push)));
    let along = [(0, 2), (0, 3), (1, 2), (1, 3)]
        .map(|(i, j)| dot(pushed, unit(cross(w.normals[i], w.normals[j]))).abs())
        .into_iter()
        .fold(0.0, f64::max);
    let label = format!(
        "corner {:.0}° r {:.3e} push {:.2}r uneven {:.2} gap {:.1} floor {:?}",
        c.degrees, r, c.push, c.uneven, c.gap, c.floor
    );
    let mut m = Monitor::new(label, &w, start, r);
    let mut rest = start;
    push_run(&w, &mut m, start, push, steps, |m, k, p| {
        let moved = sub(p, start);
        if c.floor.is_none() {
            m.drift(dot(moved, crease).abs(), along * (k + 1) as f64);
        }
        if k == settle {
            rest = p;
        } else if k > settle {
            let d = sub(p, rest);
            m.motion(norm(if c.floor.is_some() {
                d
            } else {
                across(d, crease)
            }));
        }
    });
    m
}

/// A ball rolling under gravity, bouncing (or sliding) and kicked, in a closed box or a closed
/// wedge: never deeper, never through a wall, never moved back along a step's displacement.
pub fn rolling<S: Tolerance>(seed: u64, kind: u8, steps: usize, wedge: bool) -> Monitor {
    let mut g = rng(seed);
    let (r, shift) = sizes(kind, &mut g);
    let (tris, local) = if wedge {
        let h = 6.0 * r;
        let alpha = g.range(40.0, 150.0).to_radians();
        let at = [g.range(-0.1, 0.1) * r, 0.6 * h, g.range(-2.0, 2.0) * r];
        (wedge_tris(alpha, h, 4.0 * r), at)
    } else {
        let h = r * g.range(2.0, 6.0);
        (box_tris(h), g.point(h - 1.01 * r))
    };
    let w = World::<S>::new(&tris, Rigid::random(&mut g, shift));
    let start = back(v::<S>(w.m.point(local)));
    let name = if wedge { "wedge" } else { "box" };
    let mut m = Monitor::new(
        format!("rolling {name} seed {seed} kind {kind}"),
        &w,
        start,
        r,
    );
    assert!(
        w.overlaps(start, r).iter().all(|&o| o == 0.0),
        "{m}: bad start"
    );
    let gravity = scale(
        unit([g.range(-0.3, 0.3), -1.0, g.range(-0.3, 0.3)]),
        0.01 * r,
    );
    let e = if g.next() < 0.5 { 0.0 } else { 0.5 };
    roll(&w, &mut m, start, gravity, 0.3 * r, e, steps, &mut g, |p| {
        w.behind_convex(p)
    });
    m
}

/// A ball pushed up or down stairs against gravity: never deeper, never into the steps.
pub fn stairs<S: Tolerance>(seed: u64, kind: u8, steps: usize) -> Monitor {
    let mut g = rng(seed);
    let (r, shift) = sizes(kind, &mut g);
    let (k, tread, rise) = (4, 3.0 * r, r * g.range(0.2, 1.4));
    let tall = k as f64 * rise + 4.0 * r;
    let w = World::<S>::new(
        &stairs_tris(k, tread, rise, 3.0 * r, tall),
        Rigid::random(&mut g, shift),
    );
    let up = g.next() < 0.5;
    let gap = g.range(0.0, 2.0) * r / 1024.0;
    let local = if up {
        [1.5 * r, r + gap, 0.0]
    } else {
        [
            (k as f64 - 0.5) * tread,
            (k - 1) as f64 * rise + r + gap,
            0.0,
        ]
    };
    let start = back(v::<S>(w.m.point(local)));
    let sign = if up { 1.0 } else { -1.0 };
    let push = [sign * r * g.range(0.05, 0.3), -0.05 * r, 0.0];
    let mut m = Monitor::new(format!("stairs seed {seed} kind {kind}"), &w, start, r);
    let end = k as f64 * tread;
    push_run(&w, &mut m, start, push, steps, |m, _, p| {
        let [x, y, _] = w.m.local(p);
        let step = (x / tread).floor().clamp(0.0, (k - 1) as f64);
        m.behind((-x).max(x - end).max(step * rise - y));
    });
    m
}
