//! Distortion of a chart: how far its map from the surface to the plane is from conformal and
//! from area-preserving.
//!
//! For each triangle the map is affine with Jacobian `J` (from the triangle laid flat to its uv
//! triangle) and singular values `σ1 ≥ σ2`:
//! - **angle distortion** `σ1 / σ2` — 1 for a conformal (angle-preserving) triangle, the
//!   quasi-conformal ratio of Sander, Snyder, Gortler, Hoppe, "Texture mapping progressive
//!   meshes", SIGGRAPH 2001 (their `Γ/γ`);
//! - **area distortion** `max(ρ, 1/ρ)` with `ρ = σ1 σ2 · (A_3D / A_uv)`, the triangle's area ratio
//!   normalized by the chart's total areas — 1 when every triangle keeps its share of the area.
//!
//! - **L2 stretch** `sqrt(Σ A_T (σ1² + σ2²)/2 / Σ A_T)` after scaling the uvs to the surface's
//!   area — Sander et al.'s `L²` norm (their eq. 3 and §4), 1 for an isometry, growing with both
//!   kinds of distortion.
//!
//! A chart's figures are the 3-D-area-weighted means and the maxima over its triangles. All are
//! invariant under scaling the uvs, so they compare before and after packing.

use glam::DVec2;

use crate::geometry::{flatten, is_degenerate, jacobian, singular_values};
use crate::{Chart, UnwrapMesh, flipped_triangles};

/// Distortion figures of one chart (or an atlas), as defined in the module documentation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChartStats {
    /// Triangles.
    pub triangles: usize,
    /// Triangles flipped or degenerate in uv ([`flipped_triangles`]).
    pub flipped: usize,
    /// Triangles of zero 3-D area (left out of the means and maxima).
    pub degenerate: usize,
    /// Area-weighted mean of `σ1 / σ2` (≥ 1).
    pub angle_distortion_mean: f64,
    /// Largest `σ1 / σ2`.
    pub angle_distortion_max: f64,
    /// Area-weighted mean of `max(ρ, 1/ρ)` (≥ 1).
    pub area_distortion_mean: f64,
    /// Largest `max(ρ, 1/ρ)`.
    pub area_distortion_max: f64,
    /// Sander et al.'s L2 stretch (≥ 1; 1 for an isometry up to scale).
    pub stretch_l2: f64,
    /// 3-D surface area.
    pub surface_area: f64,
    /// Signed uv area.
    pub uv_area: f64,
}

/// The distortion of `chart` (texture coordinates of `mesh`'s triangles).
///
/// # Accuracy
/// The singular values come from Blinn's closed form, within `1e-14` relative of the exact ones
/// for a scaled rotation (`geometry.rs` unit test); a uniform scaling measures 1 within `1e-12`
/// and a 1 : 4 stretch 4 within `1e-12` (the example below).
///
/// ```
/// use barytex_unwrap::{Chart, UnwrapMesh, chart_stats};
/// use glam::{DVec2, DVec3};
///
/// let mesh = UnwrapMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).unwrap();
/// let mut chart = Chart {
///     faces: vec![0],
///     vertices: vec![0, 1, 2],
///     triangles: vec![[0, 1, 2]],
///     uvs: vec![DVec2::ZERO, DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)],
/// };
/// let s = chart_stats(&mesh, &chart);
/// assert!((s.angle_distortion_mean - 1.0).abs() < 1e-12); // a uniform scaling is conformal
/// assert!((s.stretch_l2 - 1.0).abs() < 1e-12); // and, up to scale, an isometry
/// chart.uvs[2].y = 8.0;
/// assert!((chart_stats(&mesh, &chart).angle_distortion_max - 4.0).abs() < 1e-12);
/// ```
#[must_use]
pub fn chart_stats(mesh: &UnwrapMesh, chart: &Chart) -> ChartStats {
    atlas_stats(mesh, core::slice::from_ref(chart))
}

/// The distortion of several charts together: means over all their triangles, the area ratio
/// normalized by the totals over all charts (so a chart drawn too small or too large relative to
/// the others counts — meaningful after packing, when the charts share one scale).
#[must_use]
pub fn atlas_stats(mesh: &UnwrapMesh, charts: &[Chart]) -> ChartStats {
    let mut s = ChartStats::default();
    // (3-D area, Jacobian singular values) per usable triangle.
    let mut per = Vec::new();
    for chart in charts {
        s.triangles += chart.triangles.len();
        s.flipped += flipped_triangles(chart);
        for (j, t) in chart.triangles.iter().enumerate() {
            let face = chart.faces.get(j).copied().unwrap_or(u32::MAX);
            let Some(tri) = mesh.triangles().get(face as usize) else {
                s.degenerate += 1;
                continue;
            };
            let p = tri.map(|v| mesh.positions()[v as usize]);
            let uv = t.map(|v| chart.uvs.get(v as usize).copied().unwrap_or(DVec2::NAN));
            let q = flatten(p);
            let jac = if is_degenerate(p) {
                None
            } else {
                jacobian(q, uv)
            };
            match jac {
                Some(jac) if jac.is_finite() => {
                    let area = 0.5 * crate::geometry::doubled_area_2d(q);
                    s.surface_area += area;
                    s.uv_area += 0.5 * crate::geometry::doubled_area_2d(uv);
                    per.push((area, singular_values(jac), jac.determinant() > 0.0));
                }
                _ => s.degenerate += 1,
            }
        }
    }
    let norm = s.surface_area / s.uv_area;
    let mut weight = 0.0;
    let mut stretch = 0.0;
    for &(area, (s1, s2), positive) in &per {
        stretch += area * 0.5 * (s1 * s1 + s2 * s2) * norm;
        let angle = if positive && s2 > 0.0 {
            s1 / s2
        } else {
            f64::INFINITY
        };
        let rho = s1 * s2 * norm;
        let area_d = if rho > 0.0 {
            rho.max(1.0 / rho)
        } else {
            f64::INFINITY
        };
        s.angle_distortion_max = s.angle_distortion_max.max(angle);
        s.area_distortion_max = s.area_distortion_max.max(area_d);
        s.angle_distortion_mean += area * angle;
        s.area_distortion_mean += area * area_d;
        weight += area;
    }
    if weight > 0.0 {
        s.angle_distortion_mean /= weight;
        s.area_distortion_mean /= weight;
        s.stretch_l2 = (stretch / weight).sqrt();
    }
    s
}
