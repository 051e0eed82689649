//! The torus.

use glam::{DVec2, DVec3};

use super::TriMesh;
use super::builder::{Builder, Vertex, at_least, fraction, turn, within_limit};
use crate::UvError;

/// The torus of Buss, *3D Computer Graphics* (2003), ch. V (Figure V.6), around the `y` axis, major
/// radius `major` (`R`), minor `minor` (`r`):
/// `P(θ, φ) = ((R + r cos φ) sin θ, r sin φ, (R + r cos φ) cos θ)`, `u = θ/2π`, `v = −φ/2π` (mod 1;
/// `v` grows downward across the outer equator, so the texture is unmirrored), with `segments`
/// columns around the axis and `rings` rows around the tube; both seams (`u = 0/1` and `v = 0/1`)
/// are duplicated.
///
/// # Errors
/// [`UvError::NonFinite`] for a NaN or infinite radius; [`UvError::OutOfRange`] unless
/// `R > r > 0` (the torus would cross itself), or for `segments < 3` or `rings < 3`;
/// [`UvError::TooLarge`] beyond [`MAX_VERTICES`](super::MAX_VERTICES).
///
/// ```
/// let torus = barytex_uv::mesh::torus(24, 12, 1.0, 0.25).expect("valid");
/// assert_eq!(torus.positions.len(), 25 * 13);
/// assert!(barytex_uv::mesh::torus(24, 12, 0.25, 1.0).is_err());
/// ```
pub fn torus(segments: u32, rings: u32, major: f32, minor: f32) -> Result<TriMesh, UvError> {
    for (what, value) in [("torus major radius", major), ("torus minor radius", minor)] {
        if !value.is_finite() {
            return Err(UvError::NonFinite { what });
        }
    }
    if minor <= 0.0 {
        return Err(UvError::OutOfRange {
            what: "torus minor radius",
            value: f64::from(minor),
        });
    }
    if major <= minor {
        return Err(UvError::OutOfRange {
            what: "torus major radius",
            value: f64::from(major),
        });
    }
    at_least("torus segments", segments, 3)?;
    at_least("torus rings", rings, 3)?;
    let vertices = within_limit((u128::from(segments) + 1) * (u128::from(rings) + 1))?;
    let (big, small) = (f64::from(major), f64::from(minor));
    let mut builder = Builder::with_capacity(vertices);
    builder.grid(segments, rings, |i, j| {
        let (sin_theta, cos_theta) = turn(i, segments);
        // φ = −2π v.
        let (sin_psi, cos_psi) = turn(j, rings);
        let (sin_phi, cos_phi) = (-sin_psi, cos_psi);
        let radial = DVec3::new(sin_theta, 0.0, cos_theta);
        let normal = radial * cos_phi + DVec3::Y * sin_phi;
        Vertex {
            position: radial * big + normal * small,
            normal,
            dpdu: DVec3::new(cos_theta, 0.0, -sin_theta),
            // −∂p/∂φ (v grows as φ falls), divided by r.
            dpdv: radial * sin_phi - DVec3::Y * cos_phi,
            uv: DVec2::new(fraction(i, segments), fraction(j, rings)),
        }
    });
    Ok(builder.finish())
}
