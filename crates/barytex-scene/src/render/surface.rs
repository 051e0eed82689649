//! The varying a scene shader interpolates: world position, normal, both texture coordinate
//! sets and the vertex colour.

use barytex_interp::Interpolate;
use glam::{Vec2, Vec3, Vec4};

/// What the fragment stage of a scene material reads, interpolated over the triangle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Surface {
    pub(crate) position: Vec3,
    pub(crate) normal: Vec3,
    pub(crate) uv0: Vec2,
    pub(crate) uv1: Vec2,
    pub(crate) color: Vec4,
    /// Gouraud shading's per-vertex diffuse and specular light (zero otherwise).
    pub(crate) diffuse: Vec3,
    pub(crate) specular: Vec3,
    /// World-space tangent with the bitangent sign in `w` (normal-mapped materials only).
    pub(crate) tangent: Vec4,
}

impl Interpolate for Surface {
    #[inline]
    fn scale(self, w: f32) -> Self {
        Self {
            position: self.position * w,
            normal: self.normal * w,
            uv0: self.uv0 * w,
            uv1: self.uv1 * w,
            color: self.color * w,
            diffuse: self.diffuse * w,
            specular: self.specular * w,
            tangent: self.tangent * w,
        }
    }

    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            position: self.position + o.position,
            normal: self.normal + o.normal,
            uv0: self.uv0 + o.uv0,
            uv1: self.uv1 + o.uv1,
            color: self.color + o.color,
            diffuse: self.diffuse + o.diffuse,
            specular: self.specular + o.specular,
            tangent: self.tangent + o.tangent,
        }
    }

    #[inline]
    fn lerp(self, o: Self, t: f32) -> Self {
        Self {
            position: Interpolate::lerp(self.position, o.position, t),
            normal: Interpolate::lerp(self.normal, o.normal, t),
            uv0: Interpolate::lerp(self.uv0, o.uv0, t),
            uv1: Interpolate::lerp(self.uv1, o.uv1, t),
            color: Interpolate::lerp(self.color, o.color, t),
            diffuse: Interpolate::lerp(self.diffuse, o.diffuse, t),
            specular: Interpolate::lerp(self.specular, o.specular, t),
            tangent: Interpolate::lerp(self.tangent, o.tangent, t),
        }
    }
}
