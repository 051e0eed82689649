//! Generalized barycentric coordinates over polygons: exact references and the invariant check
//! shared by the property tests (`crates/barytex-interp/tests/polygon_coordinates.rs`), the fuzz
//! target `polygon` and its regression replay.

use barytex_interp::{GeneralizedBarycentric, PolygonError, PolygonLocation};
use glam::{DVec2, Vec2};
use num_traits::{Signed, Zero};

use crate::exact::{self, Q, qf};
use crate::ulp::ulp_f32;

/// `f32::EPSILON` (2⁻²³) in f64: the unit of the documented bounds.
const EPS: f64 = f32::EPSILON as f64;

/// The smallest f32 subnormal: the absolute rounding of weights in f32's subnormal range.
const SUBNORMAL: f64 = 1.401_298_464_324_817e-45;

/// The convex polygon with vertices on the ellipse `centre + (radii.x·cos θ, radii.y·sin θ)` at
/// the angles `start + 2π·(g₀ + … + gᵢ₋₁)/Σg` (counter-clockwise; `gaps` positive, at least 3):
/// strictly convex before rounding to f32, and after it too unless a gap is tiny.
#[must_use]
pub fn polygon_on_ellipse(centre: Vec2, radii: Vec2, start: f64, gaps: &[f64]) -> Vec<Vec2> {
    let total: f64 = gaps.iter().sum();
    let mut angle = start;
    gaps.iter()
        .map(|g| {
            let v = centre.as_dvec2() + radii.as_dvec2() * DVec2::new(angle.cos(), angle.sin());
            angle += core::f64::consts::TAU * g / total;
            v.as_vec2()
        })
        .collect()
}

/// The error the validation must report, decided with exact rational signs in the documented
/// order; `Ok(orientation sign)` for an accepted polygon.
///
/// # Errors
/// The expected [`PolygonError`].
pub fn expected_validation(
    method: GeneralizedBarycentric,
    p: Vec2,
    polygon: &[Vec2],
) -> Result<i8, PolygonError> {
    let n = polygon.len();
    if n < 3 {
        return Err(PolygonError::TooFewVertices { count: n });
    }
    if !p.is_finite() {
        return Err(PolygonError::NonFinite { what: "point" });
    }
    if !polygon.iter().all(|v| v.is_finite()) {
        return Err(PolygonError::NonFinite { what: "polygon" });
    }
    if let Some(index) = (0..n).find(|&i| polygon[i] == polygon[(i + 1) % n]) {
        return Err(PolygonError::RepeatedVertex { index });
    }
    let mut orientation = 0i8;
    let mut flat = None;
    let upper = |i: usize| {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        b.y > a.y || (b.y == a.y && b.x > a.x)
    };
    let mut changes = 0;
    for i in 0..n {
        let (a, b, c) = (polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
        let s = exact::orient2d_sign(a, b, c);
        if s == 0 {
            let dir = |u: f32, v: f32| (v > u) as i8 - (v < u) as i8;
            let straight = dir(a.x, b.x) == dir(b.x, c.x) && dir(a.y, b.y) == dir(b.y, c.y);
            if !straight || method == GeneralizedBarycentric::Wachspress {
                flat.get_or_insert(i);
            }
        } else if orientation == 0 {
            orientation = s;
        } else if s != orientation {
            return Err(PolygonError::NotConvex { vertex: i });
        }
        if upper(i) != upper((i + 1) % n) {
            changes += 1;
        }
    }
    if orientation == 0 {
        return Err(PolygonError::Collinear);
    }
    if let Some(vertex) = flat {
        return Err(PolygonError::NotConvex { vertex });
    }
    if changes != 2 {
        return Err(PolygonError::SelfIntersecting);
    }
    Ok(orientation)
}

/// The exact location of `p` in an accepted convex polygon of the given orientation.
#[must_use]
pub fn exact_location(p: Vec2, polygon: &[Vec2], orientation: i8) -> PolygonLocation {
    let n = polygon.len();
    if let Some(i) = polygon.iter().position(|&v| v == p) {
        return PolygonLocation::OnVertex(i);
    }
    let signs: Vec<i8> = (0..n)
        .map(|i| exact::orient2d_sign(p, polygon[i], polygon[(i + 1) % n]) * orientation)
        .collect();
    if signs.contains(&-1) {
        return PolygonLocation::Outside;
    }
    (0..n)
        .find(|&i| {
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            signs[i] == 0
                && p.x >= a.x.min(b.x)
                && p.x <= a.x.max(b.x)
                && p.y >= a.y.min(b.y)
                && p.y <= a.y.max(b.y)
        })
        .map_or(PolygonLocation::Inside, PolygonLocation::OnEdge)
}

/// The exact affine coordinates `(λᵢ, λᵢ₊₁)` of `p` on the line of edge `i` (p collinear).
#[must_use]
pub fn exact_edge_weights(p: Vec2, polygon: &[Vec2], i: usize) -> (Q, Q) {
    let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
    let (pa, pb, pp) = if a.x != b.x {
        (qf(a.x), qf(b.x), qf(p.x))
    } else {
        (qf(a.y), qf(b.y), qf(p.y))
    };
    let span = &pb - &pa;
    ((&pb - &pp) / &span, (&pp - &pa) / span)
}

/// The exact Wachspress weights of `p` (off the boundary) in a strictly convex polygon, from the
/// product form `ŵᵢ = Cᵢ·Π_{j∉{i−1,i}} Aⱼ` (continuous across edge lines); `None` at a pole
/// (the sum vanishes). Also returns the condition number `Σ|ŵᵢ|/|Σŵᵢ|` of the normalisation.
#[must_use]
pub fn exact_wachspress(p: Vec2, polygon: &[Vec2]) -> Option<(Vec<Q>, f64)> {
    let n = polygon.len();
    let areas: Vec<Q> = (0..n)
        .map(|i| exact::orient2d_det(p, polygon[i], polygon[(i + 1) % n]))
        .collect();
    let corner =
        |i: usize| exact::orient2d_det(polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
    let raw: Vec<Q> = if areas.iter().all(|a| !a.is_zero()) {
        (0..n)
            .map(|i| corner(i) / (&areas[(i + n - 1) % n] * &areas[i]))
            .collect()
    } else {
        (0..n)
            .map(|i| {
                let mut w = corner(i);
                for (j, a) in areas.iter().enumerate() {
                    if j != i && j != (i + n - 1) % n {
                        w *= a;
                    }
                }
                w
            })
            .collect()
    };
    let sum: Q = raw.iter().cloned().sum();
    if sum.is_zero() {
        return None;
    }
    let abs_sum: Q = raw.iter().map(Signed::abs).sum();
    let kappa = exact::to_f64(&(abs_sum / sum.abs()));
    Some((raw.iter().map(|w| w / &sum).collect(), kappa))
}

/// Mean value weights by the textbook angle formula in f64 (`atan2` angles, `tan(α/2)`): an
/// independent reference for well-shaped polygons and points away from the boundary.
#[must_use]
pub fn mean_value_reference_f64(p: Vec2, polygon: &[Vec2]) -> Vec<f64> {
    let n = polygon.len();
    let d: Vec<DVec2> = polygon
        .iter()
        .map(|v| v.as_dvec2() - p.as_dvec2())
        .collect();
    let tans: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b) = (d[i], d[(i + 1) % n]);
            (a.perp_dot(b).atan2(a.dot(b)) / 2.0).tan()
        })
        .collect();
    let w: Vec<f64> = (0..n)
        .map(|i| (tans[(i + n - 1) % n] + tans[i]) / d[i].length())
        .collect();
    let sum: f64 = w.iter().sum();
    w.iter().map(|x| x / sum).collect()
}

/// The outside term of the mean-value linear-precision bound, `Σ|tan(αᵢ/2)| / |Σwⱼ|`, in f64.
#[must_use]
pub fn mean_value_cancellation(p: Vec2, polygon: &[Vec2]) -> f64 {
    let n = polygon.len();
    let d: Vec<DVec2> = polygon
        .iter()
        .map(|v| v.as_dvec2() - p.as_dvec2())
        .collect();
    let tans: Vec<f64> = (0..n)
        .map(|i| {
            let (a, b) = (d[i], d[(i + 1) % n]);
            (a.perp_dot(b).atan2(a.dot(b)) / 2.0).tan()
        })
        .collect();
    let sum: f64 = (0..n)
        .map(|i| (tans[(i + n - 1) % n] + tans[i]) / d[i].length())
        .sum();
    tans.iter().map(|t| t.abs()).sum::<f64>() / sum.abs()
}

/// `(|Σλᵢ − 1|, Σ|λᵢ|, |Σλᵢ(vᵢ − p)|, Σ|λᵢ||vᵢ − p|, max|vᵢ − p|)` in f64 (the f64 rounding of
/// these sums is far below the f32 bounds they are compared with).
#[must_use]
pub fn residuals(p: Vec2, polygon: &[Vec2], weights: &[f32]) -> [f64; 5] {
    let q = p.as_dvec2();
    let mut sum = 0.0;
    let mut abs_sum = 0.0;
    let mut lin = DVec2::ZERO;
    let mut lin_scale = 0.0;
    let mut reach = 0.0f64;
    for (v, &w) in polygon.iter().zip(weights) {
        let (w, d) = (f64::from(w), v.as_dvec2() - q);
        sum += w;
        abs_sum += w.abs();
        lin += d * w;
        lin_scale += w.abs() * d.length();
        reach = reach.max(d.length());
    }
    [(sum - 1.0).abs(), abs_sum, lin.length(), lin_scale, reach]
}

/// Every documented property of `method` at `p` in `polygon`: the exact error for invalid
/// input; the exact location; exact unit weights on a vertex; on an edge, `+0.0` off the edge
/// and the two edge weights within 1 ulp of the exact affine coordinates; inside, non-negative
/// weights, partition of unity within `ε` and linear precision within `ε·Σλᵢ|vᵢ − p|`;
/// outside, a negative weight (or `−0.0` when it underflows) and the outside bounds; for
/// Wachspress each weight within 1 ulp of the exact rational weight (inside) or within its
/// condition-scaled bound (outside). `Undefined` is accepted only for outside points.
///
/// # Errors
/// A description of the violated invariant.
pub fn check_polygon_coordinates(
    method: GeneralizedBarycentric,
    p: Vec2,
    polygon: &[Vec2],
) -> Result<(), String> {
    let name = method.name();
    let n = polygon.len();
    let mut weights = vec![f32::NAN; n];
    let got = method.weights(p, polygon, &mut weights);
    let orientation = match expected_validation(method, p, polygon) {
        Err(want) => {
            return if got == Err(want) {
                Ok(())
            } else {
                Err(format!(
                    "{name}: {p:?} in {polygon:?} gave {got:?}, expected Err({want:?})"
                ))
            };
        }
        Ok(o) => o,
    };
    let location = exact_location(p, polygon, orientation);
    let got = match got {
        Err(PolygonError::Undefined) if location == PolygonLocation::Outside => return Ok(()),
        Err(e) => return Err(format!("{name}: {p:?} in {polygon:?} failed: {e:?}")),
        Ok(got) => got,
    };
    if got != location {
        return Err(format!(
            "{name}: {p:?} in {polygon:?} located {got:?}, exact {location:?}"
        ));
    }
    let context = || format!("{name}: {p:?} in {polygon:?} ({location:?}): weights {weights:?}");
    if weights.iter().any(|w| !w.is_finite()) {
        return Err(format!("{}: non-finite weight", context()));
    }
    match location {
        PolygonLocation::OnVertex(i) => {
            let ok = weights
                .iter()
                .enumerate()
                .all(|(j, w)| w.to_bits() == if i == j { 1.0f32.to_bits() } else { 0 });
            return if ok {
                Ok(())
            } else {
                Err(format!("{}: not the unit vector e{i}", context()))
            };
        }
        PolygonLocation::OnEdge(i) => {
            let j = (i + 1) % n;
            if weights
                .iter()
                .enumerate()
                .any(|(k, w)| k != i && k != j && w.to_bits() != 0)
            {
                return Err(format!("{}: a weight off edge {i} is not +0.0", context()));
            }
            let (wi, wj) = exact_edge_weights(p, polygon, i);
            for (k, e) in [(i, wi), (j, wj)] {
                let err = exact::abs_diff(&qf(weights[k]), &e);
                let bound = ulp_f32(exact::to_f64(&e));
                if err > bound {
                    return Err(format!(
                        "{}: edge weight {k} error {err:e} > 1 ulp {bound:e}",
                        context()
                    ));
                }
            }
            return Ok(());
        }
        PolygonLocation::Inside | PolygonLocation::Outside => {}
    }
    let inside = location == PolygonLocation::Inside;
    let [partition, abs_sum, linear, linear_scale, reach] = residuals(p, polygon, &weights);
    // f64 evaluation of the residuals themselves: n·2⁻⁵³ relative, well below 2⁻⁴⁰.
    let slack = 1.0 + 2f64.powi(-40);
    let subnormal = n as f64 * SUBNORMAL;
    if partition > (EPS * abs_sum + subnormal) * slack {
        return Err(format!(
            "{}: |Σλ − 1| = {partition:e} > ε·Σ|λ| = {:e}",
            context(),
            EPS * abs_sum
        ));
    }
    let mut linear_bound = EPS * linear_scale + subnormal * reach;
    if inside {
        if weights.iter().any(|&w| w < 0.0 || w.is_sign_negative()) {
            return Err(format!("{}: negative weight inside", context()));
        }
    } else {
        if !weights.iter().any(|w| w.is_sign_negative()) {
            return Err(format!("{}: no negative weight outside", context()));
        }
        if method == GeneralizedBarycentric::MeanValue {
            linear_bound += 2f64.powi(-26) * mean_value_cancellation(p, polygon) * reach;
        }
    }
    if linear > linear_bound * slack {
        return Err(format!(
            "{}: linear precision |Σλ(v − p)| = {linear:e} > {linear_bound:e}",
            context()
        ));
    }
    if method == GeneralizedBarycentric::Wachspress {
        let Some((exact_weights, kappa)) = exact_wachspress(p, polygon) else {
            // At a pole there is no exact weight to compare with. The rounded normalising sum
            // there is rounding noise, and only exactly 0 or non-finite makes it `Undefined`
            // (floating point cannot tell a pole from the κ ≈ 7·10¹¹ of a hexagon 10⁶ sizes away):
            // what the weights promise is what they promise wherever `d ≥ ½`, finiteness,
            // partition of unity and linear precision, all checked above. (The input
            // `fuzz/regressions/polygon/crash-4d08…`, an exact pole with weights of 10¹⁶,
            // failed the former rule that a pole must give `Undefined`.)
            return Ok(());
        };
        for (i, (w, e)) in weights.iter().zip(&exact_weights).enumerate() {
            let e64 = exact::to_f64(e);
            let err = exact::abs_diff(&qf(*w), e);
            // Outside, the normalising sum cancels: a relative error d = 2⁻²⁶(1 + κ) of the sum
            // gives |λ − λ*| ≤ d/(1 − d)·|λ*| (the first-order d·|λ*| is not a bound once d is
            // not small). For d ≥ ½ the sum carries no correct digit and nothing is promised.
            let d = 2f64.powi(-26) * (1.0 + kappa);
            if !inside && d >= 0.5 {
                continue;
            }
            let bound = if inside {
                ulp_f32(e64)
            } else {
                d / (1.0 - d) * e64.abs() + ulp_f32(e64)
            };
            if err > bound {
                return Err(format!(
                    "{}: weight {i} = {w} vs exact {e64:e}: error {err:e} > {bound:e} (κ = {kappa:e})",
                    context()
                ));
            }
        }
    }
    Ok(())
}

/// [`check_polygon_coordinates`] for both methods, and that each answers the same for every
/// rotation of the vertex list (the weights rotated with it, bit for bit).
///
/// # Errors
/// The first violated invariant.
pub fn check_polygon_all(p: Vec2, polygon: &[Vec2]) -> Result<(), String> {
    for method in GeneralizedBarycentric::ALL {
        check_polygon_coordinates(method, p, polygon)?;
        check_rotation_invariance(method, p, polygon)?;
    }
    Ok(())
}

/// Every cyclic shift of the vertex list gives the same location (its indices shifted) and the
/// same weights, bit for bit, shifted likewise; errors are the same up to the shifted index.
///
/// # Errors
/// The first rotation that differs.
pub fn check_rotation_invariance(
    method: GeneralizedBarycentric,
    p: Vec2,
    polygon: &[Vec2],
) -> Result<(), String> {
    let n = polygon.len();
    let mut base = vec![0.0f32; n];
    let base_result = method.weights(p, polygon, &mut base);
    let mut rotated = polygon.to_vec();
    let mut weights = vec![0.0f32; n];
    for shift in 1..n {
        rotated.rotate_left(1);
        let result = method.weights(p, &rotated, &mut weights);
        // Vertex/edge i of the rotated list is vertex/edge (i + shift) % n of the original.
        let unshift = |i: usize| (i + shift) % n;
        let same = match (base_result, result) {
            (Ok(a), Ok(b)) => {
                let b = match b {
                    PolygonLocation::OnEdge(i) => PolygonLocation::OnEdge(unshift(i)),
                    PolygonLocation::OnVertex(i) => PolygonLocation::OnVertex(unshift(i)),
                    other => other,
                };
                a == b && (0..n).all(|i| weights[i].to_bits() == base[unshift(i)].to_bits())
            }
            // Which vertex an error names depends on where the scan starts.
            (Err(a), Err(b)) => core::mem::discriminant(&a) == core::mem::discriminant(&b),
            _ => false,
        };
        if !same {
            return Err(format!(
                "{}: rotating {polygon:?} by {shift} changed the answer at {p:?}: {base_result:?} {base:?} vs {result:?} {weights:?}",
                method.name()
            ));
        }
    }
    Ok(())
}
