//! The build's own cases: what the public tests cannot see (leaf classes).

use crate::bvh::{Node, class_bits, class_of, leaf_slots, nodes_for};
use crate::{Degenerates, Mesh, Scene, Triangle, Vec3};

/// A lone thin floor triangle (all edges active until the build covers one) whose long
/// edge two fatter coplanar triangles cover, meeting in a T-junction at its middle: the
/// edge is switched off, as in a `Scene`, and the leaf's seam class, the thin one's (the
/// largest once its edge is off), follows the change.
#[test]
fn t_junction_covers_a_lone_triangles_edge() {
    let v = |x: f32, z: f32| Vec3::new(x, 0.0, z);
    let floor = [
        Triangle::new(v(0.9, 0.9), v(0.0, 2.0), v(2.0, 0.0)),
        Triangle::new(v(2.0, 0.0), v(1.0, 1.0), v(2.0, 2.0)),
        Triangle::new(v(1.0, 1.0), v(0.0, 2.0), v(2.0, 2.0)),
    ];
    let mut nodes = [Node::default(); nodes_for(3)];
    let mut tris = [Mesh::<f32>::filler(); 3];
    let (mut order, mut scratch) = ([0u32; 3], [0u64; 18]);
    let (mesh, _) = Mesh::build(
        &floor,
        Degenerates::Refuse,
        &mut nodes,
        &mut tris,
        &mut order,
        &mut scratch,
    )
    .unwrap();
    let mut scene: Scene<f32, 3> = Scene::new();
    for t in floor {
        scene.push(t).unwrap();
    }
    let lone = mesh.triangle(0).unwrap();
    assert!(!lone.features().edge(1) && lone.features().edge(0));
    for i in 0..3 {
        let want = scene.triangle(i).unwrap().features();
        assert_eq!(mesh.triangle(i).unwrap().features(), want, "triangle {i}");
    }
    // Every leaf's class is the largest of its triangles' (the lone one's has grown).
    assert!(class_of(lone) > 0);
    let children = mesh
        .nodes()
        .iter()
        .flat_map(|n| n.children.iter().take(n.count as usize));
    let leaves: Vec<_> = children
        .filter_map(|&c| Some((c, leaf_slots(c)?)))
        .collect();
    assert!(!leaves.is_empty());
    for (child, slots) in leaves {
        let most = slots.map(|s| class_of(&mesh.triangles()[s])).max();
        assert_eq!(Some(class_bits(child)), most);
    }
}
