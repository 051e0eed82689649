//! Load a glTF 2.0 / GLB file under limits and print what the flattened scene holds: mesh
//! instances, materials and their textures, cameras, lights, decoded images, warnings.
//!
//! Run with `cargo run -p barytex-gltf --example inspect -- [MODEL.gltf|MODEL.glb]`. Without an
//! argument it writes a small textured quad (`.gltf`, `.bin` and `.png`) to the temporary folder
//! and loads that. The `barytex-render` crate's `render_gltf` example draws a model.

use std::error::Error;
use std::path::{Path, PathBuf};

use barytex_gltf::{LoadOptions, SceneLimits, load_path};
use barytex_texture::load::save_png;
use barytex_texture::{Srgba8, Texture2d};

fn main() -> Result<(), Box<dyn Error>> {
    let path = match std::env::args_os().nth(1) {
        Some(path) => PathBuf::from(path),
        None => {
            write_quad(&std::env::temp_dir().join(format!("barytex-quad-{}", std::process::id())))?
        }
    };
    // Files are untrusted: every size is checked against the limits before it is allocated.
    let options = LoadOptions {
        limits: SceneLimits::default(),
        ..LoadOptions::default()
    };
    let scene = load_path(&path, &options)?;
    println!(
        "{}: scene {:?} of {}, {} triangles",
        path.display(),
        scene.scene_index,
        scene.scene_count,
        scene.triangle_count()
    );
    for instance in &scene.instances {
        println!(
            "  node {} {:?}: {} primitive(s), {} triangles",
            instance.node,
            instance.node_name.as_deref().unwrap_or(""),
            instance.mesh.primitives.len(),
            instance.triangle_count()
        );
    }
    for (i, material) in scene.materials.iter().enumerate() {
        let textures: Vec<String> = material
            .texture_refs()
            .iter()
            .map(|(texture, space)| format!("texture {} ({space:?})", texture.texture))
            .collect();
        println!(
            "  material {i} {:?}: base colour {:.2}, {:?}, unlit {}, {}",
            material.name.as_deref().unwrap_or(""),
            material.base_color_factor,
            material.alpha_mode,
            material.unlit,
            if textures.is_empty() {
                "no texture".to_string()
            } else {
                textures.join(", ")
            }
        );
    }
    for camera in &scene.cameras {
        println!(
            "  camera {} {:?} at node {}: {:?}",
            camera.camera,
            camera.name.as_deref().unwrap_or(""),
            camera.node,
            camera.projection
        );
    }
    println!("  {} light(s)", scene.lights.len());
    for (i, image) in scene.images.iter().enumerate() {
        let size = |t: &Option<std::sync::Arc<barytex_texture::load::AnyTexture2d>>| {
            t.as_ref().map(|t| t.size())
        };
        println!(
            "  image {i}: decoded as sRGB {:?}, as linear {:?}",
            size(&image.srgb),
            size(&image.linear)
        );
    }
    for warning in &scene.warnings {
        println!("  warning: {warning}");
    }
    println!("  {:?}", scene.stats);
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
