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
//! (their count, the first eight indices, and where the first three are in the file: an OBJ
//! face's line, a glTF node, mesh and primitive), the form's sizes, bytes in flash, and the
//! precision planner's verdict at the level's extent for a ball of radius R (default 0.5);
//! for a mesh, the bytes of the other scalars too, and before it a warning where more
//! one-sided triangles face down than up (a level exported with the other winding) or where
//! most face along z (a level exported +Z up). A bad file or a level outside the scalar's
//! range gets a message naming the file and the problem (a triangle by its index and its place
//! in the file), a non-zero exit status and no output on stdout.

use ballcast::Scalar;
use ballcast::bvh::LeafSize;
use ballcast::plan::{Memory, ScalarType};
use ballcast_level::{
    Baked, Emit, Heightmap, Level, LevelError, Placement, bake_compact, bake_heightfield,
    bake_with, load, load_heightmap, verdicts,
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
    let options = match parse(std::env::args().skip(1)) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("bake: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    let done = if options.heightmap() {
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

impl Options {
    /// Whether the file is a heightmap (`.png`), not a mesh level.
    fn heightmap(&self) -> bool {
        self.path.to_ascii_lowercase().ends_with(".png")
    }
}

/// The options, or what makes no sense in the command line.
fn parse(args: impl Iterator<Item = String>) -> Result<Options, String> {
    // `--flag=value` as `--flag value` (a value may start with a minus sign either way).
    let mut args = args.flat_map(|a| match a.split_once('=') {
        Some((flag, value)) if flag.starts_with("--") => vec![flag.to_string(), value.to_string()],
        _ => vec![a],
    });
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
    // Any number f64 reads, NaN and infinities included: the bake says what is wrong with it.
    let number = |flag: &str, a: Option<String>| {
        let a = a.ok_or_else(|| format!("{flag} needs a value"))?;
        a.parse::<f64>()
            .map_err(|_| format!("{flag} needs a number, not {a:?}"))
    };
    let (mut mesh_only, mut map_only) = (None, None);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--scalar" => o.scalar = args.next().ok_or("--scalar needs a value")?,
            "--radius" => {
                o.radius = number(&a, args.next())?;
                if !(o.radius >= 0.0 && o.radius.is_finite()) {
                    return Err(format!(
                        "--radius must be finite and not negative, not {}",
                        o.radius
                    ));
                }
            }
            "--two-sided" | "--compact" | "--leaves" => {
                o.two_sided |= a == "--two-sided";
                o.compact |= a == "--compact";
                if a == "--leaves" {
                    o.leaves = match args.next().as_deref() {
                        Some("2") => LeafSize::Two,
                        Some("4") => LeafSize::Four,
                        other => return Err(format!("--leaves takes 2 or 4, not {other:?}")),
                    };
                }
                mesh_only = Some(a);
            }
            "--spacing" | "--height" => {
                let v = number(&a, args.next())?;
                if a == "--spacing" {
                    o.spacing = v;
                } else {
                    o.height = Some(v);
                }
                map_only = Some(a);
            }
            "--origin" => {
                let xyz = args.next().ok_or("--origin needs a value")?;
                let parts = xyz
                    .split(',')
                    .map(|c| number(&a, Some(c.into())))
                    .collect::<Result<Vec<_>, _>>()?;
                o.origin = parts
                    .try_into()
                    .map_err(|_| format!("--origin takes X,Y,Z, not {xyz:?}"))?;
                map_only = Some(a);
            }
            _ if a.starts_with("--") => return Err(format!("unknown option {a}")),
            _ if o.path.is_empty() => o.path = a,
            _ => return Err(format!("one level at a time: {} and {a}", o.path)),
        }
    }
    o.scalar.make_ascii_lowercase();
    if o.path.is_empty() {
        return Err("no level given".into());
    }
    match (o.heightmap(), mesh_only, map_only) {
        (true, Some(flag), _) => Err(format!("{flag} applies to mesh levels, not heightmaps")),
        (false, _, Some(flag)) => Err(format!(
            "{flag} applies to heightmaps (.png), not mesh levels"
        )),
        _ => Ok(o),
    }
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
    if level.looks_z_up() {
        eprintln!(
            "{}: warning: few one-sided triangles face up or down along y and many along z, \
             so this level was likely exported +Z up, and its floors are walls to a character \
             walking on +Y: export it +Y up, or give Character::with_slope the level's up \
             (and gravity along it)",
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
        let (shape, heights) = m.grid::<S>(p)?;
        let columns = m.columns as usize;
        let hole = |i: u32, k: u32| m.holes[k as usize * columns + i as usize];
        let baked = bake_heightfield(&m.path, shape, &heights, hole)?;
        Ok((baked, shape.unit.to_f64()))
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
