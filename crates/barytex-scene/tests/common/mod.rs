//! Shared helpers for the integration tests: locating the shared fixtures.
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
