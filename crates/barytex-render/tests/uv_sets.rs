//! Texture coordinate sets: a material sampling a set the renderer does not decode is refused
//! with an error naming it, never drawn with another set.

use barytex_gltf::{LoadOptions, load_path};
use barytex_render::{RenderError, RenderOptions, render};
use barytex_texture::{Srgba8, Texture2d};

/// A triangle with three TEXCOORD sets whose material samples set `set`.
fn render_with_set(set: u32) -> Result<(), RenderError> {
    let dir = std::env::temp_dir().join(format!("barytex-uv-sets-{}-{set}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp folder");
    let texels = Texture2d::from_texels(1, 1, vec![Srgba8([255, 0, 0, 255])]).expect("tiny");
    barytex_texture::load::save_png(&texels, dir.join("red.png")).expect("writes");
    let positions: [f32; 9] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
    let bin: Vec<u8> = positions.iter().flat_map(|f| f.to_le_bytes()).collect();
    std::fs::write(dir.join("tri.bin"), &bin).expect("writes");
    let uv = r#"{"componentType":5126,"count":3,"type":"VEC2"}"#;
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0"}},
        "buffers":[{{"byteLength":36,"uri":"tri.bin"}}],
        "bufferViews":[{{"buffer":0,"byteLength":36}}],
        "accessors":[{{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}},
                     {uv}, {uv}, {uv}],
        "images":[{{"uri":"red.png"}}],
        "textures":[{{"source":0}}],
        "materials":[{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0,"texCoord":{set}}}}}}}],
        "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1,"TEXCOORD_1":2,"TEXCOORD_2":3}},"material":0}}]}}],
        "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#
    );
    std::fs::write(dir.join("tri.gltf"), gltf).expect("writes");
    let scene = load_path(dir.join("tri.gltf"), &LoadOptions::default());
    let _ = std::fs::remove_dir_all(&dir);
    let options = RenderOptions {
        width: 8,
        height: 8,
        ..RenderOptions::default()
    };
    render(&scene.expect("loads"), &options).map(|_| ())
}

#[test]
fn sets_beyond_the_second_are_refused_by_name() {
    assert!(render_with_set(0).is_ok());
    assert!(render_with_set(1).is_ok());
    let err = render_with_set(2).expect_err("TEXCOORD_2 is not decoded");
    assert!(
        matches!(&err, RenderError::Unsupported { material: Some(0), what } if what == "TEXCOORD_2"),
        "{err:?}"
    );
    assert!(err.to_string().contains("TEXCOORD_2"), "{err}");
}
