//! [`Mesh::build`]: the tree over the triangles' boxes, preparation into its leaf order, active
//! edges (shared edges by a radix sort, then the open ones along T-junctions by the tree); or,
//! where a triangle is refused or skipped, preparation in input order first and the prepared
//! triangles moved into leaf order after.

use super::{Buffer, Degenerates, Mesh, MeshError, MeshOptions};
use crate::adjacency::{link_all, open_edges};
use crate::bvh::{self, BuildError, Cells, Grid, MAX_TRIANGLES, Node};
use crate::cover::cover_open;
use crate::merge::earliest;
use crate::triangle::prepare_here;
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
    /// With [`Degenerates::Refuse`] the tree comes first and each triangle is prepared straight
    /// into its leaf's slot (about 3 % faster on a terrain of 10^5 triangles); skipping, the
    /// triangles are prepared in input order, then moved into leaf order.
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
    /// an edge from behind. `two_sided` is asked in no set order, and may be asked twice for
    /// one index: it should answer from the index alone.
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
        let n = sources.len();
        if n > MAX_TRIANGLES {
            return Err(MeshError::TooMany);
        }
        let checks = [
            short(Buffer::Triangles, triangles.len(), n),
            short(Buffer::Order, order.len(), n),
            short(Buffer::Scratch, scratch.len(), 6 * n),
        ];
        if let Some(e) = checks.into_iter().flatten().next() {
            return Err(e);
        }
        let (kept, used, grid) = match in_leaf_order(
            sources, two_sided, options, nodes, triangles, order, scratch,
        ) {
            Some(tree) => tree,
            None => in_input_order(
                sources, two_sided, options, nodes, triangles, order, scratch,
            )?,
        };
        let (triangles, order) = (&mut triangles[..kept], &mut order[..kept]);
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

/// `Some` capacity error where a buffer of `len` elements holds fewer than `needed`.
fn short(buffer: Buffer, len: usize, needed: usize) -> Option<MeshError> {
    (len < needed).then_some(MeshError::Capacity {
        buffer,
        needed,
        given: len,
    })
}

/// The grid's exponent and box for a mesh whose kept vertices span `world` (in the scalar;
/// `None` for no triangle: `to_f64` is monotone, so it comes once, at the end).
fn grid_of<S: Scalar>(world: Option<([S; 3], [S; 3])>) -> (i32, Cells) {
    let (wlo, whi) = world.map_or(([f64::MAX; 3], [f64::MIN; 3]), |(lo, hi)| {
        (lo.map(S::to_f64), hi.map(S::to_f64))
    });
    let largest = (0..3).fold(0.0f64, |m, a| m.max(wlo[a].abs()).max(whi[a].abs()));
    let exponent = Grid::exponent_for(largest);
    let cells = match world {
        None => ([0; 3], [0; 3]),
        Some(_) => Grid::cells(exponent, wlo, whi),
    };
    (exponent, cells)
}

/// Grows the box `(lo, hi)` by the vertices of `t`; returns whether they lie within
/// `±LIMIT` (NaN does not).
fn grow<S: Scalar>((lo, hi): &mut ([S; 3], [S; 3]), t: &Triangle<S>) -> bool {
    let mut within = true;
    for p in t.vertices().map(Vec3::to_array) {
        for a in 0..3 {
            let c = p[a];
            within &= (c >= -S::LIMIT) & (c <= S::LIMIT);
            lo[a] = if c < lo[a] { c } else { lo[a] };
            hi[a] = if c > hi[a] { c } else { hi[a] };
        }
    }
    within
}

/// The tree's errors as the mesh's, `given` nodes.
fn tree_error(e: BuildError, given: usize) -> MeshError {
    match e {
        BuildError::Nodes(needed) => MeshError::Capacity {
            buffer: Buffer::Nodes,
            needed,
            given,
        },
        BuildError::Depth => MeshError::TooMany,
    }
}

/// The build where every triangle prepares (returns the triangles kept, the nodes used and the
/// grid): the tree first, over the sources' boxes, then each triangle prepared straight into
/// its slot in leaf order, so no prepared triangle is moved afterwards (on a terrain of 10^5
/// triangles, moving them took about 2.4 ms of a 28 ms build; built this way, the whole build
/// takes about 3 % less time). `None`, having written only into the buffers, where
/// degenerate triangles are to be skipped, a vertex lies out of range, a triangle is refused
/// or the nodes are too few: the input-order build then decides, naming the first triangle
/// refused in input order. Both give the same parts: the tree depends only on the boxes and the input
/// indices, and the active edges on the triangles, not on their slots.
fn in_leaf_order<S: Scalar>(
    sources: &[Triangle<S>],
    two_sided: &dyn Fn(usize) -> bool,
    options: MeshOptions,
    nodes: &mut [Node],
    triangles: &mut [StandardTriangle<S>],
    order: &mut [u32],
    scratch: &mut [u64],
) -> Option<(usize, usize, Grid)> {
    let (n, leaf_size) = (sources.len(), options.leaf_size);
    // Skipping, a degenerate triangle (common in exported levels) would only be found after
    // the tree was built over it, and the input-order build would start again.
    let skip = options.degenerates == Degenerates::Skip;
    if skip || nodes.len() < bvh::nodes_for_leaves(n, leaf_size) {
        return None;
    }
    // Every coordinate within range, so the boxes below are finite (no triangle: the other
    // path).
    let first = sources.first()?.v0.to_array();
    let mut world = (first, first);
    let within = sources.iter().fold(true, |ok, t| grow(&mut world, t) & ok);
    if !within {
        return None;
    }
    let (exponent, (lo, hi)) = grid_of(Some(world));
    let (items, rest) = scratch.split_at_mut(4 * n);
    let (items, _) = items.as_chunks_mut::<4>();
    let keys = rest.get_mut(..n)?;
    for (c, it) in items.iter_mut().enumerate() {
        let (blo, bhi) = Grid::bounds(&sources[c]);
        // Classes come once the active edges are known.
        *it = bvh::item(Grid::cells(exponent, blo, bhi), c, 0);
    }
    let used = bvh::build(items, keys, (lo, hi), nodes, leaf_size).ok()?;
    for (s, &k) in keys.iter().enumerate() {
        let index = bvh::key_index(k);
        let st = prepare_here(sources.get(index)?).ok()?;
        triangles[s] = st.with_two_sided(two_sided(index));
        order[s] = index as u32;
    }
    // The buffers may be longer than the mesh: only its slots.
    let (triangles, order) = (triangles.get_mut(..n)?, order.get_mut(..n)?);
    link_all(sources, order, triangles, &mut scratch[..6 * n]);
    // Each triangle's class once, in slot order, for the leaves to take the largest of.
    let classes = &mut scratch[..n];
    for (c, t) in classes.iter_mut().zip(triangles.iter()) {
        *c = bvh::class_of(t) as u64;
    }
    bvh::set_classes(&mut nodes[..used], |s| {
        classes.get(s).map_or(0, |&c| c as u32)
    });
    Some((n, used, Grid { exponent, lo, hi }))
}

/// The build in input order, skipping degenerate triangles where told to: each triangle
/// prepared as it comes (the first refused is named), then the tree, then the prepared
/// triangles moved into leaf order. Returns what [`in_leaf_order`] does.
fn in_input_order<S: Scalar>(
    sources: &[Triangle<S>],
    two_sided: &dyn Fn(usize) -> bool,
    options: MeshOptions,
    nodes: &mut [Node],
    triangles: &mut [StandardTriangle<S>],
    order: &mut [u32],
    scratch: &mut [u64],
) -> Result<(usize, usize, Grid), MeshError> {
    let MeshOptions {
        degenerates,
        leaf_size,
    } = options;
    // Prepare, in input order, keeping the input index; the kept triangles' world bounds.
    let mut kept = 0;
    let mut world = None;
    for (index, t) in sources.iter().enumerate() {
        match prepare_here(t) {
            Ok(st) => {
                triangles[kept] = st.with_two_sided(two_sided(index));
                order[kept] = index as u32;
                kept += 1;
                let p = t.v0.to_array();
                grow(world.get_or_insert((p, p)), t);
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
    let needed = bvh::nodes_for_leaves(kept, leaf_size);
    if let Some(e) = short(Buffer::Nodes, nodes.len(), needed) {
        return Err(e);
    }
    let (triangles, order) = (&mut triangles[..kept], &mut order[..kept]);
    link_all(sources, order, triangles, &mut scratch[..6 * kept]);
    let input = |o: &u32| open_edges(*o).0 as usize;
    let (exponent, (lo, hi)) = grid_of(world);
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
    let used =
        bvh::build(items, keys, (lo, hi), nodes, leaf_size).map_err(|e| tree_error(e, given))?;
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
    Ok((kept, used, Grid { exponent, lo, hi }))
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
mod tests;
