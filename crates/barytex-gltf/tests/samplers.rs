//! glTF samplers as barytex-texture reads them: every magnification × minification pair of
//! the non-mipmapped filters, against hand-computed values (glTF 2.0 §3.8.4 "Samplers" and
//! OpenGL 4.6 §8.14: the minification filter applies whenever the level of detail is positive,
//! even when the texture has no mip levels).

use barytex_gltf::{MagFilter, MinFilter, SamplerParams};
use barytex_texture::{R32f, Sampler, Texture2d, TextureSampler};
use glam::Vec2;

/// 4 × 4 texels whose value is the column index: a ramp along u.
fn ramp() -> Texture2d<R32f> {
    Texture2d::from_fn(4, 4, |x, _| R32f(x as f32)).expect("small")
}

fn sample(mag_filter: MagFilter, min_filter: MinFilter, footprint: f32) -> f32 {
    let params = SamplerParams {
        mag_filter,
        min_filter,
        ..SamplerParams::default()
    };
    let sampler = TextureSampler::single_level(ramp(), params.to_descriptor());
    // u·4 − ½ = 0.7: nearest reads column 1, linear blends columns 0 and 1 at 0.7.
    let uv = Vec2::new(0.3, 0.5);
    let d = footprint / 4.0;
    sampler.sample(uv, Vec2::new(d, 0.0), Vec2::new(0.0, d)).x
}

#[test]
fn minified_lookups_use_the_min_filter_without_mipmaps() {
    use MagFilter as Mag;
    use MinFilter as Min;
    // Two texels per pixel (λ = 1): the minification filter decides.
    assert_eq!(sample(Mag::Nearest, Min::Nearest, 2.0), 1.0);
    assert_eq!(sample(Mag::Linear, Min::Nearest, 2.0), 1.0);
    assert!((sample(Mag::Nearest, Min::Linear, 2.0) - 0.7).abs() < 1e-6);
    assert!((sample(Mag::Linear, Min::Linear, 2.0) - 0.7).abs() < 1e-6);
    // A quarter texel per pixel (λ = −2): the magnification filter decides.
    assert_eq!(sample(Mag::Nearest, Min::Linear, 0.25), 1.0);
    assert!((sample(Mag::Linear, Min::Nearest, 0.25) - 0.7).abs() < 1e-6);
}

/// With mipmaps, a 2× minified lookup reads level 1 (columns 0.5 and 2.5 averaged pairwise).
#[test]
fn mipmapped_samplers_still_read_their_levels() {
    let params = SamplerParams {
        min_filter: MinFilter::NearestMipmapNearest,
        ..SamplerParams::default()
    };
    assert!(params.uses_mipmaps());
    let chain =
        barytex_texture::MipChain::generate(ramp(), &barytex_texture::MipOptions::default())
            .expect("small");
    let sampler = TextureSampler::new(chain, params.to_descriptor());
    let got = sampler
        .sample(
            Vec2::new(0.3, 0.5),
            Vec2::new(0.5, 0.0),
            Vec2::new(0.0, 0.5),
        )
        .x;
    // λ = 1 → level 1 (2 × 2); u·2 − ½ = 0.1 → its column 0, the mean of columns 0 and 1.
    assert!((got - 0.5).abs() < 1e-6, "{got}");
}
