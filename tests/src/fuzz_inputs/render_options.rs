//! Byte layout and checks of the `render_options` fuzz target: a fixed small scene rendered with
//! arbitrary [`RenderOptions`].
//!
//! The scene ([`render_options_scene`]) is a glTF document built once: an indexed quad textured
//! with a 4 × 4 PNG (mipmapped sampler, `KHR_texture_transform`), a non-indexed triangle with an
//! emissive material, a perspective camera, and a point, a spot and a directional light
//! (`KHR_lights_punctual`).
//!
//! Layout (missing bytes read as zero): byte 0 width and byte 1 height, each `mod 65` (0 is an
//! invalid size); byte 2 the camera (0 first, 1 automatic, `n ≥ 2` the scene camera `n − 2`:
//! only camera 0 exists); byte 3 the shading (`mod 5`: unlit, flat, Gouraud, Phong, hybrid);
//! byte 4 the filter (`mod 6`: from the file, nearest, bilinear, trilinear, anisotropic, EWA) and
//! byte 5 the anisotropic probe count (0–255, clamped by the renderer); byte 6 the anti-aliasing
//! (`mod 5`: none, supersample, jitter, MSAA, adaptive) and byte 7 its `n` (`mod 18`: 0 and 17
//! are out of range for supersampling, most counts are not MSAA counts); byte 8 bit 0 fog, bit 1
//! fog by view depth (else Euclidean), bit 2 `measure_stages`; bytes 9–12 the background and
//! 13–15 the fog colour (unorm); bytes 16–19 the fog density as f32 bits (NaN, ∞, negative
//! included).
//!
//! Invariants: never a panic; `Ok` exactly when the options are valid — then the image has the
//! asked size and no pixel has a NaN channel — and otherwise the documented error: a zero side
//! `InvalidOption`, camera `n ≥ 1` `NoSuchCamera { index: n, count: 1 }`, a supersampling or
//! jitter `n` outside 1–16 `InvalidOption`, an MSAA count other than 1, 2, 4, 8, 16 a `Raster`
//! error.

use std::fmt::Write as _;
use std::sync::OnceLock;

use barytex_gltf::{LoadOptions, Scene, load_slice};
use barytex_render::{
    AntiAliasing, CameraChoice, Filter, RenderError, RenderOptions, Shading, render,
};
use barytex_shade::{ExponentialFog, FogDistance};
use barytex_texture::load::encode_png;
use barytex_texture::{Srgba8, Texture2d};
use glam::{Vec3, Vec4};

/// Bytes the target reads.
pub const RENDER_OPTIONS_LEN: usize = 20;

fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::new();
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[((n >> (18 - 6 * i)) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// The glTF document of the scene (JSON with data URIs).
///
/// # Panics
/// Never: the 4 × 4 image always encodes.
#[must_use]
pub fn render_options_gltf() -> String {
    let mut bin: Vec<u8> = Vec::new();
    let floats = |bin: &mut Vec<u8>, v: &[f32]| v.iter().for_each(|x| bin.extend(x.to_le_bytes()));
    // Quad: positions (0), normals (48), uvs (96), indices (128); triangle positions (140).
    floats(
        &mut bin,
        &[-1., -1., 0., 1., -1., 0., 1., 1., 0., -1., 1., 0.],
    );
    floats(&mut bin, &[0., 0., 1., 0., 0., 1., 0., 0., 1., 0., 0., 1.]);
    floats(&mut bin, &[0., 1., 2., 1., 2., -1., 0., -1.]);
    for i in [0u16, 1, 2, 0, 2, 3] {
        bin.extend(i.to_le_bytes());
    }
    floats(&mut bin, &[0., 0., 0.5, 1.5, 0., -0.5, 0., 1.5, 0.2]);
    let image = Texture2d::from_fn(4, 4, |x, y| {
        let on = (x + y) % 2 == 0;
        Srgba8(if on {
            [230, 40, 40, 255]
        } else {
            [30, 30, 200, 160]
        })
    })
    .and_then(|t| encode_png(&t))
    .expect("a 4×4 PNG");
    format!(
        r#"{{"asset": {{"version": "2.0"}},
  "extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform"],
  "extensions": {{"KHR_lights_punctual": {{"lights": [
    {{"type": "point", "color": [1, 0.9, 0.8], "intensity": 20, "range": 10}},
    {{"type": "spot", "intensity": 40, "spot": {{"innerConeAngle": 0.2, "outerConeAngle": 0.6}}}},
    {{"type": "directional", "color": [0.3, 0.3, 0.5], "intensity": 1.5}}]}}}},
  "buffers": [{{"byteLength": {len}, "uri": "data:application/octet-stream;base64,{data}"}}],
  "bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": 48}},
                  {{"buffer": 0, "byteOffset": 48, "byteLength": 48}},
                  {{"buffer": 0, "byteOffset": 96, "byteLength": 32}},
                  {{"buffer": 0, "byteOffset": 128, "byteLength": 12}},
                  {{"buffer": 0, "byteOffset": 140, "byteLength": 36}}],
  "accessors": [
    {{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]}},
    {{"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"}},
    {{"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"}},
    {{"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}},
    {{"bufferView": 4, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, -0.5], "max": [1.5, 1.5, 0.5]}}],
  "images": [{{"uri": "data:image/png;base64,{png}"}}],
  "samplers": [{{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 33648}}],
  "textures": [{{"source": 0, "sampler": 0}}],
  "materials": [
    {{"pbrMetallicRoughness": {{"baseColorTexture": {{"index": 0, "extensions": {{"KHR_texture_transform":
       {{"offset": [0.25, 0], "rotation": 0.3, "scale": [3, 2]}}}}}}, "roughnessFactor": 0.3}}}},
    {{"pbrMetallicRoughness": {{"baseColorFactor": [0.2, 0.8, 0.3, 0.7]}}, "emissiveFactor": [0.1, 0, 0.2],
      "alphaMode": "BLEND", "doubleSided": true}}],
  "meshes": [{{"primitives": [
    {{"attributes": {{"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}, "indices": 3, "material": 0}},
    {{"attributes": {{"POSITION": 4}}, "material": 1}}]}}],
  "cameras": [{{"type": "perspective", "perspective": {{"yfov": 0.8, "znear": 0.1, "zfar": 50}}}}],
  "nodes": [
    {{"mesh": 0, "rotation": [0.1, 0.2, 0, 0.9747]}},
    {{"camera": 0, "translation": [0.3, 0.2, 3.5]}},
    {{"extensions": {{"KHR_lights_punctual": {{"light": 0}}}}, "translation": [1, 1, 2]}},
    {{"extensions": {{"KHR_lights_punctual": {{"light": 1}}}}, "translation": [0, 0, 3]}},
    {{"extensions": {{"KHR_lights_punctual": {{"light": 2}}}}, "rotation": [-0.38, 0, 0, 0.925]}}],
  "scenes": [{{"nodes": [0, 1, 2, 3, 4]}}]}}"#,
        len = bin.len(),
        data = base64(&bin),
        png = base64(&image),
    )
}

/// The scene, loaded once.
///
/// # Panics
/// If the fixed document does not load (a bug this crate's tests catch).
pub fn render_options_scene() -> &'static Scene {
    static SCENE: OnceLock<Scene> = OnceLock::new();
    SCENE.get_or_init(|| {
        load_slice(render_options_gltf().as_bytes(), &LoadOptions::default())
            .expect("the render_options scene loads")
    })
}

/// Decodes `bytes` (any length).
#[must_use]
pub fn render_options_input(bytes: &[u8]) -> RenderOptions {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let unorm = |i: usize| f32::from(byte(i)) / 255.0;
    let camera = match byte(2) {
        0 => CameraChoice::First,
        1 => CameraChoice::Auto,
        n => CameraChoice::Index(usize::from(n - 2)),
    };
    let shading = [
        Shading::Unlit,
        Shading::Flat,
        Shading::Gouraud,
        Shading::Phong,
        Shading::Hybrid,
    ][usize::from(byte(3) % 5)];
    let filter = match byte(4) % 6 {
        0 => Filter::FromFile,
        1 => Filter::Nearest,
        2 => Filter::Bilinear,
        3 => Filter::Trilinear,
        4 => Filter::Anisotropic(u16::from(byte(5))),
        _ => Filter::Ewa,
    };
    let n = u32::from(byte(7) % 18);
    let anti_aliasing = match byte(6) % 5 {
        0 => AntiAliasing::None,
        1 => AntiAliasing::Supersample(n),
        2 => AntiAliasing::Jitter(n),
        3 => AntiAliasing::Msaa(n),
        _ => AntiAliasing::Adaptive(n),
    };
    let flags = byte(8);
    let density = f32::from_bits(u32::from_le_bytes([byte(16), byte(17), byte(18), byte(19)]));
    let fog = (flags & 1 != 0).then_some(ExponentialFog {
        density,
        colour: Vec3::new(unorm(13), unorm(14), unorm(15)),
        distance: if flags & 2 != 0 {
            FogDistance::ViewDepth
        } else {
            FogDistance::Euclidean
        },
    });
    RenderOptions {
        width: u32::from(byte(0) % 65),
        height: u32::from(byte(1) % 65),
        camera,
        shading,
        filter,
        anti_aliasing,
        background: Vec4::new(unorm(9), unorm(10), unorm(11), unorm(12)),
        fog,
        measure_stages: flags & 4 != 0,
        // The scene has no portals: the depth changes nothing, so no byte decodes it.
        portal_depth: RenderOptions::default().portal_depth,
    }
}

/// The invariants (see the module documentation).
///
/// # Errors
/// A description of the violated invariant.
pub fn check_render_options(bytes: &[u8]) -> Result<(), String> {
    let options = render_options_input(bytes);
    let scene = render_options_scene();
    let got = render(scene, &options);
    let camera_index = match options.camera {
        CameraChoice::Index(i) => Some(i),
        _ => None,
    };
    let size_ok = options.width > 0 && options.height > 0;
    let camera_ok = camera_index.is_none_or(|i| i < scene.cameras.len());
    let aa_ok = match options.anti_aliasing {
        AntiAliasing::Supersample(n) | AntiAliasing::Jitter(n) => (1..=16).contains(&n),
        AntiAliasing::Msaa(n) => [1, 2, 4, 8, 16].contains(&n),
        AntiAliasing::None | AntiAliasing::Adaptive(_) => true,
    };
    match got {
        Ok(out) => {
            if !(size_ok && camera_ok && aa_ok) {
                return Err(format!("{options:?} rendered, though invalid"));
            }
            let image = &out.image;
            if (image.width(), image.height()) != (options.width, options.height) {
                return Err(format!(
                    "{options:?}: a {}×{} image",
                    image.width(),
                    image.height()
                ));
            }
            for y in 0..options.height {
                for x in 0..options.width {
                    let p = image.pixel(x, y);
                    if p.is_none_or(|p| p.is_nan()) {
                        return Err(format!("{options:?}: pixel ({x}, {y}) is {p:?}"));
                    }
                }
            }
            Ok(())
        }
        Err(e) => {
            let expected = match &e {
                RenderError::InvalidOption(_) => {
                    !size_ok
                        || matches!(
                            options.anti_aliasing,
                            AntiAliasing::Supersample(_) | AntiAliasing::Jitter(_)
                        ) && !aa_ok
                }
                RenderError::NoSuchCamera { index, count } => {
                    size_ok
                        && Some(*index) == camera_index
                        && *count == scene.cameras.len()
                        && !camera_ok
                }
                RenderError::Raster(_) => {
                    size_ok
                        && camera_ok
                        && matches!(options.anti_aliasing, AntiAliasing::Msaa(_))
                        && !aa_ok
                }
                _ => false,
            };
            if expected {
                Ok(())
            } else {
                Err(format!("{options:?} failed: {e:?}"))
            }
        }
    }
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn render_options_code(bytes: &[u8]) -> String {
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    // {:?}", render_options_input(bytes));
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_render_options(bytes), Ok(()));\n}");
    out
}
