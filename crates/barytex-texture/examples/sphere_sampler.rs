//! A uv mapping with derivatives feeding a sampler: ray-trace a unit sphere, map each pixel's
//! surface point (with its screen-space derivatives) through barytex-uv's equirectangular sphere
//! mapping, and let an anisotropic sampler over a linear-light mip chain pick the footprint.
//! Writes the picture, and the same picture point-sampled (aliased), as PNGs.
//!
//! Run with `cargo run -p barytex-texture --example sphere_sampler -- [OUT_DIR]` (default: the
//! temporary folder).

use barytex_texture::load::save_png;
use barytex_texture::sampler::AddressMode;
use barytex_texture::{
    MipChain, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texel, Texture2d, TextureError,
    TextureSampler,
};
use barytex_uv::mappings::{SphereProjection, Spherical};
use barytex_uv::{SurfacePoint, UvMapping};
use glam::{Vec3, Vec4};

const SIZE: u32 = 256;
const EYE: Vec3 = Vec3::new(0.0, 0.0, 3.0);

/// The view ray through pixel `(x, y)`: a pinhole looking down −z, vertical field of view ~45°.
fn ray(x: f32, y: f32) -> Vec3 {
    let f = SIZE as f32 / (2.0 * 0.414);
    Vec3::new(
        (x - SIZE as f32 / 2.0) / f,
        -(y - SIZE as f32 / 2.0) / f,
        -1.0,
    )
    .normalize()
}

/// The unit sphere's surface seen through pixel `(x, y)`, with `∂p/∂x` and `∂p/∂y` from the
/// neighbouring pixels' rays meeting the tangent plane (pbrt-v4, §10.1.1).
fn surface_point(x: f32, y: f32) -> Option<SurfacePoint> {
    let d = ray(x, y);
    let b = EYE.dot(d);
    let disc = b * b - (EYE.length_squared() - 1.0);
    if disc < 0.0 {
        return None;
    }
    let p = EYE + d * (-b - disc.sqrt());
    let n = p.normalize();
    let on_plane = |d: Vec3| EYE + d * (n.dot(p - EYE) / n.dot(d)) - p;
    Some(SurfacePoint::with_derivatives(
        p,
        n,
        on_plane(ray(x + 1.0, y)),
        on_plane(ray(x, y + 1.0)),
    ))
}

fn render(
    sampler: &impl Sampler,
    mapping: &impl UvMapping,
) -> Result<Texture2d<Srgba8>, TextureError> {
    let background = Vec4::new(0.05, 0.05, 0.08, 1.0);
    Texture2d::from_fn(SIZE, SIZE, |x, y| {
        let colour = surface_point(x as f32 + 0.5, y as f32 + 0.5)
            .and_then(|point| mapping.map(&point))
            .map_or(background, |s| sampler.sample(s.uv, s.duvdx, s.duvdy));
        Srgba8::from_linear(colour)
    })
}

fn main() -> Result<(), TextureError> {
    let out = std::env::args_os()
        .nth(1)
        .map_or_else(std::env::temp_dir, Into::into);
    // An equirectangular checkerboard, 256×128 checks of 4 texels: around the silhouette a
    // pixel covers many checks.
    let checks = Texture2d::from_fn(1024, 512, |x, y| {
        Srgba8(if (x / 4 + y / 4) % 2 == 0 {
            [230, 200, 60, 255]
        } else {
            [30, 60, 160, 255]
        })
    })?;
    let chain = MipChain::generate(checks, &MipOptions::default())?;
    let mapping =
        Spherical::new(1.0, SphereProjection::Equirectangular).expect("radius 1 is valid");
    let wrap = |d: SamplerDescriptor| SamplerDescriptor {
        address_mode_u: AddressMode::Repeat,
        ..d
    };

    let filtered = TextureSampler::new(chain.clone(), wrap(SamplerDescriptor::anisotropic(16)));
    let aliased = TextureSampler::single_level(
        chain.level(0).cloned().expect("a chain has a base level"),
        wrap(SamplerDescriptor::default()),
    );
    for (name, picture) in [
        ("filtered", render(&filtered, &mapping)?),
        ("aliased", render(&aliased, &mapping)?),
    ] {
        let path = out.join(format!("barytex-sphere-{name}.png"));
        save_png(&picture, &path)?;
        // Aliasing shows as pixel-to-pixel noise: the mean difference between horizontal
        // neighbours on the sphere is far larger point-sampled than filtered.
        let mut sum = 0.0;
        let mut count = 0u32;
        for y in 0..SIZE {
            for x in 1..SIZE {
                let (a, b) = (picture.texel(x - 1, y), picture.texel(x, y));
                if let (Some(a), Some(b)) = (a, b)
                    && surface_point(x as f32 - 0.5, y as f32 + 0.5).is_some()
                    && surface_point(x as f32 + 0.5, y as f32 + 0.5).is_some()
                {
                    sum += (a.to_linear() - b.to_linear()).truncate().length();
                    count += 1;
                }
            }
        }
        println!(
            "{name:>8}: {} (mean neighbour difference {:.3})",
            path.display(),
            sum / count as f32
        );
    }
    Ok(())
}
