//! Object-space mappings, one per file: [`Planar`] (any frame), [`BoxMapping`] (face by the
//! dominant normal axis, with [`triplanar_weights`]), [`Cylindrical`] (optional planar caps),
//! [`Spherical`] (equirectangular or equal-area, [`SphereProjection`]) and [`Torus`] compute uv
//! from the position; [`TexCoordMapping`] reads a mesh's vertex uv set through an affine
//! transform (glTF's `KHR_texture_transform`).
//!
//! Every mapping evaluates its formulas in f64 from the f32 inputs
//! ([`UvMapping64::uv_and_jacobian_f64`], the reference the tests differentiate numerically) and
//! rounds once to f32 for [`PositionMapping`](crate::PositionMapping); a result that would not be finite in
//! f32 (a gradient overflowing next to an axis) is `None`.
//!
//! # From the textbook's (s, t) to (u, v)
//! The formulas of Buss, *3D Computer Graphics* (2003), ch. V, give `s` to the right and `t` **up**
//! (OpenGL). barytex's uv has `v` down (glTF, (0, 0) top-left), so every angular mapping returns
//! `u = s`, `v = 1 − t`, wrapped into `[0, 1)` where the parameter is periodic: the top of a
//! cylinder and the north pole of a sphere are at the top of the image. Angles: `θ = atan2(x, z)`
//! about the y axis (θ = 0 on +z, u increasing towards +x), so `u ∈ [0, 1)` with the seam on the
//! half-plane `x = 0, z < 0`.
//!
//! # Inverses
//! [`InverseUvMapping::point_at`] maps a texture coordinate back to the surface (the plane, the
//! cylinder's side, the sphere, the torus); `uv → point → uv` is the identity away from seams
//! and poles (tested).

mod box_mapping;
mod cylindrical;
mod planar;
mod spherical;
mod tex_coord;
mod torus;

pub use box_mapping::{BoxFace, BoxMapping, triplanar_weights};
pub use cylindrical::{CylinderCaps, Cylindrical};
pub use planar::Planar;
pub use spherical::{SphereProjection, Spherical};
pub use tex_coord::TexCoordMapping;
pub use torus::Torus;

use glam::{DVec2, DVec3, Vec2, Vec3};

use crate::{UvError, UvJacobian};

/// [`UvJacobian`] in f64: a mapping's exact-formula reference.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DUvJacobian {
    /// The texture coordinate.
    pub uv: DVec2,
    /// `∇u` with respect to the position.
    pub du: DVec3,
    /// `∇v` with respect to the position.
    pub dv: DVec3,
}

impl DUvJacobian {
    /// Rounded once to f32; `None` unless every component is finite in f32.
    #[must_use]
    pub fn to_f32(self) -> Option<UvJacobian> {
        let j = UvJacobian {
            uv: self.uv.as_vec2(),
            du: self.du.as_vec3(),
            dv: self.dv.as_vec3(),
        };
        (j.uv.is_finite() && j.du.is_finite() && j.dv.is_finite()).then_some(j)
    }
}

/// The f64 evaluation behind a mapping's [`UvMapping`](crate::UvMapping) implementation.
pub trait UvMapping64 {
    /// The texture coordinate and its gradients at `position` with unit `normal`, in f64, or
    /// `None` where the mapping is undefined (non-finite input, an axis, a pole).
    fn uv_and_jacobian_f64(&self, position: DVec3, normal: DVec3) -> Option<DUvJacobian>;
}

/// A mapping with an inverse: texture coordinate → surface point.
pub trait InverseUvMapping {
    /// The surface point whose texture coordinate is `uv`, or `None` for a non-finite `uv` or
    /// one outside the mapping's image (e.g. `v ∉ [0, 1]` on the sphere).
    fn point_at(&self, uv: Vec2) -> Option<Vec3>;
}

/// `s` in `[0, 1)` from an angle in `(−π, π]` (the f32 rounding of `1 − ε` is folded to 0 by
/// [`wrap_unit_f32`] at the end).
pub(crate) fn unit_turns(angle: f64) -> f64 {
    let s = angle / core::f64::consts::TAU;
    if s < 0.0 { s + 1.0 } else { s }
}

/// Folds a coordinate that rounded up to exactly 1.0 in f32 back to 0.0 so `u ∈ [0, 1)`.
pub(crate) fn wrap_unit_f32(mut j: UvJacobian, u: bool, v: bool) -> UvJacobian {
    if u && j.uv.x >= 1.0 {
        j.uv.x = 0.0;
    }
    if v && j.uv.y >= 1.0 {
        j.uv.y = 0.0;
    }
    j
}

/// `value` as f64 if finite, else the error naming it.
pub(crate) fn finite(what: &'static str, value: f32) -> Result<f64, UvError> {
    if value.is_finite() {
        Ok(f64::from(value))
    } else {
        Err(UvError::NonFinite { what })
    }
}

/// `value` as f64 if finite and strictly positive, else the error naming it.
pub(crate) fn positive(what: &'static str, value: f32) -> Result<f64, UvError> {
    let v = finite(what, value)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(UvError::OutOfRange { what, value: v })
    }
}
