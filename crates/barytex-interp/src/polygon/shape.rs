//! What both coordinate families share: validating the polygon (exact convexity), locating the
//! point exactly, the boundary weights, and the order-independent normalisation.

use glam::Vec2;

use super::{PolygonError, PolygonLocation};
use crate::determinant::orient2d_det;

/// Polygons up to this many vertices keep their per-vertex f64 intermediates on the stack;
/// larger ones recompute them in a second pass (never allocating either way).
pub(super) const STACK: usize = 32;

/// Whether a vertex whose neighbours are collinear with it (a "flat" vertex) is accepted.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Convexity {
    /// Every turn strictly the same way (Wachspress: a flat vertex would get weight 0 everywhere).
    Strict,
    /// Flat vertices allowed, as long as the boundary goes straight on through them.
    Weak,
}

/// A validated convex polygon.
#[derive(Clone, Copy)]
pub(super) struct Shape {
    /// `+1.0` for counter-clockwise vertex order, `−1.0` for clockwise.
    pub(super) orientation: f64,
    /// The lexicographically smallest vertex: sums start there, so rotating the vertex list
    /// leaves every result bit-identical.
    pub(super) start: usize,
}

/// The vertex after `i`, cyclically.
#[inline]
pub(super) fn next(i: usize, n: usize) -> usize {
    if i + 1 == n { 0 } else { i + 1 }
}

/// The vertex before `i`, cyclically.
#[inline]
pub(super) fn prev(i: usize, n: usize) -> usize {
    if i == 0 { n - 1 } else { i - 1 }
}

/// Checks the inputs and the polygon's convexity, exactly.
///
/// `turn(i)` is called once per vertex with the exact-sign turn determinant at vertex `i`
/// (`(vᵢ − vᵢ₋₁) × (vᵢ₊₁ − vᵢ₋₁)`), so Wachspress can keep it.
pub(super) fn validate(
    p: Vec2,
    polygon: &[Vec2],
    weights: usize,
    convexity: Convexity,
    mut turn: impl FnMut(usize, f64),
) -> Result<Shape, PolygonError> {
    let n = polygon.len();
    if n < 3 {
        return Err(PolygonError::TooFewVertices { count: n });
    }
    if weights != n {
        return Err(PolygonError::WeightsLength {
            vertices: n,
            weights,
        });
    }
    if !p.is_finite() {
        return Err(PolygonError::NonFinite { what: "point" });
    }
    if !polygon.iter().all(|v| v.is_finite()) {
        return Err(PolygonError::NonFinite { what: "polygon" });
    }
    if let Some(index) = (0..n).find(|&i| polygon[i] == polygon[next(i, n)]) {
        return Err(PolygonError::RepeatedVertex { index });
    }
    let mut orientation = 0.0;
    let mut start = 0;
    // Each edge direction's half plane: `true` for angles in [0, π). With every turn the same
    // way and below π, the direction passes angle 0 once per revolution, so the half plane
    // changes exactly twice per revolution. Comparing coordinates is exact.
    let upper = |i: usize| {
        let (a, b) = (polygon[i], polygon[next(i, n)]);
        b.y > a.y || (b.y == a.y && b.x > a.x)
    };
    let mut changes = 0usize;
    let mut flat_at = None;
    for i in 0..n {
        let (a, b, c) = (polygon[prev(i, n)], polygon[i], polygon[next(i, n)]);
        let det = orient2d_det(a, b, c);
        turn(i, det);
        if det == 0.0 {
            // Collinear: allowed (weakly) only if the boundary goes straight on through `b`,
            // i.e. `b − a` and `c − b` point the same way in both coordinates (exact compares).
            let straight = (a.x < b.x) == (b.x < c.x)
                && (a.x > b.x) == (b.x > c.x)
                && (a.y < b.y) == (b.y < c.y)
                && (a.y > b.y) == (b.y > c.y);
            if !straight {
                flat_at.get_or_insert(Err(i));
            } else if convexity == Convexity::Strict {
                flat_at.get_or_insert(Ok(i));
            }
        } else if orientation == 0.0 {
            orientation = det.signum();
        } else if det.signum() != orientation {
            return Err(PolygonError::NotConvex { vertex: i });
        }
        if upper(i) != upper(next(i, n)) {
            changes += 1;
        }
        let (v, s) = (polygon[i], polygon[start]);
        if v.x < s.x || (v.x == s.x && v.y < s.y) {
            start = i;
        }
    }
    if orientation == 0.0 {
        return Err(PolygonError::Collinear);
    }
    if let Some(Ok(vertex) | Err(vertex)) = flat_at {
        return Err(PolygonError::NotConvex { vertex });
    }
    if changes != 2 {
        return Err(PolygonError::SelfIntersecting);
    }
    Ok(Shape { orientation, start })
}

/// The point's place relative to a validated polygon, from the exact-sign edge areas
/// `area(i) = (vᵢ − p) × (vᵢ₊₁ − p)`.
fn locate(p: Vec2, polygon: &[Vec2], shape: Shape, area: impl Fn(usize) -> f64) -> PolygonLocation {
    let n = polygon.len();
    if let Some(i) = polygon.iter().position(|&v| v == p) {
        return PolygonLocation::OnVertex(i);
    }
    let mut on_edge = None;
    for i in 0..n {
        let a = area(i) * shape.orientation;
        if a < 0.0 {
            return PolygonLocation::Outside;
        }
        // With every area ≥ 0 the point is in the closed polygon, so a zero area means it is on
        // that edge's line inside the polygon; with flat vertices two consecutive edges share the
        // line, and the segment test picks the one holding the point.
        if a == 0.0 && on_edge.is_none() && within_segment(p, polygon[i], polygon[next(i, n)]) {
            on_edge = Some(i);
        }
    }
    on_edge.map_or(PolygonLocation::Inside, PolygonLocation::OnEdge)
}

/// [`locate`], and for a point on a vertex or an edge also its weights, which every generalized
/// barycentric coordinate shares there (`eᵢ`, or the edge's affine coordinates). Returns the
/// location and whether `weights` are final.
pub(super) fn locate_and_weigh_boundary(
    p: Vec2,
    polygon: &[Vec2],
    shape: Shape,
    area: impl Fn(usize) -> f64,
    weights: &mut [f32],
) -> (PolygonLocation, bool) {
    let location = locate(p, polygon, shape, area);
    let done = match location {
        PolygonLocation::OnVertex(i) => {
            vertex_weights(i, weights);
            true
        }
        PolygonLocation::OnEdge(i) => {
            edge_weights(p, polygon, i, weights);
            true
        }
        PolygonLocation::Inside | PolygonLocation::Outside => false,
    };
    (location, done)
}

/// Whether `p`, known to be on the line through `a` and `b`, is between them (exact compares).
fn within_segment(p: Vec2, a: Vec2, b: Vec2) -> bool {
    p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y)
}

/// Writes the weights of a point exactly on vertex `i`: `eᵢ`.
fn vertex_weights(i: usize, weights: &mut [f32]) {
    weights.fill(0.0);
    weights[i] = 1.0;
}

/// Writes the affine coordinates of `p` on the line of edge `i` (exactly collinear with it):
/// the two weights of the edge, every other weight `+0.0`.
///
/// Because `p` is exactly on the line, the ratio of one coordinate's differences is the exact
/// parameter; the coordinate with the larger extent is used, and each weight is its own ratio
/// (not `1 − t`) so both ends are as accurate. Returns `false` when a weight overflows f32.
pub(super) fn edge_weights(p: Vec2, polygon: &[Vec2], i: usize, weights: &mut [f32]) -> bool {
    let j = next(i, polygon.len());
    let (a, b, q) = (polygon[i].as_dvec2(), polygon[j].as_dvec2(), p.as_dvec2());
    let d = b - a;
    let (from_a, to_b, span) = if d.x.abs() >= d.y.abs() {
        (q.x - a.x, b.x - q.x, d.x)
    } else {
        (q.y - a.y, b.y - q.y, d.y)
    };
    weights.fill(0.0);
    weights[i] = (to_b / span) as f32;
    weights[j] = (from_a / span) as f32;
    weights[i].is_finite() && weights[j].is_finite()
}

/// Normalises the unnormalised weights `w(i)` into `weights`: `λᵢ = wᵢ / Σⱼ wⱼ`.
///
/// The sum runs from `shape.start`, the lexicographically smallest vertex, so a rotated vertex
/// list gives bit-identical weights. `w` is evaluated twice per vertex for polygons beyond
/// [`STACK`] vertices and once otherwise. `Err(Undefined)` when the sum is zero or a weight
/// overflows f32 (possible only outside).
pub(super) fn normalise(
    n: usize,
    shape: Shape,
    w: impl Fn(usize) -> f64,
    weights: &mut [f32],
) -> Result<(), PolygonError> {
    let mut cache = [0.0f64; STACK];
    let cached = n <= STACK;
    let mut sum = 0.0;
    for i in (shape.start..n).chain(0..shape.start) {
        let wi = w(i);
        if cached {
            cache[i] = wi;
        }
        sum += wi;
    }
    if sum == 0.0 || !sum.is_finite() {
        return Err(PolygonError::Undefined);
    }
    let mut finite = true;
    for (i, out) in weights.iter_mut().enumerate() {
        let wi = if cached { cache[i] } else { w(i) };
        // `0.0 / negative` would be `-0.0`: a zero weight is written as `+0.0`.
        *out = if wi == 0.0 { 0.0 } else { (wi / sum) as f32 };
        finite &= out.is_finite();
    }
    if finite {
        Ok(())
    } else {
        Err(PolygonError::Undefined)
    }
}
