//! Render targets: linear f32 colour (premultiplied inside, straight alpha outside) and depth,
//! with one or more samples per pixel, stored tile by tile.
//!
//! The buffers are laid out in [`TILE`]² blocks (row-major inside a block, samples of a pixel
//! together), so each parallel tile of a draw owns one contiguous slice: no copy in or out.

use barytex_texture::{Limits, Rgba32f, Srgba8, Texel, Texture2d, TextureError};
use glam::Vec4;

use crate::samples::SamplePattern;

/// Tile side in pixels: the unit of parallel work and of the buffers' layout.
pub const TILE: u32 = 64;

/// A colour buffer in linear light and a depth buffer of the same size, with
/// [`samples`](Self::samples) per pixel.
///
/// Colours are stored premultiplied (so blending "over" is one multiply-add); every accessor
/// returns straight alpha, resolved (averaged over the samples) where the target is
/// multisampled.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    width: u32,
    height: u32,
    tiles_x: u32,
    pattern: SamplePattern,
    samples: u32,
    pub(crate) color: Vec<Vec4>,
    pub(crate) depth: Vec<f32>,
    /// Pixels that may be written (`None`: all): one flag per pixel, tile layout.
    pub(crate) mask: Option<Vec<bool>>,
}

impl Framebuffer {
    /// A `width × height` target with one sample per pixel (at its centre), cleared to `clear`
    /// (straight alpha) and depth 1, under `limits` (20 bytes per pixel).
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn new(
        width: u32,
        height: u32,
        clear: Vec4,
        limits: &Limits,
    ) -> Result<Self, TextureError> {
        Self::multisampled(width, height, SamplePattern::CENTRE, clear, limits)
    }

    /// A target with the samples of `pattern` in every pixel (20 bytes per sample): MSAA when
    /// the pipeline shades once per pixel, supersampling when it shades per sample
    /// ([`PipelineState::sample_shading`](crate::PipelineState::sample_shading)).
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, SamplePattern};
    /// use barytex_texture::Limits;
    /// use glam::Vec4;
    ///
    /// let fb = Framebuffer::multisampled(64, 48, SamplePattern::Standard { count: 4 },
    ///     Vec4::new(0.0, 0.0, 0.0, 1.0), &Limits::default())?;
    /// assert_eq!(fb.samples(), 4);
    /// assert_eq!(fb.pixel(10, 10), Some(Vec4::new(0.0, 0.0, 0.0, 1.0)));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    ///
    /// # Errors
    /// An invalid pattern ([`SamplePattern::validate`]), a zero side, a size beyond the limits,
    /// or a failed allocation.
    pub fn multisampled(
        width: u32,
        height: u32,
        pattern: SamplePattern,
        clear: Vec4,
        limits: &Limits,
    ) -> Result<Self, TextureError> {
        pattern.validate()?;
        let samples = pattern.count();
        let bytes = limits.check(width, height, 20 * samples as usize)?;
        let tiles_x = width.div_ceil(TILE);
        let tiles_y = height.div_ceil(TILE);
        let pixels = tiles_x as usize * tiles_y as usize * (TILE * TILE) as usize;
        let n = pixels * samples as usize;
        let mut color = Vec::new();
        let mut depth = Vec::new();
        color
            .try_reserve_exact(n)
            .and_then(|()| depth.try_reserve_exact(n))
            .map_err(|_| TextureError::OutOfMemory { bytes })?;
        color.resize(n, premultiply(clear));
        depth.resize(n, 1.0);
        Ok(Self {
            width,
            height,
            tiles_x,
            pattern,
            samples,
            color,
            depth,
            mask: None,
        })
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Samples per pixel.
    #[must_use]
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// Where the samples lie.
    #[must_use]
    pub fn pattern(&self) -> SamplePattern {
        self.pattern
    }

    pub(crate) fn tiles_x(&self) -> u32 {
        self.tiles_x
    }

    /// Index of pixel (x, y)'s first sample (no bounds check).
    #[inline]
    pub(crate) fn pixel_index(&self, x: u32, y: u32) -> usize {
        let tile = (y / TILE) as usize * self.tiles_x as usize + (x / TILE) as usize;
        let local = (y % TILE * TILE + x % TILE) as usize;
        tile * (TILE * TILE) as usize + local
    }

    /// Pixel (x, y) in linear light, straight alpha, averaged over its samples; `None` outside.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> Option<Vec4> {
        (x < self.width && y < self.height).then(|| unpremultiply(self.resolved(x, y)))
    }

    /// The premultiplied mean of pixel (x, y)'s samples.
    pub(crate) fn resolved(&self, x: u32, y: u32) -> Vec4 {
        let s = self.samples as usize;
        let i = self.pixel_index(x, y) * s;
        let sum: Vec4 = self.color[i..i + s].iter().sum();
        sum / s as f32
    }

    /// The depth at pixel (x, y) (its first sample); `None` outside.
    #[must_use]
    pub fn depth(&self, x: u32, y: u32) -> Option<f32> {
        (x < self.width && y < self.height)
            .then(|| self.depth[self.pixel_index(x, y) * self.samples as usize])
    }

    /// Clears every sample to `color` (straight alpha) and depth 1; the mask stays.
    pub fn clear(&mut self, color: Vec4) {
        self.color.fill(premultiply(color));
        self.depth.fill(1.0);
    }

    /// Restricts writes to the pixels where `keep(x, y)` holds (a stencil-like mask: masked
    /// pixels are neither shaded nor written); `None` lifts the restriction.
    pub fn set_mask(&mut self, keep: Option<&dyn Fn(u32, u32) -> bool>) {
        self.mask = keep.map(|keep| {
            let mut mask = vec![false; self.color.len() / self.samples as usize];
            for y in 0..self.height {
                for x in 0..self.width {
                    mask[self.pixel_index(x, y)] = keep(x, y);
                }
            }
            mask
        });
    }

    /// The colour buffer as a linear f32 texture (straight alpha, resolved).
    ///
    /// # Errors
    /// A failed allocation.
    pub fn to_rgba32f(&self) -> Result<Texture2d<Rgba32f>, TextureError> {
        Texture2d::from_fn_with_limits(self.width, self.height, &Limits::UNLIMITED, |x, y| {
            Rgba32f::from_linear(unpremultiply(self.resolved(x, y)))
        })
    }

    /// The colour buffer encoded as 8-bit sRGB (correctly rounded, resolved).
    ///
    /// # Errors
    /// A failed allocation.
    pub fn to_srgba8(&self) -> Result<Texture2d<Srgba8>, TextureError> {
        Texture2d::from_fn_with_limits(self.width, self.height, &Limits::UNLIMITED, |x, y| {
            Srgba8::from_linear(unpremultiply(self.resolved(x, y)))
        })
    }
}

pub(crate) fn premultiply(c: Vec4) -> Vec4 {
    (c.truncate() * c.w).extend(c.w)
}

pub(crate) fn unpremultiply(c: Vec4) -> Vec4 {
    if c.w > 0.0 {
        let rgb = c.truncate() / c.w;
        if rgb.is_finite() {
            return rgb.extend(c.w);
        }
    }
    Vec4::new(0.0, 0.0, 0.0, c.w.max(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tile_layout_is_a_bijection_onto_the_padded_buffer() {
        let fb = Framebuffer::new(130, 70, Vec4::ZERO, &Limits::default()).expect("small");
        let mut seen = vec![false; fb.color.len()];
        for y in 0..70 {
            for x in 0..130 {
                let i = fb.pixel_index(x, y);
                assert!(!seen[i]);
                seen[i] = true;
            }
        }
        assert_eq!(fb.color.len(), 3 * 2 * 64 * 64);
    }
}
