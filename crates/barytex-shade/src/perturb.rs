//! Normal perturbation before lighting (Blinn 1978; Buss, *3D Computer Graphics*, 2003, §V.2;
//! S. Schaefer's *Shading/Texturing* slides): normal maps (tangent-space XYZ stored
//! as RGB) and bump maps (a height field whose slope tilts the normal). Both need the normal per
//! pixel — Phong shading, not Gouraud.

use barytex_uv::TriMesh;
use glam::{Vec2, Vec3, Vec4};

/// A normal-map texel (linear RGB in `[0, 1]`) as a tangent-space vector: `2c − 1`.
///
/// Store normal maps in a **linear** format (`Rgba8`, not `Srgba8`): sRGB decoding would bend the
/// vectors. `(0.5, 0.5, 1)` decodes to the unperturbed `(0, 0, 1)`.
///
/// ```
/// use barytex_shade::decode_normal;
/// use glam::Vec3;
/// assert_eq!(decode_normal(Vec3::new(0.5, 0.5, 1.0)), Vec3::Z);
/// ```
#[must_use]
#[inline]
pub fn decode_normal(rgb: Vec3) -> Vec3 {
    rgb * 2.0 - Vec3::ONE
}

/// The world-space normal for the tangent-space normal `m` (x along the tangent, y along the
/// bitangent `w·(n × t)`, z along `n`; glTF and barytex-uv meshes: `+y` is up in the image),
/// with the tangent re-orthogonalized against `n` (Gram–Schmidt).
///
/// # Special values
/// A zero, non-finite or normal-parallel tangent, or a zero or non-finite `m`, leave `n`
/// unchanged; `w = 0` counts as `+1`.
///
/// ```
/// use barytex_shade::perturb_normal;
/// use glam::{Vec3, Vec4};
///
/// let n = Vec3::Y;
/// let t = Vec4::new(1.0, 0.0, 0.0, 1.0);
/// // (0, 0, 1) is "no change".
/// assert_eq!(perturb_normal(n, t, Vec3::Z), n);
/// // Tilting towards +x in tangent space tilts along the tangent.
/// let tilted = perturb_normal(n, t, Vec3::new(1.0, 0.0, 1.0));
/// assert!((tilted - Vec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-6);
/// ```
#[must_use]
pub fn perturb_normal(n: Vec3, tangent: Vec4, m: Vec3) -> Vec3 {
    let Some(n) = n.try_normalize() else {
        return n;
    };
    let t = tangent.truncate();
    let Some(t) = (t - n * n.dot(t)).try_normalize() else {
        return n;
    };
    if !m.is_finite() {
        return n;
    }
    let w = if tangent.w < 0.0 { -1.0 } else { 1.0 };
    let b = n.cross(t) * w;
    (t * m.x + b * m.y + n * m.z).try_normalize().unwrap_or(n)
}

/// Bump mapping on any surface from screen-space derivatives alone (Mikkelsen's surface
/// gradient, 2010): `dpdx`, `dpdy` are the position's change per pixel right and down, `dhdx`,
/// `dhdy` the height's. The result is the normal of the surface displaced by the height along
/// `n` (to first order).
///
/// # Special values
/// A zero height gradient returns `n` (normalized); degenerate derivatives (a surface seen edge
/// on) or non-finite input return `n` unchanged.
///
/// # Accuracy
/// On a plane the result is the exact normal of the displaced plane `h(x, y)`,
/// `(−h_x, −h_y, 1)/|…|`, within 4e-7 (`tests/texturing.rs::bump_on_a_plane_is_exact`).
///
/// ```
/// use barytex_shade::bump_normal;
/// use glam::Vec3;
/// // A flat height field leaves the normal alone.
/// let n = bump_normal(Vec3::Z, Vec3::X * 0.01, Vec3::Y * 0.01, 0.0, 0.0);
/// assert_eq!(n, Vec3::Z);
/// ```
#[must_use]
pub fn bump_normal(n: Vec3, dpdx: Vec3, dpdy: Vec3, dhdx: f32, dhdy: f32) -> Vec3 {
    let r1 = dpdy.cross(n);
    let r2 = n.cross(dpdx);
    let det = dpdx.dot(r1);
    if det == 0.0 || !det.is_finite() || !dhdx.is_finite() || !dhdy.is_finite() {
        return n;
    }
    let gradient = det.signum() * (r1 * dhdx + r2 * dhdy);
    (n * det.abs() - gradient).try_normalize().unwrap_or(n)
}

/// A scalar height over texture space, for bump mapping.
pub trait HeightField {
    /// The height at `uv` (in the surface's units, before the bump scale).
    fn height(&self, uv: Vec2) -> f32;
}

impl<F: Fn(Vec2) -> f32> HeightField for F {
    fn height(&self, uv: Vec2) -> f32 {
        self(uv)
    }
}

/// MikkTSpace tangents (`xyz` unit, `w = ±1` glTF handedness) for `mesh`'s positions, normals
/// and uvs, via the `bevy_mikktspace` crate (a safe port of Mikkelsen's reference implementation,
/// bit-identical to it on x86) — what glTF asks for when a normal-mapped mesh has no
/// tangents. The uvs are handed over as `(u, 1 − v)` so that `w·(n × t)` points up in the image
/// (decreasing `v`), the convention of glTF and of barytex-uv's meshes.
///
/// Returns `None` when the mesh has no triangles, mismatched attribute counts, an index out of
/// range, or when MikkTSpace fails. A vertex MikkTSpace finds no tangent for (only degenerate
/// faces around it) gets the reference implementation's default, `(1, 0, 0, −1)`.
///
/// ```
/// let sphere = barytex_uv::mesh::sphere(16, 8).expect("valid");
/// let tangents = barytex_shade::generate_tangents(&sphere).expect("a regular mesh");
/// assert_eq!(tangents.len(), sphere.positions.len());
/// ```
#[must_use]
pub fn generate_tangents(mesh: &TriMesh) -> Option<Vec<Vec4>> {
    let n = mesh.positions.len();
    if mesh.indices.is_empty()
        || mesh.normals.len() != n
        || mesh.uvs.len() != n
        || mesh.indices.iter().flatten().any(|&i| i as usize >= n)
    {
        return None;
    }
    struct Geometry<'a> {
        mesh: &'a TriMesh,
        tangents: Vec<Vec4>,
    }
    impl Geometry<'_> {
        fn index(&self, face: usize, vert: usize) -> usize {
            self.mesh.indices[face][vert] as usize
        }
    }
    impl bevy_mikktspace::Geometry for Geometry<'_> {
        fn num_faces(&self) -> usize {
            self.mesh.indices.len()
        }
        fn num_vertices_of_face(&self, _face: usize) -> usize {
            3
        }
        fn position(&self, face: usize, vert: usize) -> [f32; 3] {
            self.mesh.positions[self.index(face, vert)].to_array()
        }
        fn normal(&self, face: usize, vert: usize) -> [f32; 3] {
            self.mesh.normals[self.index(face, vert)].to_array()
        }
        fn tex_coord(&self, face: usize, vert: usize) -> [f32; 2] {
            let uv = self.mesh.uvs[self.index(face, vert)];
            [uv.x, 1.0 - uv.y]
        }
        fn set_tangent(
            &mut self,
            tangent_space: Option<bevy_mikktspace::TangentSpace>,
            face: usize,
            vert: usize,
        ) {
            let i = self.index(face, vert);
            let tangent = tangent_space.unwrap_or_default().tangent_encoded();
            self.tangents[i] = Vec4::from_array(tangent);
        }
    }
    let mut geometry = Geometry {
        mesh,
        tangents: vec![Vec4::ZERO; n],
    };
    bevy_mikktspace::generate_tangents(&mut geometry)
        .ok()
        .map(|()| geometry.tangents)
}
