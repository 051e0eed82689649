//! Light a mesh with Phong and a normal map: a torus from barytex-uv, MikkTSpace tangents, a
//! procedural normal map (a grid of round studs) in a linear-light mip chain, two lights, drawn
//! by barytex-raster with 4× MSAA into a PNG, beside the same torus without the map.
//!
//! Run with `cargo run -p barytex-shade --example normal_mapped_torus -- [OUT_DIR]` (default:
//! the temporary folder).

use barytex_raster::{Framebuffer, PipelineState, SamplePattern, TargetLimits, draw};
use barytex_shade::{
    Attenuation, Camera, Light, PhongMaterial, ShadeContext, SurfaceShader, ViewVector,
    generate_tangents, mesh_vertices,
};
use barytex_texture::load::save_png;
use barytex_texture::sampler::AddressMode;
use barytex_texture::{MipChain, MipOptions, Rgba8, SamplerDescriptor, Texture2d, TextureSampler};
use glam::{Vec2, Vec3, Vec4};

/// A tangent-space normal map of round studs, 32 texels apart, stored linear (not sRGB: sRGB
/// decoding would bend the vectors).
fn studs() -> Result<Texture2d<Rgba8>, barytex_texture::TextureError> {
    Texture2d::from_fn(256, 256, |x, y| {
        let cell = Vec2::new((x % 32) as f32 + 0.5, (y % 32) as f32 + 0.5) / 32.0 - 0.5;
        let r = cell.length();
        // A hemispherical stud of radius 0.35 cells: its normal tilts outwards with the slope.
        let n = if r < 0.35 {
            let z = (0.35f32 * 0.35 - r * r).sqrt();
            Vec3::new(cell.x, -cell.y, z).normalize()
        } else {
            Vec3::Z
        };
        let encode = |c: f32| ((c * 0.5 + 0.5) * 255.0).round() as u8;
        Rgba8([encode(n.x), encode(n.y), encode(n.z), 255])
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args_os()
        .nth(1)
        .map_or_else(std::env::temp_dir, Into::into);
    let mut torus = barytex_uv::mesh::torus(96, 48, 1.0, 0.4)?;
    // MikkTSpace tangents, what glTF asks for when a normal-mapped mesh comes without them.
    torus.tangents = generate_tangents(&torus).ok_or("MikkTSpace found no tangents")?;
    let (vertices, indices) = mesh_vertices(&torus);

    let (width, height) = (400, 300);
    let scene = ShadeContext {
        camera: Camera::look_at(
            Vec3::new(0.0, 2.2, 2.6),
            Vec3::ZERO,
            Vec3::Y,
            45f32.to_radians(),
            width as f32 / height as f32,
            0.1,
            20.0,
        )
        .ok_or("a regular camera")?,
        lights: vec![
            Light::Directional {
                direction: Vec3::new(-1.0, -1.0, -0.5).normalize(),
                color: Vec3::splat(0.8),
            },
            Light::Point {
                position: Vec3::new(1.5, 1.0, 1.5),
                color: Vec3::new(1.0, 0.7, 0.4) * 2.0,
                attenuation: Attenuation::default(),
            },
        ],
        ambient: Vec3::splat(0.08),
        material: PhongMaterial {
            diffuse: Vec3::new(0.55, 0.2, 0.15),
            ambient: Vec3::new(0.55, 0.2, 0.15),
            specular: Vec3::splat(0.4),
            shininess: 40.0,
            ..PhongMaterial::default()
        },
        view: ViewVector::Local,
    };
    let normal_map = TextureSampler::new(
        MipChain::generate(studs()?, &MipOptions::default())?,
        SamplerDescriptor {
            address_mode_u: AddressMode::Repeat,
            address_mode_v: AddressMode::Repeat,
            ..SamplerDescriptor::anisotropic(8)
        },
    );
    let shaders = [
        ("plain", SurfaceShader::new(&scene)),
        (
            "normal-mapped",
            SurfaceShader {
                normal_map: Some(&normal_map),
                ..SurfaceShader::new(&scene)
            },
        ),
    ];
    for (name, shader) in shaders {
        let mut target = Framebuffer::multisampled(
            width,
            height,
            SamplePattern::Standard { count: 4 },
            Vec4::new(0.1, 0.1, 0.12, 1.0),
            &TargetLimits::default(),
        )?;
        let stats = draw(
            &mut target,
            &shader,
            &PipelineState::default(),
            &vertices,
            &indices,
        );
        let path = out.join(format!("barytex-torus-{name}.png"));
        save_png(&target.to_srgba8()?, &path)?;
        println!(
            "{name:>14}: {} fragments shaded -> {}",
            stats.fragments_shaded,
            path.display()
        );
    }
    Ok(())
}
