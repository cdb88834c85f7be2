//! [`Heightfield`]: a terrain stored as a grid of 16-bit heights, about 1.5 bytes per triangle,
//! answering exactly as the same triangles in a [`Mesh`](crate::Mesh) or a linear scan.
//!
//! # Layout
//! `columns × rows` square cells of side `spacing` in the x–z plane; vertex `(i, k)` (column `i`
//! along x, row `k` along z) is `origin + (i spacing, heights[k (columns + 1) + i] unit, k spacing)`.
//! Cell `c = k columns + i` holds triangles `2c` and `2c + 1`, split along the diagonal from
//! `(i, k)` to `(i + 1, k + 1)`:
//!
//! ```text
//!  z  (i,k+1) ---- (i+1,k+1)        2c:     (i,k), (i,k+1), (i+1,k+1)
//!  ^     |  2c  /     |             2c + 1: (i,k), (i+1,k+1), (i+1,k)
//!  |     |    /  2c+1 |             counter-clockwise seen from +y: front faces up
//!  |  (i,k) ------ (i+1,k)  -> x
//! ```
//!
//! One byte per cell ([`Heightfield::cells`]) holds the active-edge bits of its two triangles
//! (bits 0–2 and 3–5, edge `e` from vertex `e` to `e + 1`) and the [`HOLE`] bit: a hole cell has
//! no triangles, and the edges around it are open. [`Heightfield::build`] computes the edge bits
//! with the rule of a [`Scene`](crate::Scene) (flat or valley across a shared edge: inactive;
//! ridge or open: active), from the triangles prepared exactly as a mesh would prepare them, so
//! the same triangles give the same answers in every form. Memory: 2 bytes per vertex and 1
//! per cell, about 1.5 bytes per triangle (a prepared triangle is 92 bytes in `f32`).
//!
//! # Query
//! The sweep's footprint in x–z, grown by the radius and a bound on every rounding (as the
//! tree of a [`Mesh`](crate::Mesh) grows its boxes, [`bvh`](crate::bvh)), is walked row by row
//! of cells in the direction of travel, each row only over the columns the grown path crosses
//! within it (a scanline of the swept capsule's bounds). A cell's box, from its four heights, is
//! clipped against the segment by the slab test; a triangle whose box the segment reaches before
//! the earliest contact found so far is prepared on the spot and cast. Rows beyond that contact
//! end the walk. The cost grows with the path's length in cells, not with the grid's size; the
//! answer is the linear scan's, bit for bit, because the bounds are conservative and simultaneous
//! contacts merge in index order whatever the visiting order. Where `f64` is software (a
//! Cortex-M), a fixed-point sweep's short query runs in integers instead (`units.rs`): the
//! cells under the box of its grown path, culled by their heights and each triangle by a bound
//! on the sweep's heights above its plane, the same answer.

#[cfg(feature = "alloc")]
mod buf;
mod build;
mod error;
mod units;
mod walk;

#[cfg(feature = "alloc")]
pub use buf::HeightfieldBuf;
pub use error::HeightfieldError;

use crate::triangle::prepare_here;
use crate::{Features, Scalar, StandardTriangle, Triangle, Vec3};

/// The hole bit of a cell byte: the cell has no triangles.
pub const HOLE: u8 = 1 << 6;
/// Most triangles a heightfield holds (triangle indices stay below 2^31).
pub const MAX_TRIANGLES: usize = 1 << 31;

/// Where a heightfield's grid lies and how its numbers become lengths: plain data, checked by
/// [`Heightfield::build`]. Named fields, so a call cannot swap the columns for the rows or the
/// cell side for the height step.
///
/// Vertex `(i, k)` (column `i` along x, row `k` along z) lies at
/// `origin + (i spacing, unit × its height, k spacing)`.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightfieldShape<S> {
    /// Vertex `(0, 0)` at height 0: the grid's corner of least x and z.
    pub origin: Vec3<S>,
    /// The cells' side along x and z, in world units (positive).
    #[cfg_attr(feature = "serde", serde(with = "crate::interop::number"))]
    pub spacing: S,
    /// The height step: a height of `h` lies `h × unit` above `origin.y` (nonzero).
    #[cfg_attr(feature = "serde", serde(with = "crate::interop::number"))]
    pub unit: S,
    /// Cells along x (at least one).
    pub columns: u32,
    /// Cells along z (at least one).
    pub rows: u32,
}

/// A grid of heights forming a terrain, borrowing its heights and cell bytes.
///
/// Made by [`Heightfield::build`] from heights and holes, or by [`Heightfield::from_parts`] (a
/// `const fn`) from baked ones. See the [module docs](self) for the layout and the query.
///
/// ```
/// use ballcast::{Heightfield, HeightfieldShape, Sweep, Vec3};
/// // 2 × 2 cells of side 1 around the origin, heights in steps of 0.25: a bump in the middle.
/// let heights = [0i16, 0, 0, 0, 4, 0, 0, 0, 0];
/// let mut cells = [0u8; 4];
/// let shape = HeightfieldShape { origin: Vec3::new(-1.0f32, 0.0, -1.0), spacing: 1.0, unit: 0.25, columns: 2, rows: 2 };
/// let ground = Heightfield::build(shape, &heights, |_, _| false, &mut cells)?;
/// let hit = ground.cast(&Sweep::new(Vec3::new(0.0, 3.0, 0.0), Vec3::new(0.0, -1.0, 0.0), 0.5)?).unwrap();
/// assert_eq!(hit.position.y, 1.5); // on the bump's top vertex, height 1
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Heightfield<'a, S: Scalar> {
    origin: Vec3<S>,
    spacing: S,
    unit: S,
    columns: u32,
    rows: u32,
    heights: &'a [i16],
    cells: &'a [u8],
    bounds: [i16; 2],
    class: u8,
}

/// The active edges of triangle `index` (either half of a cell) from its cell's byte.
fn features(byte: u8, index: usize) -> Features {
    Features::of_edges(byte >> (3 * (index % 2)))
}

/// Triangle `half` (0: `2c`, 1: `2c + 1`) of a cell from its corners (see
/// [`Heightfield::corners`]).
fn half<S: Scalar>([a, b, d, e]: [Vec3<S>; 4], half: usize) -> Triangle<S> {
    if half == 0 {
        Triangle::new(a, b, d)
    } else {
        Triangle::new(a, d, e)
    }
}

impl<'a, S: Scalar> Heightfield<'a, S> {
    /// A heightfield from parts made by [`build`](Self::build) (or baked from them), in a
    /// `const` context, so it can be a `static`. Nothing is checked here: check baked parts
    /// against [`build`](Self::build) in a test. Parts from elsewhere can give wrong answers,
    /// never undefined behaviour, and no panic in a release build (with overflow checks on, as
    /// in a debug build, out-of-range parts can trip them, as any integer arithmetic would).
    pub const fn from_parts(
        shape: HeightfieldShape<S>,
        heights: &'a [i16],
        cells: &'a [u8],
        bounds: [i16; 2],
        class: u8,
    ) -> Self {
        Self {
            origin: shape.origin,
            spacing: shape.spacing,
            unit: shape.unit,
            columns: shape.columns,
            rows: shape.rows,
            heights,
            cells,
            bounds,
            class,
        }
    }

    /// Vertex `(column, row)`, if on the grid.
    pub fn vertex(&self, column: u32, row: u32) -> Option<Vec3<S>> {
        let y = self.height(column, row)?;
        let (o, a) = (self.origin, |o: S, n: u32| self.along(o, n));
        Some(Vec3::new(a(o.x, column), y, a(o.z, row)))
    }

    /// The world height of vertex `(column, row)`, if on the grid.
    fn height(&self, column: u32, row: u32) -> Option<S> {
        if column > self.columns || row > self.rows {
            return None;
        }
        let at = (row as usize)
            .checked_mul(self.columns as usize + 1)?
            .checked_add(column as usize)?;
        let h = *self.heights.get(at)?;
        Some(self.origin.y + self.unit.mul(S::from_int(h as i32)))
    }

    /// The world coordinate of grid line `n` along x (or z), from the origin's `o`.
    fn along(&self, o: S, n: u32) -> S {
        // Indices beyond i32 saturate; `build` refuses grids whose indices are not exact.
        o + self.spacing.mul(S::from_int(n.min(i32::MAX as u32) as i32))
    }

    /// Triangle `index` (cell `index / 2`; see the [module docs](self)), holes included: the
    /// triangles the heightfield answers with are those [`prepared`](Self::prepared) gives
    /// (`None` for a hole), or the cell bytes without the [`HOLE`] bit.
    pub fn triangle(&self, index: usize) -> Option<Triangle<S>> {
        let c = index / 2;
        let w = self.columns.max(1) as usize;
        if c >= self.cells_count()? {
            return None;
        }
        let corners = self.corners((c % w) as u32, (c / w) as u32)?;
        Some(half(corners, index % 2))
    }

    /// The corners of the cell at column `i`, row `k`: vertices `(i, k)`, `(i, k + 1)`,
    /// `(i + 1, k + 1)` and `(i + 1, k)`, if on the grid.
    #[inline]
    fn corners(&self, i: u32, k: u32) -> Option<[Vec3<S>; 4]> {
        // The cell's two grid lines each way, shared by its corners.
        let (o, a) = (self.origin, |o: S, n: u32| self.along(o, n));
        let (x, z) = ([a(o.x, i), a(o.x, i + 1)], [a(o.z, k), a(o.z, k + 1)]);
        let v = |di: usize, dk: usize| {
            let y = self.height(i + di as u32, k + dk as u32)?;
            Some(Vec3::new(x[di], y, z[dk]))
        };
        Some([v(0, 0)?, v(0, 1)?, v(1, 1)?, v(1, 0)?])
    }

    /// Triangle `index`, as [`prepared`](Self::prepared) gives it, from its cell's
    /// [`corners`](Self::corners) and byte.
    fn prepare_from(corners: [Vec3<S>; 4], index: usize, byte: u8) -> Option<StandardTriangle<S>> {
        let st = StandardTriangle::new(&half(corners, index % 2)).ok()?;
        Some(st.with_features(features(byte, index)))
    }

    /// [`prepare_from`](Self::prepare_from) the corners of the cell at column `i`, row `k`,
    /// made here, where the preparation runs: passed in a copy just stored, they would be
    /// loaded back before the stores complete (a store-forwarding wait on x86-64).
    #[inline(never)]
    fn prepare_cell(&self, i: u32, k: u32, index: usize, byte: u8) -> Option<StandardTriangle<S>> {
        let t = half(self.corners(i, k)?, index % 2);
        let st = prepare_here(&t).ok()?;
        Some(st.with_features(features(byte, index)))
    }

    /// Triangle `index` prepared with its active edges, as a mesh of the same triangles holds
    /// it; `None` for a hole or beyond the grid.
    pub fn prepared(&self, index: usize) -> Option<StandardTriangle<S>> {
        let byte = *self.cells.get(index / 2)?;
        if byte & HOLE != 0 {
            return None;
        }
        let c = index / 2;
        let w = self.columns.max(1) as usize;
        self.prepare_cell((c % w) as u32, (c / w) as u32, index, byte)
    }

    /// Cells along x and along z.
    pub fn size(&self) -> (u32, u32) {
        (self.columns, self.rows)
    }

    /// Triangles, holes included: `2 columns rows` (zero for parts whose size overflows).
    pub fn len(&self) -> usize {
        2 * self.cells_count().unwrap_or(0)
    }

    /// `columns × rows`, if within what a heightfield holds (parts from elsewhere may not be).
    pub(crate) fn cells_count(&self) -> Option<usize> {
        (self.columns as usize)
            .checked_mul(self.rows as usize)
            .filter(|&n| n <= MAX_TRIANGLES / 2)
    }

    /// Whether the grid has no cells (never true of a built heightfield).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The heights, row by row (x fastest).
    pub fn heights(&self) -> &'a [i16] {
        self.heights
    }

    /// The cell bytes: active edges and [`HOLE`].
    pub fn cells(&self) -> &'a [u8] {
        self.cells
    }

    /// The lowest and the highest of the heights.
    pub fn bounds(&self) -> [i16; 2] {
        self.bounds
    }

    /// The seam class of the worst triangle (the [`bvh`](crate::bvh) docs explain it).
    pub fn class(&self) -> u8 {
        self.class
    }

    /// The grid's place, cell side, height step and size.
    pub const fn shape(&self) -> HeightfieldShape<S> {
        HeightfieldShape {
            origin: self.origin,
            spacing: self.spacing,
            unit: self.unit,
            columns: self.columns,
            rows: self.rows,
        }
    }
}
