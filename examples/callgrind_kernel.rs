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
//! Run: `callgrind_kernel <face|cast|face_near|cast_near|scene|prepare> <f32|f64|I32F32|I16F16> <n>`
//! (n a multiple of 64; `_near`: the same loops on the sweeps near a triangle, `near_sweeps`;
//! `prepare`: `StandardTriangle::new` on 256 triangles of a terrain (`terrain`), n a multiple of 256); it
//! prints `calls <n> hits <h>` (for `prepare`, `hits` counts triangles accepted).

use ballcast::{Scene, StandardTriangle, Sweep, Triangle};
use fixed::types::{I16F16, I32F32};
use std::hint::black_box;

#[path = "../benches/inputs/mod.rs"]
mod inputs;

use inputs::*;

macro_rules! kernels {
    ($($s:ty => $face:ident, $cast:ident, $scene:ident, $prepare:ident, $run:ident);*) => {$(
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

        #[inline(never)]
        #[unsafe(no_mangle)]
        #[allow(non_snake_case)]
        pub fn $prepare(tris: &[Triangle<$s>], n: usize) -> usize {
            let mut ok = 0;
            for _ in 0..n / tris.len() {
                for t in tris {
                    ok += StandardTriangle::new(black_box(t)).is_ok() as usize;
                }
            }
            ok
        }

        #[allow(non_snake_case)]
        fn $run(function: &str, n: usize) -> usize {
            match function {
                "face" | "cast" | "face_near" | "cast_near" => {
                    let st = StandardTriangle::new(&tri::<$s>(TRIANGLE)).unwrap();
                    let near = function.ends_with("_near");
                    let sw = sweeps::<$s>(&if near { near_sweeps() } else { single_sweeps() });
                    if function.starts_with("face") {
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
                "prepare" => {
                    let tris: Vec<Triangle<$s>> = terrain(256).iter().map(|t| tri(*t)).collect();
                    $prepare(black_box(&tris), n)
                }
                _ => panic!("unknown function {function}: face, cast, face_near, cast_near, scene or prepare"),
            }
        }
    )*};
}

kernels!(
    f32 => ck_face_f32, ck_cast_f32, ck_scene_f32, ck_prepare_f32, run_f32;
    f64 => ck_face_f64, ck_cast_f64, ck_scene_f64, ck_prepare_f64, run_f64;
    I32F32 => ck_face_I32F32, ck_cast_I32F32, ck_scene_I32F32, ck_prepare_I32F32, run_I32F32;
    I16F16 => ck_face_I16F16, ck_cast_I16F16, ck_scene_I16F16, ck_prepare_I16F16, run_I16F16
);

fn main() {
    let args: Vec<String> = std::env::args().collect();
    assert!(
        args.len() == 4,
        "usage: callgrind_kernel <face|cast|face_near|cast_near|scene|prepare> <f32|f64|I32F32|I16F16> <n>"
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
