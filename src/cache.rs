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
//! The cache is direct-mapped: triangle `index` has one slot, chosen by a multiplicative hash of
//! the index (Knuth's, *TAOCP* vol. 3, §6.4), so neighbouring cells and rows spread over the
//! slots; a triangle prepared where another is kept replaces it. Memory: about 100 bytes per
//! slot in `f32` and `I16F16`, 190 in `f64` and `I32F32`
//! (`size_of::<TriangleCache<S, N>>()`); 16 to 64 slots hold what a character touches in a
//! frame. [`TriangleCache::hits`] and [`misses`](TriangleCache::misses) tell how well a size
//! works. A triangle not found is prepared whole to be kept, where the query without a cache
//! prepares the frame first and finishes only a triangle its heights leave in reach: a cache
//! too small to be found in (`N = 0`, or far fewer slots than the triangles a query reaches)
//! costs more than none.
//!
//! [`Cached`] borrows its cache, so the geometry and the cache live side by side (a local of
//! the game loop, or two fields of a level lent together); keep the `Cached` for as long as
//! the queries come back to the same place (across frames), since lending empties the cache.
//! A cache is not `Sync` (its slots are `Cell`s): one per thread.

use crate::compound::CompoundPart;
use crate::merge::{Earliest, earliest_of};
use crate::{Geometry, Mesh, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};
use core::cell::Cell;

/// No triangle: the key of an empty slot.
const EMPTY: usize = usize::MAX;

/// `N` prepared triangles of one geometry, by index (see the [module docs](self)). Lend it to a
/// [`Cached`] geometry, which empties it first.
pub struct TriangleCache<S: Scalar, const N: usize> {
    keys: [Cell<usize>; N],
    triangles: [Cell<StandardTriangle<S>>; N],
    hits: Cell<u32>,
    misses: Cell<u32>,
}

impl<S: Scalar, const N: usize> TriangleCache<S, N> {
    /// An empty cache.
    pub fn new() -> Self {
        Self {
            keys: core::array::from_fn(|_| Cell::new(EMPTY)),
            triangles: core::array::from_fn(|_| Cell::new(Mesh::<S>::filler())),
            hits: Cell::new(0),
            misses: Cell::new(0),
        }
    }

    /// Triangles found kept since the cache was lent out (saturating). Each is cast at once,
    /// sparing a preparation, or the culls that would have passed it by unprepared.
    pub fn hits(&self) -> u32 {
        self.hits.get()
    }

    /// Triangles prepared and kept since then (saturating): those not found that the culls
    /// kept. (A triangle not found that the culls pass by counts as neither.)
    pub fn misses(&self) -> u32 {
        self.misses.get()
    }

    /// Forgets every triangle and the counts.
    fn clear(&mut self) {
        self.keys.iter().for_each(|k| k.set(EMPTY));
        self.hits.set(0);
        self.misses.set(0);
    }

    pub(crate) fn slots(&self) -> Slots<'_, S> {
        Slots {
            keys: &self.keys,
            triangles: &self.triangles,
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

impl<S: Scalar, const N: usize> Default for TriangleCache<S, N> {
    fn default() -> Self {
        Self::new()
    }
}

/// A [`TriangleCache`] as the forms' queries use it, whatever its size.
#[doc(hidden)]
#[derive(Clone, Copy)]
pub struct Slots<'a, S: Scalar> {
    keys: &'a [Cell<usize>],
    triangles: &'a [Cell<StandardTriangle<S>>],
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
    /// Keeps `triangle`, just prepared, as triangle `index`, in place of the one in its slot.
    fn put(&self, index: usize, triangle: StandardTriangle<S>);
}

impl<S: Scalar> Keep<S> for () {
    const ON: bool = false;
    fn get(&self, _: usize) -> Option<StandardTriangle<S>> {
        None
    }
    fn put(&self, _: usize, _: StandardTriangle<S>) {}
}

impl<S: Scalar> Slots<'_, S> {
    /// The slot of triangle `index`: Knuth's multiplicative hash, its top bits scaled to the
    /// slot count (in 32 bits where the count allows: a Cortex-M0 multiplies 64 bits in software).
    fn slot(&self, index: usize) -> usize {
        let n = self.keys.len();
        let h = (index as u32 ^ (index as u64 >> 32) as u32).wrapping_mul(0x9E37_79B9);
        if n <= 1 << 16 {
            (((h >> 16) as usize) * n) >> 16
        } else {
            ((h as u64 * n as u64) >> 32) as usize
        }
    }
}

impl<S: Scalar> Keep<S> for Slots<'_, S> {
    const ON: bool = true;

    fn get(&self, index: usize) -> Option<StandardTriangle<S>> {
        let k = self.slot(index);
        let found = self.keys.get(k).is_some_and(|key| key.get() == index);
        let kept = found
            .then(|| self.triangles.get(k).map(Cell::get))
            .flatten();
        if kept.is_some() {
            count(self.hits);
        }
        kept
    }

    fn put(&self, index: usize, triangle: StandardTriangle<S>) {
        let k = self.slot(index);
        if let (Some(key), Some(t)) = (self.keys.get(k), self.triangles.get(k)) {
            count(self.misses);
            key.set(index);
            t.set(triangle);
        }
    }
}

/// One more, saturating.
fn count(c: &Cell<u32>) {
    c.set(c.get().saturating_add(1));
}

/// A geometry whose queries can keep the triangles they prepare in a [`TriangleCache`]:
/// [`Heightfield`](crate::Heightfield) and [`CompactMesh`](crate::CompactMesh).
pub trait Cacheable<S: Scalar>: CompoundPart<S> {
    /// Offers the contacts of the geometry's quick path, taking and keeping prepared triangles
    /// in `cache`; false where it found its parts malformed (then the caller scans).
    #[doc(hidden)]
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool;
}

/// A geometry with a [`TriangleCache`] beside it: the same answers, bit for bit, for less work
/// where queries come back to the same triangles (see the [module docs](self)). A
/// [`Geometry`] and a [`CompoundPart`], as the geometry is.
///
/// ```
/// use ballcast::{Cached, Heightfield, TriangleCache, Vec3, move_and_slide};
/// let heights = [0i16; 9];
/// let mut cells = [0u8; 4];
/// let ground = Heightfield::build(Vec3::new(-1.0f32, 0.0, -1.0), 1.0, 0.25, 2, 2, &heights, |_, _| false, &mut cells)?;
/// let mut cache: TriangleCache<f32, 16> = TriangleCache::new();
/// let level = Cached::new(ground, &mut cache);
/// let mut at = Vec3::new(-0.5, 0.6, 0.0);
/// for _ in 0..10 {
///     at = move_and_slide(&level, at, Vec3::new(0.05, -0.1, 0.0), 0.5)?.position;
/// }
/// assert!((at.y - 0.5).abs() < 0.01); // resting on the ground
/// let down = ballcast::Sweep::new(at, at - Vec3::new(0.0, 1.0, 0.0), 0.5)?;
/// assert_eq!(level.cast(&down), ground.cast(&down)); // the heightfield's answer
/// assert!(cache.hits() > cache.misses()); // the same few triangles, prepared once
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug)]
pub struct Cached<'c, G, S: Scalar, const N: usize> {
    geometry: G,
    cache: &'c TriangleCache<S, N>,
}

impl<'c, G: Cacheable<S>, S: Scalar, const N: usize> Cached<'c, G, S, N> {
    /// `geometry` with `cache` beside it, emptied first (it may hold another geometry's
    /// triangles). The cache stays lent for as long as this lives: its triangles are always
    /// this geometry's.
    pub fn new(geometry: G, cache: &'c mut TriangleCache<S, N>) -> Self {
        cache.clear();
        Self { geometry, cache }
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
        self.cache
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize> Geometry<S> for Cached<'_, G, S, N> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Cached::cast(self, sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.geometry.visit(min, max, f)
    }
}

impl<G: Cacheable<S>, S: Scalar, const N: usize> CompoundPart<S> for Cached<'_, G, S, N> {
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
