//! `Cached`: a heightfield or a compact mesh with a `TriangleCache` beside it answers as
//! without, bit for bit, for any cache size (one slot, a count that is no power of two, more
//! than the triangles), alone, in a compound and in a walk of slides, with two-sided triangles
//! and over a malformed tree (scanned); a cache lent to another geometry forgets the first
//! one's triangles. Every property in every scalar.

mod common;
mod meshes;

use ballcast::{
    Cacheable, Cached, CompactMesh, Compound, Degenerates, Heightfield, Mesh, Scalar, Sweep,
    TriangleCache, move_and_slide,
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
        o,
        S::ONE,
        S::from_f64(1.0 / 64.0),
        W,
        W,
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
    let mut cache: TriangleCache<S, N> = TriangleCache::new();
    let cached = Cached::new(geometry, &mut cache);
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
    let mut cache: TriangleCache<S, 32> = TriangleCache::new();
    let cached = Cached::new(field, &mut cache);
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
    let (mut c1, mut c2): (TriangleCache<S, 16>, TriangleCache<S, 16>) = Default::default();
    let both = Compound::new(Cached::new(field, &mut c1), Cached::new(field, &mut c2)).unwrap();
    let plain = Compound::new(field, field).unwrap();
    let mut rng = Rng(0x5eed_0003);
    for s in sweeps::<S>(&mut rng, 600) {
        assert_eq!(
            format!("{:?}", both.cast(&s)),
            format!("{:?}", plain.cast(&s))
        );
    }
}

/// A cache used with one terrain and then lent to another of the same size (the same triangle
/// indices) answers as the second: lending empties it.
fn a_cache_lent_again_forgets_the_first_geometry<S: Scalar>() {
    let (mut h1, mut c1) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let (mut h2, mut c2) = (Vec::new(), vec![0u8; (W * W) as usize]);
    let (first, second) = (
        terrain::<S>(0x0cac_4e04, &mut h1, &mut c1),
        terrain::<S>(0x0cac_4e05, &mut h2, &mut c2),
    );
    let mut rng = Rng(0x5eed_0004);
    let sweeps = sweeps::<S>(&mut rng, 400);
    let mut cache: TriangleCache<S, 1024> = TriangleCache::new();
    let warm = Cached::new(first, &mut cache);
    sweeps.iter().for_each(|s| {
        let _ = warm.cast(s);
    });
    let (mut differ, mut hits) = (0, 0);
    let again = Cached::new(second, &mut cache);
    for s in &sweeps {
        let want = second.cast(s);
        differ += (first.cast(s) != want) as usize;
        hits += want.is_some() as usize;
        assert_eq!(
            format!("{:?}", again.cast(s)),
            format!("{want:?}"),
            "{}",
            core::any::type_name::<S>()
        );
    }
    // The two terrains do answer differently (else the test would prove nothing).
    assert!(differ > 50 && hits > 100, "{differ} differ, {hits} hits");
}

meshes::per_scalar!(
    heightfield_answers_as_without,
    compact_answers_as_without,
    compact_two_sided_and_malformed_as_without,
    walks_and_compounds_as_without,
    a_cache_lent_again_forgets_the_first_geometry,
);
