//! The glTF-Validator's test assets: every file the validator reports errors for is refused,
//! every file without errors loads, and nothing panics.
//!
//! `CATALOG.md` lists each asset as `- file | description | numErrors | codes` under a heading
//! `## base/<group>` (files in `test/base/data/<group>/`) or `## ext/<EXT>/<path>` (files in
//! `test/ext/<EXT>/data/<path>/`).

mod common;

use std::path::PathBuf;

use barytex_gltf::{LoadOptions, SceneError, load_path};

/// Invalid assets this loader accepts on purpose. Each reason says why the rule the validator
/// enforces does not matter to what the loader produces.
const ACCEPTED_DESPITE_ERRORS: &[(&str, &str)] = &[
    // Joint indices duplicated/out of range, negative or unnormalised weights: skinning is not
    // applied (meshes load in their bind pose) and JOINTS_n/WEIGHTS_n are never decoded.
    (
        "base/mesh_data/joints_weights_complex.gltf",
        "JOINTS/WEIGHTS data is never read: skinning is not applied",
    ),
    // The material uses KHR_materials_anisotropy / KHR_materials_clearcoat normal textures on a
    // primitive without normals: those extensions are not implemented, their textures are
    // never sampled, and the core material renders without a tangent space.
    (
        "ext/KHR_materials_anisotropy/material/no_tangent_space.gltf",
        "KHR_materials_anisotropy is not implemented; its tangent-space needs never arise",
    ),
    (
        "ext/KHR_materials_clearcoat/material/no_tangent_space.gltf",
        "KHR_materials_clearcoat is not implemented; its tangent-space needs never arise",
    ),
];

/// Valid assets this loader refuses on purpose.
const REFUSED_DESPITE_VALID: &[(&str, &str)] = &[
    // `minVersion: "2.1"` says the asset needs glTF 2.1 features; the specification requires
    // a loader for an older minor version to refuse it (the validator, knowing 2.1 is
    // backward-compatible JSON, has nothing to object to).
    (
        "base/asset/min_version_valid.gltf",
        "minVersion 2.1 > the 2.0 this loader implements",
    ),
];

struct Entry {
    id: String,
    path: PathBuf,
    errors: usize,
    codes: String,
}

fn catalog() -> Vec<Entry> {
    let Some(root) = common::fixtures() else {
        return Vec::new();
    };
    let base = root.join("gltf-invalid/glTF-Validator");
    let Ok(text) = std::fs::read_to_string(base.join("CATALOG.md")) else {
        println!("note: CATALOG.md absent, test skipped");
        return Vec::new();
    };
    let mut section = String::new();
    let mut out = Vec::new();
    for line in text.lines() {
        if let Some(h) = line.strip_prefix("## ") {
            section = h.split(" — ").next().unwrap_or_default().trim().to_owned();
            continue;
        }
        let Some(item) = line.strip_prefix("- ") else {
            continue;
        };
        let cols: Vec<&str> = item.split(" | ").map(str::trim).collect();
        let [file, _desc, errors, codes] = cols.as_slice() else {
            panic!("malformed catalog line {line:?}");
        };
        let mut parts = section.splitn(3, '/');
        let dir = match (parts.next(), parts.next(), parts.next()) {
            (Some("base"), Some(group), None) => base.join("test/base/data").join(group),
            (Some("ext"), Some(ext), Some(rest)) => {
                base.join("test/ext").join(ext).join("data").join(rest)
            }
            _ => panic!("unexpected catalog section {section:?}"),
        };
        out.push(Entry {
            id: format!("{section}/{file}"),
            path: dir.join(file),
            errors: errors
                .parse()
                .unwrap_or_else(|_| panic!("bad count in {line:?}")),
            codes: (*codes).to_owned(),
        });
    }
    out
}

#[test]
fn validator_assets() {
    let entries = catalog();
    if entries.is_empty() {
        return;
    }
    let allowed = |list: &[(&str, &str)], id: &str| list.iter().any(|(f, _)| *f == id);
    let mut problems = Vec::new();
    let (mut refused, mut loaded) = (0, 0);
    for e in &entries {
        assert!(e.path.exists(), "{} missing at {}", e.id, e.path.display());
        let result = load_path(&e.path, &LoadOptions::default());
        if let Err(SceneError::Internal(msg)) = &result {
            problems.push(format!("PANIC {}: {msg}", e.id));
            continue;
        }
        match (&result, e.errors > 0) {
            (Err(err), true) => {
                refused += 1;
                println!("refused  {} [{}]: {err}", e.id, e.codes);
                if allowed(ACCEPTED_DESPITE_ERRORS, &e.id) {
                    problems.push(format!(
                        "{} is refused now: drop it from the allow-list",
                        e.id
                    ));
                }
            }
            (Ok(_), false) => {
                loaded += 1;
                if allowed(REFUSED_DESPITE_VALID, &e.id) {
                    problems.push(format!("{} loads now: drop it from the list", e.id));
                }
            }
            (Ok(_), true) => {
                if allowed(ACCEPTED_DESPITE_ERRORS, &e.id) {
                    println!("accepted {} [{}] (allow-listed)", e.id, e.codes);
                } else {
                    problems.push(format!("ACCEPTED {} [{}]", e.id, e.codes));
                }
            }
            (Err(err), false) => {
                if allowed(REFUSED_DESPITE_VALID, &e.id) {
                    println!("refused  {} (valid, listed): {err}", e.id);
                } else {
                    problems.push(format!("REFUSED valid {}: {err}", e.id));
                }
            }
        }
    }
    println!(
        "{} assets: {refused} invalid refused, {loaded} valid loaded, {} allow-listed invalid, {} listed valid",
        entries.len(),
        ACCEPTED_DESPITE_ERRORS.len(),
        REFUSED_DESPITE_VALID.len()
    );
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}
