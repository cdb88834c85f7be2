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

use crate::{Mesh, Scalar, StandardTriangle};
use core::cell::Cell;
use core::fmt;
use core::ops::Range;

mod cached;

pub use cached::{Cacheable, Cached};

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
