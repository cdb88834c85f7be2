//! Instructions per query (one `Geometry::cast` of `move_and_slide`) on the baked meshes, for
//! `count.sh`'s mesh table: each geometry's casts go through its own `query_*` function, which
//! QEMU's instruction log attributes. Runs:
//! - the firmware's ramp room (96 triangles) as a linear scan of its prepared triangles
//!   (`query_ramp_scan`) and as a mesh (`query_ramp_mesh`): the ball of `firmware`, 60 steps;
//! - the arena (2 168 triangles, `query_arena_mesh`): the first throw of the arena run, 100
//!   steps (it lands after about 50); the same on the arena as a compact mesh
//!   (`query_arena_compact`);
//! - the 64 × 64 terrain heightfield of `forms`: its second throw, 100 steps falling onto it
//!   (`query_terrain_air`), then 200 rolling on it (`query_terrain_ground`);
//! - the compact arena's and the terrain's runs again, each `Cached` with 32 slots (`query_*_cached`); their hashes must equal the runs' without.
//!
//! Run: `cargo m0 mesh_counts` in `embedded/` (prints the runs' hashes; `count.sh` counts).
#![no_std]
#![no_main]

use ballcast::{
    Cached, CompactMesh, Geometry, Heightfield, SceneHit, StandardTriangle, Sweep, Vec3,
};
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use fixed::types::I16F16;
use panic_semihosting as _;

#[path = "../arena.rs"]
mod arena;
#[path = "../lockstep.rs"]
mod lockstep;
mod level {
    include!(concat!(env!("OUT_DIR"), "/arena.rs"));
}
mod ramp {
    include!(concat!(env!("OUT_DIR"), "/ramp.rs"));
}
mod compact {
    include!(concat!(env!("OUT_DIR"), "/compact.rs"));
}
mod terrain {
    include!(concat!(env!("OUT_DIR"), "/terrain.rs"));
}

type Hit = Option<SceneHit<I16F16>>;

/// Calls `f` with the triangles of a geometry that may meet a box.
type Visit = fn(Vec3<I16F16>, Vec3<I16F16>, &mut dyn FnMut(usize, &StandardTriangle<I16F16>));

/// A geometry whose casts go through one non-inlined function (its visits, for the push-out
/// of a starting overlap, through another).
struct Probe(fn(&Sweep<I16F16>) -> Hit, Visit);

impl Geometry<I16F16> for Probe {
    fn cast(&self, sweep: &Sweep<I16F16>) -> Hit {
        (self.0)(sweep)
    }

    fn visit(
        &self,
        min: Vec3<I16F16>,
        max: Vec3<I16F16>,
        f: &mut dyn FnMut(usize, &StandardTriangle<I16F16>),
    ) {
        (self.1)(min, max, f)
    }
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_ramp_scan(s: &Sweep<I16F16>) -> Hit {
    ramp::TRIANGLES[..].cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_ramp_mesh(s: &Sweep<I16F16>) -> Hit {
    ramp::MESH.cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_arena_mesh(s: &Sweep<I16F16>) -> Hit {
    level::MESH.cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_arena_compact(s: &Sweep<I16F16>) -> Hit {
    compact::MESH.cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_terrain_air(s: &Sweep<I16F16>) -> Hit {
    terrain::HEIGHTFIELD.cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_terrain_ground(s: &Sweep<I16F16>) -> Hit {
    // Not the same body as `query_terrain_air`'s, so the linker keeps the two apart.
    core::hint::black_box(2u8);
    terrain::HEIGHTFIELD.cast(s)
}

/// A cache's slots beside the terrain and the compact arena (100 bytes each in `I16F16` here).
const SLOTS: usize = 32;
type CachedField = Cached<Heightfield<'static, I16F16>, I16F16, SLOTS>;
type CachedCompact = Cached<CompactMesh<'static, I16F16, u16>, I16F16, SLOTS>;

/// A geometry whose casts go through one non-inlined function taking it.
struct Via<'a, G>(&'a G, fn(&G, &Sweep<I16F16>) -> Hit);

impl<G: Geometry<I16F16>> Geometry<I16F16> for Via<'_, G> {
    fn cast(&self, sweep: &Sweep<I16F16>) -> Hit {
        (self.1)(self.0, sweep)
    }

    fn visit(
        &self,
        min: Vec3<I16F16>,
        max: Vec3<I16F16>,
        f: &mut dyn FnMut(usize, &StandardTriangle<I16F16>),
    ) {
        self.0.visit(min, max, f)
    }
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_arena_compact_cached(g: &CachedCompact, s: &Sweep<I16F16>) -> Hit {
    g.cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_terrain_air_cached(g: &CachedField, s: &Sweep<I16F16>) -> Hit {
    g.cast(s)
}

#[inline(never)]
#[unsafe(no_mangle)]
fn query_terrain_ground_cached(g: &CachedField, s: &Sweep<I16F16>) -> Hit {
    core::hint::black_box(3u8);
    g.cast(s)
}

/// The forms' second throw onto the terrain (the first leaves the grid at once): 100 steps
/// through `air`, falling from 9 units up until it lands, then 200 through `ground`, rolling
/// on the ground.
fn terrain_run<A: Geometry<I16F16>, B: Geometry<I16F16>>(air: &A, ground: &B) -> u64 {
    let k = lockstep::Params::<I16F16>::new();
    let v3 = |p: [f64; 3]| Vec3::new(p[0], p[1], p[2]).map(I16F16::from_num);
    let (p, v) = arena::throw(1);
    let mut ball = lockstep::Ball { p: v3(p), v: v3(v) };
    let mut hash = lockstep::Fnv::new();
    for n in 0..300 {
        let step = if n < 100 {
            lockstep::step(air, &k, &mut ball)
        } else {
            lockstep::step(ground, &k, &mut ball)
        };
        if step.is_err() {
            break;
        }
        for v in ball.p.to_array() {
            hash.write_u64(lockstep::Bits::bits(v));
        }
    }
    hash.0
}

/// The firmware's ball in the ramp room: `steps` steps from (5.5, 4.5, 4.5) at rest.
fn ramp_run(g: &Probe, steps: usize) -> u64 {
    let k = lockstep::Params::<I16F16>::new();
    let c = I16F16::from_num;
    let z = I16F16::ZERO;
    let mut ball = lockstep::Ball {
        p: ballcast::Vec3::new(c(5.5), c(4.5), c(4.5)),
        v: ballcast::Vec3::new(z, z, z),
    };
    let mut hash = lockstep::Fnv::new();
    for _ in 0..steps {
        if lockstep::step(g, &k, &mut ball).is_err() {
            break;
        }
        for v in ball.p.to_array() {
            hash.write_u64(lockstep::Bits::bits(v));
        }
    }
    hash.0
}

#[entry]
fn main() -> ! {
    let scan = ramp_run(
        &Probe(query_ramp_scan, |a, b, f| {
            ramp::TRIANGLES[..].visit(a, b, f)
        }),
        60,
    );
    let mesh = ramp_run(
        &Probe(query_ramp_mesh, |a, b, f| ramp::MESH.visit(a, b, f)),
        60,
    );
    let arena = arena::simulate::<I16F16, _>(
        &Probe(query_arena_mesh, |a, b, f| level::MESH.visit(a, b, f)),
        1,
        100,
    );
    let compact = arena::simulate::<I16F16, _>(
        &Probe(query_arena_compact, |a, b, f| compact::MESH.visit(a, b, f)),
        1,
        100,
    );
    let visit: Visit = |a, b, f| terrain::HEIGHTFIELD.visit(a, b, f);
    let field = terrain_run(
        &Probe(query_terrain_air, visit),
        &Probe(query_terrain_ground, visit),
    );
    // The same runs with a cache beside the compact arena and the terrain (one at a time:
    // 3 KB each).
    let compact_cached = {
        let cached = CachedCompact::new(compact::MESH);
        arena::simulate::<I16F16, _>(&Via(&cached, query_arena_compact_cached), 1, 100)
    };
    let field_cached = {
        let cached = CachedField::new(terrain::HEIGHTFIELD);
        terrain_run(
            &Via(&cached, query_terrain_air_cached),
            &Via(&cached, query_terrain_ground_cached),
        )
    };
    hprintln!(
        "ramp scan {:016x}, ramp mesh {:016x}, arena {:016x}, arena compact {:016x}, terrain {:016x}",
        scan,
        mesh,
        arena.hash,
        compact.hash,
        field
    );
    if scan != mesh || arena.hash != compact.hash {
        hprintln!(
            "FAIL: the ramp's mesh and linear scan, or the arena's mesh and compact mesh, disagree"
        );
        debug::exit(debug::EXIT_FAILURE);
    }
    if compact_cached.hash != compact.hash || field_cached != field {
        hprintln!("FAIL: a cached form answers otherwise than without its cache");
        debug::exit(debug::EXIT_FAILURE);
    }
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
