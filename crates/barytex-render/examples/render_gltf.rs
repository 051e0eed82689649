//! Load a glTF and render it: barytex-gltf loads the file under limits, barytex-render draws it
//! (the file's first camera or the automatic one, its materials and textures, Blinn–Phong
//! lighting, 4× MSAA, anisotropic filtering) and the image is written as a PNG.
//!
//! Run with `cargo run --release -p barytex-render --example render_gltf -- [MODEL.gltf|.glb]
//! [OUT.png]`. Without a model it writes a small textured quad (`.gltf`, `.bin`, `.png`) to the
//! temporary folder and renders that; the default output is `barytex-render.png` there.

use std::error::Error;
use std::path::{Path, PathBuf};

use barytex_gltf::{LoadOptions, load_path};
use barytex_render::{AntiAliasing, Filter, RenderOptions, render};
use barytex_texture::load::save_png;
use barytex_texture::{Srgba8, Texture2d};

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args_os().skip(1);
    let model = match args.next() {
        Some(path) => PathBuf::from(path),
        None => {
            write_quad(&std::env::temp_dir().join(format!("barytex-quad-{}", std::process::id())))?
        }
    };
    let out = args.next().map_or_else(
        || std::env::temp_dir().join("barytex-render.png"),
        PathBuf::from,
    );

    let scene = load_path(&model, &LoadOptions::default())?;
    let options = RenderOptions {
        width: 480,
        height: 360,
        anti_aliasing: AntiAliasing::Msaa(4),
        filter: Filter::Anisotropic(16),
        ..RenderOptions::default()
    };
    let rendered = render(&scene, &options)?;
    save_png(&rendered.image.to_srgba8()?, &out)?;
    println!(
        "{}: {} triangles, camera {:?}, {} fragments shaded -> {}",
        model.display(),
        scene.triangle_count(),
        rendered.camera.source,
        rendered.stats.draw.fragments_shaded,
        out.display()
    );
    Ok(())
}

/// Writes a small model to `dir`: `quad.gltf`, its buffer `quad.bin` and its base-colour image
/// `checker.png` (relative URIs, read from the model's own folder), a textured square tilted
/// 45° about x. Returns the path of `quad.gltf`.
fn write_quad(dir: &Path) -> Result<PathBuf, Box<dyn Error>> {
    std::fs::create_dir_all(dir)?;
    let positions = [
        [-1.0f32, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ];
    let uvs = [[0.0f32, 4.0], [4.0, 4.0], [4.0, 0.0], [0.0, 0.0]];
    let indices = [0u16, 1, 2, 0, 2, 3];
    let mut bin: Vec<u8> = positions
        .iter()
        .flatten()
        .flat_map(|c| c.to_le_bytes())
        .collect();
    bin.extend(uvs.iter().flatten().flat_map(|c| c.to_le_bytes()));
    bin.extend(indices.iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("quad.bin"), &bin)?;
    let checker = Texture2d::from_fn(64, 64, |x, y| {
        Srgba8(if (x / 8 + y / 8) % 2 == 0 {
            [240, 180, 40, 255]
        } else {
            [40, 70, 150, 255]
        })
    })?;
    save_png(&checker, dir.join("checker.png"))?;
    let gltf = format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "buffers": [{{"uri": "quad.bin", "byteLength": {}}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                  {{"buffer": 0, "byteOffset": 48, "byteLength": 32}},
                  {{"buffer": 0, "byteOffset": 80, "byteLength": 12}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                  "min": [-1, -1, 0], "max": [1, 1, 0]}},
                {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"}},
                {{"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}}],
  "images": [{{"uri": "checker.png"}}],
  "textures": [{{"source": 0}}],
  "materials": [{{"name": "checker", "doubleSided": true,
                  "pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}, "metallicFactor": 0}}}}],
  "meshes": [{{"name": "quad", "primitives": [{{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1}},
                                               "indices": 2, "material": 0}}]}}],
  "nodes": [{{"name": "tilted quad", "mesh": 0, "rotation": [-0.38268343, 0, 0, 0.9238795]}}],
  "scenes": [{{"nodes": [0]}}]
}}"#,
        bin.len()
    );
    let path = dir.join("quad.gltf");
    std::fs::write(&path, gltf)?;
    Ok(path)
}
