//! Load a glTF and render it: barytex-gltf loads the file under limits, barytex-render draws it
//! (the file's first camera or the automatic one, its materials and textures, Blinn–Phong
//! lighting, 4× MSAA, anisotropic filtering) and the image is written as a PNG.
//!
//! Run with `cargo run --release -p barytex-render --example render_gltf -- [MODEL.gltf|.glb]
//! [OUT.png]`. Without a model it writes a small textured quad (`.gltf`, `.bin`, `.png`) to the
//! temporary folder and renders that; the default output is `barytex-render.png` there.

use std::error::Error;
use std::path::PathBuf;

use barytex_gltf::{LoadOptions, load_path};
use barytex_render::{AntiAliasing, Filter, RenderOptions, render};
use barytex_testkit::sample_model::write_textured_quad;
use barytex_texture::load::save_png;

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args_os().skip(1);
    let model = match args.next() {
        Some(path) => PathBuf::from(path),
        None => write_textured_quad(
            &std::env::temp_dir().join(format!("barytex-quad-{}", std::process::id())),
        )?,
    };
    let out = args.next().map_or_else(
        || std::env::temp_dir().join("barytex-render.png"),
        PathBuf::from,
    );

    let scene = load_path(&model, &LoadOptions::default())?;
    let options = RenderOptions {
        width: 480,
        height: 360,
        anti_aliasing: AntiAliasing::Msaa(4),
        filter: Filter::Anisotropic(16),
        ..RenderOptions::default()
    };
    let rendered = render(&scene, &options)?;
    save_png(&rendered.image.to_srgba8()?, &out)?;
    println!(
        "{}: {} triangles, camera {:?}, {} fragments shaded -> {}",
        model.display(),
        scene.triangle_count(),
        rendered.camera.source,
        rendered.stats.draw.fragments_shaded,
        out.display()
    );
    Ok(())
}
