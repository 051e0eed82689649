//! Shared helpers for the loader's integration tests: the sample fixtures, a minimal textured
//! glTF.
#![allow(dead_code, unreachable_pub, unused_imports)]

/// The shared fixtures folder (`$BARYTEX_FIXTURES` or `../shared/fixtures`), and the sample
/// models in it; `None` / empty, with a printed note, when absent.
pub use barytex_testkit::{fixtures_dir as fixtures, sample_models};

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

/// Default load options with `limits`.
pub fn with_limits(limits: barytex_gltf::SceneLimits) -> barytex_gltf::LoadOptions {
    barytex_gltf::LoadOptions {
        limits,
        ..barytex_gltf::LoadOptions::default()
    }
}

/// A fresh, empty folder for this test process and `name` (removed first if a previous run left
/// it).
pub fn temp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("barytex-gltf-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Asserts a `TooLarge` for `what` at `pointer`, asking for `requested` against `limit`, and that
/// the message names both numbers.
#[track_caller]
pub fn assert_too_large(
    r: &Result<barytex_gltf::Scene, barytex_gltf::SceneError>,
    what: &str,
    pointer: &str,
    requested: u64,
    limit: u64,
) {
    match r {
        Err(
            e @ barytex_gltf::SceneError::TooLarge {
                what: w,
                pointer: p,
                requested: req,
                limit: lim,
            },
        ) => {
            assert_eq!(
                (*w, p.as_str(), *req, *lim),
                (what, pointer, requested, limit),
                "{e}"
            );
            let text = e.to_string();
            assert!(
                text.contains(&requested.to_string()) && text.contains(&limit.to_string()),
                "the message should name the size and the limit: {text}"
            );
        }
        other => panic!("expected TooLarge {{ what: {what:?} }}, got {other:?}"),
    }
}
