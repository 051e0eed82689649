//! A reference software rasterizer: exact where GPUs are exact (fixed-point edge functions with
//! 8 sub-pixel bits, the top-left fill rule), correct where the peers are not (homogeneous
//! near-plane clipping, perspective-correct varyings with exact derivatives), deterministic for
//! any thread count (tiles own their pixels and draw in submission order).
//!
//! | concept | items |
//! |---|---|
//! | the seam | [`Shader`], [`Fragment`] |
//! | the draw call | [`draw`] (triangles; [`draw_cleared`] clears each tile just before drawing it), [`draw_points`], [`draw_lines`] with a [`LineTopology`] (OpenGL 4.6 §14.4, §14.5: the diamond-exit rule), [`DrawStats`] |
//! | state | [`PipelineState`], [`CullMode`], [`FrontFace`], [`Viewport`], [`Scissor`], [`DepthCompare`], [`Blend`], [`Interpolation`] |
//! | targets | [`Framebuffer`] (one or more samples per pixel, tile-major storage) under [`TargetLimits`], its colour in a [`ColorFormat`]: [`LinearRgba32f`] (16 bytes, the default), [`Rgba8Unorm`] (4 bytes), `Srgba8Unorm` (4 bytes, feature `texture`); errors are [`RasterError`]s |
//! | masks | [`mask_samples`] (the samples a draw would write, as a one-bit stencil [`SampleMask`]) and [`Framebuffer::copy_samples`] (composite another target's samples through it) |
//! | anti-aliasing | multisampled targets ([`Framebuffer::multisampled`] with a [`SamplePattern`]: regular, per-pixel jitter, the GPUs' standard positions) shaded per pixel (MSAA) or per sample; [`render_supersampled`] by accumulating passes; [`render_adaptive`] adds samples only where they disagree (up to 40) |
//! | the scanline backend (Schaefer's lecture slides) | [`scanline::scanline_fill`]: Edge Table and Active Edge List, exact with rational arithmetic |
//! | instruction sets | [`allow_avx2`], [`avx2_in_use`]: the paired fragment loop's AVX2 + FMA build, chosen at run time, the same bits as the baseline's |
//!
//! Conventions: clip space is Vulkan's/wgpu's (`−w ≤ x, y ≤ w`, `0 ≤ z ≤ w`, y up); screen
//! space is y down with pixel centres at `(x + ½, y + ½)`; counter-clockwise (in clip space) is
//! front by default.
//!
//! Dependencies: barytex-interp, glam and rayon; on x86-64 safe_arch and pulp. The optional `texture` feature adds
//! barytex-texture (without its image decoders) for `Framebuffer::to_rgba32f` and
//! `Framebuffer::to_srgba8`, which return its `Texture2d`; [`Framebuffer::to_linear_rgba`] reads
//! the resolved pixels without it.
//!
//! # References
//! - S. Schaefer, *Shading/Texturing*, lecture slides, Texas A&M University: interpolating over
//!   polygons with an Edge Table and an Active Edge List (`maxY`, `currentX`, `xIncr`,
//!   `currentF`, `fIncr`, then `dF` along each span), worked on the triangle A = (0, 0),
//!   B = (1, 5), C = (4, 2).
//! - J. D. Foley, A. van Dam, S. K. Feiner, J. F. Hughes, *Computer Graphics: Principles and
//!   Practice*, 2nd ed., Addison-Wesley, 1990, §3.6 "Filling Polygons" (the edge table and
//!   active-edge table scanline fill).
//! - S. R. Buss, *3D Computer Graphics: A Mathematical Introduction with OpenGL*, Cambridge
//!   University Press, 2003: hyperbolic (perspective-correct) interpolation, §IV.5 and Figure
//!   V.2 (affine interpolation's wrong foreshortening); regular and jittered supersampling,
//!   Figure V.7; pixels selectively supersampled up to 40 times, Figure IX.9.
//! - R. L. Cook, "Stochastic sampling in computer graphics", *ACM Transactions on Graphics* 5(1),
//!   1986 (jittered sampling).
#![forbid(unsafe_code)]

mod adaptive;
mod assemble;
mod clip;
mod cpu_features;
mod draw;
mod edge;
mod error;
mod format;
mod paired;
mod pieces;
mod primitives;
mod resolve;
mod run_bound;
mod run_depth;
mod sample_mask;
mod samples;
pub mod scanline;
mod shader;
#[cfg(target_arch = "x86_64")]
mod small_box;
mod state;
mod supersample;
mod target;
mod tile;

pub use adaptive::{AdaptiveOptions, AdaptiveStats, render_adaptive};
pub use cpu_features::{allow_avx2, avx2_in_use};
pub use draw::{DrawStats, draw, draw_cleared};
pub use edge::{MAX_COORDINATE, SUBPIXEL_BITS};
pub use error::{RasterError, TargetLimits};
#[cfg(feature = "texture")]
pub use format::Srgba8Unorm;
pub use format::{ColorFormat, LinearRgba32f, Rgba8Unorm};
pub use primitives::{LineTopology, draw_lines, draw_points};
pub use sample_mask::{SampleMask, mask_samples};
pub use samples::{MAX_GRID, MAX_SAMPLES, SamplePattern};
pub use shader::{Fragment, Shader};
pub use state::{
    Blend, CullMode, DepthCompare, FrontFace, Interpolation, PipelineState, Scissor, Viewport,
};
pub use supersample::render_supersampled;
pub use target::{Framebuffer, TILE};

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
