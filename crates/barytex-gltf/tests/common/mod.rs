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
