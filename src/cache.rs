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
//! prepared 524 triangles with 32 such slots, and 18 with 32 in sets of four.) Memory: about
//! 104 bytes per slot in `f32` and `I16F16`, 196 in `f64` and `I32F32`
//! (`size_of::<TriangleCache<S, N>>()`); 16 to 64 slots hold what a character touches in a
//! frame. [`TriangleCache::hits`] and [`misses`](TriangleCache::misses) tell how well a size
//! works, on the target itself: the same walk, bit for bit, counts other hits and misses on a
//! Cortex-M0, whose culls before preparing a triangle are the integer ones (other triangles are
//! prepared and kept), than on a PC. A triangle not found is prepared whole to be kept, where
//! the query without a cache
//! prepares the frame first and finishes only a triangle its heights leave in reach: a cache
//! too small to be found in (`N = 0`, or far fewer slots than the triangles a query reaches)
//! costs more than none.
//!
//! A [`Cached`] owns its cache, so it can live wherever the game keeps its level (a field of
//! its state, one per character: each character's cache holds what it touches) and be kept
//! for as long as the queries come back to the same place, across frames: that is where a cache
//! pays; or it borrows one kept apart ([`Cached::with_cache`]: a firmware's zero-initialised
//! `static mut`, in RAM and not in flash) for as long as it lives. A new `Cached`
//! starts empty. The geometry inside is only ever lent out shared, so the kept triangles are
//! always its own. A cache is not `Sync` (its slots are `Cell`s): one per thread.

use crate::compound::{Compound, CompoundPart};
use crate::merge::{Earliest, earliest_of};
use crate::{Geometry, Mesh, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};
use core::borrow::Borrow;
use core::cell::Cell;
use core::fmt;
use core::marker::PhantomData;
use core::ops::Range;

/// No triangle: the key of an empty slot. A slot holding triangle `index` has the key
/// `index + 1`, so an empty cache is zero bytes throughout (see [`TriangleCache::new`]).
const EMPTY: usize = 0;

/// `N` prepared triangles of one geometry, by index (see the [module docs](self)): the cache a
/// [`Cached`] geometry owns, for its size (`size_of::<TriangleCache<S, N>>()`) and its counts.
#[derive(Clone)]
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
    /// An empty cache. Every byte of it is zero, so a `static` (or `static mut`) one is
    /// zero-initialised: on a microcontroller it takes RAM (`.bss`) and no flash. Lend it to
    /// a geometry with [`Cached::with_cache`].
    pub const fn new() -> Self {
        Self {
            keys: [const { Cell::new(EMPTY) }; N],
            triangles: [const { Cell::new(Mesh::<S>::filler()) }; N],
            used: [const { Cell::new(0) }; N],
            clock: Cell::new(0),
            hits: Cell::new(0),
            misses: Cell::new(0),
        }
    }

    /// Empties the cache in place (its slots' triangles, never read from an empty slot, are
    /// left as they are) and zeroes its counts.
    fn clear(&self) {
        self.keys.iter().for_each(|k| k.set(EMPTY));
        self.used.iter().for_each(|u| u.set(0));
        for c in [&self.clock, &self.hits, &self.misses] {
            c.set(0);
        }
    }

    /// Triangles found kept since the cache was made or lent (saturating). Each is cast at once,
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
            base: 0,
        }
    }
}

impl<S: Scalar, const N: usize> Default for TriangleCache<S, N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<S: Scalar, const N: usize> fmt::Debug for TriangleCache<S, N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
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
    /// Added to a part's own indices: a compound's second part keeps its triangles under the
    /// indices the compound gives them, apart from the first part's.
    base: usize,
}

/// Where a form's query takes and keeps prepared triangles: a cache's [`Slots`], or `()` for
/// none, whose query keeps nothing and pays nothing for it (`ON` is a constant).
pub(crate) trait Keep<S: Scalar>: Copy {
    /// Whether triangles are kept at all.
    const ON: bool;
    /// Triangle `index`, if kept.
    fn get(&self, index: usize) -> Option<StandardTriangle<S>>;
    /// Keeps `triangle`, just prepared, as triangle `index`, in place of another if need be.
    fn put(&self, index: usize, triangle: &StandardTriangle<S>);
}

impl<S: Scalar> Keep<S> for () {
    const ON: bool = false;
    fn get(&self, _: usize) -> Option<StandardTriangle<S>> {
        None
    }
    fn put(&self, _: usize, _: &StandardTriangle<S>) {}
}

/// Slots per set.
const WAYS: usize = 4;

impl<S: Scalar> Slots<'_, S> {
    /// The same slots for a part whose indices start `by` further on.
    fn shifted(self, by: usize) -> Self {
        let base = self.base.saturating_add(by);
        Self { base, ..self }
    }

    /// Triangle `index` of the part, as the whole cache's index, and its key.
    fn key(&self, index: usize) -> (usize, usize) {
        let index = index.saturating_add(self.base);
        (index, index.wrapping_add(1))
    }

    /// The slots of triangle `index`'s set.
    fn set(&self, index: usize) -> Range<usize> {
        let n = self.keys.len();
        ways(n, set_of(index, (n / WAYS).max(1)))
    }

    /// Marks slot `k` used now. (The clock wraps after 2^32 uses; ages are read modulo 2^32,
    /// so the order holds across the wrap but for a slot left untouched that long, which then
    /// looks young: that costs a preparation, never an answer.)
    fn touch(&self, k: usize) {
        let now = self.clock.get().wrapping_add(1);
        self.clock.set(now);
        if let Some(u) = self.used.get(k) {
            u.set(now);
        }
    }
}

/// Set `s` of the `max(1, n / WAYS)` sets over `n` slots: whole sets of [`WAYS`], the last
/// also taking what is left (up to `2 WAYS - 1` slots; all `n` where `n < WAYS`).
fn ways(n: usize, s: usize) -> Range<usize> {
    let (start, sets) = (s.saturating_mul(WAYS).min(n), (n / WAYS).max(1));
    if s + 1 >= sets {
        start..n
    } else {
        start..start + WAYS
    }
}

/// The set of triangle `index` among `sets`: Knuth's multiplicative hash, its top bits scaled
/// to the set count (in 32 bits where the count allows: a Cortex-M0 multiplies 64 bits in
/// software).
fn set_of(index: usize, sets: usize) -> usize {
    let h = (index as u32 ^ (index as u64 >> 32) as u32).wrapping_mul(0x9E37_79B9);
    if sets <= 1 << 16 {
        (((h >> 16) as usize) * sets) >> 16
    } else {
        ((h as u64).wrapping_mul(sets as u64) >> 32) as usize
    }
}

impl<S: Scalar> Keep<S> for Slots<'_, S> {
    const ON: bool = true;

    fn get(&self, index: usize) -> Option<StandardTriangle<S>> {
        let (index, key) = self.key(index);
        // (A compound's indices stay below `usize::MAX`; were one to reach it, its key would
        // be `EMPTY`, and it is never found.)
        if key == EMPTY {
            return None;
        }
        let ways = self.set(index);
        let k = ways
            .clone()
            .find(|&k| self.keys.get(k).is_some_and(|k| k.get() == key))?;
        let kept = self.triangles.get(k).map(Cell::get)?;
        self.touch(k);
        count(self.hits);
        Some(kept)
    }

    fn put(&self, index: usize, triangle: &StandardTriangle<S>) {
        let (index, key) = self.key(index);
        // An empty slot of the set, else the least recently used.
        let now = self.clock.get();
        let age = |k: &usize| match (self.keys.get(*k), self.used.get(*k)) {
            (Some(slot), _) if slot.get() == EMPTY => u32::MAX,
            (_, Some(used)) => now.wrapping_sub(used.get()),
            _ => 0,
        };
        let Some(k) = self.set(index).max_by_key(age) else {
            return;
        };
        if let (Some(slot), Some(t)) = (self.keys.get(k), self.triangles.get(k)) {
            count(self.misses);
            slot.set(key);
            t.set(*triangle);
            self.touch(k);
        }
    }
}

/// One more, saturating.
fn count(c: &Cell<u32>) {
    c.set(c.get().saturating_add(1));
}

/// A geometry a [`Cached`] can hold: [`Heightfield`](crate::Heightfield) and
/// [`CompactMesh`](crate::CompactMesh) (and, with the `alloc` feature, `HeightfieldBuf` and
/// `CompactMeshBuf`) keep the triangles they prepare; the prepared forms ([`Mesh`], `MeshBuf`,
/// [`Scene`](crate::Scene), slices of prepared triangles) have nothing to keep; a
/// [`Compound`] keeps each part's triangles under the indices it gives them, so a whole level
/// can be cached as one; and a shared reference to any of them (several characters' caches
/// over one level).
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

/// A compound keeps each part's triangles under the indices it gives them.
impl<S: Scalar, A: Cacheable<S>, B: Cacheable<S>> Cacheable<S> for Compound<A, B> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool {
        self.offer_parts(
            acc,
            |a, acc| a.offer_cached(sweep, acc, cache),
            |b, offset, acc| b.offer_cached(sweep, acc, cache.shifted(offset)),
        )
    }
}

/// The prepared forms keep nothing: their quick path as it is, so that a compound of them
/// and the forms that prepare on the spot can be [`Cached`] whole.
impl<S: Scalar> Cacheable<S> for Mesh<'_, S> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: Slots<'_, S>) -> bool {
        self.offer_contacts(sweep, acc, false)
    }
}

impl<S: Scalar> Cacheable<S> for [StandardTriangle<S>] {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: Slots<'_, S>) -> bool {
        self.offer_contacts(sweep, acc, false)
    }
}

impl<S: Scalar, const N: usize> Cacheable<S> for crate::Scene<S, N> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: Slots<'_, S>) -> bool {
        self.offer_contacts(sweep, acc, false)
    }
}

#[cfg(feature = "alloc")]
impl<S: Scalar> Cacheable<S> for crate::MeshBuf<S> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: Slots<'_, S>) -> bool {
        self.offer_contacts(sweep, acc, false)
    }
}

/// A geometry with a [`TriangleCache`] of `N` triangles of its own: the same answers, bit for
/// bit, for less work where queries come back to the same triangles (see the
/// [module docs](self)). A [`Geometry`] and a [`CompoundPart`], as the geometry is. Cache a
/// whole level at once (`Cached::new(Compound::new(terrain, buildings)?)`: the terrain's
/// triangles are kept, the prepared buildings need no keeping) or one part of it
/// (`Compound::new(Cached::new(terrain), buildings)?`).
///
/// ```
/// use ballcast::{Cached, Heightfield, HeightfieldShape, Vec3, move_and_slide};
/// let heights = [0i16; 9];
/// let mut cells = [0u8; 4];
/// let ground = Heightfield::build(HeightfieldShape { origin: Vec3::new(-1.0f32, 0.0, -1.0), spacing: 1.0, unit: 0.25, columns: 2, rows: 2 }, &heights, |_, _| false, &mut cells)?;
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
#[derive(Clone)]
pub struct Cached<G, S: Scalar, const N: usize, C = TriangleCache<S, N>> {
    geometry: G,
    cache: C,
    _scalar: PhantomData<S>,
}

impl<G: Cacheable<S>, S: Scalar, const N: usize> Cached<G, S, N> {
    /// `geometry` with an empty cache of its own. The slot count is part of the type
    /// (`let level: Cached<_, _, 32> = Cached::new(terrain);`): 32 slots take 3.3 KB in `f32`
    /// (3.2 KB on a 32-bit core), 512 in `f64` about 100 KB. As a local, count on up to twice
    /// that on the stack (built, then moved: a Cortex-M0 build took 3 348 bytes of frame for a
    /// 1 664-byte cache); on a microcontroller keep the cache in a `static mut` and lend it
    /// with [`with_cache`](Cached::with_cache).
    pub fn new(geometry: G) -> Self {
        Self::owning(geometry, TriangleCache::new())
    }

    /// [`new`](Self::new) at compile time, for a `static mut` holding the geometry and its
    /// cache together. The geometry's references make the whole `static` initialised data,
    /// which takes its size in flash too (copied to RAM at reset): a cache kept apart, as
    /// [`with_cache`](Cached::with_cache) borrows it, takes RAM alone.
    pub const fn for_static(geometry: G) -> Self {
        Self::owning(geometry, TriangleCache::new())
    }

    const fn owning(geometry: G, cache: TriangleCache<S, N>) -> Self {
        Self {
            geometry,
            cache,
            _scalar: PhantomData,
        }
    }
}

impl<'c, G: Cacheable<S>, S: Scalar, const N: usize> Cached<G, S, N, &'c TriangleCache<S, N>> {
    /// `geometry` with `cache` lent to it, emptied first: the same as [`new`](Cached::new),
    /// the cache kept wherever the caller likes. On a microcontroller, a `static mut` of
    /// cortex-m-rt's `#[entry]` function (handed over as a `&'static mut`, no `unsafe`): an
    /// empty [`TriangleCache`] is zero bytes, so it takes RAM (`.bss`) and no flash, and the
    /// geometry can stay a `static` in flash. The cache starts empty and stays borrowed for as
    /// long as the `Cached` lives (clones share it, over the same geometry): triangles are
    /// kept by index, and another geometry's under the same indices are never found. Its type
    /// names the borrow (`Cached<_, _, 16, _>`: the last parameter defaults to an owned
    /// cache), and it is not `Send` (a cache's slots are `Cell`s).
    ///
    /// ```ignore
    /// #[entry]
    /// fn main() -> ! {
    ///     static mut CACHE: TriangleCache<I16F16, 16> = TriangleCache::new();
    ///     let level = Cached::with_cache(terrain::HEIGHTFIELD, CACHE);
    ///     // ... `me.update(&level, wish, gravity, dt)` every frame
    /// }
    /// ```
    pub fn with_cache(geometry: G, cache: &'c mut TriangleCache<S, N>) -> Self {
        cache.clear();
        Self {
            geometry,
            cache,
            _scalar: PhantomData,
        }
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize, C: Borrow<TriangleCache<S, N>>>
    Cached<G, S, N, C>
{
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
        self.cache.borrow()
    }

    /// The geometry, the cache dropped (or no longer borrowed).
    pub fn into_geometry(self) -> G {
        self.geometry
    }
}

impl<G: fmt::Debug, S: Scalar, const N: usize, C: Borrow<TriangleCache<S, N>>> fmt::Debug
    for Cached<G, S, N, C>
{
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Cached")
            .field("geometry", &self.geometry)
            .field("cache", self.cache.borrow())
            .finish()
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize, C: Borrow<TriangleCache<S, N>>> Geometry<S>
    for Cached<G, S, N, C>
{
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Cached::cast(self, sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.geometry.visit(min, max, f)
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize, C: Borrow<TriangleCache<S, N>>> CompoundPart<S>
    for Cached<G, S, N, C>
{
    fn index_bound(&self) -> usize {
        self.geometry.index_bound()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        if scan {
            self.geometry.offer_contacts(sweep, acc, true)
        } else {
            self.geometry.offer_cached(sweep, acc, self.cache().slots())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Triangle;

    /// Every slot lies in exactly one set, sets of four and the last of up to seven, for every
    /// size; every index's set is one of them.
    #[test]
    fn the_sets_cover_every_slot_once() {
        let sizes = (0..=70).chain([511, 512, 513, 1 << 18, (1 << 18) + 3]);
        for n in sizes {
            let sets = (n / WAYS).max(1);
            let mut next = 0;
            for s in 0..sets {
                let r = ways(n, s);
                assert_eq!(r.start, next, "{n} slots, set {s}");
                assert!(
                    r.len() < 2 * WAYS && (n == 0 || r.len() >= WAYS.min(n)),
                    "{r:?}"
                );
                next = r.end;
            }
            assert_eq!(next, n);
            for index in [0, 1, 21, 1000, 1 << 40, usize::MAX - 1] {
                assert!(set_of(index, sets) < sets, "{n} slots, index {index}");
            }
        }
    }

    /// A triangle found since the others of its set were kept outlives them: the least
    /// recently used is replaced, across the clock's wrap too.
    #[test]
    fn the_least_recently_used_is_replaced() {
        let v = crate::Vec3::new;
        let t = |k: f32| {
            let t = Triangle::new(v(0.0, 0.0, 0.0), v(k, 0.0, 1.0), v(k, 0.0, 0.0));
            StandardTriangle::new(&t).unwrap()
        };
        for clock in [0, u32::MAX - 2] {
            let cache: TriangleCache<f32, 4> = TriangleCache::new();
            cache.clock.set(clock);
            let slots = cache.slots();
            for i in 1..=4 {
                slots.put(i, &t(i as f32));
            }
            assert_eq!(slots.get(1), Some(t(1.0)));
            slots.put(5, &t(5.0));
            assert_eq!(slots.get(2), None, "clock from {clock}");
            for i in [1, 3, 4, 5] {
                assert_eq!(slots.get(i), Some(t(i as f32)), "clock from {clock}");
            }
        }
    }
}
