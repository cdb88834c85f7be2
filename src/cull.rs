//! Conservative culling of one triangle against a swept ball, before it is prepared: its box,
//! then its plane, in `f64`, grown by the radius and a bound on every rounding (or, for a
//! fixed-point sweep where `f64` is software, its box alone in integers: [`UnitBox`]). Shared
//! by the forms that prepare triangles on the fly ([`Heightfield`](crate::Heightfield),
//! [`CompactMesh`](crate::CompactMesh)).

mod heights;

pub(crate) use heights::UnitHeights;

/// A fixed-point point's coordinates as the integers of their bits (units of `2^-frac`);
/// `None` for floats.
pub(crate) fn unit_bits<S: Scalar>(p: Vec3<S>) -> Option<[i64; 3]> {
    let b = |v: S| v.fixed_bits().map(|(b, _)| b);
    Some([b(p.x)?, b(p.y)?, b(p.z)?])
}

use crate::scalar::largest;
use crate::{Scalar, Sweep, Vec3};

/// The sweep in world units (`f64`), with what every box test needs.
pub(crate) struct Path {
    pub(crate) p0: [f64; 3],
    pub(crate) d: [f64; 3],
    pub(crate) inv: [f64; 3],
    /// How far every box is grown: the radius, every rounding, and the seam margins.
    pub(crate) pad: f64,
    /// The pad less the seam margins, which widen a face within its plane only: how far from
    /// the plane a contact can find the ball's centre (the radius and every rounding).
    plane: f64,
    /// That less the radius: more than the rounding of a triangle's heights in `cast`.
    slack: f64,
    /// A bound on the rounding of a prepared unit vector: `16 EPSILON` (floats), or `1/1024`
    /// of that (fixed point, whose unit vectors have 30 or 62 fractional bits).
    unit: f64,
}

impl Path {
    /// The path of `sweep` among geometry whose coordinates reach `extent` in magnitude, its
    /// boxes grown by [`pad`](Self::pad).
    pub(crate) fn new<S: Scalar>(sweep: &Sweep<S>, extent: f64, class: u8) -> Self {
        let (ends, r) = (endpoints(sweep), sweep.radius().to_f64());
        let (p0, d, _) = ends;
        let (plane, pad) = grown::<S>(r, ends, extent, class);
        let per_unit = if S::PRECISION.relative {
            1.0
        } else {
            1.0 / 1024.0
        };
        Self {
            p0,
            d,
            inv: d.map(|x| 1.0 / x),
            pad,
            plane,
            slack: plane - r,
            unit: 16.0 * S::PRECISION.epsilon * per_unit,
        }
    }

    /// How far [`new`](Self::new) grows the boxes: the radius, a bound on every rounding (as a
    /// [`Mesh`](crate::Mesh)'s tree grows its boxes) and `2^class` seam margins (the
    /// [`bvh`](crate::bvh) docs explain both). Alone, for the integer box ([`UnitBox`]).
    pub(crate) fn pad<S: Scalar>(sweep: &Sweep<S>, extent: f64, class: u8) -> f64 {
        grown_by::<S>(sweep.radius().to_f64(), endpoints(sweep), extent, class)
    }

    /// Where the segment, over `[0, limit]`, enters and leaves the box `lo..hi` grown by the pad.
    #[inline]
    pub(crate) fn clip(&self, lo: [f64; 3], hi: [f64; 3], limit: f64) -> Option<(f64, f64)> {
        self.clip_within(lo, hi, (0.0, limit), 0..3)
    }

    /// [`clip`](Self::clip) over `[t0, t1]`, on the `axes` alone: a part of the path already
    /// clipped against the box's other slabs.
    #[inline(always)]
    pub(crate) fn clip_within(
        &self,
        lo: [f64; 3],
        hi: [f64; 3],
        (mut t0, mut t1): (f64, f64),
        axes: core::ops::Range<usize>,
    ) -> Option<(f64, f64)> {
        for a in axes {
            let (near, far) = (lo[a] - self.pad - self.p0[a], hi[a] + self.pad - self.p0[a]);
            if !self.inv[a].is_finite() {
                // Parallel to the slab (or as good as): inside it all along, or never.
                let d = self.d[a].abs();
                if near > d || far < -d {
                    return None;
                }
                continue;
            }
            // Never NaN (finite bounds, a finite inverse): plain comparisons, cheaper than
            // `f64::min` and `max`.
            let (ta, tb) = (near * self.inv[a], far * self.inv[a]);
            let (enter, leave) = if tb < ta { (tb, ta) } else { (ta, tb) };
            if enter > t0 {
                t0 = enter;
            }
            if leave < t1 {
                t1 = leave;
            }
        }
        (t0 <= t1).then_some((t0, t1))
    }
}

impl Path {
    /// Whether the path, over `[t0, t1]`, comes within the radius and every rounding (the pad
    /// less its seam margins, which widen a face within its plane only) of the plane through
    /// `v`: every contact needs the ball within its radius of the triangle's plane. The distance
    /// along the path is linear, so its ends decide. A one-sided triangle (front where `v` turns
    /// counter-clockwise) is also passed by where the path starts behind its plane, beyond the
    /// rounding of the heights `cast` decides it by.
    ///
    /// The prepared triangle's plane is tilted from the exact one by the rounding of its
    /// normal, which a sliver magnifies: the normal comes from the cross product of two edges
    /// scaled to a largest component of one, rounded by about a unit vector's step, so its
    /// direction is off by up to that step over the product's length (`|n| / (l1 l2)` for the
    /// two longest edges' largest components `l1`, `l2`: no more than the scaled edges' product).
    /// Heights at a distance `D` from the triangle's first vertex move by the tilt times `D`.
    pub(crate) fn near_plane(&self, v: [[f64; 3]; 3], span: (f64, f64), one_sided: bool) -> bool {
        self.slab(v, span, one_sided).is_some()
    }

    /// [`near_plane`](Self::near_plane), and then whether the part of the span within reach
    /// of the plane keeps out of reach of every edge's line on the outer side: each point of
    /// the triangle lies on the inner side of all three, so a ball centre farther than its
    /// radius (and every rounding) beyond one of them cannot touch it. An inactive edge's seam
    /// widens the face beyond its line by far less than the radius, and the pad's seam margins
    /// cover it. Distances within the plane are off in the prepared frame by the same tilt as
    /// heights, so the same reach bounds both.
    pub(crate) fn near_triangle(
        &self,
        v: [[f64; 3]; 3],
        span: (f64, f64),
        one_sided: bool,
    ) -> bool {
        let Some(Slab {
            n,
            span: (mut a, mut b),
            start,
            along,
            across,
            reach,
        }) = self.slab(v, span, one_sided)
        else {
            return false;
        };
        // The part of the span within reach of the plane.
        if along != 0.0 {
            let (ta, tb) = ((-across - start) / along, (across - start) / along);
            let (lo, hi) = if tb < ta { (tb, ta) } else { (ta, tb) };
            if lo > a {
                a = lo;
            }
            if hi < b {
                b = hi;
            }
        }
        // Outward in the plane from edge `i` is `e_i × n`, of length |e_i| |n|; the distance
        // times that is linear along the path, so the span's ends decide. Squares compare it
        // with the reach (itself times |n|) without a square root.
        // An empty part (by rounding: the plane tests kept the triangle) keeps it too.
        is_less(b, a)
            || !(0..3).any(|i| {
                let (from, e) = (v[i], sub(v[(i + 1) % 3], v[i]));
                let out = cross(e, n);
                let (w0, dw) = (dot(sub(self.p0, from), out), dot(self.d, out));
                let (wa, wb) = (w0 + a * dw, w0 + b * dw);
                let limit = reach * reach * dot(e, e);
                wa > 0.0 && wb > 0.0 && wa * wa > limit && wb * wb > limit
            })
    }

    /// The plane tests of [`near_plane`](Self::near_plane), and what the edge tests of
    /// [`near_triangle`](Self::near_triangle) need of a triangle they keep.
    #[inline(always)]
    fn slab(&self, v: [[f64; 3]; 3], (t0, t1): (f64, f64), one_sided: bool) -> Option<Slab> {
        let (e, f) = (sub(v[1], v[0]), sub(v[2], v[0]));
        let n = cross(e, f);
        // Distances times |n|, where the path enters the triangle's box and where it leaves.
        let (start, along) = (dot(n, sub(self.p0, v[0])), dot(n, self.d));
        let (d0, d1) = (start + t0 * along, start + t1 * along);
        let norm = libm::sqrt(dot(n, n));
        // Largest magnitudes by plain comparisons (a NaN is passed over, as by `f64::max`).
        let big = |a: [f64; 3]| {
            a.iter()
                .fold(0.0f64, |m, x| if x.abs() > m { x.abs() } else { m })
        };
        let l = [big(e), big(f), big(sub(v[2], v[1]))];
        let longest = largest(l[0], l[1], l[2]);
        // The two largest's product, and the tilt (infinite or NaN for an exactly flat
        // triangle: nothing is passed by).
        let product = largest(l[0] * l[1], l[0] * l[2], l[1] * l[2]);
        let tilt = self.unit * product / norm;
        // Points of the path over the span lie within the pad of the triangle's box, whose
        // extent is at most `longest` per axis from the first vertex: `2 (longest + pad)` away.
        let tilted = tilt * 2.0 * (longest + self.pad);
        // Across the plane, the radius and every rounding; within it, the seam margins too.
        let (across, reach) = ((self.plane + tilted) * norm, (self.pad + tilted) * norm);
        let height = |far: f64| (self.slack + tilt * 2.0 * far) * norm;
        let behind = one_sided && is_less(start, -height(big(sub(self.p0, v[0]))));
        // d0 and d1 are finite (the path and the triangle are): ordered by one comparison.
        let (near, far) = if d1 < d0 { (d1, d0) } else { (d0, d1) };
        if behind || is_less(across, near) || is_less(far, -across) {
            return None;
        }
        Some(Slab {
            n,
            span: (t0, t1),
            start,
            along,
            across,
            reach,
        })
    }
}

/// What [`Path::near_plane`] found of a triangle it keeps: its normal `n` (unnormalised), the
/// span, the path's distance from the plane at its start and its change along the path, and
/// the reach across the plane and within it (all distances times `|n|`).
struct Slab {
    n: [f64; 3],
    span: (f64, f64),
    start: f64,
    along: f64,
    across: f64,
    reach: f64,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|k| a[k] - b[k])
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a < b`, false where either is NaN (never expected): a NaN keeps a triangle.
pub(crate) fn is_less(a: f64, b: f64) -> bool {
    a.partial_cmp(&b) == Some(core::cmp::Ordering::Less)
}

/// Whether `f64` arithmetic is software on this target: bare-metal Arm, whose Cortex-M FPUs,
/// where present, are single precision. There a [`CompactMesh`](crate::CompactMesh) passes a
/// fixed-point sweep's triangles by with its [`UnitBox`] and [`UnitHeights`] alone, in
/// integers (and a heightfield's short query runs in integers: `heightfield/units.rs`): on a
/// Cortex-M0 the `f64` box and plane tests cost several times the preparations they save. Culls only pass triangles by, so the answers are the same on every target.
pub(crate) const SOFT_F64: bool = cfg!(all(target_arch = "arm", target_os = "none"));

/// The box the grown path of a fixed-point sweep stays within, in its scalar's units
/// (`2^-frac`): a triangle whose three vertices all lie beyond it on one axis is out of reach,
/// told by integer comparisons. Floats have none.
pub(crate) struct UnitBox {
    lo: [i64; 3],
    hi: [i64; 3],
}

impl UnitBox {
    /// The box of the whole segment of `sweep`, grown by `pad` (the [`Path`]'s), rounded out.
    pub(crate) fn new<S: Scalar>(sweep: &Sweep<S>, pad: f64) -> Option<Self> {
        let (_, frac) = sweep.radius().fixed_bits()?;
        let bits = |p: Vec3<S>| p.to_array().map(|v| v.fixed_bits().map_or(0, |(b, _)| b));
        let (p0, p1) = (bits(sweep.p0()), bits(sweep.p1()));
        // Exact scaling by a power of two, then up to whole units (saturating; never NaN).
        let pad = libm::ceil(pad * (1u64 << frac.min(62)) as f64) as i64;
        Some(Self {
            lo: [0, 1, 2].map(|a| p0[a].min(p1[a]).saturating_sub(pad)),
            hi: [0, 1, 2].map(|a| p0[a].max(p1[a]).saturating_add(pad)),
        })
    }

    /// Whether the triangle `v` lies wholly beyond the box on some axis.
    pub(crate) fn misses<S: Scalar>(&self, v: [Vec3<S>; 3]) -> bool {
        (0..3).any(|a| {
            let c = v.map(|p| p.to_array()[a].fixed_bits().map_or(0, |(b, _)| b));
            let (low, high) = (c[0].min(c[1]).min(c[2]), c[0].max(c[1]).max(c[2]));
            high < self.lo[a] || low > self.hi[a]
        })
    }
}

/// [`Path::pad`], given the sweep's radius and [`endpoints`].
#[inline]
fn grown_by<S: Scalar>(
    r: f64,
    ends: ([f64; 3], [f64; 3], [f64; 3]),
    extent: f64,
    class: u8,
) -> f64 {
    grown::<S>(r, ends, extent, class).1
}

/// [`grown_by`] without the seam margins, and with them.
fn grown<S: Scalar>(
    r: f64,
    (p0, d, p1): ([f64; 3], [f64; 3], [f64; 3]),
    extent: f64,
    class: u8,
) -> (f64, f64) {
    let big = |a: [f64; 3]| a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let magnitude = big(p0).max(big(p1)).max(extent);
    // 2^class, exactly.
    let seams = f64::from_bits(((1023 + class.min(31) as u32) as u64) << 52);
    let plane = crate::bvh::rounding_pad::<S>(r, big(d), magnitude)
        + crate::bvh::ray_pad::<S>(r, magnitude);
    (
        plane,
        plane + (r / 64.0 + 4.0 * S::PRECISION.epsilon) * seams,
    )
}

/// A sweep's start and displacement in `f64`, and its end.
#[inline]
fn endpoints<S: Scalar>(sweep: &Sweep<S>) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let f = |p: Vec3<S>| p.to_array().map(S::to_f64);
    let (p0, p1) = (f(sweep.p0()), f(sweep.p1()));
    (p0, [0, 1, 2].map(|a| p1[a] - p0[a]), p1)
}

#[cfg(test)]
mod tests;
