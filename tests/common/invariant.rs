//! The fuzzing invariant, shared by the cargo-fuzz targets (`fuzz/`) and their proptest twin
//! (`tests/fuzz_invariants.rs`).
//!
//! Bits become a triangle, a ball path and a radius in one scalar. Constructors either refuse
//! them with an [`Error`] value that the input justifies, or accept exactly the finite values
//! within the safe range; whatever they accept the algorithms answer without panicking (in a
//! build with overflow checks, so any fixed-point overflow panics), and a hit has
//! `0 <= alpha < 1` and a unit normal within the scalar's tolerance.
//!
//! Input layout: a mode byte, a 32-bit selector, then [`WORDS`] 64-bit words, one per value:
//! `v0`, `v1`, `v2`, `p0`, `p1` (three coordinates each) and the radius. Value kinds
//! (`mode % 4`): 0 raw bit patterns (floats: NaN, infinities, subnormals, huge values;
//! fixed-point: the whole range, most of it beyond `LIMIT`); 1 raw values folded into `±LIMIT`;
//! 2 a small integer grid with optional perturbations of a few ULP, scaled by a shared power of
//! two (`2^((mode >> 3) - 16)`); 3 a per-value mix of the three plus special values, chosen by
//! the selector's bit pairs. With `mode & 4` the path is instead aimed at the triangle (see
//! [`aim`]), so that hits, grazing paths and contacts near edges are common.
#![allow(dead_code)]

use ballcast::{
    Error, Hit, Scalar, StandardSweep, StandardTriangle, Sweep, Triangle, Vec3, standard_face,
};
use fixed::types::{I16F16, I32F32};

/// Values per input: nine vertex coordinates, six path coordinates, one radius.
pub const WORDS: usize = 16;
/// Bytes per input that [`check_bytes`] reads (shorter inputs are padded with zeros).
pub const BYTES: usize = 1 + 4 + 8 * WORDS;

/// How a scalar is made from bits.
pub trait Bits: Scalar {
    /// The low bits of `w` reinterpreted as a value, whatever it is.
    fn raw(w: u64) -> Self;
    /// A raw value folded into `[-LIMIT, LIMIT]`.
    fn folded(w: u64) -> Self;
}

macro_rules! float_bits {
    ($t:ty, $u:ty) => {
        impl Bits for $t {
            fn raw(w: u64) -> Self {
                <$t>::from_bits(w as $u)
            }
            fn folded(w: u64) -> Self {
                let f = Self::raw(w);
                if !f.is_finite() {
                    // Keep the payload: a fraction of the range from the low bits.
                    (w as $u as f64 / <$u>::MAX as f64 * 2.0 - 1.0) as $t * Self::LIMIT
                } else if f.abs() > Self::LIMIT {
                    f % Self::LIMIT
                } else {
                    f
                }
            }
        }
    };
}
float_bits!(f32, u32);
float_bits!(f64, u64);

macro_rules! fixed_bits {
    ($t:ty, $bits:ty) => {
        impl Bits for $t {
            fn raw(w: u64) -> Self {
                <$t>::from_bits(w as $bits)
            }
            fn folded(w: u64) -> Self {
                let lim = Self::LIMIT.to_bits();
                <$t>::from_bits((w as $bits).rem_euclid(2 * lim + 1) - lim)
            }
        }
    };
}
fixed_bits!(I16F16, i32);
fixed_bits!(I32F32, i64);

/// Values worth hitting on purpose: zeros, the range's edges and just past them, the standard
/// frame's bound `3.5 * LIMIT`, one step, the smallest and largest values, NaN and infinities.
fn special<S: Bits>(w: u64) -> S {
    let l = S::LIMIT.to_f64();
    let e = S::EPSILON.to_f64();
    let table = [
        0.0,
        -0.0,
        l,
        -l,
        l * (1.0 + 2.0 * e),
        3.5 * l,
        -3.5 * l,
        e,
        -e,
        f64::MIN_POSITIVE,
        1e-300,
        f64::MAX,
        f64::MIN,
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    S::from_f64(table[(w % table.len() as u64) as usize])
}

/// A point of a small integer grid (quarters in `[-32, 32)`), optionally moved by a few ULP of
/// one, times `2^scale`.
fn grid<S: Bits>(w: u64, scale: i32) -> S {
    let mut x = (w as u8 as i8) as f64 / 4.0;
    if w & 0x100 != 0 {
        let ulps = ((w >> 16) as u8 as i8) as f64;
        x += ulps * S::EPSILON.to_f64() * (1u32 << ((w >> 24) & 7)) as f64;
    }
    S::from_f64(x * 2f64.powi(scale))
}

/// A fraction from 16 bits of `w`, in `[lo, hi]`.
fn frac(w: u64, shift: u32, lo: f64, hi: f64) -> f64 {
    lo + ((w >> shift) as u16) as f64 / 65535.0 * (hi - lo)
}

/// Replaces the path and radius (`x[9..16]`) by one aimed at the triangle `x[0..9]`, computed in
/// f64 and rounded to `S`: the radius from `w[15]`'s value, a target point with barycentric
/// weights from `w[9]`, `w[10]` (a little beyond the edges too), a start above and an end below
/// the plane at the contact height (from `w[11]`, `w[12]`; often exactly at it), and a sideways
/// drift (`w[13]`, `w[14]`). Degenerate or non-finite triangles are left alone.
pub fn aim<S: Bits>(x: &mut [S; WORDS], w: &[u64; WORDS]) {
    let f: [f64; 9] = core::array::from_fn(|i| x[i].to_f64());
    let (a, b, c) = ([f[0], f[1], f[2]], [f[3], f[4], f[5]], [f[6], f[7], f[8]]);
    let sub = |p: [f64; 3], q: [f64; 3]| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    let (e1, e2) = (sub(b, a), sub(c, a));
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let span = e1.iter().chain(&e2).fold(0.0f64, |m, v| m.max(v.abs()));
    if !(len.is_finite() && len > 0.0 && span.is_finite()) {
        return;
    }
    let n = n.map(|v| v / len);
    let r = x[15].to_f64().abs();
    let r = if r.is_finite() {
        r.min(span)
    } else {
        span / 8.0
    };
    let (u, v) = (frac(w[9], 0, -0.1, 1.1), frac(w[10], 0, -0.1, 1.1));
    // Heights of the centre above the plane: exactly at contact when the selector bits say so.
    let h0 = r + if w[11] & 1 == 0 {
        0.0
    } else {
        frac(w[11], 8, 0.0, 2.0) * span
    };
    let h1 = r - if w[12] & 1 == 0 {
        0.0
    } else {
        frac(w[12], 8, -0.1, 2.0) * span
    };
    let (dx, dz) = (
        frac(w[13], 0, -0.5, 0.5) * span,
        frac(w[14], 0, -0.5, 0.5) * span,
    );
    let d = [dx, 0.0, dz];
    for k in 0..3 {
        let q = a[k] + u * e1[k] + v * e2[k];
        x[9 + k] = S::from_f64(q + n[k] * h0 + d[k]);
        x[12 + k] = S::from_f64(q + n[k] * h1 - d[k]);
    }
    x[15] = S::from_f64(r);
}

/// Value `i` of an input.
pub fn value<S: Bits>(mode: u8, sel: u32, i: usize, w: u64) -> S {
    let scale = (mode >> 3) as i32 - 16;
    let kind = if mode % 4 == 3 {
        (sel >> (2 * i)) & 3
    } else {
        mode as u32 % 4
    };
    match kind {
        0 => S::raw(w),
        1 => S::folded(w),
        2 => grid(w, scale),
        _ => special(w),
    }
}

fn in_range<S: Scalar>(x: S, bound: S) -> bool {
    x.is_finite() && x <= bound && x >= -bound
}

fn point_in_range<S: Scalar>(p: Vec3<S>, bound: S) -> bool {
    in_range(p.x, bound) && in_range(p.y, bound) && in_range(p.z, bound)
}

fn any_non_finite<S: Scalar>(xs: &[S]) -> bool {
    xs.iter().any(|x| !x.is_finite())
}

/// An error is justified by the values it refused: `xs` are the coordinates (each allowed up
/// to `bound`), `r` the radius if there is one (allowed up to `LIMIT`).
fn justified<S: Scalar>(e: Error, xs: &[S], bound: S, r: Option<S>) {
    let beyond = |x: S, b: S| x.is_finite() && !in_range(x, b);
    match e {
        Error::NaN { .. } => assert!(
            any_non_finite(xs) || r.is_some_and(|r| !r.is_finite()),
            "NaN for {xs:?} {r:?}"
        ),
        Error::OutOfRange { value, .. } => assert!(
            xs.iter().chain(r.as_ref()).any(|x| x.to_f64() == value)
                && (xs.iter().any(|x| beyond(*x, bound) || !x.is_finite())
                    || r.is_some_and(|r| beyond(r, S::LIMIT) || !r.is_finite())),
            "OutOfRange ({value}) for {xs:?} {r:?}"
        ),
        Error::NegativeRadius { value } => assert!(
            r.is_some_and(|r| r < S::ZERO && r.to_f64() == value),
            "NegativeRadius, {r:?}"
        ),
        // Only containers and responses report these.
        e @ (Error::Full { .. } | Error::RadiusTooSmall { .. }) => {
            panic!("a constructor reported {e:?}")
        }
        Error::Degenerate { .. } => assert!(
            r.is_none() && xs.iter().all(|x| in_range(*x, bound)),
            "Degenerate for {xs:?}"
        ),
        e => panic!("an error this invariant does not know: {e:?}"),
    }
}

fn length<S: Scalar>(n: Vec3<S>) -> f64 {
    let [x, y, z] = n.to_array().map(S::to_f64);
    (x * x + y * y + z * z).sqrt()
}

/// Unit length within four steps of the scalar near one.
fn assert_unit<S: Scalar>(n: Vec3<S>, what: &str) {
    let len = length(n);
    assert!(
        (len - 1.0).abs() <= 4.0 * S::EPSILON.to_f64(),
        "{what} {n:?} has length {len}"
    );
}

fn assert_alpha<S: Scalar>(a: S, what: &str) {
    assert!(a >= S::ZERO && a < S::ONE, "{what} {a:?} outside [0, 1)");
}

/// How far an input got: which constructors accepted it and whether the face test hit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outcome {
    /// `Sweep::new` accepted the path and radius.
    pub sweep: bool,
    /// `StandardTriangle::new` accepted the vertices.
    pub triangle: bool,
    /// `face_collision` reported a hit (both accepted).
    pub hit: bool,
}

/// Checks one input; panics (a finding) if the invariant fails.
pub fn check<S: Bits>(mode: u8, sel: u32, w: &[u64; WORDS]) -> Outcome {
    let mut out = Outcome::default();
    let mut x: [S; WORDS] = core::array::from_fn(|i| value(mode, sel, i, w[i]));
    if mode & 4 != 0 {
        aim(&mut x, w);
    }
    let p = |i: usize| Vec3::new(x[i], x[i + 1], x[i + 2]);
    let (v0, v1, v2, p0, p1, r) = (p(0), p(3), p(6), p(9), p(12), x[15]);

    // The sweep constructor accepts exactly the finite values within ±LIMIT with r >= 0.
    let sweep = Sweep::new(p0, p1, r);
    let valid = point_in_range(p0, S::LIMIT)
        && point_in_range(p1, S::LIMIT)
        && in_range(r, S::LIMIT)
        && r >= S::ZERO;
    assert_eq!(sweep.is_ok(), valid, "Sweep::new({p0:?}, {p1:?}, {r:?})");
    out.sweep = valid;
    if let Err(e) = sweep {
        justified(e, &x[9..15], S::LIMIT, Some(r));
    }
    // So does the standard-frame one, with 3.5 * LIMIT for coordinates.
    let bound = S::from_f64(3.5 * S::LIMIT.to_f64());
    let standard = StandardSweep::new(p0, p1, r);
    let valid = point_in_range(p0, bound)
        && point_in_range(p1, bound)
        && in_range(r, S::LIMIT)
        && r >= S::ZERO;
    assert_eq!(
        standard.is_ok(),
        valid,
        "StandardSweep::new({p0:?}, {p1:?}, {r:?})"
    );
    if let Err(e) = standard {
        justified(e, &x[9..15], bound, Some(r));
    }

    // The triangle constructor accepts only vertices within ±LIMIT, and then a proper frame.
    let tri = StandardTriangle::new(&Triangle::new(v0, v1, v2));
    let st = match tri {
        Err(e) => {
            justified(e, &x[..9], S::LIMIT, None);
            return out;
        }
        Ok(st) => st,
    };
    out.triangle = true;
    for v in [v0, v1, v2] {
        assert!(point_in_range(v, S::LIMIT), "accepted vertex {v:?}");
    }
    assert_unit(st.normal(), "triangle normal");
    let [_, [x1, y1, z1], [x2, y2, z2]] = st.vertices().map(Vec3::to_array);
    assert!(y1 == S::ZERO && y2 == S::ZERO && z2 == S::ZERO);
    assert!(
        x2 > S::ZERO && z1 > S::ZERO,
        "standard shape {x1:?} {z1:?} {x2:?}"
    );
    let _ = st.axes();

    // Everything accepted is answered.
    if let Ok(s) = standard
        && let Some(beta) = standard_face(&st, &s)
    {
        assert_alpha(beta, "standard_face beta");
    }
    let Ok(s) = sweep else { return out };
    let ss = st.standardize(&s);
    assert_eq!(st.to_standard(p0), Ok(ss.p0()));
    assert_eq!(st.to_standard(p1), Ok(ss.p1()));
    let hit = st.face_collision(&s);
    assert_eq!(hit.map(|h| h.alpha), standard_face(&st, &ss));
    if let Some(Hit { alpha, normal, .. }) = hit {
        assert_alpha(alpha, "alpha");
        assert_eq!(normal, st.normal());
        assert_unit(normal, "hit normal");
        out.hit = true;
    }
    // The full test: a face hit is its answer too; any hit has a valid alpha and unit normal.
    let full = st.cast(&s);
    if let Some(h) = hit {
        assert_eq!(
            full.map(|f| f.alpha),
            Some(h.alpha),
            "cast disagrees with the face hit"
        );
    }
    if let Some(Hit { alpha, normal, .. }) = full {
        assert_alpha(alpha, "cast alpha");
        assert_unit(normal, "cast normal");
    }
    out
}

/// Splits raw bytes into an input (zero-padded) and checks it in scalar `S`.
pub fn check_bytes<S: Bits>(data: &[u8]) -> Outcome {
    let mut b = [0u8; BYTES];
    let n = data.len().min(BYTES);
    b[..n].copy_from_slice(&data[..n]);
    let sel = u32::from_le_bytes(b[1..5].try_into().unwrap());
    let w =
        core::array::from_fn(|i| u64::from_le_bytes(b[5 + 8 * i..13 + 8 * i].try_into().unwrap()));
    check::<S>(b[0], sel, &w)
}
