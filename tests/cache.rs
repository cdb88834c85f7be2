//! `Cached`: a heightfield or a compact mesh with a `TriangleCache` beside it answers as
//! without, bit for bit, for any cache size (one slot, a count that is no power of two, more
//! than the triangles), alone, in a compound and in a walk of slides, with two-sided triangles
//! and over a malformed tree (scanned); caches of several characters over one terrain, each
//! through a reference; a cache kept across frames saves preparations; a cache lent to the
//! geometry from elsewhere answers as one of its own. Every property in every scalar.

mod common;
mod meshes;

use ballcast::{
    Cacheable, Cached, CompactMesh, Compound, Degenerates, Heightfield, HeightfieldShape, Mesh,
    Scalar, Sweep, TriangleCache, move_and_slide, slide::Character,
};
use common::{Rng, v};
use fixed::types::{I16F16, I32F32};

const W: u32 = 10;

/// A bumpy terrain with holes, heights from `seed`.
fn terrain<'a, S: Scalar>(
    seed: u64,
    heights: &'a mut Vec<i16>,
    cells: &'a mut [u8],
) -> Heightfield<'a, S> {
    let mut rng = Rng(seed);
    *heights = (0..(W + 1) * (W + 1))
        .map(|_| rng.range(-40.0, 40.0) as i16)
        .collect();
    let hole = |i: u32, k: u32| (3 * i + k).is_multiple_of(11);
    let o = v([-(W as f64) / 2.0, -0.5, -(W as f64) / 2.0]);
    Heightfield::build(
        HeightfieldShape {
            origin: o,
            spacing: S::ONE,
            unit: S::from_f64(1.0 / 64.0),
            columns: W,
            rows: W,
        },
        heights,
        hole,
        cells,
    )
    .unwrap()
}

/// Short moves near the ground (as a character's slides are) and longer casts down onto it.
fn sweeps<S: Scalar>(rng: &mut Rng, n: usize) -> Vec<Sweep<S>> {
    (0..n)
        .map(|k| {
            let r = rng.range(0.1, 0.6);
            let p0 = [
                rng.range(-4.0, 4.0),
                rng.range(-0.5, 1.2),
                rng.range(-4.0, 4.0),
            ];
            let reach = if k % 4 == 0 { 4.0 } else { 0.4 };
            let p1 = p0.map(|x| x + reach * rng.range(-1.0, 1.0));
            Sweep::new(v(p0), v(p1), S::from_f64(r)).unwrap()
        })
        .collect()
}

/// Each sweep cast twice through the cache (the second time from what the first kept) and
/// once without it: the same answer, bit for bit (`Debug` shows every bit of every field).
fn same_answers<S: Scalar, G: Cacheable<S> + Copy, const N: usize>(
    geometry: G,
    sweeps: &[Sweep<S>],
) -> u32 {
    let cached: Cached<G, S, N> = Cached::new(geometry);
    for s in sweeps {
        let want = format!("{:?}", geometry.cast(s));
        for _ in 0..2 {
            assert_eq!(
                format!("{:?}", cached.cast(s)),
                want,
                "{} N={N}",
                core::any::type_name::<S>()
            );
        }
    }
    cached.cache().hits()
}

fn heightfield_answers_as_without<S: Scalar>() {
    let (mut heights, mut cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let field = terrain::<S>(0x0cac_4e01, &mut heights, &mut cells);
    let mut rng = Rng(0x5eed_0001);
    let sweeps = sweeps::<S>(&mut rng, 1500);
    let hits = same_answers::<S, _, 1>(field, &sweeps)
        + same_answers::<S, _, 7>(field, &sweeps)
        + same_answers::<S, _, 512>(field, &sweeps);
    assert!(hits > 3000, "{hits} hits");
}

fn compact_answers_as_without<S: Scalar>() {
    let mut rng = Rng(0x0cac_4e02);
    let src = meshes::boxes(&mut rng, 12, 4.0);
    let owned = meshes::build::<S>(
        &src.iter().map(|&t| meshes::tri(t)).collect::<Vec<_>>(),
        Degenerates::Refuse,
    )
    .unwrap();
    let (vertices, indices) = meshes::indexed::<S>(&src);
    let n = owned.mesh().len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
    let mesh: Mesh<'_, S> = owned.mesh();
    let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let sweeps = sweeps::<S>(&mut rng, 1500);
    let hits = same_answers::<S, _, 1>(compact, &sweeps)
        + same_answers::<S, _, 7>(compact, &sweeps)
        + same_answers::<S, _, 512>(compact, &sweeps);
    assert!(hits > 1000, "{hits} hits");
}

/// A compact mesh of a soup whose even triangles are two-sided (kept with their sidedness),
/// whole and with its tree broken (every inner child pointing past the nodes: the query finds
/// it malformed and scans every triangle, with or without the cache).
fn compact_two_sided_and_malformed_as_without<S: Scalar>() {
    let mut rng = Rng(0x0cac_4e06);
    let src = meshes::soup(&mut rng, 200, 4.0);
    let tris: Vec<_> = src.iter().map(|&t| meshes::tri::<S>(t)).collect();
    let owned = meshes::build_sided::<S>(&tris, |i| i % 2 == 0, Degenerates::Skip).unwrap();
    let (vertices, indices) = meshes::indexed::<S>(&src);
    let mesh = owned.mesh();
    let n = mesh.len();
    let (mut t, mut o, mut b) = (vec![[0u16; 3]; n], vec![0u16; n], vec![0u8; n]);
    let compact = CompactMesh::compact(&mesh, &vertices, &indices, &mut t, &mut o, &mut b).unwrap();
    let (nodes, grid, vs, ts, order, bytes, class) = compact.parts();
    let mut broken = nodes.to_vec();
    for child in broken.iter_mut().flat_map(|n| n.children.iter_mut()) {
        if *child & (1 << 31) == 0 {
            *child = u32::MAX >> 1;
        }
    }
    let malformed = CompactMesh::from_parts(&broken, grid, vs, ts, order, bytes, class);
    let sweeps: Vec<Sweep<S>> = (0..1500)
        .map(|_| {
            let p0 = [0; 3].map(|_| rng.range(-4.0, 4.0));
            let p1 = p0.map(|x| x + rng.range(-1.0, 1.0));
            Sweep::new(v(p0), v(p1), S::from_f64(rng.range(0.05, 0.5))).unwrap()
        })
        .collect();
    let back = sweeps
        .iter()
        .filter(|s| compact.cast(s).is_some_and(|h| h.index % 2 == 0))
        .count();
    assert!(back > 100, "{back} hits on two-sided triangles");
    assert!(same_answers::<S, _, 7>(compact, &sweeps) > 500);
    // The scan takes nothing from the cache: only the answers count.
    same_answers::<S, _, 7>(malformed, &sweeps);
}

/// A walk of slides over the terrain, and a compound of the cached terrain with a cached
/// compact mesh: the same positions step by step, and most lookups find their triangle.
fn walks_and_compounds_as_without<S: Scalar>() {
    let (mut heights, mut cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let field = terrain::<S>(0x0cac_4e03, &mut heights, &mut cells);
    let cached: Cached<_, S, 32> = Cached::new(field);
    let (r, step) = (S::from_f64(0.3), v::<S>([0.05, -0.04, 0.03]));
    let (mut a, mut b) = (v::<S>([-3.0, 1.5, -2.0]), v::<S>([-3.0, 1.5, -2.0]));
    for _ in 0..150 {
        let (x, y) = (
            move_and_slide(&cached, a, step, r).unwrap(),
            move_and_slide(&field, b, step, r).unwrap(),
        );
        assert_eq!(
            format!("{x:?}"),
            format!("{y:?}"),
            "{}",
            core::any::type_name::<S>()
        );
        (a, b) = (x.position, y.position);
    }
    let c = cached.cache();
    assert!(
        c.hits() > 2 * c.misses(),
        "{} hits, {} misses",
        c.hits(),
        c.misses()
    );
    // The terrain twice, as a compound's two parts (every contact tied with its twin): cached
    // in both parts or in none.
    let (c1, c2): (Cached<_, S, 16>, Cached<_, S, 16>) = (Cached::new(field), Cached::new(field));
    let both = Compound::new(c1, c2).unwrap();
    let plain = Compound::new(field, field).unwrap();
    let mut rng = Rng(0x5eed_0003);
    for s in sweeps::<S>(&mut rng, 600) {
        assert_eq!(
            format!("{:?}", both.cast(&s)),
            format!("{:?}", plain.cast(&s))
        );
    }
}

/// Two characters' caches over one terrain, each through a shared reference to it, walking
/// apart: each answers as the terrain step by step and finds most of its triangles kept.
fn caches_by_reference_walk_as_the_terrain<S: Scalar>() {
    let (mut heights, mut cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let field = terrain::<S>(0x0cac_4e04, &mut heights, &mut cells);
    let r = S::from_f64(0.3);
    for (from, step) in [
        ([-3.0, 1.5, -2.0], [0.05, -0.04, 0.03]),
        ([3.0, 1.5, 2.0], [-0.04, -0.05, -0.02]),
    ] {
        let cached: Cached<&Heightfield<'_, S>, S, 24> = Cached::new(&field);
        let (step, mut at) = (v::<S>(step), v::<S>(from));
        for _ in 0..120 {
            let (x, y) = (
                move_and_slide(&cached, at, step, r).unwrap(),
                move_and_slide(&field, at, step, r).unwrap(),
            );
            assert_eq!(format!("{x:?}"), format!("{y:?}"));
            at = x.position;
        }
        let c = cached.cache();
        assert!(c.hits() > 2 * c.misses(), "{c:?} at {at:?}");
    }
}

/// A character walking frame after frame: one `Cached` kept throughout answers as the terrain
/// and prepares far fewer triangles than one made anew each frame (which starts empty), the
/// use it exists for: 18 against 654 to 691 in the four scalars, with 32 slots. (One slot per
/// triangle instead of sets of four prepared 524 kept, in `f32`: two triangles touched every
/// frame shared a slot.)
fn a_cached_kept_across_frames_prepares_far_fewer<S: Scalar>() {
    let (mut heights, mut cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let field = terrain::<S>(0x0cac_4e05, &mut heights, &mut cells);
    let (gravity, dt) = (v::<S>([0.0, -9.81, 0.0]), S::from_f64(1.0 / 64.0));
    let walk = |anew: bool| {
        let start = v::<S>([-3.0, 1.0, -2.0]);
        let (mut me, mut plain) = (
            Character::new(start, S::from_f64(0.4)).unwrap(),
            Character::new(start, S::from_f64(0.4)).unwrap(),
        );
        let mut level: Cached<_, S, 32> = Cached::new(field);
        let mut prepared = 0;
        for f in 0..200 {
            if anew {
                prepared += level.cache().misses();
                level = Cached::new(field);
            }
            let a = f as f64 / 40.0;
            let wish = v::<S>([2.0 * a.cos(), 0.0, 2.0 * a.sin()]);
            me.update(&level, wish, gravity, dt).unwrap();
            plain.update(&field, wish, gravity, dt).unwrap();
            assert_eq!(format!("{me:?}"), format!("{plain:?}"), "frame {f}");
        }
        prepared + level.cache().misses()
    };
    let (kept, anew) = (walk(false), walk(true));
    assert!(
        kept > 0 && 10 * kept < anew,
        "{kept} prepared kept, {anew} anew"
    );
}

/// One `Cached` over a whole level: a compound of two different terrains over the same ground
/// (the same triangle indices in each part) and a prepared mesh of boxes, nested either way. Each part's
/// triangles are kept under the compound's indices, so neither terrain is answered with the
/// other's triangles: the answers are the compound's without a cache, and both terrains' are
/// found kept.
fn a_cached_compound_keeps_its_parts_apart<S: Scalar>() {
    let (mut h1, mut c1) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let (mut h2, mut c2) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let (a, b) = (
        terrain::<S>(0x0cac_4e07, &mut h1, &mut c1),
        terrain::<S>(0x0cac_4e08, &mut h2, &mut c2),
    );
    let mut rng = Rng(0x0cac_4e09);
    let src = meshes::boxes(&mut rng, 6, 4.0);
    let tris: Vec<_> = src.iter().map(|&t| meshes::tri::<S>(t)).collect();
    let owned = meshes::build::<S>(&tris, Degenerates::Refuse).unwrap();
    let mesh = owned.mesh();
    let plain = Compound::new(Compound::new(a, b).unwrap(), mesh).unwrap();
    // The same parts nested the other way: the terrains' indices shifted twice over.
    let other = Compound::new(mesh, Compound::new(a, b).unwrap()).unwrap();
    let cached: Cached<_, S, 64> = Cached::new(plain);
    let cached_other: Cached<_, S, 64> = Cached::new(other);
    let sweeps = sweeps::<S>(&mut rng, 1500);
    let mut parts = [0; 3];
    for s in &sweeps {
        let (want, want_other) = (plain.cast(s), other.cast(s));
        for _ in 0..2 {
            assert_eq!(format!("{:?}", cached.cast(s)), format!("{want:?}"));
            assert_eq!(
                format!("{:?}", cached_other.cast(s)),
                format!("{want_other:?}")
            );
        }
        if let Some(h) = want {
            let inner = plain.first().offset();
            let part = (h.index >= inner) as usize + (h.index >= plain.offset()) as usize;
            parts[part] += 1;
        }
    }
    assert!(parts.iter().all(|&n| n > 50), "hits per part {parts:?}");
    for c in [cached.cache(), cached_other.cache()] {
        assert!(c.hits() > 1000, "{c:?}");
    }
}

/// `Cached::for_static`, the cache made at compile time for a `static`: the same answers and
/// counts as `Cached::new`'s cache, and the geometry's answers.
fn a_cache_made_at_compile_time_answers_as_without<S: Scalar>() {
    let (mut heights, mut cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let field = terrain::<S>(0x0cac_4e07, &mut heights, &mut cells);
    let mut rng = Rng(0x5eed_0007);
    let (made, compiled): (Cached<_, S, 7>, Cached<_, S, 7>) =
        (Cached::new(field), Cached::for_static(field));
    for s in sweeps::<S>(&mut rng, 600) {
        let want = format!("{:?}", field.cast(&s));
        assert_eq!(format!("{:?}", compiled.cast(&s)), want);
        assert_eq!(format!("{:?}", made.cast(&s)), want);
    }
    let counts = |c: &Cached<_, S, 7>| (c.cache().hits(), c.cache().misses());
    assert_eq!(counts(&compiled), counts(&made));
    assert!(counts(&made).0 > 50, "{:?}", counts(&made));
    // Evaluated by the compiler: an empty level's cache, as a firmware's `static` would be.
    let nothing: Cached<&[ballcast::StandardTriangle<f32>], f32, 4> =
        const { Cached::for_static(&[]) };
    let fall = Sweep::new(
        ballcast::Vec3::new(0.0, 1.0, 0.0),
        ballcast::Vec3::ZERO,
        0.5,
    )
    .unwrap();
    assert_eq!(nothing.cast(&fall), None);
}

/// `Cached::with_cache`, a geometry lent a cache kept apart (a firmware's zero-initialised
/// `static mut`): the same answers and counts as a cache of its own; lent again, to another
/// terrain whose triangles have the same indices, it starts empty and answers as that terrain
/// (a triangle kept for the first would be a wrong answer for the second).
fn a_lent_cache_answers_as_an_owned_one<S: Scalar>() {
    let (mut heights, mut cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let field = terrain::<S>(0x1e47_ca5e, &mut heights, &mut cells);
    let (mut other_heights, mut other_cells) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let other = terrain::<S>(0x07e4_0002, &mut other_heights, &mut other_cells);
    let mut rng = Rng(0x5eed_0008);
    let mut cache: TriangleCache<S, 9> = const { TriangleCache::new() };
    let owned: Cached<_, S, 9> = Cached::new(field);
    let sweeps = sweeps::<S>(&mut rng, 600);
    let counts = |c: &TriangleCache<S, 9>| (c.hits(), c.misses());
    {
        let lent = Cached::with_cache(field, &mut cache);
        for s in &sweeps {
            let want = format!("{:?}", field.cast(s));
            assert_eq!(format!("{:?}", lent.cast(s)), want);
            assert_eq!(format!("{:?}", owned.cast(s)), want);
        }
        assert_eq!(counts(lent.cache()), counts(owned.cache()));
        assert!(counts(lent.cache()).0 > 50, "{:?}", counts(lent.cache()));
    }
    // The same sweeps over the other terrain, the last first: where the first terrain's
    // triangles were kept last.
    let lent = Cached::with_cache(other, &mut cache);
    assert_eq!(counts(lent.cache()), (0, 0));
    let fresh: Cached<_, S, 9> = Cached::new(other);
    for s in sweeps.iter().rev() {
        let want = format!("{:?}", other.cast(s));
        assert_eq!(format!("{:?}", lent.cast(s)), want);
        assert_eq!(format!("{:?}", fresh.cast(s)), want);
    }
    assert_eq!(counts(lent.cache()), counts(fresh.cache()));
}

meshes::per_scalar!(
    heightfield_answers_as_without,
    compact_answers_as_without,
    compact_two_sided_and_malformed_as_without,
    walks_and_compounds_as_without,
    caches_by_reference_walk_as_the_terrain,
    a_cached_kept_across_frames_prepares_far_fewer,
    a_cached_compound_keeps_its_parts_apart,
    a_cache_made_at_compile_time_answers_as_without,
    a_lent_cache_answers_as_an_owned_one,
);
