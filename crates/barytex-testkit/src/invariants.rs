//! Invariant checks shared by property tests and fuzz targets: each returns `Err(description)`
//! rather than panicking, so a fuzz target and a proptest assert the same thing.

use barytex_interp::{
    InterpError, InverseBilinear, Location, barycentric_2d, inverse_bilinear_2d, locate_2d,
    orient2d,
};
use glam::{DVec2, Vec2};

use crate::exact;
use crate::reference::bilinear_f64;
use crate::ulp::ulp_f32;

/// The condition number of a barycentric query:
/// `max(|p|, |a|, |b|, |c|) · max edge length / |2·area|` (in f64; ∞ for zero area).
#[must_use]
pub fn barycentric_condition(p: Vec2, [a, b, c]: [Vec2; 3]) -> f64 {
    let (p, a, b, c) = (p.as_dvec2(), a.as_dvec2(), b.as_dvec2(), c.as_dvec2());
    let magnitude = [p, a, b, c].iter().map(|v| v.length()).fold(0.0, f64::max);
    let edge = (b - a).length().max((c - b).length()).max((a - c).length());
    let area2 = exact::to_f64(&exact::orient2d_det(a.as_vec2(), b.as_vec2(), c.as_vec2())).abs();
    magnitude * edge / area2
}

/// The project's accuracy bar for one 2D barycentric weight (`docs/ACCURACY.md`):
/// `4 ulp + 2⁻²⁴·κ` around the exact value.
#[must_use]
pub fn barycentric_bar(exact_weight: f64, kappa: f64) -> f64 {
    4.0 * ulp_f32(exact_weight) + kappa * 2f64.powi(-24)
}

/// The tighter bound `barytex_interp::barycentric_2d` documents: 1 ulp of the exact weight.
#[must_use]
pub fn barycentric_documented_bound(exact_weight: f64) -> f64 {
    ulp_f32(exact_weight)
}

/// `orient2d` is an error exactly for non-finite input and otherwise has the exact sign.
///
/// # Errors
/// A description of the violated invariant.
pub fn check_orient2d(a: Vec2, b: Vec2, c: Vec2) -> Result<(), String> {
    let got = orient2d(a, b, c);
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return match got {
            Err(_) => Ok(()),
            Ok(o) => Err(format!(
                "orient2d({a:?}, {b:?}, {c:?}) = {o:?} for non-finite input"
            )),
        };
    }
    let want = exact::orient2d_sign(a, b, c);
    match got {
        Ok(o) if o.sign() == want => Ok(()),
        other => Err(format!(
            "orient2d({a:?}, {b:?}, {c:?}) = {other:?}, exact sign {want}"
        )),
    }
}

/// `barycentric_2d` and `locate_2d`: errors for non-finite and degenerate input, exact location,
/// zero weights exactly zero on edges and vertices, each weight within the documented bound
/// (1 ulp) and the project's accuracy bar ([`barycentric_bar`]).
///
/// # Errors
/// A description of the violated invariant.
pub fn check_barycentric_2d(p: Vec2, tri: [Vec2; 3]) -> Result<(), String> {
    let got = barycentric_2d(p, tri);
    let located = locate_2d(p, tri);
    if !(p.is_finite() && tri.iter().all(|v| v.is_finite())) {
        return match (got, located) {
            (Err(InterpError::NonFinite { .. }), Err(InterpError::NonFinite { .. })) => Ok(()),
            other => Err(format!("non-finite input {p:?} {tri:?} gave {other:?}")),
        };
    }
    let want = exact::location_2d(p, tri);
    if located != Ok(want) {
        return Err(format!(
            "locate_2d({p:?}, {tri:?}) = {located:?}, exact {want:?}"
        ));
    }
    let Some(exact_weights) = exact::barycentric_2d(p, tri) else {
        return match got {
            Err(InterpError::DegenerateTriangle) => Ok(()),
            other => Err(format!("degenerate {tri:?} gave {other:?}")),
        };
    };
    let b = got.map_err(|e| format!("barycentric_2d({p:?}, {tri:?}) failed: {e}"))?;
    if b.location != want {
        return Err(format!("location {:?}, exact {want:?}", b.location));
    }
    let kappa = barycentric_condition(p, tri);
    for (i, (w, e)) in b.weights.iter().zip(&exact_weights).enumerate() {
        let e64 = exact::to_f64(e);
        if (e64 as f32).is_infinite() {
            // The exact weight is beyond f32's range: the documented value is the infinity of
            // its sign.
            if *w != e64 as f32 {
                return Err(format!(
                    "weight {i} of {p:?} in {tri:?}: {w}, exact {e64:e}"
                ));
            }
            continue;
        }
        if !w.is_finite() {
            return Err(format!(
                "weight {i} of {p:?} in {tri:?} is {w}, exact {e64:e}"
            ));
        }
        let err = exact::abs_diff(&exact::qf(*w), e);
        let bound = barycentric_documented_bound(e64).min(barycentric_bar(e64, kappa));
        if err > bound {
            return Err(format!(
                "weight {i} of {p:?} in {tri:?}: {w} vs exact {e64}, error {err:e} > bound {bound:e}"
            ));
        }
        if e64 == 0.0 && *w != 0.0 && matches!(want, Location::OnEdge(_) | Location::OnVertex(_)) {
            return Err(format!("weight {i} should be exactly 0, got {w}"));
        }
    }
    Ok(())
}

/// `inverse_bilinear_2d` never panics; non-finite input is an error; `DegenerateQuad` only for
/// exactly collinear corners; every preimage it reports
/// inside `[0, 1]²` maps back to the point within `4e-7` of the quad's size, and no reported
/// preimage is NaN.
///
/// # Errors
/// A description of the violated invariant.
pub fn check_inverse_bilinear_2d(p: Vec2, quad: [Vec2; 4]) -> Result<(), String> {
    let got = inverse_bilinear_2d(p, quad);
    if !(p.is_finite() && quad.iter().all(|v| v.is_finite())) {
        return match got {
            Err(InterpError::NonFinite { .. }) => Ok(()),
            other => Err(format!("non-finite input gave {other:?}")),
        };
    }
    let result = match got {
        Ok(result) => result,
        Err(InterpError::DegenerateQuad) => {
            // Only a quad whose four corners lie exactly on one line may be called degenerate.
            let [x, y, z, w] = quad;
            let flat = [(x, y, z), (x, z, w), (x, y, w), (y, z, w)]
                .iter()
                .all(|&(a, b, c)| exact::orient2d_sign(a, b, c) == 0);
            return if flat {
                Ok(())
            } else {
                Err(format!(
                    "DegenerateQuad for the non-flat quad {quad:?} at {p:?}"
                ))
            };
        }
        Err(e) => return Err(format!("unexpected error {e} for {p:?} in {quad:?}")),
    };
    let q64 = quad.map(|v| v.as_dvec2());
    let size = q64
        .iter()
        .flat_map(|a| q64.iter().map(move |b| (*a - *b).length()))
        .fold(0.0, f64::max);
    let check = |ab: Vec2| -> Result<(), String> {
        if !(0.0..=1.0).contains(&ab.x) || !(0.0..=1.0).contains(&ab.y) {
            return Err(format!("inside preimage {ab:?} outside [0,1]²"));
        }
        let back = bilinear_f64(q64, ab.as_dvec2());
        let residual = (back - p.as_dvec2()).length();
        if residual > 4e-7 * size {
            return Err(format!(
                "preimage {ab:?} of {p:?} in {quad:?} maps to {back:?}, residual {residual:e} (size {size:e})"
            ));
        }
        Ok(())
    };
    match result {
        InverseBilinear::Inside(ab) => check(ab),
        InverseBilinear::Folded(a, b) => check(a).and(check(b)),
        InverseBilinear::Outside(Some(ab)) if ab.is_nan() => {
            Err(format!("outside preimage is NaN: {ab:?}"))
        }
        InverseBilinear::Outside(_) => Ok(()),
    }
}

/// Distance in parameter space between a reported preimage and the f64 Newton reference.
#[must_use]
pub fn inverse_bilinear_error(ab: Vec2, reference: DVec2) -> f64 {
    (ab.as_dvec2() - reference).abs().max_element()
}

/// Inputs up to this many points are also compared against the brute-force exact hull
/// ([`exact::convex_hull_2d_vertex_set`]) by [`check_convex_hull_2d`].
pub const HULL_2D_BRUTE_FORCE_MAX: usize = 16;

/// `convex_hull_2d` under both policies: the typed error naming the first non-finite point;
/// otherwise both hulls pass [`ConvexHull2d::validate`](barytex_interp::ConvexHull2d::validate)
/// (exact: counter-clockwise from the lowest point, convex, every point inside or on the
/// boundary, policy respected, lowest index of duplicates), agree on the shape, the `Drop` hull is
/// the `Keep` hull without its straight-ahead vertices (same order), and, for at most
/// [`HULL_2D_BRUTE_FORCE_MAX`] points, both vertex sets equal the brute-force exact ones.
///
/// # Errors
/// A description of the violated invariant.
pub fn check_convex_hull_2d(points: &[Vec2]) -> Result<(), String> {
    use barytex_interp::{CollinearPoints, HullError2d, convex_hull_2d};
    let drop = convex_hull_2d(points, CollinearPoints::Drop);
    let keep = convex_hull_2d(points, CollinearPoints::Keep);
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        let want = Some(HullError2d::NonFinite { index });
        if drop.as_ref().err().copied() != want || keep.as_ref().err().copied() != want {
            return Err(format!(
                "non-finite point {index}: Drop gave {drop:?}, Keep gave {keep:?}"
            ));
        }
        return Ok(());
    }
    let drop = drop.map_err(|e| format!("Drop: unexpected error {e}"))?;
    let keep = keep.map_err(|e| format!("Keep: unexpected error {e}"))?;
    drop.validate(points)
        .map_err(|d| format!("Drop hull {:?} invalid: {d}", drop.vertices()))?;
    keep.validate(points)
        .map_err(|d| format!("Keep hull {:?} invalid: {d}", keep.vertices()))?;
    if drop.shape() != keep.shape() {
        return Err(format!(
            "shapes differ: Drop {:?}, Keep {:?}",
            drop.shape(),
            keep.shape()
        ));
    }
    let filtered: Vec<usize> = keep
        .vertices()
        .iter()
        .copied()
        .filter(|i| drop.vertices().contains(i))
        .collect();
    if filtered != drop.vertices() {
        return Err(format!(
            "Drop hull {:?} is not Keep hull {:?} without its straight-ahead vertices",
            drop.vertices(),
            keep.vertices()
        ));
    }
    if points.len() <= HULL_2D_BRUTE_FORCE_MAX {
        for (hull, keep_policy) in [(&drop, false), (&keep, true)] {
            let mut got = hull.vertices().to_vec();
            got.sort_unstable();
            let want = exact::convex_hull_2d_vertex_set(points, keep_policy);
            if got != want {
                return Err(format!(
                    "{:?} vertex set {got:?}, brute-force exact {want:?}",
                    hull.collinear()
                ));
            }
        }
    }
    Ok(())
}
