//! Texel storage, exact sRGB and texture filtering.
//!
//! Storage and filtering are separate (pbrt's and wgpu's split): a [`Texture2d`] stores texels of
//! one [`Texel`] format, a sampler descriptor says how to filter them.
//!
//! | concept | items |
//! |---|---|
//! | texel formats | [`Texel`], [`TextureFormat`], [`Srgba8`], [`Rgba8`], [`R8`], [`Rg8`], [`Rgba16f`], [`Rgba32f`], [`R32f`] |
//! | storage | [`Texture2d`], [`Limits`], [`TextureError`] |
//! | colour | [`srgb`]: exact decode table, correctly rounded encode |
//! | mip chains | [`MipChain`], [`MipChain::generate`] with [`MipOptions`] ([`MipFilter`]: box for any size, Kaiser, Lanczos-3; [`MipColorSpace`]: linear light or sRGB-naive; alpha coverage) |
//! | loading and saving (feature `image`) | [`load`]: `load_from_memory`, `load_from_path` (limits checked before decoding), `encode_png`, `save_png` |
//! | image remapping | [`remap::remap_bilinear_rgba8`] (OpenCV `remap` INTER_LINEAR with exact weights) |
//! | cube maps | [`CubeTexture`]: sampled by direction, seamless across edges and corners |
//! | arrays and volumes | [`Texture2dArray`] (Vulkan layer selection), [`Texture3d`] (trilinear volumes) |
//! | procedural textures | [`procedural`]: [`Checkerboard`](procedural::Checkerboard), [`BoxFilteredCheckerboard`](procedural::BoxFilteredCheckerboard) (exact ground truth), [`Stripes`](procedural::Stripes), [`ValueNoise`](procedural::ValueNoise) |
//! | ground truth | [`reference::SupersampledReference`]: N×N jittered samples over the footprint, N ≤ 32 |
//! | the seam | [`Sampler`], [`SamplerDescriptor`] and its enums in [`sampler`] |
//! | texel addressing (Vulkan) | [`addressing`]: [`wrap`](addressing::wrap), [`linear_taps`](addressing::linear_taps), [`nearest_index`](addressing::nearest_index) |
//!
//! Conventions: texel (0, 0) is the top-left; texture coordinate (0, 0) is the top-left corner of
//! texel (0, 0) and (1, 1) the bottom-right corner of the last texel (glTF, Vulkan). Colours handed
//! to and from [`Texel`] are **linear light, straight (not premultiplied) alpha**; filters work on
//! premultiplied linear values internally.
//!
//! # References
//! - L. Yan, *GAMES101: Introduction to Modern Computer Graphics*, Lecture 9 "Shading 3 (Texture
//!   Mapping cont.)", 2020: nearest, bilinear (two horizontal lerps, then one vertical) and
//!   bicubic magnification; a 512× supersampled image as the reference for minification; the
//!   footprint `L = max(√((du/dx)² + (dv/dx)²), √((du/dy)² + (dv/dy)²))`, `D = log₂ L`;
//!   trilinear filtering; anisotropic filtering and EWA.
//! - L. Williams, "Pyramidal parametrics", *SIGGRAPH '83* (mip maps).
//! - N. Greene, P. S. Heckbert, "Creating raster Omnimax images from multiple perspective views
//!   using the elliptical weighted average filter", *IEEE Computer Graphics and Applications*
//!   6(6), 1986; P. S. Heckbert, *Fundamentals of Texture Mapping and Image Warping*, M.S.
//!   thesis, UC Berkeley, 1989 (EWA).
//! - The Khronos Group, *Vulkan 1.3 Specification*, ch. "Image Operations": "Texel Coordinate
//!   Systems", "Scale Factor Operation, Level-of-Detail Operation and Image Level(s) Selection",
//!   "Texel Filtering"; *OpenGL 4.6 Core Profile*, §8.14 "Texture Minification" and §8.15
//!   "Texture Magnification" (separate minification and magnification filters).
//! - D. R. Peachey, "Solid texturing of complex surfaces", and K. Perlin, "An image
//!   synthesizer", both *SIGGRAPH '85* (procedural textures).
//!
//! ```
//! use barytex_texture::{Srgba8, Texel, Texture2d};
//!
//! // A 2×1 sRGB texture: black and white.
//! let texture = Texture2d::from_texels(2, 1, vec![Srgba8([0, 0, 0, 255]), Srgba8([255; 4])])?;
//! assert_eq!(texture.texel(1, 0).map(Texel::to_linear).map(|c| c.x), Some(1.0));
//! // Their linear-light mean encodes to byte 188, not to the sRGB mean 128.
//! let mean = (texture.texels()[0].to_linear() + texture.texels()[1].to_linear()) / 2.0;
//! assert_eq!(Srgba8::from_linear(mean).0[0], 188);
//! # Ok::<(), barytex_texture::TextureError>(())
//! ```
#![forbid(unsafe_code)]

pub mod addressing;
mod cube;
mod error;
mod limits;
#[cfg(feature = "image")]
pub mod load;
pub mod mip_chain;
pub mod mip_generation;
#[cfg(feature = "image")]
mod png_direct;
#[cfg(feature = "image")]
mod png_palette;
pub mod procedural;
pub mod reference;
pub mod remap;
pub mod sampler;
pub mod srgb;
mod texel;
mod texture2d;
mod volume;

pub use cube::CubeTexture;
pub use error::TextureError;
pub use limits::Limits;
pub use mip_chain::MipChain;
pub use mip_generation::{MipColorSpace, MipFilter, MipOptions};
pub use sampler::{Sampler, SamplerDescriptor, TextureSampler};
pub use texel::{R8, R32f, Rg8, Rgba8, Rgba16f, Rgba32f, Srgba8, Texel, TextureFormat};
pub use texture2d::Texture2d;
pub use volume::{Texture2dArray, Texture3d};

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
