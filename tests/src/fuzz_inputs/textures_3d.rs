//! Byte layout and checks of the `textures_3d` fuzz target: cube maps, 2D arrays, volumes and
//! comparison sampling, with an arbitrary sampler descriptor and arbitrary coordinates.
//!
//! Layout: byte 0 filters (as the `sampling` target: bits 0–1 mag, 2–3 min — nearest, linear,
//! Catmull-Rom, B-spline; bit 4 linear mip; bit 5 anisotropy 16; bit 6 EWA); byte 1 address modes
//! (bits 0–1 u, 2–3 v, 4–5 w: clamp, repeat, mirror, border; bits 6–7 border colour); byte 2
//! bits 0–3 the comparison function (0–7 `Never` … `Always`, 8–15 none), bits 4–6 the side − 1
//! (1–8 texels); byte 3 bits 0–1 layers and depth − 1 (1–4), bit 2 full mip chains (else one
//! level). Then 14 words as f32 bit patterns: the direction (also `uvw`; its x, y are the `uv`),
//! `ddx`, `ddy` (three each), `lod`, the layer, the depth reference, `lod_bias`, `lod_min_clamp`,
//! then texels, 4 bytes each (RGBA8, unorm), repeating the bytes given (or a fixed pattern
//! without any).
//!
//! Invariants (their documentation): every filtered colour is in `[0, 1]` per channel (unorm
//! texels) up to the f32 rounding slack of the `sampling` target (4 ε, or 16 ε for summed
//! filters), except under a Catmull-Rom filter, documented to overshoot, where it is finite; a zero or non-finite direction gives the cube's transparent black, a
//! non-finite `uvw` the volume's; the array's `layer_index` is a valid layer; comparison sampling
//! gives `Some` value in `[0, 1]` with a comparison function and `None` without.

use std::fmt::Write as _;

use barytex_texture::sampler::{CompareFunction, CubicKernel, FilterMode};
use barytex_texture::{
    CubeTexture, Limits, MipChain, MipOptions, Rgba8, SamplerDescriptor, Texture2d, Texture2dArray,
    Texture3d, TextureSampler,
};
use glam::{Vec3, Vec4};

use super::sampling::{address, border, filtering};
use super::word;

/// Bytes of the fixed part (the texels follow).
pub const TEXTURES_3D_HEADER: usize = 4 + 14 * 4;
/// The most bytes the target reads: the header and an 8 × 8 × 4 block of texels.
pub const TEXTURES_3D_LEN: usize = TEXTURES_3D_HEADER + 8 * 8 * 4 * 4;

/// A decoded `textures_3d` input.
#[derive(Clone, Debug)]
pub struct Textures3dInput {
    /// The descriptor for every texture.
    pub descriptor: SamplerDescriptor,
    /// Face, layer and slice side in texels.
    pub side: u32,
    /// Layers of the array and slices of the volume.
    pub depth: u32,
    /// Whether the 2D textures get full mip chains.
    pub mipmapped: bool,
    /// Direction and `uvw`.
    pub dir: Vec3,
    /// Derivatives of the direction.
    pub ddx: Vec3,
    /// Derivatives of the direction.
    pub ddy: Vec3,
    /// Explicit level of detail.
    pub lod: f32,
    /// Array layer.
    pub layer: f32,
    /// Depth reference of the comparison.
    pub reference: f32,
    /// The texel bytes.
    pub texels: Vec<u8>,
}

/// Decodes `bytes` (any length).
#[must_use]
pub fn textures_3d_input(bytes: &[u8]) -> Textures3dInput {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let f = |i: usize| f32::from_bits(word(bytes, 1 + i));
    let v3 = |i: usize| Vec3::new(f(i), f(i + 1), f(i + 2));
    let (filters, modes, kind, sizes) = (byte(0), byte(1), byte(2), byte(3));
    let compare = [
        CompareFunction::Never,
        CompareFunction::Less,
        CompareFunction::Equal,
        CompareFunction::LessEqual,
        CompareFunction::Greater,
        CompareFunction::NotEqual,
        CompareFunction::GreaterEqual,
        CompareFunction::Always,
    ]
    .get(usize::from(kind & 15))
    .copied();
    let descriptor = SamplerDescriptor {
        address_mode_u: address(modes),
        address_mode_v: address(modes >> 2),
        address_mode_w: address(modes >> 4),
        border_color: Some(border(modes >> 6)),
        compare,
        lod_bias: f(12),
        lod_min_clamp: f(13),
        ..filtering(filters)
    };
    Textures3dInput {
        descriptor,
        side: u32::from((kind >> 4) & 7) + 1,
        depth: u32::from(sizes & 3) + 1,
        mipmapped: sizes & 4 != 0,
        dir: v3(0),
        ddx: v3(3),
        ddy: v3(6),
        lod: f(9),
        layer: f(10),
        reference: f(11),
        texels: bytes.get(TEXTURES_3D_HEADER..).unwrap_or(&[]).to_vec(),
    }
}

impl Textures3dInput {
    /// Texel `(x, y)` of layer (face, slice) `z`.
    fn texel(&self, x: u32, y: u32, z: u32) -> Rgba8 {
        let i = ((z * self.side + y) * self.side + x) as usize * 4;
        let b = |k: usize| {
            if self.texels.is_empty() {
                ((i + k) * 37 % 256) as u8
            } else {
                self.texels[(i + k) % self.texels.len()]
            }
        };
        Rgba8([b(0), b(1), b(2), b(3)])
    }

    fn chain(&self, z: u32) -> MipChain<Rgba8> {
        let base = Texture2d::from_fn(self.side, self.side, |x, y| self.texel(x, y, z))
            .expect("at most 8×8");
        if self.mipmapped {
            MipChain::generate(base, &MipOptions::default()).expect("at most 8×8")
        } else {
            MipChain::single(base)
        }
    }
}

/// In `[0, 1]` up to f32 rounding — the slack the `sampling` target allows around the texels'
/// range: 4 ε for two-tap blends, 16 ε where up to 16 weighted terms are summed and normalised
/// (cubic, anisotropic probes, EWA); with a Catmull-Rom filter, which may overshoot
/// (`CubicKernel::CatmullRom`), only finite.
fn check_colour(what: &str, c: Vec4, d: &SamplerDescriptor) -> Result<(), String> {
    let catmull_rom = FilterMode::Cubic(CubicKernel::CatmullRom);
    let overshoots = d.mag_filter == catmull_rom || d.min_filter == catmull_rom;
    let summed = d.anisotropy_clamp > 1
        || matches!(d.mag_filter, FilterMode::Cubic(_))
        || matches!(d.min_filter, FilterMode::Cubic(_));
    let slack = if summed { 16.0 } else { 4.0 } * f32::EPSILON;
    let ok = |x: &f32| {
        if overshoots {
            x.is_finite()
        } else {
            (-slack..=1.0 + slack).contains(x)
        }
    };
    if c.to_array().iter().all(ok) {
        Ok(())
    } else {
        Err(format!(
            "{what} = {c:?}, not in [0, 1] (slack {slack:e}) under {d:?}"
        ))
    }
}

/// The invariants (see the module documentation).
///
/// # Errors
/// A description of the first violated invariant.
///
/// # Panics
/// Never: the sizes are valid by construction.
pub fn check_textures_3d(bytes: &[u8]) -> Result<(), String> {
    let input = textures_3d_input(bytes);
    let Textures3dInput {
        descriptor: d,
        dir,
        ddx,
        ddy,
        lod,
        layer,
        reference,
        ..
    } = input;
    let faces: [MipChain<Rgba8>; 6] = core::array::from_fn(|z| input.chain(z as u32));
    let cube = CubeTexture::new(faces, d).map_err(|e| format!("cube refused: {e}"))?;
    let blank = !dir.is_finite() || dir == Vec3::ZERO;
    for (what, c) in [
        ("cube.sample_level", cube.sample_level(dir, lod)),
        ("cube.sample", cube.sample(dir, ddx, ddy)),
    ] {
        check_colour(&format!("{what}({dir:?}, …)"), c, &d)?;
        if blank && c != Vec4::ZERO {
            return Err(format!(
                "{what}({dir:?}, …) = {c:?} for a zero or non-finite direction"
            ));
        }
    }

    let layers = (0..input.depth).map(|z| input.chain(z)).collect();
    let array = Texture2dArray::new(layers, d).map_err(|e| format!("array refused: {e}"))?;
    let index = array.layer_index(layer);
    if index >= array.layer_count() {
        return Err(format!(
            "layer_index({layer}) = {index} of {}",
            array.layer_count()
        ));
    }
    let uv = dir.truncate();
    let (du, dv) = (ddx.truncate(), ddy.truncate());
    check_colour("array.sample", array.sample(uv, layer, du, dv), &d)?;
    check_colour("array.sample_level", array.sample_level(uv, layer, lod), &d)?;

    let volume = Texture3d::from_fn(
        [input.side, input.side, input.depth],
        &Limits::default(),
        |x, y, z| input.texel(x, y, z),
    )
    .map_err(|e| format!("volume refused: {e}"))?;
    let c = volume.sample(dir, &d);
    check_colour(&format!("volume.sample({dir:?})"), c, &d)?;
    if !dir.is_finite() && c != Vec4::ZERO {
        return Err(format!(
            "volume.sample({dir:?}) = {c:?} for a non-finite uvw"
        ));
    }

    let sampler = TextureSampler::new(input.chain(0), d);
    match (d.compare, sampler.sample_compare_level(uv, reference, lod)) {
        (Some(_), Some(x)) if (0.0..=1.0).contains(&x) => {}
        (None, None) => {}
        (compare, got) => {
            return Err(format!(
                "sample_compare_level({uv:?}, {reference}, {lod}) = {got:?} with {compare:?}"
            ));
        }
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn textures_3d_code(bytes: &[u8]) -> String {
    let input = textures_3d_input(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(
        out,
        "    // {:?}, side {}, depth {}, mipmapped {}, dir {:?}, ddx {:?}, ddy {:?}, lod {}, layer {}, reference {}",
        input.descriptor,
        input.side,
        input.depth,
        input.mipmapped,
        input.dir,
        input.ddx,
        input.ddy,
        input.lod,
        input.layer,
        input.reference
    );
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_textures_3d(bytes), Ok(()));\n}");
    out
}
