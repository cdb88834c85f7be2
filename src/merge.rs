//! The earliest contact among many triangles, with simultaneous contacts merged by a rule that
//! does not depend on the order the triangles are visited in.
//!
//! A linear scan meets triangles in index order, a tree in whatever order its traversal takes;
//! both must give the same bits. So the answer is defined on the set of contacts, not on the
//! visit: the earliest is the smallest alpha; among equal alphas, the contact whose position
//! (the ball's centre at contact, formed from the unrounded fraction) lies first along the
//! path, then the smallest index. The contacts *tied* with it are those that could have come
//! first but for rounding: alpha within [`tie`] of its alpha, and position within twice the
//! position's rounding of its position ([`Window`]: on a long fixed-point path four steps of
//! alpha are far apart along it, and contacts that far apart are not simultaneous); their
//! normals are summed in index order. [`Earliest`] keeps the contacts within the alpha window with the [`TIES`]
//! smallest indices in a fixed buffer; in the rare case that it had to drop one while the
//! window was still moving, [`earliest`] visits once more with the earliest contact known,
//! which makes the kept set exact.

use crate::contact::unit;
use crate::scalar::{largest, tie};
use crate::{Contact, Hit, Scalar, SceneHit, Sweep, Vec3};
use heapless::Vec;

/// How many tied contacts are kept (by smallest index): a vertex where eight triangles meet.
pub(crate) const TIES: usize = 8;

/// How many distinct planes a [`SceneHit`] lists: more than three are never needed to stop a
/// ball, and a slide uses at most this many.
pub const PLANES: usize = 4;

/// A tied contact: its triangle's index, alpha, normal, feature and position along the path
/// ([`Window::along`]).
type Tie<S> = (usize, S, Vec3<S>, Contact, S);

/// An accumulator for the contacts of one sweep, fed in any order with [`offer`](Self::offer).
/// (Public only to name it in [`CompoundPart`](crate::compound::CompoundPart)'s hidden method:
/// this module is private, so no user can.)
#[derive(Debug)]
pub struct Earliest<S: Scalar> {
    best: Option<(usize, Hit<S>)>,
    /// Added to the index of every contact offered: where the current part of a
    /// [`Compound`](crate::Compound) starts in its index space.
    base: usize,
    /// The contacts within the alpha window as `(index, alpha, normal, feature, along)`: all the
    /// merge needs, so that a firmware's stack pays for no more.
    ties: Vec<Tie<S>, TIES>,
    /// The sweep's direction and the position window.
    window: Window<S>,
    /// Set on the second visit: the first visit's reach and earliest position along the path
    /// (the window no longer moves).
    fixed: Option<(S, S)>,
    /// A tied contact was dropped for room while the window could still shrink.
    lossy: bool,
    /// [`reach`](Self::reach), kept up to date as `best` changes: the traversal and every
    /// triangle's test ask for it.
    reach: S,
}

impl<S: Scalar> Earliest<S> {
    fn new(window: Window<S>, fixed: Option<(S, S)>) -> Self {
        Self {
            best: None,
            base: 0,
            ties: Vec::new(),
            window,
            fixed,
            lossy: false,
            reach: fixed.map_or(S::ONE, |(w, _)| w),
        }
    }

    /// The largest alpha still worth testing: contacts later than this can neither come first
    /// nor tie with the first. One (the end of the path) while nothing was found; on a second
    /// visit, the first's.
    #[inline]
    pub(crate) fn reach(&self) -> S {
        self.reach
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
        // The second visit knows the earliest position: contacts beyond the window never tie.
        let along = self.window.along(hit.position);
        if let Some((_, at)) = self.fixed
            && !self.window.near(along, at)
        {
            return;
        }
        let first = self.best.is_none_or(|(i, b)| {
            hit.alpha < b.alpha
                || (hit.alpha == b.alpha && self.window.before(along, b.position, index < i))
        });
        if first {
            self.best = Some((index, hit));
            if self.fixed.is_none() {
                self.reach = hit.alpha + tie::<S>();
            }
            let reach = self.reach;
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
        // Room was made above, so the push succeeds; then the entry rotates into place unless
        // it is already last. (No `insert`: its index assertion would leave a panic path the
        // optimiser cannot remove.)
        if self
            .ties
            .push((index, hit.alpha, hit.normal, hit.contact, along))
            .is_ok()
            && let Some(tail) = self.ties.get_mut(at..)
            && tail.len() > 1
        {
            tail.rotate_right(1);
        }
    }

    fn finish(&self) -> Option<SceneHit<S>> {
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
        let (window, at) = (self.window, self.window.along(position));
        let ties = || self.ties.iter().filter(|t| window.near(t.4, at));
        let face_has =
            |n: Vec3<S>| ties().any(|&(_, _, m, c, _)| c == Contact::Face && same_plane(m, n));
        let mut planes = [None; PLANES];
        let (mut sum, mut count, mut only) = (Vec3::ZERO, 0, normal);
        for &(_, _, n, c, _) in ties() {
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
pub(crate) fn earliest<S: Scalar>(
    sweep: &Sweep<S>,
    mut visit: impl FnMut(&mut Earliest<S>),
) -> Option<SceneHit<S>> {
    let window = Window::of(sweep);
    let mut acc = Earliest::new(window, None);
    visit(&mut acc);
    if acc.lossy
        && let Some((_, best)) = acc.best
    {
        // The second run in the first's place: one accumulator on the stack.
        acc = Earliest::new(window, Some((acc.reach(), window.along(best.position))));
        visit(&mut acc);
    }
    acc.finish()
}

/// What orders and ties contacts besides alpha: the path's largest axis and its direction along
/// it, and how far apart two positions may lie and be simultaneous.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Window<S: Scalar> {
    axis: usize,
    forward: bool,
    /// Twice the position's rounding at the path's magnitude ([`Precision::position_error`]:
    /// two height roundings for floats, one for fixed point): a simultaneous contact's position
    /// lies within it of the first's, while contacts farther apart along the path are not
    /// simultaneous, whatever their rounded alphas. Wider than four steps of alpha along any
    /// float path (whose components are at most twice the magnitude: there it never decides)
    /// and any fixed-point path up to 4 long; narrower on longer fixed-point paths (in
    /// `I16F16`, 2.4e-4 against 3.1e-3 on a path 50 long).
    ///
    /// [`Precision::position_error`]: crate::Precision::position_error
    apart: S,
}

impl<S: Scalar> Window<S> {
    fn of(sweep: &Sweep<S>) -> Self {
        let (p0, p1) = (sweep.p0(), sweep.p1());
        let d = (p1 - p0).abs();
        let axis = if d.x >= d.y && d.x >= d.z {
            0
        } else if d.y >= d.z {
            1
        } else {
            2
        };
        let m = largest(p0.abs().max_element(), p1.abs().max_element(), S::ZERO);
        let e = S::height_error(m);
        let position = if S::PRECISION.relative { e + e } else { e };
        Self {
            axis,
            forward: component(p1, axis) >= component(p0, axis),
            apart: position + position,
        }
    }

    /// A position's coordinate on the path's largest axis: positions on the path differ in
    /// the others by no more (each is `p0 + f (p1 - p0)` for its fraction `f`, rounded).
    fn along(&self, position: Vec3<S>) -> S {
        component(position, self.axis)
    }

    /// Whether a contact at `a` along the path comes before one at position `b` of equal
    /// alpha: lies first along the path's largest axis, or at the same point there and
    /// `smaller` (its index is).
    fn before(&self, a: S, b: Vec3<S>, smaller: bool) -> bool {
        let b = self.along(b);
        if a == b {
            smaller
        } else {
            (a < b) == self.forward
        }
    }

    /// Whether two positions along the path lie within the window of each other.
    fn near(&self, a: S, b: S) -> bool {
        (a - b).abs() <= self.apart
    }
}

/// [`earliest`] over the contacts `offer(acc, scan)` gives: by its quick path (`scan` false),
/// which returns false when it found its parts malformed; then over all of them by a scan
/// (`scan` true) of every triangle, whose answer holds whatever the parts.
pub(crate) fn earliest_of<S: Scalar>(
    sweep: &Sweep<S>,
    mut offer: impl FnMut(&mut Earliest<S>, bool) -> bool,
) -> Option<SceneHit<S>> {
    let mut sound = true;
    let hit = earliest(sweep, |acc| sound &= offer(acc, false));
    if sound {
        return hit;
    }
    earliest(sweep, |acc| {
        offer(acc, true);
    })
}

/// Component `axis` (0, 1 or 2) of `v`.
fn component<S: Scalar>(v: Vec3<S>, axis: usize) -> S {
    match axis {
        0 => v.x,
        1 => v.y,
        _ => v.z,
    }
}

#[cfg(test)]
mod order_tests;
