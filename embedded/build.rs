//! Puts memory.x where the linker (cortex-m-rt's link.x) finds it, and bakes the firmware's
//! levels into `OUT_DIR` with the bake `cargo run --example bake` uses (`ballcast-level`):
//! `ramp.rs` (`examples/data/ramp.obj`, 96 triangles) and `arena.rs` (`arena.obj`, 2 168),
//! both I16F16 meshes in flash. A bad level fails the build with the loader's message.
use fixed::types::I16F16;
use std::{env, fs, path::PathBuf};

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    fs::write(out.join("memory.x"), include_bytes!("memory.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
    for name in ["ramp", "arena"] {
        let path = format!("../examples/data/{name}.obj");
        println!("cargo:rerun-if-changed={path}");
        let baked = ballcast_level::load(&path).and_then(|l| ballcast_level::bake::<I16F16>(&l));
        match baked {
            Ok(b) => fs::write(out.join(format!("{name}.rs")), b.source).unwrap(),
            Err(e) => panic!("{e}"),
        }
    }
}
