//! How much a uv layout stretches a surface: per triangle, the singular values `σ1 ≥ σ2` of the
//! Jacobian of the affine map from the triangle (in its own plane) to its uv triangle; per mesh,
//! area-weighted summaries.
//!
//! - **Angle distortion** is `σ1/σ2` (1 for a conformal map, `∞` where the uv triangle is
//!   degenerate): how much a small circle on the surface is elongated in the texture.
//! - **Area distortion** compares the triangle's area ratio `σ1σ2 = A_uv/A_3d` with the mesh's
//!   mean ratio `ΣA_uv/ΣA_3d`: with `ρ = σ1σ2 / mean`, it is `max(ρ, 1/ρ)` (1 when every
//!   triangle gets its fair share of texels, 2 when a triangle gets twice or half its share).
//!
//! Both are ≥ 1, and both are scale-free: scaling the mesh or the uvs changes neither.
//!
//! A mesh's figures include its discretization: flat triangles are not the smooth surface. The
//! unit sphere at `2n × n` measures an excess area distortion of about `1.6/n` with the
//! equal-area uvs (exactly 1 in the limit), and the equirectangular one approaches its closed
//! form `1.5166` from below by about as much (`crates/barytex-uv/tests/distortion.rs`):
//!
//! | sphere | equirectangular area mean / max | equal-area area mean / max | angle mean (equirect. / equal-area) |
//! |---|---|---|---|
//! | 64 × 32 | 1.468 / 6.7 | 1.051 / 2.0 | 1.72 / 2.90 |
//! | 256 × 128 | 1.504 / 26.2 | 1.013 / 2.0 | 1.74 / 3.34 |
//!
//! ```
//! use barytex_uv::distortion::MeshDistortion;
//! use barytex_uv::mesh::{self, SphereUv};
//!
//! let equirectangular = MeshDistortion::of(&mesh::sphere(64, 32).expect("valid")).expect("measurable");
//! let equal_area =
//!     MeshDistortion::of(&mesh::sphere_with(64, 32, SphereUv::EqualArea).expect("valid")).expect("measurable");
//! assert!(equal_area.area_mean < 1.06); // 1.6/32 of discretization, see above
//! assert!(equirectangular.area_mean > 1.3);
//! ```

use glam::{DMat2, DVec2, Vec2, Vec3};

use crate::mesh::TriMesh;

/// The singular values `(σ1, σ2)`, `σ1 ≥ σ2 ≥ 0`, of a 2 × 2 matrix, in closed form (Blinn's):
/// with the matrix split into a similarity and an anti-similarity part,
/// `σ1 = |similarity| + |anti-similarity|` and `σ2 = |det| / σ1` (not their difference, which
/// cancels when `σ2 ≪ σ1`).
///
/// Non-finite entries give non-finite values; the zero matrix gives `(0, 0)`.
///
/// # Accuracy
/// Both values within `1e-13·σ1` of the exact singular values (a few f64 roundings);
/// `crates/barytex-uv/tests/distortion.rs::singular_values_match_their_construction` checks it on matrices built
/// from known rotations and scales.
///
/// ```
/// use barytex_uv::distortion::singular_values;
/// use glam::DMat2;
///
/// // A rotation by 30° after scaling x by 3: singular values 3 and 1.
/// let m = DMat2::from_angle(0.5236) * DMat2::from_diagonal(glam::DVec2::new(3.0, 1.0));
/// let (s1, s2) = singular_values(m);
/// assert!((s1 - 3.0).abs() < 1e-12 && (s2 - 1.0).abs() < 1e-12);
/// ```
#[must_use]
pub fn singular_values(m: DMat2) -> (f64, f64) {
    // Columns are x_axis and y_axis: m = [[a, b], [c, d]] in row form.
    let (a, c, b, d) = (m.x_axis.x, m.x_axis.y, m.y_axis.x, m.y_axis.y);
    let similarity = f64::hypot((a + d) / 2.0, (c - b) / 2.0);
    let anti = f64::hypot((a - d) / 2.0, (c + b) / 2.0);
    let s1 = similarity + anti;
    if s1 == 0.0 {
        return (0.0, 0.0);
    }
    let det = a.mul_add(d, -(b * c));
    (s1, (det.abs() / s1).min(s1))
}

/// One triangle's distortion: the singular values of its surface → uv Jacobian, and its areas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleDistortion {
    /// The larger singular value `σ1` (uv length per unit surface length, along the most
    /// stretched direction).
    pub sigma_max: f64,
    /// The smaller singular value `σ2`.
    pub sigma_min: f64,
    /// The triangle's area on the surface.
    pub area_3d: f64,
    /// Its area in uv (`σ1σ2·area_3d`).
    pub area_uv: f64,
}

impl TriangleDistortion {
    /// Angle distortion `σ1/σ2` (1 = conformal; `∞` for a degenerate uv triangle).
    #[must_use]
    pub fn angle(&self) -> f64 {
        if self.sigma_min == 0.0 {
            f64::INFINITY
        } else {
            self.sigma_max / self.sigma_min
        }
    }

    /// The area ratio `σ1σ2 = A_uv / A_3d`.
    #[must_use]
    pub fn area_ratio(&self) -> f64 {
        self.sigma_max * self.sigma_min
    }
}

/// The distortion of the triangle `p` (surface) mapped affinely to `uv`, computed in f64, or
/// `None` when `p` is degenerate (zero area relative to its edges) or anything is non-finite.
///
/// # Accuracy
/// Computed in f64 from the f32 inputs, so the error is the inputs' own rounding, which grows
/// with the coordinates' size over the triangle's (f32 `ε` times that ratio). For a triangle
/// with angles ≥ 20° placed within 10 edge lengths of the origin, with uvs an affine map
/// (`σ1 ≤ 10`, `σ2 ≥ σ1/20`) of it plus `(½, ½)`, both rounded to f32, `σ1` and `σ2` are within
/// `1e-5·σ1` of that map's singular values (measured: `1.35e-6·σ1` over 2 million random
/// cases; `crates/barytex-uv/tests/distortion.rs::triangle_singular_values_of_a_known_affine_map`).
///
/// ```
/// use barytex_uv::distortion::triangle_distortion;
/// use glam::{Vec2, Vec3};
///
/// // A unit right triangle mapped to half its size in u only.
/// let d = triangle_distortion(
///     [Vec3::ZERO, Vec3::X, Vec3::Y],
///     [Vec2::ZERO, Vec2::new(0.5, 0.0), Vec2::new(0.0, 1.0)],
/// )
/// .expect("non-degenerate");
/// assert_eq!((d.sigma_max, d.sigma_min), (1.0, 0.5));
/// assert_eq!(d.angle(), 2.0);
/// ```
#[must_use]
pub fn triangle_distortion(p: [Vec3; 3], uv: [Vec2; 3]) -> Option<TriangleDistortion> {
    let p = p.map(Vec3::as_dvec3);
    let uv = uv.map(Vec2::as_dvec2);
    if !p.iter().all(|q| q.is_finite()) || !uv.iter().all(|q| q.is_finite()) {
        return None;
    }
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let normal = e1.cross(e2);
    let (l1, l2) = (e1.length(), e2.length());
    if normal.length() <= f64::EPSILON * l1 * l2 || l1 == 0.0 || l2 == 0.0 {
        return None;
    }
    // The triangle in its own plane: e1 along x, e2 in the upper half plane.
    let x = e1 / l1;
    let y = normal.cross(e1).normalize();
    let local = DMat2::from_cols(DVec2::new(l1, 0.0), DVec2::new(e2.dot(x), e2.dot(y)));
    let texture = DMat2::from_cols(uv[1] - uv[0], uv[2] - uv[0]);
    let area_3d = l1 * e2.dot(y) / 2.0;
    if area_3d.is_nan() || area_3d <= 0.0 {
        return None;
    }
    let jacobian = texture * local.inverse();
    let (sigma_max, sigma_min) = singular_values(jacobian);
    if !(sigma_max.is_finite() && sigma_min.is_finite()) {
        return None;
    }
    let area_uv = texture.determinant().abs() / 2.0;
    Some(TriangleDistortion {
        sigma_max,
        sigma_min,
        area_3d,
        area_uv,
    })
}

/// The area distortion `max(ρ, 1/ρ)` of a triangle with area ratio `ratio` in a mesh of mean ratio
/// `mean` (`ρ = ratio/mean`; `∞` for a zero ratio).
#[must_use]
pub fn area_distortion(ratio: f64, mean: f64) -> f64 {
    let rho = ratio / mean;
    if rho == 0.0 {
        f64::INFINITY
    } else {
        rho.max(rho.recip())
    }
}

/// A mesh's distortion: area-weighted means (weights are the triangles' surface areas) and
/// maxima of the per-triangle angle and area distortion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshDistortion {
    /// Triangles measured.
    pub triangles: usize,
    /// Triangles left out (degenerate on the surface, non-finite, or indices out of range).
    pub skipped: usize,
    /// The mean area ratio `ΣA_uv / ΣA_3d`, the reference of the area distortion.
    pub mean_area_ratio: f64,
    /// Area-weighted mean of `σ1/σ2`.
    pub angle_mean: f64,
    /// Largest `σ1/σ2`.
    pub angle_max: f64,
    /// Area-weighted mean of the area distortion `max(ρ, 1/ρ)`.
    pub area_mean: f64,
    /// Largest area distortion.
    pub area_max: f64,
}

impl MeshDistortion {
    /// Measures every triangle of `mesh`; `None` when no triangle could be measured or the uv
    /// area is zero.
    ///
    /// ```
    /// use barytex_uv::distortion::MeshDistortion;
    ///
    /// let d = MeshDistortion::of(&barytex_uv::mesh::plane(4, 4).expect("valid")).expect("measurable");
    /// assert!((d.area_max - 1.0).abs() < 1e-6 && (d.angle_max - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub fn of(mesh: &TriMesh) -> Option<Self> {
        let measured: Vec<TriangleDistortion> = mesh
            .indices
            .iter()
            .filter_map(|&corners| {
                let p = corners.map(|i| mesh.positions.get(i as usize).copied());
                let uv = corners.map(|i| mesh.uvs.get(i as usize).copied());
                let [Some(p0), Some(p1), Some(p2)] = p else {
                    return None;
                };
                let [Some(t0), Some(t1), Some(t2)] = uv else {
                    return None;
                };
                triangle_distortion([p0, p1, p2], [t0, t1, t2])
            })
            .collect();
        let total_3d: f64 = measured.iter().map(|t| t.area_3d).sum();
        let total_uv: f64 = measured.iter().map(|t| t.area_uv).sum();
        let positive = |x: f64| x > 0.0 && x.is_finite();
        if measured.is_empty() || !positive(total_uv) || !positive(total_3d) {
            return None;
        }
        let mean = total_uv / total_3d;
        let (mut angle_sum, mut angle_max, mut area_sum, mut area_max) =
            (0.0, 1.0_f64, 0.0, 1.0_f64);
        for t in &measured {
            let (angle, area) = (t.angle(), area_distortion(t.area_ratio(), mean));
            angle_sum += angle * t.area_3d;
            area_sum += area * t.area_3d;
            angle_max = angle_max.max(angle);
            area_max = area_max.max(area);
        }
        Some(Self {
            triangles: measured.len(),
            skipped: mesh.indices.len() - measured.len(),
            mean_area_ratio: mean,
            angle_mean: angle_sum / total_3d,
            angle_max,
            area_mean: area_sum / total_3d,
            area_max,
        })
    }

    /// How many times more *excess* area distortion (`area_mean − 1`) this mesh has than
    /// `other` (`∞` when only `other` has none, NaN when neither has any).
    #[must_use]
    pub fn area_excess_ratio(&self, other: &Self) -> f64 {
        (self.area_mean - 1.0) / (other.area_mean - 1.0)
    }
}
