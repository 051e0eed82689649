//! Checks of the `gltf_loader` fuzz target: arbitrary bytes as a glTF (JSON) or GLB file.
//!
//! The loader must answer every input with a scene or an error — never a panic, and never its
//! `Internal` error (a panic it caught: a bug); a scene it accepts must render (a 16×12 image,
//! automatic and scene cameras) without panicking, with every triangle accounted for. Limits are
//! small so that a crafted file cannot make a run slow.

use std::fmt::Write as _;

use barytex_gltf::{LoadOptions, SceneError, SceneLimits, load_slice};
use barytex_render::{CameraChoice, RenderOptions, Shading, render};

/// Longest input the target reads.
pub const GLTF_LEN: usize = 1 << 16;

/// The loader's limits under fuzzing.
#[must_use]
pub fn fuzz_limits() -> SceneLimits {
    SceneLimits {
        max_file_bytes: GLTF_LEN as u64,
        max_buffer_bytes: 1 << 20,
        max_total_buffer_bytes: 1 << 21,
        max_image_file_bytes: 1 << 16,
        image: barytex_texture::Limits {
            max_width: 256,
            max_height: 256,
            max_bytes: 1 << 20,
        },
        max_triangles: 20_000,
        max_accessor_elements: 100_000,
        max_unbacked_accessor_elements: 100_000,
        max_instanced_triangles: 100_000,
        max_instanced_vertices: 300_000,
        max_total_image_bytes: 4 << 20,
        max_lights: 64,
        ..SceneLimits::default()
    }
}

/// The invariants (see the module documentation).
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_gltf_loader(bytes: &[u8]) -> Result<(), String> {
    let options = LoadOptions {
        limits: fuzz_limits(),
        ..LoadOptions::default()
    };
    let scene = match load_slice(bytes, &options) {
        Err(SceneError::Internal(message)) => {
            return Err(format!("the loader caught a panic: {message}"));
        }
        Err(_) => return Ok(()),
        Ok(scene) => scene,
    };
    for camera in [CameraChoice::First, CameraChoice::Auto] {
        for shading in [Shading::Phong, Shading::Unlit] {
            let options = RenderOptions {
                width: 16,
                height: 12,
                camera,
                shading,
                ..RenderOptions::default()
            };
            // An error (nothing to frame, a texture over the limits) is an answer; a panic is not.
            if let Ok(out) = render(&scene, &options) {
                let d = out.stats.draw;
                let triangles = u64::try_from(out.stats.triangles).unwrap_or(u64::MAX);
                if d.triangles_in != triangles * u64::from(out.stats.passes) {
                    return Err(format!("{d:?} for {triangles} triangles"));
                }
            }
        }
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn gltf_loader_code(bytes: &[u8]) -> String {
    let mut out = String::from("{\n");
    let _ = writeln!(
        out,
        "    // {}",
        String::from_utf8_lossy(&bytes[..bytes.len().min(200)]).replace('\n', " ")
    );
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_gltf_loader(bytes), Ok(()));\n}");
    out
}
