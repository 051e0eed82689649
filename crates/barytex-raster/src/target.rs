//! Render targets: linear f32 colour (premultiplied inside, straight alpha outside) and depth.

use barytex_texture::{Limits, Rgba32f, Srgba8, Texel, Texture2d, TextureError};
use glam::Vec4;

/// A colour buffer in linear light and a depth buffer of the same size.
///
/// Colours are stored premultiplied (so blending "over" is one multiply-add); every accessor
/// returns straight alpha.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    width: u32,
    height: u32,
    pub(crate) color: Vec<Vec4>,
    pub(crate) depth: Vec<f32>,
}

impl Framebuffer {
    /// A `width × height` target cleared to `clear` (straight alpha) and depth 1, under
    /// `limits` (20 bytes per pixel).
    ///
    /// # Errors
    /// A zero side, a size beyond the limits, or a failed allocation.
    pub fn new(
        width: u32,
        height: u32,
        clear: Vec4,
        limits: &Limits,
    ) -> Result<Self, TextureError> {
        let bytes = limits.check(width, height, 20)?;
        let n = width as usize * height as usize;
        let mut color = Vec::new();
        let mut depth = Vec::new();
        color
            .try_reserve_exact(n)
            .and_then(|()| depth.try_reserve_exact(n))
            .map_err(|_| TextureError::OutOfMemory { bytes })?;
        let c = premultiply(clear);
        color.resize(n, c);
        depth.resize(n, 1.0);
        Ok(Self {
            width,
            height,
            color,
            depth,
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

    /// Pixel (x, y) in linear light, straight alpha; `None` outside.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> Option<Vec4> {
        (x < self.width && y < self.height)
            .then(|| unpremultiply(self.color[(y * self.width + x) as usize]))
    }

    /// The depth at pixel (x, y); `None` outside.
    #[must_use]
    pub fn depth(&self, x: u32, y: u32) -> Option<f32> {
        (x < self.width && y < self.height).then(|| self.depth[(y * self.width + x) as usize])
    }

    /// The colour buffer as a linear f32 texture (straight alpha).
    ///
    /// # Errors
    /// A failed allocation.
    pub fn to_rgba32f(&self) -> Result<Texture2d<Rgba32f>, TextureError> {
        Texture2d::from_fn_with_limits(self.width, self.height, &Limits::UNLIMITED, |x, y| {
            Rgba32f::from_linear(unpremultiply(self.color[(y * self.width + x) as usize]))
        })
    }

    /// The colour buffer encoded as 8-bit sRGB (correctly rounded).
    ///
    /// # Errors
    /// A failed allocation.
    pub fn to_srgba8(&self) -> Result<Texture2d<Srgba8>, TextureError> {
        Texture2d::from_fn_with_limits(self.width, self.height, &Limits::UNLIMITED, |x, y| {
            Srgba8::from_linear(unpremultiply(self.color[(y * self.width + x) as usize]))
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
