//! Loading and saving images through the `image` crate (feature `image`), with [`Limits`]
//! checked against the header **before** any pixel is decoded.

use std::io::Cursor;
use std::path::Path;

use glam::Vec4;
use half::f16;
use image::{DynamicImage, ImageReader};

use crate::{Limits, R8, Rgba8, Rgba16f, Rgba32f, Srgba8, Texel, Texture2d, TextureError, srgb};

/// How to interpret an image's colour values. Images do not reliably say: glTF, for one, fixes
/// base colour and emissive textures as sRGB and every other texture as linear.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ColorSpace {
    /// Colour channels are sRGB-encoded (photographs, albedo/base-colour maps).
    #[default]
    Srgb,
    /// Values are linear data (normal, roughness, height, occlusion maps).
    Linear,
}

/// A loaded texture in the format closest to the file's.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum AnyTexture2d {
    /// 8-bit colour interpreted as sRGB.
    Srgba8(Texture2d<Srgba8>),
    /// 8-bit linear colour (with alpha).
    Rgba8(Texture2d<Rgba8>),
    /// 8-bit linear single channel (a greyscale data map).
    R8(Texture2d<R8>),
    /// 16-bit images, as half floats in linear light.
    Rgba16f(Texture2d<Rgba16f>),
    /// Floating-point images.
    Rgba32f(Texture2d<Rgba32f>),
}

impl AnyTexture2d {
    /// `(width, height)`.
    ///
    /// ```
    /// use barytex_texture::load::{AnyTexture2d, ColorSpace, encode_png, load_from_memory};
    /// use barytex_texture::{Limits, Srgba8, Texture2d};
    ///
    /// let png = encode_png(&Texture2d::new(3, 2, Srgba8([1, 2, 3, 255]))?)?;
    /// let loaded = load_from_memory(&png, ColorSpace::Srgb, &Limits::default())?;
    /// assert_eq!(loaded.size(), (3, 2));
    /// assert!(matches!(loaded, AnyTexture2d::Srgba8(_)));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn size(&self) -> (u32, u32) {
        match self {
            Self::Srgba8(t) => t.size(),
            Self::Rgba8(t) => t.size(),
            Self::R8(t) => t.size(),
            Self::Rgba16f(t) => t.size(),
            Self::Rgba32f(t) => t.size(),
        }
    }

    /// The texture in linear-light f32 RGBA.
    ///
    /// # Errors
    /// A failed allocation.
    ///
    /// ```
    /// use barytex_texture::load::{ColorSpace, encode_png, load_from_memory};
    /// use barytex_texture::{Limits, Rgba8, Texture2d};
    ///
    /// let png = encode_png(&Texture2d::new(1, 1, Rgba8([188, 0, 255, 255]))?)?;
    /// // The same bytes read as sRGB colour or as linear data.
    /// let srgb = load_from_memory(&png, ColorSpace::Srgb, &Limits::default())?.to_rgba32f()?;
    /// let data = load_from_memory(&png, ColorSpace::Linear, &Limits::default())?.to_rgba32f()?;
    /// let (s, d) = (srgb.texel(0, 0).unwrap().0, data.texel(0, 0).unwrap().0);
    /// assert!((s[0] - 0.5).abs() < 0.003); // sRGB 188 is half the light
    /// assert_eq!(d[0], 188.0 / 255.0);
    /// assert_eq!((s[2], s[3], d[2]), (1.0, 1.0, 1.0));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    pub fn to_rgba32f(&self) -> Result<Texture2d<Rgba32f>, TextureError> {
        match self {
            Self::Srgba8(t) => t.to_linear(),
            Self::Rgba8(t) => t.to_linear(),
            Self::R8(t) => t.to_linear(),
            Self::Rgba16f(t) => t.to_linear(),
            Self::Rgba32f(t) => Ok(t.clone()),
        }
    }
}

/// Decodes a PNG or JPEG held in memory.
///
/// The header's dimensions are checked against `limits` (and the decoder is given the same
/// limits) before pixels are decoded, so a file that claims to be 100000×100000 is refused
/// without allocating.
///
/// # Errors
/// [`TextureError::TooLarge`] or [`TextureError::Empty`] for refused dimensions,
/// [`TextureError::Decode`] for an unknown format or a corrupt file (also when the decoder
/// panics on it: the panic is caught, the message is [`DECODER_PANIC`]).
///
/// ```
/// use barytex_texture::load::{AnyTexture2d, ColorSpace, encode_png, load_from_memory};
/// use barytex_texture::{Limits, Rgba8, Texture2d, TextureError};
///
/// let texture = Texture2d::from_fn(8, 4, |x, y| Rgba8([x as u8, y as u8, 0, 255]))?;
/// let png = encode_png(&texture)?;
/// // Linear 8-bit colour comes back texel for texel.
/// let AnyTexture2d::Rgba8(back) = load_from_memory(&png, ColorSpace::Linear, &Limits::default())? else {
///     panic!("an RGBA8 PNG loads as Rgba8 under ColorSpace::Linear");
/// };
/// assert_eq!(back, texture);
/// // The header's width is checked before decoding.
/// let narrow = Limits { max_width: 4, ..Limits::default() };
/// assert!(matches!(
///     load_from_memory(&png, ColorSpace::Linear, &narrow),
///     Err(TextureError::TooLarge { what: "width", requested: 8, limit: 4 })
/// ));
/// assert!(matches!(
///     load_from_memory(b"not an image", ColorSpace::Srgb, &Limits::default()),
///     Err(TextureError::Decode(_))
/// ));
/// # Ok::<(), TextureError>(())
/// ```
pub fn load_from_memory(
    bytes: &[u8],
    color_space: ColorSpace,
    limits: &Limits,
) -> Result<AnyTexture2d, TextureError> {
    guarded(|| decode(bytes, color_space, limits))
}

/// The message of the [`TextureError::Decode`] that [`load_from_memory`] and [`decoded_size`]
/// return when a third-party decoder panics on a file (caught: files are untrusted input).
///
/// Catching needs unwinding: a program built with `panic = "abort"` still aborts on such a
/// file. The panic hook runs before the catch, so by default the decoder's panic message and
/// location are printed to standard error, though the call returns this error.
pub const DECODER_PANIC: &str =
    "the image decoder failed on this file (it panicked: a decoder bug, caught)";

/// Runs `f`, which calls third-party decoders, with a panic becoming
/// [`TextureError::Decode`]`(`[`DECODER_PANIC`]`)`: files are untrusted input, and a decoder's
/// bug must not take the caller down. zune-jpeg (the `image` crate's JPEG decoder, 0.5.15)
/// panics on some corrupt files — in its AVX2 and scalar inverse DCTs (an `unwrap` of an
/// out-of-range block slice) and its AVX2 upsampler; zune-image issue #361, open — which the
/// fuzz target `png_jpeg_loader` found. The panic's message is not kept: it names decoder
/// internals, not the file.
fn guarded<T>(f: impl FnOnce() -> Result<T, TextureError>) -> Result<T, TextureError> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f))
        .unwrap_or_else(|_| Err(TextureError::Decode(DECODER_PANIC.to_owned())))
}

/// [`load_from_memory`] without its guard.
fn decode(
    bytes: &[u8],
    color_space: ColorSpace,
    limits: &Limits,
) -> Result<AnyTexture2d, TextureError> {
    crate::png_palette::check_palette(bytes)?;
    let reader = || {
        ImageReader::new(Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|e| TextureError::Decode(e.to_string()))
    };
    let (width, height) = reader()?
        .into_dimensions()
        .map_err(|e| TextureError::Decode(e.to_string()))?;
    // The largest decoded form is RGBA32F: check that, so every conversion below fits.
    limits.check(width, height, 16)?;
    if let Some(texture) = direct_png(bytes, color_space, limits) {
        return texture;
    }
    let mut decoder = reader()?;
    let mut image_limits = image::Limits::default();
    image_limits.max_image_width = Some(limits.max_width);
    image_limits.max_image_height = Some(limits.max_height);
    image_limits.max_alloc = Some(limits.max_bytes);
    decoder.limits(image_limits);
    let image = decoder
        .decode()
        .map_err(|e| TextureError::Decode(e.to_string()))?;
    convert(image, color_space)
}

/// An 8-bit RGB or RGBA PNG decoded row by row into its texels (see `png_direct`); `None` for
/// the files that path does not take.
fn direct_png(
    bytes: &[u8],
    color_space: ColorSpace,
    limits: &Limits,
) -> Option<Result<AnyTexture2d, TextureError>> {
    let unlimited = &Limits::UNLIMITED;
    Some(match color_space {
        ColorSpace::Srgb => {
            let (w, h, texels) = crate::png_direct::decode_rgba8(bytes, limits, Srgba8)?;
            Texture2d::from_texels_with_limits(w, h, texels, unlimited).map(AnyTexture2d::Srgba8)
        }
        ColorSpace::Linear => {
            let (w, h, texels) = crate::png_direct::decode_rgba8(bytes, limits, Rgba8)?;
            Texture2d::from_texels_with_limits(w, h, texels, unlimited).map(AnyTexture2d::Rgba8)
        }
    })
}

/// `(width, height, bytes)` of the texture [`load_from_memory`] returns for `bytes`, read from
/// the image's header without decoding a pixel; `bytes` is `width × height ×` the texel size
/// of the format it is decoded into (1 byte for 8-bit greyscale as linear data, 4 for other
/// 8-bit images, 8 for 16-bit ones, 16 for float ones). Temporary buffers while decoding are
/// not counted, and no [`Limits`] are checked.
///
/// # Errors
/// [`TextureError::Decode`] for an unknown format or an unreadable header.
pub fn decoded_size(
    bytes: &[u8],
    color_space: ColorSpace,
) -> Result<(u32, u32, u64), TextureError> {
    guarded(|| header_size(bytes, color_space))
}

/// [`decoded_size`] without its guard.
fn header_size(bytes: &[u8], color_space: ColorSpace) -> Result<(u32, u32, u64), TextureError> {
    use image::{ColorType, ImageDecoder as _};
    let decode_error = |e: image::ImageError| TextureError::Decode(e.to_string());
    let decoder = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| TextureError::Decode(e.to_string()))?
        .into_decoder()
        .map_err(decode_error)?;
    let (width, height) = decoder.dimensions();
    // The texel size of each arm of `convert`.
    let texel: u64 = match decoder.color_type() {
        ColorType::L8 if color_space == ColorSpace::Linear => 1,
        ColorType::L8 | ColorType::La8 | ColorType::Rgb8 | ColorType::Rgba8 => 4,
        ColorType::Rgb32F | ColorType::Rgba32F => 16,
        _ => 8,
    };
    let bytes = u64::from(width)
        .saturating_mul(u64::from(height))
        .saturating_mul(texel);
    Ok((width, height, bytes))
}

/// Decodes a PNG or JPEG file; see [`load_from_memory`].
///
/// # Errors
/// As [`load_from_memory`], plus [`TextureError::Decode`] when the file cannot be read.
///
/// ```
/// use barytex_texture::load::{ColorSpace, load_from_path, save_png};
/// use barytex_texture::{Limits, Srgba8, Texture2d, TextureError};
///
/// let path = std::env::temp_dir().join(format!("barytex-doc-load-{}.png", std::process::id()));
/// save_png(&Texture2d::new(2, 2, Srgba8([9, 8, 7, 255]))?, &path)?;
/// let loaded = load_from_path(&path, ColorSpace::Srgb, &Limits::default());
/// std::fs::remove_file(&path).ok();
/// assert_eq!(loaded?.size(), (2, 2));
/// // A missing file is a Decode error naming the path.
/// let missing = load_from_path(&path, ColorSpace::Srgb, &Limits::default());
/// assert!(matches!(missing, Err(TextureError::Decode(m)) if m.contains("barytex-doc-load")));
/// # Ok::<(), TextureError>(())
/// ```
pub fn load_from_path(
    path: impl AsRef<Path>,
    color_space: ColorSpace,
    limits: &Limits,
) -> Result<AnyTexture2d, TextureError> {
    let path = path.as_ref();
    let bytes = std::fs::read(path)
        .map_err(|e| TextureError::Decode(format!("{}: {e}", path.display())))?;
    load_from_memory(&bytes, color_space, limits)
}

fn convert(image: DynamicImage, color_space: ColorSpace) -> Result<AnyTexture2d, TextureError> {
    let (w, h) = (image.width(), image.height());
    let unlimited = &Limits::UNLIMITED;
    Ok(match image {
        DynamicImage::ImageLuma8(gray) if color_space == ColorSpace::Linear => {
            let texels = gray.into_raw().into_iter().map(R8).collect();
            AnyTexture2d::R8(Texture2d::from_texels_with_limits(w, h, texels, unlimited)?)
        }
        // RGB (JPEGs, and the PNGs `png_direct` leaves here: interlaced ones) straight to
        // 4-byte texels: one pass over the decoded image instead of two (`into_rgba8` builds a
        // whole RGBA image first, which took 11–13 ms of a 2048² image's 38 ms load).
        DynamicImage::ImageRgb8(rgb) => {
            let raw = rgb.into_raw();
            let opaque = |c: &[u8]| [c[0], c[1], c[2], u8::MAX];
            match color_space {
                ColorSpace::Srgb => {
                    let texels = raw.chunks_exact(3).map(|c| Srgba8(opaque(c))).collect();
                    AnyTexture2d::Srgba8(Texture2d::from_texels_with_limits(
                        w, h, texels, unlimited,
                    )?)
                }
                ColorSpace::Linear => {
                    let texels = raw.chunks_exact(3).map(|c| Rgba8(opaque(c))).collect();
                    AnyTexture2d::Rgba8(Texture2d::from_texels_with_limits(
                        w, h, texels, unlimited,
                    )?)
                }
            }
        }
        DynamicImage::ImageLuma8(_)
        | DynamicImage::ImageLumaA8(_)
        | DynamicImage::ImageRgba8(_) => {
            let raw = image.into_rgba8().into_raw();
            match color_space {
                ColorSpace::Srgb => {
                    let texels = raw
                        .chunks_exact(4)
                        .map(|c| Srgba8([c[0], c[1], c[2], c[3]]))
                        .collect();
                    AnyTexture2d::Srgba8(Texture2d::from_texels_with_limits(
                        w, h, texels, unlimited,
                    )?)
                }
                ColorSpace::Linear => {
                    let texels = raw
                        .chunks_exact(4)
                        .map(|c| Rgba8([c[0], c[1], c[2], c[3]]))
                        .collect();
                    AnyTexture2d::Rgba8(Texture2d::from_texels_with_limits(
                        w, h, texels, unlimited,
                    )?)
                }
            }
        }
        DynamicImage::ImageRgb32F(_) | DynamicImage::ImageRgba32F(_) => {
            // Float images hold linear values whatever the caller says.
            let raw = image.into_rgba32f().into_raw();
            let texels = raw
                .chunks_exact(4)
                .map(|c| Rgba32f::from_linear(Vec4::new(c[0], c[1], c[2], c[3])))
                .collect();
            AnyTexture2d::Rgba32f(Texture2d::from_texels_with_limits(w, h, texels, unlimited)?)
        }
        // 16-bit and any other layout: through 16-bit RGBA into half floats.
        other => {
            let raw = other.into_rgba16().into_raw();
            let decode = |v: u16| {
                let x = f32::from(v) / 65535.0;
                match color_space {
                    ColorSpace::Srgb => srgb::to_linear(x),
                    ColorSpace::Linear => x,
                }
            };
            let texels = raw
                .chunks_exact(4)
                .map(|c| {
                    Rgba16f([
                        f16::from_f32(decode(c[0])),
                        f16::from_f32(decode(c[1])),
                        f16::from_f32(decode(c[2])),
                        f16::from_f32(f32::from(c[3]) / 65535.0),
                    ])
                })
                .collect();
            AnyTexture2d::Rgba16f(Texture2d::from_texels_with_limits(w, h, texels, unlimited)?)
        }
    })
}

/// Encodes an 8-bit texture as PNG (sRGB textures are written as they are stored, which is what
/// PNG viewers expect).
///
/// # Errors
/// [`TextureError::Decode`] if the encoder fails.
///
/// ```
/// use barytex_texture::load::encode_png;
/// use barytex_texture::{Srgba8, Texture2d};
///
/// let png = encode_png(&Texture2d::new(4, 4, Srgba8([255, 0, 0, 255]))?)?;
/// assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n"); // the PNG signature
/// # Ok::<(), barytex_texture::TextureError>(())
/// ```
pub fn encode_png<T: Texel + Into<[u8; 4]>>(
    texture: &Texture2d<T>,
) -> Result<Vec<u8>, TextureError> {
    let (w, h) = texture.size();
    let raw: Vec<u8> = texture.texels().iter().flat_map(|&t| t.into()).collect();
    let image = image::RgbaImage::from_raw(w, h, raw)
        .ok_or_else(|| TextureError::Decode("texel buffer does not match its size".into()))?;
    let mut bytes = Vec::new();
    image
        .write_to(&mut Cursor::new(&mut bytes), image::ImageFormat::Png)
        .map_err(|e| TextureError::Decode(e.to_string()))?;
    Ok(bytes)
}

/// Writes an 8-bit texture as a PNG file.
///
/// # Errors
/// [`TextureError::Decode`] if encoding or writing fails.
///
/// ```
/// use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_path, save_png};
/// use barytex_texture::{Limits, Srgba8, Texture2d};
///
/// let texture = Texture2d::from_fn(3, 1, |x, _| Srgba8([40 * x as u8, 0, 0, 255]))?;
/// let path = std::env::temp_dir().join(format!("barytex-doc-save-{}.png", std::process::id()));
/// save_png(&texture, &path)?;
/// let back = load_from_path(&path, ColorSpace::Srgb, &Limits::default());
/// std::fs::remove_file(&path).ok();
/// // sRGB bytes are written as stored, so they come back unchanged.
/// assert!(matches!(back?, AnyTexture2d::Srgba8(t) if t == texture));
/// # Ok::<(), barytex_texture::TextureError>(())
/// ```
pub fn save_png<T: Texel + Into<[u8; 4]>>(
    texture: &Texture2d<T>,
    path: impl AsRef<Path>,
) -> Result<(), TextureError> {
    let path = path.as_ref();
    std::fs::write(path, encode_png(texture)?)
        .map_err(|e| TextureError::Decode(format!("{}: {e}", path.display())))
}
