//! Mip-chain generation: box (2×2 for even sides, the 3-tap polyphase box for odd sides), Kaiser
//! and Lanczos; in linear light with premultiplied alpha by default, sRGB-naive as an option;
//! optional alpha-coverage preservation.

mod alpha_coverage;
mod plane;
mod polyphase_box;
mod windowed_sinc;

use glam::Vec4;

use crate::mip_chain::{full_length, level_size};
use crate::sampler::texel_fetch::{premultiply, unpremultiply};
use crate::texture2d::try_vec_with_capacity;
use crate::{Limits, MipChain, Texel, Texture2d, TextureError};

use plane::Plane;

/// The reduction filter from one level to the next.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MipFilter {
    /// The box filter, exact for every size: 2×2 averages for even sides, and for an odd side
    /// `w = 2w' + 1` the 3-tap polyphase box whose weights `((w' − i)/w, w'/w, (i + 1)/w)` integrate
    /// the source exactly over each output texel's footprint (NVIDIA, "Non-Power-of-Two
    /// Mipmapping", 2005). Preserves the mean exactly in exact arithmetic.
    #[default]
    Box,
    /// A Kaiser-windowed sinc (α = 4, 3 lobes): sharper than the box, slight ringing.
    Kaiser,
    /// Lanczos-3: the sharpest; rings at hard edges (results are clamped to the format's range).
    Lanczos3,
}

/// Which values are filtered.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum MipColorSpace {
    /// Decode sRGB to linear light, premultiply alpha, filter, un-premultiply, encode. Correct.
    #[default]
    LinearLight,
    /// Filter the stored values as they are, with straight alpha: what most resizers do. Darkens
    /// sRGB textures' minified detail and bleeds transparent texels' colour; kept so the report
    /// can show the difference.
    SrgbNaive,
}

/// How [`MipChain::generate`] builds a chain.
///
/// ```
/// use barytex_texture::{MipChain, MipColorSpace, MipOptions, Srgba8, Texture2d};
///
/// // Black and white sRGB texels: their 1×1 level depends on what is averaged.
/// let base = Texture2d::from_fn(2, 2, |x, y| {
///     Srgba8(if (x + y) % 2 == 0 { [255, 255, 255, 255] } else { [0, 0, 0, 255] })
/// })?;
/// let top = |options: &MipOptions| -> Result<Srgba8, barytex_texture::TextureError> {
///     let chain = MipChain::generate(base.clone(), options)?;
///     Ok(chain.level(1).and_then(|l| l.texel(0, 0)).unwrap_or_default())
/// };
/// // Linear light (the default): half the light, sRGB byte 188.
/// assert_eq!(top(&MipOptions::default())?, Srgba8([188, 188, 188, 255]));
/// // sRGB-naive: the mean of the bytes, visibly darker.
/// let naive = MipOptions { color_space: MipColorSpace::SrgbNaive, ..MipOptions::default() };
/// assert_eq!(top(&naive)?, Srgba8([128, 128, 128, 255]));
/// # Ok::<(), barytex_texture::TextureError>(())
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MipOptions {
    /// The reduction filter.
    pub filter: MipFilter,
    /// Which values are filtered.
    pub color_space: MipColorSpace,
    /// `Some(reference)`: scale each level's alpha so the fraction of texels with alpha ≥
    /// `reference` is the base level's (Castaño, "Computing Alpha Mipmaps", 2010) — keeps
    /// alpha-tested foliage from thinning out in the distance. A NaN or infinite reference is
    /// ignored (as `None`).
    pub alpha_coverage: Option<f32>,
    /// Stop after this many levels (base included); `None` = down to 1×1. `Some(0)` is read as
    /// `Some(1)` (the base alone); more than a complete chain gives the complete chain.
    pub max_levels: Option<usize>,
}

impl<T: Texel> MipChain<T> {
    /// The chain of `base` down to 1×1 (or `max_levels`), under the default [`Limits`].
    ///
    /// # Errors
    /// When the chain's total size exceeds the limits or an allocation fails.
    ///
    /// # Accuracy
    /// Box, linear light: each level is the exact box average of the base in f32 arithmetic on
    /// premultiplied linear values (levels are computed from the previous level's f32 values, not
    /// from the rounded texels), then rounded once to the format: the mean of every level equals the
    /// base mean within `4·ε·L·max|texel|` for level `L` in f32 formats (test
    /// `mip_generation.rs::box_preserves_the_mean`), and within one storage step for 8-bit formats.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, Srgba8, Texture2d};
    /// let base = Texture2d::from_fn(5, 3, |x, _| Srgba8([if x % 2 == 0 { 255 } else { 0 }; 4]))?;
    /// let chain = MipChain::generate(base, &MipOptions::default())?;
    /// assert_eq!(chain.len(), 3);
    /// assert_eq!(chain.level(2).map(|l| l.size()), Some((1, 1)));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    pub fn generate(base: Texture2d<T>, options: &MipOptions) -> Result<Self, TextureError> {
        Self::generate_with_limits(base, options, &Limits::default())
    }

    /// [`generate`](Self::generate) under the caller's limits (all levels' bytes count).
    ///
    /// # Errors
    /// When the chain's total size exceeds the limits or an allocation fails.
    ///
    /// ```
    /// use barytex_texture::{Limits, MipChain, MipOptions, R8, Texture2d, TextureError};
    ///
    /// // A 16×16 one-byte base: 256 bytes, and 341 with all its levels.
    /// let base = Texture2d::new(16, 16, R8(0))?;
    /// let tight = Limits { max_bytes: 300, ..Limits::default() };
    /// assert!(matches!(
    ///     MipChain::generate_with_limits(base.clone(), &MipOptions::default(), &tight),
    ///     Err(TextureError::TooLarge { what: "mip chain bytes", requested: 341, limit: 300 })
    /// ));
    /// let base_only = MipOptions { max_levels: Some(1), ..MipOptions::default() };
    /// assert_eq!(MipChain::generate_with_limits(base, &base_only, &tight)?.len(), 1);
    /// # Ok::<(), TextureError>(())
    /// ```
    pub fn generate_with_limits(
        base: Texture2d<T>,
        options: &MipOptions,
        limits: &Limits,
    ) -> Result<Self, TextureError> {
        let (w, h) = base.size();
        let count = options
            .max_levels
            .unwrap_or(usize::MAX)
            .clamp(1, full_length(w, h));
        let bytes_per_texel = T::FORMAT.bytes_per_texel() as u64;
        let total: u64 = (0..count)
            .map(|i| {
                let (lw, lh) = level_size(w, h, i);
                u64::from(lw) * u64::from(lh) * bytes_per_texel
            })
            .sum();
        if total > limits.max_bytes {
            return Err(TextureError::TooLarge {
                what: "mip chain bytes",
                requested: total,
                limit: limits.max_bytes,
            });
        }
        let linear = options.color_space == MipColorSpace::LinearLight;
        let coverage_target = options
            .alpha_coverage
            .filter(|r| r.is_finite())
            .map(|reference| (reference, alpha_coverage::coverage(&base, reference)));
        let mut levels = Vec::new();
        levels
            .try_reserve_exact(count)
            .map_err(|_| TextureError::OutOfMemory { bytes: total })?;
        let mut previous: Option<Plane> = None;
        for _ in 1..count {
            let plane = match &previous {
                None => reduce(
                    &TexelSource {
                        texture: &base,
                        linear,
                    },
                    options.filter,
                )?,
                Some(p) => reduce(p, options.filter)?,
            };
            let mut level = plane.to_texture::<T>(linear)?;
            if let Some((reference, target)) = coverage_target {
                alpha_coverage::preserve(&mut level, reference, target);
            }
            levels.push(level);
            previous = Some(plane);
        }
        levels.insert(0, base);
        MipChain::from_levels(levels)
    }
}

/// Something a reduction can read: a texture (converting on the fly) or a working plane.
pub(crate) trait Source {
    fn size(&self) -> (u32, u32);
    /// The value to filter at `(x, y)` (inside the source).
    fn get(&self, x: u32, y: u32) -> Vec4;
    /// Row `y` as values to filter: borrowed where the source stores them, else converted into
    /// `buffer` (which is resized as needed).
    fn row<'a>(&'a self, y: u32, buffer: &'a mut Vec<Vec4>) -> &'a [Vec4];
}

/// A texture read as premultiplied linear values (or, sRGB-naive, stored values).
struct TexelSource<'a, T> {
    texture: &'a Texture2d<T>,
    linear: bool,
}

impl<T: Texel> Source for TexelSource<'_, T> {
    #[inline]
    fn size(&self) -> (u32, u32) {
        self.texture.size()
    }

    #[inline]
    fn get(&self, x: u32, y: u32) -> Vec4 {
        let texel = self.texture.texels()[y as usize * self.texture.width() as usize + x as usize];
        self.convert(texel)
    }

    fn row<'a>(&'a self, y: u32, buffer: &'a mut Vec<Vec4>) -> &'a [Vec4] {
        buffer.clear();
        if let Some(row) = self.texture.row(y) {
            buffer.extend(row.iter().map(|&t| self.convert(t)));
        }
        buffer
    }
}

impl<T: Texel> TexelSource<'_, T> {
    #[inline]
    fn convert(&self, texel: T) -> Vec4 {
        if self.linear {
            premultiply(texel.to_linear())
        } else {
            texel.to_stored()
        }
    }
}

fn reduce(source: &impl Source, filter: MipFilter) -> Result<Plane, TextureError> {
    match filter {
        MipFilter::Box => polyphase_box::reduce(source),
        MipFilter::Kaiser => windowed_sinc::reduce(source, windowed_sinc::Window::Kaiser),
        MipFilter::Lanczos3 => windowed_sinc::reduce(source, windowed_sinc::Window::Lanczos3),
    }
}

impl Plane {
    /// The plane stored as texels: un-premultiplied and encoded (linear) or encoded as stored
    /// values (naive).
    fn to_texture<T: Texel>(&self, linear: bool) -> Result<Texture2d<T>, TextureError> {
        let mut texels = try_vec_with_capacity(self.values.len())?;
        if linear {
            texels.extend(
                self.values
                    .iter()
                    .map(|&v| T::from_linear(unpremultiply(v))),
            );
        } else {
            texels.extend(self.values.iter().map(|&v| T::from_stored(v)));
        }
        Texture2d::from_texels_with_limits(self.width, self.height, texels, &Limits::UNLIMITED)
    }
}
