//! A shader that keeps another's vertex stage and makes its fragment stage a constant, so that
//! timing a pass with it measures everything but the shading.

use barytex_raster::{Fragment, Shader};
use glam::Vec4;

/// `S`'s vertex stage; a fragment stage that returns white. The varying is still interpolated
/// (the rasterizer does that before calling the fragment stage); `black_box` keeps the optimizer
/// from dropping that work.
pub(crate) struct RasterOnly<'a, S>(pub(crate) &'a S);

impl<S: Shader> Shader for RasterOnly<'_, S> {
    type Vertex = S::Vertex;
    type Varying = S::Varying;

    fn vertex(&self, vertex: &Self::Vertex) -> (Vec4, Self::Varying) {
        self.0.vertex(vertex)
    }

    fn fragment(&self, fragment: &Fragment<'_, Self::Varying>) -> Option<Vec4> {
        std::hint::black_box(&fragment.varying);
        Some(Vec4::ONE)
    }
}
