//! The scenes of the response matrix: ground, walls, corners, stairs, ditches and bumps, as
//! triangle lists, with where the ball starts, what it wishes and the heading progress is
//! measured along.

use std::f64::consts::FRAC_1_SQRT_2;

pub type Tri = [[f64; 3]; 3];
pub type P = [f64; 3];

fn add(a: P, b: P) -> P {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn scale(a: P, k: f64) -> P {
    a.map(|c| c * k)
}
fn cross(a: P, b: P) -> P {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn unit(a: P) -> P {
    scale(a, 1.0 / (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt())
}
fn tan(degrees: f64) -> f64 {
    degrees.to_radians().tan()
}

/// A square of half-side `half` centred on `c`, facing the unit normal `n`.
fn plane(t: &mut Vec<Tri>, c: P, n: P, half: f64) {
    let u = unit(if n[1].abs() > 0.99 {
        [1.0, 0.0, 0.0]
    } else {
        cross([0.0, 1.0, 0.0], n)
    });
    let (u, v) = (scale(u, half), scale(cross(n, u), half));
    let at = |a: f64, b: f64| add(c, add(scale(u, a), scale(v, b)));
    t.push([at(-1.0, -1.0), at(1.0, -1.0), at(1.0, 1.0)]);
    t.push([at(-1.0, -1.0), at(1.0, 1.0), at(-1.0, 1.0)]);
}

/// The ground `y = f(x, z)` over x in [-8, 8], z in [-6, 6], in cells of `cell`, facing up.
fn ground(t: &mut Vec<Tri>, f: &dyn Fn(f64, f64) -> f64, cell: f64) {
    let (n, m) = ((16.0 / cell) as usize, (12.0 / cell) as usize);
    let p = |i: usize, j: usize| {
        let (x, z) = (-8.0 + i as f64 * cell, -6.0 + j as f64 * cell);
        [x, f(x, z), z]
    };
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (p(i, j), p(i, j + 1), p(i + 1, j + 1), p(i + 1, j));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
}

/// The normal of a wall facing `h` (level, unit) leaning back by `lean` degrees.
fn leaning(h: P, lean: f64) -> P {
    let (s, c) = lean.to_radians().sin_cos();
    [h[0] * c, s, h[2] * c]
}

/// A scene: its triangles, where the ball starts, the wished velocity and the heading along
/// which progress is measured.
pub struct Case {
    pub name: String,
    pub tris: Vec<Tri>,
    pub start: P,
    pub wish: P,
    pub heading: P,
}

pub fn cases() -> Vec<Case> {
    let mut out = Vec::new();
    for (lean, rise, tilt) in [(0.0, 10.0, 8.0), (10.0, 10.0, 8.0), (20.0, 10.0, 0.0)] {
        for side in [0.0, 0.6] {
            let mut t = Vec::new();
            ground(&mut t, &|x, z| tan(rise) * x + tan(tilt) * z, 2.0);
            plane(
                &mut t,
                [3.0, 0.0, 0.0],
                leaning([-1.0, 0.0, 0.0], lean),
                9.0,
            );
            let heading = if side > 0.0 {
                [0.0, 0.0, 1.0]
            } else {
                [1.0, 0.0, 0.0]
            };
            let name = format!("wall lean {lean} rise {rise} tilt {tilt} side {side}");
            let start = [-3.0, 0.7 - 3.0 * tan(rise), 0.0];
            out.push(Case {
                name,
                tris: t,
                start,
                wish: [2.0, 0.0, side],
                heading,
            });
        }
    }
    // Inside corners (one a face bent by 4°: two faces at 88° to the heading), convex edges.
    for (inside, lean, half) in [
        (true, 15.0, 45.0f64),
        (true, 25.0, 30.0),
        (true, 15.0, 88.0),
        (false, 25.0, 30.0),
        (false, 40.0, 30.0),
    ] {
        for rise in [0.0, 10.0] {
            let mut t = Vec::new();
            ground(&mut t, &|x, _| tan(rise) * x, 2.0);
            let (s, c) = half.to_radians().sin_cos();
            // Two faces from the edge through (3, 0, 0): along each level direction `d`, facing
            // `h` (into the corner's opening, or out of the edge), towards -x.
            let faces = if inside {
                [([-c, 0.0, s], [-s, 0.0, -c]), ([-c, 0.0, -s], [-s, 0.0, c])]
            } else {
                [([c, 0.0, s], [-s, 0.0, c]), ([c, 0.0, -s], [-s, 0.0, -c])]
            };
            for (d, h) in faces {
                plane(
                    &mut t,
                    add([3.0, 0.0, 0.0], scale(d, 4.5)),
                    leaning(h, lean),
                    4.5,
                );
            }
            let kind = if inside {
                "inside corner"
            } else {
                "convex edge"
            };
            let name = format!("{kind} lean {lean} half-angle {half} rise {rise}");
            let start = [-3.0, 0.7 - 3.0 * tan(rise), 0.0];
            let (wish, heading) = ([2.0, 0.0, 0.1], [1.0, 0.0, 0.0]);
            out.push(Case {
                name,
                tris: t,
                start,
                wish,
                heading,
            });
        }
    }
    for (h, tread, riser) in [
        (0.2, 0.6, 90.0),
        (0.25, 0.5, 70.0),
        (0.15, 0.3, 60.0),
        (0.18, 0.28, 90.0),
    ] {
        for down in [false, true] {
            let mut t = Vec::new();
            let run = h / tan(riser);
            let (mut x, mut y) = (-8.0, 0.0);
            let mut pts = vec![(x, y)];
            while x < 8.0 {
                x += tread;
                pts.push((x, y));
                (x, y) = (x + run, y + h);
                pts.push((x, y));
            }
            // Treads and risers across z in [-6, 6], each facing up or towards -x.
            for w in pts.windows(2) {
                let ((x0, y0), (x1, y1)) = (w[0], w[1]);
                let at = |x: f64, y: f64, z: f64| [x, y, z];
                let (a, b) = (at(x0, y0, 6.0), at(x1, y1, 6.0));
                let (c, d) = (at(x1, y1, -6.0), at(x0, y0, -6.0));
                t.push([a, b, c]);
                t.push([a, c, d]);
            }
            let (start, wish) = if down {
                ([7.0, y + 0.6, 0.0], [-2.0, 0.0, 0.0])
            } else {
                ([-7.5, 0.6, 0.0], [2.0, 0.0, 0.0])
            };
            let dir = if down { "down" } else { "up" };
            let name = format!("stairs {h} on {tread} riser {riser} {dir}");
            out.push(Case {
                name,
                tris: t,
                start,
                wish,
                heading: unit(wish),
            });
        }
    }
    for (slope, rise, side) in [
        (40.0, 5.0, 0.4),
        (50.0, 5.0, 0.0),
        (50.0, 5.0, 0.4),
        (50.0, -5.0, 0.4),
        (60.0, 0.0, 0.4),
        (70.0, 20.0, 0.3),
    ] {
        let mut t = Vec::new();
        ground(&mut t, &|x, z| tan(slope) * z.abs() + tan(rise) * x, 1.0);
        let name = format!("ditch sides {slope} rise {rise} side {side}");
        let start = [
            -5.0,
            0.5 / slope.to_radians().cos() + 0.05 - 5.0 * tan(rise),
            0.0,
        ];
        out.push(Case {
            name,
            tris: t,
            start,
            wish: [2.0, 0.0, side],
            heading: [1.0, 0.0, 0.0],
        });
    }
    for (amp, lean) in [(0.05, 0.0), (0.1, 10.0), (0.05, 30.0)] {
        let mut t = Vec::new();
        let bumps = move |x: f64, z: f64| amp * ((x * 3.1).sin() + (z * 2.3 + x).cos());
        ground(&mut t, &bumps, 0.5);
        plane(
            &mut t,
            [0.0, 0.0, 2.0],
            leaning([0.0, 0.0, -1.0], lean),
            9.0,
        );
        let name = format!("bumps {amp} beside a wall leaning {lean}");
        let start = [-6.0, 0.75, 1.0];
        out.push(Case {
            name,
            tris: t,
            start,
            wish: [2.0, 0.0, 0.6],
            heading: [1.0, 0.0, 0.0],
        });
    }
    // A ditch with a walkable side (the floor) and a steep one, walked along pushing into the
    // steep side; and a pocket of steep bumps walked into diagonally (held there: stuck frames
    // are expected, a zig is a shake).
    for (low, high) in [(20.0, 60.0), (35.0, 75.0)] {
        let mut t = Vec::new();
        let y = move |_: f64, z: f64| {
            if z < 0.0 {
                -tan(low) * z
            } else {
                tan(high) * z
            }
        };
        ground(&mut t, &y, 0.5);
        out.push(Case {
            name: format!("ditch sides {low}/{high} along the steep side"),
            tris: t,
            start: [-5.0, 0.7, 0.0],
            wish: [2.0, 0.0, 0.4],
            heading: [1.0, 0.0, 0.0],
        });
    }
    let mut t = Vec::new();
    let steep = |x: f64, z: f64| {
        0.4 * ((1.7 * x + 0.3).sin() + (2.3 * z + x).cos() + 0.5 * (3.1 * (x + z)).sin())
    };
    ground(&mut t, &steep, 0.5);
    out.push(Case {
        name: "pocket of steep bumps".into(),
        tris: t,
        start: [-4.775, 0.3, -1.741],
        wish: [1.414, 0.0, 1.414],
        heading: [FRAC_1_SQRT_2, 0.0, FRAC_1_SQRT_2],
    });
    // Standing still on slopes: progress is a creep down them.
    for slope in [5.0, 20.0, 40.0] {
        let mut t = Vec::new();
        ground(&mut t, &|x, _| tan(slope) * x, 2.0);
        let name = format!("standing on a slope of {slope}");
        let start = [0.0, 0.55 / slope.to_radians().cos(), 0.0];
        let down = unit([-1.0, -tan(slope), 0.0]);
        out.push(Case {
            name,
            tris: t,
            start,
            wish: [0.0; 3],
            heading: down,
        });
    }
    // The ditches again 1 400 units out and turned 23° about y: there `f32` rounds a
    // coordinate to 6e-5, a step of a 960 Hz walk is a skin or two, and no line of the scene
    // runs along an axis.
    let far: Vec<Case> = out
        .iter()
        .filter(|c| c.name.starts_with("ditch"))
        .map(|c| placed(c, 23.0, [1000.3, 7.1, -1000.7]))
        .collect();
    out.extend(far);
    out
}

/// `case` turned by `degrees` about y, then moved by `offset`.
fn placed(case: &Case, degrees: f64, offset: P) -> Case {
    let (s, c) = degrees.to_radians().sin_cos();
    let turn = |p: P| [c * p[0] - s * p[2], p[1], s * p[0] + c * p[2]];
    let at = |p: P| add(turn(p), offset);
    Case {
        name: format!("{}, far and turned", case.name),
        tris: case.tris.iter().map(|t| t.map(at)).collect(),
        start: at(case.start),
        wish: turn(case.wish),
        heading: turn(case.heading),
    }
}
