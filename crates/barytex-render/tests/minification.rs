//! Mip chains are built for every texture that is minified somewhere on screen, conservatively:
//! a floor running under the camera, or seen at a grazing angle, is minified in its distance
//! even where a per-triangle area average says otherwise.

use barytex_gltf::{LoadOptions, load_path};
use barytex_render::{CameraChoice, RenderOptions, Shading, render};
use barytex_texture::{Srgba8, Texture2d};

/// A 2-unit-wide floor quad at y = 0 from z = `near` to z = `far`, textured once with a
/// `side`² checker (trilinear sampler), seen by a camera at height 0.5 at the origin looking
/// down −z. Returns the render's (mip chains built, mip chains skipped).
fn mips(near: f32, far: f32, side: u32) -> (usize, usize) {
    let positions = [
        [-1.0, 0.0, near],
        [1.0, 0.0, near],
        [1.0, 0.0, far],
        [-1.0, 0.0, far],
    ];
    quad_mips(positions, [1.0, 1.0], side, CameraChoice::Index(0))
}

/// A 16² checker on a quad facing the automatic camera and filling the view, its uvs scaled
/// by `uv_scale` (repeating).
fn facing_mips(uv_scale: [f32; 2]) -> (usize, usize) {
    let positions = [
        [-1.0, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ];
    quad_mips(positions, uv_scale, 16, CameraChoice::Auto)
}

/// The quad `positions` (counter-clockwise seen from +y or +z) with uvs over `[0, 1]²` scaled
/// by `uv_scale`, textured with a `side`² checker; its (mip chains built, skipped).
fn quad_mips(
    positions: [[f32; 3]; 4],
    uv_scale: [f32; 2],
    side: u32,
    camera: CameraChoice,
) -> (usize, usize) {
    // A folder of its own per call (tests run in parallel).
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let [su, sv] = uv_scale;
    let dir = std::env::temp_dir().join(format!(
        "barytex-minification-{}-{call}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).expect("temp folder");
    let checker = Texture2d::from_fn(side, side, |x, y| {
        Srgba8(if (x + y) % 2 == 0 {
            [255; 4]
        } else {
            [0, 0, 0, 255]
        })
    })
    .expect("small");
    barytex_texture::load::save_png(&checker, dir.join("checker.png")).expect("writes");
    let uvs = [0.0, sv, su, sv, su, 0.0, 0.0, 0.0];
    let floats: Vec<f32> = positions.iter().flatten().copied().chain(uvs).collect();
    let mut bin: Vec<u8> = floats.iter().flat_map(|f| f.to_le_bytes()).collect();
    bin.extend([0_u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("floor.bin"), &bin).expect("writes");
    let min = (0..3).map(|k| positions.iter().map(|p| p[k]).fold(f32::INFINITY, f32::min));
    let max = (0..3).map(|k| {
        positions
            .iter()
            .map(|p| p[k])
            .fold(f32::NEG_INFINITY, f32::max)
    });
    let (lo, hi): (Vec<f32>, Vec<f32>) = (min.collect(), max.collect());
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":{},"uri":"floor.bin"}}],
        "bufferViews":[{{"buffer":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":32}},
                       {{"buffer":0,"byteOffset":80,"byteLength":12}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":{lo:?},"max":{hi:?}}},
                     {{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"}},
                     {{"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}}],
        "images":[{{"uri":"checker.png"}}],
        "textures":[{{"source":0}}],
        "materials":[{{"doubleSided":true,"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}}}}}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"indices":2,"material":0}}]}}],
        "cameras":[{{"type":"perspective","perspective":{{"yfov":0.8,"znear":0.05}}}}],
        "nodes":[{{"mesh":0}},{{"camera":0,"translation":[0,0.5,0]}}],
        "scenes":[{{"nodes":[0,1]}}]}}"#,
        bin.len()
    );
    std::fs::write(dir.join("floor.gltf"), gltf).expect("writes");
    let scene = load_path(dir.join("floor.gltf"), &LoadOptions::default()).expect("loads");
    let _ = std::fs::remove_dir_all(&dir);
    let options = RenderOptions {
        width: 64,
        height: 64,
        camera,
        shading: Shading::Unlit,
        ..RenderOptions::default()
    };
    let stats = render(&scene, &options).expect("renders").stats;
    (stats.mip_chains, stats.mips_skipped)
}

/// The floor runs from behind the camera to 100 units ahead: both triangles cross the eye
/// plane, so no on-screen measure exists — in doubt, the chain is built. (Skipped before.)
#[test]
fn a_floor_running_under_the_camera_gets_mips() {
    assert_eq!(mips(100.0, -100.0, 64), (1, 0));
}

/// The floor lies wholly ahead (z from −0.5 to −200): towards the horizon a pixel covers many
/// texels along z.
#[test]
fn a_floor_at_a_grazing_angle_gets_mips() {
    assert_eq!(mips(-0.5, -200.0, 8), (1, 0));
}

/// Facing the camera, uvs repeating 16 times across and 1/64 of the texture down: a pixel covers
/// about 4 texels across and 1/16 of a texel down, so its area covers a quarter of a texel —
/// but along u it is minified 4×. (Skipped before: the area average hid the anisotropy.)
#[test]
fn anisotropic_minification_gets_mips() {
    assert_eq!(facing_mips([16.0, 1.0 / 64.0]), (1, 0));
    // The same area, isotropic: magnified both ways.
    assert_eq!(facing_mips([0.125, 0.125]), (0, 1));
}

/// A floor close up and short, magnified everywhere, still skips its chain.
#[test]
fn a_magnified_floor_skips_its_chain() {
    assert_eq!(mips(-0.3, -0.6, 16), (0, 1));
}
