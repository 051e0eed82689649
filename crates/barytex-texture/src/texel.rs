//! Texel formats: how one texel is stored and how it converts to and from linear-light RGBA.

use glam::Vec4;
use half::f16;

use crate::srgb;

/// The storage formats, named as wgpu names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum TextureFormat {
    /// 8-bit RGBA, sRGB-encoded colour, linear alpha (`Rgba8UnormSrgb`).
    Rgba8UnormSrgb,
    /// 8-bit RGBA, linear (`Rgba8Unorm`).
    Rgba8Unorm,
    /// 8-bit single channel, linear (`R8Unorm`).
    R8Unorm,
    /// 8-bit two channels, linear (`Rg8Unorm`).
    Rg8Unorm,
    /// 16-bit float RGBA (`Rgba16Float`).
    Rgba16Float,
    /// 32-bit float RGBA (`Rgba32Float`).
    Rgba32Float,
    /// 32-bit float single channel (`R32Float`).
    R32Float,
}

impl TextureFormat {
    /// Bytes per texel.
    ///
    /// ```
    /// use barytex_texture::{Rgba16f, Srgba8, Texel, TextureFormat};
    ///
    /// assert_eq!(TextureFormat::R8Unorm.bytes_per_texel(), 1);
    /// assert_eq!(Srgba8::FORMAT.bytes_per_texel(), 4);
    /// // The size of the Rust type is the size of the stored texel.
    /// assert_eq!(Rgba16f::FORMAT.bytes_per_texel(), size_of::<Rgba16f>());
    /// ```
    #[must_use]
    pub const fn bytes_per_texel(self) -> usize {
        match self {
            Self::R8Unorm => 1,
            Self::Rg8Unorm => 2,
            Self::Rgba8UnormSrgb | Self::Rgba8Unorm | Self::R32Float => 4,
            Self::Rgba16Float => 8,
            Self::Rgba32Float => 16,
        }
    }

    /// Whether colour channels are sRGB-encoded.
    ///
    /// ```
    /// use barytex_texture::{Rgba8, Srgba8, Texel};
    ///
    /// assert!(Srgba8::FORMAT.is_srgb());
    /// assert!(!Rgba8::FORMAT.is_srgb());
    /// ```
    #[must_use]
    pub const fn is_srgb(self) -> bool {
        matches!(self, Self::Rgba8UnormSrgb)
    }
}

/// One texel of a storage format.
///
/// `to_linear` gives linear-light RGBA with straight alpha; channels the format lacks read as GPUs
/// read them: `(r, 0, 0, 1)` for one channel, `(r, g, 0, 1)` for two. `from_linear` rounds to
/// nearest (sRGB: correctly rounded through [`srgb::encode`]), clamps unorm formats to [0, 1] and
/// maps NaN to 0.
pub trait Texel: Copy + Default + Send + Sync + core::fmt::Debug + 'static {
    /// The storage format.
    const FORMAT: TextureFormat;

    /// Whether every texel decodes to finite components in [0, 1] (the 8-bit normalized
    /// formats). Then a blend of premultiplied texels with non-negative weights divided by its
    /// positive alpha is finite, and samplers leave out the finiteness test of un-premultiplying.
    const UNIT_RANGE: bool = false;

    /// This texel as linear-light RGBA, straight alpha.
    #[must_use]
    fn to_linear(self) -> Vec4;

    /// The texel nearest a linear-light RGBA colour with straight alpha.
    #[must_use]
    fn from_linear(color: Vec4) -> Self;

    /// Whether this texel's alpha is exactly 1: `to_linear().w == 1.0`, which formats without
    /// alpha always give and 8-bit formats give for the byte 255. Samplers use it to skip
    /// premultiplying textures whose every texel is opaque (multiplying by 1 changes nothing).
    #[must_use]
    #[inline]
    fn is_opaque(self) -> bool {
        self.to_linear().w == 1.0
    }

    /// [`to_linear`](Self::to_linear) of a texel known to be opaque ([`is_opaque`](Self::is_opaque)):
    /// the same value, which 8-bit formats compute without reading the alpha byte.
    #[must_use]
    #[inline]
    fn to_linear_opaque(self) -> Vec4 {
        self.to_linear()
    }

    /// The stored values as numbers, **without** colour decoding: for sRGB formats the encoded
    /// values (byte / 255), for every other format the same as [`to_linear`](Self::to_linear).
    /// Filtering these is the "sRGB-naive" path GPUs and most resizers take (kept for comparison).
    #[must_use]
    #[inline]
    fn to_stored(self) -> Vec4 {
        self.to_linear()
    }

    /// The inverse of [`to_stored`](Self::to_stored): the nearest texel to stored values.
    #[must_use]
    #[inline]
    fn from_stored(values: Vec4) -> Self {
        Self::from_linear(values)
    }
}

/// `Rgba8UnormSrgb`: sRGB colour bytes, linear alpha byte.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct Srgba8(pub [u8; 4]);

impl From<Srgba8> for [u8; 4] {
    fn from(t: Srgba8) -> Self {
        t.0
    }
}

/// `Rgba8Unorm`: linear bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct Rgba8(pub [u8; 4]);

impl From<Rgba8> for [u8; 4] {
    fn from(t: Rgba8) -> Self {
        t.0
    }
}

/// `R8Unorm`: one linear byte.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct R8(pub u8);

/// `Rg8Unorm`: two linear bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[repr(transparent)]
pub struct Rg8(pub [u8; 2]);

/// `Rgba16Float`: four half floats.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(transparent)]
pub struct Rgba16f(pub [f16; 4]);

/// `Rgba32Float`: four f32, also the linear-light working format.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(transparent)]
pub struct Rgba32f(pub [f32; 4]);

/// `R32Float`: one f32.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(transparent)]
pub struct R32f(pub f32);

/// `b / 255` for every byte, each the f32 nearest the quotient (IEEE division is correctly
/// rounded, in constant evaluation as at run time): a load instead of a division per channel.
const UNORM8: [f32; 256] = {
    let mut table = [0.0; 256];
    let mut b = 0;
    while b < 256 {
        table[b] = b as f32 / 255.0;
        b += 1;
    }
    table
};

/// Byte → [0, 1], exact division (the f32 nearest `b / 255`).
#[inline]
fn unorm8_to_f32(b: u8) -> f32 {
    UNORM8[usize::from(b)]
}

/// [0, 1] → nearest byte; NaN → 0.
#[inline]
fn f32_to_unorm8(x: f32) -> u8 {
    let x = if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) };
    // x·255 + 0.5 ∈ [0.5, 255.5]: the truncating cast rounds half up and cannot overflow.
    (x * 255.0 + 0.5) as u8
}

impl Texel for Srgba8 {
    const FORMAT: TextureFormat = TextureFormat::Rgba8UnormSrgb;
    const UNIT_RANGE: bool = true;

    // Always inlined: a trilinear lookup decodes eight texels, and a call each costs as much as
    // the decode (seen in the renderer's fragment loop, where the compiler declined to inline).
    #[inline(always)]
    fn to_linear(self) -> Vec4 {
        let [r, g, b, a] = self.0;
        Vec4::new(
            srgb::decode(r),
            srgb::decode(g),
            srgb::decode(b),
            unorm8_to_f32(a),
        )
    }

    #[inline]
    fn is_opaque(self) -> bool {
        self.0[3] == u8::MAX
    }

    #[inline(always)]
    fn to_linear_opaque(self) -> Vec4 {
        let [r, g, b, _] = self.0;
        // unorm8_to_f32(255) is exactly 1.
        Vec4::new(srgb::decode(r), srgb::decode(g), srgb::decode(b), 1.0)
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self([
            srgb::encode(c.x),
            srgb::encode(c.y),
            srgb::encode(c.z),
            f32_to_unorm8(c.w),
        ])
    }

    #[inline]
    fn to_stored(self) -> Vec4 {
        self.bytes_as_unorm()
    }

    #[inline]
    fn from_stored(values: Vec4) -> Self {
        Self(Rgba8::from_linear(values).0)
    }
}

impl Srgba8 {
    /// The stored bytes as numbers in [0, 1] (no decoding).
    #[inline]
    fn bytes_as_unorm(self) -> Vec4 {
        Rgba8(self.0).to_linear()
    }
}

impl Texel for Rgba8 {
    const FORMAT: TextureFormat = TextureFormat::Rgba8Unorm;
    const UNIT_RANGE: bool = true;

    #[inline(always)]
    fn to_linear(self) -> Vec4 {
        let [r, g, b, a] = self.0;
        Vec4::new(
            unorm8_to_f32(r),
            unorm8_to_f32(g),
            unorm8_to_f32(b),
            unorm8_to_f32(a),
        )
    }

    #[inline]
    fn is_opaque(self) -> bool {
        self.0[3] == u8::MAX
    }

    #[inline(always)]
    fn to_linear_opaque(self) -> Vec4 {
        let [r, g, b, _] = self.0;
        Vec4::new(unorm8_to_f32(r), unorm8_to_f32(g), unorm8_to_f32(b), 1.0)
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self([
            f32_to_unorm8(c.x),
            f32_to_unorm8(c.y),
            f32_to_unorm8(c.z),
            f32_to_unorm8(c.w),
        ])
    }
}

impl Texel for R8 {
    const FORMAT: TextureFormat = TextureFormat::R8Unorm;
    const UNIT_RANGE: bool = true;

    #[inline]
    fn to_linear(self) -> Vec4 {
        Vec4::new(unorm8_to_f32(self.0), 0.0, 0.0, 1.0)
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self(f32_to_unorm8(c.x))
    }
}

impl Texel for Rg8 {
    const FORMAT: TextureFormat = TextureFormat::Rg8Unorm;
    const UNIT_RANGE: bool = true;

    #[inline]
    fn to_linear(self) -> Vec4 {
        Vec4::new(unorm8_to_f32(self.0[0]), unorm8_to_f32(self.0[1]), 0.0, 1.0)
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self([f32_to_unorm8(c.x), f32_to_unorm8(c.y)])
    }
}

/// NaN → 0, so a stored texel is never NaN.
#[inline]
fn finite_or_zero(x: f32) -> f32 {
    if x.is_nan() { 0.0 } else { x }
}

impl Texel for Rgba16f {
    const FORMAT: TextureFormat = TextureFormat::Rgba16Float;

    #[inline]
    fn to_linear(self) -> Vec4 {
        let [r, g, b, a] = self.0;
        Vec4::new(r.to_f32(), g.to_f32(), b.to_f32(), a.to_f32())
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self(c.to_array().map(|x| f16::from_f32(finite_or_zero(x))))
    }
}

impl Texel for Rgba32f {
    const FORMAT: TextureFormat = TextureFormat::Rgba32Float;

    #[inline]
    fn to_linear(self) -> Vec4 {
        Vec4::from_array(self.0)
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self(c.to_array().map(finite_or_zero))
    }
}

impl Texel for R32f {
    const FORMAT: TextureFormat = TextureFormat::R32Float;

    #[inline]
    fn to_linear(self) -> Vec4 {
        Vec4::new(self.0, 0.0, 0.0, 1.0)
    }

    #[inline]
    fn from_linear(c: Vec4) -> Self {
        Self(finite_or_zero(c.x))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trips<T: Texel + PartialEq>(texel: T) {
        assert_eq!(T::from_linear(texel.to_linear()), texel, "{texel:?}");
    }

    #[test]
    fn the_unorm8_table_is_the_division() {
        for b in 0..=255_u8 {
            assert_eq!(unorm8_to_f32(b).to_bits(), (f32::from(b) / 255.0).to_bits());
        }
    }

    #[test]
    fn byte_formats_round_trip_every_value() {
        for b in 0..=255_u8 {
            round_trips(Srgba8([b, b, b, b]));
            round_trips(Rgba8([b, 255 - b, b, 255 - b]));
            round_trips(R8(b));
            round_trips(Rg8([b, 255 - b]));
        }
    }

    #[test]
    fn is_opaque_is_alpha_exactly_one() {
        for b in 0..=255_u8 {
            for t in [Srgba8([7, 8, 9, b]), Srgba8([b; 4])] {
                assert_eq!(t.is_opaque(), t.to_linear().w == 1.0, "{t:?}");
            }
            let t = Rgba8([9, 8, 7, b]);
            assert_eq!(t.is_opaque(), t.to_linear().w == 1.0, "{t:?}");
            assert!(R8(b).is_opaque() && Rg8([b, b]).is_opaque());
        }
        assert!(Rgba32f([f32::NAN, 0.0, 0.0, 1.0]).is_opaque());
        assert!(!Rgba32f([0.0, 0.0, 0.0, f32::NAN]).is_opaque());
        assert!(!Rgba16f([f16::ONE, f16::ONE, f16::ONE, f16::INFINITY]).is_opaque());
        assert!(R32f(f32::INFINITY).is_opaque());
        // The opaque decode is the decode, bit for bit.
        for b in 0..=255_u8 {
            let bits = |c: Vec4| c.to_array().map(f32::to_bits);
            let (s, r) = (
                Srgba8([b, 255 - b, b / 2, 255]),
                Rgba8([b, 255 - b, b / 2, 255]),
            );
            assert_eq!(bits(s.to_linear_opaque()), bits(s.to_linear()));
            assert_eq!(bits(r.to_linear_opaque()), bits(r.to_linear()));
        }
    }

    #[test]
    fn missing_channels_read_as_gpus_read_them() {
        assert_eq!(R8(255).to_linear(), Vec4::new(1.0, 0.0, 0.0, 1.0));
        assert_eq!(Rg8([0, 255]).to_linear(), Vec4::new(0.0, 1.0, 0.0, 1.0));
        assert_eq!(R32f(0.25).to_linear(), Vec4::new(0.25, 0.0, 0.0, 1.0));
    }

    #[test]
    fn bad_values_clamp_and_nan_is_zero() {
        assert_eq!(
            Rgba8::from_linear(Vec4::new(f32::NAN, -1.0, 2.0, f32::INFINITY)).0,
            [0, 0, 255, 255]
        );
        assert_eq!(Rgba32f::from_linear(Vec4::splat(f32::NAN)).0, [0.0; 4]);
        assert_eq!(
            Rgba16f::from_linear(Vec4::splat(f32::NAN)).to_linear(),
            Vec4::ZERO
        );
        assert_eq!(Srgba8::from_linear(Vec4::splat(f32::NAN)).0, [0; 4]);
    }

    #[test]
    fn sizes_match_the_format() {
        assert_eq!(
            core::mem::size_of::<Srgba8>(),
            Srgba8::FORMAT.bytes_per_texel()
        );
        assert_eq!(core::mem::size_of::<R8>(), R8::FORMAT.bytes_per_texel());
        assert_eq!(core::mem::size_of::<Rg8>(), Rg8::FORMAT.bytes_per_texel());
        assert_eq!(
            core::mem::size_of::<Rgba16f>(),
            Rgba16f::FORMAT.bytes_per_texel()
        );
        assert_eq!(
            core::mem::size_of::<Rgba32f>(),
            Rgba32f::FORMAT.bytes_per_texel()
        );
        assert_eq!(core::mem::size_of::<R32f>(), R32f::FORMAT.bytes_per_texel());
    }
}
