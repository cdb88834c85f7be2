//! Bakes the firmware's levels (`examples/data/ramp.obj` in every scalar, and in `f32` with
//! leaves of four too; `arena.obj` in I16F16), their compact forms (the ramp in `f32`, the arena
//! in I16F16) and the `hills.png` heightmap (I16F16 and `f32`) into `OUT_DIR` with this crate's
//! own bake, so `tests/baked.rs` can compile the statics and check them against the run-time
//! build.

use std::path::{Path, PathBuf};

#[allow(dead_code, unused_imports)]
#[path = "src/lib.rs"]
mod level;

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("../data");
    println!("cargo::rerun-if-changed=src");
    let load = |name: &str| {
        let path = data.join(name);
        println!("cargo::rerun-if-changed={}", path.display());
        level::load(&path).unwrap_or_else(|e| panic!("{e}"))
    };
    let write = |name: &str, baked: Result<level::Baked, level::LevelError>| {
        let baked = baked.unwrap_or_else(|e| panic!("{e}"));
        std::fs::write(out.join(name), baked.source).expect("OUT_DIR is writable");
    };
    let ramp = load("ramp.obj");
    write("ramp_f32.rs", level::bake::<f32>(&ramp));
    let four = ballcast::bvh::LeafSize::Four;
    write("ramp_f32_four.rs", level::bake_with::<f32>(&ramp, four));
    write("ramp_f64.rs", level::bake::<f64>(&ramp));
    write("ramp_i16f16.rs", level::bake::<fixed::types::I16F16>(&ramp));
    write("ramp_i32f32.rs", level::bake::<fixed::types::I32F32>(&ramp));
    let arena = load("arena.obj");
    write(
        "arena_i16f16.rs",
        level::bake::<fixed::types::I16F16>(&arena),
    );
    write("ramp_compact_f32.rs", level::bake_compact::<f32>(&ramp));
    write(
        "arena_compact_i16f16.rs",
        level::bake_compact::<fixed::types::I16F16>(&arena),
    );
    let path = data.join("hills.png");
    println!("cargo::rerun-if-changed={}", path.display());
    let hills = level::load_heightmap(&path).unwrap_or_else(|e| panic!("{e}"));
    let placement = level::Placement {
        origin: [-8.0, -1.0, -8.0],
        spacing: 0.5,
        height: 4.0,
    };
    write(
        "hills_i16f16.rs",
        hills.bake::<fixed::types::I16F16>(&placement),
    );
    write("hills_f32.rs", hills.bake::<f32>(&placement));
}
