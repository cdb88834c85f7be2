//! [`CompactMesh`]'s query: the tree walked as [`Mesh::cast`](crate::Mesh::cast) walks it,
//! each triangle of a leaf reached culled, then prepared on the spot and cast (see the
//! [module docs](super)).

use super::{CompactMesh, MeshIndex, TWO_SIDED};
use crate::bvh::{self, Grid};
use crate::cache::{Cacheable, Keep, Slots};
use crate::compound::CompoundPart;
use crate::contact::within_reach;
use crate::cull::{Path, SOFT_F64, UnitBox, UnitHeights};
use crate::merge::{Earliest, earliest_of};
use crate::scalar::{largest, smallest};
use crate::triangle::{Frame, prepare_here};
use crate::{Features, Geometry, Hit, Scalar, SceneHit, StandardTriangle, Sweep, Triangle, Vec3};

impl<S: Scalar, I: MeshIndex> CompactMesh<'_, S, I> {
    /// The earliest contact along the sweep: the prepared mesh's answer, bit for bit.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.cast_culled(sweep, SOFT_F64)
    }

    /// [`cast`](Self::cast), passing triangles by before preparing them with the `f64` box and
    /// plane tests, or (`integer`, for a fixed-point sweep) with its box in integers alone: where
    /// `f64` is software (a Cortex-M) the `f64` tests cost more than the preparations they
    /// save. Either way the answer is the same.
    pub(super) fn cast_culled(&self, sweep: &Sweep<S>, integer: bool) -> Option<SceneHit<S>> {
        earliest_of(sweep, |acc, scan| self.offer(sweep, acc, scan, integer, ()))
    }

    /// Offers the contacts of the triangles the tree reaches, culled as
    /// [`cast_culled`](Self::cast_culled) says (all of them with `scan`), taking and keeping
    /// prepared triangles in `cache` if there is one (by slot); false where the tree proved
    /// malformed (never from `compact`).
    pub(super) fn offer<K: Keep<S>>(
        &self,
        sweep: &Sweep<S>,
        acc: &mut Earliest<S>,
        scan: bool,
        integer: bool,
        cache: K,
    ) -> bool {
        let corners = |s: usize| Some(self.triangles.get(s)?.map(I::get));
        if scan {
            let slot = |s: usize| -> Option<(usize, StandardTriangle<S>)> {
                let st = prepare(self.vertices, corners(s)?, *self.bytes.get(s)?)?;
                Some((self.order.get(s)?.get(), st))
            };
            for s in 0..self.triangles.len() {
                if let Some((i, t)) = slot(s)
                    && let Some(hit) = t.cast(sweep)
                {
                    acc.offer(i, hit);
                }
            }
            return true;
        }
        let cells = self.grid.lo.iter().chain(&self.grid.hi);
        let extent =
            cells.fold(0.0f64, |m, &c| m.max((c as f64).abs())) / Grid::scale(self.grid.exponent);
        // The `f64` path only where it is used: its reciprocals are software on a Cortex-M.
        let units = integer
            .then(|| UnitBox::new(sweep, Path::pad(sweep, extent, self.class)))
            .flatten();
        // Behind the integer box, the heights bounded in integers too (see `cull::heights`).
        let heights = units.as_ref().and_then(|_| UnitHeights::new(sweep));
        let cull = match units {
            Some(b) => Err(b),
            None => Ok(Path::new(sweep, extent, self.class)),
        };
        // Slot `s`'s contact within the reach. Behind the integer box (whose triangles the
        // heights often pass by: it tests no plane) the triangle's frame comes first, and the
        // rest of its preparation only where the heights leave a contact possible; behind the
        // `f64` plane test they seldom do, and the triangle is prepared at once.
        // With a cache the whole triangle is prepared and kept, for the next query.
        let cast_slot = |s: usize, reach: S| -> Option<(usize, Hit<S>)> {
            let byte = *self.bytes.get(s)?;
            let hit = if cull.is_err() && !K::ON {
                let t = triangle(self.vertices, corners(s)?)?;
                cast_lazily(&t, byte, sweep, reach)
            } else {
                let st = prepare(self.vertices, corners(s)?, byte)?;
                cache.put(s, &st);
                st.cast_within(sweep, reach)
            };
            Some((self.order.get(s)?.get(), hit?))
        };
        // Whether slot `s` may hold a contact within the reach (preparing costs far more).
        let near = |acc: &Earliest<S>, s: usize| -> Option<()> {
            let c = corners(s)?;
            let path = match &cull {
                Ok(path) => path,
                Err(b) => {
                    let v = triangle(self.vertices, c)?.vertices();
                    let one_sided = self.bytes.get(s).is_some_and(|b| b & TWO_SIDED == 0);
                    let out = b.misses(v)
                        || heights
                            .as_ref()
                            .is_some_and(|h| h.rule_out(sweep, v, acc.reach(), one_sided));
                    return (!out).then_some(());
                }
            };
            let limit = S::to_f64(acc.reach()) + 1.0 / (1u64 << 50) as f64;
            let v = world(self.vertices, c)?;
            // Coordinates of validated vertices: never NaN.
            let lo = [0, 1, 2].map(|a| smallest(v[0][a], v[1][a], v[2][a]));
            let hi = [0, 1, 2].map(|a| largest(v[0][a], v[1][a], v[2][a]));
            let two_sided = self.bytes.get(s).is_some_and(|b| b & TWO_SIDED != 0);
            let span = path.clip(lo, hi, limit)?;
            path.near_triangle(v, span, !two_sided).then_some(())
        };
        bvh::leaves_along(self.nodes, &self.grid, sweep, acc, |acc, slots, _| {
            for s in slots {
                // A kept triangle is cast at once: its heights cull as the box and plane would.
                if let Some(kept) = cache.get(s) {
                    if let Some(hit) = kept.cast_within(sweep, acc.reach())
                        && let Some(i) = self.order.get(s)
                    {
                        acc.offer(i.get(), hit);
                    }
                } else if near(acc, s).is_some()
                    && let Some((i, hit)) = cast_slot(s, acc.reach())
                {
                    acc.offer(i, hit);
                }
            }
        })
    }
}

/// The corners of `vertices` at `corners` in `f64`, if they exist.
#[inline]
fn world<S: Scalar>(vertices: &[Vec3<S>], corners: [usize; 3]) -> Option<[[f64; 3]; 3]> {
    // Each vertex converted as it is read (an array's `map` here was left out of line, its
    // result stored and loaded back).
    let v = |k: usize| {
        let p = vertices.get(corners[k])?;
        Some([p.x.to_f64(), p.y.to_f64(), p.z.to_f64()])
    };
    Some([v(0)?, v(1)?, v(2)?])
}

/// The triangle of `vertices` at `corners`, if they exist.
fn triangle<S: Scalar>(vertices: &[Vec3<S>], corners: [usize; 3]) -> Option<Triangle<S>> {
    let v = |k: usize| vertices.get(corners[k]).copied();
    Some(Triangle::new(v(0)?, v(1)?, v(2)?))
}

/// The triangle of `vertices` at `corners` prepared with the features and sidedness of `byte`:
/// [`StandardTriangle::new`]'s work, the vertices read here, where it runs (a triangle passed
/// to it in a copy just stored would be read back before the stores complete, a
/// store-forwarding wait on x86-64).
#[inline(never)]
pub(super) fn prepare<S: Scalar>(
    vertices: &[Vec3<S>],
    corners: [usize; 3],
    byte: u8,
) -> Option<StandardTriangle<S>> {
    let t = triangle(vertices, corners)?;
    Some(with_byte(prepare_here(&t).ok()?, byte))
}

/// The contact of `t` (a triangle with `byte`) with the sweep at alpha `reach` or earlier, its
/// preparation finished only if the heights of the sweep above its plane leave one possible.
#[inline(never)]
fn cast_lazily<S: Scalar>(t: &Triangle<S>, byte: u8, sweep: &Sweep<S>, reach: S) -> Option<Hit<S>> {
    let frame = Frame::of(t).ok()?;
    let heights = frame.heights(sweep);
    within_reach(sweep, heights, byte & TWO_SIDED != 0, reach)?;
    with_byte(frame.finish(t).ok()?, byte).cast_within_heights(sweep, heights, reach)
}

/// A prepared triangle with the active edges and sidedness of its byte.
fn with_byte<S: Scalar>(st: StandardTriangle<S>, byte: u8) -> StandardTriangle<S> {
    let features = Features::from_bits(byte & Features::ALL.bits());
    st.with_features(features)
        .with_two_sided(byte & TWO_SIDED != 0)
}

impl<S: Scalar, I: MeshIndex> CompoundPart<S> for CompactMesh<'_, S, I> {
    /// One more than the largest input index held.
    fn index_bound(&self) -> usize {
        self.order
            .iter()
            .fold(0, |m, i| m.max(i.get().saturating_add(1)))
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        self.offer(sweep, acc, scan, SOFT_F64, ())
    }
}

impl<S: Scalar, I: MeshIndex> Cacheable<S> for CompactMesh<'_, S, I> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool {
        self.offer(sweep, acc, false, SOFT_F64, cache)
    }
}

impl<S: Scalar, I: MeshIndex> Geometry<S> for CompactMesh<'_, S, I> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        CompactMesh::cast(self, sweep)
    }

    /// Every triangle of the leaves whose boxes meet the box (the tree's box query) whose
    /// vertices' box meets it too, prepared; the box grown by the tests' rounding first.
    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        let [lo, hi] = self.grid.visit_box(min, max);
        let query = bvh::query_cells(&self.grid, lo, hi);
        // A first walk that only checks the tree, so malformed parts (never from `compact`)
        // are scanned instead without a triangle given twice.
        if bvh::overlapping(self.nodes, &self.grid, query, |_| {}) {
            bvh::overlapping(self.nodes, &self.grid, query, |slots| {
                slots.for_each(|s| self.visit_slot(s, lo, hi, f))
            });
        } else {
            (0..self.triangles.len()).for_each(|s| self.visit_slot(s, lo, hi, f));
        }
    }
}

impl<S: Scalar, I: MeshIndex> CompactMesh<'_, S, I> {
    /// Calls `f` with triangle slot `s`, prepared, if its vertices' box meets `lo..hi`.
    fn visit_slot(
        &self,
        s: usize,
        lo: [f64; 3],
        hi: [f64; 3],
        f: &mut dyn FnMut(usize, &StandardTriangle<S>),
    ) {
        let Some(corners) = self.triangles.get(s) else {
            return;
        };
        let Some(v) = world(self.vertices, corners.map(I::get)) else {
            return;
        };
        let apart = (0..3).any(|a| {
            let (l, u) = (
                v[0][a].min(v[1][a]).min(v[2][a]),
                v[0][a].max(v[1][a]).max(v[2][a]),
            );
            u < lo[a] || l > hi[a]
        });
        if apart {
            return;
        }
        let byte = self.bytes.get(s).copied();
        if let (Some(b), Some(i)) = (byte, self.order.get(s))
            && let Some(st) = prepare(self.vertices, corners.map(I::get), b)
        {
            f(i.get(), &st);
        }
    }
}
