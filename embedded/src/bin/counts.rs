//! Instruction counts of the face test and the full `cast`, per scalar, on bare metal.
//!
//! For every scalar this runs `StandardTriangle::face_collision` on a fixed set of sweeps against
//! one precomputed triangle in general position. Each measured call goes through an
//! `#[inline(never)]`, unmangled wrapper `face_<scalar>`, called from an unmangled driver
//! `bench_<group>_<scalar>`, so QEMU's per-instruction log (`-singlestep -d exec,nochain`) can
//! attribute every executed instruction between entering `face_*` and returning to the driver,
//! callees such as the soft-float and 128-bit division routines included. `embedded/count.sh`
//! does that and prints the table; this program itself prints what it ran, and fails unless
//! every sweep hit or missed as designed.
//!
//! `cast_<scalar>` wraps `StandardTriangle::cast` the same way, driven by `bench_cast_<scalar>`
//! over the `full` sweeps.
//!
//! Groups: `full` sweeps reach the division and the three edge tests (3 hits, 3 misses outside one
//! edge each); `early` sweeps leave at the height tests (start behind the plane, move away, stop
//! short, stay above).
#![no_std]
#![no_main]

use ballcast::{Hit, Scalar, StandardTriangle, Sweep, Triangle, Vec3};
use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use fixed::types::{I16F16, I32F32};
use panic_semihosting as _;

const RADIUS: f64 = 0.5;

/// The triangle, counter-clockwise from the front; front normal about (-0.15, 0.99, -0.04).
const TRIANGLE: [[f64; 3]; 3] = [[1.0, 0.5, 2.0], [3.0, 1.0, 7.0], [8.0, 1.5, 1.0]];

/// A sweep: barycentric point `q` on the triangle, heights `h0`, `h1` above it along the unit
/// normal, and a drift added to the end point.
type Spec = ([f64; 3], f64, f64, [f64; 3]);

/// 3 hits, then 3 misses just outside the edges opposite v0, v1 and v2 in turn.
const FULL: [Spec; 6] = [
    ([1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0], 3.0, -1.0, [0.0; 3]),
    ([0.6, 0.2, 0.2], 2.0, 0.0, [0.4, 0.0, 0.2]),
    ([0.2, 0.3, 0.5], 5.0, -4.0, [-0.5, 0.0, 0.5]),
    ([-0.3, 0.6, 0.7], 3.0, -1.0, [0.0; 3]),
    ([0.6, -0.3, 0.7], 3.0, -1.0, [0.0; 3]),
    ([0.6, 0.7, -0.3], 3.0, -1.0, [0.0; 3]),
];
const FULL_HITS: u32 = 3;

/// Start behind the plane, move away, stop short, stay above.
const EARLY: [Spec; 4] = [
    ([0.3, 0.3, 0.4], 0.2, -1.0, [0.0; 3]),
    ([0.3, 0.3, 0.4], 1.0, 3.0, [0.0; 3]),
    ([0.3, 0.3, 0.4], 3.0, 1.0, [0.0; 3]),
    ([0.3, 0.3, 0.4], 2.0, 2.0, [1.0, 0.0, 1.0]),
];

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The triangle's front unit normal in `f64`.
fn unit_normal() -> [f64; 3] {
    let [v0, v1, v2] = TRIANGLE;
    let (a, b) = (sub(v1, v0), sub(v2, v0));
    let n = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let len = newton_sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    n.map(|c| c / len)
}

/// A square root by Newton's method, so setup needs no extra crate (its accuracy only sets the
/// sweeps' direction, the same in every scalar).
fn newton_sqrt(x: f64) -> f64 {
    let mut r = x;
    for _ in 0..16 {
        r = 0.5 * (r + x / r);
    }
    r
}

/// A sweep's end points in `f64`, from its spec against [`TRIANGLE`] with unit normal `n`.
fn world(spec: &Spec, n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let [v0, v1, v2] = TRIANGLE;
    let (w, h0, h1, drift) = *spec;
    let mut p0 = [0.0; 3];
    let mut p1 = [0.0; 3];
    for k in 0..3 {
        let q = w[0] * v0[k] + w[1] * v1[k] + w[2] * v2[k];
        p0[k] = q + n[k] * h0;
        p1[k] = q + n[k] * h1 + drift[k];
    }
    (p0, p1)
}

fn sweeps<S: Scalar, const N: usize>(specs: &[Spec; N], n: [f64; 3]) -> [Sweep<S>; N] {
    let v = |p: [f64; 3]| Vec3::new(p[0], p[1], p[2]).map(S::from_f64);
    specs.map(|s| {
        let (p0, p1) = world(&s, n);
        Sweep::new(v(p0), v(p1), S::from_f64(RADIUS)).expect("valid sweep")
    })
}

/// Calls `face` on every sweep; the count of hits.
#[inline(always)]
fn drive<S: Scalar>(
    t: &StandardTriangle<S>,
    sweeps: &[Sweep<S>],
    face: fn(&StandardTriangle<S>, &Sweep<S>) -> Option<Hit<S>>,
) -> u32 {
    let mut hits = 0;
    for s in sweeps {
        if black_box(face(black_box(t), black_box(s))).is_some() {
            hits += 1;
        }
    }
    hits
}

macro_rules! measured {
    ($s:ty, $name:literal, $face:ident, $full:ident, $early:ident, $cast:ident, $full_cast:ident) => {
        /// The measured call: one full `cast` (face, edges, vertices).
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $cast(t: &StandardTriangle<$s>, s: &Sweep<$s>) -> Option<Hit<$s>> {
            t.cast(s)
        }

        /// Driver for `cast` on the `full` group.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $full_cast(t: &StandardTriangle<$s>, sweeps: &[Sweep<$s>]) -> u32 {
            drive(t, sweeps, $cast) + black_box(2) - 2
        }

        /// The measured call: one face test.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $face(t: &StandardTriangle<$s>, s: &Sweep<$s>) -> Option<Hit<$s>> {
            t.face_collision(s)
        }

        // The two drivers differ by a constant only so that the linker cannot merge them.

        /// Driver for the `full` group.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $full(t: &StandardTriangle<$s>, sweeps: &[Sweep<$s>]) -> u32 {
            drive(t, sweeps, $face) + black_box(0)
        }

        /// Driver for the `early` group.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $early(t: &StandardTriangle<$s>, sweeps: &[Sweep<$s>]) -> u32 {
            drive(t, sweeps, $face) + black_box(1) - 1
        }

        impl Measure for $s {
            const NAME: &'static str = $name;
            fn full(t: &StandardTriangle<$s>, sweeps: &[Sweep<$s>]) -> u32 {
                $full(t, sweeps)
            }
            fn early(t: &StandardTriangle<$s>, sweeps: &[Sweep<$s>]) -> u32 {
                $early(t, sweeps)
            }
            fn full_cast(t: &StandardTriangle<$s>, sweeps: &[Sweep<$s>]) -> u32 {
                $full_cast(t, sweeps)
            }
        }
    };
}

trait Measure: Scalar {
    const NAME: &'static str;
    fn full(t: &StandardTriangle<Self>, sweeps: &[Sweep<Self>]) -> u32;
    fn early(t: &StandardTriangle<Self>, sweeps: &[Sweep<Self>]) -> u32;
    fn full_cast(t: &StandardTriangle<Self>, sweeps: &[Sweep<Self>]) -> u32;
}

measured!(
    f32,
    "f32",
    face_f32,
    bench_full_f32,
    bench_early_f32,
    cast_f32,
    bench_cast_f32
);
measured!(
    f64,
    "f64",
    face_f64,
    bench_full_f64,
    bench_early_f64,
    cast_f64,
    bench_cast_f64
);
measured!(
    I16F16,
    "I16F16",
    face_i16f16,
    bench_full_i16f16,
    bench_early_i16f16,
    cast_i16f16,
    bench_cast_i16f16
);
measured!(
    I32F32,
    "I32F32",
    face_i32f32,
    bench_full_i32f32,
    bench_early_i32f32,
    cast_i32f32,
    bench_cast_i32f32
);

/// Runs both groups in `S`; false if any sweep did not hit or miss as designed.
fn measure<S: Measure>() -> bool {
    let [a, b, c] = TRIANGLE.map(|p| Vec3::new(p[0], p[1], p[2]).map(S::from_f64));
    let t = StandardTriangle::new(&Triangle::new(a, b, c)).expect("valid triangle");
    let n = unit_normal();
    let (full, early) = (sweeps::<S, 6>(&FULL, n), sweeps::<S, 4>(&EARLY, n));
    let full_hits = S::full(&t, &full);
    let early_hits = S::early(&t, &early);
    // `cast` also catches the balls beside the edges: more hits than the face test, never fewer.
    let cast_hits = S::full_cast(&t, &full);
    hprintln!(
        "{} full {} calls {} hits; early {} calls {} hits",
        S::NAME,
        full.len(),
        full_hits,
        early.len(),
        early_hits
    );
    hprintln!("{} cast {} calls {} hits", S::NAME, full.len(), cast_hits);
    full_hits == FULL_HITS && early_hits == 0 && cast_hits >= FULL_HITS
}

#[entry]
fn main() -> ! {
    let ok = measure::<f32>() & measure::<f64>() & measure::<I16F16>() & measure::<I32F32>();
    if !ok {
        hprintln!("error: a sweep did not hit or miss as designed");
    }
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {
        cortex_m::asm::wfi();
    }
}
