//! The earliest contact among many triangles, with simultaneous contacts merged by a rule that
//! does not depend on the order the triangles are visited in.
//!
//! A linear scan meets triangles in index order, a tree in whatever order its traversal takes;
//! both must give the same bits. So the answer is defined on the set of contacts, not on the
//! visit: the earliest is the smallest alpha (the smallest index on an exact tie); the contacts
//! *tied* with it are those whose alpha lies within [`tie`] of it, each of which could have come
//! first but for rounding; their normals are summed in index order. [`Earliest`] keeps the
//! tied contacts with the [`TIES`] smallest indices in a fixed buffer; in the rare case that it
//! had to drop one while the window was still moving, [`earliest`] visits once more with the
//! window fixed, which makes the kept set exact.

use crate::contact::unit;
use crate::scalar::tie;
use crate::{Contact, Hit, Scalar, SceneHit, Vec3};
use heapless::Vec;

/// How many tied contacts are kept (by smallest index): a vertex where eight triangles meet.
pub(crate) const TIES: usize = 8;

/// How many distinct planes a [`SceneHit`] lists: more than three are never needed to stop a
/// ball, and a slide uses at most this many.
pub const PLANES: usize = 4;

/// A tied contact: its triangle's index, alpha, normal and feature.
type Tie<S> = (usize, S, Vec3<S>, Contact);

/// An accumulator for the contacts of one sweep, fed in any order with [`offer`](Self::offer).
/// (Public only to name it in [`CompoundPart`](crate::compound::CompoundPart)'s hidden method:
/// this module is private, so no user can.)
#[derive(Debug)]
pub struct Earliest<S: Scalar> {
    best: Option<(usize, Hit<S>)>,
    /// Added to the index of every contact offered: where the current part of a
    /// [`Compound`](crate::Compound) starts in its index space.
    base: usize,
    /// The tied contacts as `(index, alpha, normal, feature)`: all the merge needs, so that a
    /// firmware's stack pays for no more.
    ties: Vec<Tie<S>, TIES>,
    /// Set on the second visit: the window no longer moves.
    fixed: Option<S>,
    /// A tied contact was dropped for room while the window could still shrink.
    lossy: bool,
}

impl<S: Scalar> Earliest<S> {
    fn new(fixed: Option<S>) -> Self {
        Self {
            best: None,
            base: 0,
            ties: Vec::new(),
            fixed,
            lossy: false,
        }
    }

    /// The largest alpha still worth testing: contacts later than this can neither come first
    /// nor tie with the first. One (the end of the path) while nothing was found.
    pub(crate) fn reach(&self) -> S {
        match (self.fixed, self.best) {
            (Some(w), _) => w,
            (None, Some((_, b))) => b.alpha + tie::<S>(),
            (None, None) => S::ONE,
        }
    }

    /// Sets the index the next contacts' indices count from; returns the one before.
    pub(crate) fn rebase(&mut self, base: usize) -> usize {
        core::mem::replace(&mut self.base, base)
    }

    /// Takes the contact of triangle `index`.
    pub(crate) fn offer(&mut self, index: usize, hit: Hit<S>) {
        if hit.alpha > self.reach() {
            return;
        }
        let index = self.base.saturating_add(index);
        let first = self
            .best
            .is_none_or(|(i, b)| hit.alpha < b.alpha || (hit.alpha == b.alpha && index < i));
        if first {
            self.best = Some((index, hit));
            let reach = self.reach();
            self.ties.retain(|t| t.1 <= reach);
        }
        // Keep the buffer sorted by index, dropping the largest index when full.
        let at = self.ties.partition_point(|t| t.0 < index);
        if self.ties.is_full() {
            self.lossy |= self.fixed.is_none();
            if at == TIES {
                return;
            }
            self.ties.pop();
        }
        // Room was made above, so the push succeeds; then the entry rotates into place. (No
        // `insert`: its index assertion would leave a panic path the optimiser cannot remove.)
        if self
            .ties
            .push((index, hit.alpha, hit.normal, hit.contact))
            .is_ok()
            && let Some(tail) = self.ties.get_mut(at..)
            && !tail.is_empty()
        {
            tail.rotate_right(1);
        }
    }

    fn finish(self) -> Option<SceneHit<S>> {
        let (
            index,
            Hit {
                alpha,
                position,
                normal,
                contact,
            },
        ) = self.best?;
        // An edge or vertex in the plane of a face touched at the same moment adds nothing but
        // its rounding (a ghost bump, e.g. an open edge where neighbours meet in a T-junction):
        // the face speaks for it.
        let face_has = |n: Vec3<S>| {
            self.ties
                .iter()
                .any(|&(_, _, m, c)| c == Contact::Face && same_plane(m, n))
        };
        let mut planes = [None; PLANES];
        let (mut sum, mut count, mut only) = (Vec3::ZERO, 0, normal);
        for &(_, _, n, c) in &self.ties {
            if c != Contact::Face && face_has(n) {
                continue;
            }
            (sum, count, only) = (sum + n, count + 1, n);
            if !planes.iter().flatten().any(|p| same_plane(*p, n))
                && let Some(slot) = planes.iter_mut().find(|p| p.is_none())
            {
                *slot = Some(n);
            }
        }
        let normal = if count > 1 {
            unit(sum).unwrap_or(only)
        } else {
            only
        };
        Some(SceneHit {
            alpha,
            position,
            normal,
            contact,
            index,
            planes,
        })
    }
}

/// Whether two unit normals agree within about 1e-3 rad per component: one plane for a response.
pub(crate) fn same_plane<S: Scalar>(a: Vec3<S>, b: Vec3<S>) -> bool {
    let d = a - b;
    let tol = S::div_pow2(S::ONE, 10);
    d.x.abs() <= tol && d.y.abs() <= tol && d.z.abs() <= tol
}

/// The earliest contact found by `visit`, which offers contacts (in any order) to the
/// accumulator it is given and may skip whatever lies beyond its [`reach`](Earliest::reach).
/// `visit` runs once, or twice when more than [`TIES`] contacts tied and the first run could
/// not keep the right ones.
pub(crate) fn earliest<S: Scalar>(mut visit: impl FnMut(&mut Earliest<S>)) -> Option<SceneHit<S>> {
    let mut acc = Earliest::new(None);
    visit(&mut acc);
    if acc.lossy {
        // The second run in the first's place: one accumulator on the stack.
        acc = Earliest::new(Some(acc.reach()));
        visit(&mut acc);
    }
    acc.finish()
}

/// [`earliest`] over the contacts `offer(acc, scan)` gives: by its quick path (`scan` false),
/// which returns false when it found its parts malformed; then over all of them by a scan
/// (`scan` true) of every triangle, whose answer holds whatever the parts.
pub(crate) fn earliest_of<S: Scalar>(
    mut offer: impl FnMut(&mut Earliest<S>, bool) -> bool,
) -> Option<SceneHit<S>> {
    let mut sound = true;
    let hit = earliest(|acc| sound &= offer(acc, false));
    if sound {
        return hit;
    }
    earliest(|acc| {
        offer(acc, true);
    })
}
