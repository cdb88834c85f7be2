//! [`Mesh::build`]: preparation, active edges (shared edges by a radix sort, then the open
//! ones along T-junctions by the tree), the tree, and the triangles into its leaf order.

use super::{Buffer, Degenerates, Mesh, MeshError, MeshOptions};
use crate::adjacency::{link_all, open_edges};
use crate::bvh::{self, BuildError, Grid, MAX_TRIANGLES, Node};
use crate::cover::cover_open;
use crate::merge::earliest;
use crate::{Scalar, StandardTriangle, Sweep, Triangle, Vec3};

impl<'a, S: Scalar> Mesh<'a, S> {
    /// Prepares `sources`, computes their active edges and builds the tree, into the given
    /// buffers; returns the mesh borrowing them and the number of degenerate triangles skipped.
    /// Active edges follow [`Scene`](crate::Scene)'s rules: an edge shared with an opposite
    /// edge is off where the surface is flat or a valley there; an open edge (one sharing its
    /// vertex pair with no opposite edge but that of its own triangle's reverse) is off where
    /// flat neighbours cover it from end to end (a T-junction), found by walking the tree along
    /// it (neighbours on the edge's other side only). Unlike a `Scene`, a mesh applies the
    /// second rule to open edges only (an edge both
    /// shared and covered, which takes three or more triangles along one line, stays as the
    /// pair decides); an edge along more than 64 neighbours' edges, or with more than 256
    /// triangles near it (their boxes meeting its own, grown by a few roundings), stays active,
    /// and after `256 N` triangles met near edges in all (only where the triangles' boxes
    /// overlap wholesale) the edges not yet checked, in input order, stay active. The
    /// per-edge limits count by geometry alone, so below the overall budget the active edges
    /// are the same whatever the leaf size.
    ///
    /// `options`: a [`Degenerates`], or [`MeshOptions`] to choose the tree's leaf size too
    /// (leaves of up to two triangles unless told otherwise).
    ///
    /// Buffers: `nodes` at least [`nodes_for_leaves`](crate::bvh::nodes_for_leaves)`(kept,
    /// leaf size)` (kept = input less skipped; [`nodes_for`](crate::bvh::nodes_for)`(sources.len())`
    /// always suffices), `triangles` and `order` one per input triangle, `scratch` six words per
    /// input triangle. Time `O(N log N)` (active edges: plus one
    /// comparison per pair of triangles on either side of a shared edge), no allocation, stack
    /// use independent of `N`. The same input gives the same parts, byte for byte, on every target.
    ///
    /// Errors: [`MeshError::Triangle`] for a triangle [`StandardTriangle::new`] refuses (unless it
    /// is degenerate and `degenerates` is [`Degenerates::Skip`]); [`MeshError::Capacity`] for a
    /// buffer too small; [`MeshError::TooMany`] beyond 2^24 triangles.
    pub fn build(
        sources: &[Triangle<S>],
        options: impl Into<MeshOptions>,
        nodes: &'a mut [Node],
        triangles: &'a mut [StandardTriangle<S>],
        order: &'a mut [u32],
        scratch: &mut [u64],
    ) -> Result<(Self, usize), MeshError> {
        Self::build_sided(
            sources,
            |_| false,
            options,
            nodes,
            triangles,
            order,
            scratch,
        )
    }

    /// [`build`](Self::build) with the triangles for which `two_sided(index)` holds two-sided
    /// (as [`Scene::push_two_sided`](crate::Scene::push_two_sided) makes them: they stop balls
    /// from either side, at their edges and vertices too); the same active-edge rules as a
    /// `Scene` given the same sides. A level exported with mixed winding, thin walls and
    /// floors seen from below need them: a triangle added a second time reversed stops a ball
    /// at its face from behind, but not one that passes its plane beside it and comes back at
    /// an edge from behind.
    ///
    /// ```
    /// use ballcast::{bvh::nodes_for, Degenerates, Mesh, Node, Sweep, Triangle, Vec3};
    /// let v = Vec3::new;
    /// // A fence panel in the plane x = 0, two-sided.
    /// let tris = [
    ///     Triangle::new(v(0.0f32, 0.0, 0.0), v(0.0, 2.0, 0.0), v(0.0, 2.0, 2.0)),
    ///     Triangle::new(v(0.0, 0.0, 0.0), v(0.0, 2.0, 2.0), v(0.0, 0.0, 2.0)),
    /// ];
    /// let (mut nodes, mut prepared) = ([Node::default(); nodes_for(2)], [Mesh::filler(); 2]);
    /// let (mut order, mut scratch) = ([0u32; 2], [0u64; 12]);
    /// let (mesh, _) = Mesh::build_sided(&tris, |_| true, Degenerates::Refuse,
    ///     &mut nodes, &mut prepared, &mut order, &mut scratch)?;
    /// for x in [-2.0, 2.0] {
    ///     let hit = mesh.cast(&Sweep::new(v(x, 1.0, 1.0), v(-x, 1.0, 1.0), 0.5)?).unwrap();
    ///     assert_eq!(hit.alpha, 0.375); // the centre half a unit from the panel, either way
    /// }
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn build_sided(
        sources: &[Triangle<S>],
        two_sided: impl Fn(usize) -> bool,
        options: impl Into<MeshOptions>,
        nodes: &'a mut [Node],
        triangles: &'a mut [StandardTriangle<S>],
        order: &'a mut [u32],
        scratch: &mut [u64],
    ) -> Result<(Self, usize), MeshError> {
        // One copy of the build per scalar, whatever the closure and the options' type.
        let options = options.into();
        Self::build_into(
            sources, &two_sided, options, nodes, triangles, order, scratch,
        )
    }

    /// [`build_sided`](Self::build_sided) itself.
    fn build_into(
        sources: &[Triangle<S>],
        two_sided: &dyn Fn(usize) -> bool,
        options: MeshOptions,
        nodes: &'a mut [Node],
        triangles: &'a mut [StandardTriangle<S>],
        order: &'a mut [u32],
        scratch: &mut [u64],
    ) -> Result<(Self, usize), MeshError> {
        let MeshOptions {
            degenerates,
            leaf_size,
        } = options;
        let n = sources.len();
        if n > MAX_TRIANGLES {
            return Err(MeshError::TooMany);
        }
        let short = |buffer, len: usize, needed: usize| {
            (len < needed).then_some(MeshError::Capacity {
                buffer,
                needed,
                given: len,
            })
        };
        let checks = [
            short(Buffer::Triangles, triangles.len(), n),
            short(Buffer::Order, order.len(), n),
            short(Buffer::Scratch, scratch.len(), 6 * n),
        ];
        if let Some(e) = checks.into_iter().flatten().next() {
            return Err(e);
        }
        // Prepare, in input order, keeping the input index; the kept triangles' world bounds
        // (in the scalar: `to_f64` is monotone, so it can come once, at the end).
        let mut kept = 0;
        let mut world: Option<([S; 3], [S; 3])> = None;
        for (index, t) in sources.iter().enumerate() {
            match StandardTriangle::new(t) {
                Ok(st) => {
                    triangles[kept] = st.with_two_sided(two_sided(index));
                    order[kept] = index as u32;
                    kept += 1;
                    for p in t.vertices().map(Vec3::to_array) {
                        let (lo, hi) = world.get_or_insert((p, p));
                        for a in 0..3 {
                            if p[a] < lo[a] {
                                lo[a] = p[a];
                            }
                            if p[a] > hi[a] {
                                hi[a] = p[a];
                            }
                        }
                    }
                }
                Err(e) if e.is_degenerate() && degenerates == Degenerates::Skip => {}
                Err(e) => {
                    return Err(MeshError::Triangle {
                        index,
                        error: e.at(index),
                    });
                }
            }
        }
        if let Some(e) = short(
            Buffer::Nodes,
            nodes.len(),
            bvh::nodes_for_leaves(kept, leaf_size),
        ) {
            return Err(e);
        }
        let (triangles, order) = (&mut triangles[..kept], &mut order[..kept]);
        let (wlo, whi) = world.map_or(([f64::MAX; 3], [f64::MIN; 3]), |(lo, hi)| {
            (lo.map(S::to_f64), hi.map(S::to_f64))
        });
        let largest = (0..3).fold(0.0f64, |m, a| m.max(wlo[a].abs()).max(whi[a].abs()));
        link_all(sources, order, triangles, &mut scratch[..6 * kept]);
        let input = |o: &u32| open_edges(*o).0 as usize;
        let exponent = Grid::exponent_for(largest);
        let (lo, hi) = if kept == 0 {
            ([0; 3], [0; 3])
        } else {
            Grid::cells(exponent, wlo, whi)
        };
        // Scratch: the items (four words each), the build's keys, the old order.
        let (items, rest) = scratch.split_at_mut(4 * kept);
        let (items, _) = items.as_chunks_mut::<4>();
        let (keys, rest) = rest.split_at_mut(kept);
        for (c, it) in items.iter_mut().enumerate() {
            let (blo, bhi) = Grid::bounds(&sources[input(&order[c])]);
            let class = bvh::class_of(&triangles[c]);
            *it = bvh::item(Grid::cells(exponent, blo, bhi), c, class);
        }
        let given = nodes.len();
        let used = bvh::build(items, keys, (lo, hi), nodes, leaf_size).map_err(|e| match e {
            BuildError::Nodes(needed) => MeshError::Capacity {
                buffer: Buffer::Nodes,
                needed,
                given,
            },
            BuildError::Depth => MeshError::TooMany,
        })?;

        // Into leaf order: slot s takes compact triangle key_index(keys[s]).
        let old = &mut rest[..kept];
        for (o, &i) in old.iter_mut().zip(order.iter()) {
            *o = i as u64;
        }
        for (i, &k) in order.iter_mut().zip(keys.iter()) {
            *i = old[bvh::key_index(k)] as u32;
        }
        // Along each cycle of the permutation, marking the slots placed.
        const PLACED: u64 = 1 << 63;
        for start in 0..kept {
            if keys[start] & PLACED != 0 {
                continue;
            }
            let held = triangles[start];
            let mut s = start;
            loop {
                keys[s] |= PLACED;
                let from = bvh::key_index(keys[s]);
                if from == start {
                    triangles[s] = held;
                    break;
                }
                triangles[s] = triangles[from];
                s = from;
            }
        }
        let grid = Grid { exponent, lo, hi };
        let nodes = &mut nodes[..used];
        if cover(sources, nodes, &grid, triangles, order, &mut scratch[..n]) {
            bvh::set_classes(nodes, |s| triangles.get(s).map_or(0, bvh::class_of));
        }
        for o in order.iter_mut() {
            *o = open_edges(*o).0;
        }
        let (nodes, triangles, order): (&'a [Node], &'a [StandardTriangle<S>], &'a [u32]) =
            (nodes, triangles, order);
        Ok((Self::from_parts(nodes, triangles, order, grid), n - kept))
    }
}

/// Switches off the open edges (marked in `order` by `link_all`) that flat neighbours cover,
/// finding the neighbours with the tree. Returns whether any edge was switched off.
fn cover<S: Scalar>(
    sources: &[Triangle<S>],
    nodes: &[Node],
    grid: &Grid,
    triangles: &mut [StandardTriangle<S>],
    order: &[u32],
    scratch: &mut [u64],
) -> bool {
    let source = |s: usize| {
        let (i, _) = open_edges(*order.get(s)?);
        sources.get(i as usize)
    };
    let open = |s: usize| order.get(s).map_or(0, |&o| open_edges(o).1);
    // The slots in input order (one more than each slot, by input index; zero for a triangle
    // skipped), so that the edges are checked in an order every tree shares.
    scratch.fill(0);
    for (s, &o) in order.iter().enumerate() {
        if let Some(at) = scratch.get_mut(open_edges(o).0 as usize) {
            *at = s as u64 + 1;
        }
    }
    let slots = scratch.iter().filter(|&&s| s != 0).map(|&s| s as usize - 1);
    // Along each edge as a sweep of a ball: the leaves near its line only, however it runs.
    cover_open(triangles, slots, source, open, |a, b, r, f| {
        let Ok(edge) = Sweep::new(a, b, r) else {
            return;
        };
        earliest(&edge, |acc| {
            bvh::leaves_along(nodes, grid, &edge, acc, |_, slots, _| {
                slots.for_each(&mut *f)
            });
        });
    })
}

#[cfg(test)]
mod tests {
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
}
