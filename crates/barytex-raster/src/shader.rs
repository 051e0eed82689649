//! The `Shader` seam: vertex → clip position + varying; fragment → colour or discard.

use barytex_interp::Interpolate;
use glam::{UVec2, Vec4};

/// A programmable pipeline stage pair. Uniforms live in the implementing type.
///
/// ```
/// use barytex_raster::{Fragment, Shader};
/// use glam::{Vec3, Vec4};
///
/// /// Flat-coloured triangles with positions already in clip space.
/// struct Solid(Vec4);
///
/// impl Shader for Solid {
///     type Vertex = Vec3;
///     type Varying = f32; // nothing interesting to interpolate
///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) {
///         (v.extend(1.0), 0.0)
///     }
///     fn fragment(&self, _: &Fragment<f32>) -> Option<Vec4> {
///         Some(self.0)
///     }
/// }
/// ```
pub trait Shader: Sync {
    /// The per-vertex input.
    type Vertex: Sync;
    /// What the vertex stage hands to the fragment stage, interpolated across the triangle.
    type Varying: Interpolate + Send + Sync;

    /// The clip-space position `(x, y, z, w)` (visible: `−w ≤ x, y ≤ w`, `0 ≤ z ≤ w`) and the
    /// varying of a vertex.
    fn vertex(&self, vertex: &Self::Vertex) -> (Vec4, Self::Varying);

    /// The linear-light, straight-alpha colour of a fragment, or `None` to discard it.
    fn fragment(&self, fragment: &Fragment<Self::Varying>) -> Option<Vec4>;
}

/// What the fragment stage sees at one pixel.
#[derive(Clone, Copy, Debug)]
pub struct Fragment<V> {
    /// The varying at the pixel centre (perspective-correct unless the state says affine).
    pub varying: V,
    /// Its change per pixel to the right (exact derivative of the interpolation at the centre).
    pub ddx: V,
    /// Its change per pixel down.
    pub ddy: V,
    /// Depth in the viewport's depth range.
    pub depth: f32,
    /// The pixel, (0, 0) at the top-left.
    pub pixel: UVec2,
    /// Whether the triangle faces the viewer (after the pipeline's `front_face`).
    pub front_facing: bool,
}
