//! OBJ polygons of four or more corners into triangles. A polygon whose fan from its first
//! corner covers it exactly (every convex one, quads included) is split as that fan, as
//! `tobj` and most tools split it; any other (concave) one is ear-clipped (`earcutr`) in its
//! plane, so that no triangle lies outside it or faces the other way. A polygon that crosses
//! or folds over itself has no such split and is refused.

type P = [f64; 3];

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: P, b: P) -> P {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn length(a: P) -> f64 {
    dot(a, a).sqrt()
}

/// The polygon crosses or folds over itself: no set of triangles is it.
#[derive(Debug)]
pub(crate) struct Tangled;

/// The triangles of polygon `p` (corners in order, counter-clockwise seen from its front), as
/// corner indices, each counter-clockwise seen from the polygon's front.
pub(crate) fn triangulate(p: &[P]) -> Result<Vec<[usize; 3]>, Tangled> {
    if p.len() <= 3 {
        return Ok(vec![[0, 1, 2]; p.len() / 3]);
    }
    let fan: Vec<[usize; 3]> = (1..p.len().saturating_sub(1))
        .map(|i| [0, i, i + 1])
        .collect();
    // Twice each fan triangle's area vector; their sum is twice the polygon's (Newell's
    // normal), whatever the fan's shape.
    let normals: Vec<P> = fan
        .iter()
        .map(|&[a, b, c]| cross(sub(p[b], p[a]), sub(p[c], p[a])))
        .collect();
    let total = normals
        .iter()
        .fold([0.0; 3], |s, n| [s[0] + n[0], s[1] + n[1], s[2] + n[2]]);
    let area = length(total);
    let sum: f64 = normals.iter().map(|&n| length(n)).sum();
    // No area at all (or too large a coordinate to tell): the fan, as before; the bake skips
    // its degenerate triangles or refuses the coordinates.
    if !(sum > 0.0 && sum.is_finite()) {
        return Ok(fan);
    }
    // Slack for rounding, a billionth of the fan's area.
    let slack = 1e-9 * sum;
    if area <= slack {
        return Err(Tangled); // its halves cancel: a figure eight
    }
    // The fan covers the polygon when no fan triangle turns against the polygon's normal
    // (a sliver within rounding of flat aside), as in every convex polygon.
    if normals.iter().all(|&n| dot(n, total) >= -slack * area) {
        return Ok(fan);
    }
    ear_clipped(p, total)
}

/// Ear clipping on `p` projected onto the plane across `normal` (the polygon's), in axes
/// that keep its counter-clockwise order counter-clockwise.
fn ear_clipped(p: &[P], normal: P) -> Result<Vec<[usize; 3]>, Tangled> {
    let n = normal.map(|c| c / length(normal));
    // Any axis across the normal; the one least along it is farthest from parallel.
    let least = (0..3)
        .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
        .unwrap_or(0);
    let mut e = [0.0; 3];
    e[least] = 1.0;
    let u = cross(e, n);
    let u = u.map(|c| c / length(u));
    let v = cross(n, u);
    let flat: Vec<f64> = p
        .iter()
        .flat_map(|&q| {
            let d = sub(q, p[0]);
            [dot(d, u), dot(d, v)]
        })
        .collect();
    let at = |i: usize| (flat[2 * i], flat[2 * i + 1]);
    // Twice the signed area of a triangle (or of the polygon, as a fan) in the plane.
    let twice = |[a, b, c]: [usize; 3]| {
        let ((ax, ay), (bx, by), (cx, cy)) = (at(a), at(b), at(c));
        (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    };
    let polygon: f64 = (1..p.len() - 1).map(|i| twice([0, i, i + 1])).sum();
    let indices = earcutr::earcut(&flat, &[], 2).map_err(|_| Tangled)?;
    let mut out = Vec::with_capacity(indices.len() / 3);
    let mut covered = 0.0;
    for t in indices.chunks_exact(3) {
        let t = [t[0], t[1], t[2]];
        let a = twice(t);
        covered += a.abs();
        out.push(if a < 0.0 { [t[0], t[2], t[1]] } else { t });
    }
    // A simple polygon's triangles cover its area exactly; a crossing one's cover its lobes,
    // which its signed area counts against each other, or leave some out.
    if (covered - polygon).abs() > 1e-9 * polygon.abs().max(covered) || polygon <= 0.0 {
        return Err(Tangled);
    }
    Ok(out)
}
