//! `#[no_mangle]` wrappers around `StandardTriangle::new`, `Sweep::new`, `face_collision`, `cast`,
//! the scene-level casts and the box queries (`penetration`, `winding`) of a slice, a `Mesh`, a
//! `CompactMesh` and a `Heightfield`, the cast of a `Compound` of the four and of the last two `Cached`, for every scalar, linked for a bare-metal target in release. Without the default `triangle`
//! feature the triangle constructor is left out: the face wrappers then take their triangle from
//! an opaque static, so the face test is checked on its own. The panic handler calls a function
//! that does not exist, so the link fails if any panic path survives optimisation: every
//! `core::panicking::*`, `panic_bounds_check`, `panic_const_*`, `unwrap_failed`, … ends in the
//! panic handler. With `--features locate` the handler exists instead, to find the path with
//! `llvm-objdump`.
#![no_std]
#![no_main]

use ballcast::penetration::{Penetration, penetration};
use ballcast::winding::{Winding, winding};
use ballcast::{
    Cached, CompactMesh, Compound, Error, Geometry, Grid, Heightfield, HeightfieldShape, Hit, Mesh, SceneHit,
    StandardTriangle, Sweep, Triangle, Vec3,
    slide::{Character, Slide},
};
use core::hint::black_box;
use fixed::types::{I16F16, I32F32};

#[cfg(not(feature = "locate"))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    unsafe extern "C" {
        // Deliberately undefined: referencing it from a reachable panic fails the link.
        fn ballcast_has_a_panic_path() -> !;
    }
    // SAFETY: never called in a successful link; the symbol does not exist.
    unsafe { ballcast_has_a_panic_path() }
}

#[cfg(feature = "locate")]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    loop {
        core::hint::spin_loop();
    }
}

macro_rules! wrappers {
    ($t:ty, $tri:ident, $sweep:ident, $face:ident, $cast:ident, $geometry:ident, $around:ident, $walk:ident, $run:ident) => {
        #[cfg(feature = "triangle")]
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $tri(t: &Triangle<$t>) -> Result<StandardTriangle<$t>, Error> {
            StandardTriangle::new(t)
        }

        /// Without the constructor: a triangle the optimiser knows nothing about.
        #[cfg(not(feature = "triangle"))]
        fn $tri(_: &Triangle<$t>) -> Result<StandardTriangle<$t>, Error> {
            static SLOT: Result<StandardTriangle<$t>, Error> =
                Err(Error::Degenerate { triangle: None });
            *black_box(&SLOT)
        }

        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $sweep(p0: Vec3<$t>, p1: Vec3<$t>, r: $t) -> Result<Sweep<$t>, Error> {
            Sweep::new(p0, p1, r)
        }

        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $face(t: &StandardTriangle<$t>, s: &Sweep<$t>) -> Option<Hit<$t>> {
            t.face_collision(s)
        }

        /// The full test: face, edges and vertices.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $cast(t: &StandardTriangle<$t>, s: &Sweep<$t>) -> Option<Hit<$t>> {
            t.cast(s)
        }

        /// The scene-level queries: a slice's linear scan (the merge of simultaneous contacts),
        /// a mesh's tree, a compact mesh, a heightfield and a compound of the four.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $geometry(
            t: &[StandardTriangle<$t>],
            m: &Mesh<'_, $t>,
            c: &CompactMesh<'_, $t>,
            h: &Heightfield<'_, $t>,
            s: &Sweep<$t>,
        ) -> [Option<SceneHit<$t>>; 7] {
            // And all four as one geometry, nested.
            let all = Compound::new(t, m)
                .and_then(|a| Compound::new(a, Compound::new(c, h)?))
                .ok();
            // The two forms that prepare triangles on the spot, with a cache of their own.
            let (kc, kh): (Cached<_, $t, 8>, Cached<_, $t, 8>) = (Cached::new(*c), Cached::new(*h));
            [
                t.cast(s),
                m.cast(s),
                c.cast(s),
                h.cast(s),
                all.and_then(|a| a.cast(s)),
                kc.cast(s),
                kh.cast(s),
            ]
        }

        /// The box queries (penetration and winding) on the same four forms.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $around(
            t: &[StandardTriangle<$t>],
            m: &Mesh<'_, $t>,
            c: &CompactMesh<'_, $t>,
            h: &Heightfield<'_, $t>,
            p: Vec3<$t>,
            r: $t,
        ) -> [(
            Result<Option<Penetration<$t>>, Error>,
            Result<Winding, Error>,
        ); 4] {
            [
                (penetration(t, p, r), winding(t, p)),
                (penetration(m, p, r), winding(m, p)),
                (penetration(c, p, r), winding(c, p)),
                (penetration(h, p, r), winding(h, p)),
            ]
        }

        /// A frame of the character loop (the whole response: slides, push-outs, steps, the
        /// snap) on a slice, after a jump.
        #[unsafe(no_mangle)]
        #[inline(never)]
        pub fn $walk(
            t: &[StandardTriangle<$t>],
            me: &mut Character<$t>,
            wish: Vec3<$t>,
            gravity: Vec3<$t>,
            dt: $t,
        ) -> Result<Slide<$t>, Error> {
            me.jump(dt)?;
            me.update(t, wish, gravity, dt)
        }

        /// Calls the wrappers on values the optimiser cannot see.
        fn $run() {
            let tri = black_box(Triangle::<$t>::default());
            let st = black_box($tri(&tri));
            let v = black_box(Vec3::<$t>::default());
            let s = black_box($sweep(v, black_box(v), black_box(tri.v0.x)));
            if let (Ok(st), Ok(s)) = (st, s) {
                black_box($face(&st, &s));
                black_box($cast(&st, &s));
                let many = [st; 3];
                let m = black_box(Mesh::from_parts(
                    &[],
                    black_box(&many[..]),
                    &[],
                    Grid::default(),
                ));
                let c = black_box(CompactMesh::from_parts(
                    &[],
                    Grid::default(),
                    &[],
                    &[],
                    &[],
                    &[],
                    0,
                ));
                let z = black_box(<$t>::default());
                let h = black_box(Heightfield::from_parts(HeightfieldShape { origin: v, spacing: z, unit: z, columns: 1, rows: 1 }, &[], &[], [0, 0], 0));
                black_box($geometry(black_box(&many[..]), &m, &c, &h, &s));
                black_box($around(black_box(&many[..]), &m, &c, &h, v, tri.v0.x));
                if let Ok(mut me) = Character::new(v, tri.v0.x) {
                    black_box($walk(black_box(&many[..]), &mut me, v, black_box(v), z));
                }
            }
        }
    };
}

wrappers!(
    f32,
    ballcast_f32_triangle,
    ballcast_f32_sweep,
    ballcast_f32_face,
    ballcast_f32_cast,
    ballcast_f32_geometry,
    ballcast_f32_around,
    ballcast_f32_walk,
    run_f32
);
wrappers!(
    f64,
    ballcast_f64_triangle,
    ballcast_f64_sweep,
    ballcast_f64_face,
    ballcast_f64_cast,
    ballcast_f64_geometry,
    ballcast_f64_around,
    ballcast_f64_walk,
    run_f64
);
wrappers!(
    I16F16,
    ballcast_i16f16_triangle,
    ballcast_i16f16_sweep,
    ballcast_i16f16_face,
    ballcast_i16f16_cast,
    ballcast_i16f16_geometry,
    ballcast_i16f16_around,
    ballcast_i16f16_walk,
    run_i16f16
);
wrappers!(
    I32F32,
    ballcast_i32f32_triangle,
    ballcast_i32f32_sweep,
    ballcast_i32f32_face,
    ballcast_i32f32_cast,
    ballcast_i32f32_geometry,
    ballcast_i32f32_around,
    ballcast_i32f32_walk,
    run_i32f32
);

/// A wrapper that can panic (an index the optimiser cannot check), for the self-test.
#[cfg(feature = "selftest")]
#[unsafe(no_mangle)]
#[inline(never)]
pub fn ballcast_selftest_index(a: &[u8; 4], i: usize) -> u8 {
    a[i]
}

/// The entry point: makes every wrapper reachable, so none is discarded before linking.
#[unsafe(no_mangle)]
pub extern "C" fn _start() -> ! {
    loop {
        run_f32();
        run_f64();
        run_i16f16();
        run_i32f32();
        #[cfg(feature = "selftest")]
        black_box(ballcast_selftest_index(&black_box([1; 4]), black_box(9)));
    }
}
