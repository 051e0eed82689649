//! Mip-chain generation: box (2×2 for even sides, the 3-tap polyphase box for odd sides), Kaiser
//! and Lanczos; in linear light with premultiplied alpha by default, sRGB-naive as an option;
//! optional alpha-coverage preservation.

mod alpha_coverage;
mod cascade;
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
        let reduced =
            if options.filter == MipFilter::Box && w.is_power_of_two() && h.is_power_of_two() {
                cascade_levels(&base, count, linear)?
            } else {
                plane_levels(&base, count, linear, options.filter)?
            };
        for mut level in reduced {
            if let Some((reference, target)) = coverage_target {
                alpha_coverage::preserve(&mut level, reference, target);
            }
            levels.push(level);
        }
        levels.insert(0, base);
        MipChain::from_levels(levels)
    }
}

/// Levels `1..count` of a power-of-two box chain in one streaming pass (bit-identical to
/// [`plane_levels`]: `tests::cascade_equals_the_plane_path`).
fn cascade_levels<T: Texel>(
    base: &Texture2d<T>,
    count: usize,
    linear: bool,
) -> Result<Vec<Texture2d<T>>, TextureError> {
    if linear {
        cascade::reduce_chain(
            base,
            count,
            |t: T| premultiply(t.to_linear()),
            |v| T::from_linear(unpremultiply(v)),
        )
    } else {
        cascade::reduce_chain(base, count, T::to_stored, T::from_stored)
    }
}

/// Levels `1..count` of any chain, each reduced from the previous level's f32 plane.
fn plane_levels<T: Texel>(
    base: &Texture2d<T>,
    count: usize,
    linear: bool,
    filter: MipFilter,
) -> Result<Vec<Texture2d<T>>, TextureError> {
    let mut levels = Vec::new();
    let mut previous: Option<Plane> = None;
    for _ in 1..count {
        let plane = match &previous {
            None => reduce(
                &TexelSource {
                    texture: base,
                    linear,
                },
                filter,
            )?,
            Some(p) => reduce(p, filter)?,
        };
        levels.push(plane.to_texture::<T>(linear)?);
        previous = Some(plane);
    }
    Ok(levels)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Rgba32f, Srgba8};

    fn bits<T: Texel>(levels: &[Texture2d<T>]) -> Vec<Vec<[u32; 4]>> {
        levels
            .iter()
            .map(|l| {
                l.texels()
                    .iter()
                    .map(|t| t.to_stored().to_array().map(f32::to_bits))
                    .collect()
            })
            .collect()
    }

    fn random_bytes(seed: u64) -> impl FnMut() -> [u8; 8] {
        let mut state = seed | 1;
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state.to_le_bytes()
        }
    }

    /// The streaming cascade against the plane path, bit for bit, on every power-of-two shape
    /// up to 64 on a side (1×N and N×1 take the copy taps), in both colour spaces, for 8-bit
    /// sRGB and for float texels including zero, huge and non-finite values.
    #[test]
    fn cascade_equals_the_plane_path() {
        let sides = [1, 2, 4, 8, 16, 64];
        let specials = [0.0, -0.0, 1e30, -3.5, f32::INFINITY, f32::NAN, 1e-40];
        for (k, (&w, &h)) in sides
            .iter()
            .flat_map(|w| sides.iter().map(move |h| (w, h)))
            .enumerate()
        {
            let mut next = random_bytes(k as u64 + 1);
            let srgb = Texture2d::from_fn(w, h, |_, _| {
                let b = next();
                Srgba8([b[0], b[1], b[2], b[3]])
            })
            .expect("small");
            let mut next = random_bytes(k as u64 + 99);
            let float = Texture2d::from_fn(w, h, |x, y| {
                let b = next();
                let special = specials[usize::from(b[4]) % specials.len()];
                let v = f32::from(b[0]) / 37.0;
                Rgba32f(if (x + y) % 5 == 0 {
                    [special, v, v, f32::from(b[1]) / 255.0]
                } else {
                    [v, v * 0.5, 1.0 - v, f32::from(b[2]) / 255.0]
                })
            })
            .expect("small");
            let count = crate::mip_chain::full_length(w, h);
            for linear in [true, false] {
                assert_eq!(
                    bits(&cascade_levels(&srgb, count, linear).expect("small")),
                    bits(&plane_levels(&srgb, count, linear, MipFilter::Box).expect("small")),
                    "sRGB {w}×{h} linear {linear}"
                );
                assert_eq!(
                    bits(&cascade_levels(&float, count, linear).expect("small")),
                    bits(&plane_levels(&float, count, linear, MipFilter::Box).expect("small")),
                    "float {w}×{h} linear {linear}"
                );
            }
            // A shorter chain (max_levels) stops the cascade early.
            let short = count.min(2);
            assert_eq!(
                bits(&cascade_levels(&srgb, short, true).expect("small")),
                bits(&plane_levels(&srgb, short, true, MipFilter::Box).expect("small")),
            );
        }
    }
}
