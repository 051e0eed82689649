//! The sampler seam (pbrt's chain: mapping → **sampler** → colour): a texture coordinate with its
//! screen-space derivatives, or an explicit level of detail, in; a filtered colour out.
//!
//! Image textures, procedural textures and the supersampled reference all implement [`Sampler`],
//! so every filter can be measured against the same ground truth.

mod anisotropic;
mod compare;
mod cubic;
pub mod descriptor;
mod ewa;
mod level_filters;
pub mod lod;
pub(crate) mod texel_fetch;
mod texture_sampler;

use glam::{Vec2, Vec4};

pub use descriptor::{
    AddressMode, AnisotropicFilter, BorderColor, CompareFunction, CubicKernel, FilterMode,
    MipmapFilterMode, SamplerDescriptor,
};
pub use texture_sampler::TextureSampler;

/// Anything that turns a texture coordinate into a filtered linear-light colour.
///
/// Colours are linear light with **straight** alpha. Implementations document what NaN or
/// infinite coordinates give (never a panic).
pub trait Sampler {
    /// The colour filtered over the footprint of a pixel whose texture coordinate is `uv` and whose
    /// neighbours one pixel to the right and one pixel down are at `uv + ddx` and `uv + ddy`.
    #[must_use]
    fn sample(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4;

    /// The colour at an explicit level of detail (`lod` 0 = the base level; each +1 halves the
    /// resolution).
    #[must_use]
    fn sample_level(&self, uv: Vec2, lod: f32) -> Vec4;
}
