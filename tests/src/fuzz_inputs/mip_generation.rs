//! Byte layout and checks of the `mip_generation` fuzz target: arbitrary sizes (1–16 per side),
//! filters, colour spaces, alpha-coverage references and level counts over sRGB RGBA8 texels.
//!
//! Layout: byte 0 width − 1 (mod 16), byte 1 height − 1 (mod 16), byte 2 options (bits 0–1
//! filter: box, Kaiser, Lanczos-3; bit 2 sRGB-naive; bit 3 alpha coverage with reference byte 3
//! / 255; bits 4–6 max levels, 0 = all), then texels, 4 bytes each (missing texels repeat the
//! bytes given, or a fixed pattern when none are).

use std::fmt::Write as _;

use barytex_texture::mip_chain::{full_length, level_size};
use barytex_texture::{MipChain, MipColorSpace, MipFilter, MipOptions, Srgba8, Texel, Texture2d};
use glam::Vec4;

/// Bytes of the fixed part.
pub const MIP_HEADER: usize = 4;
/// The most bytes the target reads: header and a 16×16 texture.
pub const MIP_LEN: usize = MIP_HEADER + 256 * 4;

/// `(base, options)` decoded from `bytes`.
///
/// # Panics
/// Never: sides are 1 to 16.
#[must_use]
pub fn mip_input(bytes: &[u8]) -> (Texture2d<Srgba8>, MipOptions) {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let (w, h) = (u32::from(byte(0) % 16) + 1, u32::from(byte(1) % 16) + 1);
    let texel_bytes = bytes.get(MIP_HEADER..).unwrap_or(&[]);
    let base = Texture2d::from_fn(w, h, |x, y| {
        let i = (y * w + x) as usize * 4;
        let b = |k: usize| {
            if texel_bytes.is_empty() {
                ((i + k) * 53 % 256) as u8
            } else {
                texel_bytes[(i + k) % texel_bytes.len()]
            }
        };
        Srgba8([b(0), b(1), b(2), b(3)])
    })
    .expect("at most 16×16");
    let o = byte(2);
    let options = MipOptions {
        filter: [
            MipFilter::Box,
            MipFilter::Kaiser,
            MipFilter::Lanczos3,
            MipFilter::Box,
        ][usize::from(o & 3)],
        color_space: if o & 4 != 0 {
            MipColorSpace::SrgbNaive
        } else {
            MipColorSpace::LinearLight
        },
        alpha_coverage: (o & 8 != 0).then(|| f32::from(byte(3)) / 255.0),
        max_levels: match (o >> 4) & 7 {
            0 => None,
            n => Some(usize::from(n)),
        },
    };
    (base, options)
}

/// The invariants: the chain has the halving sizes and the asked length; without alpha coverage
/// and with the box filter every level's stored values lie within the base's per-channel range
/// (one 8-bit step of rounding allowed) — in the colour space the filter works in; a constant
/// opaque base stays constant.
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_mip_generation(bytes: &[u8]) -> Result<(), String> {
    let (base, options) = mip_input(bytes);
    let (w, h) = base.size();
    let chain = MipChain::generate(base.clone(), &options).map_err(|e| format!("{e}"))?;
    let want_len = options
        .max_levels
        .unwrap_or(usize::MAX)
        .clamp(1, full_length(w, h));
    if chain.len() != want_len {
        return Err(format!("{} levels, expected {want_len}", chain.len()));
    }
    for (i, level) in chain.levels().iter().enumerate() {
        if level.size() != level_size(w, h, i) {
            return Err(format!("level {i} is {:?}", level.size()));
        }
    }
    let value = |t: &Srgba8| match options.color_space {
        MipColorSpace::SrgbNaive => t.to_stored(),
        MipColorSpace::LinearLight => t.to_linear(),
    };
    let opaque = base.texels().iter().all(|t| t.0[3] == 255);
    // Linear light un-premultiplies: with varying alpha a colour channel may leave the base's
    // straight-colour range only through alpha weighting, so check opaque bases there.
    let check_range = options.filter == MipFilter::Box
        && options.alpha_coverage.is_none()
        && (opaque || options.color_space == MipColorSpace::SrgbNaive);
    if check_range {
        let values: Vec<Vec4> = base.texels().iter().map(value).collect();
        let step = 1.0 / 255.0 + 1e-6;
        let lo = values.iter().fold(Vec4::INFINITY, |a, &b| a.min(b)) - step;
        let hi = values.iter().fold(Vec4::NEG_INFINITY, |a, &b| a.max(b)) + step;
        for (i, level) in chain.levels().iter().enumerate() {
            for t in level.texels() {
                let v = value(t);
                if !(v.cmpge(lo).all() && v.cmple(hi).all()) {
                    return Err(format!("level {i}: {t:?} outside the base's range"));
                }
            }
        }
    }
    let first = base.texels()[0];
    if opaque && base.texels().iter().all(|t| *t == first) && options.alpha_coverage.is_none() {
        for (i, level) in chain.levels().iter().enumerate() {
            if let Some(t) = level.texels().iter().find(|t| **t != first) {
                return Err(format!("constant {first:?} became {t:?} at level {i}"));
            }
        }
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn mip_generation_code(bytes: &[u8]) -> String {
    let (base, options) = mip_input(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    // {:?} base, {options:?}", base.size());
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_mip_generation(bytes), Ok(()));\n}");
    out
}
