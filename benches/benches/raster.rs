//! Criterion benchmarks of the rasterizer against euc 0.5.3 on the same scenes at 1024², in the
//! same run (for scale: when the project set its speed targets, euc took ≈ 17.5 ms for a
//! teapot-sized mesh and ≈ 94 ms for 10k random textured triangles on this kind of machine):
//!
//! - `torus_6k`: a textured, Lambert-lit torus of 6144 triangles (teapot-sized) filling the view;
//! - `random_10k`: 10 000 small random textured triangles (≈ 20 px across), depth-tested.
//!
//! Both renderers run the same shading: a nearest-texel lookup into a 256² checker (done by hand,
//! as euc's own example does, so the rasterizers are compared, not the samplers) times a Lambert
//! term for the torus. barytex runs single-threaded (a 1-thread rayon pool) and with 2 threads.
//!
//! The `raster_only_*` groups isolate rasterization: a constant shader with one (unused)
//! interpolated float and the same colour format on both sides, depth-tested — 4 bytes
//! (barytex's `Rgba8Unorm` beside euc writing the same `u32`) and 16 bytes (RGBA f32 on both
//! sides). The targets are allocated once, outside the timed loop, and cleared (colour and
//! depth) in every iteration on both sides; `barytex_rgba8_draw_cleared` draws the same with
//! barytex's `draw_cleared`, which clears each tile just before drawing it (the same bytes).
//!
//! Run with `cargo bench -p barytex-benches --bench raster`.

mod common;

use std::hint::black_box;
use std::time::Duration;

use barytex_raster::{LinearRgba32f, Rgba8Unorm};
use common::{
    ClipMesh, FLAT, NearestTexture, barytex_target, euc_targets, flat_u32, random_scene,
    raster_only_barytex, raster_only_barytex_draw_cleared, raster_only_euc, render_barytex,
    render_euc,
};
use criterion::{Criterion, criterion_group, criterion_main};
use glam::{Mat4, Vec3};

const SIZE: u32 = 1024;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

fn torus_scene() -> ClipMesh {
    let mesh = barytex_uv::mesh::torus(96, 32, 1.0, 0.4).expect("valid torus");
    // Depth in [0, w], y up (glam's DirectX convention), 50° vertical field of view, square image.
    let projection =
        glam::camera::rh::proj::directx::perspective(50_f32.to_radians(), 1.0, 0.1, 100.0);
    // Seen from 45° above, 3.1 units away.
    let view = Mat4::from_translation(Vec3::new(0.0, 0.0, -3.1))
        * Mat4::from_rotation_x(45_f32.to_radians());
    let mvp = projection * view;
    ClipMesh {
        clip: mesh.positions.iter().map(|p| mvp * p.extend(1.0)).collect(),
        uv: mesh.uvs.clone(),
        normal: mesh.normals.clone(),
        indices: mesh.indices.iter().flatten().copied().collect(),
    }
}

fn bench(c: &mut Criterion) {
    let texture = NearestTexture::checker(256, 16);
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
        ("random_10k", random_scene(SIZE), false),
    ] {
        let mut group = c.benchmark_group(format!("raster_1024_{name}"));
        group.bench_function("barytex_1_thread", |b| {
            b.iter(|| one.install(|| black_box(render_barytex(&scene, &texture, lit, SIZE))));
        });
        group.bench_function("barytex_2_threads", |b| {
            b.iter(|| two.install(|| black_box(render_barytex(&scene, &texture, lit, SIZE))));
        });
        group.bench_function("euc", |b| {
            b.iter(|| black_box(render_euc(&scene, &texture, lit, SIZE)));
        });
        group.finish();
        // Rasterization alone: a constant shader and the same colour format on both sides, so
        // the shared shader's divisions and lookups do not hide the rasterizers; targets
        // allocated once, cleared per iteration on both sides.
        let vertices: Vec<u32> = (0..scene.clip.len() as u32).collect();
        let mut group = c.benchmark_group(format!("raster_only_1024_{name}"));
        let mut fb8 = barytex_target::<Rgba8Unorm>(SIZE);
        let mut euc8 = euc_targets(SIZE, 0_u32);
        let mut fb16 = barytex_target::<LinearRgba32f>(SIZE);
        let mut euc16 = euc_targets(SIZE, [0.0_f32; 4]);
        group.bench_function("barytex_rgba8", |b| {
            b.iter(|| one.install(|| raster_only_barytex(&scene, &vertices, &mut fb8)));
        });
        group.bench_function("barytex_rgba8_draw_cleared", |b| {
            b.iter(|| {
                one.install(|| raster_only_barytex_draw_cleared(&scene, &vertices, &mut fb8))
            });
        });
        group.bench_function("euc_u32", |b| {
            b.iter(|| raster_only_euc(&scene, flat_u32(), 0, &mut euc8));
        });
        group.bench_function("barytex_f32x4", |b| {
            b.iter(|| one.install(|| raster_only_barytex(&scene, &vertices, &mut fb16)));
        });
        group.bench_function("euc_f32x4", |b| {
            b.iter(|| raster_only_euc(&scene, FLAT, [0.0; 4], &mut euc16));
        });
        group.finish();
        // Both sides drew the same bytes over (nearly) the same pixels: the fill rules differ
        // only on edges through pixel centres.
        let ours = (0..SIZE * SIZE)
            .filter(|i| fb8.stored(i % SIZE, i / SIZE) == Some(flat_u32().to_le_bytes()))
            .count();
        let theirs = euc8.0.as_ref().iter().filter(|&&p| p == flat_u32()).count();
        eprintln!("raster_only_1024_{name}: covered pixels barytex {ours}, euc {theirs}");
        black_box((&fb16, &euc16));
    }
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
