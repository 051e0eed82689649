//! Criterion benchmarks of the rasterizer against euc 0.5.3 on the same scenes at 1024², in the
//! same run (REFERENCES anchors: euc ≈ 17.5 ms for a teapot-sized mesh, ≈ 94 ms for 10k random
//! textured triangles, on this kind of machine):
//!
//! - `torus_6k`: a textured, Lambert-lit torus of 6144 triangles (teapot-sized) filling the view;
//! - `random_10k`: 10 000 small random textured triangles (≈ 20 px across), depth-tested.
//!
//! Both renderers run the same shading: a nearest-texel lookup into a 256² checker (done by hand,
//! as euc's own example does, so the rasterizers are compared, not the samplers) times a Lambert
//! term for the torus. barytex runs single-threaded (a 1-thread rayon pool) and with 2 threads.
//!
//! Run with `cargo bench -p barytex-benches --bench raster`.

use std::hint::black_box;
use std::time::Duration;

use barytex_raster::{CullMode, Fragment, Framebuffer, PipelineState, Shader, draw};
use barytex_texture::Limits;
use criterion::{Criterion, criterion_group, criterion_main};
use euc::Pipeline;
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingDisabled, Triangles};
use glam::{Mat4, Vec2, Vec3, Vec4};

const SIZE: u32 = 1024;
const TEX: usize = 256;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

/// A scene: clip positions, uvs and normals per vertex, triangles as index triples.
struct Scene {
    clip: Vec<Vec4>,
    uv: Vec<Vec2>,
    normal: Vec<Vec3>,
    indices: Vec<u32>,
}

fn checker() -> Vec<u32> {
    (0..TEX * TEX)
        .map(|i| {
            let (x, y) = (i % TEX, i / TEX);
            if (x / 16 + y / 16) % 2 == 0 {
                0xFFE0_E0E0
            } else {
                0xFF20_4080
            }
        })
        .collect()
}

fn texel(texture: &[u32], uv: Vec2) -> u32 {
    let x = ((uv.x * TEX as f32) as usize).min(TEX - 1);
    let y = ((uv.y * TEX as f32) as usize).min(TEX - 1);
    texture[y * TEX + x]
}

fn unpack(c: u32) -> Vec4 {
    Vec4::new(
        ((c >> 16) & 0xff) as f32 / 255.0,
        ((c >> 8) & 0xff) as f32 / 255.0,
        (c & 0xff) as f32 / 255.0,
        1.0,
    )
}

fn torus_scene() -> Scene {
    let mesh = barytex_uv::mesh::torus(96, 32, 1.0, 0.4).expect("valid torus");
    // Vulkan-style perspective (z in [0, 1]), 50° vertical field of view, square image.
    let f = 1.0 / (25_f32.to_radians()).tan();
    let (near, far) = (0.1_f32, 100.0_f32);
    let projection = Mat4::from_cols(
        Vec4::new(f, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, far / (near - far), -1.0),
        Vec4::new(0.0, 0.0, near * far / (near - far), 0.0),
    );
    // Seen from 45° above, 3.1 units away.
    let view = Mat4::from_translation(Vec3::new(0.0, 0.0, -3.1))
        * Mat4::from_rotation_x(45_f32.to_radians());
    let mvp = projection * view;
    Scene {
        clip: mesh.positions.iter().map(|p| mvp * p.extend(1.0)).collect(),
        uv: mesh.uvs.clone(),
        normal: mesh.normals.clone(),
        indices: mesh.indices.iter().flatten().copied().collect(),
    }
}

fn random_scene() -> Scene {
    let mut state = 0x2545_F491_4F6C_DD1D_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut scene = Scene {
        clip: Vec::new(),
        uv: Vec::new(),
        normal: Vec::new(),
        indices: Vec::new(),
    };
    let px = 2.0 / SIZE as f32;
    for _ in 0..10_000 {
        let centre = Vec2::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0);
        let z = next();
        for _ in 0..3 {
            let offset = Vec2::new(next() - 0.5, next() - 0.5) * 20.0 * px;
            let p = centre + offset;
            scene.indices.push(scene.clip.len() as u32);
            scene.clip.push(Vec4::new(p.x, p.y, z, 1.0));
            scene.uv.push(Vec2::new(next(), next()));
            scene.normal.push(Vec3::Z);
        }
    }
    scene
}

/// barytex's side: positions already in clip space.
struct BarytexShader<'a> {
    scene: &'a Scene,
    texture: &'a [u32],
    light: Vec3,
    lit: bool,
}

impl Shader for BarytexShader<'_> {
    type Vertex = u32;
    type Varying = (Vec2, Vec3);
    fn vertex(&self, &i: &u32) -> (Vec4, (Vec2, Vec3)) {
        let i = i as usize;
        (self.scene.clip[i], (self.scene.uv[i], self.scene.normal[i]))
    }
    fn fragment(&self, f: &Fragment<'_, (Vec2, Vec3)>) -> Option<Vec4> {
        let c = unpack(texel(self.texture, f.varying.0));
        Some(if self.lit {
            let lambert = f.varying.1.normalize_or_zero().dot(self.light).max(0.0);
            (c.truncate() * (0.15 + lambert)).extend(1.0)
        } else {
            c
        })
    }
}

/// euc's side: the same data, the same shading, packed ARGB output.
struct EucPipeline<'a> {
    scene: &'a Scene,
    texture: &'a [u32],
    light: Vec3,
    lit: bool,
}

impl Pipeline for EucPipeline<'_> {
    type Vertex = u32;
    type VsOut = (vek::Vec2<f32>, vek::Vec3<f32>);
    type Pixel = u32;
    fn vert(&self, &i: &u32) -> ([f32; 4], Self::VsOut) {
        let i = i as usize;
        let (uv, n) = (self.scene.uv[i], self.scene.normal[i]);
        (
            self.scene.clip[i].to_array(),
            (vek::Vec2::new(uv.x, uv.y), vek::Vec3::new(n.x, n.y, n.z)),
        )
    }
    fn frag(&self, (uv, n): &Self::VsOut) -> u32 {
        let c = texel(self.texture, Vec2::new(uv.x, uv.y));
        if self.lit {
            let n = Vec3::new(n.x, n.y, n.z).normalize_or_zero();
            let k = 0.15 + n.dot(self.light).max(0.0);
            let s = |v: u32| ((v & 0xff) as f32 * k).min(255.0) as u32;
            0xFF00_0000 | s(c >> 16) << 16 | s(c >> 8) << 8 | s(c)
        } else {
            c
        }
    }
}

fn render_barytex(scene: &Scene, texture: &[u32], lit: bool) -> Framebuffer {
    let mut fb = Framebuffer::new(SIZE, SIZE, Vec4::ZERO, &Limits::default()).expect("1024²");
    let shader = BarytexShader {
        scene,
        texture,
        light: Vec3::new(0.3, 0.8, 0.5).normalize(),
        lit,
    };
    let state = PipelineState {
        cull: CullMode::None,
        ..PipelineState::default()
    };
    let vertices: Vec<u32> = (0..scene.clip.len() as u32).collect();
    draw(&mut fb, &shader, &state, &vertices, &scene.indices);
    fb
}

fn render_euc(scene: &Scene, texture: &[u32], lit: bool) -> Buffer2d<u32> {
    let mut color = Buffer2d::new([SIZE as usize, SIZE as usize], 0_u32);
    let mut depth = Buffer2d::new([SIZE as usize, SIZE as usize], 1.0_f32);
    let pipeline = EucPipeline {
        scene,
        texture,
        light: Vec3::new(0.3, 0.8, 0.5).normalize(),
        lit,
    };
    pipeline.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingDisabled>, _>(
        &scene.indices,
        &mut color,
        Some(&mut depth),
    );
    color
}

fn bench(c: &mut Criterion) {
    let texture = checker();
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("pool");
    for (name, scene, lit) in [
        ("torus_6k", torus_scene(), true),
        ("random_10k", random_scene(), false),
    ] {
        let mut group = c.benchmark_group(format!("raster_1024_{name}"));
        group.bench_function("barytex_1_thread", |b| {
            b.iter(|| one.install(|| black_box(render_barytex(&scene, &texture, lit))));
        });
        group.bench_function("barytex_2_threads", |b| {
            b.iter(|| two.install(|| black_box(render_barytex(&scene, &texture, lit))));
        });
        group.bench_function("euc", |b| {
            b.iter(|| black_box(render_euc(&scene, &texture, lit)));
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
