//! Only the textures the caller reads are decoded and required: an unlit render never reads a
//! normal map, so a missing one is a warning, not a refused file.

use barytex_gltf::{LoadOptions, SceneError, TextureRole, TextureRoles, load_path};
use barytex_texture::{Srgba8, Texture2d};

/// A textured triangle whose base colour image exists and whose normal map (`missing.png`) does
/// not; loaded with `roles`.
fn load(roles: TextureRoles) -> Result<barytex_gltf::Scene, SceneError> {
    let dir = std::env::temp_dir().join(format!(
        "barytex-image-roles-{}-{roles:?}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).expect("temp folder");
    let texels = Texture2d::from_texels(1, 1, vec![Srgba8([255, 0, 0, 255])]).expect("tiny");
    barytex_texture::load::save_png(&texels, dir.join("red.png")).expect("writes");
    let gltf = r#"{"asset":{"version":"2.0"},
        "images":[{"uri":"red.png"},{"uri":"missing.png"}],
        "textures":[{"source":0},{"source":1}],
        "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}},
                      "normalTexture":{"index":1}}],
        "accessors":[{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]},
                     {"componentType":5126,"count":3,"type":"VEC2"}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]}"#;
    std::fs::write(dir.join("tri.gltf"), gltf).expect("writes");
    let scene = load_path(
        dir.join("tri.gltf"),
        &LoadOptions {
            image_roles: roles,
            ..LoadOptions::default()
        },
    );
    let _ = std::fs::remove_dir_all(&dir);
    scene
}

#[test]
fn a_missing_image_no_read_role_samples_is_a_warning() {
    let base_only = TextureRoles::NONE.with(TextureRole::BaseColor);
    let scene = load(base_only).expect("the normal map is not needed");
    assert_eq!(scene.stats.images_decoded, 1);
    assert!(scene.images[0].srgb.is_some());
    assert!(scene.images[1].linear.is_none());
    assert!(
        scene
            .warnings
            .iter()
            .any(|w| w.starts_with("/images/1") && w.contains("missing.png")),
        "{:?}",
        scene.warnings
    );
}

#[test]
fn a_missing_image_a_read_role_samples_refuses_the_file() {
    let err = load(TextureRoles::ALL).expect_err("the normal map is needed");
    assert!(err.to_string().contains("missing.png"), "{err}");
}
