//! Load a PNG, build a linear-light mip chain, sample it with wgpu-style sampler descriptors.
//!
//! Run with `cargo run -p barytex-texture --example mip_chain_png -- [IMAGE.png]`. Without an
//! argument it first writes a 256×256 sRGB test image (one-texel horizontal black-and-white
//! stripes) to the temporary folder and loads that.

use barytex_texture::load::{AnyTexture2d, ColorSpace, load_from_path, save_png};
use barytex_texture::sampler::{AddressMode, AnisotropicFilter};
use barytex_texture::{
    Limits, MipChain, MipColorSpace, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texel,
    Texture2d, TextureError, TextureSampler,
};
use glam::Vec2;

fn main() -> Result<(), TextureError> {
    let path = match std::env::args_os().nth(1) {
        Some(path) => path.into(),
        None => {
            // One-texel horizontal stripes, white on even rows: the worst case for minification.
            let stripes = Texture2d::from_fn(256, 256, |_, y| {
                Srgba8(if y % 2 == 0 {
                    [255, 255, 255, 255]
                } else {
                    [0, 0, 0, 255]
                })
            })?;
            let path =
                std::env::temp_dir().join(format!("barytex-stripes-{}.png", std::process::id()));
            save_png(&stripes, &path)?;
            path
        }
    };
    // The header is checked against the limits before a single pixel is decoded.
    let limits = Limits::default();
    let texture = load_from_path(&path, ColorSpace::Srgb, &limits)?;
    let (width, height) = texture.size();
    println!("loaded {} ({width}×{height})", path.display());
    match texture {
        AnyTexture2d::Srgba8(t) => show(t),
        AnyTexture2d::Rgba8(t) => show(t),
        AnyTexture2d::R8(t) => show(t),
        AnyTexture2d::Rgba16f(t) => show(t),
        AnyTexture2d::Rgba32f(t) => show(t),
        other => show(other.to_rgba32f()?),
    }
}

fn show<T: Texel>(base: Texture2d<T>) -> Result<(), TextureError> {
    // Linear light (the default): sRGB is decoded, alpha premultiplied, then box-filtered.
    let chain = MipChain::generate(base.clone(), &MipOptions::default())?;
    let naive = MipOptions {
        color_space: MipColorSpace::SrgbNaive,
        ..MipOptions::default()
    };
    let naive_chain = MipChain::generate(base, &naive)?;
    let last = chain.len() - 1;
    let mean = |c: &MipChain<T>| {
        c.level(last)
            .and_then(|l| l.texel(0, 0))
            .map(Texel::to_linear)
    };
    println!(
        "{} levels; the 1×1 level holds {:.3} in linear light (an sRGB-naive chain: {:.3})",
        chain.len(),
        mean(&chain).unwrap_or_default(),
        mean(&naive_chain).unwrap_or_default()
    );

    let (w, h) = chain.level(0).map(Texture2d::size).unwrap_or((1, 1));
    let texel = Vec2::new(1.0 / w as f32, 1.0 / h as f32);
    // A pixel whose footprint is 8 texels wide and 1 texel tall (a floor seen at a grazing
    // angle), centred on texel (w/2, h/2): over the generated stripes it covers one white row,
    // so a filter that follows the footprint reads white, and one that blurs isotropically
    // (trilinear picks the level of the longer axis) reads grey.
    let uv = (Vec2::new((w / 2) as f32, (h / 2) as f32) + 0.5) * texel;
    let (ddx, ddy) = (Vec2::new(8.0, 0.0) * texel, Vec2::new(0.0, 1.0) * texel);
    let repeat = |d: SamplerDescriptor| SamplerDescriptor {
        address_mode_u: AddressMode::Repeat,
        address_mode_v: AddressMode::Repeat,
        ..d
    };
    let descriptors = [
        ("nearest", repeat(SamplerDescriptor::default())),
        ("bilinear", repeat(SamplerDescriptor::bilinear())),
        ("trilinear", repeat(SamplerDescriptor::trilinear())),
        (
            "anisotropic ×16",
            repeat(SamplerDescriptor::anisotropic(16)),
        ),
        (
            "EWA ×16",
            repeat(SamplerDescriptor {
                anisotropic_filter: AnisotropicFilter::Ewa,
                ..SamplerDescriptor::anisotropic(16)
            }),
        ),
    ];
    println!("one pixel covering 8×1 texels at uv {uv:.4}:");
    for (name, descriptor) in descriptors {
        let sampler = TextureSampler::new(chain.clone(), descriptor);
        let colour = sampler.sample(uv, ddx, ddy);
        println!(
            "  {name:<17} lod {:5.2} -> linear rgba {colour:.3}",
            sampler.lod(ddx, ddy, 0.0)
        );
    }
    Ok(())
}
