//! Render targets: linear f32 colour (premultiplied inside, straight alpha outside) and depth,
//! with one or more samples per pixel, stored tile by tile.
//!
//! The buffers are laid out in [`TILE`]² blocks (row-major inside a block, samples of a pixel
//! together), so each parallel tile of a draw owns one contiguous slice: no copy in or out.

#[cfg(feature = "texture")]
use barytex_texture::{Limits, Rgba32f, Srgba8, Texel, Texture2d, TextureError};
use glam::Vec4;

use crate::error::{RasterError, TargetLimits, try_filled, try_filled_parallel};
use crate::format::{ColorFormat, LinearRgba32f};
use crate::samples::SamplePattern;

/// Tile side in pixels: the unit of parallel work and of the buffers' layout.
pub const TILE: u32 = 64;

/// A colour buffer and a depth buffer of the same size, with [`samples`](Self::samples) per
/// pixel; the colour stored in format `C` (a [`ColorFormat`]).
///
/// The default format, [`LinearRgba32f`], stores linear light premultiplied (so blending
/// "over" is one multiply-add); [`Rgba8Unorm`](crate::Rgba8Unorm) stores 4 bytes per sample
/// (see [`with_format`](Self::with_format)). Every accessor returns straight alpha in linear
/// light, resolved (averaged over the samples) where the target is multisampled.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer<C: ColorFormat = LinearRgba32f> {
    width: u32,
    height: u32,
    tiles_x: u32,
    pattern: SamplePattern,
    samples: u32,
    format: C,
    pub(crate) color: Vec<C::Sample>,
    pub(crate) depth: Vec<f32>,
    /// Pixels that may be written (`None`: all): one flag per pixel, tile layout.
    pub(crate) mask: Option<Vec<bool>>,
}

impl Framebuffer {
    /// A `width × height` target with one sample per pixel (at its centre), cleared to `clear`
    /// (straight alpha) and depth 1, under `limits` (20 bytes per pixel, the sides padded to
    /// multiples of [`TILE`]).
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let clear = Vec4::new(0.25, 0.5, 1.0, 0.5);
    /// let fb = Framebuffer::new(100, 30, clear, &TargetLimits::default())?;
    /// assert_eq!((fb.width(), fb.height(), fb.samples()), (100, 30, 1));
    /// assert_eq!(fb.pixel(99, 29), Some(clear));
    /// assert_eq!(fb.depth(0, 0), Some(1.0));
    /// assert_eq!(fb.pixel(100, 0), None);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// # Errors
    /// [`RasterError::InvalidParameter`] for a zero side, [`RasterError::TooLarge`] beyond the
    /// limits, [`RasterError::OutOfMemory`] when the allocation fails.
    pub fn new(
        width: u32,
        height: u32,
        clear: Vec4,
        limits: &TargetLimits,
    ) -> Result<Self, RasterError> {
        Self::multisampled(width, height, SamplePattern::CENTRE, clear, limits)
    }

    /// A target with the samples of `pattern` in every pixel: MSAA when the pipeline shades
    /// once per pixel, supersampling when it shades per sample
    /// ([`PipelineState::sample_shading`](crate::PipelineState::sample_shading)).
    ///
    /// It allocates 20 bytes per sample (colour and depth) for the sides padded to multiples of
    /// [`TILE`], and those bytes are what `limits.max_bytes` bounds: every product is checked
    /// before anything is allocated.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, SamplePattern, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let fb = Framebuffer::multisampled(64, 48, SamplePattern::Standard { count: 4 },
    ///     Vec4::new(0.0, 0.0, 0.0, 1.0), &TargetLimits::default())?;
    /// assert_eq!(fb.samples(), 4);
    /// assert_eq!(fb.pixel(10, 10), Some(Vec4::new(0.0, 0.0, 0.0, 1.0)));
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// # Errors
    /// An invalid pattern ([`SamplePattern::validate`], checked first), a zero side
    /// ([`RasterError::InvalidParameter`]), a side or size beyond the limits
    /// ([`RasterError::TooLarge`]), or a failed allocation ([`RasterError::OutOfMemory`]).
    pub fn multisampled(
        width: u32,
        height: u32,
        pattern: SamplePattern,
        clear: Vec4,
        limits: &TargetLimits,
    ) -> Result<Self, RasterError> {
        Self::with_format(width, height, pattern, clear, limits)
    }
}

impl<C: ColorFormat> Framebuffer<C> {
    /// A target storing its colour in format `C`, with the samples of `pattern` in every pixel
    /// (as [`Framebuffer::multisampled`]), cleared to `clear` (straight alpha) and depth 1. It
    /// allocates `C`'s bytes plus 4 (the f32 depth) per sample of the padded target, and
    /// `limits.max_bytes` bounds them.
    ///
    /// A 4-byte target ([`Rgba8Unorm`](crate::Rgba8Unorm)) moves a quarter of the float
    /// target's colour bytes; [`draw`](crate::draw) writes it through the same pipeline.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, Rgba8Unorm, SamplePattern, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let clear = Vec4::new(1.0, 0.5, 0.0, 1.0);
    /// let fb = Framebuffer::<Rgba8Unorm>::with_format(100, 30, SamplePattern::CENTRE, clear,
    ///     &TargetLimits::default())?;
    /// assert_eq!(fb.stored(99, 29), Some([255, 128, 0, 255]));
    /// assert_eq!(fb.pixel(0, 0), Some(Vec4::new(1.0, 128.0 / 255.0, 0.0, 1.0)));
    /// assert_eq!(fb.depth(0, 0), Some(1.0));
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// # Errors
    /// As [`Framebuffer::multisampled`].
    pub fn with_format(
        width: u32,
        height: u32,
        pattern: SamplePattern,
        clear: Vec4,
        limits: &TargetLimits,
    ) -> Result<Self, RasterError> {
        pattern.validate()?;
        limits.check_sides(width, height)?;
        let samples = pattern.count();
        let tiles_x = width.div_ceil(TILE);
        let tiles_y = height.div_ceil(TILE);
        // Samples in the padded buffers and their bytes, in u64 with every product checked.
        let n = u64::from(tiles_x)
            .checked_mul(u64::from(tiles_y))
            .and_then(|t| t.checked_mul(u64::from(TILE * TILE)))
            .and_then(|p| p.checked_mul(u64::from(samples)));
        // Colour and an f32 depth per sample.
        let bytes = n.and_then(|n| n.checked_mul(C::BYTES + 4));
        limits.check_bytes(bytes)?;
        // The bytes fit a usize, so the sample count does.
        let (n, bytes) = (n.unwrap_or(0) as usize, bytes.unwrap_or(0));
        let out_of_memory = |_| RasterError::OutOfMemory { bytes };
        let color = try_filled_parallel(n, C::store(clear)).map_err(out_of_memory)?;
        let depth = try_filled_parallel(n, 1.0_f32).map_err(out_of_memory)?;
        Ok(Self {
            width,
            height,
            tiles_x,
            pattern,
            samples,
            format: C::default(),
            color,
            depth,
            mask: None,
        })
    }

    /// Width in pixels.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, SamplePattern, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let pattern = SamplePattern::Regular { n: 2 };
    /// let fb = Framebuffer::multisampled(3, 2, pattern, Vec4::ZERO, &TargetLimits::default())?;
    /// assert_eq!((fb.width(), fb.height()), (3, 2));
    /// assert_eq!(fb.samples(), 4);
    /// assert_eq!(fb.pattern(), pattern);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
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
        let sum: Vec4 = self.color[i..i + s].iter().map(|&c| C::load(c)).sum();
        sum / s as f32
    }

    /// The colour format.
    #[must_use]
    pub fn format(&self) -> C {
        self.format
    }

    /// Pixel (x, y)'s first sample as stored (for [`Rgba8Unorm`](crate::Rgba8Unorm), its four
    /// bytes; for the default format, the premultiplied colour); `None` outside.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, Rgba8Unorm, SamplePattern, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let half = Vec4::new(1.0, 0.0, 0.0, 0.5);
    /// let fb = Framebuffer::<Rgba8Unorm>::with_format(2, 2, SamplePattern::CENTRE, half,
    ///     &TargetLimits::default())?;
    /// assert_eq!(fb.stored(1, 1), Some([255, 0, 0, 128])); // straight alpha
    /// assert_eq!(fb.stored(2, 0), None);
    /// let float = Framebuffer::new(2, 2, half, &TargetLimits::default())?;
    /// assert_eq!(float.stored(0, 0), Some(Vec4::new(0.5, 0.0, 0.0, 0.5))); // premultiplied
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    #[must_use]
    pub fn stored(&self, x: u32, y: u32) -> Option<C::Sample> {
        (x < self.width && y < self.height)
            .then(|| self.color[self.pixel_index(x, y) * self.samples as usize])
    }

    /// The depth at pixel (x, y) (its first sample); `None` outside.
    #[must_use]
    pub fn depth(&self, x: u32, y: u32) -> Option<f32> {
        (x < self.width && y < self.height)
            .then(|| self.depth[self.pixel_index(x, y) * self.samples as usize])
    }

    /// Clears every sample to `color` (straight alpha) and depth 1; the mask stays. Followed by
    /// a [`draw`](crate::draw), [`draw_cleared`](crate::draw_cleared) gives the same target in
    /// one pass over its memory instead of two.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let mut fb = Framebuffer::new(4, 4, Vec4::ZERO, &TargetLimits::default())?;
    /// fb.clear(Vec4::new(1.0, 0.0, 0.0, 1.0));
    /// assert_eq!(fb.pixel(3, 3), Some(Vec4::new(1.0, 0.0, 0.0, 1.0)));
    /// // Fully transparent: the colour cannot be recovered from premultiplied storage.
    /// fb.clear(Vec4::new(1.0, 0.0, 0.0, 0.0));
    /// assert_eq!(fb.pixel(3, 3), Some(Vec4::ZERO));
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    pub fn clear(&mut self, color: Vec4) {
        use rayon::prelude::*;
        let color = C::store(color);
        // In tiles, in parallel on the current rayon pool.
        self.color
            .par_chunks_mut((TILE * TILE) as usize)
            .for_each(|c| c.fill(color));
        self.depth
            .par_chunks_mut((TILE * TILE) as usize)
            .for_each(|d| d.fill(1.0));
    }

    /// Restricts writes to the pixels where `keep(x, y)` holds (a stencil-like mask: masked
    /// pixels are neither shaded nor written); `None` lifts the restriction.
    ///
    /// ```
    /// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw};
    /// use glam::{Vec3, Vec4};
    ///
    /// struct White;
    /// impl Shader for White {
    ///     type Vertex = Vec3;
    ///     type Varying = f32;
    ///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), 0.0) }
    ///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> { Some(Vec4::ONE) }
    /// }
    /// // A clip-space triangle larger than the screen: covers every pixel.
    /// let big = [Vec3::new(-3.0, -3.0, 0.5), Vec3::new(3.0, -3.0, 0.5), Vec3::new(0.0, 3.0, 0.5)];
    /// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
    /// fb.set_mask(Some(&|x, _| x < 2))?;
    /// draw(&mut fb, &White, &PipelineState::default(), &big, &[0, 1, 2]);
    /// assert_eq!(fb.pixel(1, 5), Some(Vec4::ONE));
    /// assert_eq!(fb.pixel(2, 5), Some(Vec4::ZERO));
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// # Errors
    /// [`RasterError::OutOfMemory`] when the mask (one byte per pixel of the padded target)
    /// cannot be allocated; the target keeps its previous mask.
    pub fn set_mask(&mut self, keep: Option<&dyn Fn(u32, u32) -> bool>) -> Result<(), RasterError> {
        self.mask = match keep {
            None => None,
            Some(keep) => {
                let mut mask = try_filled(self.color.len() / self.samples as usize, false)?;
                for y in 0..self.height {
                    for x in 0..self.width {
                        mask[self.pixel_index(x, y)] = keep(x, y);
                    }
                }
                Some(mask)
            }
        };
        Ok(())
    }

    /// The resolved colours (straight alpha, linear light, averaged over the samples), row by
    /// row from the top: `width × height` values, pixel (x, y) at `y · width + x`. No cargo
    /// feature needed.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let fb = Framebuffer::new(3, 2, Vec4::new(0.0, 0.5, 1.0, 1.0), &TargetLimits::default())?;
    /// let rows = fb.to_linear_rgba()?;
    /// assert_eq!(rows.len(), 6);
    /// assert_eq!(rows[5], Vec4::new(0.0, 0.5, 1.0, 1.0));
    /// assert_eq!(rows.chunks_exact(3).count(), 2);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// # Errors
    /// [`RasterError::OutOfMemory`] when the 16 bytes per pixel cannot be allocated.
    pub fn to_linear_rgba(&self) -> Result<Vec<Vec4>, RasterError> {
        // Both sides passed the target's checks, and the padded buffers hold more: no overflow.
        let n = self.width as usize * self.height as usize;
        let mut out = try_filled(n, Vec4::ZERO)?;
        for (y, row) in out.chunks_exact_mut(self.width as usize).enumerate() {
            self.resolve_row(y as u32, row, |c| c);
        }
        Ok(out)
    }

    /// The colour buffer as a linear f32 texture (straight alpha, resolved). Needs the
    /// `texture` feature.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, TargetLimits};
    /// use glam::Vec4;
    ///
    /// let fb = Framebuffer::new(4, 2, Vec4::new(0.5, 0.25, 1.0, 1.0), &TargetLimits::default())?;
    /// let texture = fb.to_rgba32f()?;
    /// assert_eq!(texture.size(), (4, 2));
    /// assert_eq!(texture.linear(3, 1), fb.pixel(3, 1));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// A failed allocation.
    #[cfg(feature = "texture")]
    pub fn to_rgba32f(&self) -> Result<Texture2d<Rgba32f>, TextureError> {
        self.encoded(Rgba32f::from_linear)
    }

    /// The colour buffer encoded as 8-bit sRGB (correctly rounded, resolved). Needs the
    /// `texture` feature.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, TargetLimits};
    /// use glam::Vec4;
    ///
    /// // Linear 0.5 is sRGB 187.5/255 (IEC 61966-2-1), alpha stays linear.
    /// let fb = Framebuffer::new(2, 2, Vec4::new(0.5, 0.0, 1.0, 0.5), &TargetLimits::default())?;
    /// let image = fb.to_srgba8()?;
    /// assert_eq!(image.texel(1, 1).map(|t| t.0), Some([188, 0, 255, 128]));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// A failed allocation.
    #[cfg(feature = "texture")]
    pub fn to_srgba8(&self) -> Result<Texture2d<Srgba8>, TextureError> {
        self.encoded(Srgba8::from_linear)
    }

    /// Every pixel resolved, un-premultiplied and encoded by `encode`, rows in parallel on the
    /// current rayon pool; the result does not depend on the thread count.
    #[cfg(feature = "texture")]
    fn encoded<T: Texel>(
        &self,
        encode: impl Fn(Vec4) -> T + Sync,
    ) -> Result<Texture2d<T>, TextureError> {
        use rayon::prelude::*;
        let (w, h) = (self.width as usize, self.height as usize);
        let mut texels = Vec::new();
        texels
            .try_reserve_exact(w * h)
            .map_err(|_| TextureError::OutOfMemory {
                bytes: (w * h * core::mem::size_of::<T>()) as u64,
            })?;
        texels.resize(w * h, T::default());
        texels
            .par_chunks_mut(w.max(1))
            .enumerate()
            .for_each(|(y, row)| self.resolve_row(y as u32, row, &encode));
        Texture2d::from_texels_with_limits(self.width, self.height, texels, &Limits::UNLIMITED)
    }
}

#[inline]
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
        let fb = Framebuffer::new(130, 70, Vec4::ZERO, &TargetLimits::default()).expect("small");
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

    /// A 2 × 2 jittered target with distinct, partly transparent pixels.
    fn painted() -> Framebuffer {
        let pattern = SamplePattern::Jittered { n: 2, seed: 3 };
        let mut fb = Framebuffer::multisampled(3, 2, pattern, Vec4::ZERO, &TargetLimits::default())
            .expect("small");
        for y in 0..2 {
            for x in 0..3 {
                let i = fb.pixel_index(x, y) * 4;
                for k in 0..4 {
                    let c = Vec4::new(x as f32 / 3.0, y as f32, k as f32 / 4.0, 0.25 * k as f32);
                    fb.color[i + k] = premultiply(c);
                }
            }
        }
        fb
    }

    #[test]
    fn linear_rows_are_the_resolved_pixels_row_by_row() {
        let fb = painted();
        let rows = fb.to_linear_rgba().expect("small");
        assert_eq!(rows.len(), 6);
        for y in 0..2 {
            for x in 0..3 {
                let p = fb.pixel(x, y).expect("inside");
                assert_eq!(rows[(y * 3 + x) as usize], p);
            }
        }
        // Resolved: the mean alpha of 0, ¼, ½, ¾.
        assert_eq!(rows[4].w, 0.375);
        assert_ne!(rows[4], rows[5]);
    }

    #[test]
    fn masks_are_allocated_fallibly_and_cover_the_padding() {
        let mut fb = painted();
        fb.set_mask(Some(&|x, y| x == y)).expect("small");
        let mask = fb.mask.as_deref().expect("set");
        assert_eq!(mask.len(), 64 * 64);
        assert_eq!(mask.iter().filter(|&&m| m).count(), 2);
        fb.set_mask(None).expect("nothing to allocate");
        assert!(fb.mask.is_none());
    }

    #[cfg(feature = "texture")]
    #[test]
    fn textures_hold_the_same_pixels() {
        let fb = painted();
        let rows = fb.to_linear_rgba().expect("small");
        let linear = fb.to_rgba32f().expect("small");
        let srgb = fb.to_srgba8().expect("small");
        assert_eq!((linear.width(), linear.height()), (3, 2));
        for (i, &p) in rows.iter().enumerate() {
            let (x, y) = (i as u32 % 3, i as u32 / 3);
            assert_eq!(linear.linear(x, y), Some(p));
            assert_eq!(srgb.texel(x, y), Some(Srgba8::from_linear(p)));
        }
    }
}
