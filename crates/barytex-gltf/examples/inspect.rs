//! Load a glTF 2.0 / GLB file under limits and print what the flattened scene holds: mesh
//! instances, materials and their textures, cameras, lights, decoded images, warnings.
//!
//! Run with `cargo run -p barytex-gltf --example inspect -- [MODEL.gltf|MODEL.glb]`. Without an
//! argument it writes a small textured quad (`.gltf`, `.bin` and `.png`) to the temporary folder
//! and loads that. The `barytex-render` crate's `render_gltf` example draws a model.

use std::error::Error;
use std::path::PathBuf;

use barytex_gltf::{LoadOptions, SceneLimits, load_path};
use barytex_testkit::sample_model::write_textured_quad;

fn main() -> Result<(), Box<dyn Error>> {
    let path = match std::env::args_os().nth(1) {
        Some(path) => PathBuf::from(path),
        None => write_textured_quad(
            &std::env::temp_dir().join(format!("barytex-quad-{}", std::process::id())),
        )?,
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
