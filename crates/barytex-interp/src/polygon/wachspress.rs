//! Wachspress coordinates: `wᵢ = Cᵢ / (Aᵢ₋₁·Aᵢ)`, normalised, where `Cᵢ` is the area of the
//! corner triangle `(vᵢ₋₁, vᵢ, vᵢ₊₁)` and `Aᵢ` the area of `(p, vᵢ, vᵢ₊₁)`.

use glam::Vec2;

use super::shape::{
    Convexity, STACK, edge_weights, locate_and_weigh_boundary, next, normalise, prev, validate,
};
use super::{PolygonError, PolygonLocation};
use crate::determinant::orient2d_det;

/// Wachspress coordinates of `p` in the strictly convex `polygon`, written into `weights`
/// (one per vertex); returns where `p` lies.
///
/// The polygon may be counter-clockwise or clockwise. `p` is located exactly first: on a
/// vertex the weights are exactly that vertex's unit vector; on an edge, the linear
/// interpolation along it with every other weight exactly `+0.0`. Inside, every weight is
/// `Cᵢ/(Aᵢ₋₁·Aᵢ)` normalised, with the areas computed from the f32 inputs with an exact sign
/// and a relative error below 2⁻³⁰ (the exact expansion sum of `determinant.rs` where plain f64
/// is not that accurate); every term is positive, so nothing cancels however close `p` is to
/// the boundary. No allocation; the sum starts at the lexicographically smallest vertex, so a
/// rotated vertex list gives bit-identical (rotated) weights.
///
/// **Outside** (`Ok(Outside)`) the weights are the rational functions' values, extrapolated:
/// they sum to one and reproduce `p`, and at least one is negative. On the line of one edge they
/// are the affine coordinates along that edge (the functions' limit). Where the functions have a
/// pole (their denominator `Σ wᵢ` vanishes, which happens on a curve outside every polygon of
/// more than three vertices, or `p` is on the lines of two non-adjacent edges) the result is
/// `Err(Undefined)` when `p` is on two edge lines or the rounded sum is 0; elsewhere on the
/// curve the rounded sum is rounding noise rather than 0 (floating point cannot tell a pole
/// from a point whose sum cancels to 12 digits), and the weights are those of any point with
/// `d ≥ ½` below: finite, a partition of unity, linearly precise, no correct digit. Near a pole
/// the weights are large and only as accurate as the sum's condition number allows.
///
/// # Errors
/// [`PolygonError::TooFewVertices`], [`WeightsLength`](PolygonError::WeightsLength),
/// [`NonFinite`](PolygonError::NonFinite), [`RepeatedVertex`](PolygonError::RepeatedVertex),
/// [`Collinear`](PolygonError::Collinear); [`NotConvex`](PolygonError::NotConvex) when a turn
/// has the wrong sign *or is zero* (a vertex with collinear neighbours would get weight 0
/// everywhere, so Wachspress needs strict convexity; use [`mean_value_weights`](super::mean_value_weights)),
/// [`SelfIntersecting`](PolygonError::SelfIntersecting) for star polygons; and
/// [`Undefined`](PolygonError::Undefined) at a pole outside the polygon where rounding shows it
/// (see above). Convexity is checked
/// with exact orientation signs.
///
/// # Accuracy
/// Inside and on the boundary, each weight is within 1 ulp of the exact rational Wachspress
/// weight of the f32 inputs, whatever the scale (tested from 1e-30 to 1e30), offset or
/// closeness to an edge; hence `|Σλᵢ − 1| ≤ ε` and `|Σλᵢ(vᵢ − p)| ≤ ε·Σλᵢ|vᵢ − p|` (linear
/// precision, `ε = 2⁻²³`). Outside, `|λᵢ − λᵢ*| ≤ d/(1 − d)·|λᵢ*| + 1 ulp` with
/// `d = 2⁻²⁶·(1 + κ)` and `κ = Σ|wⱼ|/|Σwⱼ|` the condition number of the normalising sum; where
/// `d ≥ ½` (points so far out that the sum cancels completely, κ ≳ 3·10⁷) the weights carry no
/// correct digit and only finiteness and the partition below are promised; partition of unity and linear
/// precision hold within `ε·Σ|λᵢ|` and `ε·Σ|λᵢ||vᵢ − p|` (plus `n·2⁻¹⁴⁹·max|vᵢ − p|` for weights
/// in f32's subnormal range). Tests: `polygon_coordinates.rs::{wachspress_matches_exact,
/// wachspress_outside_within_condition_bound, hard_cases_hold}` through
/// `barytex_testkit::polygon_invariants::check_polygon_coordinates` (also the fuzz target
/// `polygon`).
///
/// ```
/// use barytex_interp::{wachspress_weights, PolygonLocation};
/// use glam::Vec2;
/// let quad = [Vec2::ZERO, Vec2::new(4.0, 0.0), Vec2::new(4.0, 2.0), Vec2::new(0.0, 2.0)];
/// let mut w = [0.0; 4];
/// assert_eq!(wachspress_weights(Vec2::new(1.0, 1.0), &quad, &mut w)?, PolygonLocation::Inside);
/// assert_eq!(w, [0.375, 0.125, 0.125, 0.375]); // bilinear on a rectangle
/// assert_eq!(wachspress_weights(Vec2::new(4.0, 0.5), &quad, &mut w)?, PolygonLocation::OnEdge(1));
/// assert_eq!(w, [0.0, 0.75, 0.25, 0.0]);
/// # Ok::<(), barytex_interp::PolygonError>(())
/// ```
pub fn wachspress_weights(
    p: Vec2,
    polygon: &[Vec2],
    weights: &mut [f32],
) -> Result<PolygonLocation, PolygonError> {
    let n = polygon.len();
    let cached = n <= STACK;
    let mut corners = [0.0f64; STACK];
    let shape = validate(p, polygon, weights.len(), Convexity::Strict, |i, det| {
        if cached {
            corners[i] = det;
        }
    })?;
    let mut areas = [0.0f64; STACK];
    let area = |i: usize| orient2d_det(p, polygon[i], polygon[next(i, n)]);
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
    if location == PolygonLocation::Outside {
        // On the line of an edge the weights are that edge's affine coordinates, if it is the
        // only such line; on two, every numerator of the product form vanishes.
        let mut zeros = (0..n).filter(|&i| area_at(i) == 0.0);
        if let Some(i) = zeros.next() {
            if zeros.next().is_some() || !edge_weights(p, polygon, i, weights) {
                return Err(PolygonError::Undefined);
            }
            return Ok(location);
        }
    }
    let corner = |i: usize| {
        if cached {
            corners[i]
        } else {
            orient2d_det(polygon[prev(i, n)], polygon[i], polygon[next(i, n)])
        }
    };
    // Every area is non-zero here. `Cᵢ/(Aᵢ₋₁Aᵢ)` stays inside f64's range for all finite f32
    // input (areas lie between 2⁻²⁹⁸ and 2²⁵⁷), so no rescaling is needed.
    let w = |i: usize| corner(i) / (area_at(prev(i, n)) * area_at(i));
    normalise(n, shape, w, weights)?;
    Ok(location)
}
