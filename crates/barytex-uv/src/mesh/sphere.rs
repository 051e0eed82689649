//! The UV sphere, in either latitude mapping of Buss, *3D Computer Graphics* (2003), eqs. (V.2)
//! and (V.3).

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::{DVec2, DVec3};

use super::TriMesh;
use super::builder::{Builder, Vertex, at_least, fraction, turn, within_limit};
use crate::UvError;

/// How the sphere's latitude `φ` becomes `v` (`u = θ/2π` in both).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SphereUv {
    /// Buss's eq. (V.2), `t = φ/180° + 1/2` (equirectangular: rows of equal latitude step are
    /// equally tall in the texture); `v = 1 − t`.
    #[default]
    Equirectangular,
    /// Buss's eq. (V.3), `t = sin φ / 2 + 1/2` (Lambert's cylindrical equal-area projection);
    /// `v = 1 − t`.
    EqualArea,
}

/// The unit sphere with `segments` columns around and `rings` rows from pole to pole, equally
/// spaced in longitude and latitude, uvs equirectangular; see [`sphere_with`].
///
/// # Errors
/// As [`sphere_with`].
///
/// ```
/// let sphere = barytex_uv::mesh::sphere(16, 8).expect("valid");
/// assert!(sphere.validate().is_ok());
/// ```
pub fn sphere(segments: u32, rings: u32) -> Result<TriMesh, UvError> {
    sphere_with(segments, rings, SphereUv::Equirectangular)
}

/// The unit sphere of Buss, *3D Computer Graphics* (2003), ch. V,
/// `P(θ, φ) = (sin θ cos φ, sin φ, cos θ cos φ)`, with `segments` columns (`θ ∈ [0, 2π]`, the
/// `θ = 0` and `θ = 2π` columns duplicated) and `rings` rows (`φ` from `+π/2` at the top of the
/// texture to `−π/2`), `u = θ/2π` and `v` from `uv`.
///
/// Each pole is one vertex per column, at the column's middle `u`; the collapsed half of each
/// pole quad is left out, so a sphere has `2·segments·(rings − 1)` triangles.
///
/// # Errors
/// [`UvError::OutOfRange`] for `segments < 3` or `rings < 2`; [`UvError::TooLarge`] when
/// `(segments + 1)(rings + 1)` exceeds [`MAX_VERTICES`](super::MAX_VERTICES).
///
/// ```
/// use barytex_uv::mesh::{SphereUv, sphere_with};
///
/// let sphere = sphere_with(8, 4, SphereUv::EqualArea).expect("valid");
/// assert_eq!(sphere.indices.len(), 2 * 8 * 3);
/// // The equator sits at v = 1/2 in both mappings.
/// assert!(sphere.uvs.iter().any(|uv| uv.y == 0.5));
/// ```
pub fn sphere_with(segments: u32, rings: u32, uv: SphereUv) -> Result<TriMesh, UvError> {
    at_least("sphere segments", segments, 3)?;
    at_least("sphere rings", rings, 2)?;
    let vertices = within_limit((u128::from(segments) + 1) * (u128::from(rings) + 1))?;
    let mut builder = Builder::with_capacity(vertices);
    builder.grid(segments, rings, |i, j| {
        // Exact poles, so the collapsed pole quads are detected by equal positions.
        let (sin_phi, cos_phi) = match j {
            0 => (1.0, 0.0),
            _ if j == rings => (-1.0, 0.0),
            _ => (FRAC_PI_2 - PI * fraction(j, rings)).sin_cos(),
        };
        let pole = cos_phi == 0.0;
        let u = if pole && i < segments {
            (f64::from(i) + 0.5) / f64::from(segments)
        } else {
            fraction(i, segments)
        };
        let (sin_theta, cos_theta) = if pole {
            (TAU * u).sin_cos()
        } else {
            turn(i, segments)
        };
        let position = DVec3::new(sin_theta * cos_phi, sin_phi, cos_theta * cos_phi);
        let t = match uv {
            SphereUv::Equirectangular => 1.0 - fraction(j, rings),
            SphereUv::EqualArea => sin_phi / 2.0 + 0.5,
        };
        Vertex {
            position,
            normal: position,
            // ∂p/∂θ divided by cos φ: its direction, defined at the poles too.
            dpdu: DVec3::new(cos_theta, 0.0, -sin_theta),
            // v grows as φ falls.
            dpdv: -DVec3::new(-sin_theta * sin_phi, cos_phi, -cos_theta * sin_phi),
            uv: DVec2::new(u, 1.0 - t),
        }
    });
    Ok(builder.finish())
}
