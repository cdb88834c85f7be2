//! `Mesh` against the linear scan: random sweeps on heightfields, closed boxes and soups with
//! overlaps, slivers and duplicates give the same answer, bit for bit; its active edges are
//! `Scene`'s; the build is deterministic; extremes are errors, not panics. Every property in
//! every scalar.

mod common;
mod meshes;

use ballcast::bvh::{LeafSize, nodes_for, nodes_for_leaves};
use ballcast::penetration::{Penetration, penetration};
use ballcast::winding::winding;
use ballcast::{
    Buffer, Contact, Degenerates, Geometry, Mesh, MeshError, MeshPart, Node, Scalar, ScalarType,
    Scene, StandardTriangle, Sweep, Triangle, Vec3,
};
use common::{P, Rng, v};
use fixed::types::{I16F16, I32F32};
use meshes::{
    against_linear, against_linear_by, against_linear_sided, boxes, build, build_sided,
    heightfield, soup, t_junctions, tri,
};

fn sweeps_on_all<S: Scalar>(per_shape: usize) {
    let mut rng = Rng(0x5eed_0001);
    let hf = heightfield(&mut rng, 12, 1.0, 0.65);
    against_linear::<S>(&mut rng, &hf, per_shape, 6.0);
    let b = boxes(&mut rng, 16, 5.0);
    against_linear::<S>(&mut rng, &b, per_shape, 6.0);
    let s = soup(&mut rng, 200, 4.0);
    against_linear::<S>(&mut rng, &s, per_shape, 5.0);
}

fn matches_linear_scan<S: Scalar>() {
    sweeps_on_all::<S>(700);
}

fn matches_linear_scan_long<S: Scalar>() {
    for seed in 0..10u64 {
        let mut rng = Rng(0xbeef ^ seed << 20);
        let hf = heightfield(&mut rng, 40, 1.0, 0.65);
        against_linear::<S>(&mut rng, &hf, 4000, 20.0);
        let b = boxes(&mut rng, 60, 15.0);
        against_linear::<S>(&mut rng, &b, 3000, 16.0);
        let s = soup(&mut rng, 600, 8.0);
        against_linear::<S>(&mut rng, &s, 3000, 9.0);
    }
}

/// Paths 50–250 units long that graze an edge or vertex at the radius: the tree's boxes are
/// grown for the rounding that grows with the path's length (alpha's last step times the
/// length), and no such contact is culled.
fn long_grazing_paths<S: Scalar>() {
    let mut rng = Rng(0x5eed_0005);
    let shapes = meshes::shapes(&mut rng);
    for src in shapes {
        against_linear_by::<S>(&mut rng, &src, 1500, |rng, _| {
            let length = rng.range(50.0, 250.0);
            meshes::grazing(rng, &src, length)
        });
    }
}

/// Paths along a triangle's plane, starting on it, a few roundings off it or near the radius.
fn along_a_plane<S: Scalar>() {
    let mut rng = Rng(0x5eed_0006);
    let shapes = meshes::shapes(&mut rng);
    for src in shapes {
        against_linear_by::<S>(&mut rng, &src, 1500, |rng, _| {
            meshes::along_plane(rng, &src)
        });
    }
}

/// Floors with T-junctions, whose edges along the junctions the build switches off after the
/// tree is made (so their seam margins must reach the tree's boxes too): sweeps that fall or
/// slide onto the seams, and the mixed ones, as the linear scan.
fn t_junction_seams_as_linear<S: Scalar>() {
    let mut rng = Rng(0x5eed_000c);
    let floor = t_junctions(&mut rng, 12);
    against_linear::<S>(&mut rng, &floor, 2000, 7.0);
    let [a, b, c] = meshes::plane_of(&floor);
    against_linear_by::<S>(&mut rng, &floor, 3000, |rng, _| {
        // Near the junction line x = 0, falling or gliding a little over the floor.
        let (x, z, r) = (
            rng.range(-0.5, 0.5),
            rng.range(-6.0, 6.0),
            rng.range(0.05, 1.0),
        );
        let p0 = [x, a * x + b * z + c + r + rng.range(-0.01, 0.3), z];
        let d = [
            rng.range(-1.0, 1.0),
            rng.range(-0.4, 0.0),
            rng.range(-1.0, 1.0),
        ];
        (p0, [p0[0] + d[0], p0[1] + d[1], p0[2] + d[2]], r)
    });
}

/// Balls sliding across the T-junctions of tilted floors, at or just under their radius above
/// the plane: every contact is with a face, none with an edge along a junction (a ghost bump).
fn sliding_over_t_junctions_meets_no_edge<S: Scalar>() {
    let mut rng = Rng(0x5eed_000d);
    for _ in 0..3 {
        let floor = t_junctions(&mut rng, 12);
        let [a, b, c] = meshes::plane_of(&floor);
        let input: Vec<Triangle<S>> = floor.iter().map(|&t| tri(t)).collect();
        let owned = build(&input, Degenerates::Refuse).unwrap();
        let mesh = owned.mesh();
        let l = (a * a + 1.0 + b * b).sqrt();
        let up = [-a / l, 1.0 / l, -b / l];
        let at =
            |x: f64, z: f64, h: f64| [x + up[0] * h, a * x + b * z + c + up[1] * h, z + up[2] * h];
        let mut hits = 0;
        for _ in 0..10_000 {
            let (r, x, z) = (
                rng.range(0.1, 0.6),
                rng.range(-1.0, -0.2),
                rng.range(-5.0, 5.0),
            );
            let p0 = at(x, z, r + rng.range(0.0, 1e-3));
            let p1 = at(
                x + 1.2,
                z + rng.range(-0.15, 0.15),
                r - rng.range(0.0, 0.05),
            );
            let sweep = Sweep::new(v::<S>(p0), v::<S>(p1), S::from_f64(r)).unwrap();
            if let Some(hit) = mesh.cast(&sweep) {
                assert_eq!(hit.contact, Contact::Face, "{p0:?} -> {p1:?} r {r}");
                hits += 1;
            }
        }
        assert!(hits > 9_000, "{hits} hits");
    }
}

/// A thin triangle, an identical copy of it, and a floor triangle beyond its short edge, whose
/// apex lies within the cover tolerance of the long edge: neither copy covers the other's
/// edges (a triangle's own edges never cover it), so both end alike, whichever comes first, in
/// a mesh and in a `Scene`.
fn duplicate_slivers_cover_alike<S: Scalar>() {
    // Thin enough that the apex is within the tolerance, not so thin that it is degenerate.
    let (l, h) = match S::PRECISION.scalar {
        ScalarType::F32 => (0.01, 1e-6),
        ScalarType::F64 => (0.01, 2e-15),
        ScalarType::I16F16 => (10.0, 1.0 / 4096.0),
        ScalarType::I32F32 => (10.0, 2e-9),
    };
    let (a, b, c) = ([0.0, 0.0, 0.0], [l, 0.0, 0.0], [l / 2.0, 0.0, -h]);
    let d = [c[0] - b[0], 0.0, c[2] - b[2]];
    let p = [c[0] + 0.25 * d[0], 0.0, c[2] + 0.25 * d[2]];
    let q = [b[0] - 0.25 * d[0], 0.0, b[2] - 0.25 * d[2]];
    let src = [[a, b, c], [a, b, c], [p, q, [0.8 * l, 0.0, -0.8 * l]]];
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let bits = |order: [usize; 3]| {
        let picked: Vec<Triangle<S>> = order.iter().map(|&k| input[k]).collect();
        let owned = build(&picked, Degenerates::Refuse).unwrap();
        let mut scene: Scene<S, 3> = Scene::new();
        for &t in &picked {
            scene.push(t).unwrap();
        }
        let mut out = [[0u8; 2]; 3];
        for (k, &i) in order.iter().enumerate() {
            let mesh = owned.mesh().triangle(k).unwrap().features().bits();
            out[i] = [mesh, scene.triangle(k).unwrap().features().bits()];
        }
        out
    };
    let first = bits([0, 1, 2]);
    assert_eq!(first[0], first[1], "the copies differ");
    assert_eq!(first[0][0], first[0][1], "mesh and scene differ");
    assert_eq!(bits([2, 1, 0]), first);
    assert_eq!(bits([2, 0, 1]), first);
}

/// A long thin triangle whose long edge two floor triangles cover, meeting in a T-junction:
/// with that edge off, its face reaches (by the seam margin, which its sharp corners magnify)
/// well past its tip, and the tree's boxes must be grown for it. Balls falling beside the tip
/// as the linear scan.
fn sliver_tip_past_a_covered_edge<S: Scalar>() {
    let (a, b, c, m) = (
        [0.0, 0.0, 0.0],
        [10.0, 0.0, 0.0],
        [10.0, 0.0, -0.1],
        [5.0, 0.0, 0.0],
    );
    let src = [[a, b, c], [m, a, [0.0, 0.0, 5.0]], [b, m, [10.0, 0.0, 5.0]]];
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    assert!(!owned.mesh().triangle(0).unwrap().features().edge(0));
    let (mesh, reference) = (owned.mesh(), owned.reference());
    let mut rng = Rng(0x5eed_000e);
    for _ in 0..5000 {
        let r = rng.range(0.3, 1.0);
        let (x, z) = (rng.range(-1.6 * r, 0.0), rng.range(0.0, 0.02 * r));
        let sweep = Sweep::new(
            v::<S>([x, r + 0.5, z]),
            v::<S>([x, r - 0.5, z]),
            S::from_f64(r),
        );
        let sweep = sweep.unwrap();
        assert_eq!(mesh.cast(&sweep), reference(&sweep), "x {x} z {z} r {r}");
    }
}

/// Long thin triangles side by side, every edge open and every box overlapping nearly every
/// other: the build bounds its search for T-junctions (edges it does not get to stay active),
/// and the mesh still answers as the linear scan of what it built.
fn overlapping_strips_as_linear<S: Scalar>() {
    let mut rng = Rng(0x5eed_000f);
    let strips = meshes::diagonal_strips(600);
    against_linear::<S>(&mut rng, &strips, 500, 60.0);
}

/// `penetration` and `winding` on the mesh (its tree's box query) give the linear scan's
/// answers, and a small box reaches a handful of the mesh's triangles, not all of them.
fn box_queries_as_linear<S: Scalar>() {
    let mut rng = Rng(0x5eed_0007);
    let shapes = [
        heightfield(&mut rng, 40, 1.0, 0.65),
        boxes(&mut rng, 16, 5.0),
        soup(&mut rng, 200, 4.0),
    ];
    // Each shape under both leaf sizes.
    let sizes = [LeafSize::Two, LeafSize::Four];
    for (src, leaves) in shapes.iter().flat_map(|s| sizes.map(|l| (s, l))) {
        let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
        let owned = build(&input, Degenerates::Skip.with_leaf_size(leaves)).unwrap();
        let (mesh, linear) = (owned.mesh(), owned.linear());
        let mut kept: Vec<u32> = owned.order.clone();
        kept.sort();
        let mut overlaps = 0;
        for _ in 0..500 {
            let t = src[(rng.next() * src.len() as f64) as usize];
            let r = rng.range(0.05, 1.0);
            let c = [0, 1, 2].map(|a| t[0][a] + rng.range(-r, r));
            let (c, r) = (v::<S>(c), S::from_f64(r));
            let got = penetration(&mesh, c, r).unwrap();
            let want = penetration(linear.as_slice(), c, r)
                .unwrap()
                .map(|p| Penetration {
                    index: kept[p.index] as usize,
                    ..p
                });
            assert_eq!(got, want, "centre {c:?}, r {r:?}");
            overlaps += got.is_some() as usize;
            let mut want = winding(linear.as_slice(), c).unwrap();
            want.first_away = want.first_away.map(|i| kept[i] as usize);
            assert_eq!(winding(&mesh, c).unwrap(), want, "winding from {c:?}");
        }
        assert!(overlaps > 100, "{overlaps} overlaps");
    }
    // A ball-sized box on a 3 200-triangle terrain reaches a few leaves.
    let src = heightfield(&mut rng, 40, 1.0, 0.65);
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let mut reached = 0;
    let half = S::from_f64(0.5);
    let c = v::<S>([0.3, 0.0, -0.2]);
    owned.mesh().visit(
        c - Vec3::new(half, half, half),
        c + Vec3::new(half, half, half),
        &mut |_, _| reached += 1,
    );
    assert!(
        (4..=64).contains(&reached),
        "{reached} of {} triangles",
        input.len()
    );
}

/// The mesh's prepared triangles, features included, are `Scene`'s on the same input.
fn active_edges_are_scenes<S: Scalar>() {
    active_edges_are_scenes_sided::<S>(|_| false);
}

/// As [`active_edges_are_scenes`] with every third triangle two-sided (`build_sided` and
/// `Scene::push_sided`): the valley rule only between one-sided triangles, the rest alike.
fn two_sided_active_edges_are_scenes<S: Scalar>() {
    active_edges_are_scenes_sided::<S>(|i| i.is_multiple_of(3));
}

/// Mixed sides on heightfields, boxes and soups: the mesh answers as the linear scan of what it
/// built (whose triangles carry their sides), so the tree's culling allows for balls coming at
/// a two-sided triangle from behind.
fn two_sided_as_linear<S: Scalar>() {
    let mut rng = Rng(0x5eed_2515);
    for (src, half) in [
        (heightfield(&mut rng, 10, 1.0, 0.65), 6.0),
        (boxes(&mut rng, 12, 5.0), 6.0),
        (soup(&mut rng, 150, 4.0), 5.0),
    ] {
        against_linear_sided::<S>(&mut rng, &src, |i| i % 3 != 1, 1500, half);
    }
}

fn active_edges_are_scenes_sided<S: Scalar>(sided: fn(usize) -> bool) {
    let mut rng = Rng(0x5eed_0002);
    let mut shapes = vec![
        heightfield(&mut rng, 12, 1.0, 0.65),
        boxes(&mut rng, 16, 5.0),
        soup(&mut rng, 200, 4.0),
    ];
    // Flat: every interior edge inactive; identical copies: none paired; T-junctions, whose
    // edges along the junction only flat neighbours' coverage switches off.
    shapes.push(heightfield(&mut rng, 8, 1.0, 0.0));
    shapes.push(t_junctions(&mut rng, 8));
    shapes.push(t_junctions(&mut rng, 12));
    // A floor stopping balls from both sides, made of each triangle and its reverse: a
    // triangle's reverse is no partner, so the junctions' edges are still found open.
    let floor = t_junctions(&mut rng, 8);
    let backs = floor.iter().map(|&[a, b, c]| [a, c, b]);
    shapes.push(floor.iter().copied().chain(backs).collect());
    shapes.push(vec![
        [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]];
        40
    ]);
    for src in shapes {
        let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
        let owned = build_sided(&input, sided, Degenerates::Skip).unwrap();
        let mesh = owned.mesh();
        let mut scene: Box<Scene<S, 512>> = Box::default();
        let push = |(i, t): (usize, &Triangle<S>)| scene.push_sided(*t, sided(i)).ok();
        let pushed: Vec<Option<usize>> = input.iter().enumerate().map(push).collect();
        let mut inactive = 0;
        for (i, k) in pushed.into_iter().enumerate() {
            let Some(k) = k else {
                assert!(
                    mesh.triangle(i).is_none(),
                    "triangle {i} kept but refused by Scene"
                );
                continue;
            };
            let (a, b) = (mesh.triangle(i).unwrap(), scene.triangle(k).unwrap());
            assert_eq!(a.to_parts(), b.to_parts(), "triangle {i}");
            inactive += (0..3).filter(|&e| !b.features().edge(e)).count();
        }
        assert_eq!(scene.len(), mesh.len());
        // The comparison is not vacuous: the heightfields and boxes have inactive edges.
        assert!(
            inactive > 0 || !matches!(src.len(), 128 | 192 | 288),
            "no inactive edge"
        );
    }
}

/// Repeated builds give the same parts; a shuffled input gives the same answers (alphas, and
/// whether anything is hit) although the tree's tie-breaks differ.
fn deterministic<S: Scalar>() {
    let mut rng = Rng(0x5eed_0003);
    let src = heightfield(&mut rng, 12, 1.0, 0.65);
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let (a, b) = (
        build(&input, Degenerates::Refuse).unwrap(),
        build(&input, Degenerates::Refuse).unwrap(),
    );
    assert_eq!(a.mesh(), b.mesh());
    let mut perm: Vec<usize> = (0..input.len()).collect();
    for i in (1..perm.len()).rev() {
        perm.swap(i, (rng.next() * (i + 1) as f64) as usize);
    }
    let shuffled: Vec<Triangle<S>> = perm.iter().map(|&i| input[i]).collect();
    let c = build(&shuffled, Degenerates::Refuse).unwrap();
    let (ma, mc) = (a.mesh(), c.mesh());
    for (i, &p) in perm.iter().enumerate() {
        let (x, y) = (ma.triangle(p).unwrap(), mc.triangle(i).unwrap());
        assert_eq!(x.features(), y.features(), "features of input triangle {p}");
    }
    let mut hits = 0;
    for _ in 0..300 {
        let (p0, p1) = (rng.point(6.0), rng.point(6.0));
        let sweep = Sweep::new(v::<S>(p0), v(p1), S::from_f64(rng.range(0.1, 1.0))).unwrap();
        let (x, y) = (ma.cast(&sweep), mc.cast(&sweep));
        assert_eq!(x.map(|h| h.alpha), y.map(|h| h.alpha), "{p0:?} -> {p1:?}");
        hits += x.is_some() as usize;
    }
    assert!(hits > 30);
}

/// A hash of every byte of a mesh built with leaves of `leaves`, pinned: the same in debug and
/// release, on every target.
fn pinned_bytes<S: Scalar>(leaves: LeafSize) -> u64 {
    let mut rng = Rng(0x5eed_0004);
    let src = heightfield(&mut rng, 10, 1.0, 0.65);
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let m = build(&input, Degenerates::Refuse.with_leaf_size(leaves)).unwrap();
    let parts: Vec<_> = m.tris.iter().map(|t| t.to_parts()).collect();
    let text = format!("{:?}{:?}{:?}{:?}", m.nodes, m.order, m.grid, parts);
    text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ b as u64).wrapping_mul(0x100_0000_01b3)
    })
}

#[test]
fn same_bytes_everywhere() {
    for (leaves, pinned) in [(LeafSize::Two, PINNED), (LeafSize::Four, PINNED_FOUR)] {
        let got = [
            pinned_bytes::<f32>(leaves),
            pinned_bytes::<f64>(leaves),
            pinned_bytes::<I16F16>(leaves),
            pinned_bytes::<I32F32>(leaves),
        ];
        assert_eq!(got, pinned, "{leaves:?} {got:#x?}");
    }
}

/// Leaves of up to two triangles, the default.
const PINNED: [u64; 4] = [
    0x62ae0e790613f252,
    0x8f2db3ce8b7e2f94,
    0x4b9200263ab08d93,
    0xdf20fed149bc9818,
];

/// Leaves of up to four.
const PINNED_FOUR: [u64; 4] = [
    0x218025b8f57384d6,
    0x2e15621867ff81b2,
    0xd35886d574afd8ab,
    0xa8f3a705ef64f9d6,
];

/// A mesh spanning the whole safe range (±4096 in I16F16), sweeps across it.
fn range_edges<S: Scalar>() {
    let l = S::LIMIT.to_f64();
    let mut rng = Rng(0x5eed_0005);
    let mut src = heightfield(&mut rng, 8, l / 4.0, l / 64.0);
    // Corners exactly at ±LIMIT.
    src.push([[-l, -l, -l], [-l, -l, l], [l, -l, l]]);
    src.push([[l, l, l], [l, l, -l], [-l, l, -l]]);
    against_linear::<S>(&mut rng, &src, 300, l);
}

/// A heightfield 2^-107 units across, and falls from near its vertices to 2^-19 units below
/// and aside (floats; fixed point has no such scale): a fall spans more than 2^100 of the
/// tree's cells, where the node test's `f32` reciprocal is too small to scale exactly and that axis
/// culls nothing. Still the linear scan's answers.
fn tiny_mesh_long_falls<S: Scalar>() {
    if !S::PRECISION.relative {
        return;
    }
    let mut rng = Rng(0x5eed_0008);
    let unit = (-110f64).exp2();
    let src: Vec<[P; 3]> = heightfield(&mut rng, 8, 1.0, 0.65)
        .iter()
        .map(|t| t.map(|p| p.map(|c| c * unit)))
        .collect();
    let targets = src.clone();
    against_linear_by::<S>(&mut rng, &src, 300, |rng, k| {
        let t = targets[(rng.next() * targets.len() as f64) as usize][k % 3];
        let p0 = [0.0, 2.0, 0.0].map(|up| rng.range(-1.0, 1.0 + up) * unit);
        let p0 = [0, 1, 2].map(|a| t[a] + p0[a]);
        let far = (-19f64).exp2();
        let d = [rng.range(-far, far), -far, rng.range(-far, far)];
        (
            p0,
            [0, 1, 2].map(|a| p0[a] + d[a]),
            rng.range(0.0, 1.5) * unit,
        )
    });
}

/// Empty, one triangle, all identical: answers as the linear scan; an empty mesh hits nothing.
fn small_meshes<S: Scalar>() {
    let mut rng = Rng(0x5eed_0006);
    let empty = build::<S>(&[], Degenerates::Refuse).unwrap();
    assert!(empty.mesh().is_empty() && empty.nodes.is_empty());
    let sweep = Sweep::new(v::<S>([0.0, 1.0, 0.0]), v([0.0, -1.0, 0.0]), S::ONE).unwrap();
    assert_eq!(empty.mesh().cast(&sweep), None);
    let one = [[[-2.0, 0.0, -2.0], [-2.0, 0.0, 2.0], [2.0, 0.0, 0.0]]];
    against_linear::<S>(&mut rng, &one, 200, 3.0);
    against_linear::<S>(&mut rng, &[one[0]; 37], 200, 3.0);
}

/// Buffers one short, degenerate and out-of-range triangles: errors naming the cause.
fn errors_not_panics<S: Scalar>() {
    let mut rng = Rng(0x5eed_0007);
    let mut src: Vec<Triangle<S>> = heightfield(&mut rng, 6, 1.0, 0.65)
        .iter()
        .map(|&t| tri(t))
        .collect();
    let n = src.len();
    let attempt = |src: &[Triangle<S>], sizes: [usize; 4], deg| {
        let mut nodes = vec![Node::default(); sizes[0]];
        let mut tris = vec![Mesh::<S>::filler(); sizes[1]];
        let mut order = vec![0u32; sizes[2]];
        let mut scratch = vec![0u64; sizes[3]];
        Mesh::build(src, deg, &mut nodes, &mut tris, &mut order, &mut scratch)
            .map(|(m, k)| (m.len(), k))
    };
    let full = [nodes_for(n), n, n, 6 * n];
    assert_eq!(attempt(&src, full, Degenerates::Refuse), Ok((n, 0)));
    for (k, buffer) in [
        Buffer::Nodes,
        Buffer::Triangles,
        Buffer::Order,
        Buffer::Scratch,
    ]
    .into_iter()
    .enumerate()
    {
        let mut sizes = full;
        sizes[k] -= 1;
        let needed = full[k];
        assert_eq!(
            attempt(&src, sizes, Degenerates::Refuse),
            Err(MeshError::Capacity {
                buffer,
                needed,
                given: needed - 1
            })
        );
    }
    let short = attempt(&src, [1, n, n, 6 * n], Degenerates::Refuse).unwrap_err();
    let said = format!(
        "the buffer of nodes (bvh::nodes_for_leaves of the triangles kept) holds 1, too few: {} needed",
        nodes_for(n)
    );
    assert_eq!(short.to_string(), said);
    // Two degenerate triangles (a repeated vertex, collinear vertices) at 5 and 9.
    let p = v::<S>([1.0, 2.0, 3.0]);
    src[5] = Triangle::new(p, p, v([0.0, 0.0, 0.0]));
    src[9] = Triangle::new(v([0.0, 0.0, 0.0]), v([1.0, 1.0, 1.0]), v([2.0, 2.0, 2.0]));
    let e = attempt(&src, full, Degenerates::Refuse).unwrap_err();
    assert_eq!(
        e,
        MeshError::Triangle {
            index: 5,
            error: ballcast::Error::Degenerate { triangle: Some(5) }
        }
    );
    assert_eq!(
        e.to_string(),
        "triangle 5: degenerate (coincident or collinear vertices)"
    );
    assert_eq!(attempt(&src, full, Degenerates::Skip), Ok((n - 2, 2)));
    // A node buffer sized for the kept triangles only will do.
    let kept_only = [nodes_for(n - 2), n, n, 6 * n];
    assert_eq!(attempt(&src, kept_only, Degenerates::Skip), Ok((n - 2, 2)));
    // Skipping builds the mesh of the kept triangles alone, byte for byte.
    let skipped = build(&src, Degenerates::Skip).unwrap();
    let rest: Vec<_> = [&src[..5], &src[6..9], &src[10..]].concat();
    let alone = build(&rest, Degenerates::Refuse).unwrap();
    let parts = |m: &meshes::Owned<S>| m.tris.iter().map(|t| t.to_parts()).collect::<Vec<_>>();
    assert_eq!(skipped.nodes, alone.nodes);
    assert_eq!(parts(&skipped), parts(&alone));
    let input = |i: u32| i - (i > 5) as u32 - (i > 9) as u32;
    let renumbered: Vec<u32> = skipped.order.iter().map(|&i| input(i)).collect();
    assert_eq!(renumbered, alone.order);
    // Out of range is never skipped.
    src[7] = Triangle::new(
        v([0.0, 0.0, 0.0]),
        v([0.0, 0.0, 1.0]),
        v([S::LIMIT.to_f64() * 2.0, 0.0, 0.0]),
    );
    assert!(matches!(
        attempt(&src, full, Degenerates::Skip),
        Err(MeshError::Triangle { index: 7, .. })
    ));
}

/// `move_and_slide` runs on a mesh and moves exactly as on the linear scan.
fn slides_as_linear<S: Scalar>() {
    let mut rng = Rng(0x5eed_0008);
    let src = heightfield(&mut rng, 12, 1.0, 0.65);
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let linear = owned.linear();
    for _ in 0..200 {
        let p = [
            rng.range(-5.0, 5.0),
            rng.range(0.8, 2.0),
            rng.range(-5.0, 5.0),
        ];
        let d = [
            rng.range(-1.0, 1.0),
            rng.range(-2.0, 0.0),
            rng.range(-1.0, 1.0),
        ];
        let r = S::from_f64(rng.range(0.2, 0.5));
        let a = ballcast::move_and_slide(&owned.mesh(), v::<S>(p), v(d), r).unwrap();
        let b = ballcast::move_and_slide(linear.as_slice(), v::<S>(p), v(d), r).unwrap();
        assert_eq!(a, b);
    }
}

/// Found by the 10^5-sweep run: a sliver whose long edge is inactive (here flat with its
/// neighbour) stretched its face test's seam margin far along its active edge, so `cast`
/// reported a face contact two units beyond the sliver's corner, and the tree's boxes had to
/// reach it. The widening is now bounded by the triangle's box grown by the margin: nothing is
/// met there, by the linear scan or by the tree, on the slab traversal (a long fall) and on the
/// box walk (a short step down); 0.01 beyond the corner, within the margin, both meet the
/// sliver or its neighbour.
fn sliver_seam_beyond_its_corner<S: Scalar>() {
    let floor = [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [10.0, 0.0, 0.0]];
    let sliver = [[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [5.0, 0.0, -0.01]];
    let src = [floor, sliver];
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let linear = owned.linear();
    for (x, met) in [(-2.0, false), (-0.001, true)] {
        for (from, to) in [(1.0, -1.0), (0.6, 0.4)] {
            let sweep = Sweep::new(
                v::<S>([x, from, 0.006]),
                v([x, to, 0.006]),
                S::from_f64(0.5),
            );
            let sweep = sweep.unwrap();
            let want = Geometry::cast(linear.as_slice(), &sweep);
            assert_eq!(want.is_some(), met, "the linear scan at x = {x}");
            assert_eq!(owned.mesh().cast(&sweep), want, "x = {x}, from y = {from}");
        }
    }
}

/// A short step (shorter than the radius, so the box walk takes it) that touches a wall only at
/// its very end: the walk's box must hold the whole step while nothing is found, and a box cut
/// short of the end (a quarter off) loses the contact.
fn short_step_touching_at_its_end<S: Scalar>() {
    let mut rng = Rng(0x5eed_0011);
    let mut src = heightfield(&mut rng, 4, 1.0, 0.2);
    let wall = [
        [0.0, -1.0, -1.0],
        [0.0, 1.0, -1.0],
        [0.0, 1.0, 1.0],
        [0.0, -1.0, 1.0],
    ];
    // Facing −x, towards the ball.
    src.push([wall[0], wall[2], wall[1]]);
    src.push([wall[0], wall[3], wall[2]]);
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let linear = owned.linear();
    let sweep = Sweep::new(
        v::<S>([-0.45, 0.5, 0.1]),
        v([-0.2499, 0.5, 0.1]),
        S::from_f64(0.25),
    );
    let sweep = sweep.unwrap();
    let want = Geometry::cast(linear.as_slice(), &sweep);
    assert!(want.is_some_and(|h| h.alpha.to_f64() > 0.99), "{want:?}");
    assert_eq!(owned.mesh().cast(&sweep), want);
}

/// A node slice of exactly `nodes_for_leaves(n, leaf size)` is enough for each leaf size and
/// used to the last node; one node fewer is a capacity error naming the count needed.
#[test]
fn node_buffers_sized_exactly_for_each_leaf_size() {
    let mut rng = Rng(0x5eed_000c);
    let cells = heightfield(&mut rng, 9, 1.0, 0.65);
    for n in 1..cells.len() {
        let input: Vec<Triangle<f32>> = cells[..n].iter().map(|&t| tri(t)).collect();
        for leaves in [LeafSize::Two, LeafSize::Four] {
            let need = nodes_for_leaves(n, leaves);
            let options = Degenerates::Refuse.with_leaf_size(leaves);
            let mut tris = vec![Mesh::<f32>::filler(); n];
            let (mut order, mut scratch) = (vec![0u32; n], vec![0u64; 6 * n]);
            let mut nodes = vec![Node::default(); need];
            let built = Mesh::build(
                &input,
                options,
                &mut nodes,
                &mut tris,
                &mut order,
                &mut scratch,
            );
            assert_eq!(
                built.map(|(m, _)| m.nodes().len()),
                Ok(need),
                "{n} {leaves:?}"
            );
            let mut short = vec![Node::default(); need - 1];
            let built = Mesh::build(
                &input,
                options,
                &mut short,
                &mut tris,
                &mut order,
                &mut scratch,
            );
            let capacity = MeshError::Capacity {
                buffer: Buffer::Nodes,
                needed: need,
                given: need - 1,
            };
            assert_eq!(built.map(|_| ()), Err(capacity), "{n} {leaves:?}");
        }
    }
}

/// Sizing the node buffer takes any count without overflow, beyond what a build accepts too
/// (`nodes_for(usize::MAX)` overflowed a product in debug), and grows with the count.
#[test]
fn node_counts_of_any_size_do_not_overflow() {
    let max = ballcast::bvh::MAX_TRIANGLES;
    let mut last = 0;
    for n in [
        max,
        max + 1,
        usize::MAX / 4,
        usize::MAX / 2,
        usize::MAX - 1,
        usize::MAX,
    ] {
        for leaves in [LeafSize::Two, LeafSize::Four] {
            let need = nodes_for_leaves(n, leaves);
            assert!(need >= n / 12, "{n} {leaves:?}: {need}");
        }
        assert!(nodes_for(n) >= last, "{n}");
        last = nodes_for(n);
    }
}

/// A floor edge covered by two flat neighbours meeting in a T-junction, with 400 tiny posts
/// standing along it (more than the 256 triangles near one edge the build looks at): the
/// edges switched off must not depend on how the tree found the posts. With leaves of four the
/// build met more of them near the edge than with leaves of two and left the edge active; the
/// two trees then answered sweeps across it differently.
fn t_junction_among_many_posts_has_the_same_edges_for_every_leaf_size<S: Scalar>() {
    let floor = [
        [[0.0, 0.0, 0.0], [8.0, 0.0, 0.0], [4.0, 0.0, -4.0]],
        [[4.0, 0.0, 0.0], [0.0, 0.0, 0.0], [2.0, 0.0, 3.0]],
        [[8.0, 0.0, 0.0], [4.0, 0.0, 0.0], [6.0, 0.0, 3.0]],
    ];
    let posts = (0..400).map(|k| {
        let x = 0.1 + 7.8 * k as f64 / 400.0;
        let y = if k % 4 == 0 { 0.0 } else { 0.005 };
        [[x, y, -0.002], [x, y, 0.002], [x, y + 0.004, 0.0]]
    });
    let src: Vec<[P; 3]> = floor.into_iter().chain(posts).collect();
    let input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let two = build(&input, Degenerates::Skip).unwrap();
    let four = build(&input, Degenerates::Skip.with_leaf_size(LeafSize::Four)).unwrap();
    let (two, four) = (two.mesh(), four.mesh());
    for i in 0..input.len() {
        let features = |m: &Mesh<'_, S>| m.triangle(i).map(|t| t.features());
        assert_eq!(features(&two), features(&four), "triangle {i}");
    }
    let mut rng = Rng(0x5eed_000b);
    for k in 0..2000 {
        let x = rng.range(0.0, 8.0);
        let r = rng.range(0.001, 0.01);
        let (z0, h) = (rng.range(-0.5, 0.5), r * rng.range(0.99, 1.01));
        let sweep = Sweep::new(v::<S>([x, h, z0]), v([x + 0.003, h, -z0]), S::from_f64(r));
        if let Ok(sweep) = sweep {
            assert_eq!(two.cast(&sweep), four.cast(&sweep), "sweep {k}");
        }
    }
}

/// `Mesh::verify`, the check for baked parts: a mesh from `from_parts` passes against its
/// triangles, and fails once a part or a triangle of the input differs, naming the first part
/// that differs: the prepared triangle (by its input index) where only its baked active edges
/// do, a node where a vertex of the input moved.
fn verify_baked_parts<S: Scalar>() {
    let mut rng = Rng(0x5eed_0009);
    let src = heightfield(&mut rng, 6, 1.0, 0.65);
    let mut input: Vec<Triangle<S>> = src.iter().map(|&t| tri(t)).collect();
    let owned = build(&input, Degenerates::Refuse).unwrap();
    let n = input.len();
    let verify = |baked: &Mesh<'_, S>, input: &[Triangle<S>]| {
        let mut nodes = vec![Node::default(); nodes_for(n)];
        let mut tris = vec![Mesh::<S>::filler(); n];
        let mut order = vec![0u32; n];
        let mut scratch = vec![0u64; 6 * n];
        let deg = Degenerates::Refuse;
        baked.verify(input, deg, &mut nodes, &mut tris, &mut order, &mut scratch)
    };
    let mesh = owned.mesh();
    assert_eq!(verify(&mesh, &input), Ok(()));
    // Slot 5's triangle baked with one active edge bit flipped.
    let mut triangles = mesh.triangles().to_vec();
    let mut parts = triangles[5].to_parts();
    parts.features ^= 1;
    triangles[5] = StandardTriangle::from_parts(parts);
    let tampered = Mesh::from_parts(mesh.nodes(), &triangles, mesh.order(), mesh.grid());
    let part = MeshPart::Triangle {
        index: mesh.order()[5] as usize,
    };
    assert_eq!(verify(&tampered, &input), Err(MeshError::Mismatch { part }));
    input[3].v1.y = input[3].v1.y + S::from_f64(0.25);
    let moved = verify(&mesh, &input);
    assert!(
        matches!(
            moved,
            Err(MeshError::Mismatch {
                part: MeshPart::Node { .. }
            })
        ),
        "{moved:?}"
    );
}

meshes::per_scalar!(
    matches_linear_scan,
    long_grazing_paths,
    along_a_plane,
    box_queries_as_linear,
    active_edges_are_scenes,
    two_sided_active_edges_are_scenes,
    two_sided_as_linear,
    t_junction_seams_as_linear,
    sliding_over_t_junctions_meets_no_edge,
    duplicate_slivers_cover_alike,
    sliver_tip_past_a_covered_edge,
    overlapping_strips_as_linear,
    deterministic,
    range_edges,
    tiny_mesh_long_falls,
    small_meshes,
    errors_not_panics,
    slides_as_linear,
    sliver_seam_beyond_its_corner,
    short_step_touching_at_its_end,
    verify_baked_parts,
    t_junction_among_many_posts_has_the_same_edges_for_every_leaf_size,
    matches_linear_scan_long #[ignore = "10^5 sweeps per scalar: run with --release -- --ignored"],
);

/// A mesh baked into `static`s through the `const` constructors (here one floor triangle, its
/// parts written out by hand) equals the run-time build and verifies against its source.
mod baked {
    use ballcast::{Edge, Grid, Mesh, Node, Parts, StandardTriangle, Vec3};

    const H: f32 = core::f32::consts::FRAC_1_SQRT_2;
    static TRIANGLES: [StandardTriangle<f32>; 1] = [StandardTriangle::from_parts(Parts {
        origin: Vec3::new(0.0, 0.0, 0.0),
        // The build's axes, zeros' signs included (the check is bit for bit).
        axes: [
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(-0.0, 1.0, 0.0),
            Vec3::new(0.0, -0.0, 1.0),
        ],
        shape: [0.0, 1.0, 1.0],
        normal: Vec3::new(-0.0, 1.0, 0.0),
        edges: [
            Edge {
                dir: [0.0, 1.0],
                len: 1.0,
            },
            Edge {
                dir: [H, -H],
                len: core::f32::consts::SQRT_2,
            },
            Edge {
                dir: [-1.0, 0.0],
                len: 1.0,
            },
        ],
        features: 0b11_1111,
        two_sided: false,
        // Its first vertex is the world's origin: floats measure heights from there.
        world_heights: true,
    })];
    static ORDER: [u32; 1] = [0];
    // The grid: cells of 2^-23 units; the triangle's box grown by a cell; one leaf of one triangle.
    static NODES: [Node; 1] = [Node {
        boxes: [
            [0; 4],
            [0; 4],
            [0; 4],
            [129, 0, 0, 0],
            [2, 0, 0, 0],
            [129, 0, 0, 0],
        ],
        shift: [16, 0, 16],
        count: 1,
        children: [1 << 31, 0, 0, 0],
    }];
    static MESH: Mesh<'static, f32> = Mesh::from_parts(
        &NODES,
        &TRIANGLES,
        &ORDER,
        Grid {
            exponent: -23,
            lo: [-1, -1, -1],
            hi: [8_388_609, 1, 8_388_609],
        },
    );

    #[test]
    fn static_mesh_equals_the_build() {
        let v = Vec3::new;
        let source = [ballcast::Triangle::new(
            v(0.0f32, 0.0, 0.0),
            v(0.0, 0.0, 1.0),
            v(1.0, 0.0, 0.0),
        )];
        let built = super::build(&source, ballcast::Degenerates::Refuse).unwrap();
        assert_eq!(built.mesh(), MESH);
        let (mut nodes, mut tris) = ([Node::default(); 1], [Mesh::<f32>::filler(); 1]);
        let (mut order, mut scratch) = ([0u32; 1], [0u64; 6]);
        let deg = ballcast::Degenerates::Refuse;
        let checked = MESH.verify(
            &source,
            deg,
            &mut nodes,
            &mut tris,
            &mut order,
            &mut scratch,
        );
        assert_eq!(checked, Ok(()));
    }
}

/// A lone triangle 0.01 across at x = 10 000 (`f32`; `f64` at 10^13), shorter than the
/// T-junction test's tolerance there: with no neighbour, nothing covers its edges, and a ball
/// moving into its vertex stops there in a `Scene` and a `Mesh` as on the triangle alone. The
/// test once found such edges covered by nothing and let the ball through.
#[test]
fn small_triangle_far_out_keeps_its_edges() {
    fn case<S: Scalar>(x: f64, side: f64) {
        let t = Triangle::new(
            v::<S>([x, 0.0, 0.0]),
            v([x, 0.0, side]),
            v([x + side, 0.0, 0.0]),
        );
        let lone = ballcast::StandardTriangle::new(&t).unwrap();
        let mut scene: Scene<S, 1> = Scene::new();
        scene.push(t).unwrap();
        let mesh = build(&[t], Degenerates::Refuse).unwrap();
        let sweep = Sweep::new(
            v::<S>([x + 1.0, 0.0, 0.0]),
            v([x - 1.0, 0.0, 0.0]),
            S::from_f64(0.5),
        );
        let want = lone.cast(&sweep.unwrap()).unwrap();
        for got in [
            scene.cast(&sweep.unwrap()),
            mesh.mesh().cast(&sweep.unwrap()),
        ] {
            let got = got.expect("the vertex stops the ball");
            assert_eq!(
                (got.alpha, got.normal, got.contact),
                (want.alpha, want.normal, want.contact)
            );
        }
    }
    case::<f32>(10_000.0, 0.01);
    case::<f64>(1e13, 0.01);
}

/// The edges of a T-junction `(A edge 0, B edge 2, C edge 2)` as a `Scene` and a `Mesh` set
/// them, for a floor where sliver A (below z = 0, its far vertex `h` below its long edge)
/// covers the short edges of B and C above the line, at `x0`.
fn t_junction_edges<S: Scalar>(x0: f64, h: f64) -> [[bool; 3]; 2] {
    let p = |x: f64, z: f64| v::<S>([x0 + x, 0.0, z]);
    let tris = [
        Triangle::new(p(0.0, 0.0), p(2.0, 0.0), p(1.0, -h)),
        Triangle::new(p(0.0, 0.0), p(0.0, 1.0), p(1.0, 0.0)),
        Triangle::new(p(1.0, 0.0), p(1.0, 1.0), p(2.0, 0.0)),
        Triangle::new(p(0.0, 1.0), p(1.0, 1.0), p(1.0, 0.0)),
    ];
    let mut scene: Scene<S, 4> = Scene::new();
    for t in tris {
        scene.push(t).unwrap();
    }
    let owned = build(&tris, Degenerates::Refuse).unwrap();
    let at = |t: &ballcast::StandardTriangle<S>, e: usize| t.features().edge(e);
    let of = |t: &dyn Fn(usize) -> ballcast::StandardTriangle<S>| {
        [at(&t(0), 0), at(&t(1), 2), at(&t(2), 2)]
    };
    [
        of(&|i| *scene.triangle(i).unwrap()),
        of(&|i| *owned.mesh().triangle(i).unwrap()),
    ]
}

/// A sliver (its far vertex 10^-4 below its long edge, within the T-junction test's tolerance
/// in `I16F16`) and its neighbours cover each other's edges along their shared line: all go
/// off, as in thicker floors. An earlier rule kept the neighbours' edges on wherever a triangle
/// was thinner than the tolerance, and balls crossing the seam met them.
#[test]
fn a_sliver_covers_its_neighbours_edges() {
    let off = [[false; 3]; 2];
    for (x0, h) in [(10.0, 1e-4), (1000.0, 2e-4), (1000.0, 0.1)] {
        assert_eq!(t_junction_edges::<I16F16>(x0, h), off, "I16F16 {x0} {h}");
    }
    for (x0, h) in [(100.0, 1e-4), (4000.0, 1e-3), (1.0, 1.0)] {
        assert_eq!(t_junction_edges::<f32>(x0, h), off, "f32 {x0} {h}");
    }
}

/// Slivers lying along one side of a triangle's long edge, their edges on its line and
/// running the other way, but on the triangle's own side (`f32`, 10 000 out, 0.005 thin): they
/// hide nothing beyond it, so the edge stays on and a ball falling beside it lands on the edge.
/// The test once counted them as covering it.
#[test]
fn slivers_on_the_edges_own_side_leave_it_active() {
    let (x0, h) = (1e4, 0.005);
    let p = |x: f64, z: f64| v::<f32>([x0 + x, 0.0, z]);
    let up = |a, b, c| {
        let t = Triangle::new(a, b, c);
        let facing = ballcast::StandardTriangle::new(&t).is_ok_and(|s| s.normal().y > 0.0);
        if facing { t } else { Triangle::new(a, c, b) }
    };
    let tris = [
        Triangle::new(p(0.0, 0.0), p(2.0, 0.0), p(1.0, -h)),
        up(p(0.0, 0.0), p(1.0, -h), p(-1.0, -h * 0.5)),
        up(p(2.0, 0.0), p(1.0, -h), p(3.0, -h * 0.5)),
    ];
    let mut scene: Scene<f32, 3> = Scene::new();
    for t in tris {
        scene.push(t).unwrap();
    }
    let owned = build(&tris, Degenerates::Refuse).unwrap();
    assert!(scene.triangle(0).unwrap().features().edge(0));
    assert!(owned.mesh().triangle(0).unwrap().features().edge(0));
    let sweep = Sweep::new(p(1.3, 1.0), p(1.3, -1.0), 0.5).unwrap();
    let sweep = Sweep::new(
        sweep.p0() + v([0.0, 0.0, 0.3]),
        sweep.p1() + v([0.0, 0.0, 0.3]),
        0.5,
    );
    let hit = scene.cast(&sweep.unwrap()).unwrap();
    assert_eq!((hit.contact, hit.index), (ballcast::Contact::Edge(0), 0));
}
