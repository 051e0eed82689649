//! 2D barycentric coordinates with exact classification (Buss 2003, ch. IV, barycentric
//! coordinates; Denisjuk, Theorems 4, 5 and 8).

use glam::Vec2;

use crate::orient::orient2d_value;
use crate::{InterpError, Interpolate, interpolate3};

/// Where a point lies relative to a triangle, decided exactly.
///
/// Edge `i` is the edge opposite vertex `i` (the one where weight `i` is zero).
///
/// ```
/// use barytex_interp::{locate_2d, Location};
/// use glam::Vec2;
/// let tri = [Vec2::ZERO, Vec2::new(4.0, 0.0), Vec2::new(0.0, 4.0)];
/// let on_vertex = locate_2d(Vec2::new(4.0, 0.0), tri)?;
/// assert_eq!(on_vertex, Location::OnVertex(1));
/// assert!(on_vertex.is_inside_closed());
/// assert!(!locate_2d(Vec2::new(-1.0, 0.0), tri)?.is_inside_closed());
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// Strictly inside: all three weights positive.
    Inside,
    /// On the relative interior of edge `i` (opposite vertex `i`): weight `i` is exactly zero,
    /// the other two positive.
    OnEdge(usize),
    /// Exactly on vertex `i`: weights are `eᵢ`.
    OnVertex(usize),
    /// Outside the closed triangle: at least one weight negative.
    Outside,
    /// The triangle's vertices are exactly collinear (zero area); weights do not exist.
    Degenerate,
}

impl Location {
    /// Inside or on the boundary (edge or vertex) of the triangle.
    #[must_use]
    pub fn is_inside_closed(self) -> bool {
        matches!(self, Self::Inside | Self::OnEdge(_) | Self::OnVertex(_))
    }
}

/// Barycentric coordinates `(α, β, γ)` of a point in a 2D triangle and its exact location: the
/// result of [`barycentric_2d`] (its 3D twin is [`Barycentric3d`](crate::Barycentric3d)).
///
/// `p = α·a + β·b + γ·c` with `α + β + γ = 1`; weight `i` is the signed area of the sub-triangle
/// opposite vertex `i` over the triangle's area, `α = A/(A + B + C)` (Buss, *3D Computer
/// Graphics*, 2003, §IV.1.3).
///
/// ```
/// use barytex_interp::{barycentric_2d, Location};
/// use glam::{Vec2, Vec3};
///
/// let tri = [Vec2::ZERO, Vec2::new(4.0, 0.0), Vec2::new(0.0, 4.0)];
/// let b = barycentric_2d(Vec2::new(1.0, 2.0), tri)?;
/// assert_eq!(b.weights, [0.25, 0.25, 0.5]);
/// assert_eq!(b.location, Location::Inside);
/// // Interpolate per-vertex colours at the point.
/// assert_eq!(b.interpolate([Vec3::X, Vec3::Y, Vec3::Z]), Vec3::new(0.25, 0.25, 0.5));
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Barycentric2d {
    /// `[α, β, γ]`, the weights of vertices `a`, `b`, `c`.
    pub weights: [f32; 3],
    /// Where the point is, decided with exact predicates; consistent with the signs of `weights`
    /// except where a weight's magnitude is below f32's range (it then reads `0.0`).
    pub location: Location,
}

impl Barycentric2d {
    /// `Σ wᵢ·vᵢ`: the value at the point from per-vertex values ([`interpolate3`] with
    /// [`weights`](Self::weights)).
    ///
    /// # Accuracy
    /// As [`Interpolate::combine3`]: exact at a vertex (weights `eᵢ` return `values[i]`).
    #[must_use]
    #[inline]
    pub fn interpolate<T: Interpolate>(&self, values: [T; 3]) -> T {
        interpolate3(values, self.weights)
    }
}

/// The signed sub-areas `[d_a, d_b, d_c]` and the total `d`, each with an exact sign.
#[inline]
fn signed_areas(p: Vec2, [a, b, c]: [Vec2; 3]) -> Option<([f64; 3], f64)> {
    let total = orient2d_value(a, b, c)?;
    let da = orient2d_value(b, c, p)?;
    let db = orient2d_value(c, a, p)?;
    let dc = orient2d_value(a, b, p)?;
    Some(([da, db, dc], total))
}

#[inline]
fn classify(sub: [f64; 3], total: f64) -> Location {
    if total == 0.0 {
        return Location::Degenerate;
    }
    // Signs relative to the triangle's own orientation, so clockwise triangles work alike.
    let rel = sub.map(|d| if total > 0.0 { d } else { -d });
    if rel.iter().any(|&d| d < 0.0) {
        return Location::Outside;
    }
    let zeros = rel.iter().filter(|&&d| d == 0.0).count();
    match zeros {
        0 => Location::Inside,
        1 => Location::OnEdge(rel.iter().position(|&d| d == 0.0).unwrap_or(0)),
        // Two zero weights on a non-degenerate triangle: p is the remaining vertex.
        _ => Location::OnVertex(rel.iter().position(|&d| d != 0.0).unwrap_or(0)),
    }
}

/// Exactly where `p` lies relative to the triangle `tri = [a, b, c]`.
///
/// # Errors
/// [`InterpError::NonFinite`] when any coordinate is NaN or infinite.
///
/// # Accuracy
/// Exact for every finite input (test `locate_matches_exact_rational` and the hard-case table).
///
/// ```
/// use barytex_interp::{locate_2d, Location};
/// use glam::Vec2;
/// let tri = [Vec2::ZERO, Vec2::new(4.0, 0.0), Vec2::new(0.0, 4.0)];
/// assert_eq!(locate_2d(Vec2::new(2.0, 0.0), tri)?, Location::OnEdge(2));
/// assert_eq!(locate_2d(Vec2::new(3.0, 3.0), tri)?, Location::Outside);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[inline]
pub fn locate_2d(p: Vec2, tri: [Vec2; 3]) -> Result<Location, InterpError> {
    let (sub, total) = signed_areas(p, tri).ok_or(non_finite(p))?;
    Ok(classify(sub, total))
}

/// Barycentric coordinates of `p` in the triangle `tri = [a, b, c]`, with exact classification.
///
/// Signed areas are computed with an exact sign and a relative error below 2⁻³⁰ (an exact
/// expansion sum where plain f64 is not accurate enough); each weight is its own area
/// ratio (not `1 − β − γ`), so a point near any vertex is as accurate as near another. Zero
/// weights are exactly `0.0` on edges and vertices. Works for both triangle orientations.
///
/// # Errors
/// [`InterpError::DegenerateTriangle`] for zero-area triangles, [`InterpError::NonFinite`] for NaN
/// or infinite coordinates.
///
/// # Accuracy
/// Each weight is within 1 ulp of the exact rational value, whatever the triangle's shape,
/// scale or offset (a weight beyond f32's range is the infinity of its sign). The project's
/// accuracy bar (`docs/ACCURACY.md`) is `4 ulp + 2⁻²⁴·κ` with
/// `κ = max(|p|, |a|, |b|, |c|) · max edge / |2·area|`
/// (tests `barycentric_2d_within_bar`, `barycentric_2d_within_bar_scaled`, `total_on_any_bits`
/// and `hard_cases_within_bar`).
///
/// ```
/// use barytex_interp::{barycentric_2d, Location};
/// use glam::Vec2;
/// // Denisjuk, Example 7: x = (0,0), y = (2,3), z = (3,1).
/// let tri = [Vec2::new(0.0, 0.0), Vec2::new(2.0, 3.0), Vec2::new(3.0, 1.0)];
/// let b = barycentric_2d(Vec2::new(1.0, 0.0), tri)?;
/// assert_eq!(b.location, Location::Outside);
/// let [a, be, c] = b.weights;
/// assert!((a - 5.0 / 7.0).abs() < 1e-7 && (be + 1.0 / 7.0).abs() < 1e-7 && (c - 3.0 / 7.0).abs() < 1e-7);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[inline]
pub fn barycentric_2d(p: Vec2, tri: [Vec2; 3]) -> Result<Barycentric2d, InterpError> {
    let (sub, total) = signed_areas(p, tri).ok_or(non_finite(p))?;
    let location = classify(sub, total);
    if location == Location::Degenerate {
        return Err(InterpError::DegenerateTriangle);
    }
    Ok(Barycentric2d {
        // `0.0 / negative` would be `-0.0`: zero weights are written as `+0.0`.
        weights: sub.map(|d| if d == 0.0 { 0.0 } else { (d / total) as f32 }),
        location,
    })
}

fn non_finite(p: Vec2) -> InterpError {
    InterpError::NonFinite {
        what: if p.is_finite() { "triangle" } else { "point" },
    }
}

pub(crate) mod methods {
    use glam::{DVec2, Vec2};

    /// Kahan's `a·b − c·d` with one fused multiply-add correction: nearly correctly rounded.
    #[inline]
    pub(crate) fn difference_of_products(a: f32, b: f32, c: f32, d: f32) -> f32 {
        let cd = c * d;
        let err = crate::math::fma_f32(-c, d, cd);
        let dop = crate::math::fma_f32(a, b, -cd);
        dop + err
    }

    /// The textbook formula (Denisjuk, Theorem 8) in plain f32: `β = (z−x)×(u−x) / (z−x)×(y−x)`,
    /// `γ = (u−x)×(y−x) / (z−x)×(y−x)`, `α = 1 − β − γ`.
    ///
    /// # Accuracy
    /// None guaranteed: error grows with `κ` at f32 precision and `α` loses accuracy near vertex
    /// `a`; signs can be wrong near edges. Degenerate triangles give infinities or NaN. Kept for
    /// the speed-vs-error report.
    #[must_use]
    pub fn barycentric_2d_naive_f32(u: Vec2, [x, y, z]: [Vec2; 3]) -> [f32; 3] {
        let zx = z - x;
        let ux = u - x;
        let yx = y - x;
        let den = zx.perp_dot(yx);
        let beta = zx.perp_dot(ux) / den;
        let gamma = ux.perp_dot(yx) / den;
        [1.0 - beta - gamma, beta, gamma]
    }

    /// Each signed area by Kahan's difference of products in f32, divided by the total.
    ///
    /// # Accuracy
    /// Products are nearly exact but the edge differences still round in f32; no sign
    /// guarantee. Kept for the speed-vs-error report.
    #[must_use]
    pub fn barycentric_2d_dop_f32(p: Vec2, [a, b, c]: [Vec2; 3]) -> [f32; 3] {
        let cross = |o: Vec2, q: Vec2, r: Vec2| {
            let u = q - o;
            let v = r - o;
            difference_of_products(u.x, v.y, u.y, v.x)
        };
        let total = cross(a, b, c);
        [
            cross(b, c, p) / total,
            cross(c, a, p) / total,
            cross(a, b, p) / total,
        ]
    }

    /// Each signed area in plain f64 arithmetic, divided by the total, rounded to f32.
    ///
    /// # Accuracy
    /// Within `1 ulp + 2⁻⁴⁹·κ` of exact (same `κ` as [`barycentric_2d`](crate::barycentric_2d))
    /// but without the exact classification: a weight of a point on an edge may come out as a
    /// tiny non-zero value of either sign.
    #[must_use]
    pub fn barycentric_2d_f64(p: Vec2, [a, b, c]: [Vec2; 3]) -> [f32; 3] {
        let (p, a, b, c) = (p.as_dvec2(), a.as_dvec2(), b.as_dvec2(), c.as_dvec2());
        let cross = |o: DVec2, q: DVec2, r: DVec2| (q - o).perp_dot(r - o);
        let total = cross(a, b, c);
        [
            (cross(b, c, p) / total) as f32,
            (cross(c, a, p) / total) as f32,
            (cross(a, b, p) / total) as f32,
        ]
    }
}
