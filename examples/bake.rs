//! Bakes a level (Wavefront OBJ, glTF 2.0 or GLB) into Rust source for a `static` prepared
//! [`ballcast::Mesh`]: the tree's nodes, the prepared triangles and their order, built through
//! `const` constructors, so firmware keeps the level in flash and does no work at start-up.
//!
//! Run: `cargo run --release --example bake -- LEVEL [--scalar f32|f64|i16f16|i32f32] [--radius R]
//! [--two-sided] [--leaves 2|4]`
//!
//! Triangles of a glTF material marked `doubleSided` are baked two-sided (they stop balls from
//! both sides); `--two-sided` makes every triangle so (an OBJ file has no such mark).
//! `--leaves 4` builds the tree with leaves of up to four triangles: 3.6 bytes per triangle
//! less flash, queries that test more triangles (verify the statics with
//! `Degenerates::Skip.with_leaf_size(LeafSize::Four)`).
//!
//! Writes the source to stdout (`include!` it in a module; `MESH` is the mesh) and one line of
//! statistics to stderr: triangles, degenerate ones skipped (by index), nodes, bytes in flash
//! for every scalar, and the precision planner's verdict at the level's extent for a ball of
//! radius R (default 0.5); before it, a warning where more one-sided triangles face down than
//! up (a level exported with the other winding). A bad file or a level outside the scalar's
//! range gets a message naming the file and the problem, a non-zero exit status and no output
//! on stdout.

use ballcast::bvh::LeafSize;
use ballcast::plan::{Memory, ScalarType};
use ballcast_level::{Baked, LevelError, bake_with, load, verdicts};
use fixed::types::{I16F16, I32F32};
use std::process::ExitCode;

const USAGE: &str = "usage: bake LEVEL [--scalar f32|f64|i16f16|i32f32 (default i16f16)] [--radius R] [--two-sided] [--leaves 2|4 (default 2)]";

fn usage() -> ExitCode {
    eprintln!("{USAGE}");
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let mut args = std::env::args().skip(1);
    let (mut path, mut scalar, mut radius) = (None, "i16f16".to_string(), 0.5);
    let (mut two_sided, mut leaves) = (false, LeafSize::Two);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--scalar" => match args.next() {
                Some(s) => scalar = s.to_ascii_lowercase(),
                None => return usage(),
            },
            "--radius" => match args.next().and_then(|r| r.parse::<f64>().ok()) {
                Some(r) if r >= 0.0 => radius = r,
                _ => return usage(),
            },
            "--two-sided" => two_sided = true,
            "--leaves" => match args.next().as_deref() {
                Some("2") => leaves = LeafSize::Two,
                Some("4") => leaves = LeafSize::Four,
                _ => return usage(),
            },
            _ if path.is_none() && !a.starts_with("--") => path = Some(a),
            _ => return usage(),
        }
    }
    let Some(path) = path else {
        return usage();
    };
    match run(&path, &scalar, radius, two_sided, leaves) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bake: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(
    path: &str,
    scalar: &str,
    radius: f64,
    two_sided: bool,
    leaves: LeafSize,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut level = load(path)?;
    if two_sided {
        level.two_sided = vec![true; level.triangles.len()];
    }
    let all: [(&str, Result<Baked, LevelError>); 4] = [
        ("f32", bake_with::<f32>(&level, leaves)),
        ("f64", bake_with::<f64>(&level, leaves)),
        ("i16f16", bake_with::<I16F16>(&level, leaves)),
        ("i32f32", bake_with::<I32F32>(&level, leaves)),
    ];
    let chosen = all
        .iter()
        .position(|(name, _)| *name == scalar)
        .ok_or_else(|| format!("unknown scalar {scalar:?}\n{USAGE}"))?;
    let baked = match &all[chosen].1 {
        Ok(b) => b.clone(),
        Err(e) => return Err(e.to_string().into()),
    };
    let sizes: Vec<String> = all
        .iter()
        .map(|(name, b)| match b {
            Ok(b) => format!(
                "{name} {} ({:.1}/triangle)",
                b.stats.bytes,
                b.stats.per_triangle()
            ),
            Err(_) => format!("{name} out of range"),
        })
        .collect();
    // The planner's memory figures for the compact form, over the level's distinct vertices.
    let vertices: std::collections::HashSet<[u64; 3]> = level
        .triangles
        .iter()
        .flatten()
        .map(|p| p.map(f64::to_bits))
        .collect();
    let compact: Vec<String> = ScalarType::ALL
        .iter()
        .map(|&s| {
            let kept = baked.stats.triangles - baked.stats.skipped.len();
            let m = Memory::of(s, kept, vertices.len());
            format!("{s} {}", m.compact)
        })
        .collect();
    print!("{}", baked.source);
    let (up, down) = level.facing();
    if down > up {
        eprintln!(
            "{}: warning: {down} one-sided triangles face down and {up} up; floors face up, so \
             this level was likely exported with the other winding (a ball falls through a \
             floor it meets from behind): flip the faces, or bake with --two-sided",
            level.path.display()
        );
    }
    eprintln!(
        "{}: {}; bytes in flash: {}; as a compact mesh ({} vertices): {}; {}",
        level.path.display(),
        baked.stats,
        sizes.join(", "),
        vertices.len(),
        compact.join(", "),
        verdicts(baked.stats.extent, radius)
    );
    Ok(())
}
