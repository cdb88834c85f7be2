//! A level made of parts: a [`Compound`] casts against two geometries as one, for a terrain
//! kept as a [`Heightfield`](crate::Heightfield) with the buildings on it in a
//! [`Mesh`](crate::Mesh) or [`CompactMesh`](crate::CompactMesh), or a flash level with a few
//! triangles in RAM beside it.
//!
//! Both parts offer their contacts to one accumulator, so the answer is the one a single
//! geometry holding the same prepared triangles would give: the earliest contact, and the
//! contacts tied with it merged by the rule of [`Scene::cast`](crate::Scene::cast), whichever
//! part they come from. A ball wedged between the terrain and a wall gets both planes in
//! [`SceneHit::planes`](crate::SceneHit::planes), and `move_and_slide` slides along the crease
//! as it would in one mesh. The second part is culled by the earliest contact the first found.
//! Compounds nest: `Compound::new(Compound::new(a, b)?, c)?`.
//!
//! Active edges are each part's own: an edge that two parts share (a building's floor that
//! meets the terrain's triangles edge to edge) stays active in both, where one mesh of all the
//! triangles would switch a flat or valley seam off, and a ball rolling over it can catch on it
//! as on a ridge. Keep triangles that share edges in one part; parts that touch without sharing
//! edges (a wall standing on the ground, a crate on it) lose nothing.
//!
//! Indices: the first part's hits and visits keep their indices; the second's follow them,
//! from [`Compound::offset`] (the first's [`CompoundPart::index_bound`]). Engines name the
//! same idea a sub-shape ID (Jolt's `SubShapeID` in its compound shapes); here it is one number.

use crate::merge::{Earliest, earliest_of};
use crate::{Error, Geometry, Hit, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};

/// A geometry that can be a part of a [`Compound`]: every geometry of this crate, a reference
/// to one, and a compound. Your own [`Geometry`] can be one too: implement
/// [`index_bound`](Self::index_bound); its [`cast`](Geometry::cast) is then taken as one contact
/// (its merged normal counts once in a tie with the other part's).
pub trait CompoundPart<S: Scalar>: Geometry<S> {
    /// One more than the largest index the part's hits and visits report (zero when empty):
    /// a compound numbers its second part's triangles from there. For a mesh, one more than
    /// its largest *kept* input index (a degenerate triangle skipped at the end of the input
    /// takes no number); for a heightfield, two per cell, holes included.
    fn index_bound(&self) -> usize;

    /// Offers the part's contacts with the sweep to `acc` (by its quick path; with `scan`,
    /// by testing every triangle); false where the quick path found the part malformed.
    #[doc(hidden)]
    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        let _ = scan;
        if let Some(h) = self.cast(sweep) {
            let hit = Hit {
                alpha: h.alpha,
                position: h.position,
                normal: h.normal,
                contact: h.contact,
            };
            acc.offer(h.index, hit);
        }
        true
    }
}

/// Two geometries cast against as one (see the [module docs](self)). Its parts are fixed at
/// construction: the second's indices are numbered from the first's bound, which
/// [`new`](Self::new) reads once.
///
/// ```
/// use ballcast::{Compound, PartIndex, Scene, Triangle, Sweep, Vec3};
/// let v = Vec3::new;
/// // A floor in one part, a wall (the plane x = 1, facing -x) standing on it in another.
/// let mut floor: Scene<f32, 2> = Scene::new();
/// floor.push(Triangle::new(v(-5.0, 0.0, -5.0), v(-5.0, 0.0, 5.0), v(5.0, 0.0, 5.0)))?;
/// floor.push(Triangle::new(v(-5.0, 0.0, -5.0), v(5.0, 0.0, 5.0), v(5.0, 0.0, -5.0)))?;
/// let mut wall: Scene<f32, 1> = Scene::new();
/// wall.push(Triangle::new(v(1.0, -1.0, -5.0), v(1.0, 0.0, 5.0), v(1.0, 5.0, -5.0)))?;
/// let level = Compound::new(&floor, &wall)?;
/// assert_eq!(level.offset(), 2); // the wall is triangle 2
/// // Down into the corner: the floor and the wall at once, half way.
/// let hit = level.cast(&Sweep::new(v(0.0, 1.0, 0.0), v(1.0, 0.0, 0.0), 0.5)?).unwrap();
/// assert_eq!(hit.alpha, 0.5);
/// assert_eq!(level.locate(hit.index), PartIndex::First(1)); // first along the path, then the smaller index
/// assert_eq!(hit.planes.iter().flatten().count(), 2); // both planes, for the slide
/// assert!((hit.normal.x + hit.normal.y).abs() < 1e-6); // between them
/// # Ok::<(), ballcast::Error>(())
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Compound<A, B> {
    first: A,
    second: B,
    offset: usize,
    bound: usize,
}

/// Which part of a [`Compound`] an index names, and its index there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PartIndex {
    /// The first part's triangle.
    First(usize),
    /// The second part's triangle.
    Second(usize),
}

impl<A, B> Compound<A, B> {
    /// The two parts as one geometry.
    ///
    /// Errors: [`Error::Full`] when the two index spaces together exceed `usize` (on a 32-bit
    /// target, parts of more than 2^32 triangles in all).
    pub fn new<S: Scalar>(first: A, second: B) -> Result<Self, Error>
    where
        A: CompoundPart<S>,
        B: CompoundPart<S>,
    {
        let offset = first.index_bound();
        let bound = offset.checked_add(second.index_bound());
        let bound = bound.ok_or(Error::Full {
            capacity: usize::MAX,
        })?;
        Ok(Self {
            first,
            second,
            offset,
            bound,
        })
    }

    /// The first part.
    pub const fn first(&self) -> &A {
        &self.first
    }

    /// The second part.
    pub const fn second(&self) -> &B {
        &self.second
    }

    /// The index the second part's triangles are numbered from.
    pub const fn offset(&self) -> usize {
        self.offset
    }

    /// One more than the largest index the compound reports: its second part's bound after
    /// the offset.
    pub const fn index_bound(&self) -> usize {
        self.bound
    }

    /// The part an index of a hit or a visit names, and its index there (in a nested compound,
    /// locate it again in that part).
    pub const fn locate(&self, index: usize) -> PartIndex {
        if index < self.offset {
            PartIndex::First(index)
        } else {
            PartIndex::Second(index - self.offset)
        }
    }

    /// The earliest contact along the sweep with either part; simultaneous contacts merged
    /// across both as one geometry would merge them.
    pub fn cast<S: Scalar>(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>>
    where
        A: CompoundPart<S>,
        B: CompoundPart<S>,
    {
        earliest_of(sweep, |acc, scan| self.offer_contacts(sweep, acc, scan))
    }
}

impl<S: Scalar, A: CompoundPart<S>, B: CompoundPart<S>> Geometry<S> for Compound<A, B> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Compound::cast(self, sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.first.visit(min, max, f);
        let offset = self.offset;
        self.second
            .visit(min, max, &mut |i, t| f(offset.saturating_add(i), t));
    }
}

impl<S: Scalar, A: CompoundPart<S>, B: CompoundPart<S>> CompoundPart<S> for Compound<A, B> {
    fn index_bound(&self) -> usize {
        Compound::index_bound(self)
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        self.offer_parts(
            acc,
            |a, acc| a.offer_contacts(sweep, acc, scan),
            |b, _, acc| b.offer_contacts(sweep, acc, scan),
        )
    }
}

impl<A, B> Compound<A, B> {
    /// Offers the first part's contacts with `first`, then the second's with `second` (given
    /// the offset its indices start from) with `acc` numbering them after the first's, from
    /// wherever this compound's own start; whether both parts were well formed.
    pub(crate) fn offer_parts<S: Scalar>(
        &self,
        acc: &mut Earliest<S>,
        first: impl FnOnce(&A, &mut Earliest<S>) -> bool,
        second: impl FnOnce(&B, usize, &mut Earliest<S>) -> bool,
    ) -> bool {
        let first = first(&self.first, acc);
        let base = acc.rebase(0);
        acc.rebase(base.saturating_add(self.offset));
        let second = second(&self.second, self.offset, acc);
        acc.rebase(base);
        first && second
    }
}

impl<S: Scalar, T: CompoundPart<S> + ?Sized> CompoundPart<S> for &T {
    fn index_bound(&self) -> usize {
        (**self).index_bound()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        (**self).offer_contacts(sweep, acc, scan)
    }
}

impl<S: Scalar, T: Geometry<S> + ?Sized> Geometry<S> for &T {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        (**self).cast(sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        (**self).visit(min, max, f)
    }
}
