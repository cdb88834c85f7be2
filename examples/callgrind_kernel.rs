//! The measured loops of `scripts/callgrind.sh`: `face_collision`, `cast` and a 256-triangle
//! scene's `cast`, per scalar, on the inputs of `benches/cast.rs` (one triangle in general
//! position and 64 sweeps down through it; the tiled 16 × 8 × 16 room and 64 short moves inside
//! it, radius 0.5).
//!
//! Each loop is an `#[inline(never)]`, unmangled function `ck_<function>_<scalar>` that makes
//! exactly `n` calls (cycling through the 64 sweeps), so callgrind's `--toggle-collect` counts
//! those calls and nothing of the set-up; the loop's own bookkeeping (a few instructions per
//! call) is included.
//!
//! Run: `callgrind_kernel <face|cast|scene> <f32|f64|I32F32|I16F16> <n>` (n a multiple of 64);
//! it prints `calls <n> hits <h>`.

use ballcast::{Scalar, Scene, StandardTriangle, Sweep, Triangle, Vec3};
use fixed::types::{I16F16, I32F32};
use std::hint::black_box;

const SWEEPS: usize = 64;
type P = [f64; 3];
type Path = (P, P, f64);

/// The generator of `benches/cast.rs` (xorshift64), same seeds, so the inputs are the same.
struct Rng(u64);
impl Rng {
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        lo + (hi - lo) * (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

const TRIANGLE: [P; 3] = [[0.3, 0.2, 0.1], [1.0, 0.4, 6.5], [7.0, -0.3, 0.5]];

fn single_sweeps() -> Vec<Path> {
    let mut g = Rng(0x9E37_79B9_7F4A_7C15);
    (0..SWEEPS)
        .map(|_| {
            let p0 = [g.range(-2.0, 8.0), g.range(1.0, 6.0), g.range(-2.0, 8.0)];
            let p1 = [g.range(-2.0, 8.0), g.range(-4.0, 1.0), g.range(-2.0, 8.0)];
            (p0, p1, g.range(0.1, 1.0))
        })
        .collect()
}

fn room(n: usize) -> (Vec<[P; 3]>, Vec<Path>) {
    let per_side = (n as f64 / 12.0).sqrt().ceil() as usize;
    let mut tris = Vec::new();
    let mut quad = |o: P, a: P, b: P| {
        let k = per_side as f64;
        let at = |i: usize, j: usize| {
            [0, 1, 2].map(|c| o[c] + a[c] * i as f64 / k + b[c] * j as f64 / k)
        };
        for i in 0..per_side {
            for j in 0..per_side {
                tris.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                tris.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
    };
    let (w, h) = (16.0, 8.0);
    quad([0.0; 3], [0.0, 0.0, w], [w, 0.0, 0.0]);
    quad([0.0, h, 0.0], [w, 0.0, 0.0], [0.0, 0.0, w]);
    quad([0.0; 3], [w, 0.0, 0.0], [0.0, h, 0.0]);
    quad([0.0, 0.0, w], [0.0, h, 0.0], [w, 0.0, 0.0]);
    quad([0.0; 3], [0.0, h, 0.0], [0.0, 0.0, w]);
    quad([w, 0.0, 0.0], [0.0, 0.0, w], [0.0, h, 0.0]);
    tris.truncate(n);
    let mut g = Rng(0x5EED);
    let sweeps = (0..SWEEPS)
        .map(|_| {
            let p0 = [
                g.range(1.0, w - 1.0),
                g.range(1.0, h - 1.0),
                g.range(1.0, w - 1.0),
            ];
            let d = [g.range(-1.5, 1.5), g.range(-1.5, 1.5), g.range(-1.5, 1.5)];
            (p0, [p0[0] + d[0], p0[1] + d[1], p0[2] + d[2]], 0.5)
        })
        .collect();
    (tris, sweeps)
}

fn v<S: Scalar>(p: P) -> Vec3<S> {
    Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]))
}

fn sweeps<S: Scalar>(raw: &[Path]) -> Vec<Sweep<S>> {
    raw.iter()
        .map(|&(a, b, r)| Sweep::new(v(a), v(b), S::from_f64(r)).unwrap())
        .collect()
}

fn tri<S: Scalar>(t: [P; 3]) -> Triangle<S> {
    Triangle::new(v(t[0]), v(t[1]), v(t[2]))
}

macro_rules! kernels {
    ($($s:ty => $face:ident, $cast:ident, $scene:ident, $run:ident);*) => {$(
        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $face(st: &StandardTriangle<$s>, sw: &[Sweep<$s>], n: usize) -> usize {
            let mut hits = 0;
            for _ in 0..n / sw.len() {
                for s in sw {
                    hits += black_box(st).face_collision(black_box(s)).is_some() as usize;
                }
            }
            hits
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $cast(st: &StandardTriangle<$s>, sw: &[Sweep<$s>], n: usize) -> usize {
            let mut hits = 0;
            for _ in 0..n / sw.len() {
                for s in sw {
                    hits += black_box(st).cast(black_box(s)).is_some() as usize;
                }
            }
            hits
        }

        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $scene(scene: &Scene<$s, 256>, sw: &[Sweep<$s>], n: usize) -> usize {
            let mut hits = 0;
            for _ in 0..n / sw.len() {
                for s in sw {
                    hits += black_box(scene).cast(black_box(s)).is_some() as usize;
                }
            }
            hits
        }

        #[allow(non_snake_case)]
        fn $run(function: &str, n: usize) -> usize {
            match function {
                "face" | "cast" => {
                    let st = StandardTriangle::new(&tri::<$s>(TRIANGLE)).unwrap();
                    let sw = sweeps::<$s>(&single_sweeps());
                    if function == "face" {
                        $face(black_box(&st), black_box(&sw), n)
                    } else {
                        $cast(black_box(&st), black_box(&sw), n)
                    }
                }
                "scene" => {
                    let (tris, raw) = room(256);
                    let mut scene: Box<Scene<$s, 256>> = Box::new(Scene::new());
                    for t in &tris {
                        scene.push(tri(*t)).unwrap();
                    }
                    let sw = sweeps::<$s>(&raw);
                    $scene(black_box(&scene), black_box(&sw), n)
                }
                _ => panic!("unknown function {function}: face, cast or scene"),
            }
        }
    )*};
}

kernels!(
    f32 => ck_face_f32, ck_cast_f32, ck_scene_f32, run_f32;
    f64 => ck_face_f64, ck_cast_f64, ck_scene_f64, run_f64;
    I32F32 => ck_face_I32F32, ck_cast_I32F32, ck_scene_I32F32, run_I32F32;
    I16F16 => ck_face_I16F16, ck_cast_I16F16, ck_scene_I16F16, run_I16F16
);

fn main() {
    let args: Vec<String> = std::env::args().collect();
    assert!(
        args.len() == 4,
        "usage: callgrind_kernel <face|cast|scene> <f32|f64|I32F32|I16F16> <n>"
    );
    let n: usize = args[3].parse().expect("n");
    assert!(n.is_multiple_of(SWEEPS), "n must be a multiple of {SWEEPS}");
    let hits = match args[2].as_str() {
        "f32" => run_f32(&args[1], n),
        "f64" => run_f64(&args[1], n),
        "I32F32" => run_I32F32(&args[1], n),
        "I16F16" => run_I16F16(&args[1], n),
        s => panic!("unknown scalar {s}"),
    };
    println!("calls {n} hits {hits}");
}
