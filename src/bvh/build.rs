//! The build: items split at the median of their centres into complete 4-wide subtrees (see
//! the module docs of [`bvh`](super)).

use super::{
    CLASS_SHIFT, Cells, LEAF_FLAG, LeafSize, MAX_CLASS, MAX_DEPTH, Node, PAYLOAD, STACK, leaf_slots,
};

/// Why a tree could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum BuildError {
    /// The node slice holds fewer than this many nodes.
    Nodes(usize),
    /// Deeper than [`MAX_DEPTH`] (cannot happen below [`MAX_TRIANGLES`](super::MAX_TRIANGLES)).
    Depth,
}

/// The sizes of the up to four children of a node over `n > 0` items (zeros unused), for
/// leaves of up to `leaf` items: each takes as many as a complete subtree one level down holds
/// (`leaf * 4^k` for the smallest `k` with `4^(k+1)` leaves enough for all), the last what
/// remains. Every subtree but the last at each level is complete, so a mesh of `N` triangles
/// needs about `N / (3 leaf)` nodes.
const fn parts(n: usize, leaf: usize) -> [usize; 4] {
    let leaves = n.div_ceil(leaf);
    // `per * 4 < leaves`, with no product that can overflow for any `n`.
    let mut per = 1;
    while per < leaves.div_ceil(4) {
        per *= 4;
    }
    let per = per.saturating_mul(leaf);
    let mut out = [0; 4];
    let (mut k, mut left) = (0, n);
    while k < 4 {
        out[k] = if left < per { left } else { per };
        left -= out[k];
        k += 1;
    }
    out
}

/// Nodes the build makes for `n` triangles (zero for none) with the default
/// [`LeafSize::Two`]: size the node slice with it (it is enough for every leaf size).
pub const fn nodes_for(n: usize) -> usize {
    nodes_for_leaves(n, LeafSize::Two)
}

/// Nodes the build makes for `n` triangles (zero for none) with leaves of `leaves`.
/// `O(log² n)`: a node's complete children are alike, so one of them is counted for all.
pub const fn nodes_for_leaves(n: usize, leaves: LeafSize) -> usize {
    if n == 0 {
        return 0;
    }
    let leaf = leaves.triangles();
    let p = parts(n, leaf);
    let mut total = 1;
    // The last child counted: its size and nodes.
    let (mut size, mut nodes) = (0, 0);
    let mut k = 0;
    while k < 4 {
        if p[k] > leaf {
            if p[k] != size {
                (size, nodes) = (p[k], nodes_for_leaves(p[k], leaves));
            }
            total += nodes;
        }
        k += 1;
    }
    total
}

/// One triangle during the build: its box's minimum in cells and its index (first two words,
/// two halves each), its box's maximum and its [`seam_class`](super::seam_class) (last two): four
/// lanes of minima, four of maxima, so a union is lane by lane.
pub(crate) type Item = [u64; 4];

/// Packs a box, an index and a seam class into an [`Item`].
pub(crate) fn item((lo, hi): Cells, index: usize, class: u32) -> Item {
    let w = |a: i32, b: i32| (a as u32 as u64) | ((b as u32 as u64) << 32);
    [
        w(lo[0], lo[1]),
        w(lo[2], index as u32 as i32),
        w(hi[0], hi[1]),
        w(hi[2], class as i32),
    ]
}

/// The two lanes of a word of an [`Item`].
fn lanes(w: u64) -> [i32; 2] {
    [w as u32 as i32, (w >> 32) as u32 as i32]
}

/// The box of an [`Item`].
pub(crate) fn item_box(it: &Item) -> Cells {
    let ([a, b], [c, _], [d, e], [f, _]) = (lanes(it[0]), lanes(it[1]), lanes(it[2]), lanes(it[3]));
    ([a, b, c], [d, e, f])
}

/// Bits of a key holding an item's index.
const INDEX_BITS: u32 = 24;
/// The index part of a key.
const INDEX: u64 = (1 << INDEX_BITS) - 1;

/// The index of the item a key refers to.
pub(crate) fn key_index(key: u64) -> usize {
    (key & INDEX) as usize
}

/// The union of the boxes of the items `keys` refer to, lane by lane (the index's and the
/// class's lanes left out: classes are set once the tree is built).
#[inline(never)]
fn union(keys: &[u64], items: &[Item]) -> Cells {
    let (mut lo, mut hi) = ([i32::MAX; 3], [i32::MIN; 3]);
    for it in keys.iter().filter_map(|&k| items.get(key_index(k))) {
        let ([a, b], [c, _]) = (lanes(it[0]), lanes(it[1]));
        let ([e, f], [g, _]) = (lanes(it[2]), lanes(it[3]));
        let (l, u) = ([a, b, c], [e, f, g]);
        for k in 0..3 {
            lo[k] = lo[k].min(l[k]);
            hi[k] = hi[k].max(u[k]);
        }
    }
    (lo, hi)
}

/// The seam class of the item in slot `s` once the keys are in leaf order.
fn class_at(keys: &[u64], items: &[Item], s: usize) -> u32 {
    let it = keys.get(s).and_then(|&k| items.get(key_index(k)));
    it.map_or(0, |it| lanes(it[3])[1].max(0) as u32)
}

/// Bits per axis of a key's quantized centre.
const CENTRE_BITS: u32 = 13;

/// The key of an item: its box's centre quantized to [`CENTRE_BITS`] per axis on one scale for
/// the three axes (x above y above z: [`Fields`] `[0, 1, 2]`), above its index.
fn key_of(it: &Item, c: usize, (lo, hi): Cells) -> u64 {
    let extent = (0..3).fold(0i64, |m, a| m.max(hi[a] as i64 - lo[a] as i64));
    let (blo, bhi) = item_box(it);
    let q = |a: usize| {
        let twice = blo[a] as i64 + bhi[a] as i64 - 2 * lo[a] as i64;
        ((twice.clamp(0, 2 * extent) << CENTRE_BITS) / (2 * extent + 1)) as u64
    };
    let centres = q(0) << (2 * CENTRE_BITS) | q(1) << CENTRE_BITS | q(2);
    centres << INDEX_BITS | c as u64 & INDEX
}

/// Which axis's centre each field of a key holds, from the top: the keys' own order is by the
/// centre on the first, then the second, the third, the index.
type Fields = [usize; 3];

/// Rewrites the centres of `keys`, whose fields are those of `*fields`, into the fields `to`.
fn arrange(keys: &mut [u64], fields: &mut Fields, to: Fields) {
    if *fields == to {
        return;
    }
    let at = |f: usize| (2 - f) as u32 * CENTRE_BITS + INDEX_BITS;
    // Where each new field's axis sits now: the same shifts for every key.
    let from = to.map(|a| at(fields.iter().position(|&b| b == a).unwrap_or(0)));
    let mask = (1u64 << CENTRE_BITS) - 1;
    for key in keys.iter_mut() {
        let k = *key;
        let field = |f: usize| (k >> from[f] & mask) << at(f);
        *key = field(0) | field(1) | field(2) | k & INDEX;
    }
    *fields = to;
}

/// Puts the `m` keys with the smallest centres on the longest axis of `bounds` (the lowest such
/// axis on a tie) first: an object-median split. Equal centres on that axis (a grid's columns)
/// are ordered by the centre on the next longest axis, so that a run cut out of a column is
/// a stretch of it, not a scatter along it; then by the last axis and the index. The order is
/// a total one, so the split is the same whatever algorithm makes it. Returns `bounds` cut at
/// the median: the two sides' boxes as far as choosing their own split axis needs. `root` is
/// the box the centres were quantized in; `fields`, the keys' fields.
fn split(
    keys: &mut [u64],
    m: usize,
    (lo, hi): Cells,
    root: Cells,
    fields: &mut Fields,
) -> (Cells, Cells) {
    if m == 0 || m >= keys.len() {
        return ((lo, hi), (lo, hi));
    }
    // The axes longest first, the lower axis on a tie.
    let mut by = [0, 1, 2];
    let length = |a: usize| hi[a] as i64 - lo[a] as i64;
    by.sort_unstable_by_key(|&a| (core::cmp::Reverse(length(a)), a));
    let axis = by[0];
    arrange(keys, fields, by);
    let (_, &mut median, _) = keys.select_nth_unstable(m);
    let extent = (0..3).fold(0i64, |m, a| m.max(root.1[a] as i64 - root.0[a] as i64));
    let q = (median >> (INDEX_BITS + 2 * CENTRE_BITS)) as i64;
    let cut = root.0[axis] as i64 + ((q * (2 * extent + 1)) >> (CENTRE_BITS + 1));
    let (mut left, mut right) = (hi, lo);
    (left[axis], right[axis]) = (cut as i32, cut as i32);
    ((lo, left), (right, hi))
}

/// Builds the tree over `items` (each a triangle's box, index and seam class: zero where the
/// caller sets the classes afterwards with [`set_classes`]) into `nodes`, the root's box being
/// `root`, with leaves of `leaves`. `keys` (one per item, any values) ends in leaf order: slot `s`
/// holds item [`key_index`]`(keys[s])`. Returns the number of nodes used.
pub(crate) fn build(
    items: &[Item],
    keys: &mut [u64],
    root: Cells,
    nodes: &mut [Node],
    leaves: LeafSize,
) -> Result<usize, BuildError> {
    let n = items.len().min(keys.len());
    let keys = &mut keys[..n];
    for (c, (key, it)) in keys.iter_mut().zip(items).enumerate() {
        *key = key_of(it, c, root);
    }
    let needed = nodes_for_leaves(n, leaves);
    let leaf = leaves.triangles();
    if nodes.len() < needed {
        return Err(BuildError::Nodes(needed));
    }
    if n == 0 {
        return Ok(0);
    }
    // (node, first item, item count, node box, depth, its keys' fields)
    type Work = (usize, usize, usize, Cells, usize, Fields);
    let mut work: heapless::Vec<Work, STACK> = heapless::Vec::new();
    let _ = work.push((0, 0, n, root, 1, [0, 1, 2]));
    let mut next = 1;
    while let Some((at, first, count, (lo, hi), depth, mut fields)) = work.pop() {
        if depth > MAX_DEPTH {
            return Err(BuildError::Depth);
        }
        let range = &mut keys[first..first + count];
        // Up to four runs: the two halves split at the median, each split again.
        let p = parts(count, leaf);
        let (lb, rb) = split(range, p[0] + p[1], (lo, hi), root, &mut fields);
        let (left, right) = range.split_at_mut(p[0] + p[1]);
        let (mut lf, mut rf) = (fields, fields);
        split(left, p[0], lb, root, &mut lf);
        split(right, p[2], rb, root, &mut rf);
        let all = [lf, lf, rf, rf];
        let bounds = [
            (0, p[0]),
            (p[0], p[0] + p[1]),
            (p[0] + p[1], p[0] + p[1] + p[2]),
            (p[0] + p[1] + p[2], count),
        ];
        let mut node = Node::default();
        for ax in 0..3 {
            let extent = hi[ax] as i64 - lo[ax] as i64;
            let mut s = 0;
            while extent > 255 << s {
                s += 1;
            }
            node.shift[ax] = s as u8;
        }
        for (&(s, e), &fields) in bounds.iter().zip(&all) {
            if s == e {
                continue;
            }
            let part = &mut range[s..e];
            let (clo, chi) = union(part, items);
            let k = node.count as usize;
            let mut dlo = [0; 3];
            let mut dhi = [0; 3];
            for ax in 0..3 {
                let sh = node.shift[ax] as u32;
                let step = 1i64 << sh;
                let qlo = (clo[ax] as i64 - lo[ax] as i64) >> sh;
                let qhi = (chi[ax] as i64 - lo[ax] as i64 + step - 1) >> sh;
                node.boxes[ax][k] = qlo as u8;
                node.boxes[3 + ax][k] = qhi as u8;
                dlo[ax] = lo[ax] + ((qlo as i32) << sh);
                dhi[ax] = lo[ax] + ((qhi as i32) << sh);
            }
            if part.len() <= leaf {
                part.sort_unstable_by_key(|&k| k & INDEX);
                node.children[k] = LEAF_FLAG | ((first + s) as u32) << 2 | (part.len() - 1) as u32;
            } else {
                let child = next;
                next += 1;
                if child >= nodes.len() {
                    return Err(BuildError::Nodes(needed));
                }
                node.children[k] = child as u32;
                if work
                    .push((child, first + s, e - s, (dlo, dhi), depth + 1, fields))
                    .is_err()
                {
                    return Err(BuildError::Depth);
                }
            }
            node.count += 1;
        }
        nodes[at] = node;
    }
    // Every child comes after its parent: the seam classes bottom-up.
    set_classes(&mut nodes[..next], |s| class_at(keys, items, s));
    Ok(next)
}

/// Sets anew the seam class of every child reference in `nodes`, made by [`build`] (so every
/// node's children come after it): a leaf's is the largest `class(slot)` of its triangles, a
/// node's the largest of its own children's. For a mesh whose active edges changed after the
/// build.
pub(crate) fn set_classes(nodes: &mut [Node], class: impl Fn(usize) -> u32) {
    let of = |node: &Node| {
        let refs = node.children.iter().take(node.count as usize);
        refs.map(|&c| super::class_bits(c)).max().unwrap_or(0)
    };
    for at in (0..nodes.len()).rev() {
        let Some(&node) = nodes.get(at) else {
            continue;
        };
        let mut children = node.children;
        for child in children.iter_mut().take(node.count as usize) {
            let c = match leaf_slots(*child) {
                Some(slots) => slots.map(&class).max().unwrap_or(0),
                None => nodes.get((*child & PAYLOAD) as usize).map_or(0, of),
            };
            *child = *child & !(MAX_CLASS << CLASS_SHIFT) | c.min(MAX_CLASS) << CLASS_SHIFT;
        }
        if let Some(node) = nodes.get_mut(at) {
            node.children = children;
        }
    }
}
