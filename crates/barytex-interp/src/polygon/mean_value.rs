//! Floater's mean value coordinates in Hormann & Floater's signed-angle form:
//! `wᵢ = (tan(αᵢ₋₁/2) + tan(αᵢ/2)) / rᵢ`, normalised, where `rᵢ = |vᵢ − p|` and `αᵢ` is the
//! signed angle at `p` from `vᵢ` to `vᵢ₊₁`.

use glam::Vec2;

use super::shape::{Convexity, STACK, locate_and_weigh_boundary, next, normalise, prev, validate};
use super::{PolygonError, PolygonLocation};
use crate::determinant::orient2d_det;

/// `tan(α/2)` for the angle `α` at `p` between `dᵢ = vᵢ − p` and `dⱼ = vⱼ − p`, from
/// `area = dᵢ × dⱼ` (exact sign, relative error below 2⁻³⁰), `dot = dᵢ·dⱼ` and the lengths.
///
/// `tan(α/2) = area/(rᵢrⱼ + dot) = (rᵢrⱼ − dot)/area`: the first form is used when `dot ≥ 0`
/// and the second otherwise, so the sum or difference never cancels (both of its terms have the
/// same sign); the sign of the result is the sign of `area`, exactly.
#[inline]
fn half_angle_tan(area: f64, dot: f64, r_product: f64) -> f64 {
    if dot >= 0.0 {
        area / (r_product + dot)
    } else {
        (r_product - dot) / area
    }
}

/// Mean value coordinates of `p` in the convex `polygon`, written into `weights` (one per
/// vertex); returns where `p` lies.
///
/// The polygon may be counter-clockwise or clockwise, and may have flat vertices (a vertex
/// collinear with its neighbours, the boundary going straight on through it), which keep a
/// proper weight. `p` is located exactly first: on a vertex the weights are exactly that
/// vertex's unit vector; on an edge, the linear interpolation along it with every other weight
/// exactly `+0.0`. Otherwise each `tan(αᵢ/2)` comes from the exact-sign area `dᵢ × dᵢ₊₁` and the
/// f64 dot product and lengths through whichever of `area/(rᵢrᵢ₊₁ + dot)` and
/// `(rᵢrᵢ₊₁ − dot)/area` does not cancel. Inside, every term is positive. No allocation; the sum
/// starts at the lexicographically smallest vertex, so a rotated vertex list gives
/// bit-identical (rotated) weights.
///
/// **Outside** (`Ok(Outside)`) the angles are signed (negative for the edges that face `p`), as
/// in Hormann & Floater's extension: the weights still sum to one and reproduce `p`, they are
/// smooth across the extensions of the edges, and at least one is negative (a point outside the
/// convex hull is no convex combination). In exact arithmetic the normalising sum never
/// vanishes off the boundary (Hormann & Floater 2006); should rounding cancel it far away, the
/// result is `Err(Undefined)`.
///
/// # Errors
/// [`PolygonError::TooFewVertices`], [`WeightsLength`](PolygonError::WeightsLength),
/// [`NonFinite`](PolygonError::NonFinite), [`RepeatedVertex`](PolygonError::RepeatedVertex),
/// [`Collinear`](PolygonError::Collinear), [`NotConvex`](PolygonError::NotConvex) (a turn the
/// wrong way, or the boundary doubling back), [`SelfIntersecting`](PolygonError::SelfIntersecting)
/// (star polygons), all decided with exact orientation signs; and
/// [`Undefined`](PolygonError::Undefined) when the normalising sum rounds to zero or a weight
/// overflows f32 (only outside).
///
/// # Accuracy
/// Inside: `|Σλᵢ − 1| ≤ ε` and linear precision `|Σλᵢ(vᵢ − p)| ≤ ε·Σλᵢ|vᵢ − p|` (`ε = 2⁻²³`;
/// plus `n·2⁻¹⁴⁹·max|vᵢ − p|` for weights in f32's subnormal range), every weight ≥ 0, at any
/// scale, offset and closeness to an edge or vertex; each weight within `2⁻²²` of an f64
/// `atan2` reference on well-shaped polygons — as tested: strictly convex, 3–16 vertices on an
/// ellipse with semi-axes 0.5 … 5 at angles `2π·gᵢ/Σg` apart with `gᵢ ∈ [0.2, 1]` (no gap more
/// than 5× another), the point an interior combination of the vertices with weights
/// 0.001 … 1 (the reference's own `atan2` angles lose accuracy near the boundary). Outside: partition within `ε·Σ|λᵢ|`, and linear
/// precision within `ε·Σ|λᵢ||vᵢ − p| + 2⁻²⁶·Σ|tan(αᵢ/2)|/|Σwⱼ|` (the terms
/// `tan(αᵢ₋₁/2) + tan(αᵢ/2)` of opposite signs cancel there). Tests:
/// `polygon_coordinates.rs::{mean_value_matches_atan2_reference, hard_cases_hold}` and every
/// property through `barytex_testkit::polygon_invariants::check_polygon_coordinates` (also the
/// fuzz target `polygon`).
///
/// ```
/// use barytex_interp::{mean_value_weights, PolygonLocation};
/// use glam::Vec2;
/// let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
/// let mut w = [0.0; 4];
/// assert_eq!(mean_value_weights(Vec2::new(0.5, 0.5), &square, &mut w)?, PolygonLocation::Inside);
/// assert_eq!(w, [0.25; 4]);
/// assert_eq!(mean_value_weights(Vec2::ONE, &square, &mut w)?, PolygonLocation::OnVertex(2));
/// assert_eq!(w, [0.0, 0.0, 1.0, 0.0]);
/// assert_eq!(mean_value_weights(Vec2::new(2.0, 0.5), &square, &mut w)?, PolygonLocation::Outside);
/// assert!(w.iter().any(|&x| x < 0.0));
/// # Ok::<(), barytex_interp::PolygonError>(())
/// ```
pub fn mean_value_weights(
    p: Vec2,
    polygon: &[Vec2],
    weights: &mut [f32],
) -> Result<PolygonLocation, PolygonError> {
    let n = polygon.len();
    let shape = validate(p, polygon, weights.len(), Convexity::Weak, |_, _| {})?;
    let cached = n <= STACK;
    let q = p.as_dvec2();
    // `vᵢ − p` in f64: exact unless the two magnitudes differ by more than 2²⁹ (then correctly
    // rounded); squares and products of f32-sized values never overflow or underflow f64.
    let d = |i: usize| polygon[i].as_dvec2() - q;
    let radius = |i: usize| crate::math::sqrt(d(i).length_squared());
    let area = |i: usize| orient2d_det(p, polygon[i], polygon[next(i, n)]);
    let mut areas = [0.0f64; STACK];
    if cached {
        for (i, a) in areas.iter_mut().enumerate().take(n) {
            *a = area(i);
        }
    }
    let area_at = |i: usize| if cached { areas[i] } else { area(i) };
    let (location, done) = locate_and_weigh_boundary(p, polygon, shape, area_at, weights);
    if done {
        return Ok(location);
    }
    // Every radius is positive here (`p` is no vertex).
    let mut radii = [0.0f64; STACK];
    let mut tans = [0.0f64; STACK];
    if cached {
        for (i, r) in radii.iter_mut().enumerate().take(n) {
            *r = radius(i);
        }
        for (i, t) in tans.iter_mut().enumerate().take(n) {
            let j = next(i, n);
            *t = half_angle_tan(areas[i], d(i).dot(d(j)), radii[i] * radii[j]);
        }
    }
    let tan_at = |i: usize| {
        if cached {
            tans[i]
        } else {
            let j = next(i, n);
            half_angle_tan(area(i), d(i).dot(d(j)), radius(i) * radius(j))
        }
    };
    let radius_at = |i: usize| if cached { radii[i] } else { radius(i) };
    let w = |i: usize| (tan_at(prev(i, n)) + tan_at(i)) / radius_at(i);
    normalise(n, shape, w, weights)?;
    Ok(location)
}
