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
    ///
    /// ```
    /// use barytex_texture::procedural::{BoxFilteredCheckerboard, Checkerboard};
    /// use barytex_texture::Sampler;
    /// use glam::{Vec2, Vec4};
    ///
    /// let board = Checkerboard { even: Vec4::ONE, odd: Vec4::ZERO, checks: 8.0 };
    /// // A pixel spanning two checks each way: the point sample aliases to one colour,
    /// // the filtered checkerboard gives the true mean.
    /// let (uv, ddx, ddy) = (Vec2::splat(0.5), Vec2::new(0.25, 0.0), Vec2::new(0.0, 0.25));
    /// assert_eq!(board.sample(uv, ddx, ddy), Vec4::ONE);
    /// let mean = BoxFilteredCheckerboard(board).sample(uv, ddx, ddy);
    /// assert!((mean.x - 0.5).abs() < 1e-6);
    /// ```
    #[must_use]
    fn sample(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4;

    /// The colour at an explicit level of detail (`lod` 0 = the base level; each +1 halves the
    /// resolution).
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// // 4×1 texels 0, 1, 2, 3 (as texel values); level 1 holds 0.5, 2.5; level 2 holds 1.5.
    /// let base = Texture2d::from_fn(4, 1, |x, _| R32f(x as f32))?;
    /// let chain = MipChain::generate(base, &MipOptions::default())?;
    /// let sampler = TextureSampler::new(chain, SamplerDescriptor::default());
    /// let uv = Vec2::new(0.1, 0.5);
    /// assert_eq!(sampler.sample_level(uv, 0.0).x, 0.0);
    /// assert_eq!(sampler.sample_level(uv, 1.0).x, 0.5);
    /// assert_eq!(sampler.sample_level(uv, 2.0).x, 1.5);
    /// assert_eq!(sampler.sample_level(uv, 9.0).x, 1.5); // beyond the chain: its last level
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    fn sample_level(&self, uv: Vec2, lod: f32) -> Vec4;

    /// The colour over the footprint a [`UvMapping`](barytex_uv::UvMapping) returned: the
    /// mapping → sampler step of the chain, with the derivatives computed once by the mapping.
    ///
    /// ```
    /// use barytex_texture::procedural::Checkerboard;
    /// use barytex_texture::Sampler;
    /// use barytex_uv::mappings::TexCoordMapping;
    /// use barytex_uv::{SurfacePoint, UvMapping, UvSample};
    /// use glam::{Vec2, Vec3, Vec4};
    ///
    /// let board = Checkerboard { even: Vec4::ZERO, odd: Vec4::ONE, checks: 2.0 };
    /// let vertex = UvSample { uv: Vec2::new(0.1, 0.1), ..UvSample::default() };
    /// let point = SurfacePoint::at(Vec3::ZERO, Vec3::Z).with_tex_coords([vertex; 2]);
    /// // Offset by half a board: the top-left square's neighbour.
    /// let mapping = TexCoordMapping::khr_texture_transform(0, Vec2::new(0.5, 0.0), 0.0, Vec2::ONE);
    /// let mapped = mapping.map(&point).expect("finite");
    /// assert_eq!(board.sample_uv(&mapped), board.sample(Vec2::new(0.6, 0.1), Vec2::ZERO, Vec2::ZERO));
    /// assert_ne!(board.sample_uv(&mapped), board.sample(vertex.uv, Vec2::ZERO, Vec2::ZERO));
    /// ```
    #[must_use]
    #[inline]
    fn sample_uv(&self, mapped: &barytex_uv::UvSample) -> Vec4 {
        self.sample(mapped.uv, mapped.duvdx, mapped.duvdy)
    }
}
