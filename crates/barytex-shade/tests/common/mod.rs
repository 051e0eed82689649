//! Shared scene and image comparison for the shader tests.
#![allow(dead_code, unreachable_pub)]

use barytex_raster::TargetLimits;
use barytex_raster::{Framebuffer, PipelineState, Shader, draw};
use barytex_shade::{Camera, Light, PhongMaterial, ShadeContext, ViewVector};
use glam::{Vec3, Vec4};

pub const SIZE: u32 = 128;

/// A unit sphere seen from z = 3, one directional light from the upper left front.
pub fn scene() -> ShadeContext {
    ShadeContext {
        camera: Camera::look_at(
            Vec3::new(0.0, 0.0, 3.0),
            Vec3::ZERO,
            Vec3::Y,
            45f32.to_radians(),
            1.0,
            0.1,
            10.0,
        )
        .expect("regular"),
        lights: vec![Light::Directional {
            direction: Vec3::new(1.0, -1.0, -1.5),
            color: Vec3::ONE,
        }],
        ambient: Vec3::splat(0.1),
        material: PhongMaterial {
            diffuse: Vec3::new(0.6, 0.4, 0.3),
            ambient: Vec3::new(0.6, 0.4, 0.3),
            specular: Vec3::splat(0.5),
            shininess: 40.0,
            ..PhongMaterial::default()
        },
        view: ViewVector::Local,
    }
}

pub fn render<S: Shader>(shader: &S, vertices: &[S::Vertex], indices: &[u32]) -> Framebuffer {
    let mut fb = Framebuffer::new(SIZE, SIZE, Vec4::ZERO, &TargetLimits::default()).expect("small");
    draw(
        &mut fb,
        shader,
        &PipelineState::default(),
        vertices,
        indices,
    );
    fb
}

/// Mean and max over the pixels both images cover of the largest channel difference.
pub fn error(a: &Framebuffer, b: &Framebuffer) -> (f64, f64, usize) {
    let (mut sum, mut max, mut n) = (0.0, 0.0f64, 0usize);
    for y in 0..a.height() {
        for x in 0..a.width() {
            let (p, q) = (a.pixel(x, y).expect("in"), b.pixel(x, y).expect("in"));
            if p.w == 0.0 || q.w == 0.0 {
                continue;
            }
            let d = f64::from((p.truncate() - q.truncate()).abs().max_element());
            sum += d;
            max = max.max(d);
            n += 1;
        }
    }
    (sum / n.max(1) as f64, max, n)
}

/// A framebuffer holding `pixels` (others transparent), drawn as one quad per pixel.
pub fn from_pixels(size: u32, pixels: &[(u32, u32, Vec4)]) -> Framebuffer {
    struct Px;
    impl Shader for Px {
        type Vertex = (glam::Vec2, Vec4);
        type Varying = Vec4;
        fn vertex(&self, v: &(glam::Vec2, Vec4)) -> (Vec4, Vec4) {
            (Vec4::new(v.0.x, v.0.y, 0.5, 1.0), v.1)
        }
        fn fragment(&self, f: &barytex_raster::Fragment<'_, Vec4>) -> Option<Vec4> {
            Some(f.varying)
        }
    }
    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    let s = size as f32;
    for &(x, y, c) in pixels {
        let ndc = |px: f32, py: f32| glam::Vec2::new(px / s * 2.0 - 1.0, 1.0 - py / s * 2.0);
        let base = vertices.len() as u32;
        let (x, y) = (x as f32, y as f32);
        vertices.extend([
            (ndc(x, y + 1.0), c),
            (ndc(x + 1.0, y + 1.0), c),
            (ndc(x + 1.0, y), c),
            (ndc(x, y), c),
        ]);
        indices.extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }
    let mut fb = Framebuffer::new(size, size, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let state = PipelineState {
        cull: barytex_raster::CullMode::None,
        depth_compare: None,
        ..PipelineState::default()
    };
    draw(&mut fb, &Px, &state, &vertices, &indices);
    fb
}
