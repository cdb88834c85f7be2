//! Many triangles at once: [`Scene`], a fixed-capacity set of prepared triangles with active
//! edges computed from adjacency, and its earliest-contact query.

use crate::compound::CompoundPart;
use crate::merge::{Earliest, PLANES, earliest};
use crate::scalar::{largest, tie};
use crate::seam::seam_margin;
use crate::{Contact, Error, Scalar, StandardTriangle, Sweep, Triangle, Vec3};
use heapless::Vec;

mod edges;

/// An axis-aligned box, `min <= max` per axis.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Bounds<S> {
    min: Vec3<S>,
    max: Vec3<S>,
}

impl<S: Scalar> Bounds<S> {
    fn of(points: &[Vec3<S>], grow: S) -> Self {
        let pick = |f: fn(S, S) -> bool, get: fn(&Vec3<S>) -> S| {
            points
                .iter()
                .map(get)
                .reduce(|a, b| if f(b, a) { b } else { a })
        };
        let lo = |g| pick(|b, a| b < a, g).unwrap_or(S::ZERO) - grow;
        let hi = |g| pick(|b, a| b > a, g).unwrap_or(S::ZERO) + grow;
        Self {
            min: Vec3::new(lo(|p| p.x), lo(|p| p.y), lo(|p| p.z)),
            max: Vec3::new(hi(|p| p.x), hi(|p| p.y), hi(|p| p.z)),
        }
    }

    fn overlaps(&self, o: &Self) -> bool {
        self.min.x <= o.max.x
            && o.min.x <= self.max.x
            && self.min.y <= o.max.y
            && o.min.y <= self.max.y
            && self.min.z <= o.max.z
            && o.min.z <= self.max.z
    }
}

/// The earliest contact of a sweep with a [`Scene`]: a plain `Copy` struct.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(
    feature = "serde",
    serde(
        bound = "S: crate::Scalar",
        try_from = "crate::interop::hit::SceneHitRead<S>"
    )
)]
pub struct SceneHit<S> {
    /// Fraction of the path travelled at first contact, in `[0, 1)`.
    #[doc(alias = "time_of_impact")]
    #[cfg_attr(feature = "serde", serde(with = "crate::interop::number"))]
    pub alpha: S,
    /// The ball's centre at first contact (see [`Hit::position`](crate::Hit::position)): that
    /// of the contact reported, triangle `index`'s. Where several triangles' contacts round to
    /// the same alpha, the one whose position comes first along the path is reported, so the
    /// position keeps `Hit::position`'s accuracy on long paths too.
    pub position: Vec3<S>,
    /// Unit contact normal; where several triangles are touched at the same moment (alphas
    /// within four steps of the scalar's resolution and positions within twice
    /// [`Precision::position_error`](crate::Precision::position_error) of each other), the
    /// normalised sum of their normals in index order. On a convex mesh a face touched that
    /// much later has a normal within `acos(1 - window / r)` of the first contact's: in
    /// `I16F16`, where the window is 2.4e-4, a ball of 0.01 sees up to 0.16 rad between the
    /// merged normal and the first contact's (a sphere's edges and vertices on paths of 50).
    pub normal: Vec3<S>,
    /// The feature touched on triangle `index` (the earliest of simultaneous contacts).
    pub contact: Contact,
    /// Index of the touched triangle, in the order pushed: among equal alphas, the contact
    /// first along the path, the smallest index where those are equal too.
    pub index: usize,
    /// The distinct planes touched at this moment (normals of the simultaneous contacts, in
    /// index order, nearly parallel ones once): what a response must not move into. The first
    /// is always `Some`.
    pub planes: [Option<Vec3<S>>; PLANES],
}

/// Up to `N` prepared triangles, stored inline (no allocation), queried together.
///
/// Each [`push`](Self::push) validates and standardizes the triangle and updates the active
/// edges of it and its neighbours: an edge shared (same two vertices, opposite winding) with a
/// neighbour that continues the surface flat (normals within about 1e-3 rad) or folds towards
/// the front (a valley) can never be touched first, so it is switched off; ridges and open
/// edges stay active. A vertex stays active while one of the triangle's two edges at it does.
/// A ball rolling over a tiled floor therefore only ever sees the floor's normal.
///
/// Queries stream through a compact array of bounding boxes first; only triangles whose box
/// meets the sweep's are tested in full: a linear scan, and each push compares the triangle
/// with every earlier one, so a `Scene` suits rooms and small levels (up to a few hundred
/// triangles). Storage is inline: 152 bytes per triangle of capacity in `f32` and `I16F16`
/// (304 in `f64` and `I32F32`: the prepared triangle, its source and its box), so a
/// `Scene<f32, 65_536>` is 10 MB, more than a thread's stack holds (`Box::new(Scene::new())`
/// builds it on the stack first, in a debug build). Whole levels belong in a
/// [`Mesh`](crate::Mesh): a tree over caller-provided buffers, 103 bytes per triangle in `f32`.
///
/// ```
/// use ballcast::{Contact, Scene, Sweep, Triangle, Vec3};
/// let v = Vec3::new;
/// let mut floor: Scene<f32, 8> = Scene::new();
/// // Two triangles tiling a square floor, facing +y, sharing the edge (0,0,0)-(2,0,2).
/// floor.push(Triangle::new(v(0.0, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 2.0)))?;
/// floor.push(Triangle::new(v(0.0, 0.0, 0.0), v(2.0, 0.0, 2.0), v(2.0, 0.0, 0.0)))?;
/// // The shared diagonal is inactive in both.
/// assert!(!floor.triangle(0).unwrap().features().edge(2));
/// let hit = floor.cast(&Sweep::new(v(1.0, 3.0, 1.0), v(1.0, -1.0, 1.0), 0.5)?).unwrap();
/// assert_eq!((hit.alpha, hit.normal, hit.contact), (0.625, v(0.0, 1.0, 0.0), Contact::Face));
/// # Ok::<(), ballcast::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Scene<S: Scalar, const N: usize> {
    bounds: Vec<Bounds<S>, N>,
    triangles: Vec<StandardTriangle<S>, N>,
    sources: Vec<Triangle<S>, N>,
}

impl<S: Scalar, const N: usize> Default for Scene<S, N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<S: Scalar, const N: usize> Scene<S, N> {
    /// An empty scene.
    pub const fn new() -> Self {
        Self {
            bounds: Vec::new(),
            triangles: Vec::new(),
            sources: Vec::new(),
        }
    }

    /// Removes every triangle, keeping the capacity.
    pub fn clear(&mut self) {
        self.bounds.clear();
        self.triangles.clear();
        self.sources.clear();
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Whether the scene holds no triangle.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The prepared triangle at `index`.
    pub fn triangle(&self, index: usize) -> Option<&StandardTriangle<S>> {
        self.triangles.get(index)
    }

    /// The triangles as pushed, in order.
    pub fn sources(&self) -> impl Iterator<Item = Triangle<S>> + '_ {
        self.sources.iter().copied()
    }

    /// Whether each triangle, in order, is two-sided.
    pub fn sidedness(&self) -> impl Iterator<Item = bool> + '_ {
        self.triangles.iter().map(|t| t.is_two_sided())
    }

    /// Adds a one-sided triangle and returns its index.
    ///
    /// One-sided is the default: the triangle stops balls coming from its front, where
    /// `(v1 - v0) × (v2 - v0)` points (vertices counter-clockwise seen from the front), and lets
    /// them through from behind. Check a level's winding against a point known to be above its
    /// floor or inside its rooms with [`winding`](crate::winding()); use
    /// [`push_two_sided`](Self::push_two_sided) for triangles that must stop balls either way.
    ///
    /// Errors: those of [`StandardTriangle::new`], naming the index the triangle would have
    /// had ([`Error::triangle`]), or [`Error::Full`] with the capacity `N`.
    pub fn push(&mut self, t: Triangle<S>) -> Result<usize, Error> {
        self.push_sided(t, false)
    }

    /// Adds a triangle that stops balls from both sides; edges are still deactivated against
    /// flat neighbours only, since a valley on one side is a ridge on the other.
    /// Errors as for [`push`](Self::push).
    pub fn push_two_sided(&mut self, t: Triangle<S>) -> Result<usize, Error> {
        self.push_sided(t, true)
    }

    /// [`push`](Self::push) or [`push_two_sided`](Self::push_two_sided), as `two_sided` says.
    pub fn push_sided(&mut self, t: Triangle<S>, two_sided: bool) -> Result<usize, Error> {
        let index = self.triangles.len();
        let st = StandardTriangle::new(&t).map_err(|e| e.at(index))?;
        if self.triangles.is_full() {
            return Err(Error::Full { capacity: N });
        }
        let st = st.with_two_sided(two_sided);
        let bounds = Bounds::of(&[t.v0, t.v1, t.v2], rounding(&t.vertices()));
        // Capacity was checked: none of these can fail.
        let _ = (
            self.bounds.push(bounds),
            self.triangles.push(st),
            self.sources.push(t),
        );
        self.edges_against_earlier(index);
        Ok(index)
    }

    /// Removes the triangle at `index` and returns it as it was pushed (its sidedness was
    /// [`triangle(index)`](Self::triangle)`.is_two_sided()`); the triangles after it move down
    /// one index, as in `Vec::remove`. `None`, the scene unchanged, for an index beyond it.
    ///
    /// Every active edge is then found anew, as if the scene had been built without it (an
    /// edge the triangle hid is active again): the cost of building the scene again, which
    /// grows with the square of its length (in `f32` on a PC, about 2 ms for 512 triangles of
    /// a terrain, 15 ms for 2 048). Keep what
    /// changes at run time, a door or a breakable wall, in a small scene of its own beside the
    /// level ([`Compound`](crate::Compound)), and take several triangles out at once with
    /// [`retain`](Self::retain). Indices kept from before (a [`SceneHit::index`], a
    /// character's floor) name other triangles afterwards, and a triangle pushed back comes
    /// last, so ties between simultaneous contacts may then be reported by another index.
    pub fn remove(&mut self, index: usize) -> Option<Triangle<S>> {
        let removed = self.sources.get(index).copied()?;
        self.retain(|i, _| i != index);
        Some(removed)
    }

    /// Keeps the triangles for which `keep(index, triangle as pushed)` is true, in order, and
    /// finds every active edge anew once, as [`remove`](Self::remove) does for one: the scene
    /// as if built from the triangles kept. Returns how many were taken out.
    pub fn retain(&mut self, mut keep: impl FnMut(usize, &Triangle<S>) -> bool) -> usize {
        let mut kept = 0;
        for i in 0..self.len() {
            if !keep(i, &self.sources[i]) {
                continue;
            }
            self.bounds[kept] = self.bounds[i];
            self.triangles[kept] = self.triangles[i];
            self.sources[kept] = self.sources[i];
            kept += 1;
        }
        let removed = self.len() - kept;
        if removed > 0 {
            self.bounds.truncate(kept);
            self.triangles.truncate(kept);
            self.sources.truncate(kept);
            self.active_edges_anew();
        }
        removed
    }

    /// The earliest contact of the sweep with any triangle, or `None`.
    ///
    /// Contacts within four steps of the scalar's resolution of the earliest alpha, and within
    /// twice the position's rounding of its position, arrive together: their normals are
    /// summed in index order and normalised, so a ball landing on a seam gets one well-defined
    /// normal, and their distinct planes are listed for a response ([`SceneHit`]). The rule
    /// depends on the set of contacts, not on the order they are found in.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        earliest(sweep, |acc| self.offer(sweep, acc))
    }

    /// Offers the contact of every triangle whose box the path's grown box meets.
    fn offer(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>) {
        let reach = Bounds::of(&[sweep.p0(), sweep.p1()], reach(sweep));
        for (i, (b, t)) in self.bounds.iter().zip(self.triangles.iter()).enumerate() {
            if b.overlaps(&reach)
                && let Some(hit) = t.cast(sweep)
            {
                acc.offer(i, hit);
            }
        }
    }
}

/// How far from the path's box a triangle's box may lie and the triangle still report a
/// contact: the radius, the seam margin by which faces are widened along inactive edges
/// (`r / 64 + 4 EPSILON`, bounded by the triangle's box grown by as much), and the rounding of
/// the contact tests (sixteen height errors at the path's magnitude, and four steps of alpha
/// twice over the path's length), so the box test never drops a contact the triangle reports.
/// The heights' rounding at the triangle's own magnitude (its frame's origin can lie far from
/// the path) grows the triangle's box instead: see [`rounding`]; `reach`'s sixteen height
/// errors are the path's share.
fn reach<S: Scalar>(sweep: &Sweep<S>) -> S {
    let (p0, p1, r) = (sweep.p0(), sweep.p1(), sweep.radius());
    let d = p1 - p0;
    let steps = tie::<S>().mul(d.abs().max_element());
    r + seam_margin(r) + rounding(&[p0, p1, Vec3::new(r, r, r)]) + steps + steps
}

/// How far a box is grown for the rounding of heights at its points' coordinates: sixteen
/// height errors at their largest. A triangle's box takes its share at its own coordinates, a
/// query's (the path's in [`reach`], a box's in `visit`) at its: the two add up to the
/// rounding at the larger of the two.
fn rounding<S: Scalar>(points: &[Vec3<S>]) -> S {
    let size = |m: S, p: &Vec3<S>| largest(m, p.abs().max_element(), S::ZERO);
    let mut e = S::height_error(points.iter().fold(S::ZERO, size));
    for _ in 0..4 {
        e = e + e;
    }
    e
}

/// Anything a ball can be cast against: a [`Scene`], or a slice of prepared triangles such as
/// a `static` baked into flash with [`StandardTriangle::from_parts`].
pub trait Geometry<S: Scalar> {
    /// The earliest contact along the sweep, simultaneous contacts merged as in [`Scene::cast`].
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>>;

    /// Calls `f` with the index and prepared form of every triangle that may meet the box
    /// from `min` to `max` (at least those that do; in any order): what
    /// [`penetration`](crate::penetration::penetration) and [`winding`](crate::winding()) examine.
    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>));
}

impl<S: Scalar, const N: usize> Geometry<S> for Scene<S, N> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        Scene::cast(self, sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        let reach = Bounds::of(&[min, max], rounding(&[min, max]));
        for (i, (b, t)) in self.bounds.iter().zip(self.triangles.iter()).enumerate() {
            if b.overlaps(&reach) {
                f(i, t);
            }
        }
    }
}

/// A slice has no bounding boxes to reject with, so every triangle is tested: fine for the
/// small scenes firmware keeps in flash.
impl<S: Scalar> Geometry<S> for [StandardTriangle<S>] {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        earliest(sweep, |acc| {
            self.offer_contacts(sweep, acc, true);
        })
    }

    fn visit(&self, _: Vec3<S>, _: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.iter().enumerate().for_each(|(i, t)| f(i, t));
    }
}

impl<S: Scalar, const N: usize> CompoundPart<S> for Scene<S, N> {
    fn index_bound(&self) -> usize {
        self.len()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: bool) -> bool {
        self.offer(sweep, acc);
        true
    }
}

impl<S: Scalar> CompoundPart<S> for [StandardTriangle<S>] {
    fn index_bound(&self) -> usize {
        self.len()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, _: bool) -> bool {
        for (i, t) in self.iter().enumerate() {
            if let Some(hit) = t.cast(sweep) {
                acc.offer(i, hit);
            }
        }
        true
    }
}
