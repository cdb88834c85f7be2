//! [`HeightfieldBuf`]: a [`Heightfield`] that owns its heights and cell bytes, for PCs (feature
//! `alloc`).

use super::{Heightfield, HeightfieldError, HeightfieldShape};
use crate::cache::Slots;
use crate::compound::CompoundPart;
use crate::merge::Earliest;
use crate::{Cacheable, Geometry, Scalar, SceneHit, StandardTriangle, Sweep, Vec3};
use alloc::vec;
use alloc::vec::Vec;

/// A heightfield owning its heights and cell bytes on the heap: [`Heightfield::build`] with
/// the cell buffer allocated for you, to keep in a game's level struct beside the rest (a
/// [`Heightfield`] borrows both, so it cannot sit next to them). Lend it out with
/// [`heightfield`](Self::heightfield); it is also a [`Geometry`] and a [`CompoundPart`]
/// itself, answering as the heightfield it lends, and [`Cacheable`] (a [`Cached`](crate::Cached)
/// can own it).
///
/// ```
/// use ballcast::{HeightfieldBuf, HeightfieldShape, Sweep, Vec3};
/// // 2 × 2 cells of side 1 around the origin, heights in steps of 0.25: a bump in the middle.
/// let heights = vec![0i16, 0, 0, 0, 4, 0, 0, 0, 0];
/// let shape = HeightfieldShape { origin: Vec3::new(-1.0f32, 0.0, -1.0), spacing: 1.0, unit: 0.25, columns: 2, rows: 2 };
/// let ground = HeightfieldBuf::build(shape, heights, |_, _| false)?;
/// let sweep = Sweep::new(Vec3::new(0.0, 3.0, 0.0), Vec3::new(0.0, -1.0, 0.0), 0.5)?;
/// assert_eq!(ground.heightfield().cast(&sweep).unwrap().position.y, 1.5);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HeightfieldBuf<S: Scalar> {
    shape: HeightfieldShape<S>,
    heights: Vec<i16>,
    cells: Vec<u8>,
    bounds: [i16; 2],
    class: u8,
}

impl<S: Scalar> HeightfieldBuf<S> {
    /// Builds the heightfield of `heights` as [`Heightfield::build`] does (the same arguments,
    /// the heights taken over), its cell bytes in a buffer it allocates.
    ///
    /// Errors: those of [`Heightfield::build`] (never [`HeightfieldError::Capacity`]).
    pub fn build(
        shape: HeightfieldShape<S>,
        heights: Vec<i16>,
        hole: impl Fn(u32, u32) -> bool,
    ) -> Result<Self, HeightfieldError> {
        // The cells `build` needs; none where it refuses the sizes before it looks at them
        // (too many cells, or heights of another count), so nothing large is allocated then.
        let (w, h) = (shape.columns as usize, shape.rows as usize);
        let vertices = (w + 1).checked_mul(h + 1);
        let n = w
            .checked_mul(h)
            .filter(|&n| n <= super::MAX_TRIANGLES / 2 && vertices == Some(heights.len()));
        let mut cells = vec![0u8; n.unwrap_or(0)];
        let built = Heightfield::build(shape, &heights, hole, &mut cells)?;
        let (bounds, class) = (built.bounds(), built.class());
        Ok(Self {
            shape,
            heights,
            cells,
            bounds,
            class,
        })
    }

    /// The heightfield, borrowing these heights and cell bytes.
    pub fn heightfield(&self) -> Heightfield<'_, S> {
        Heightfield::from_parts(
            self.shape,
            &self.heights,
            &self.cells,
            self.bounds,
            self.class,
        )
    }

    /// The earliest contact along the sweep: [`Geometry::cast`] without importing the trait.
    pub fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.heightfield().cast(sweep)
    }
}

impl<S: Scalar> Geometry<S> for HeightfieldBuf<S> {
    fn cast(&self, sweep: &Sweep<S>) -> Option<SceneHit<S>> {
        self.heightfield().cast(sweep)
    }

    fn visit(&self, min: Vec3<S>, max: Vec3<S>, f: &mut dyn FnMut(usize, &StandardTriangle<S>)) {
        self.heightfield().visit(min, max, f)
    }
}

impl<S: Scalar> CompoundPart<S> for HeightfieldBuf<S> {
    fn index_bound(&self) -> usize {
        self.heightfield().index_bound()
    }

    fn offer_contacts(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, scan: bool) -> bool {
        self.heightfield().offer_contacts(sweep, acc, scan)
    }
}

impl<S: Scalar> Cacheable<S> for HeightfieldBuf<S> {
    fn offer_cached(&self, sweep: &Sweep<S>, acc: &mut Earliest<S>, cache: Slots<'_, S>) -> bool {
        self.heightfield().offer_cached(sweep, acc, cache)
    }
}
