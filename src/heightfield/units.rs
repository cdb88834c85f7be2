//! The heightfield's query in integers, for a fixed-point sweep where `f64` is software (a
//! Cortex-M, whose `f64` arithmetic is a library call per operation): the cells under the
//! box of the sweep's grown path, found from the coordinates' bits, each culled by its heights,
//! each triangle by the bound of [`UnitHeights`] on the sweep's heights above its plane, then
//! prepared in two halves (its frame, and the rest only where the frame's heights leave a
//! contact possible) and cast. Culls only pass triangles by, so the answer is the `f64`
//! walk's, bit for bit; a sweep whose box spans more than [`MAX_CELLS`] cells (a long cast,
//! whose box holds far more cells than its path crosses) takes that walk instead.

use super::{HOLE, Heightfield, half};
use crate::bvh;
use crate::cache::Keep;
use crate::contact::within_reach;
use crate::cull::{UnitHeights, unit_bits};
use crate::merge::Earliest;
use crate::triangle::Frame;
use crate::{Features, Hit, Scalar, Sweep, Triangle};

/// The most cells a query's box may span for the integer query.
pub(super) const MAX_CELLS: i64 = 64;

/// A fixed-point sweep's path over a heightfield's grid, in the scalar's units (`2^-frac`):
/// its box grown by the `f64` walk's pad (rounded up), and the box of the terrain's vertices.
pub(super) struct UnitGrid {
    lo: [i64; 3],
    hi: [i64; 3],
    terrain: ([i64; 3], [i64; 3]),
    origin: [i64; 3],
    spacing: i64,
    unit: i64,
}

impl UnitGrid {
    /// The path of `sweep` over `field`'s grid; `None` for floats, a grid that is not valid
    /// and terms beyond 64 bits.
    pub(super) fn new<S: Scalar>(field: &Heightfield<'_, S>, sweep: &Sweep<S>) -> Option<Self> {
        let (r, frac) = sweep.radius().fixed_bits()?;
        let b = |v: S| v.fixed_bits().map(|(b, _)| b);
        let (p0, p1) = (unit_bits(sweep.p0())?, unit_bits(sweep.p1())?);
        let o = unit_bits(field.origin)?;
        let (spacing, unit) = (b(field.spacing)?, b(field.unit)?);
        if spacing <= 0 {
            return None;
        }
        let far = |o: i64, n: u32| o.checked_add(spacing.checked_mul(n as i64)?);
        let y = |h: i16| o[1].checked_add(unit.checked_mul(h as i64)?);
        let (ya, yb) = (y(field.bounds[0])?, y(field.bounds[1])?);
        // Vertices lie within: `origin + (i spacing, h unit, k spacing)`, exactly.
        let terrain = (
            [o[0], ya.min(yb), o[2]],
            [
                far(o[0], field.columns)?,
                ya.max(yb),
                far(o[2], field.rows)?,
            ],
        );
        let big = |v: [i64; 3]| v.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0);
        // The `f64` walk's magnitude for the grid (any height, `32768 |unit|`, counts), so the
        // pad is never below its.
        let reach = (unit.unsigned_abs()).checked_mul(32768)?;
        let grid = o[1].unsigned_abs().checked_add(reach)?;
        let magnitude = [p0, p1, terrain.0, terrain.1]
            .map(big)
            .into_iter()
            .chain([grid])
            .max();
        let ([x0, y0, z0], [x1, y1, z1]) = (p0, p1);
        let length = x1.abs_diff(x0).max(y1.abs_diff(y0)).max(z1.abs_diff(z0));
        let magnitude = i64::try_from(magnitude.unwrap_or(0)).ok()?;
        // The seam margin r / 64 + 4 units, rounded up, 2^class times.
        let seams = ((r + 63) / 64 + 4).checked_mul(1i64.checked_shl(field.class as u32)?)?;
        let pad = bvh::unit_pad(r, frac, i64::try_from(length).ok()?, magnitude)?;
        let pad = pad.checked_add(seams)?;
        let lo = [(x0, x1), (y0, y1), (z0, z1)].map(|(a, b)| a.min(b).saturating_sub(pad));
        let hi = [(x0, x1), (y0, y1), (z0, z1)].map(|(a, b)| a.max(b).saturating_add(pad));
        Some(Self {
            lo,
            hi,
            terrain,
            origin: o,
            spacing,
            unit,
        })
    }

    /// Whether the path's box lies wholly beside the terrain's on some axis: then the sweep
    /// touches no triangle.
    pub(super) fn clear(&self) -> bool {
        let (lo, hi) = self.terrain;
        let apart = |a: usize| self.lo[a] > hi[a] || self.hi[a] < lo[a];
        apart(0) || apart(1) || apart(2)
    }

    /// The cells `first..=last` along one axis whose span `[o + i s, o + (i + 1) s]` meets
    /// `lo..=hi`, within `0..n`; `None` if none do.
    fn cells(&self, o: i64, (lo, hi): (i64, i64), n: u32) -> Option<(i64, i64)> {
        let at = |v: i64| v.saturating_sub(o).checked_div_euclid(self.spacing);
        // A span's end on a cell border also meets the cell before.
        let (first, last) = ((at(lo)? - 1).max(0), at(hi)?.min(n as i64 - 1));
        (first <= last).then_some((first, last))
    }

    /// Offers the contacts the `f64` walk would offer; false, offering none (take that walk),
    /// where the box spans more than [`MAX_CELLS`] cells.
    pub(super) fn offer<S: Scalar, K: Keep<S>>(
        &self,
        field: &Heightfield<'_, S>,
        sweep: &Sweep<S>,
        acc: &mut Earliest<S>,
        cache: K,
    ) -> bool {
        if self.clear() {
            return true;
        }
        let (o, (lo, hi)) = (self.origin, (self.lo, self.hi));
        let (Some((i0, i1)), Some((k0, k1))) = (
            self.cells(o[0], (lo[0], hi[0]), field.columns),
            self.cells(o[2], (lo[2], hi[2]), field.rows),
        ) else {
            return false;
        };
        if (i1 - i0 + 1) * (k1 - k0 + 1) > MAX_CELLS {
            return false;
        }
        let bound = UnitHeights::new(sweep);
        // The heights a cell must span to reach the box (`None`: not known, every cell may).
        let span = height_span(o[1], self.unit, (lo[1], hi[1]));
        let d = sweep.p1() - sweep.p0();
        let w = field.columns as usize;
        // Rows, then columns, in the direction of travel: near cells first, so that early
        // contacts lower the reach the later cells are culled by.
        for n in 0..=(k1 - k0) {
            let k = if d.z >= S::ZERO { k0 + n } else { k1 - n };
            for m in 0..=(i1 - i0) {
                let i = if d.x >= S::ZERO { i0 + m } else { i1 - m };
                let c = k as usize * w + i as usize;
                let Some(&byte) = field.cells.get(c).filter(|&&b| b & HOLE == 0) else {
                    continue;
                };
                if !cell_in_reach(field, span, i as u32, k as u32) {
                    continue;
                }
                let Some(corners) = field.corners(i as u32, k as u32) else {
                    continue;
                };
                for t in [2 * c, 2 * c + 1] {
                    let reach = acc.reach();
                    // A kept triangle is cast at once: its heights cull as the bound would.
                    if let Some(kept) = cache.get(t) {
                        if let Some(hit) = kept.cast_within(sweep, reach) {
                            acc.offer(t, hit);
                        }
                        continue;
                    }
                    let tri = half(corners, t % 2);
                    let out = bound
                        .as_ref()
                        .is_some_and(|b| b.rule_out(sweep, tri.vertices(), reach, true));
                    if out {
                        continue;
                    }
                    // With a cache the whole triangle is prepared and kept, for the next query.
                    let hit = if K::ON {
                        Heightfield::prepare_from(corners, t, byte).and_then(|st| {
                            cache.put(t, &st);
                            st.cast_within(sweep, reach)
                        })
                    } else {
                        cast_lazily(&tri, t, byte, sweep, reach)
                    };
                    if let Some(hit) = hit {
                        acc.offer(t, hit);
                    }
                }
            }
        }
        true
    }
}

/// Whether the heights of the cell at column `i`, row `k` span some of `span` (see
/// [`height_span`]; `None`: any may).
fn cell_in_reach<S: Scalar>(
    field: &Heightfield<'_, S>,
    span: Option<(i64, i64)>,
    i: u32,
    k: u32,
) -> bool {
    let w = field.columns as usize + 1;
    let at = |di: u32, dk: u32| {
        let v = (k + dk) as usize * w + (i + di) as usize;
        field.heights.get(v).copied().unwrap_or(0)
    };
    let hs = [at(0, 0), at(0, 1), at(1, 1), at(1, 0)];
    let (l, u) = hs
        .iter()
        .fold((i16::MAX, i16::MIN), |(l, u), &h| (l.min(h), u.max(h)));
    // Heights map to y linearly: the cell's span of heights meets the box's, or not.
    span.is_none_or(|(first, last)| u as i64 >= first && l as i64 <= last)
}

/// The real heights `h` whose vertices' y, `origin + unit h`, lies within `lo..=hi`, as the
/// integers `[first, last]` a span of integer heights must meet to hold one of them (empty,
/// `first > last`, if none does); `None` where a term leaves 64 bits. Two divisions per query,
/// where comparing each cell's y would take two 64-bit products (library calls on a
/// Cortex-M0).
fn height_span(origin: i64, unit: i64, (lo, hi): (i64, i64)) -> Option<(i64, i64)> {
    // unit h within [a, b]; with a negative unit, (-unit) h within [-b, -a].
    let (a, b) = (lo.checked_sub(origin)?, hi.checked_sub(origin)?);
    let (a, b, unit) = if unit < 0 {
        (b.checked_neg()?, a.checked_neg()?, unit.checked_neg()?)
    } else {
        (a, b, unit)
    };
    if unit == 0 {
        let all = a <= 0 && 0 <= b;
        return Some(if all { (i64::MIN, i64::MAX) } else { (1, 0) });
    }
    // h within [ceil(a / unit), floor(b / unit)]: floors of a positive divisor's quotients.
    let first = a.checked_neg()?.div_euclid(unit).checked_neg()?;
    Some((first, b.div_euclid(unit)))
}

/// The contact of triangle `t` of a heightfield (`byte` its cell's), prepared in two halves
/// as [`prepare_from`](Heightfield::prepare_from) prepares it, with the sweep at alpha `reach`
/// or earlier.
fn cast_lazily<S: Scalar>(
    tri: &Triangle<S>,
    t: usize,
    byte: u8,
    sweep: &Sweep<S>,
    reach: S,
) -> Option<Hit<S>> {
    let frame = Frame::of(tri).ok()?;
    let heights = frame.heights(sweep);
    within_reach(sweep, heights, false, reach)?;
    let st = frame.finish(tri).ok()?;
    st.with_features(Features::of_edges(byte >> (3 * (t % 2))))
        .cast_within_heights(sweep, heights, reach)
}

#[cfg(test)]
mod tests {
    use super::{UnitGrid, cell_in_reach, height_span};
    use crate::merge::earliest;
    use crate::xorshift::Rng;
    use crate::{Heightfield, HeightfieldShape, Scalar, Sweep, Vec3};
    use fixed::types::{I16F16, I32F32};

    /// The integer query answers as the `f64` walk, bit for bit: short moves over and into a
    /// bumpy terrain with holes (as a slide's steps are), balls resting on it and grazing its
    /// top and its edges at the radius give or take a few hundred steps, falls from above and
    /// sweeps beside it. Sweeps whose box spans too many cells are left to the walk.
    fn integer_query_answers_as_the_walk<S: Scalar>() {
        let mut rng = Rng(0x0c1e_a40f);
        let (w, h) = (6u32, 5u32);
        let heights: Vec<i16> = (0..(w + 1) * (h + 1))
            .map(|_| (rng.signed() * 600.0) as i16)
            .collect();
        let mut cells = vec![0u8; (w * h) as usize];
        let origin = Vec3::new(S::from_f64(-3.0), S::from_f64(0.5), S::from_f64(-2.0));
        let (spacing, unit) = (S::from_f64(1.0), S::from_f64(1.0 / 1024.0));
        let hole = |i: u32, k: u32| (i + 2 * k) % 7 == 3;
        let field = Heightfield::build(
            HeightfieldShape {
                origin,
                spacing,
                unit,
                columns: w,
                rows: h,
            },
            &heights,
            hole,
            &mut cells,
        )
        .unwrap();
        let top = 0.5 + *heights.iter().max().unwrap() as f64 / 1024.0;
        let step = S::EPSILON.to_f64();
        let point =
            |p: [f64; 3]| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
        let (mut clear, mut hits, mut compared) = (0, 0, 0);
        let cache: crate::TriangleCache<S, 8> = crate::TriangleCache::new();
        for k in 0..30_000 {
            let r = 0.05 + 0.45 * (rng.signed() + 1.0) / 2.0;
            let (x, z) = (3.5 * rng.signed(), 2.5 * rng.signed());
            let ground = 0.5 + 0.6 * rng.signed();
            let (p0, p1) = match k % 4 {
                // A step of a slide near the ground, down and along.
                0 => {
                    let p0 = [x, ground + r * (1.0 + rng.signed()), z];
                    (
                        p0,
                        [
                            x + 0.3 * rng.signed(),
                            p0[1] - 0.3 * rng.signed().abs(),
                            z + 0.3 * rng.signed(),
                        ],
                    )
                }
                // A fall from above, or a move anywhere around.
                1 => {
                    let p0 = [x, top + 3.0 * rng.signed().abs(), z];
                    (
                        p0,
                        [x + 0.5 * rng.signed(), ground - 1.0, z + 0.5 * rng.signed()],
                    )
                }
                // Just above the top, or just beside the x = 3 edge, by r and -100 to 300 steps.
                _ => {
                    let gap = r + ((k % 401) as f64 - 100.0) * step;
                    if k % 4 == 2 {
                        ([x, top + gap, z], [x + 0.3, top + gap, z + 0.2])
                    } else {
                        ([3.0 + gap, top - 0.3, z], [3.0 + gap, top - 0.6, z + 0.3])
                    }
                }
            };
            let Ok(sweep) = Sweep::new(point(p0), point(p1), S::from_f64(r)) else {
                continue;
            };
            let walk = field.cast(&sweep);
            hits += walk.is_some() as usize;
            let Some(grid) = UnitGrid::new(&field, &sweep) else {
                continue;
            };
            clear += grid.clear() as usize;
            let mut taken = true;
            let hit = earliest(&sweep, |acc| taken &= grid.offer(&field, &sweep, acc, ()));
            if taken {
                compared += 1;
                assert_eq!(
                    format!("{hit:?}"),
                    format!("{walk:?}"),
                    "{p0:?} -> {p1:?} r {r}"
                );
                // With a cache of a few slots (triangles evict each other), twice: once
                // preparing and keeping, once from what was kept.
                for _ in 0..2 {
                    let c = cache.slots();
                    let cached =
                        earliest(&sweep, |acc| taken &= grid.offer(&field, &sweep, acc, c));
                    assert_eq!(format!("{cached:?}"), format!("{walk:?}"), "cached");
                }
            }
        }
        assert!(
            clear > 1_000 && hits > 5_000 && compared > 25_000,
            "{clear} clear, {hits} hits, {compared} compared"
        );
        assert!(cache.hits() > 10_000, "{} hits", cache.hits());
    }

    /// `height_span` holds exactly the integer heights whose y lies in the span, for units
    /// of both signs and zero, spans on either side of the origin and at the ends of 64 bits.
    #[test]
    fn height_span_holds_the_heights_within_the_span() {
        let mut rng = Rng(0x4e16_a5a1);
        let mut checked = 0;
        for k in 0..20_000 {
            let big = |rng: &mut Rng, m: f64| (rng.signed() * m) as i64;
            let (origin, unit) = match k % 4 {
                0 => (big(&mut rng, 1e6), big(&mut rng, 3e3)),
                1 => (big(&mut rng, 1e3), big(&mut rng, 3.0)),
                2 => (i64::MAX - big(&mut rng, 1e3).abs(), big(&mut rng, 1e3)),
                _ => (big(&mut rng, 9e18), big(&mut rng, 9e18)),
            };
            let (a, b) = (big(&mut rng, 2e6), big(&mut rng, 2e6));
            let (lo, hi) = (
                origin.saturating_add(a.min(b)),
                origin.saturating_add(a.max(b)),
            );
            let Some((first, last)) = height_span(origin, unit, (lo, hi)) else {
                continue;
            };
            for _ in 0..8 {
                let h = big(&mut rng, 40_000.0).clamp(-32768, 32767);
                let y = origin as i128 + unit as i128 * h as i128;
                let within = lo as i128 <= y && y <= hi as i128;
                assert_eq!(
                    first <= h && h <= last,
                    within,
                    "{origin} {unit} {lo} {hi} {h}"
                );
                checked += within as usize;
            }
        }
        assert!(checked > 5_000, "{checked}");
    }

    /// A cell is in reach exactly when one of its corners' exact y (or a y between them) lies
    /// in the box's span: `cell_in_reach` against `i128` products, on spans whose ends fall
    /// on, just off and between the corners' heights.
    #[test]
    fn cell_in_reach_is_the_exact_test() {
        let mut rng = Rng(0xce11_4eac);
        let (w, h) = (5u32, 4u32);
        let (mut near, mut far) = (0, 0);
        for _ in 0..400 {
            let heights: Vec<i16> = (0..(w + 1) * (h + 1))
                .map(|_| (rng.signed() * 2000.0) as i16)
                .collect();
            let (unit, origin) = ((rng.signed() * 300.0) as i64, (rng.signed() * 1e5) as i64);
            let mut cells = vec![0u8; (w * h) as usize];
            let u = I16F16::from_bits(unit as i32);
            let o = Vec3::new(I16F16::ZERO, I16F16::from_bits(origin as i32), I16F16::ZERO);
            let Ok(field) = Heightfield::build(
                HeightfieldShape {
                    origin: o,
                    spacing: I16F16::ONE,
                    unit: u,
                    columns: w,
                    rows: h,
                },
                &heights,
                |_, _| false,
                &mut cells,
            ) else {
                continue;
            };
            for _ in 0..40 {
                let (i, k) = (
                    (rng.next() % w as u64) as u32,
                    (rng.next() % h as u64) as u32,
                );
                let at = |di: u32, dk: u32| heights[((k + dk) * (w + 1) + i + di) as usize];
                let ys = [at(0, 0), at(0, 1), at(1, 1), at(1, 0)]
                    .map(|hh| origin as i128 + unit as i128 * hh as i128);
                let (ylo, yhi) = (*ys.iter().min().unwrap(), *ys.iter().max().unwrap());
                // Span ends on a corner's y, a step either side of it, or anywhere near.
                let pick = |rng: &mut Rng| {
                    let y = ys[(rng.next() % 4) as usize] as i64;
                    y + [-1, 0, 1, (rng.signed() * 5e4) as i64][(rng.next() % 4) as usize]
                };
                // Or wholly above or below the cell's, by none, one step or more.
                let gap = [0, 1, 2, (rng.next() % 50_000) as i64][(rng.next() % 4) as usize];
                let wide = (rng.next() % 50_000) as i64;
                let (lo, hi) = match rng.next() % 3 {
                    0 => {
                        let (a, b) = (pick(&mut rng), pick(&mut rng));
                        (a.min(b), a.max(b))
                    }
                    1 => (yhi as i64 + gap, yhi as i64 + gap + wide),
                    _ => (ylo as i64 - gap - wide, ylo as i64 - gap),
                };
                let exact = yhi >= lo as i128 && ylo <= hi as i128;
                let span = height_span(origin, unit, (lo, hi));
                assert_eq!(cell_in_reach(&field, span, i, k), exact, "{unit} {lo} {hi}");
                (near, far) = (near + exact as usize, far + !exact as usize);
            }
        }
        assert!(near > 2_000 && far > 2_000, "{near} in reach, {far} not");
    }

    #[test]
    fn integer_query_answers_as_the_walk_i16f16() {
        integer_query_answers_as_the_walk::<I16F16>();
    }

    #[test]
    fn integer_query_answers_as_the_walk_i32f32() {
        integer_query_answers_as_the_walk::<I32F32>();
    }
}
