//! Prepared triangles kept from one query to the next, for the forms that prepare the triangles
//! they reach on the spot ([`Heightfield`](crate::Heightfield),
//! [`CompactMesh`](crate::CompactMesh)).
//!
//! A character's frame asks about the same few triangles again and again: the slides of its
//! walk, the press into its floor, the ground probe and the snap all start where the last one
//! ended, and the next frame starts there too. A prepared mesh keeps every triangle prepared (92
//! bytes each in `f32` and `I16F16`); a compact mesh or a heightfield prepares each one it
//! reaches anew, which is most of their cost (on a Cortex-M0 the frame of an `I16F16` triangle
//! takes about 4 000 instructions). [`Cached`] puts a [`TriangleCache`] of `N` prepared
//! triangles beside such a geometry: a triangle found in it is cast at once (the box, plane and
//! heights culls before the preparation are passed by too), one prepared is kept in it. The
//! answers are the geometry's own, bit for bit: a cached triangle is the one
//! [`StandardTriangle::new`] makes, which is what the uncached query casts.
//!
//! The cache is four-way set-associative: triangle `index` may sit in one of the four slots of
//! a set chosen by a multiplicative hash of the index (Knuth's, *TAOCP* vol. 3, §6.4, which
//! spreads neighbouring cells and rows over the sets), and a triangle prepared replaces the
//! least recently used of its set. (With one slot per triangle, two triangles a character
//! touches every frame can evict each other at every query: a walk of 200 frames on a bumpy
//! 10 × 10 terrain, whose neighbours 21 indices apart often share a slot under this hash,
//! prepared 524 triangles with 32 such slots, and 18 with 32 in sets of four.) Memory: about 104 bytes per slot in `f32` and
//! `I16F16`, 196 in `f64` and `I32F32`
//! (`size_of::<TriangleCache<S, N>>()`); 16 to 64 slots hold what a character touches in a
//! frame. [`TriangleCache::hits`] and [`misses`](TriangleCache::misses) tell how well a size
//! works. A triangle not found is prepared whole to be kept, where the query without a cache
//! prepares the frame first and finishes only a triangle its heights leave in reach: a cache
//! too small to be found in (`N = 0`, or far fewer slots than the triangles a query reaches)
//! costs more than none.
//!
//! A [`Cached`] owns its cache, so it can live wherever the game keeps its level (a field of
//! its state, one per character: each character's cache holds what it touches) and be kept
//! for as long as the queries come back to the same place, across frames: that is where a cache
//! pays. A new `Cached` starts empty. The geometry inside is only ever lent out shared, so the
//! kept triangles are always its own. A cache is not `Sync` (its slots are `Cell`s): one per
//! thread.

use crate::compound::CompoundPart;
use crate::merge::{Earliest, earliest_of};
use crate::{Geometry, Mesh, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};
use core::cell::Cell;

/// No triangle: the key of an empty slot.
const EMPTY: usize = usize::MAX;

/// `N` prepared triangles of one geometry, by index (see the [module docs](self)): the cache a
/// [`Cached`] geometry owns, for its size (`size_of::<TriangleCache<S, N>>()`) and its counts.
pub struct TriangleCache<S: Scalar, const N: usize> {
    keys: [Cell<usize>; N],
    triangles: [Cell<StandardTriangle<S>>; N],
    /// When each slot was last used, by `clock` (zero: never).
    used: [Cell<u32>; N],
    clock: Cell<u32>,
    hits: Cell<u32>,
    misses: Cell<u32>,
}

impl<S: Scalar, const N: usize> TriangleCache<S, N> {
    /// An empty cache.
    pub(crate) fn new() -> Self {
        Self {
            keys: core::array::from_fn(|_| Cell::new(EMPTY)),
            triangles: core::array::from_fn(|_| Cell::new(Mesh::<S>::filler())),
            used: core::array::from_fn(|_| Cell::new(0)),
            clock: Cell::new(0),
            hits: Cell::new(0),
            misses: Cell::new(0),
        }
    }

    /// Triangles found kept since the cache was made (saturating). Each is cast at once,
    /// sparing a preparation, or the culls that would have passed it by unprepared.
    pub fn hits(&self) -> u32 {
        self.hits.get()
    }

    /// Triangles prepared and kept since then (saturating): those not found that the culls
    /// kept. (A triangle not found that the culls pass by counts as neither.)
    pub fn misses(&self) -> u32 {
        self.misses.get()
    }

    pub(crate) fn slots(&self) -> Slots<'_, S> {
        Slots {
            keys: &self.keys,
            triangles: &self.triangles,
            used: &self.used,
            clock: &self.clock,
            hits: &self.hits,
            misses: &self.misses,
        }
    }
}

impl<S: Scalar, const N: usize> core::fmt::Debug for TriangleCache<S, N> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("TriangleCache")
            .field("slots", &N)
            .field("hits", &self.hits())
            .field("misses", &self.misses())
            .finish()
    }
}

/// A [`TriangleCache`] as the forms' queries use it, whatever its size.
#[doc(hidden)]
#[derive(Clone, Copy)]
pub struct Slots<'a, S: Scalar> {
    keys: &'a [Cell<usize>],
    triangles: &'a [Cell<StandardTriangle<S>>],
    used: &'a [Cell<u32>],
    clock: &'a Cell<u32>,
    hits: &'a Cell<u32>,
    misses: &'a Cell<u32>,
}

/// Where a form's query takes and keeps prepared triangles: a cache's [`Slots`], or `()` for
/// none, whose query keeps nothing and pays nothing for it (`ON` is a constant).
pub(crate) trait Keep<S: Scalar>: Copy {
    /// Whether triangles are kept at all.
    const ON: bool;
    /// Triangle `index`, if kept.
    fn get(&self, index: usize) -> Option<StandardTriangle<S>>;
    /// Keeps `triangle`, just prepared, as triangle `index`, in place of another if need be.
    fn put(&self, index: usize, triangle: StandardTriangle<S>);
}

impl<S: Scalar> Keep<S> for () {
    const ON: bool = false;
    fn get(&self, _: usize) -> Option<StandardTriangle<S>> {
        None
    }
    fn put(&self, _: usize, _: StandardTriangle<S>) {}
}

/// Slots per set.
const WAYS: usize = 4;

impl<S: Scalar> Slots<'_, S> {
    /// The slots of triangle `index`'s set: Knuth's multiplicative hash, its top bits scaled to
    /// the set count (in 32 bits where the count allows: a Cortex-M0 multiplies 64 bits in
    /// software); the last set holds what is left of `N` after whole sets of [`WAYS`].
    fn set(&self, index: usize) -> core::ops::Range<usize> {
        let n = self.keys.len();
        let sets = n.div_ceil(WAYS);
        let h = (index as u32 ^ (index as u64 >> 32) as u32).wrapping_mul(0x9E37_79B9);
        let s = if sets <= 1 << 16 {
            (((h >> 16) as usize) * sets) >> 16
        } else {
            ((h as u64 * sets as u64) >> 32) as usize
        };
        s * WAYS..(s * WAYS + WAYS).min(n)
    }

    /// Marks slot `k` used now. (The clock wraps after 2^32 uses: the order of the uses
    /// around it is then misread once, which costs a preparation, never an answer.)
    fn touch(&self, k: usize) {
        let now = self.clock.get().wrapping_add(1);
        self.clock.set(now);
        if let Some(u) = self.used.get(k) {
            u.set(now);
        }
    }
}

impl<S: Scalar> Keep<S> for Slots<'_, S> {
    const ON: bool = true;

    fn get(&self, index: usize) -> Option<StandardTriangle<S>> {
        let ways = self.set(index);
        let k = ways
            .clone()
            .find(|&k| self.keys.get(k).is_some_and(|key| key.get() == index))?;
        let kept = self.triangles.get(k).map(Cell::get)?;
        self.touch(k);
        count(self.hits);
        Some(kept)
    }

    fn put(&self, index: usize, triangle: StandardTriangle<S>) {
        // The least recently used slot of the set (an empty one was never used).
        let age = |k: &usize| self.used.get(*k).map_or(0, Cell::get);
        let Some(k) = self.set(index).min_by_key(age) else {
            return;
        };
        if let (Some(key), Some(t)) = (self.keys.get(k), self.triangles.get(k)) {
            count(self.misses);
            key.set(index);
            t.set(triangle);
            self.touch(k);
        }
    }
}

/// One more, saturating.
fn count(c: &Cell<u32>) {
    c.set(c.get().saturating_add(1));
}

/// A geometry whose queries can keep the triangles they prepare in a [`TriangleCache`]:
/// [`Heightfield`](crate::Heightfield), [`CompactMesh`](crate::CompactMesh), `HeightfieldBuf`
/// (with the `alloc` feature) and a shared reference to any of them (several characters'
/// caches over one terrain).
pub trait Cacheable<S: Scalar>: CompoundPart<S> {
    /// Offers the contacts of the geometry's quick path, taking and keeping prepared triangles
    /// in `cache`; false where it found its parts malformed (then the caller scans).
    #[doc(hidden)]
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool;
}

impl<S: Scalar, T: Cacheable<S> + ?Sized> Cacheable<S> for &T {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool {
        (**self).offer_cached(sweep, acc, cache)
    }
}

/// A geometry with a [`TriangleCache`] of `N` triangles of its own: the same answers, bit for
/// bit, for less work where queries come back to the same triangles (see the
/// [module docs](self)). A [`Geometry`] and a [`CompoundPart`], as the geometry is.
///
/// ```
/// use ballcast::{Cached, Heightfield, Vec3, move_and_slide};
/// let heights = [0i16; 9];
/// let mut cells = [0u8; 4];
/// let ground = Heightfield::build(Vec3::new(-1.0f32, 0.0, -1.0), 1.0, 0.25, 2, 2, &heights, |_, _| false, &mut cells)?;
/// let level: Cached<_, _, 16> = Cached::new(ground); // 16 slots
/// let mut at = Vec3::new(-0.5, 0.6, 0.0);
/// for _ in 0..10 {
///     at = move_and_slide(&level, at, Vec3::new(0.05, -0.1, 0.0), 0.5)?.position;
/// }
/// assert!((at.y - 0.5).abs() < 0.01); // resting on the ground
/// let down = ballcast::Sweep::new(at, at - Vec3::new(0.0, 1.0, 0.0), 0.5)?;
/// assert_eq!(level.cast(&down), ground.cast(&down)); // the heightfield's answer
/// let cache = level.cache();
/// assert!(cache.hits() > cache.misses()); // the same few triangles, prepared once
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Cached<G, S: Scalar, const N: usize> {
    geometry: G,
    cache: TriangleCache<S, N>,
}

impl<G: Cacheable<S>, S: Scalar, const N: usize> Cached<G, S, N> {
    /// `geometry` with an empty cache of its own.
    pub fn new(geometry: G) -> Self {
        Self {
            geometry,
            cache: TriangleCache::new(),
        }
    }

    /// The earliest contact along the sweep: the geometry's own answer, bit for bit (the
    /// same as [`Geometry::cast`], without importing the trait).
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        earliest_of(|acc, scan| self.offer_contacts(sweep, acc, scan))
    }

    /// The geometry.
    pub fn geometry(&self) -> &G {
        &self.geometry
    }

    /// The cache (for its [`hits`](TriangleCache::hits) and [`misses`](TriangleCache::misses)).
    pub fn cache(&self) -> &TriangleCache<S, N> {
        &self.cache
    }

    /// The geometry, the cache dropped.
    pub fn into_geometry(self) -> G {
        self.geometry
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize> Geometry<S> for Cached<G, S, N> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Cached::cast(self, sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.geometry.visit(min, max, f)
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize> CompoundPart<S> for Cached<G, S, N> {
    fn index_bound(&self) -> usize {
        self.geometry.index_bound()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        if scan {
            self.geometry.offer_contacts(sweep, acc, true)
        } else {
            self.geometry.offer_cached(sweep, acc, self.cache.slots())
        }
    }
}
