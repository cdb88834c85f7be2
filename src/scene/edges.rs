//! A scene's active edges: found as triangles are pushed (each new one against the earlier
//! ones), and anew for all once one is removed.

use super::Scene;
use crate::adjacency::{deactivate, hides};
use crate::cover::{covered, interval};
use crate::{Features, Scalar};

impl<S: Scalar, const N: usize> Scene<S, N> {
    /// Every edge active again, then each triangle linked and covered in index order, against
    /// the ones before it, as pushing them in that order does.
    pub(super) fn active_edges_anew(&mut self) {
        for t in self.triangles.iter_mut() {
            *t = t.with_features(Features::ALL);
        }
        for index in 0..self.triangles.len() {
            self.edges_against_earlier(index);
        }
    }

    /// Triangle `index`'s edges against those of the triangles before it, and theirs against
    /// its, as when it was the last pushed.
    pub(super) fn edges_against_earlier(&mut self, index: usize) {
        for other in 0..index {
            self.link(index, other);
        }
        self.cover(index);
    }

    /// Switches off edges that flat neighbours cover without sharing a vertex pair
    /// (T-junctions): those of triangle `t`, and those of earlier triangles that one of `t`'s
    /// edges runs along. Only the triangles up to `t` count, as when `t` was the last pushed.
    ///
    /// Only triangles whose boxes meet are compared: an edge that runs along another within
    /// the tolerance of `interval` lies within it of that edge, far inside the rounding the
    /// boxes are grown by, so the answers are those of comparing every pair.
    fn cover(&mut self, t: usize) {
        let v = self.sources[t].vertices();
        let upto = t + 1;
        for j in 0..upto {
            let box_j = self.bounds[j];
            if j != t && !box_j.overlaps(&self.bounds[t]) {
                continue;
            }
            for k in 0..3 {
                let (tj, tt) = (&self.triangles[j], &self.triangles[t]);
                if !tj.features().edge(k) {
                    continue;
                }
                let near = j == t || (0..3).any(|e| interval(tj, k, tt, v, e).is_some());
                let all = (self
                    .bounds
                    .iter()
                    .zip(self.triangles.iter().zip(self.sources.iter())))
                .take(upto)
                .filter(|(b, _)| b.overlaps(&box_j))
                .map(|(_, pair)| pair);
                if near && covered(tj, k, all) {
                    deactivate(&mut self.triangles[j], k);
                }
            }
        }
    }

    /// Switches off the edges `a` and `b` share where the surface is flat or a valley there.
    /// (Triangles that share a vertex pair have boxes that meet: others are passed by.)
    fn link(&mut self, a: usize, b: usize) {
        if !self.bounds[a].overlaps(&self.bounds[b]) {
            return;
        }
        let (ta, tb) = (self.sources[a].vertices(), self.sources[b].vertices());
        for i in 0..3 {
            for j in 0..3 {
                let shared = ta[i] == tb[(j + 1) % 3] && ta[(i + 1) % 3] == tb[j];
                if shared && hides(&self.triangles[a], &self.triangles[b], tb[(j + 2) % 3]) {
                    deactivate(&mut self.triangles[a], i);
                    deactivate(&mut self.triangles[b], j);
                }
            }
        }
    }
}
