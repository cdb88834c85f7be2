//! # ballcast
//!
//! Swept-sphere (ball) versus triangle collision for embedded and deterministic simulation:
//! a ball of radius `r` moves from `p0` to `p1`; how far along that path can it go before it
//! touches a triangle, and what is the contact normal?
//!
//! ## Guarantees
//! - **`no_std`, no allocation**: nothing here touches a heap; every type is a plain value.
//! - **No panics, no undefined behaviour**: constructors validate their input and return an
//!   [`Error`] value; once constructed, every query succeeds. Inside the documented safe range
//!   ([`Scalar::LIMIT`]) no fixed-point intermediate can overflow. A link-time check (CI's
//!   `.ci/no_panic.sh`) shows the release build of construction, `face_collision` and `cast`
//!   has no panic path in any scalar. `#![forbid(unsafe_code)]`.
//! - **One algorithm, four scalars**: `f32`, `f64`, [`I16F16`](fixed::types::I16F16) and
//!   [`I32F32`](fixed::types::I32F32) run the same generic code; trajectories are bit-identical
//!   on x86-64, Cortex-M0 and Cortex-M4F in every scalar (checked under QEMU).
//! - **Measured accuracy** against `f64` at scene scale 10 (triangles within ±10, paths within
//!   ±40, radius 0.1–2; 10^6 full casts): the contact's position along the normal is off by at
//!   most 1.4e-5 (`f32`, p99 4.4e-6), 1.2e-8 (`I32F32`, p99 6.5e-9) and 7.6e-4 (`I16F16`,
//!   p99 4.3e-4, mostly alpha's own 2^-16 step over long paths). [`plan()`] predicts these for
//!   any scene size.
//! - **A response that holds**: [`move_and_slide`] never carries a ball deeper into what it
//!   overlaps, respects every plane touched at once (corners), comes to rest when pushed into a
//!   corner, and rounds every product to nearest so a resting ball does not creep (long runs of
//!   10^5 steps in `tests/response.rs`, every scalar). A ball that starts inside geometry is
//!   pushed out first ([`penetration()`] gives the overlap without moving anything).
//! - **Errors that say where**: every public entry point validates every argument, and an
//!   [`Error`] names the triangle, the offending value and the range it left.
//!
//! ## Determinism
//! The same calls with the same inputs give the same bits on every target, in every scalar,
//! debug or release: positions, normals, alphas and errors alike. Tested, not only argued: the
//! lockstep scene (28 triangles, 20 throws, 10 000 steps of [`move_and_slide`]) hashes every
//! position to the same four values (pinned in `tests/lockstep.rs`) on x86-64, aarch64 (under
//! `qemu-aarch64`), wasm32 (`wasm32-wasip1` under Node's WASI), Cortex-M0 and Cortex-M4F (under
//! `qemu-system-arm`); CI's `.ci/targets.sh` and `.ci/embedded.sh` fail on one differing bit.
//! - **Floats** use only IEEE 754 basic operations (`+ - * /`, comparisons, conversions), which
//!   round to nearest the same way on every FPU and in compiler-builtins' soft float, and libm's
//!   square root, correctly rounded whether libm computes it or uses the hardware's (`sqrtsd`,
//!   `fsqrt`, `f64.sqrt`). No fused multiply-add: Rust never contracts `a * b + c` on its own,
//!   and the crate calls no `mul_add`. No platform intrinsics, no `core::arch`, no
//!   transcendental functions.
//! - **Fixed-point** ([`I16F16`](fixed::types::I16F16), [`I32F32`](fixed::types::I32F32)) is
//!   integer arithmetic throughout, square root included: deterministic by construction.
//!
//! What you must keep equal on every machine of a lockstep session: the scalar; the triangles
//! and the order they are pushed into a [`Scene`] (adjacency and ties follow it); the inputs and
//! the order of calls; the crate version (a new version may move trajectories);
//! the enabled features; and, for floats, the FPU's default mode (round to nearest, subnormals
//! kept: no flush-to-zero set by fast-math start-up code, no x87 extended precision as on
//! 32-bit x86 without SSE2). NaN bit patterns are not portable (IEEE leaves them open); the
//! crate refuses non-finite input.
//!
//! To check your own target, run the lockstep program there and compare its four lines with
//! the host's `cargo run --release --example lockstep`: from the repository,
//! `cargo run --release --target <triple>` in `.ci/lockstep/` for any target with `std`, or
//! `cargo m0 lockstep` / `cargo m4 lockstep` in `embedded/` for Cortex-M under QEMU.
//!
//! ## Map
//! - [`scalar`] holds the [`Scalar`] trait and its implementations.
//! - [`vec3`] holds [`Vec3`].
//! - [`triangle`] holds [`Triangle`] and [`StandardTriangle`], the precomputed standard frame.
//! - [`sweep`] holds [`Sweep`] (a validated moving ball) and [`StandardSweep`].
//! - [`face`] holds the course notes' face test, [`standard_face`] and
//!   [`StandardTriangle::face_collision`].
//! - [`contact`] holds edge and vertex contacts, [`StandardTriangle::cast`] and [`Features`].
//! - [`scene`] holds [`Scene`], many triangles with active edges from adjacency, and [`SceneHit`].
//! - [`import`] builds scenes from a vertex array and an index buffer or any iterator of
//!   triangles, and converts triangles between scalars ([`Triangle::try_cast`]).
//! - [`mesh`] holds [`Mesh`], a whole level's triangles behind a bounding volume hierarchy,
//!   borrowed from flash, a caller's buffer or `Vec`s, answering exactly as a linear scan;
//!   [`bvh`] holds its tree ([`Node`], [`Grid`]): layout, build and traversal. With the `alloc`
//!   feature, `mesh_buf` holds `MeshBuf`, a mesh owning its parts in `Vec`s.
//! - [`compact`] holds [`CompactMesh`], a mesh's tree over shared vertices and indexed
//!   triangles (about 19 bytes per triangle), answering exactly as the prepared mesh; with
//!   the `alloc` feature also `CompactMeshBuf`, one made from a triangle soup and owning its
//!   parts.
//! - [`heightfield`] holds [`Heightfield`], a terrain as a grid of 16-bit heights (about 1.5
//!   bytes per triangle), answering exactly as the same triangles in a mesh; with the `alloc`
//!   feature also `HeightfieldBuf`, one owning its heights and cell bytes.
//! - [`cache`] holds [`Cached`], a heightfield or compact mesh owning (or borrowing) a
//!   [`TriangleCache`] of prepared triangles, for queries that come back to the same triangles
//!   (a character's, frame after frame), answering exactly as without.
//! - [`compound`] holds [`Compound`], two geometries (a heightfield and the meshes standing on
//!   it) cast against as one, answering exactly as one mesh of the same prepared triangles
//!   (each part keeps its own active edges), and [`CompoundPart`], what can be one of them.
//! - [`slide`] holds [`slide::Character`], a game's walking character in one call a frame
//!   (walk, steps, the floor snap, jumps, falls), and what it is built of: [`move_and_slide`],
//!   the collision response (Quake's fly-move, constrained by every plane touched), [`Slide`],
//!   the [`skin`](slide::skin) and [`min_radius`](slide::min_radius) it works with, and
//!   [`Slider`]'s ground probe ([`Slider::probe_floor`], giving a [`Floor`]), floor snap
//!   ([`Slider::snap_to_floor`]) and step up ([`Slider::step_slide`]).
//! - [`mod@penetration`] holds [`penetration()`], the deepest overlap of a resting ball with
//!   geometry and the way out ([`Penetration`]).
//! - [`mod@plan`] holds the precision planner: which scalars fit a scene, and their expected error.
//! - [`mod@winding`] holds [`winding()`], which way a scene's triangles face a point: the check
//!   for a level wound the wrong way.
//! - [`interop`] holds conversions for the `mint`, `glam` and `serde` features.
//! - [`hit`] holds [`Hit`] and [`Contact`], what a query returns; [`error`] holds [`Error`].
//!
//! ```
//! use ballcast::{StandardTriangle, Sweep, Triangle, Vec3};
//! let floor = Triangle::new(
//!     Vec3::new(-10.0f32, 0.0, 10.0),
//!     Vec3::new(10.0, 0.0, 10.0),
//!     Vec3::new(10.0, 0.0, -10.0),
//! );
//! let floor = StandardTriangle::new(&floor)?; // once per triangle
//! let ball = Sweep::new(Vec3::new(5.0, 4.0, 5.0), Vec3::new(5.0, -4.0, 5.0), 0.5)?;
//! let hit = floor.face_collision(&ball).expect("falls onto the floor");
//! assert_eq!(hit.alpha, 0.4375); // 3.5 of 8 units
//! assert_eq!(hit.normal, Vec3::new(0.0, 1.0, 0.0));
//! # Ok::<(), ballcast::Error>(())
//! ```
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

#[cfg(feature = "alloc")]
extern crate alloc;

mod adjacency;
pub mod bvh;
pub mod cache;
mod check;
pub mod compact;
pub mod compound;
pub mod contact;
mod cover;
mod cull;
pub mod error;
pub mod face;
mod features;
pub mod heightfield;
pub mod hit;
pub mod import;
pub mod interop;
mod merge;
pub mod mesh;
#[cfg(feature = "alloc")]
pub mod mesh_buf;
pub mod penetration;
pub mod plan;
mod radix;
mod reject;
pub mod scalar;
pub mod scene;
mod seam;
pub mod slide;
mod start_overlap;
pub mod sweep;
#[cfg(test)]
mod testing;
pub mod triangle;
pub mod vec3;
pub mod winding;
#[cfg(test)]
mod xorshift;

/// The `fixed` crate whose [`I16F16`](fixed::types::I16F16) and
/// [`I32F32`](fixed::types::I32F32) implement [`Scalar`]: name them through it
/// (`ballcast::fixed::types::I16F16`) to be sure of the version this crate was built with.
pub use fixed;

pub use bvh::{Grid, LeafSize, Node};
pub use cache::{Cacheable, Cached, TriangleCache};
#[cfg(feature = "alloc")]
pub use compact::CompactMeshBuf;
pub use compact::{CompactError, CompactMesh, MeshIndex};
pub use compound::{Compound, CompoundPart, PartIndex};
pub use contact::Features;
pub use error::{Error, Input};
pub use face::standard_face;
#[cfg(feature = "alloc")]
pub use heightfield::HeightfieldBuf;
pub use heightfield::{Heightfield, HeightfieldError, HeightfieldShape};
pub use hit::{Contact, Hit};
pub use merge::PLANES;
pub use mesh::{Buffer, Degenerates, Mesh, MeshError, MeshOptions, MeshPart};
#[cfg(feature = "alloc")]
pub use mesh_buf::MeshBuf;
pub use penetration::{Penetration, penetration};
pub use plan::{Precision, ScalarType, Verdict, choose, plan};
pub use scalar::Scalar;
pub use scene::{Geometry, Scene, SceneHit};
pub use slide::{Floor, MAX_SLIDES, Slide, SlideContact, Slider, move_and_slide};
pub use sweep::{StandardSweep, Sweep};
pub use triangle::{Edge, Parts, StandardTriangle, Triangle};
pub use vec3::Vec3;
pub use winding::{Winding, winding};

// The README's examples run as doctests.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
