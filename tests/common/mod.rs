//! Shared by the integration tests: an independent f64 model of the face test (world space, no
//! standard frame), conversion of a case to any scalar, and the tolerance table.
#![allow(dead_code)] // each test binary uses a different part

use ballcast::{Error, Scalar, Scene, StandardTriangle, Sweep, Triangle, Vec3};

pub mod to_and_fro;
pub mod walker;

pub type P = [f64; 3];

/// One query: a triangle, a ball path and a radius, in f64.
#[derive(Clone, Copy, Debug)]
pub struct Case {
    pub tri: [P; 3],
    pub p0: P,
    pub p1: P,
    pub r: f64,
}

pub fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
/// Two triangles covering the parallelogram `o, o + a, o + a + b, o + b`, front normal `a × b`.
pub fn quad(o: P, a: P, b: P) -> [[P; 3]; 2] {
    let (oa, ob) = (add(o, a), add(o, b));
    let oab = add(oa, b);
    [[o, oa, oab], [o, oab, ob]]
}

pub fn add(a: P, b: P) -> P {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub fn scale(a: P, s: f64) -> P {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: P, b: P) -> P {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn norm(a: P) -> f64 {
    dot(a, a).sqrt()
}
/// The angle between two directions, robust for tiny angles.
pub fn angle(a: P, b: P) -> f64 {
    norm(cross(a, b)).atan2(dot(a, b))
}

pub fn v<S: Scalar>(p: P) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}
pub fn back<S: Scalar>(p: Vec3<S>) -> P {
    [p.x.to_f64(), p.y.to_f64(), p.z.to_f64()]
}

impl Case {
    /// The same case with every input rounded to `S`: "the same inputs" for a comparison.
    pub fn rounded<S: Scalar>(&self) -> Case {
        let q = |p: P| back(v::<S>(p));
        Case {
            tri: self.tri.map(q),
            p0: q(self.p0),
            p1: q(self.p1),
            r: S::from_f64(self.r).to_f64(),
        }
    }

    /// The crate's face test in scalar `S`, results in f64.
    pub fn run<S: Scalar>(&self) -> Result<Option<(f64, P)>, Error> {
        let [a, b, c] = self.tri.map(v::<S>);
        let st = StandardTriangle::new(&Triangle::new(a, b, c))?;
        let s = Sweep::new(v(self.p0), v(self.p1), S::from_f64(self.r))?;
        Ok(st
            .face_collision(&s)
            .map(|h| (h.alpha.to_f64(), back(h.normal))))
    }
}

/// The independent model's answer for a case, and how close the case lies to a decision.
#[derive(Clone, Copy, Debug)]
pub struct Model {
    pub hit: Option<f64>,
    pub normal: P,
    /// `|(p1 - p0) · n|`: converts an error in alpha to a distance along the normal.
    pub approach: f64,
    /// Distance of the case from the nearest decision boundary, each boundary's distance divided
    /// by how much an error in height moves it (lateral boundaries move by lateral/vertical).
    pub margin: f64,
}

/// The face test in world space: heights above the plane through v0 along the unit normal,
/// containment by signed distances to the three edge lines. `None` for a degenerate triangle.
pub fn model(c: &Case) -> Option<Model> {
    let [v0, v1, v2] = c.tri;
    let n = cross(sub(v1, v0), sub(v2, v0));
    let len = norm(n);
    if len < 1e-9 {
        return None;
    }
    let n = scale(n, 1.0 / len);
    let (h0, h1) = (dot(sub(c.p0, v0), n), dot(sub(c.p1, v0), n));
    let d = sub(c.p1, c.p0);
    let approach = dot(d, n).abs();
    let lateral = norm(sub(d, scale(n, dot(d, n))));
    let mut margin = (h0 - c.r).abs().min((h1 - c.r).abs()).min((h0 - h1).abs());
    let mut hit = None;
    if h0 >= c.r && h1 < h0 && h1 < c.r {
        let beta = (c.r - h0) / (h1 - h0);
        let q = add(c.p0, scale(d, beta));
        let mut inside = true;
        for (a, b) in [(v0, v1), (v1, v2), (v2, v0)] {
            let inward = cross(n, sub(b, a));
            let dist = dot(sub(q, a), inward) / norm(inward);
            inside &= dist >= 0.0;
            margin = margin.min(dist.abs() / (1.0 + lateral / approach.max(1e-300)));
        }
        if inside {
            hit = Some(beta);
        }
    }
    Some(Model {
        hit,
        normal: n,
        approach,
        margin,
    })
}

/// Allowed error against f64 on the same (rounded) inputs, at scene scale 10: the tolerance
/// table, one row per scalar.
///
/// A contact's distance error is allowed `DISTANCE + EPSILON / 2 * approach`: the second term is
/// the unavoidable cost of reporting alpha in `S` (the nearest representable fraction is up to
/// half a step of `S` away, and a step of alpha moves the contact by `approach`, the path's
/// length along the normal, up to ~140 at this scale). `DISTANCE` is what the algorithm itself
/// adds. Reasons for each row:
/// - f64 against the independent model: two formulations agree to a few ulps of the scene's
///   largest distance (~100), i.e. ~1e-13.
/// - f32: heights are dot products of offsets up to ~90 long with unit axes; each carries a few
///   ulps of 90 (ulp = 7.6e-6), and the contact height averages those of start and end; 1e-5
///   is the target.
/// - I32F32: offsets are exact, axes carry 62 fractional bits, heights are rounded once to 32
///   fractional bits (2.3e-10) and beta to 2.3e-10 times a path of up to ~100: 2e-8 target.
/// - I16F16: heights rounded once to 16 fractional bits (7.6e-6 each); beta is quantised to
///   2^-16 of a path whose component along the normal reaches ~100: 5e-4 is the issue's
///   target. Normals are rounded to 16 fractional bits: 1.5e-5 rad, within 1e-3.
pub trait Tolerance: Scalar {
    /// Name for reports.
    const NAME: &'static str;
    /// Error of the contact's distance along the normal: `|alpha - alpha_f64| * approach`.
    const DISTANCE: f64;
    /// Angle between the reported normal and f64's, radians.
    const ANGLE: f64;
    /// Error of `Hit::position` along the normal: from the unrounded fraction, so a few steps
    /// of the scalar at the scene's extent plus the heights' rounding, with no alpha step times
    /// the path in it (fixed-point); floats' alpha is relative already, and their position is
    /// as good as their distance (`DISTANCE`), steps at coordinates up to 40 included.
    const POSITION: f64;
    /// Floats round relative to magnitude; fixed-point has one absolute step everywhere.
    const RELATIVE: bool;
    /// The spacing of representable values near `x`.
    fn spacing(x: f64) -> f64 {
        let eps = Self::EPSILON.to_f64();
        if Self::RELATIVE {
            eps * x.abs().max(1.0)
        } else {
            eps
        }
    }
}
impl Tolerance for f64 {
    const NAME: &'static str = "f64";
    const RELATIVE: bool = true;
    const DISTANCE: f64 = 1e-12;
    const ANGLE: f64 = 1e-12;
    const POSITION: f64 = 1e-12;
}
impl Tolerance for f32 {
    const NAME: &'static str = "f32";
    const RELATIVE: bool = true;
    const DISTANCE: f64 = 1e-5;
    const ANGLE: f64 = 1e-5;
    const POSITION: f64 = 2e-5;
}
impl Tolerance for fixed::types::I32F32 {
    const NAME: &'static str = "I32F32";
    const RELATIVE: bool = false;
    const DISTANCE: f64 = 2e-8;
    const ANGLE: f64 = 1e-7;
    const POSITION: f64 = 2e-8;
}
impl Tolerance for fixed::types::I16F16 {
    const NAME: &'static str = "I16F16";
    const RELATIVE: bool = false;
    const DISTANCE: f64 = 5e-4;
    const ANGLE: f64 = 1e-3;
    const POSITION: f64 = 1e-4;
}

/// The measured errors of one scalar against the model on one case.
#[derive(Clone, Copy, Debug, Default)]
pub struct Errors {
    /// Distance error along the normal at contact.
    pub distance: f64,
    /// `distance` less the half step of alpha's rounding in `S`: what the algorithm adds.
    pub excess: f64,
    pub angle: f64,
    /// A hit/miss disagreement outside the rounding band.
    pub misclassified: bool,
    /// The case was within the rounding band, so a disagreement there does not count.
    pub in_band: bool,
    /// Both the scalar and the model report a hit.
    pub hit: bool,
}

/// Compares scalar `S` with the f64 model on the same rounded inputs. `None` when the case is
/// degenerate for either.
pub fn compare<S: Tolerance>(case: &Case) -> Option<Errors> {
    let c = case.rounded::<S>();
    let m = model(&c)?;
    let got = c.run::<S>();
    // The rounding band: twice the distance tolerance, plus the model's own error.
    let in_band = m.margin <= 2.0 * S::DISTANCE + 1e-9;
    let got = match got {
        Ok(g) => g,
        // A triangle this far from collinear must be accepted by every scalar.
        Err(e) => {
            let [v0, v1, v2] = c.tri;
            let sin =
                norm(cross(sub(v1, v0), sub(v2, v0))) / (norm(sub(v1, v0)) * norm(sub(v2, v0)));
            assert!(sin < 1e-3, "{e:?} for a well-shaped triangle {c:?}");
            return None;
        }
    };
    let mut e = Errors {
        in_band,
        ..Errors::default()
    };
    match (got, m.hit) {
        (Some((alpha, n)), Some(beta)) => {
            e.distance = (alpha - beta).abs() * m.approach;
            e.excess = e.distance - S::EPSILON.to_f64() / 2.0 * m.approach;
            e.angle = angle(n, m.normal);
            e.hit = true;
        }
        (None, None) => {}
        _ => e.misclassified = !in_band,
    }
    Some(e)
}

/// A small deterministic generator (xorshift64*) for report-sized samples.
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    pub fn point(&mut self, half: f64) -> P {
        [0; 3].map(|_| self.range(-half, half))
    }
    /// A case at scene scale `s`: triangle within ±s, path within ±4s, radius 0.01s–0.2s.
    pub fn case(&mut self, s: f64) -> Case {
        Case {
            tri: [self.point(s), self.point(s), self.point(s)],
            p0: self.point(4.0 * s),
            p1: self.point(4.0 * s),
            r: self.range(0.01 * s, 0.2 * s),
        }
    }
    /// Like [`Rng::case`], but the path crosses the triangle's plane from the front: about a
    /// third of these are hits.
    pub fn falling_case(&mut self, s: f64) -> Case {
        let tri = [self.point(s), self.point(s), self.point(s)];
        let n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]));
        let n = scale(n, 1.0 / norm(n).max(1e-300));
        let h = self.range(0.1 * s, 3.0 * s);
        Case {
            tri,
            p0: add(self.point(s), scale(n, h)),
            p1: add(self.point(s), scale(n, -h)),
            r: self.range(0.01 * s, 0.2 * s),
        }
    }
    /// A case at scene scale `s` aimed at a vertex or an edge of a triangle `size` across
    /// within ±s: the path, up to `path` long and tilted up to about 40° from the normal, passes
    /// within 1.2 r of the feature (`r` 0.01s–0.2s, at most 2), so most hits are edge and
    /// vertex contacts.
    pub fn feature_case(&mut self, s: f64, size: f64, path: f64) -> Case {
        let c = self.point(s - size);
        let tri = [0; 3].map(|_| add(c, self.point(size)));
        let n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]));
        let n = scale(n, 1.0 / norm(n).max(1e-300));
        let r = self.range(0.01 * s, 0.2 * s).min(2.0);
        let k = (self.next() * 3.0) as usize % 3;
        let a = if self.next() < 0.5 { 0.0 } else { self.next() };
        let on = add(scale(tri[k], 1.0 - a), scale(tri[(k + 1) % 3], a));
        let target = add(on, scale(self.point(1.0), 1.2 * r));
        let dir = add(n, self.point(0.8));
        let dir = scale(dir, 1.0 / norm(dir).max(1e-300));
        let len = self.range(0.0, path);
        let ahead = self.range(0.0, len);
        Case {
            tri,
            p0: add(target, scale(dir, ahead)),
            p1: add(target, scale(dir, ahead - len)),
            r,
        }
    }
}

/// The point of triangle `t` closest to `p` (Ericson, Real-Time Collision Detection, 5.1.5),
/// an oracle independent of the crate's formulation.
pub fn closest_on_triangle(p: P, t: [P; 3]) -> P {
    let [a, b, c] = t;
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return add(a, scale(ab, d1 / (d1 - d3)));
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return add(a, scale(ac, d2 / (d2 - d6)));
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        return add(b, scale(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
    }
    let denom = 1.0 / (va + vb + vc);
    add(a, add(scale(ab, vb * denom), scale(ac, vc * denom)))
}

/// Distance from `p` to triangle `t`.
pub fn distance_to_triangle(p: P, t: [P; 3]) -> f64 {
    norm(sub(p, closest_on_triangle(p, t)))
}

impl Case {
    /// The crate's full `cast` in scalar `S`, results in f64, with every feature active.
    pub fn cast<S: Scalar>(&self, radius: f64) -> Result<Option<(f64, P)>, Error> {
        Ok(self
            .cast_with::<S>(radius, ballcast::Features::ALL)?
            .map(|(a, n, _)| (a, n)))
    }
    /// `cast` with the given features active, with the contact reported.
    pub fn cast_with<S: Scalar>(
        &self,
        radius: f64,
        features: ballcast::Features,
    ) -> Result<Option<(f64, P, ballcast::Contact)>, Error> {
        let [a, b, c] = self.tri.map(v::<S>);
        let st = StandardTriangle::new(&Triangle::new(a, b, c))?.with_features(features);
        let s = Sweep::new(v(self.p0), v(self.p1), S::from_f64(radius))?;
        Ok(st
            .cast(&s)
            .map(|h| (h.alpha.to_f64(), back(h.normal), h.contact)))
    }
    /// The ball's centre at fraction `t` of the path.
    pub fn at(&self, t: f64) -> P {
        add(self.p0, scale(sub(self.p1, self.p0), t))
    }
}

/// A 16 × 16 plane through the origin with front normal `n`, two triangles.
pub fn slope<S: Scalar>(n: [f64; 3]) -> Scene<S, 8> {
    let mut s = Scene::new();
    for t in plane(n) {
        s.push(Triangle::new(v(t[0]), v(t[1]), v(t[2]))).unwrap();
    }
    s
}

/// The two triangles of [`slope`].
pub fn plane(n: [f64; 3]) -> [[P; 3]; 2] {
    // Two directions in the plane: a = n × z (or n × x), b = n × a, both unit.
    let helper = if n[2].abs() < 0.9 {
        [0.0, 0.0, 1.0]
    } else {
        [1.0, 0.0, 0.0]
    };
    let a = cross(n, helper);
    let a = scale(a, 1.0 / norm(a));
    let b = cross(n, a);
    let p = |i: f64, j: f64| add(scale(a, 8.0 * i), scale(b, 8.0 * j));
    let (p0, p1, p2, p3) = (p(-1.0, -1.0), p(1.0, -1.0), p(1.0, 1.0), p(-1.0, 1.0));
    // Counter-clockwise seen from n: (p1 - p0) × (p2 - p0) points along a × b = n.
    [[p0, p1, p2], [p0, p2, p3]]
}

/// Two slopes each `steep` degrees from level meeting in a trough along z, the trough rising
/// at `rise` degrees: slopes 40 long up from the trough, 40 along it, fronts inside.
pub fn valley<S: Scalar>(steep: f64, rise: f64) -> Scene<S, 8> {
    valley_at(steep, rise, [0.0; 3])
}

/// [`valley`] with its trough's centre moved from the origin to `at`.
pub fn valley_at<S: Scalar>(steep: f64, rise: f64, at: P) -> Scene<S, 8> {
    let (s, c) = steep.to_radians().sin_cos();
    let (sr, cr) = rise.to_radians().sin_cos();
    // Tilt about x so that +z rises by `rise`, then move to `at`.
    let tilt = |p: [f64; 3]| {
        v::<S>(add(
            at,
            [p[0], p[1] * cr + p[2] * sr, p[2] * cr - p[1] * sr],
        ))
    };
    let mut level = Scene::new();
    for side in [-1.0, 1.0] {
        let up = [side * c * 40.0, s * 40.0, 0.0];
        let (o, far) = ([0.0, 0.0, -20.0], [0.0, 0.0, 20.0]);
        let (oa, ob) = (add(o, up), far);
        let oab = add(up, far);
        // Front normal `(b - o) × (a - o)` for the left slope, the other way for the right.
        let (a, b) = if side < 0.0 { (oa, ob) } else { (ob, oa) };
        level
            .push(Triangle::new(tilt(o), tilt(a), tilt(oab)))
            .unwrap();
        level
            .push(Triangle::new(tilt(o), tilt(oab), tilt(b)))
            .unwrap();
    }
    level
}

/// One test per scalar for each generic test body `name::<S>()` of the file that uses it
/// (`#[macro_use] mod common;`): `every_scalar!(first_property, second_property);`.
#[allow(unused_macros)]
macro_rules! every_scalar {
    ($($name:ident),*) => {$(
        mod $name {
            use fixed::types::{I16F16, I32F32};
            #[test] fn f64() { super::$name::<f64>() }
            #[test] fn f32() { super::$name::<f32>() }
            #[test] fn i32f32() { super::$name::<I32F32>() }
            #[test] fn i16f16() { super::$name::<I16F16>() }
        }
    )*};
}
