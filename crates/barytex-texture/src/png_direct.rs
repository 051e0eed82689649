//! 8-bit RGB and RGBA PNGs decoded row by row straight into 4-byte texels, without the
//! `image` crate's whole-image buffer in the file's own layout (12 MB for a 2048² RGB image,
//! written and read once more before the texels exist).
//!
//! Only the layouts whose rows, as the `png` crate returns them, are already the texels' bytes
//! take this path: three or four 8-bit channels, not interlaced, no `tRNS` colour key (which
//! the `image` crate's expansion would turn into alpha). Any other file, and any PNG whose
//! decoding fails, goes through the `image` crate as before, so errors read the same. The
//! texels are the bytes the `image` crate gives (`tests/load_layouts.rs` compares them).

use std::io::Cursor;

use crate::Limits;

/// The texels of `bytes` (each RGBA byte quadruple through `texel`, alpha 255 for RGB) and the
/// image's size, when the PNG is one this path decodes and decodes cleanly; `None` otherwise.
/// `limits` have been checked against the header by the caller; the decoder's own buffers
/// are held to `limits.max_bytes`.
pub(crate) fn decode_rgba8<T>(
    bytes: &[u8],
    limits: &Limits,
    texel: impl Fn([u8; 4]) -> T,
) -> Option<(u32, u32, Vec<T>)> {
    let png_limits = png::Limits {
        bytes: usize::try_from(limits.max_bytes).unwrap_or(usize::MAX),
    };
    let decoder = png::Decoder::new_with_limits(Cursor::new(bytes), png_limits);
    let mut reader = decoder.read_info().ok()?;
    let info = reader.info();
    let channels = match (info.color_type, info.bit_depth) {
        (png::ColorType::Rgb, png::BitDepth::Eight) => 3,
        (png::ColorType::Rgba, png::BitDepth::Eight) => 4,
        _ => return None,
    };
    if info.interlaced || info.trns.is_some() {
        return None;
    }
    let (width, height) = (info.width, info.height);
    let row_bytes = usize::try_from(width).ok()?.checked_mul(channels)?;
    let count = usize::try_from(u64::from(width) * u64::from(height)).ok()?;
    let mut texels = Vec::with_capacity(count);
    while let Some(row) = reader.next_row().ok()? {
        let data = row.data();
        if data.len() != row_bytes {
            return None;
        }
        if channels == 3 {
            texels.extend(
                data.chunks_exact(3)
                    .map(|c| texel([c[0], c[1], c[2], u8::MAX])),
            );
        } else {
            texels.extend(
                data.chunks_exact(4)
                    .map(|c| texel([c[0], c[1], c[2], c[3]])),
            );
        }
    }
    (texels.len() == count).then_some((width, height, texels))
}
