//! Checks of the `png_jpeg_loader` fuzz target: arbitrary bytes decoded by
//! `barytex_texture::load::load_from_memory` under small [`Limits`].
//!
//! The whole input is the file (PNG, JPEG or anything else); it is decoded twice, as sRGB and as
//! linear colour. Each answer must be an error or a texture within the limits: both sides at
//! least 1 and at most the limit, `width · height · 16` bytes (the RGBA32F size the loader checks
//! the header against) at most `max_bytes`; the same size under both colour spaces; every texel,
//! converted to linear RGBA32F, finite and in `[0, 1]` (PNG and JPEG hold unsigned normalized
//! samples only).

use std::fmt::Write as _;

use barytex_texture::Limits;
use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_memory};

/// Longest input the target reads: enough for a compressed 64 × 64 image.
pub const PNG_JPEG_LEN: usize = 1 << 13;

/// The limits under fuzzing: 64 × 64 texels, 64 KiB (64 · 64 RGBA32F texels).
pub const PNG_JPEG_LIMITS: Limits = Limits {
    max_width: 64,
    max_height: 64,
    max_bytes: 64 * 64 * 16,
};

fn check_texture(texture: &AnyTexture2d, limits: &Limits) -> Result<(), String> {
    let (w, h) = texture.size();
    if w == 0 || h == 0 || w > limits.max_width || h > limits.max_height {
        return Err(format!("a {w}×{h} texture under {limits:?}"));
    }
    if u64::from(w) * u64::from(h) * 16 > limits.max_bytes {
        return Err(format!("a {w}×{h} texture over {} bytes", limits.max_bytes));
    }
    let linear = texture
        .to_rgba32f()
        .map_err(|e| format!("a decoded {w}×{h} texture cannot convert to RGBA32F: {e}"))?;
    for (i, t) in linear.texels().iter().enumerate() {
        if !t.0.iter().all(|c| (0.0..=1.0).contains(c)) {
            return Err(format!("texel {i} of a {w}×{h} texture is {:?}", t.0));
        }
    }
    Ok(())
}

/// The invariants (see the module documentation).
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_png_jpeg_loader(bytes: &[u8]) -> Result<(), String> {
    let limits = PNG_JPEG_LIMITS;
    let mut sizes = Vec::new();
    for space in [ColorSpace::Srgb, ColorSpace::Linear] {
        match load_from_memory(bytes, space, &limits) {
            Ok(texture) => {
                check_texture(&texture, &limits).map_err(|e| format!("{space:?}: {e}"))?;
                sizes.push(Some(texture.size()));
            }
            Err(_) => sizes.push(None),
        }
    }
    if sizes[0] != sizes[1] {
        return Err(format!(
            "sRGB and linear decoding disagree: {:?} vs {:?}",
            sizes[0], sizes[1]
        ));
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn png_jpeg_loader_code(bytes: &[u8]) -> String {
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_png_jpeg_loader(bytes), Ok(()));\n}");
    out
}
