//! Long-run helpers for `tests/response.rs` (issue 11): rigid motions, scenes held in a scalar
//! next to their f64 reference geometry, the one call into the crate's response, and a monitor
//! that measures every step against independent f64 geometry (Ericson's point-triangle
//! distance from `tests/common/mod.rs`, never the crate's own answers).
#![allow(dead_code)]

use crate::common::{
    P, Rng, Tolerance, add, back, cross, distance_to_triangle, dot, norm, scale, sub, v,
};
use ballcast::{Error, MAX_SLIDES, Scalar, Scene, SceneHit, Slide, Sweep, Triangle, Vec3};
use std::fmt;

pub type Tri = [P; 3];
/// Capacity of every test scene.
pub const CAP: usize = 32;

pub fn unit(a: P) -> P {
    scale(a, 1.0 / norm(a))
}

pub use crate::common::quad;

/// A rigid motion `x ↦ R x + t`.
#[derive(Clone, Copy, Debug)]
pub struct Rigid {
    pub rot: [P; 3],
    pub shift: P,
}

impl Rigid {
    pub const IDENTITY: Rigid = Rigid {
        rot: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        shift: [0.0; 3],
    };
    /// A uniformly random rotation (a unit quaternion by rejection) and a shift within `±half`.
    pub fn random(rng: &mut Rng, half: f64) -> Rigid {
        let q = loop {
            let q = [0; 4].map(|_| rng.range(-1.0, 1.0));
            let n2: f64 = q.iter().map(|x| x * x).sum();
            if n2 > 0.01 && n2 <= 1.0 {
                break q.map(|x| x / n2.sqrt());
            }
        };
        let [w, x, y, z] = q;
        let rot = [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - w * z),
                2.0 * (x * z + w * y),
            ],
            [
                2.0 * (x * y + w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - w * x),
            ],
            [
                2.0 * (x * z - w * y),
                2.0 * (y * z + w * x),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ];
        Rigid {
            rot,
            shift: rng.point(half),
        }
    }
    pub fn dir(&self, d: P) -> P {
        self.rot.map(|row| dot(row, d))
    }
    pub fn point(&self, p: P) -> P {
        add(self.dir(p), self.shift)
    }
    /// Back to local coordinates.
    pub fn local(&self, p: P) -> P {
        let q = sub(p, self.shift);
        [0, 1, 2].map(|j| (0..3).map(|i| self.rot[i][j] * q[i]).sum())
    }
}

/// A scene in scalar `S` and the same triangles, as `S` holds them, in f64.
pub struct World<S: Scalar> {
    pub scene: Scene<S, CAP>,
    pub tris: Vec<Tri>,
    /// Unit front normals of `tris`, computed in f64 from the rounded vertices.
    pub normals: Vec<P>,
    pub m: Rigid,
    /// The spacing of `S` at the scene's largest coordinate: one step of resolution.
    pub res: f64,
    /// The scene's largest coordinate.
    pub extent: f64,
}

impl<S: Tolerance> World<S> {
    /// `local` triangles moved by `m`, rounded to `S`.
    pub fn new(local: &[Tri], m: Rigid) -> Self {
        let mut scene = Scene::new();
        let mut tris = Vec::new();
        let mut extent: f64 = 0.0;
        for t in local {
            let w = t.map(|p| back(v::<S>(m.point(p))));
            scene
                .push(Triangle::new(v(w[0]), v(w[1]), v(w[2])))
                .unwrap_or_else(|e| panic!("{}: {e:?} for {w:?}", S::NAME));
            extent = w.iter().flatten().fold(extent, |e, x| e.max(x.abs()));
            tris.push(w);
        }
        let normals = tris
            .iter()
            .map(|t| unit(cross(sub(t[1], t[0]), sub(t[2], t[0]))))
            .collect();
        World {
            scene,
            tris,
            normals,
            m,
            res: S::spacing(extent),
            extent,
        }
    }
    /// Signed height of `p` above triangle `i`'s plane.
    pub fn height(&self, i: usize, p: P) -> f64 {
        dot(sub(p, self.tris[i][0]), self.normals[i])
    }
    /// How far a ball at `p` overlaps triangle `i`, counted only from its front side.
    pub fn overlap(&self, i: usize, p: P, r: f64) -> f64 {
        if self.height(i, p) < 0.0 {
            0.0
        } else {
            (r - distance_to_triangle(p, self.tris[i])).max(0.0)
        }
    }
    pub fn overlaps(&self, p: P, r: f64) -> Vec<f64> {
        (0..self.tris.len())
            .map(|i| self.overlap(i, p, r))
            .collect()
    }
    /// For a closed convex solid: how far the centre lies behind the deepest face plane.
    pub fn behind_convex(&self, p: P) -> f64 {
        (0..self.tris.len()).fold(0.0, |m: f64, i| m.max(-self.height(i, p)))
    }
    /// One call of the crate's response (the one place to adapt if its signature changes).
    pub fn step(&self, p: Vec3<S>, d: Vec3<S>, r: S) -> Result<Slide<S>, Error> {
        ballcast::move_and_slide(&self.scene, p, d, r)
    }
    /// One query of the scene.
    pub fn cast(&self, p0: P, p1: P, r: f64) -> Option<SceneHit<S>> {
        let s = Sweep::new(v::<S>(p0), v(p1), S::from_f64(r)).unwrap();
        self.scene.cast(&s)
    }
}

/// Every plane a call met, simultaneous contacts included, in f64.
pub fn contact_normals<S: Scalar>(s: &Slide<S>) -> Vec<P> {
    s.contacts
        .iter()
        .flatten()
        .flat_map(|c| c.hit.planes.into_iter().flatten())
        .map(back)
        .collect()
}
/// The normals one scene hit reports (see [`contact_normals`]).
pub fn hit_normals<S: Scalar>(h: &SceneHit<S>) -> Vec<P> {
    vec![back(h.normal)]
}

/// Measures one run step by step and keeps its maxima and first failures.
///
/// Allowances, all from the scalar's resolution `res` (its spacing at the scene's largest
/// coordinate) and the response's documented skin (`ballcast::slide::skin` at the scene's
/// largest coordinate):
/// - depth: no triangle's overlap (front side only) may grow, within one call or since the
///   run's start, by more than one skin;
/// - against the push: a call may move the centre back along its displacement by at most one
///   skin per contact (`MAX_SLIDES` skins): the lift off the surfaces, nothing more;
/// - through: the centre may lie at most `4 res` behind a surface it must stay in front of;
/// - drift: no more than the caller's allowance plus `round`;
/// - corner motion after settling: at most `round` from the settled position;
///
/// where `round = 8 res + 8 EPSILON × path` (`path` the longest displacement asked for): a
/// contact is placed to within a step of alpha, i.e. EPSILON times the path (the README's
/// "alpha is reported in the scalar"), plus the rounding of the position itself.
pub struct Monitor {
    pub label: String,
    /// The radius, as the scalar holds it.
    pub r: f64,
    pub res: f64,
    pub skin: f64,
    /// The scalar's EPSILON, and the longest displacement asked for so far.
    eps: f64,
    pub path: f64,
    start: Vec<f64>,
    last: Vec<f64>,
    pub steps: usize,
    /// Largest growth of any overlap since the run's start.
    pub sink: f64,
    /// Largest growth of any overlap within one call.
    pub step_sink: f64,
    /// Largest motion back along the push within one call.
    pub against: f64,
    /// Deepest the centre got behind a surface.
    pub behind: f64,
    pub drift: f64,
    pub drift_excess: f64,
    pub motion: f64,
    /// Calls refused with an error.
    pub errors: usize,
    pub failed: usize,
    pub failures: Vec<String>,
    /// Whether a refusal ([`Error`]) is an acceptable outcome (it ends the run either way).
    pub may_refuse: bool,
}

impl Monitor {
    pub fn new<S: Tolerance>(label: String, w: &World<S>, start: P, r: f64) -> Self {
        let r = S::from_f64(r).to_f64();
        let o = w.overlaps(start, r);
        Monitor {
            label: format!("{} {label}", S::NAME),
            r,
            res: w.res,
            skin: ballcast::slide::skin(S::from_f64(r), S::from_f64(w.extent)).to_f64(),
            eps: S::EPSILON.to_f64(),
            path: 0.0,
            start: o.clone(),
            last: o,
            steps: 0,
            sink: 0.0,
            step_sink: 0.0,
            against: 0.0,
            behind: 0.0,
            drift: 0.0,
            drift_excess: 0.0,
            motion: 0.0,
            errors: 0,
            failed: 0,
            failures: Vec::new(),
            may_refuse: false,
        }
    }
    pub fn fail(&mut self, what: String) {
        self.failed += 1;
        if self.failures.len() < 3 {
            let msg = format!("step {}: {what}", self.steps);
            self.failures.push(msg);
        }
    }
    /// One call moved the centre from `before` to `after` for the requested `push`.
    pub fn call<S: Tolerance>(&mut self, w: &World<S>, before: P, after: P, push: P) {
        self.steps += 1;
        let now = w.overlaps(after, self.r);
        for (i, &o) in now.iter().enumerate() {
            let (run, call) = (o - self.start[i], o - self.last[i]);
            self.sink = self.sink.max(run);
            self.step_sink = self.step_sink.max(call);
            if run > self.skin || call > self.skin {
                self.fail(format!(
                    "overlap with triangle {i} {o:.3e} (start {:.3e}, before {:.3e}) at {after:?}",
                    self.start[i], self.last[i]
                ));
            }
        }
        self.last = now;
        let len = norm(push);
        self.path = self.path.max(len);
        if len > 0.0 {
            let back_along = -dot(sub(after, before), push) / len;
            self.against = self.against.max(back_along);
            if back_along > MAX_SLIDES as f64 * self.skin {
                self.fail(format!(
                    "moved {back_along:.3e} against the push {push:?}: {before:?} -> {after:?}"
                ));
            }
        }
    }
    pub fn behind(&mut self, depth: f64) {
        self.behind = self.behind.max(depth);
        if depth > 4.0 * self.res {
            self.fail(format!("centre {depth:.3e} behind a surface"));
        }
    }
    pub fn drift(&mut self, drift: f64, allowed: f64) {
        self.drift = self.drift.max(drift);
        self.drift_excess = self.drift_excess.max(drift - allowed);
        if drift > allowed + self.round() {
            self.fail(format!("drifted {drift:.3e}, allowed {allowed:.3e}"));
        }
    }
    pub fn motion(&mut self, m: f64) {
        self.motion = self.motion.max(m);
        if m > self.round() {
            self.fail(format!("moved {m:.3e} from its resting place"));
        }
    }
    pub fn refused(&mut self, e: Error) {
        self.errors += 1;
        if !self.may_refuse {
            self.fail(format!("refused: {e:?}"));
        }
    }
    /// Rounding of a placed position: `8 res + 8 EPSILON × path`.
    pub fn round(&self) -> f64 {
        8.0 * self.res + 8.0 * self.eps * self.path
    }
    pub fn ok(&self) -> bool {
        self.failed == 0
    }
}

impl fmt::Display for Monitor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} [{} steps, r {:.3e}, res {:.1e}]: sink {:.2e} (per call {:.2e}), against {:.2e}, \
             behind {:.2e}, drift {:.2e} (excess {:.2e}), corner motion {:.2e}, errors {}; {} failed",
            self.label,
            self.steps,
            self.r,
            self.res,
            self.sink,
            self.step_sink,
            self.against,
            self.behind,
            self.drift,
            self.drift_excess,
            self.motion,
            self.errors,
            self.failed
        )?;
        for m in &self.failures {
            write!(f, "\n    {m}")?;
        }
        Ok(())
    }
}

/// Prints every report and fails with all failing ones.
pub fn assert_all(reports: &[Monitor]) {
    for m in reports {
        println!("{m}");
    }
    let bad: Vec<String> = reports
        .iter()
        .filter(|m| !m.ok())
        .map(|m| m.to_string())
        .collect();
    assert!(
        bad.is_empty(),
        "{} failing runs:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

/// Per-scalar maxima over many runs, for the long-run report.
#[derive(Default)]
pub struct Maxima {
    pub runs: usize,
    pub failed_runs: usize,
    pub sink: f64,
    pub against: f64,
    pub behind: f64,
    pub drift: f64,
    pub drift_excess: f64,
    pub motion: f64,
    pub errors: usize,
}

impl Maxima {
    pub fn add(&mut self, m: &Monitor) {
        self.runs += 1;
        self.failed_runs += !m.ok() as usize;
        self.sink = self.sink.max(m.sink.max(m.step_sink));
        self.against = self.against.max(m.against);
        self.behind = self.behind.max(m.behind);
        self.drift = self.drift.max(m.drift);
        self.drift_excess = self.drift_excess.max(m.drift_excess);
        self.motion = self.motion.max(m.motion);
        self.errors += m.errors;
    }
}

impl fmt::Display for Maxima {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} runs, {} failing: depth growth {:.2e}, drift {:.2e} (beyond allowance {:.2e}), \
             corner motion {:.2e}, against push {:.2e}, behind {:.2e}, errors {}",
            self.runs,
            self.failed_runs,
            self.sink,
            self.drift,
            self.drift_excess,
            self.motion,
            self.against,
            self.behind,
            self.errors
        )
    }
}
