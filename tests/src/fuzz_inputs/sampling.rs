//! Byte layout and checks of the `sampling` fuzz target: an arbitrary sampler descriptor, a small
//! RGBA8 texture with its mip chain, and arbitrary coordinates, derivatives and LOD.
//!
//! Layout: byte 0 width − 1 (mod 8), byte 1 height − 1 (mod 8), byte 2 filters (bits 0–1 mag,
//! 2–3 min: nearest, linear, Catmull-Rom, B-spline; bit 4 linear mip; bit 5 anisotropy 16;
//! bit 6 EWA), byte 3 address modes (bits 0–1 u, 2–3 v) and border (bits 4–5); words 1–10: uv,
//! ddx, ddy, lod, bias, lod_min, lod_max as f32 bit patterns; then texels, 4 bytes each (missing
//! texels repeat the bytes given, or a fixed pattern when none are).

use std::fmt::Write as _;

use barytex_texture::sampler::{
    AddressMode, AnisotropicFilter, BorderColor, CubicKernel, FilterMode, MipmapFilterMode,
};
use barytex_texture::{
    MipChain, MipOptions, Rgba8, Sampler, SamplerDescriptor, Texel, Texture2d, TextureSampler,
};
use glam::{Vec2, Vec4};

use super::word;
use barytex_testkit::sampling_invariants::check_sample_level;

/// Bytes of the fixed part (the texels follow).
pub const SAMPLING_HEADER: usize = 4 + 10 * 4;
/// The most bytes the target reads: the header and an 8×8 texture.
pub const SAMPLING_LEN: usize = SAMPLING_HEADER + 64 * 4;

/// A decoded `sampling` input.
#[derive(Clone, Debug)]
pub struct SamplingInput {
    /// The base level.
    pub texture: Texture2d<Rgba8>,
    /// The descriptor as given (the sampler sanitises it).
    pub descriptor: SamplerDescriptor,
    /// Coordinate.
    pub uv: Vec2,
    /// Screen derivatives.
    pub ddx: Vec2,
    /// Screen derivatives.
    pub ddy: Vec2,
    /// Explicit level of detail.
    pub lod: f32,
    /// Extra bias for `sample_bias`.
    pub bias: f32,
}

/// Filter mode from two bits (nearest, linear, Catmull-Rom, B-spline).
pub(super) fn filter(bits: u8) -> FilterMode {
    match bits & 3 {
        0 => FilterMode::Nearest,
        1 => FilterMode::Linear,
        2 => FilterMode::Cubic(CubicKernel::CatmullRom),
        _ => FilterMode::Cubic(CubicKernel::BSpline),
    }
}

/// Address mode from two bits.
pub(super) fn address(bits: u8) -> AddressMode {
    [
        AddressMode::ClampToEdge,
        AddressMode::Repeat,
        AddressMode::MirrorRepeat,
        AddressMode::ClampToBorder,
    ][usize::from(bits & 3)]
}

/// The filtering half of a descriptor from one byte: mag filter (bits 0–1), min filter (2–3),
/// linear mipmaps (4), anisotropy ×16 (5), EWA (6); the rest default. Shared with the
/// `textures_3d` target, whose byte means the same.
pub(super) fn filtering(filters: u8) -> SamplerDescriptor {
    SamplerDescriptor {
        mag_filter: filter(filters),
        min_filter: filter(filters >> 2),
        mipmap_filter: if filters & 16 != 0 {
            MipmapFilterMode::Linear
        } else {
            MipmapFilterMode::Nearest
        },
        anisotropy_clamp: if filters & 32 != 0 { 16 } else { 1 },
        anisotropic_filter: if filters & 64 != 0 {
            AnisotropicFilter::Ewa
        } else {
            AnisotropicFilter::Probes
        },
        ..SamplerDescriptor::default()
    }
}

/// Border colour from two bits.
pub(super) fn border(bits: u8) -> BorderColor {
    [
        BorderColor::TransparentBlack,
        BorderColor::OpaqueBlack,
        BorderColor::OpaqueWhite,
        BorderColor::Zero,
    ][usize::from(bits & 3)]
}

/// Decodes `bytes` (any length).
///
/// # Panics
/// Never: sizes are at least 1 and at most 8.
#[must_use]
pub fn sampling_input(bytes: &[u8]) -> SamplingInput {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let (w, h) = (u32::from(byte(0) % 8) + 1, u32::from(byte(1) % 8) + 1);
    let f = |i: usize| f32::from_bits(word(bytes, 1 + i));
    let texel_bytes = bytes.get(SAMPLING_HEADER..).unwrap_or(&[]);
    let texture = Texture2d::from_fn(w, h, |x, y| {
        let i = (y * w + x) as usize * 4;
        let b = |k: usize| {
            if texel_bytes.is_empty() {
                ((i + k) * 37 % 256) as u8
            } else {
                texel_bytes[(i + k) % texel_bytes.len()]
            }
        };
        Rgba8([b(0), b(1), b(2), b(3)])
    })
    .expect("at most 8×8");
    let (filters, modes) = (byte(2), byte(3));
    let descriptor = SamplerDescriptor {
        address_mode_u: address(modes),
        address_mode_v: address(modes >> 2),
        border_color: Some(border(modes >> 4)),
        lod_bias: f(8),
        lod_min_clamp: f(8 + 1),
        lod_max_clamp: f(8 + 2),
        ..filtering(filters)
    };
    SamplingInput {
        texture,
        descriptor,
        uv: Vec2::new(f(0), f(1)),
        ddx: Vec2::new(f(2), f(3)),
        ddy: Vec2::new(f(4), f(5)),
        lod: f(6),
        bias: f(7),
    }
}

/// The invariants: no NaN; non-finite `uv` gives transparent black; opaque textures under the
/// range-preserving filters (everything but Catmull-Rom) stay within the texels' range when no
/// border is read; `sample_level` with nearest/linear filters on an opaque texture and border lies
/// in the dEQP allowed set.
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_sampling(bytes: &[u8]) -> Result<(), String> {
    let input = sampling_input(bytes);
    let chain = MipChain::generate(input.texture.clone(), &MipOptions::default())
        .map_err(|e| format!("mip generation failed: {e}"))?;
    let sampler = TextureSampler::new(chain.clone(), input.descriptor);
    let results = [
        ("sample", sampler.sample(input.uv, input.ddx, input.ddy)),
        ("sample_level", sampler.sample_level(input.uv, input.lod)),
        (
            "sample_bias",
            sampler.sample_bias(input.uv, input.ddx, input.ddy, input.bias),
        ),
    ];
    for (name, c) in results {
        if c.is_nan() {
            return Err(format!("{name} gave NaN: {c:?}"));
        }
        if !input.uv.is_finite() && c != Vec4::ZERO {
            return Err(format!("{name} at non-finite uv gave {c:?}, not (0,0,0,0)"));
        }
    }
    let d = *sampler.descriptor();
    let cubic = |f: FilterMode| matches!(f, FilterMode::Cubic(CubicKernel::CatmullRom));
    let opaque = input.texture.texels().iter().all(|t| t.0[3] == 255);
    let border_used = [d.address_mode_u, d.address_mode_v].contains(&AddressMode::ClampToBorder);
    if opaque && !border_used && !cubic(d.mag_filter) && !cubic(d.min_filter) {
        let texels: Vec<Vec4> = input
            .texture
            .texels()
            .iter()
            .map(|t| t.to_linear())
            .collect();
        // The documented slack: 4 ε for the two-tap blends, 16 ε where up to 16 weighted terms
        // are summed and normalised (cubic, anisotropic probes, EWA).
        let summed = d.anisotropy_clamp > 1
            || matches!(d.mag_filter, FilterMode::Cubic(_))
            || matches!(d.min_filter, FilterMode::Cubic(_));
        let slack = if summed { 16.0 } else { 4.0 } * f32::EPSILON;
        let lo = texels.iter().fold(Vec4::INFINITY, |a, &b| a.min(b)) - slack;
        let hi = texels.iter().fold(Vec4::NEG_INFINITY, |a, &b| a.max(b)) + slack;
        for (name, c) in results {
            if input.uv.is_finite() && !(c.cmpge(lo).all() && c.cmple(hi).all()) {
                return Err(format!(
                    "{name} = {c:?} outside the texels' range {lo:?} … {hi:?} ({d:?})"
                ));
            }
        }
    }
    let plain = |f: FilterMode| matches!(f, FilterMode::Nearest | FilterMode::Linear);
    // The verifier blends straight colours, as GPUs do; barytex blends premultiplied ones. The
    // two agree when every value blended is opaque: an opaque texture and an opaque border.
    let opaque_border = !border_used
        || matches!(
            d.border_color,
            Some(BorderColor::OpaqueBlack | BorderColor::OpaqueWhite)
        );
    if opaque && opaque_border && input.uv.is_finite() && plain(d.mag_filter) && plain(d.min_filter)
    {
        let biased = input.lod + d.lod_bias;
        let lod = if biased.is_nan() {
            d.lod_max_clamp
        } else {
            biased.clamp(d.lod_min_clamp, d.lod_max_clamp)
        };
        // Coordinates beyond 2²⁰ lose sub-texel precision in f32 itself: the verifier's
        // 2⁻⁸-texel box no longer describes them.
        if input.uv.abs().max_element() < 1e6 {
            check_sample_level(&chain, &d, input.uv, lod, results[1].1, 1e-6)?;
        }
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn sampling_code(bytes: &[u8]) -> String {
    let input = sampling_input(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    // descriptor: {:?}", input.descriptor);
    let _ = writeln!(
        out,
        "    // texture {:?}: {:?}",
        input.texture.size(),
        input.texture.texels()
    );
    let _ = writeln!(
        out,
        "    let (uv, ddx, ddy, lod) = ({:?}, {:?}, {:?}, {:?});",
        input.uv, input.ddx, input.ddy, input.lod
    );
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_sampling(bytes), Ok(()));\n}");
    out
}
