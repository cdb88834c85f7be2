//! [`Cached`]: a geometry with a [`TriangleCache`] beside it, and [`Cacheable`], the geometries
//! it can hold.

use super::{Slots, TriangleCache};
use crate::compound::{Compound, CompoundPart};
use crate::merge::{Earliest, earliest_of};
use crate::{Geometry, Mesh, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};
use core::borrow::Borrow;
use core::fmt;
use core::marker::PhantomData;

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
/// [module docs](super)). A [`Geometry`] and a [`CompoundPart`], as the geometry is. Cache a
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
        earliest_of(sweep, |acc, scan| self.offer_contacts(sweep, acc, scan))
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
