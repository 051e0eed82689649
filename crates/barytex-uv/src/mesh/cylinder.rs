//! The cylinder, with optional caps.

use glam::{DVec2, DVec3};

use super::TriMesh;
use super::builder::{Builder, Vertex, at_least, fraction, turn, within_limit};
use crate::UvError;

/// The cylinder of radius 1 around the `y` axis, `y ∈ [−1, 1]`: Buss, *3D Computer Graphics*
/// (2003), ch. V, `P(θ, y) = (sin θ, y, cos θ)`, `u = θ/2π`, `v = (1 − y)/2` (top of the texture at
/// the top), `segments` columns around and `rings` rows along the axis.
///
/// With `caps`, each end is closed by a fan of `segments` triangles around a centre vertex; a cap
/// is planar-mapped onto the whole texture (`u = (x + 1)/2`, `v = (z + 1)/2` on top, `v = (1 −
/// z)/2` below so it reads unmirrored from outside), overlapping the side's uvs; its rim
/// vertices are separate from the side's (a seam) but at bit-identical positions.
///
/// # Errors
/// [`UvError::OutOfRange`] for `segments < 3` or `rings < 1`; [`UvError::TooLarge`] beyond
/// [`MAX_VERTICES`](super::MAX_VERTICES).
///
/// ```
/// let open = barytex_uv::mesh::cylinder(12, 3, false).expect("valid");
/// let closed = barytex_uv::mesh::cylinder(12, 3, true).expect("valid");
/// assert_eq!(closed.indices.len(), open.indices.len() + 2 * 12);
/// ```
pub fn cylinder(segments: u32, rings: u32, caps: bool) -> Result<TriMesh, UvError> {
    at_least("cylinder segments", segments, 3)?;
    at_least("cylinder rings", rings, 1)?;
    let side = (u128::from(segments) + 1) * (u128::from(rings) + 1);
    let cap = if caps { u128::from(segments) + 1 } else { 0 };
    let vertices = within_limit(side + 2 * cap)?;
    let mut builder = Builder::with_capacity(vertices);
    builder.grid(segments, rings, |i, j| {
        let (sin_theta, cos_theta) = turn(i, segments);
        let v = fraction(j, rings);
        let normal = DVec3::new(sin_theta, 0.0, cos_theta);
        Vertex {
            position: DVec3::new(sin_theta, 1.0 - 2.0 * v, cos_theta),
            normal,
            dpdu: DVec3::new(cos_theta, 0.0, -sin_theta),
            dpdv: DVec3::NEG_Y,
            uv: DVec2::new(fraction(i, segments), v),
        }
    });
    if caps {
        for top in [true, false] {
            let (y, normal, dpdv) = if top {
                (1.0, DVec3::Y, DVec3::Z)
            } else {
                (-1.0, DVec3::NEG_Y, DVec3::NEG_Z)
            };
            let planar = |p: DVec3| {
                let v = if top { p.z + 1.0 } else { 1.0 - p.z };
                DVec2::new((p.x + 1.0) / 2.0, v / 2.0)
            };
            let vertex = |position: DVec3| Vertex {
                position,
                normal,
                dpdu: DVec3::X,
                dpdv,
                uv: planar(position),
            };
            let centre = builder.vertex(vertex(DVec3::new(0.0, y, 0.0)));
            for i in 0..segments {
                let (sin_theta, cos_theta) = turn(i, segments);
                builder.vertex(vertex(DVec3::new(sin_theta, y, cos_theta)));
            }
            let rim = |i: u32| centre + 1 + i % segments;
            for i in 0..segments {
                if top {
                    builder.triangle([centre, rim(i), rim(i + 1)]);
                } else {
                    builder.triangle([centre, rim(i + 1), rim(i)]);
                }
            }
        }
    }
    Ok(builder.finish())
}
