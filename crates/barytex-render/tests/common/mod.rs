//! What this crate's test binaries share.

use barytex_gltf::Scene;
use barytex_render::{RenderOptions, render};

/// Every bit of the resolved linear colour of `scene` drawn with `options`, texel by texel,
/// channel by channel: two images compare equal only if every f32 is the same.
pub(crate) fn render_bits(scene: &Scene, options: &RenderOptions) -> Vec<u32> {
    render(scene, options)
        .expect("renders")
        .image
        .to_rgba32f()
        .expect("small")
        .texels()
        .iter()
        .flat_map(|t| t.0.map(f32::to_bits))
        .collect()
}
