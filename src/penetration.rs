//! Penetration: how deep a resting ball overlaps geometry, and which way is out.
//!
//! The query parry calls `contact` (with a zero prediction distance) and Jolt a collide-shape
//! query: for a ball at `centre`, the closest point of each triangle (Ericson, *Real-Time
//! Collision Detection*, §5.1.5, closest point on a triangle, here in the triangle's standard
//! frame: the face region when the centre projects inside every edge, else the nearest point of
//! the nearest edge segment); the triangle with the largest overlap `radius - distance` wins
//! (beside a seam, the depth along the face's normal that clears the triangle stands in).

use crate::contact::unit;
use crate::{Contact, Error, Geometry, Input, Scalar, StandardTriangle, Vec3, check};

/// The deepest overlap of a ball with a [`Geometry`]: a plain `Copy` struct.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", serde(bound = "S: crate::Scalar"))]
pub struct Penetration<S> {
    /// Unit direction that moves the ball out (from the touched point towards the centre, or
    /// the face's normal when the centre lies on or behind the face).
    pub normal: Vec3<S>,
    /// How far the ball reaches into the triangle along `normal`, `> 0`: moving the centre by
    /// `normal * depth` leaves it touching.
    #[cfg_attr(feature = "serde", serde(with = "crate::interop::number"))]
    pub depth: S,
    /// The point of the triangle closest to the centre.
    pub point: Vec3<S>,
    /// The triangle's index (as in [`SceneHit::index`](crate::SceneHit::index)).
    pub index: usize,
    /// The triangle's feature nearest the centre.
    pub contact: Contact,
}

/// The deepest overlap of a ball of `radius` at `centre` with any triangle of `scene`, or `None`
/// when it overlaps nothing (touching is not overlapping).
///
/// Sidedness is the cast's: a one-sided triangle ignores a centre behind its plane (its back is
/// open, and a ball that has passed through is not pulled back); a two-sided one pushes the
/// ball out on the side its centre is. Where the nearest feature is an inactive edge or vertex
/// (a seam with a flat or valley neighbour, see [`Features`](crate::Features)), the face's
/// normal is used, as for a cast, with the depth along it that leaves the ball touching the
/// triangle (more than the radius less the distance: the way out along the face's normal is not
/// the shortest). On an exact tie of depths, the smallest index wins, whatever the visiting order.
///
/// Errors: [`Error::NaN`], [`Error::OutOfRange`] for a centre or radius outside
/// `±`[`Scalar::LIMIT`], [`Error::NegativeRadius`].
///
/// Cost: a [`Scene`](crate::Scene) tests the triangles whose bounding boxes meet the ball's; a
/// [`Mesh`](crate::Mesh) or [`CompactMesh`](crate::CompactMesh) those of the leaves of its tree
/// whose boxes meet the ball's (a box query, `O(log N)` nodes), a
/// [`Heightfield`](crate::Heightfield) those of the cells under the ball.
///
/// Accuracy: the depth carries the rounding of a height at the centre's coordinates
/// ([`Precision::height_error`](crate::Precision::height_error)) plus that of a square root.
///
/// ```
/// use ballcast::{Scene, Triangle, Vec3, penetration::penetration};
/// let v = Vec3::new;
/// let mut s: Scene<f64, 2> = Scene::new();
/// s.push(Triangle::new(v(-9.0, 0.0, -9.0), v(-9.0, 0.0, 9.0), v(9.0, 0.0, 0.0)))?;
/// // Spawned 0.2 inside a floor: push it up by 0.2.
/// let p = penetration(&s, v(0.0, 0.3, 0.0), 0.5)?.expect("overlaps");
/// assert_eq!(p.normal, v(0.0, 1.0, 0.0));
/// assert!((p.depth - 0.2).abs() < 1e-12);
/// assert_eq!(penetration(&s, v(0.0, 0.6, 0.0), 0.5)?, None);
/// # Ok::<(), ballcast::Error>(())
/// ```
pub fn penetration<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    centre: Vec3<S>,
    radius: S,
) -> Result<Option<Penetration<S>>, Error> {
    let c = check::point(centre, S::LIMIT, Input::Position)?;
    let r = check::radius(radius)?;
    Ok(deepest(scene, c, r))
}

/// [`penetration`] on validated input.
pub(crate) fn deepest<S: Scalar, G: Geometry<S> + ?Sized>(
    scene: &G,
    c: Vec3<S>,
    r: S,
) -> Option<Penetration<S>> {
    let reach = Vec3::new(r, r, r);
    let mut best: Option<Penetration<S>> = None;
    scene.visit(c - reach, c + reach, &mut |index, t| {
        if let Some(p) = overlap(t, c, r, index) {
            let deeper = match &best {
                None => true,
                Some(b) => p.depth > b.depth || (p.depth == b.depth && index < b.index),
            };
            if deeper {
                best = Some(p);
            }
        }
    });
    best
}

/// The overlap of a ball at `c` with one triangle.
pub(crate) fn overlap<S: Scalar>(
    t: &StandardTriangle<S>,
    c: Vec3<S>,
    r: S,
    index: usize,
) -> Option<Penetration<S>> {
    nearest(t, c, r, index).map(|(p, _)| p)
}

/// [`overlap`], and whether the centre lies over the face itself (not only nearest an
/// inactive edge or vertex, for which the face's plane stands in).
pub(crate) fn nearest<S: Scalar>(
    t: &StandardTriangle<S>,
    c: Vec3<S>,
    r: S,
    index: usize,
) -> Option<(Penetration<S>, bool)> {
    // The triangle lies within its two edges at v0 of its origin: a few comparisons reject most
    // triangles of a scan before any product.
    let (e, o) = (t.edges(), t.origin());
    let reach = r + if e[0].len > e[2].len {
        e[0].len
    } else {
        e[2].len
    };
    let far = |a: S, b: S| a - b > reach || b - a > reach;
    if far(c.x, o.x) || far(c.y, o.y) || far(c.z, o.z) {
        return None;
    }
    let q = t.standard_point(c);
    let behind = q.y < S::ZERO;
    // Beyond the plane's reach, behind a one-sided triangle (its back is open, as for a cast),
    // or beyond the triangle's box in its plane: no overlap. The box test also keeps every
    // offset below within the scalar's range.
    let ((lo, hi), z1) = (t.x_extent(), t.shape().1);
    if q.y >= r
        || -q.y >= r
        || (behind && !t.two_sided)
        || q.x <= lo - r
        || q.x >= hi + r
        || q.z <= -r
        || q.z >= z1 + r
    {
        return None;
    }
    let flat = Vec3::new(q.x, S::ZERO, q.z);
    let inside =
        (t.edges().iter().enumerate()).all(|(i, e)| e.out_of(flat - t.corner(i)) <= S::ZERO);
    if inside {
        // The face region: out along the normal on the centre's side.
        let n = if behind { -t.normal() } else { t.normal() };
        let p = Penetration {
            normal: n,
            depth: r - q.y.abs(),
            point: c - n.scale(q.y.abs()),
            index,
            contact: Contact::Face,
        };
        return Some((p, true));
    }
    // The nearest point of the nearest edge segment (its ends are the vertices).
    let mut near: Option<(S, Vec3<S>, Contact)> = None;
    for (i, e) in t.edges().iter().enumerate() {
        let u = e.along_of(flat - t.corner(i));
        let (u, contact) = if u <= S::ZERO {
            (S::ZERO, Contact::Vertex(i as u8))
        } else if u >= e.len {
            (e.len, Contact::Vertex(((i + 1) % 3) as u8))
        } else {
            (u, Contact::Edge(i as u8))
        };
        let p = t.corner(i) + e.along().map(|a| S::mul_unit(u, a));
        let Some((d, _)) = S::direction(q - p) else {
            continue;
        };
        if near.is_none_or(|(best, _, _)| d < best) {
            near = Some((d, p, contact));
        }
    }
    let (d, p, contact) = near?;
    if d >= r {
        return None;
    }
    let active = match contact {
        Contact::Edge(i) => t.features.edge(i as usize),
        Contact::Vertex(i) => t.features.vertex(i as usize),
        Contact::Face => true,
    };
    if !active {
        // Beside a seam the face's normal stands in (as for a cast), but the depth is what
        // clears the triangle along it: to where the nearest point `p` is `r` away, not the
        // plane's depth, which beyond the seam would overstate it (0.108 for a true 0.003).
        let n = if behind { -t.normal() } else { t.normal() };
        let clear = S::chord(r, flat - p)?;
        let depth = clear - q.y.abs();
        return (depth > S::ZERO).then(|| {
            let p = Penetration {
                normal: n,
                depth,
                point: c - t.world_direction(q - p),
                index,
                contact: Contact::Face,
            };
            (p, false)
        });
    }
    let normal = unit(t.world_direction(q - p)).unwrap_or(t.normal());
    let p = Penetration {
        normal,
        depth: r - d,
        point: c - normal.scale(d),
        index,
        contact,
    };
    Some((p, false))
}

/// Every triangle of a mesh's parts with its input index: a linear scan, for parts whose tree
/// is malformed.
pub(crate) fn each<S: Scalar>(
    triangles: &[StandardTriangle<S>],
    order: &[u32],
    f: &mut dyn FnMut(usize, &StandardTriangle<S>),
) {
    for (t, &i) in triangles.iter().zip(order) {
        f(i as usize, t);
    }
}
