//! The `UvMapping` seam: a surface point (and optionally its screen-space derivatives) → texture
//! coordinates and their derivatives.

use glam::{Vec2, Vec3};

/// A point on a surface as a mapping sees it: object-space position and unit normal, and the
/// screen-space derivatives of the position (`∂p/∂x`, `∂p/∂y` per pixel; zero when unknown).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SurfacePoint {
    /// Object-space position.
    pub position: Vec3,
    /// Unit surface normal (used by box/triplanar mappings and environment maps).
    pub normal: Vec3,
    /// `∂position/∂x` per pixel.
    pub dpdx: Vec3,
    /// `∂position/∂y` per pixel.
    pub dpdy: Vec3,
}

impl SurfacePoint {
    /// A point without screen-space derivatives.
    #[must_use]
    pub const fn at(position: Vec3, normal: Vec3) -> Self {
        Self {
            position,
            normal,
            dpdx: Vec3::ZERO,
            dpdy: Vec3::ZERO,
        }
    }

    /// A point with screen-space derivatives.
    #[must_use]
    pub const fn with_derivatives(position: Vec3, normal: Vec3, dpdx: Vec3, dpdy: Vec3) -> Self {
        Self {
            position,
            normal,
            dpdx,
            dpdy,
        }
    }
}

/// Texture coordinates and their gradients with respect to the position (the mapping's
/// Jacobian): `u` changes by `du·δp` and `v` by `dv·δp` for a small displacement `δp`, the normal
/// held fixed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UvJacobian {
    /// The texture coordinate.
    pub uv: Vec2,
    /// `∇u` with respect to the position.
    pub du: Vec3,
    /// `∇v` with respect to the position.
    pub dv: Vec3,
}

/// Texture coordinates with their screen-space derivatives, what a sampler needs to pick a level.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UvSample {
    /// The texture coordinate.
    pub uv: Vec2,
    /// `∂uv/∂x` per pixel.
    pub duvdx: Vec2,
    /// `∂uv/∂y` per pixel.
    pub duvdy: Vec2,
}

/// A mapping from surface points to texture coordinates, with derivatives.
///
/// Implementors provide [`uv_and_jacobian`](Self::uv_and_jacobian); [`map`](Self::map) applies
/// the Jacobian to the point's screen-space derivatives (the chain rule, computed once per point
/// as pbrt does) and [`uv`](Self::uv) drops the derivatives.
///
/// # Laws (checked for every mapping by the crate's tests)
/// - Total: NaN or infinite input, and points where the mapping is singular (a pole, an axis),
///   give `None`; never a panic, never a NaN inside `Some`.
/// - The Jacobian matches central finite differences of `uv` away from seams and poles.
/// - `map(p).duvdx == (du·dpdx, dv·dpdx)` and likewise for y.
pub trait UvMapping {
    /// The texture coordinate at `position` (with unit `normal`) and its gradients, or `None`
    /// where the mapping is undefined.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian>;

    /// The texture coordinate alone.
    fn uv(&self, position: Vec3, normal: Vec3) -> Option<Vec2> {
        self.uv_and_jacobian(position, normal).map(|j| j.uv)
    }

    /// Texture coordinates and their screen-space derivatives at `point`.
    fn map(&self, point: &SurfacePoint) -> Option<UvSample> {
        let j = self.uv_and_jacobian(point.position, point.normal)?;
        let sample = UvSample {
            uv: j.uv,
            duvdx: Vec2::new(j.du.dot(point.dpdx), j.dv.dot(point.dpdx)),
            duvdy: Vec2::new(j.du.dot(point.dpdy), j.dv.dot(point.dpdy)),
        };
        (sample.duvdx.is_finite() && sample.duvdy.is_finite()).then_some(sample)
    }
}
