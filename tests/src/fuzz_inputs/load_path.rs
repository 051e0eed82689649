//! Checks of the `load_path` fuzz target: a model on disk whose buffer and image URIs come from
//! the fuzzer, loaded with `barytex_gltf::load_path`, next to decoy files outside the model's
//! folder.
//!
//! Layout: the input up to its first zero byte is the buffer's URI, the rest (up to a second zero
//! byte) the image's URI (`inside.png` when there is no zero byte). Bytes that are not UTF-8 are
//! replaced (U+FFFD); every byte `0x01` stands for the absolute path of the sandbox (the folder
//! holding the model's folder and the decoys), so absolute paths are reachable. The URIs are
//! written into `model/scene.gltf` as JSON strings (escaped), so `..`, `%2e%2e/`, `%2F`,
//! backslashes and absolute paths all reach the loader as the fuzzer spelled them.
//!
//! The sandbox, made once per process in the system's temporary folder:
//! - `model/inside.bin`: the triangle's positions and uvs, `model/inside.png`: a 4 × 4 grey image,
//!   `model/link.bin`: a symbolic link to the decoy buffer (Unix);
//! - `decoy.bin` (60 bytes, the size of `inside.bin`: the floats 1001–1015) and
//!   `decoy.png` (4 × 4, colour `[1, 2, 3, 4]`), outside the model's folder.
//!
//! Invariants: `load_path` never panics and never reports a caught panic (`Internal`); a scene it
//! loads renders without panicking; and no decoy is ever loaded — no vertex position holds a
//! decoy float and no decoded image holds the decoy colour — whatever the error type of a
//! refusal. (The last invariant needs the loader's confinement of URIs to the model's folder.)

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use barytex_gltf::{LoadOptions, SceneError, load_path};
use barytex_render::{RenderOptions, Shading, render};
use barytex_texture::load::{AnyTexture2d, encode_png};
use barytex_texture::{Srgba8, Texture2d};

use super::gltf_loader::fuzz_limits;

/// Longest input the target reads.
pub const LOAD_PATH_LEN: usize = 512;

/// The decoy buffer's floats (as many as the model's buffer holds: positions and uvs).
const DECOY_FLOATS: [f32; 15] = [
    1001.0, 1002.0, 1003.0, 1004.0, 1005.0, 1006.0, 1007.0, 1008.0, 1009.0, 1010.0, 1011.0, 1012.0,
    1013.0, 1014.0, 1015.0,
];
/// The decoy image's colour.
const DECOY_COLOUR: [u8; 4] = [1, 2, 3, 4];

fn png(colour: [u8; 4]) -> Vec<u8> {
    Texture2d::new(4, 4, Srgba8(colour))
        .and_then(|t| encode_png(&t))
        .expect("a 4×4 PNG")
}

/// The prefix of the sandbox folders in the temporary folder, followed by the process id.
const SANDBOX_PREFIX: &str = "barytex-fuzz-load-path-";

/// Removes the sandboxes of processes that have ended. Each process has its own (fuzzing jobs
/// and test threads of different processes would otherwise overwrite each other's model), and a
/// fuzzer ends by `exit`, which runs no destructor, so the folder outlives its process; the next
/// process clears them. Where `/proc` does not list processes (not Linux) nothing is removed.
fn remove_ended_sandboxes(temp: &Path) {
    let proc = Path::new("/proc");
    if !proc.join("self").exists() {
        return;
    }
    let Ok(entries) = std::fs::read_dir(temp) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name
            .to_str()
            .and_then(|n| n.strip_prefix(SANDBOX_PREFIX))
            .and_then(|pid| pid.parse::<u32>().ok())
        else {
            continue;
        };
        if pid != std::process::id() && !proc.join(pid.to_string()).exists() {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// The sandbox folder (made on first use; those of ended processes are removed then).
///
/// # Panics
/// When the temporary folder cannot be written.
pub fn load_path_sandbox() -> &'static Path {
    static ROOT: OnceLock<PathBuf> = OnceLock::new();
    ROOT.get_or_init(|| {
        let temp = std::env::temp_dir();
        remove_ended_sandboxes(&temp);
        let root = temp.join(format!("{SANDBOX_PREFIX}{}", std::process::id()));
        let model = root.join("model");
        std::fs::create_dir_all(&model).expect("a temporary folder");
        let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
        let write = |path: PathBuf, bytes: &[u8]| std::fs::write(path, bytes).expect("writable");
        write(
            model.join("inside.bin"),
            &floats(&[0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 1.]),
        );
        write(model.join("inside.png"), &png([128, 128, 128, 255]));
        write(root.join("decoy.bin"), &floats(&DECOY_FLOATS));
        write(root.join("decoy.png"), &png(DECOY_COLOUR));
        #[cfg(unix)]
        {
            let link = model.join("link.bin");
            if std::fs::symlink_metadata(&link).is_err() {
                std::os::unix::fs::symlink(root.join("decoy.bin"), link).expect("a symbolic link");
            }
        }
        root.canonicalize().unwrap_or(root)
    })
}

fn json_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if u32::from(c) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The buffer and image URIs of an input.
#[must_use]
pub fn load_path_uris(bytes: &[u8]) -> (String, String) {
    let root = load_path_sandbox().to_string_lossy().into_owned();
    let text = |b: &[u8]| String::from_utf8_lossy(b).replace('\u{1}', &root);
    let mut parts = bytes.splitn(3, |&b| b == 0);
    let buffer = text(parts.next().unwrap_or_default());
    let image = parts.next().map_or_else(|| "inside.png".to_owned(), text);
    (buffer, image)
}

/// The model's JSON for the two URIs.
#[must_use]
pub fn load_path_gltf(buffer: &str, image: &str) -> String {
    format!(
        r#"{{"asset": {{"version": "2.0"}},
  "buffers": [{{"byteLength": 60, "uri": {buffer}}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}, {{"buffer": 0, "byteOffset": 36, "byteLength": 24}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [-2000, -2000, -2000], "max": [2000, 2000, 2000]}},
                {{"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}}],
  "images": [{{"uri": {image}}}],
  "textures": [{{"source": 0}}],
  "materials": [{{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0}}}}}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1}}, "material": 0}}]}}],
  "nodes": [{{"mesh": 0}}], "scenes": [{{"nodes": [0]}}]}}"#,
        buffer = json_string(buffer),
        image = json_string(image),
    )
}

fn holds_decoy_colour(texture: &AnyTexture2d) -> bool {
    match texture {
        AnyTexture2d::Srgba8(t) => t.texels().iter().any(|t| t.0 == DECOY_COLOUR),
        AnyTexture2d::Rgba8(t) => t.texels().iter().any(|t| t.0 == DECOY_COLOUR),
        _ => false,
    }
}

/// The invariants (see the module documentation).
///
/// # Errors
/// A description of the first violated invariant.
///
/// # Panics
/// When the model file cannot be written.
pub fn check_load_path(bytes: &[u8]) -> Result<(), String> {
    let (buffer, image) = load_path_uris(bytes);
    let path = load_path_sandbox().join("model").join("scene.gltf");
    std::fs::write(&path, load_path_gltf(&buffer, &image)).expect("writable");
    let options = LoadOptions {
        limits: fuzz_limits(),
        ..LoadOptions::default()
    };
    let scene = match load_path(&path, &options) {
        Err(SceneError::Internal(message)) => {
            return Err(format!("the loader caught a panic: {message}"));
        }
        Err(_) => return Ok(()),
        Ok(scene) => scene,
    };
    for instance in &scene.instances {
        for primitive in &instance.mesh.primitives {
            let uvs = primitive.tex_coords0.iter().flatten();
            let decoy = primitive
                .positions
                .iter()
                .flat_map(|p| p.to_array())
                .chain(uvs.flat_map(|uv| uv.to_array()))
                .any(|x| DECOY_FLOATS.contains(&x));
            if decoy {
                return Err(format!(
                    "buffer URI {buffer:?} loaded the decoy outside the model's folder: {:?}",
                    primitive.positions
                ));
            }
        }
    }
    for img in &scene.images {
        if [&img.srgb, &img.linear]
            .into_iter()
            .flatten()
            .any(|t| holds_decoy_colour(t))
        {
            return Err(format!(
                "image URI {image:?} loaded the decoy image outside the model's folder"
            ));
        }
    }
    let options = RenderOptions {
        width: 8,
        height: 8,
        shading: Shading::Unlit,
        ..RenderOptions::default()
    };
    // An error is an answer; a panic is not.
    let _ = render(&scene, &options);
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn load_path_code(bytes: &[u8]) -> String {
    let (buffer, image) = load_path_uris(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    // buffer URI {buffer:?}, image URI {image:?}");
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_load_path(bytes), Ok(()));\n}");
    out
}
