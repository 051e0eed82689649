//! Reading a rendered target out as an 8-bit sRGB image (`Framebuffer::to_srgba8`: resolve the
//! samples, un-premultiply, encode with the correctly rounded sRGB table), beside a same-result
//! minimal kernel kept here: `Framebuffer::pixel` for every pixel, row by row, then
//! `Srgba8::from_linear` — the formula `to_srgba8` must match bit for bit (checked on every
//! pixel before timing). Both on one thread, both allocating their output.
//!
//! Targets: 1024² with one sample per pixel (a `barytex render` frame) and 960×540 with four
//! (the demo's MSAA), filled by drawing colour gradients with translucent triangles over them.
//!
//! Run with `cargo bench -p barytex-benches --bench resolve`.

use std::hint::black_box;
use std::time::Duration;

use barytex_raster::{
    Blend, Fragment, Framebuffer, PipelineState, SamplePattern, Shader, TargetLimits, draw,
};
use barytex_texture::{Srgba8, Texel, Texture2d};
use criterion::{Criterion, criterion_group, criterion_main};
use glam::{Vec3, Vec4};

fn config() -> Criterion {
    Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2))
}

/// Vertices carry their colour; positions are already in clip space.
struct Gradient;

impl Shader for Gradient {
    type Vertex = (Vec3, Vec4);
    type Varying = Vec4;
    fn vertex(&self, v: &(Vec3, Vec4)) -> (Vec4, Vec4) {
        (v.0.extend(1.0), v.1)
    }
    fn fragment(&self, f: &Fragment<'_, Vec4>) -> Option<Vec4> {
        Some(f.varying)
    }
}

/// A `width × height` target with `pattern`: an opaque full-screen gradient, then a fan of
/// translucent triangles blended over it (so pixels on their edges mix samples).
fn painted(width: u32, height: u32, pattern: SamplePattern) -> Framebuffer {
    let mut fb =
        Framebuffer::multisampled(width, height, pattern, Vec4::ZERO, &TargetLimits::default())
            .expect("the bench's targets fit the default limits");
    let corner = |x: f32, y: f32, c: [f32; 4]| (Vec3::new(x, y, 0.5), Vec4::from_array(c));
    // In front of the gradient, so the depth test passes.
    let front = |x: f32, y: f32, c: [f32; 4]| (Vec3::new(x, y, 0.25), Vec4::from_array(c));
    let quad = [
        corner(-1.0, -1.0, [0.9, 0.1, 0.0, 1.0]),
        corner(1.0, -1.0, [0.0, 0.8, 0.2, 1.0]),
        corner(1.0, 1.0, [0.1, 0.2, 1.0, 1.0]),
        corner(-1.0, 1.0, [1.0, 1.0, 1.0, 1.0]),
    ];
    draw(
        &mut fb,
        &Gradient,
        &PipelineState::default(),
        &quad,
        &[0, 1, 2, 0, 2, 3],
    );
    let mut fan = vec![front(0.0, 0.0, [1.0, 1.0, 0.0, 0.6])];
    for k in 0..=24 {
        let a = k as f32 / 24.0 * std::f32::consts::TAU;
        let alpha = 0.2 + 0.7 * (k % 3) as f32 / 2.0;
        fan.push(front(0.9 * a.cos(), 0.9 * a.sin(), [0.3, 0.0, 0.9, alpha]));
    }
    let indices: Vec<u32> = (1..25).flat_map(|k| [0, k, k + 1]).collect();
    let blended = PipelineState {
        blend: Blend::Over,
        ..PipelineState::default()
    };
    draw(&mut fb, &Gradient, &blended, &fan, &indices);
    fb
}

/// The minimal kernel: every pixel through `Framebuffer::pixel`, encoded.
fn pixel_by_pixel(fb: &Framebuffer) -> Texture2d<Srgba8> {
    let (w, h) = (fb.width(), fb.height());
    let mut texels = Vec::with_capacity(w as usize * h as usize);
    for y in 0..h {
        for x in 0..w {
            texels.push(Srgba8::from_linear(fb.pixel(x, y).expect("inside")));
        }
    }
    Texture2d::from_texels(w, h, texels).expect("the target's size")
}

fn bench(c: &mut Criterion) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    for (name, w, h, pattern) in [
        ("1024x1024_1_sample", 1024, 1024, SamplePattern::CENTRE),
        (
            "960x540_msaa4",
            960,
            540,
            SamplePattern::Standard { count: 4 },
        ),
    ] {
        let fb = painted(w, h, pattern);
        let ours = pool.install(|| fb.to_srgba8()).expect("fits in memory");
        let kernel = pixel_by_pixel(&fb);
        assert!(
            ours == kernel,
            "{name}: to_srgba8 differs from the per-pixel formula"
        );
        let mut group = c.benchmark_group(format!("to_srgba8_{name}"));
        group.bench_function("barytex_to_srgba8", |b| {
            b.iter(|| pool.install(|| black_box(fb.to_srgba8())));
        });
        group.bench_function("kernel_pixel_by_pixel", |b| {
            b.iter(|| black_box(pixel_by_pixel(&fb)));
        });
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
