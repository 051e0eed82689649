//! The glTF sample models Avocado and Suzanne at 1024², beside euc 0.5.3 in the same run.
//!
//! For each model, under the documented automatic camera (`barytex_render::auto_camera`):
//!
//! - `barytex_draw_1_thread` / `_2_threads` and `euc`: the model's triangles in clip space, drawn
//!   depth-tested without culling, shaded by the same hand-written nearest lookup of the model's
//!   base colour texture times a Lambert term — the rasterizers compared on real meshes;
//! - `barytex_render_unlit_1_thread`: barytex's whole renderer (`render` with `Shading::Unlit`,
//!   nearest filtering, no anti-aliasing), texture preparation included — what `barytex render
//!   --shading unlit --filter nearest --aa none` costs, for scale (euc has no such renderer).
//!
//! Without the glTF sample models (`$BARYTEX_FIXTURES`, else `../shared/fixtures`: see
//! `barytex_testkit::fixtures_dir`) it prints a note and measures nothing.
//!
//! Run with `cargo bench -p barytex-benches --bench scene`.

mod common;

use std::hint::black_box;
use std::time::Duration;

use barytex_gltf::{LoadOptions, Scene, load_path};
use barytex_render::{AntiAliasing, CameraChoice, Filter, RenderOptions, Shading};
use barytex_texture::load::AnyTexture2d;
use common::{ClipMesh, NearestTexture, render_barytex, render_euc};
use criterion::{Criterion, criterion_group, criterion_main};
use glam::{Vec2, Vec3};

const SIZE: u32 = 1024;

fn config() -> Criterion {
    Criterion::default()
        .sample_size(10)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

fn load(relative: &str) -> Option<Scene> {
    let Some(fixtures) = barytex_testkit::fixtures_dir() else {
        eprintln!("skipped {relative}: the shared fixtures are absent");
        return None;
    };
    match load_path(
        fixtures.join("gltf").join(relative),
        &LoadOptions::default(),
    ) {
        Ok(scene) => Some(scene),
        Err(e) => {
            eprintln!("skipped {relative}: {e}");
            None
        }
    }
}

/// Every triangle of the scene in clip space under the automatic camera, with TEXCOORD_0 and
/// world normals.
fn clip_mesh(scene: &Scene) -> ClipMesh {
    let camera = barytex_render::auto_camera(scene, 1.0).expect("a scene with geometry");
    let view_projection = camera.projection * camera.view;
    let mut mesh = ClipMesh {
        clip: Vec::new(),
        uv: Vec::new(),
        normal: Vec::new(),
        indices: Vec::new(),
    };
    for instance in &scene.instances {
        let normal_matrix = glam::Mat3::from_mat4(instance.world).inverse().transpose();
        for primitive in &instance.mesh.primitives {
            let base = mesh.clip.len() as u32;
            for (i, &p) in primitive.positions.iter().enumerate() {
                let world = instance.world.transform_point3(p);
                mesh.clip.push(view_projection * world.extend(1.0));
                let uv = primitive.tex_coords0.as_ref().and_then(|t| t.get(i));
                mesh.uv.push(uv.copied().unwrap_or(Vec2::ZERO));
                let n = primitive.normals.as_ref().and_then(|n| n.get(i));
                mesh.normal
                    .push(normal_matrix * n.copied().unwrap_or(Vec3::Z));
            }
            mesh.indices
                .extend(primitive.triangles.iter().flatten().map(|&i| base + i));
        }
    }
    mesh
}

/// The first material's base colour texture, packed for the nearest lookup.
fn base_colour(scene: &Scene) -> NearestTexture {
    let image = scene
        .materials
        .iter()
        .find_map(|m| m.base_color_texture?.image)
        .and_then(|i| scene.images.get(i)?.srgb.clone());
    match image.as_deref() {
        Some(AnyTexture2d::Srgba8(t)) => {
            let (w, h) = t.size();
            NearestTexture {
                width: w as usize,
                height: h as usize,
                texels: t
                    .texels()
                    .iter()
                    .map(|s| {
                        let [r, g, b, a] = s.0;
                        u32::from_be_bytes([a, r, g, b])
                    })
                    .collect(),
            }
        }
        _ => NearestTexture::checker(256, 16),
    }
}

fn bench(c: &mut Criterion) {
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("pool");
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("pool");
    for (name, relative) in [
        ("avocado", "Avocado/glTF/Avocado.gltf"),
        ("suzanne", "Suzanne/glTF/Suzanne.gltf"),
    ] {
        let Some(scene) = load(relative) else {
            continue;
        };
        let mesh = clip_mesh(&scene);
        let texture = base_colour(&scene);
        let options = RenderOptions {
            width: SIZE,
            height: SIZE,
            camera: CameraChoice::Auto,
            shading: Shading::Unlit,
            filter: Filter::Nearest,
            anti_aliasing: AntiAliasing::None,
            ..RenderOptions::default()
        };
        // The two rasterizers must cover the same pixels for the times to be comparable.
        let covered_barytex = render_barytex(&mesh, &texture, true, SIZE)
            .to_srgba8()
            .expect("1024²")
            .texels()
            .iter()
            .filter(|t| t.0[3] > 0)
            .count();
        let covered_euc = render_euc(&mesh, &texture, true, SIZE)
            .as_ref()
            .iter()
            .filter(|&&p| p != 0)
            .count();
        eprintln!(
            "{name}: {} triangles; covered pixels: barytex {covered_barytex}, euc {covered_euc}",
            mesh.indices.len() / 3
        );
        let mut group = c.benchmark_group(format!("scene_1024_{name}"));
        group.bench_function("barytex_draw_1_thread", |b| {
            b.iter(|| one.install(|| black_box(render_barytex(&mesh, &texture, true, SIZE))));
        });
        group.bench_function("barytex_draw_2_threads", |b| {
            b.iter(|| two.install(|| black_box(render_barytex(&mesh, &texture, true, SIZE))));
        });
        group.bench_function("euc", |b| {
            b.iter(|| black_box(render_euc(&mesh, &texture, true, SIZE)));
        });
        group.bench_function("barytex_render_unlit_1_thread", |b| {
            b.iter(|| {
                one.install(|| {
                    black_box(barytex_render::render(&scene, &options).expect("renders"))
                })
            });
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
