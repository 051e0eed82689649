//! How a material's alpha mode reads its textures (glTF 2.0 §3.9.4 "Alpha Coverage"): OPAQUE
//! ignores alpha, so a texel's colour shows whatever its alpha; MASK and BLEND use it.

use barytex_gltf::{LoadOptions, load_path};
use barytex_render::{CameraChoice, RenderOptions, Shading, render};
use barytex_texture::{Srgba8, Texture2d};

/// A quad filling the view, textured with 2 × 2 texels of sRGB red whose alpha is `alpha`, under
/// `alpha_mode`; rendered unlit, the centre pixel's sRGB bytes.
fn centre(alpha: u8, alpha_mode: &str) -> [u8; 4] {
    let dir = std::env::temp_dir().join(format!(
        "barytex-alpha-{}-{alpha}-{alpha_mode}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).expect("temp folder");
    let texels = Texture2d::from_texels(2, 2, vec![Srgba8([255, 0, 0, alpha]); 4]).expect("tiny");
    barytex_texture::load::save_png(&texels, dir.join("red.png")).expect("writes");
    // Two triangles over [-1, 1]² at z = 0 with uvs, 4 positions then 4 uvs.
    let floats: [f32; 20] = [
        -1.0, -1.0, 0.0, 1.0, -1.0, 0.0, 1.0, 1.0, 0.0, -1.0, 1.0, 0.0, //
        0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0,
    ];
    let mut bin: Vec<u8> = floats.iter().flat_map(|f| f.to_le_bytes()).collect();
    bin.extend([0_u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("quad.bin"), &bin).expect("writes");
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":{},"uri":"quad.bin"}}],
        "bufferViews":[{{"buffer":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":32}},
                       {{"buffer":0,"byteOffset":80,"byteLength":12}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,0],"max":[1,1,0]}},
                     {{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"}},
                     {{"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}}],
        "images":[{{"uri":"red.png"}}],
        "samplers":[{{"magFilter":9729,"minFilter":9729}}],
        "textures":[{{"source":0,"sampler":0}}],
        "materials":[{{"alphaMode":"{alpha_mode}","pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}}}}}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"indices":2,"material":0}}]}}],
        "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#,
        bin.len()
    );
    std::fs::write(dir.join("quad.gltf"), gltf).expect("writes");
    let scene = load_path(dir.join("quad.gltf"), &LoadOptions::default()).expect("loads");
    let options = RenderOptions {
        width: 16,
        height: 16,
        camera: CameraChoice::Auto,
        shading: Shading::Unlit,
        ..RenderOptions::default()
    };
    let image = render(&scene, &options)
        .expect("renders")
        .image
        .to_srgba8()
        .expect("tiny");
    let _ = std::fs::remove_dir_all(&dir);
    image.texel(8, 8).expect("inside").0
}

/// OPAQUE: a texel with alpha 0 shows its red, fully opaque (it rendered black: premultiplied
/// filtering had destroyed the colour before alpha was set to 1).
#[test]
fn opaque_materials_ignore_texture_alpha() {
    for alpha in [0, 1, 128, 255] {
        assert_eq!(centre(alpha, "OPAQUE"), [255, 0, 0, 255], "alpha {alpha}");
    }
}

/// BLEND still blends by the texel's alpha, and MASK (cutoff 0.5) still cuts: the background
/// shows through.
#[test]
fn blend_and_mask_still_read_texture_alpha() {
    let background = centre(255, "BLEND");
    assert_eq!(background, [255, 0, 0, 255]);
    let half = centre(128, "BLEND");
    assert!(half[0] < 255 && half[0] > 100, "{half:?}");
    let cut = centre(0, "MASK");
    assert_ne!(cut[0], 255, "{cut:?}");
}
