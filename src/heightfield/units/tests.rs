//! The integer query of [`UnitGrid`] against the `f64` walk, and its helpers' bounds.

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
    let point = |p: [f64; 3]| Vec3::new(S::from_f64(p[0]), S::from_f64(p[1]), S::from_f64(p[2]));
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
                let cached = earliest(&sweep, |acc| taken &= grid.offer(&field, &sweep, acc, c));
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
