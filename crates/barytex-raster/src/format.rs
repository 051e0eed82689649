//! Colour formats of a [`Framebuffer`](crate::Framebuffer): how one sample's colour is stored.
//!
//! [`LinearRgba32f`] (16 bytes, premultiplied linear light: exact blending, the default) and the
//! 4-byte [`Rgba8Unorm`] (straight alpha, linear bytes, as a GPU's `R8G8B8A8_UNORM` target stores
//! them) — plus, with the `texture` feature, [`Srgba8Unorm`] (sRGB-encoded colour bytes, linear
//! alpha, as `R8G8B8A8_SRGB`). Blending ("over") happens in premultiplied linear light whatever
//! the format (Vulkan 1.3 §28.1, "Blending": the destination is converted to linear before the
//! blend and back after it), so an 8-bit target rounds once per write.

use glam::Vec4;

use crate::target::{premultiply, unpremultiply};

mod sealed {
    pub trait Sealed {}
}

/// How a target stores one sample's colour; implemented by [`LinearRgba32f`], [`Rgba8Unorm`] and
/// (feature `texture`) `Srgba8Unorm` only.
///
/// ```
/// use barytex_raster::{ColorFormat, LinearRgba32f, Rgba8Unorm};
/// use glam::Vec4;
///
/// let c = Vec4::new(1.0, 0.5, 0.0, 1.0);
/// assert_eq!(Rgba8Unorm::store(c), [255, 128, 0, 255]); // 127.5 rounds up
/// assert_eq!(LinearRgba32f::store(c), c); // premultiplied: opaque colours are unchanged
/// assert_eq!(Rgba8Unorm::load([255, 0, 0, 51]), Vec4::new(0.2, 0.0, 0.0, 0.2));
/// ```
pub trait ColorFormat:
    sealed::Sealed + Copy + Default + Send + Sync + core::fmt::Debug + PartialEq + 'static
{
    /// One stored sample.
    type Sample: Copy + Send + Sync + core::fmt::Debug + PartialEq + 'static;

    /// Bytes of one stored sample.
    const BYTES: u64 = core::mem::size_of::<Self::Sample>() as u64;

    /// The sample nearest a linear-light colour with straight alpha (what a shader returns and a
    /// "replace" write stores).
    #[must_use]
    fn store(straight: Vec4) -> Self::Sample;

    /// The sample nearest a premultiplied linear-light colour (what blending and resolving
    /// produce).
    #[must_use]
    fn store_premultiplied(premultiplied: Vec4) -> Self::Sample;

    /// A sample as premultiplied linear light (what blending reads).
    #[must_use]
    fn load(sample: Self::Sample) -> Vec4;
}

/// Four f32 per sample in linear light, premultiplied by alpha: the exact working format (16
/// bytes), [`Framebuffer`](crate::Framebuffer)'s default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct LinearRgba32f;

impl sealed::Sealed for LinearRgba32f {}

impl ColorFormat for LinearRgba32f {
    type Sample = Vec4;

    #[inline]
    fn store(straight: Vec4) -> Vec4 {
        premultiply(straight)
    }

    #[inline]
    fn store_premultiplied(premultiplied: Vec4) -> Vec4 {
        premultiplied
    }

    #[inline]
    fn load(sample: Vec4) -> Vec4 {
        sample
    }
}

/// Four bytes per sample, `[r, g, b, a]`, linear values with straight alpha: byte `b` is
/// `b / 255`, and a value `v` is stored as the nearest byte, `⌊255·clamp(v, 0, 1) + ½⌋` (NaN as
/// 0) — the rounding of D3D's and Vulkan's UNORM conversion (Vulkan 1.3 §3.9.2, "Conversion
/// from Floating-Point to Normalized Fixed-Point"; barytex-texture's `Rgba8` texel rounds the
/// same way).
///
/// # Accuracy
/// A "replace" write is the colour rounded to the nearest byte per channel: half a step
/// (1/510) at most, the float target's pixel quantized, pixel for pixel, for opaque colours
/// (test `rgba8_target_is_the_float_target_quantized`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Rgba8Unorm;

impl sealed::Sealed for Rgba8Unorm {}

/// [0, 1] → nearest byte; NaN → 0.
#[inline]
pub(crate) fn unorm8(x: f32) -> u8 {
    let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
    // x·255 + 0.5 ∈ [0.5, 255.5]: the truncating cast rounds half up and cannot overflow.
    (x * 255.0 + 0.5) as u8
}

impl ColorFormat for Rgba8Unorm {
    type Sample = [u8; 4];

    #[inline]
    fn store(c: Vec4) -> [u8; 4] {
        [unorm8(c.x), unorm8(c.y), unorm8(c.z), unorm8(c.w)]
    }

    #[inline]
    fn store_premultiplied(premultiplied: Vec4) -> [u8; 4] {
        Self::store(unpremultiply(premultiplied))
    }

    #[inline]
    fn load(sample: [u8; 4]) -> Vec4 {
        premultiply(Vec4::from_array(sample.map(|b| f32::from(b) / 255.0)))
    }
}

/// Four bytes per sample, `[r, g, b, a]`: colour encoded to sRGB with barytex-texture's
/// correctly rounded encoder (IEC 61966-2-1), alpha linear, straight alpha — a GPU's
/// `R8G8B8A8_SRGB` target. Needs the `texture` feature.
///
/// # Accuracy
/// A "replace" write is `barytex_texture::Srgba8::from_linear` of the shader's colour (correctly
/// rounded; test `srgb_target_is_the_float_target_encoded`).
#[cfg(feature = "texture")]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Srgba8Unorm;

#[cfg(feature = "texture")]
impl sealed::Sealed for Srgba8Unorm {}

#[cfg(feature = "texture")]
impl ColorFormat for Srgba8Unorm {
    type Sample = [u8; 4];

    #[inline]
    fn store(c: Vec4) -> [u8; 4] {
        use barytex_texture::Texel;
        barytex_texture::Srgba8::from_linear(c).0
    }

    #[inline]
    fn store_premultiplied(premultiplied: Vec4) -> [u8; 4] {
        Self::store(unpremultiply(premultiplied))
    }

    #[inline]
    fn load(sample: [u8; 4]) -> Vec4 {
        use barytex_texture::Texel;
        premultiply(barytex_texture::Srgba8(sample).to_linear())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm_bytes_round_to_nearest_and_survive_garbage() {
        assert_eq!(unorm8(0.0), 0);
        assert_eq!(unorm8(1.0), 255);
        assert_eq!(unorm8(-3.0), 0);
        assert_eq!(unorm8(7.0), 255);
        assert_eq!(unorm8(f32::NAN), 0);
        assert_eq!(unorm8(f32::INFINITY), 255);
        // Every byte survives a round trip, and the midpoints between bytes round up. Two
        // loops: written as one over 0..=255 with `if b < 255` around the midpoint check, the
        // optimized build (rustc 1.95 and nightly, LLVM) never leaves the loop.
        for b in 0..=255_u8 {
            assert_eq!(unorm8(f32::from(b) / 255.0), b);
        }
        for b in 0..255_u8 {
            let mid = (f32::from(b) + 0.5) / 255.0;
            assert!(unorm8(mid) == b + 1 || unorm8(mid.next_down()) == b);
        }
    }

    #[test]
    fn rgba8_loads_premultiplied_and_stores_straight() {
        let s = [200, 100, 50, 128];
        let p = Rgba8Unorm::load(s);
        assert_eq!(p.w, 128.0 / 255.0);
        assert_eq!(p.x, 200.0 / 255.0 * (128.0 / 255.0));
        assert_eq!(Rgba8Unorm::store_premultiplied(p), s);
        assert_eq!(Rgba8Unorm::store_premultiplied(Vec4::ZERO), [0; 4]);
    }

    #[cfg(feature = "texture")]
    #[test]
    fn unorm_matches_the_texture_crate_and_srgb_round_trips() {
        use barytex_texture::{Rgba8, Texel};
        let mut x = 0x9E37_79B9_u32;
        for _ in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            let v = (x as f32 / u32::MAX as f32) * 1.4 - 0.2;
            let c = Vec4::new(v, 1.0 - v, v * 0.5, 1.0);
            assert_eq!(Rgba8Unorm::store(c), Rgba8::from_linear(c).0);
        }
        for b in 0..=255_u8 {
            let s = [b, 255 - b, b / 2, 255];
            assert_eq!(Srgba8Unorm::store_premultiplied(Srgba8Unorm::load(s)), s);
        }
    }
}
