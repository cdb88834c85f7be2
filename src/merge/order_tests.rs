//! The merge's answer against the order contacts are offered in.

use super::*;
use crate::xorshift::Rng;
use fixed::types::I16F16;

/// Random contacts, offered in random orders (each visit its own): one answer.
fn any_order<S: Scalar>(seed: u64, length: f64) {
    let mut rng = Rng(seed);
    let v = |x: f64, y: f64, z: f64| Vec3::new(S::from_f64(x), S::from_f64(y), S::from_f64(z));
    let normals = [
        v(0.0, 1.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(0.0, 0.0, -1.0),
        v(0.6, 0.8, 0.0),
        v(0.0, 0.8, -0.6),
        v(-0.6, 0.0, 0.8),
    ];
    for case in 0..3000 {
        let sign = if rng.next().is_multiple_of(2) {
            1.0
        } else {
            -1.0
        };
        let sweep = Sweep::new(
            v(0.0, 1.0, 0.5),
            v(sign * length, 1.0 - 0.3 * length, 0.5 + 0.1 * length),
            S::from_f64(0.01),
        )
        .unwrap();
        let window = Window::of(&sweep);
        let (p0, d) = (sweep.p0(), sweep.p1() - sweep.p0());
        let n = 2 + (rng.next() % 24) as usize;
        let base = S::from_f64(0.3 + 0.2 * rng.signed());
        let hits: Vec<(usize, Hit<S>), 32> = (0..n)
            .map(|i| {
                let k = (rng.next() % 10) as i32;
                let mut alpha = base;
                for _ in 0..k {
                    alpha = alpha + S::EPSILON;
                }
                let at = p0 + d.scale(alpha);
                let j = S::from_f64(rng.signed() * 3.0).mul(window.apart);
                let position = at + Vec3::new(j, S::ZERO, S::ZERO);
                let c = match rng.next() % 3 {
                    0 => Contact::Face,
                    1 => Contact::Edge((rng.next() % 3) as u8),
                    _ => Contact::Vertex((rng.next() % 3) as u8),
                };
                let hit = Hit {
                    alpha,
                    position,
                    normal: normals[(rng.next() % 6) as usize],
                    contact: c,
                };
                (i * 5 + (rng.next() % 5) as usize, hit)
            })
            .collect();
        let shuffled = |rng: &mut Rng| {
            let mut h = hits.clone();
            for i in (1..h.len()).rev() {
                let j = (rng.next() % (i as u64 + 1)) as usize;
                h.swap(i, j);
            }
            h
        };
        let mut want = None;
        for _ in 0..6 {
            let orders = [shuffled(&mut rng), shuffled(&mut rng)];
            let mut visit = 0;
            let got = earliest(&sweep, |acc| {
                for &(i, h) in &orders[visit.min(1)] {
                    acc.offer(i, h);
                }
                visit += 1;
            });
            let got = alloc_free_fmt(&got);
            match &want {
                None => want = Some(got),
                Some(w) => assert_eq!(w, &got, "case {case}"),
            }
        }
    }
}

fn alloc_free_fmt<S: Scalar>(h: &Option<SceneHit<S>>) -> heapless::String<1024> {
    use core::fmt::Write;
    let mut s = heapless::String::new();
    let _ = write!(s, "{h:?}");
    s
}

#[test]
fn any_order_f32() {
    any_order::<f32>(0x1234_5678, 3.0);
}

#[test]
fn any_order_i16f16_long() {
    any_order::<I16F16>(0x8765_4321, 60.0);
    any_order::<I16F16>(0x1111_2222, 2.0);
}
