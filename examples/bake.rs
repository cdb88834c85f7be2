//! Bakes a level into Rust source for `static` data in flash, built through `const`
//! constructors, so firmware does no work at start-up: a Wavefront OBJ, glTF 2.0 or GLB level
//! as a prepared [`ballcast::Mesh`] (the fastest form) or a [`ballcast::CompactMesh`] (shared
//! vertices, about a fifth of the flash), or a grey PNG heightmap as a
//! [`ballcast::Heightfield`] (about 1.5 bytes a triangle).
//!
//! Run: `cargo run --release --example bake -- LEVEL [--scalar f32|f64|i16f16|i32f32]
//! [--radius R] [--two-sided] [--leaves 2|4] [--compact]`, or for a heightmap
//! `cargo run --release --example bake -- MAP.png --height H [--spacing S] [--origin X,Y,Z]
//! [--scalar ...] [--radius R]`
//!
//! Triangles of a glTF material marked `doubleSided` are baked two-sided (they stop balls from
//! both sides); `--two-sided` makes every triangle so (an OBJ file has no such mark).
//! `--leaves 4` builds the tree with leaves of up to four triangles: 3.6 bytes per triangle
//! less flash, queries that test more triangles (verify the statics with
//! `Degenerates::Skip.with_leaf_size(LeafSize::Four)`). `--compact` writes a compact mesh
//! (always leaves of four; `u16` indices up to 65 536 vertices and triangles).
//!
//! A heightmap's pixel `(x, y)` is grid vertex `(x, y)` at `origin + (x S, h, y S)`, where a
//! black pixel's `h` is 0 and a white one's `H` (cells of side `S`, default 1; origin default
//! 0,0,0); a fully transparent pixel cuts a hole in the cells around it.
//!
//! Writes the source to stdout (`include!` it in a module; `MESH` is the mesh, `HEIGHTFIELD`
//! the heightfield) and one line of statistics to stderr: triangles, degenerate ones skipped
//! (by index), the form's sizes, bytes in flash, and the precision planner's verdict at the
//! level's extent for a ball of radius R (default 0.5); for a mesh, the bytes of the other
//! scalars too, and before it a warning where more one-sided triangles face down than up (a
//! level exported with the other winding). A bad file or a level outside the scalar's range
//! gets a message naming the file and the problem, a non-zero exit status and no output on
//! stdout.

use ballcast::Scalar;
use ballcast::bvh::LeafSize;
use ballcast::plan::{Memory, ScalarType};
use ballcast_level::{
    Baked, Emit, Heightmap, Level, LevelError, Placement, bake_compact, bake_with, load,
    load_heightmap, verdicts,
};
use fixed::types::{I16F16, I32F32};
use std::process::ExitCode;

const USAGE: &str = "usage: bake LEVEL.obj|.gltf|.glb [--scalar f32|f64|i16f16|i32f32 (default i16f16)] [--radius R] [--two-sided] [--leaves 2|4 (default 2)] [--compact]\n       bake MAP.png --height H [--spacing S (default 1)] [--origin X,Y,Z (default 0,0,0)] [--scalar ...] [--radius R]";

/// What the command line asks for.
struct Options {
    path: String,
    scalar: String,
    radius: f64,
    two_sided: bool,
    leaves: LeafSize,
    compact: bool,
    spacing: f64,
    height: Option<f64>,
    origin: [f64; 3],
}

fn main() -> ExitCode {
    let Some(options) = parse(std::env::args().skip(1)) else {
        eprintln!("{USAGE}");
        return ExitCode::from(2);
    };
    let heightmap = options.path.to_ascii_lowercase().ends_with(".png");
    let done = if heightmap {
        run_heightmap(&options)
    } else {
        run(&options)
    };
    match done {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bake: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The options, or `None` for a command line that makes no sense.
fn parse(mut args: impl Iterator<Item = String>) -> Option<Options> {
    let mut o = Options {
        path: String::new(),
        scalar: "i16f16".into(),
        radius: 0.5,
        two_sided: false,
        leaves: LeafSize::Two,
        compact: false,
        spacing: 1.0,
        height: None,
        origin: [0.0; 3],
    };
    let number = |a: Option<String>| a?.parse::<f64>().ok().filter(|x| x.is_finite());
    while let Some(a) = args.next() {
        match a.as_str() {
            "--scalar" => o.scalar = args.next()?.to_ascii_lowercase(),
            "--radius" => o.radius = number(args.next()).filter(|&r| r >= 0.0)?,
            "--two-sided" => o.two_sided = true,
            "--compact" => o.compact = true,
            "--leaves" => {
                o.leaves = match args.next()?.as_str() {
                    "2" => LeafSize::Two,
                    "4" => LeafSize::Four,
                    _ => return None,
                }
            }
            "--spacing" => o.spacing = number(args.next())?,
            "--height" => o.height = Some(number(args.next())?),
            "--origin" => {
                let xyz = args.next()?;
                let parts: Vec<f64> = xyz
                    .split(',')
                    .map(|c| number(Some(c.into())))
                    .collect::<Option<_>>()?;
                o.origin = parts.try_into().ok()?;
            }
            _ if o.path.is_empty() && !a.starts_with("--") => o.path = a,
            _ => return None,
        }
    }
    (!o.path.is_empty()).then_some(o)
}

/// The level in scalar `S`, in the form the options ask for.
fn form<S: Scalar + Emit>(level: &Level, o: &Options) -> Result<Baked, LevelError> {
    if o.compact {
        bake_compact::<S>(level)
    } else {
        bake_with::<S>(level, o.leaves)
    }
}

/// Bakes a mesh level (OBJ, glTF, GLB).
fn run(o: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let mut level = load(&o.path)?;
    if o.two_sided {
        level.two_sided = vec![true; level.triangles.len()];
    }
    let all: [(&str, Result<Baked, LevelError>); 4] = [
        ("f32", form::<f32>(&level, o)),
        ("f64", form::<f64>(&level, o)),
        ("i16f16", form::<I16F16>(&level, o)),
        ("i32f32", form::<I32F32>(&level, o)),
    ];
    let chosen = all
        .iter()
        .position(|(name, _)| *name == o.scalar)
        .ok_or_else(|| format!("unknown scalar {:?}\n{USAGE}", o.scalar))?;
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
    let other = if o.compact {
        String::new()
    } else {
        format!(
            "; as a compact mesh ({} vertices): {}",
            vertices.len(),
            compact.join(", ")
        )
    };
    eprintln!(
        "{}: {}; bytes in flash: {}{other}; {}",
        level.path.display(),
        baked.stats,
        sizes.join(", "),
        verdicts(baked.stats.extent, o.radius)
    );
    Ok(())
}

/// Bakes a heightmap (PNG).
fn run_heightmap(o: &Options) -> Result<(), Box<dyn std::error::Error>> {
    let Some(height) = o.height else {
        return Err(format!(
            "{}: a heightmap needs --height, the height of white above black\n{USAGE}",
            o.path
        )
        .into());
    };
    let map = load_heightmap(&o.path)?;
    let placement = Placement {
        origin: o.origin,
        spacing: o.spacing,
        height,
    };
    // The baked source and the height step as the scalar holds it.
    fn field<S: Scalar + Emit>(m: &Heightmap, p: &Placement) -> Result<(Baked, f64), LevelError> {
        Ok((m.bake::<S>(p)?, m.grid::<S>(p)?.0.unit.to_f64()))
    }
    let (baked, unit) = match o.scalar.as_str() {
        "f32" => field::<f32>(&map, &placement)?,
        "f64" => field::<f64>(&map, &placement)?,
        "i16f16" => field::<I16F16>(&map, &placement)?,
        "i32f32" => field::<I32F32>(&map, &placement)?,
        s => return Err(format!("unknown scalar {s:?}\n{USAGE}").into()),
    };
    print!("{}", baked.source);
    eprintln!(
        "{}: {}; height step {unit:e}; {}",
        o.path,
        baked.stats,
        verdicts(baked.stats.extent, o.radius)
    );
    Ok(())
}
