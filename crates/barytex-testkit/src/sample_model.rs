//! A small glTF model written to disk, for examples and tests that need a file to load: a
//! textured square, its buffer and its image as separate files with relative URIs.

use std::error::Error;
use std::path::{Path, PathBuf};

use barytex_texture::load::save_png;
use barytex_texture::{Srgba8, Texture2d};

/// Writes a small model to `dir`: `quad.gltf`, its buffer `quad.bin` and its base-colour image
/// `checker.png` (relative URIs, read from the model's own folder), a textured square tilted
/// 45° about x. Returns the path of `quad.gltf`.
///
/// # Errors
/// The file system's errors, and the PNG encoder's.
pub fn write_textured_quad(dir: &Path) -> Result<PathBuf, Box<dyn Error>> {
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
