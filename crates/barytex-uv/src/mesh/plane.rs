//! The square plane.

use glam::{DVec2, DVec3};

use super::TriMesh;
use super::builder::{Builder, Vertex, at_least, fraction, within_limit};
use crate::UvError;

/// The square `[-1, 1]²` in the `xz` plane (`y = 0`), facing `+y`, as `nu × nv` quads;
/// `u = (x + 1)/2`, `v = (z + 1)/2` (so seen from above with `−z` up, the texture reads upright).
///
/// # Errors
/// [`UvError::OutOfRange`] for a zero resolution; [`UvError::TooLarge`] beyond
/// [`MAX_VERTICES`](super::MAX_VERTICES).
///
/// ```
/// let plane = barytex_uv::mesh::plane(4, 2).expect("valid");
/// assert_eq!(plane.positions.len(), 5 * 3);
/// assert_eq!(plane.indices.len(), 4 * 2 * 2);
/// ```
pub fn plane(nu: u32, nv: u32) -> Result<TriMesh, UvError> {
    at_least("plane nu", nu, 1)?;
    at_least("plane nv", nv, 1)?;
    let vertices = within_limit((u128::from(nu) + 1) * (u128::from(nv) + 1))?;
    let mut builder = Builder::with_capacity(vertices);
    builder.grid(nu, nv, |i, j| {
        let (u, v) = (fraction(i, nu), fraction(j, nv));
        Vertex {
            position: DVec3::new(2.0 * u - 1.0, 0.0, 2.0 * v - 1.0),
            normal: DVec3::Y,
            dpdu: DVec3::X,
            dpdv: DVec3::Z,
            uv: DVec2::new(u, v),
        }
    });
    Ok(builder.finish())
}
