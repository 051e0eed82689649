//! Face normals and vertex normals for Gouraud and Phong shading (Gouraud 1971; Foley et al. 1990,
//! §16.2; S. Schaefer's *Shading/Texturing* slides): the vertex normal is the normalized sum of the
//! normals of the faces that share the vertex, `N_V = ΣN_k / |ΣN_k|`, optionally weighted by face
//! area or by the angle at the vertex.

use glam::Vec3;

/// How the faces around a vertex are weighted in [`vertex_normals`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NormalWeighting {
    /// The plain average of unit face normals (Schaefer's `N_V = ΣN_k / |ΣN_k|`): every face counts
    /// the same, so a mesh that is finely split on one side of a vertex leans towards that side.
    Uniform,
    /// Weighted by face area (the unnormalized cross products summed): large faces dominate.
    Area,
    /// Weighted by the face's angle at the vertex (Thürmer and Wüthrich): independent of how
    /// the surface around the vertex is split into triangles. The default.
    #[default]
    Angle,
}

/// The unit normal of the triangle `(a, b, c)` (counter-clockwise seen from the front), or `None`
/// for a degenerate or non-finite triangle.
///
/// ```
/// use barytex_shade::face_normal;
/// use glam::Vec3;
/// assert_eq!(face_normal(Vec3::ZERO, Vec3::X, Vec3::Y), Some(Vec3::Z));
/// assert_eq!(face_normal(Vec3::ZERO, Vec3::X, Vec3::X * 2.0), None);
/// ```
#[must_use]
pub fn face_normal(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    (b - a).cross(c - a).try_normalize()
}

/// Vertex normals of an indexed triangle mesh: for each vertex, the normalized weighted sum of
/// the normals of the triangles using it.
///
/// # Special values
/// A vertex used by no valid triangle, or whose face normals cancel (e.g. the apex of a corrugated
/// fan — the warning of Foley et al. 1990, §16.2, that averaged normals can mislead), gets the zero
/// vector, which lights as ambient only. Triangles with an out-of-range index, a degenerate shape
/// or a non-finite position are skipped.
///
/// ```
/// use barytex_shade::{vertex_normals, NormalWeighting};
/// use glam::Vec3;
///
/// // Two faces of a roof meeting at 90°: the ridge normal points straight up.
/// let p = [Vec3::new(-1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0), Vec3::new(1.0, 0.0, 0.0),
///          Vec3::new(0.0, 1.0, -1.0), Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 0.0, -1.0)];
/// let tris = [[0, 1, 4], [1, 3, 4], [1, 2, 5], [1, 5, 3]];
/// let n = vertex_normals(&p, &tris, NormalWeighting::Uniform);
/// assert!((n[1] - Vec3::Y).length() < 1e-6);
/// ```
#[must_use]
pub fn vertex_normals(
    positions: &[Vec3],
    triangles: &[[u32; 3]],
    weighting: NormalWeighting,
) -> Vec<Vec3> {
    let mut sums = vec![Vec3::ZERO; positions.len()];
    for tri in triangles {
        let Some(p) = tri
            .iter()
            .map(|&i| positions.get(i as usize).copied())
            .collect::<Option<Vec<Vec3>>>()
        else {
            continue;
        };
        let cross = (p[1] - p[0]).cross(p[2] - p[0]);
        let Some(unit) = cross.try_normalize() else {
            continue;
        };
        for k in 0..3 {
            let w = match weighting {
                NormalWeighting::Uniform => unit,
                NormalWeighting::Area => cross,
                NormalWeighting::Angle => {
                    let (e1, e2) = (p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
                    unit * e1.angle_between(e2)
                }
            };
            if w.is_finite() {
                sums[tri[k] as usize] += w;
            }
        }
    }
    sums.into_iter()
        .map(|s| s.try_normalize().unwrap_or(Vec3::ZERO))
        .collect()
}
