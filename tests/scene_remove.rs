//! `Scene::remove` and `Scene::retain`: the scene left is the scene built without the
//! triangles taken out, active edges included (an edge a removed triangle hid is active
//! again), whatever triangle goes, on a bumpy terrain (ridges and valleys), a floor with
//! T-junctions (edges hidden by covering, not by a shared vertex pair) and two-sided
//! triangles; an index beyond the scene changes nothing.
//! Every property in every scalar.

#[macro_use]
mod common;
mod meshes;

use ballcast::{Contact, Scalar, Scene, Sweep, Triangle};
use common::{P, Rng, v};

const N: usize = 64;

/// The scene of `src`, triangle `k` two-sided where `two_sided(k)`.
fn scene<S: Scalar>(src: &[[P; 3]], two_sided: impl Fn(usize) -> bool) -> Scene<S, N> {
    let mut s = Scene::new();
    for (k, &t) in src.iter().enumerate() {
        s.push_sided(meshes::tri(t), two_sided(k))
            .expect("valid triangle");
    }
    s
}

/// Whether two scenes hold the same prepared triangles (frames, active edges, sidedness) and
/// sources, in the same order.
fn same<S: Scalar>(a: &Scene<S, N>, b: &Scene<S, N>) -> bool {
    a.len() == b.len()
        && (0..a.len()).all(|k| a.triangle(k) == b.triangle(k))
        && a.sources().eq(b.sources())
}

fn removing_a_triangle_is_building_without_it<S: Scalar>() {
    let mut rng = Rng(0x5CE0_E5E5_0BAD_F00D);
    let terrain = meshes::heightfield(&mut rng, 4, 1.0, 0.4);
    let floor = meshes::t_junctions(&mut rng, 4);
    let odd = |k: usize| k % 3 == 1;
    for (src, two_sided) in [
        (&terrain, &odd as &dyn Fn(usize) -> bool),
        (&floor, &|_| false),
    ] {
        let full = scene::<S>(src, two_sided);
        let mut hidden = 0;
        for k in 0..src.len() {
            let mut s = full.clone();
            let removed = s.remove(k);
            assert_eq!(removed, Some(meshes::tri(src[k])), "triangle {k}");
            let rest: Vec<[P; 3]> = (0..src.len()).filter(|&j| j != k).map(|j| src[j]).collect();
            let sided = |j: usize| two_sided(if j < k { j } else { j + 1 });
            assert!(same(&s, &scene::<S>(&rest, sided)), "without triangle {k}");
            // Count the edges of the others that come back: the test must see some.
            let back = (0..s.len())
                .map(|j| (j, if j < k { j } else { j + 1 }))
                .filter(|&(j, f)| {
                    let (now, before) = (s.triangle(j).unwrap(), full.triangle(f).unwrap());
                    (0..3).any(|e| now.features().edge(e) && !before.features().edge(e))
                });
            hidden += back.count();
        }
        assert!(hidden > 0, "no removal made an edge active again");
    }
}

/// Two coplanar triangles sharing an edge hide it from each other; with one removed, a ball
/// falling beside the other's edge catches that edge again.
fn edge_comes_back_with_its_neighbour_gone<S: Scalar>() {
    let square: [[P; 3]; 2] = [
        [[0.0, 0.0, 0.0], [0.0, 0.0, 2.0], [2.0, 0.0, 2.0]],
        [[0.0, 0.0, 0.0], [2.0, 0.0, 2.0], [2.0, 0.0, 0.0]],
    ];
    let mut s = scene::<S>(&square, |_| false);
    assert!(
        !s.triangle(0).unwrap().features().edge(2),
        "the shared diagonal is hidden"
    );
    let beside = Sweep::new(v([1.3, 2.0, 0.7]), v([1.3, -2.0, 0.7]), S::from_f64(0.5)).unwrap();
    // Over the removed half, just past the diagonal: only the edge of the one left is met.
    assert_eq!(s.cast(&beside).map(|h| h.contact), Some(Contact::Face));
    assert_eq!(s.remove(1), Some(meshes::tri(square[1])));
    assert!(s.triangle(0).unwrap().features().edge(2));
    assert_eq!(s.cast(&beside).map(|h| h.contact), Some(Contact::Edge(2)));
}

fn removing_beyond_the_scene_changes_nothing<S: Scalar>() {
    let mut rng = Rng(0x0DD5_EED5);
    let src = meshes::heightfield(&mut rng, 2, 1.0, 0.3);
    let mut s = scene::<S>(&src, |_| false);
    let before = s.clone();
    assert_eq!(s.remove(src.len()), None);
    assert_eq!(s.remove(usize::MAX), None);
    assert!(same(&s, &before));
    let mut empty: Scene<S, N> = Scene::new();
    assert_eq!(empty.remove(0), None::<Triangle<S>>);
}

/// `retain` takes out a whole set at once: the scene built from the triangles kept, and the
/// count taken out; keeping all changes nothing.
fn retaining_is_building_from_those_kept<S: Scalar>() {
    let mut rng = Rng(0x7E7A_1A5E_5EED_0001);
    let src = meshes::heightfield(&mut rng, 4, 1.0, 0.4);
    let full = scene::<S>(&src, |k| k.is_multiple_of(5));
    for m in [2, 3, 7] {
        let mut s = full.clone();
        let mut seen = Vec::new();
        let out = s.retain(|k, t| {
            seen.push((k, *t));
            k % m != 1
        });
        let all: Vec<(usize, Triangle<S>)> =
            (0..src.len()).map(|k| (k, meshes::tri(src[k]))).collect();
        assert_eq!(
            seen, all,
            "retain offers each triangle once, in order, as pushed"
        );
        let kept: Vec<usize> = (0..src.len()).filter(|k| k % m != 1).collect();
        assert_eq!(out, src.len() - kept.len());
        let rest: Vec<[P; 3]> = kept.iter().map(|&k| src[k]).collect();
        assert!(
            same(&s, &scene::<S>(&rest, |j| kept[j].is_multiple_of(5))),
            "every {m}th from 1 out"
        );
    }
    let mut s = full.clone();
    assert_eq!(s.retain(|_, _| true), 0);
    assert!(same(&s, &full));
}

every_scalar!(
    removing_a_triangle_is_building_without_it,
    retaining_is_building_from_those_kept,
    edge_comes_back_with_its_neighbour_gone,
    removing_beyond_the_scene_changes_nothing
);
