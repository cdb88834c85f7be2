//! Puts memory.x where the linker (cortex-m-rt's link.x) finds it, and bakes the firmware's
//! levels into `OUT_DIR` with the bake `cargo run --example bake` uses (`ballcast-level`):
//! `ramp.rs` (`examples/data/ramp.obj`, 96 triangles) and `arena.rs` (`arena.obj`, 2 168),
//! both I16F16 meshes in flash; and the compact forms of `forms` (`src/forms.rs`): `compact.rs`
//! (the arena as a `CompactMesh`, as `bake --compact` writes it) and `terrain.rs` (a 64 × 64
//! `Heightfield` of the heights `src/forms.rs` computes). A bad level fails the build with the
//! loader's message.
use fixed::types::I16F16;
use std::path::{Path, PathBuf};
use std::{env, fs};

#[path = "src/forms.rs"]
mod forms;

fn main() {
    let out = PathBuf::from(env::var_os("OUT_DIR").unwrap());
    fs::write(out.join("memory.x"), include_bytes!("memory.x")).unwrap();
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=src/forms.rs");
    let load = |name: &str| {
        let path = format!("../examples/data/{name}.obj");
        println!("cargo:rerun-if-changed={path}");
        ballcast_level::load(&path)
    };
    let terrain = ballcast_level::bake_heightfield::<I16F16>(
        Path::new("src/forms.rs"),
        forms::shape(),
        &forms::heights(),
        |_, _| false,
    );
    let baked = [
        (
            "ramp",
            load("ramp").and_then(|l| ballcast_level::bake::<I16F16>(&l)),
        ),
        (
            "arena",
            load("arena").and_then(|l| ballcast_level::bake::<I16F16>(&l)),
        ),
        (
            "compact",
            load("arena").and_then(|l| ballcast_level::bake_compact::<I16F16>(&l)),
        ),
        ("terrain", terrain),
    ];
    for (name, baked) in baked {
        match baked {
            Ok(b) => fs::write(out.join(format!("{name}.rs")), b.source).unwrap(),
            Err(e) => panic!("{e}"),
        }
    }
}
