//! Shared helpers for the integration tests: locating the shared fixtures, a minimal textured
//! glTF.
#![allow(dead_code, unreachable_pub)]

use std::path::PathBuf;

/// `/work/shared/fixtures`, found relative to the crate (`../../../shared/fixtures`).
#[must_use]
pub fn fixtures() -> Option<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/fixtures");
    if dir.is_dir() {
        Some(dir)
    } else {
        println!(
            "note: fixtures folder {} absent, test skipped",
            dir.display()
        );
        None
    }
}

/// Every `.gltf`/`.glb` under `<fixtures>/gltf/*/glTF*/`, sorted.
#[must_use]
pub fn sample_models() -> Vec<PathBuf> {
    let Some(root) = fixtures() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let Ok(models) = std::fs::read_dir(root.join("gltf")) else {
        return out;
    };
    for model in models.flatten() {
        let Ok(variants) = std::fs::read_dir(model.path()) else {
            continue;
        };
        for variant in variants.flatten() {
            if !variant.file_name().to_string_lossy().starts_with("glTF") {
                continue;
            }
            let Ok(files) = std::fs::read_dir(variant.path()) else {
                continue;
            };
            for f in files.flatten() {
                let p = f.path();
                if p.extension().is_some_and(|e| e == "gltf" || e == "glb") {
                    out.push(p);
                }
            }
        }
    }
    out.sort();
    out
}

/// One textured triangle (zero positions and uvs, no buffers) whose image is `image_uri`.
pub fn textured_triangle(image_uri: &str) -> String {
    format!(
        r#"{{"asset":{{"version":"2.0"}},
            "images":[{{"uri":"{image_uri}"}}],
            "textures":[{{"source":0}}],
            "materials":[{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}}}}}}],
            "accessors":[{{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}},
                         {{"componentType":5126,"count":3,"type":"VEC2"}}],
            "meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"material":0}}]}}],
            "nodes":[{{"mesh":0}}],"scenes":[{{"nodes":[0]}}]}}"#
    )
}
