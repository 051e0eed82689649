//! Draw a textured triangle with a custom `Shader` into a PNG.
//!
//! A floor triangle in perspective, its uvs interpolated perspective-correctly; the fragment
//! stage reads the uvs' exact screen derivatives (`Fragment::ddx`, `ddy`) and hands them to an
//! anisotropic barytex-texture sampler over a linear-light mip chain; 4× MSAA.
//!
//! Run with `cargo run -p barytex-raster --features texture --example textured_triangle --
//! [OUT.png]` (default: `barytex-textured-triangle.png` in the temporary folder).

use barytex_raster::{
    Fragment, Framebuffer, PipelineState, SamplePattern, Shader, TargetLimits, draw,
};
use barytex_texture::load::save_png;
use barytex_texture::sampler::AddressMode;
use barytex_texture::{
    MipChain, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texture2d, TextureSampler,
};
use glam::{Mat4, Vec2, Vec3, Vec4};

/// A vertex: a world-space position and a texture coordinate.
struct Vertex {
    position: Vec3,
    uv: Vec2,
}

/// The shader's uniforms: the camera and the texture.
struct Textured {
    view_projection: Mat4,
    sampler: TextureSampler<Srgba8>,
}

impl Shader for Textured {
    type Vertex = Vertex;
    type Varying = Vec2;

    fn vertex(&self, v: &Vertex) -> (Vec4, Vec2) {
        (self.view_projection * v.position.extend(1.0), v.uv)
    }

    fn fragment(&self, f: &Fragment<'_, Vec2>) -> Option<Vec4> {
        // The uvs' change per pixel, exact (not a 2×2-quad difference): the sampler's footprint.
        let (ddx, ddy) = f.derivatives();
        Some(self.sampler.sample(f.varying, ddx, ddy))
    }
}

/// A right-handed perspective projection into Vulkan/wgpu clip space (depth 0 at `near`, 1 at
/// `far`).
fn perspective(fov_y: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let f = 1.0 / (fov_y / 2.0).tan();
    let depth = far / (near - far);
    Mat4::from_cols(
        Vec4::new(f / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, depth, -1.0),
        Vec4::new(0.0, 0.0, near * depth, 0.0),
    )
}

/// The view matrix of an eye at `eye` looking at `target`, +y up.
fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
    let forward = (target - eye).normalize();
    let right = forward.cross(Vec3::Y).normalize();
    let up = right.cross(forward);
    Mat4::from_cols(
        Vec4::new(right.x, up.x, -forward.x, 0.0),
        Vec4::new(right.y, up.y, -forward.y, 0.0),
        Vec4::new(right.z, up.z, -forward.z, 0.0),
        Vec4::new(-right.dot(eye), -up.dot(eye), forward.dot(eye), 1.0),
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args_os().nth(1).map_or_else(
        || std::env::temp_dir().join("barytex-textured-triangle.png"),
        Into::into,
    );
    // A 256×256 sRGB checkerboard of 8×8 squares, repeated 16 times across the triangle.
    let checks = Texture2d::from_fn(256, 256, |x, y| {
        Srgba8(if (x / 32 + y / 32) % 2 == 0 {
            [235, 235, 225, 255]
        } else {
            [40, 90, 60, 255]
        })
    })?;
    let sampler = TextureSampler::new(
        MipChain::generate(checks, &MipOptions::default())?,
        SamplerDescriptor {
            address_mode_u: AddressMode::Repeat,
            address_mode_v: AddressMode::Repeat,
            ..SamplerDescriptor::anisotropic(16)
        },
    );
    let (width, height) = (480, 270);
    let projection = perspective(50f32.to_radians(), width as f32 / height as f32, 0.1, 100.0);
    let view = look_at(Vec3::new(0.0, 1.0, 2.0), Vec3::new(0.0, 0.0, -6.0));
    let shader = Textured {
        view_projection: projection * view,
        sampler,
    };
    let floor = [
        Vertex {
            position: Vec3::new(-4.0, 0.0, 1.0),
            uv: Vec2::new(0.0, 0.0),
        },
        Vertex {
            position: Vec3::new(4.0, 0.0, 1.0),
            uv: Vec2::new(8.0, 0.0),
        },
        Vertex {
            position: Vec3::new(0.0, 0.0, -30.0),
            uv: Vec2::new(4.0, 16.0),
        },
    ];
    let mut target = Framebuffer::multisampled(
        width,
        height,
        SamplePattern::Standard { count: 4 },
        Vec4::new(0.45, 0.6, 0.85, 1.0),
        &TargetLimits::default(),
    )?;
    let state = PipelineState::default();
    // Seen from above, near-left → near-right → far is counter-clockwise: the front face.
    let stats = draw(&mut target, &shader, &state, &floor, &[0, 1, 2]);
    println!(
        "{} triangles in, {} fragments shaded, {} culled",
        stats.triangles_in, stats.fragments_shaded, stats.culled
    );
    save_png(&target.to_srgba8()?, &out)?;
    println!("wrote {}", out.display());
    Ok(())
}
