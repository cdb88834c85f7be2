//! [`Heightfield::build`]: the grid validated, every triangle prepared and the cells' bytes
//! (active edges and holes) written, in `O(N)` (see the [module docs](super)).

use super::{HOLE, Heightfield, HeightfieldError, HeightfieldShape, MAX_TRIANGLES};
use crate::adjacency::hides;
use crate::{Scalar, StandardTriangle};

impl<'a, S: Scalar> Heightfield<'a, S> {
    /// Validates the grid, prepares every triangle (refusing any that [`StandardTriangle::new`]
    /// refuses, by index; each is prepared a few times, with its neighbours) and writes each
    /// cell's byte (active edges, [`HOLE`] where `hole(column, row)`) into the first
    /// `columns × rows` bytes of `cells`. Time `O(N)`, no allocation.
    ///
    /// `heights` holds `(columns + 1) × (rows + 1)` values, row by row: vertex `(i, k)`
    /// (column `i` along x, row `k` along z) at `heights[k (columns + 1) + i]`, at height
    /// `origin.y + unit × heights[..]`. `spacing` is the cells' side, `unit` the height step.
    /// In fixed point both are the scalar's nearest values (`0.3` in `I16F16` is 0.300003):
    /// a power of two, or a multiple of the scalar's step, keeps the terrain exactly as drawn
    /// in every scalar.
    ///
    /// Errors: [`HeightfieldError`]: sizes that do not match or overflow, a spacing that is not
    /// positive and finite, a height step that is zero (as a fixed-point conversion makes of a
    /// step below half the scalar's resolution) or not finite, a grid beyond the scalar's
    /// range, a degenerate triangle.
    pub fn build(
        shape: HeightfieldShape<S>,
        heights: &'a [i16],
        hole: impl Fn(u32, u32) -> bool,
        cells: &'a mut [u8],
    ) -> Result<Self, HeightfieldError> {
        let HeightfieldShape {
            origin,
            spacing,
            unit,
            columns,
            rows,
        } = shape;
        let (w, h) = (columns as usize, rows as usize);
        let n = w.checked_mul(h).filter(|&n| n <= MAX_TRIANGLES / 2);
        let Some(n) = n else {
            return Err(HeightfieldError::TooMany);
        };
        if n == 0 {
            return Err(HeightfieldError::Empty { columns, rows });
        }
        let needed = (w + 1) * (h + 1);
        if heights.len() != needed {
            let given = heights.len();
            return Err(HeightfieldError::Size { needed, given });
        }
        if cells.len() < n {
            let given = cells.len();
            return Err(HeightfieldError::Capacity { needed: n, given });
        }
        if !(spacing > S::ZERO && spacing.is_finite()) {
            let value = spacing.to_f64();
            return Err(HeightfieldError::Spacing { value });
        }
        // A zero step would flatten every height into the origin's plane, whatever they say.
        if !unit.is_finite() || unit == S::ZERO {
            let value = unit.to_f64();
            return Err(HeightfieldError::Unit { value });
        }
        if let Some(&value) = origin.to_array().iter().find(|c| !c.is_finite()) {
            let value = value.to_f64();
            return Err(HeightfieldError::Origin { value });
        }
        // The grid's far corner and heights in f64 first: a scalar's conversion saturates.
        let limit = S::LIMIT.to_f64();
        // The heights' own range (none: zero), so the terrain's box is no taller than it; the
        // range check takes height 0 too, the origin's: a height's product with the step must
        // itself stay in range (it is formed before the origin is added).
        let first = heights.first().map_or(0, |&v| v);
        let (lo, hi) = heights
            .iter()
            .fold((first, first), |(l, u), &v| (l.min(v), u.max(v)));
        let o = origin.to_array().map(S::to_f64);
        let (sp, u) = (spacing.to_f64(), unit.to_f64());
        let ends = [
            [o[0], o[0] + sp * w as f64],
            [o[1] + u * lo.min(0) as f64, o[1] + u * hi.max(0) as f64],
            [o[2], o[2] + sp * h as f64],
        ];
        // Every column and row number must be exact in the scalar (I16F16 stops at 32 767),
        // or the vertices would not be where the walk looks for them.
        let exact = |n: u32| n <= i32::MAX as u32 && S::from_int(n as i32).to_f64() == n as f64;
        // The coordinate farthest out, and its magnitude: the error gives its sign (a terrain
        // 200 below an origin at y = -4000 reaches -4200, not 4200).
        let signed = ends
            .iter()
            .flatten()
            .fold(0.0f64, |m, &v| if v.abs() > m.abs() { v } else { m });
        let far = signed.abs();
        if far > limit {
            let value = signed;
            return Err(HeightfieldError::OutOfRange { value, limit });
        }
        if !exact(columns) || !exact(rows) {
            let count = columns.max(rows);
            return Err(HeightfieldError::Sides { count });
        }
        // Cells the mesh's T-junction test cannot tell apart at these coordinates would let a
        // mesh of the same triangles switch off edges the grid keeps: refused, not answered
        // differently. The test's tolerance grows with a triangle's origin (within `far`) and
        // its edges' lengths (a diagonal's, plus at most the heights' whole rise).
        let rise = (hi as f64 - lo as f64) * u.abs();
        let extent = S::from_f64(far.max(2.0 * sp + rise).min(4.0 * limit));
        let least = crate::cover::least_cell(extent);
        if spacing <= least {
            let (spacing, least) = (spacing.to_f64(), least.to_f64());
            return Err(HeightfieldError::Fine { spacing, least });
        }
        let mut field = Self::from_parts(shape, heights, &[], [lo, hi], 0);
        for (c, byte) in cells[..n].iter_mut().enumerate() {
            *byte = if hole(c as u32 % columns, c as u32 / columns) {
                HOLE
            } else {
                0b11_1111
            };
        }
        // Each shared edge once, from the later triangle: its cell's diagonal, and the edges to
        // the cells on its left (`2c`) and below (`2c + 1`), as a mesh links them.
        let mut class = 0u32;
        for c in 0..n {
            if cells[c] & HOLE != 0 {
                continue;
            }
            let (i, k) = (c % w, c / w);
            for t in [2 * c, 2 * c + 1] {
                let later = field.prepare_at(t)?;
                let earlier = match t % 2 {
                    0 => (i > 0).then(|| (2 * (c - 1) + 1, 0, 1)),
                    _ => Some((2 * c, 0, 2)),
                };
                let below = (t % 2 == 1 && k > 0).then(|| (2 * (c - w), 2, 1));
                for (m, edge, theirs) in [earlier, below].into_iter().flatten() {
                    if cells[m / 2] & HOLE != 0 {
                        continue;
                    }
                    let other = field.prepare_at(m)?;
                    let apex = field.triangle(m).map(|t| t.vertices()[(theirs + 2) % 3]);
                    if apex.is_some_and(|a| hides(&later, &other, a)) {
                        cells[t / 2] &= !(1 << (3 * (t % 2) + edge));
                        cells[m / 2] &= !(1 << (3 * (m % 2) + theirs));
                    }
                }
            }
        }
        for t in 0..2 * n {
            if cells[t / 2] & HOLE == 0 {
                let all_active = (cells[t / 2] >> (3 * (t % 2))) & 0b111 == 0b111;
                let st = field.prepare_at(t)?;
                class = class.max(crate::bvh::seam_class(all_active, &st));
            }
        }
        field.cells = &cells[..n];
        field.class = class as u8;
        Ok(field)
    }

    /// Triangle `index` as prepared by [`StandardTriangle::new`], before active edges.
    fn prepare_at(&self, index: usize) -> Result<StandardTriangle<S>, HeightfieldError> {
        let t = self.triangle(index).ok_or(HeightfieldError::TooMany)?;
        StandardTriangle::new(&t).map_err(|e| HeightfieldError::Triangle {
            index,
            error: e.at(index),
        })
    }
}
