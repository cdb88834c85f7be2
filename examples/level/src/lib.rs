//! Levels from modelling tools for ballcast: loads Wavefront OBJ ([`tobj`]) and glTF 2.0 / GLB
//! ([`gltf`]) files into plain triangles, and bakes them into Rust source for a `static`
//! [`ballcast::Mesh`] (nodes, prepared triangles and order through the crate's `const`
//! constructors) or [`ballcast::CompactMesh`] ([`bake_compact`]); loads grey PNG heightmaps
//! ([`png`]) and bakes them, or heights of the caller's own, for a `static`
//! [`ballcast::Heightfield`] ([`load_heightmap`], [`bake_heightfield`]). Firmware keeps a level
//! in flash and does no work at start-up.
//!
//! Shared by `cargo run --release --example bake -- LEVEL` and the firmware's build script.
//!
//! Winding: both formats, like ballcast, take counter-clockwise vertices (seen from the front)
//! as the front face; the loader keeps the order (and reverses it under a mirroring glTF node
//! transform, as the glTF specification asks), so a ball stops on the side the normals face.
//!
//! Up axis: coordinates are kept as the file holds them. glTF is +Y up by its specification;
//! OBJ names none, and some tools write +Z up. ballcast's `Character` walks on +Y unless
//! `Character::with_slope(up, ..)` is given another up (with gravity along it), or rotate the
//! level on export; [`Level::facing`] counts floors along ±Y.
//!
//! OBJ: positions and faces (polylines and points ignored); a face of four or more corners is
//! split as the fan from its first corner where that covers it (every convex polygon, quads
//! included), ear-clipped in its plane where it is concave, and refused at its line where its
//! edges cross. A `#` comment after data and `\` continuations are refused at their line.
//!
//! glTF: triangle, strip and fan primitives with float positions; `KHR_mesh_quantization`,
//! Draco and meshopt compression and sparse accessors are refused; skins and morph targets
//! are ignored (the bind pose is loaded).
//!
//! Every failure is a [`LevelError`] naming the file and the problem, and where it names a
//! triangle by its index in the level, where that triangle came from in the file
//! ([`Origin`]: an OBJ face's line, a glTF node, mesh and primitive); nothing is printed and
//! nothing panics on a malformed file.

mod bake;
mod compact;
mod gltf_file;
mod heightmap;
mod obj;
mod origin;
mod polygon;
mod source;
mod stats;

pub use bake::{Baked, Emit, bake, bake_with, triangles};
pub use compact::bake_compact;
pub use heightmap::{Heightmap, MAX_PIXELS, Placement, bake_heightfield, load_heightmap};
pub use origin::{Origin, Origins};
pub use stats::{Form, PLACES_SHOWN, Stats, verdicts};

use std::fmt;
use std::path::{Path, PathBuf};

/// A triangle as three points, counter-clockwise seen from its front.
pub type Tri = [[f64; 3]; 3];

/// A loaded level: its triangles in file order (OBJ: model by model, face by face; glTF: node
/// by node depth first in the default scene, primitive by primitive).
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// The file it came from.
    pub path: PathBuf,
    /// The triangles, in world coordinates (glTF node transforms applied).
    pub triangles: Vec<Tri>,
    /// Per triangle, whether it is two-sided (stops balls from both sides): a glTF material's
    /// `doubleSided`; never for OBJ, which has no such notion. A triangle without an entry is
    /// one-sided.
    pub two_sided: Vec<bool>,
    /// Where each triangle came from in the file, for messages a level designer can follow
    /// back to the modelling tool; read through [`origin`](Self::origin). Only while they are
    /// one a triangle: add or remove triangles without them and no triangle has a place
    /// (rather than a wrong one); `Origins::default()` knows none.
    pub origins: Origins,
}

impl Level {
    /// Whether triangle `index` is two-sided (see [`two_sided`](Self::two_sided)).
    pub fn is_two_sided(&self, index: usize) -> bool {
        self.two_sided.get(index).copied().unwrap_or(false)
    }

    /// Where triangle `index` came from in the file: an OBJ face's line (and which triangle of
    /// its polygon), a glTF node, mesh, primitive and triangle. `None` past the end, or where
    /// [`origins`](Self::origins) are not one a triangle.
    pub fn origin(&self, index: usize) -> Option<Origin> {
        if self.origins.len() != self.triangles.len() {
            return None;
        }
        self.origins.get(index)
    }

    /// How many one-sided triangles face up (their front normal within 60° of +y) and how many
    /// face down (within 60° of -y): a level's floors face up, so a level where more face down
    /// was most likely exported with the other winding, and balls fall through its floors.
    pub fn facing(&self) -> (usize, usize) {
        self.facing_along(1)
    }

    /// Whether the level looks exported +Z up: more than four times as many one-sided
    /// triangles face ±z (within 60°) as face ±y. Its floors are walls to a character walking
    /// on +Y.
    pub fn looks_z_up(&self) -> bool {
        let ((y_up, y_down), (z_up, z_down)) = (self.facing(), self.facing_along(2));
        z_up + z_down > 4 * (y_up + y_down)
    }

    /// [`facing`](Self::facing) along axis `axis` (0 x, 1 y, 2 z).
    fn facing_along(&self, axis: usize) -> (usize, usize) {
        let (mut up, mut down) = (0, 0);
        for (i, [a, b, c]) in self.triangles.iter().enumerate() {
            let (e, f) = (
                [0, 1, 2].map(|k| b[k] - a[k]),
                [0, 1, 2].map(|k| c[k] - a[k]),
            );
            let n = [
                e[1] * f[2] - e[2] * f[1],
                e[2] * f[0] - e[0] * f[2],
                e[0] * f[1] - e[1] * f[0],
            ];
            let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            if self.is_two_sided(i) || length == 0.0 {
                continue;
            }
            up += (n[axis] > 0.5 * length) as usize;
            down += (n[axis] < -0.5 * length) as usize;
        }
        (up, down)
    }
}

/// Why a level could not be loaded or baked: the file and the problem.
#[derive(Debug)]
pub struct LevelError {
    /// The file.
    pub path: PathBuf,
    /// What is wrong with it.
    pub problem: Problem,
    /// Where the triangle the problem names ([`Problem::NotFinite`], [`Problem::OutOfRange`],
    /// a triangle refused by the mesh or compact build) came from in the file, where the level
    /// knows. Boxed: it holds names, and most errors have none.
    pub origin: Option<Box<Origin>>,
}

/// What is wrong with a level file.
#[non_exhaustive]
#[derive(Debug)]
pub enum Problem {
    /// It could not be read.
    Io(std::io::Error),
    /// Neither `.obj`, `.gltf` nor `.glb`.
    UnknownFormat,
    /// The parser refused it (its message).
    Malformed(String),
    /// It holds no triangle.
    NoTriangles,
    /// Every one of its triangles is degenerate in the chosen scalar (zero area, or too thin
    /// for it): nothing would be left to collide with.
    AllDegenerate {
        /// How many triangles it holds.
        count: usize,
    },
    /// A coordinate is NaN or infinite. A last check: both formats refuse one where it
    /// stands, as [`Problem::Malformed`] (OBJ at its line; glTF at its node, mesh, primitive
    /// and vertex).
    NotFinite {
        /// The triangle's index in the level.
        triangle: usize,
    },
    /// A coordinate lies outside the chosen scalar's safe range.
    OutOfRange {
        /// The triangle's index in the level.
        triangle: usize,
        /// The coordinate.
        value: f64,
        /// The scalar's name.
        scalar: &'static str,
        /// Its safe range, `±limit`.
        limit: f64,
    },
    /// The mesh build refused it.
    Mesh(ballcast::MeshError),
    /// Its compact form could not be made.
    Compact(ballcast::CompactError),
    /// A heightmap image that is not grey: a colour pixel at column `x`, row `y`.
    Colour {
        /// The pixel's column.
        x: u32,
        /// The pixel's row.
        y: u32,
    },
    /// The heightfield build refused it.
    Heightfield(ballcast::HeightfieldError),
    /// A heightmap image of more than [`MAX_PIXELS`] pixels.
    TooLarge {
        /// Its width in pixels.
        width: u32,
        /// Its height in pixels.
        height: u32,
    },
    /// A heightmap's placement that the scalar cannot hold: `what` (the height, the spacing,
    /// the origin, the grid's far corner, the terrain's height) is `value` as given.
    Placement {
        /// What.
        what: &'static str,
        /// Its value as given (or, for a corner, as the placement puts it).
        value: f64,
        /// The scalar's name.
        scalar: &'static str,
        /// Why it does not do.
        reason: Reason,
    },
}

/// Why a heightmap's placement does not do ([`Problem::Placement`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reason {
    /// It must be positive and finite.
    NotPositive,
    /// It must be finite.
    NotFinite,
    /// It rounds to zero in the scalar.
    Zero,
    /// It lies beyond the scalar's range `±limit`.
    Beyond {
        /// The scalar's limit.
        limit: f64,
    },
}

/// Where a message names triangle `index` by its index: its place in the file, or how the
/// index counts.
fn triangle_at(index: usize, origin: &Option<Box<Origin>>) -> String {
    match origin {
        Some(o) => format!("triangle {index} ({o})"),
        None => format!("triangle {index} (counting from 0, polygons split into triangles)"),
    }
}

impl fmt::Display for LevelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.path.display())?;
        // The build errors name the triangle by index alone: its place follows.
        let built = |index: usize| match &self.origin {
            Some(o) => format!("; triangle {index} is at {o}"),
            None => String::new(),
        };
        match &self.problem {
            Problem::Io(e) => write!(f, "cannot read: {e}"),
            Problem::UnknownFormat => f.write_str(
                "unknown format (expected .obj, .gltf or .glb; a .png heightmap is loaded by \
                 load_heightmap)",
            ),
            Problem::Malformed(m) => write!(f, "malformed: {m}"),
            Problem::NoTriangles => f.write_str("no triangles"),
            Problem::AllDegenerate { count } => {
                write!(
                    f,
                    "all {count} triangles are degenerate (zero area or too thin)"
                )
            }
            Problem::NotFinite { triangle } => write!(
                f,
                "{} has a NaN or infinite coordinate",
                triangle_at(*triangle, &self.origin)
            ),
            Problem::OutOfRange {
                triangle,
                value,
                scalar,
                limit,
            } => write!(
                f,
                "{} has the coordinate {value}, outside {scalar}'s range ±{limit}",
                triangle_at(*triangle, &self.origin)
            ),
            Problem::Mesh(e) => {
                let at = match e {
                    ballcast::MeshError::Triangle { index, .. } => built(*index),
                    _ => String::new(),
                };
                write!(f, "mesh build refused: {e}{at}")
            }
            Problem::Compact(e) => {
                let at = match e {
                    ballcast::CompactError::Mismatch { index }
                    | ballcast::CompactError::MissingTriangle { index, .. }
                    | ballcast::CompactError::MissingVertex { index, .. } => built(*index),
                    _ => String::new(),
                };
                write!(f, "compact mesh refused: {e}{at}")
            }
            Problem::Colour { x, y } => write!(
                f,
                "pixel ({x}, {y}) (column, row from the top left) is coloured: a heightmap's \
                 pixels are grey (red, green and blue equal)"
            ),
            Problem::Heightfield(e) => write!(f, "heightfield build refused: {e}"),
            Problem::TooLarge { width, height } => write!(
                f,
                "a heightmap of {width} x {height} pixels: more than {MAX_PIXELS} (4096 x 4096)"
            ),
            Problem::Placement {
                what,
                value,
                scalar,
                reason,
            } => {
                // Plain digits for everyday values, an exponent for the others.
                let v = if *value != 0.0 && !(1e-4..1e6).contains(&value.abs()) {
                    format!("{value:e}")
                } else {
                    value.to_string()
                };
                match reason {
                    Reason::NotPositive => {
                        write!(f, "the {what} must be positive and finite, not {v}")
                    }
                    Reason::NotFinite => write!(f, "the {what} must be finite, not {v}"),
                    Reason::Zero => write!(f, "the {what} {v} rounds to zero in {scalar}"),
                    Reason::Beyond { limit } => write!(
                        f,
                        "the {what} reaches {v}, beyond {scalar}'s range [-{limit}, {limit}]"
                    ),
                }
            }
        }
    }
}

impl std::error::Error for LevelError {}

impl LevelError {
    pub(crate) fn new(path: &Path, problem: Problem) -> Self {
        Self::at(path, problem, None)
    }

    /// The error about a triangle that came from `origin` in the file.
    pub(crate) fn at(path: &Path, problem: Problem, origin: Option<Origin>) -> Self {
        Self {
            path: path.to_path_buf(),
            problem,
            origin: origin.map(Box::new),
        }
    }
}

/// Loads a level by its extension (`.obj`, `.gltf`, `.glb`, any case).
///
/// Errors: [`Problem::Io`] (missing or unreadable), [`Problem::UnknownFormat`],
/// [`Problem::Malformed`], [`Problem::NoTriangles`], [`Problem::NotFinite`].
pub fn load(path: impl AsRef<Path>) -> Result<Level, LevelError> {
    let path = path.as_ref();
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let one_sided = |(t, origins): (Vec<Tri>, Origins)| {
        let n = t.len();
        (t, vec![false; n], origins)
    };
    let (triangles, two_sided, origins) = match ext.as_deref() {
        Some("obj") => obj::load(path).map(one_sided),
        Some("gltf" | "glb") => gltf_file::load(path),
        _ => Err(Problem::UnknownFormat),
    }
    .map_err(|p| LevelError::new(path, p))?;
    if triangles.is_empty() {
        return Err(LevelError::new(path, Problem::NoTriangles));
    }
    let level = Level {
        path: path.to_path_buf(),
        triangles,
        two_sided,
        origins,
    };
    if let Some(triangle) =
        (level.triangles.iter()).position(|t| t.iter().flatten().any(|c| !c.is_finite()))
    {
        let problem = Problem::NotFinite { triangle };
        return Err(LevelError::at(path, problem, level.origin(triangle)));
    }
    Ok(level)
}
