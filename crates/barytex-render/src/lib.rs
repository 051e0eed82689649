//! The reference renderer: a flattened [`Scene`] (loaded by barytex-gltf, or the built-in
//! [`demo`] scene) drawn by barytex-raster — cameras (the scene's or the automatic one), glTF
//! materials (base colour, vertex colours, alpha modes, emission, occlusion, normal maps, unlit),
//! punctual lights, fog, and every anti-aliasing mode of the rasterizer.
//!
//! It composes the workspace's seams and re-implements none of them: every texel is looked up
//! through a barytex-uv [`UvMapping`](barytex_uv::UvMapping) (the material's uv set with
//! `KHR_texture_transform`, or the environment's direction) and a barytex-texture
//! [`Sampler`](barytex_texture::Sampler); every light is a barytex-shade
//! [`Light`](barytex_shade::Light) evaluated by [`PhongMaterial::shade`](barytex_shade::PhongMaterial::shade)
//! with the normalized Blinn–Phong lobe, under every shading mode.
//!
//! A render runs in three stages a reader can follow: *prepare* (camera, world-space geometry,
//! textures, lights, and the per-polygon work of flat and hybrid shading), *passes* (one draw per
//! item and shading frequency, per anti-aliasing pass), and *stats* ([`RenderStats`]). It models
//! only what the image needs: textures are prepared only for materials the scene draws, mip
//! chains are built only for textures that end up minified on screen, and the statistics say
//! what was skipped.
//!
//! ```
//! use barytex_render::{render, RenderOptions};
//! use barytex_gltf::{load_slice, LoadOptions};
//!
//! let gltf = r#"{
//!   "asset": {"version": "2.0"},
//!   "buffers": [{"byteLength": 36, "uri":
//!     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
//!   "bufferViews": [{"buffer": 0, "byteLength": 36}],
//!   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
//!                  "min": [0, 0, 0], "max": [1, 1, 0]}],
//!   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
//!   "nodes": [{"mesh": 0}],
//!   "scenes": [{"nodes": [0]}]
//! }"#;
//! let scene = load_slice(gltf.as_bytes(), &LoadOptions::default())?;
//! let out = render(&scene, &RenderOptions { width: 64, height: 48, ..RenderOptions::default() })?;
//! assert!(out.stats.draw.fragments_shaded > 0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod demo;
mod framing;
mod lights;
mod material_shader;
mod options;
mod passes;
mod portals;
mod prepare;
mod prepared_scene;
mod raster_only;
mod stats;
mod surface;
mod textures;
mod unlit_shader;
mod view_draw;

use std::fmt;

use barytex_gltf::scene::Scene;
use barytex_raster::{Framebuffer, RasterError};
use barytex_texture::TextureError;

pub use framing::{CameraSource, RenderCamera, auto_camera, scene_bounds, scene_camera};
pub use options::{AntiAliasing, CameraChoice, Filter, RenderOptions, ResolvedFilter, Shading};
pub use prepare::choose_camera;
pub use prepared_scene::PreparedScene;
pub use stats::RenderStats;
pub use view_draw::MAX_PORTAL_VIEWS_PER_PASS;

use passes::Varyings;

/// Why a scene could not be rendered.
///
/// ```
/// use barytex_render::{CameraChoice, RenderError, RenderOptions, render};
///
/// let empty = barytex_gltf::Scene::default();
/// let small = RenderOptions { width: 8, height: 8, ..RenderOptions::default() };
/// assert_eq!(render(&empty, &small).unwrap_err(), RenderError::NothingToFrame);
/// let second = RenderOptions { camera: CameraChoice::Index(1), ..small };
/// assert_eq!(render(&empty, &second).unwrap_err(), RenderError::NoSuchCamera { index: 1, count: 0 });
/// let no_pixels = RenderOptions { width: 0, ..small };
/// assert!(matches!(render(&empty, &no_pixels), Err(RenderError::InvalidOption(_))));
///
/// // `CameraChoice::Index` is the document's index: a camera no node of the scene places is
/// // refused by name.
/// let gltf = br#"{"asset": {"version": "2.0"},
///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
///               {"name": "spare", "type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
///   "nodes": [{"camera": 0}], "scenes": [{"nodes": [0]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf, &barytex_gltf::LoadOptions::default()).unwrap();
/// let spare = RenderOptions { camera: CameraChoice::Index(1), ..small };
/// let error = render(&scene, &spare).unwrap_err();
/// assert_eq!(error, RenderError::CameraNotPlaced { index: 1, name: Some("spare".into()), scene: Some(0) });
/// assert_eq!(error.to_string(), "camera 1 (\"spare\") is not placed by any node of scene 0");
/// let third = RenderOptions { camera: CameraChoice::Index(2), ..small };
/// assert_eq!(render(&scene, &third).unwrap_err().to_string(), "no camera 2: the document has 2 cameras");
/// ```
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum RenderError {
    /// The scene has no finite vertex to look at (and no camera was given).
    NothingToFrame,
    /// `--camera N` beyond the document's cameras.
    NoSuchCamera {
        /// The index asked for.
        index: usize,
        /// Cameras in the document.
        count: usize,
    },
    /// `--camera N` for a camera of the document that no node of the scene places.
    CameraNotPlaced {
        /// The index asked for.
        index: usize,
        /// The camera's name, if any.
        name: Option<String>,
        /// The scene (`None`: the document has no scenes and every root node was used).
        scene: Option<usize>,
    },
    /// `--camera N` placed by a node whose world matrix has no inverse (a zero scale).
    SingularCamera {
        /// The index asked for.
        index: usize,
        /// The first node that places it.
        node: usize,
    },
    /// A parameter out of range (size, sample count).
    InvalidOption(String),
    /// A texture could not be allocated or built.
    Texture(TextureError),
    /// The target could not be made: an invalid sample count, a size over the limits, a failed
    /// allocation.
    Raster(RasterError),
    /// The scene's world-space geometry could not be allocated (every mesh instance is copied
    /// into world space; the loader's `SceneLimits` bound how much a file can ask for, a
    /// hand-built scene is bounded by nothing but memory).
    OutOfMemory {
        /// What was being allocated.
        what: &'static str,
        /// How many elements were asked for.
        count: usize,
    },
    /// The scene asks for something this renderer does not draw, rather than drawing it
    /// differently: a material sampling a texture coordinate set other than `TEXCOORD_0` and
    /// `TEXCOORD_1` (the loader decodes those two).
    Unsupported {
        /// The material's index (`None`: the default material).
        material: Option<usize>,
        /// What it asks for.
        what: String,
    },
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NothingToFrame => write!(f, "the scene has no finite vertex to frame"),
            Self::NoSuchCamera { index, count } => {
                let s = if *count == 1 { "" } else { "s" };
                write!(f, "no camera {index}: the document has {count} camera{s}")
            }
            Self::CameraNotPlaced { index, name, scene } => {
                write!(f, "camera {index}")?;
                if let Some(name) = name {
                    write!(f, " ({name:?})")?;
                }
                match scene {
                    Some(scene) => write!(f, " is not placed by any node of scene {scene}"),
                    None => write!(f, " is not placed by any node of the scene"),
                }
            }
            Self::SingularCamera { index, node } => write!(
                f,
                "camera {index} is placed by node {node}, whose world matrix has no inverse"
            ),
            Self::InvalidOption(why) => write!(f, "invalid render option: {why}"),
            Self::Texture(e) => write!(f, "{e}"),
            Self::Raster(e) => write!(f, "{e}"),
            Self::OutOfMemory { what, count } => {
                write!(f, "out of memory allocating {count} {what}")
            }
            Self::Unsupported { material, what } => match material {
                Some(m) => write!(f, "material {m} asks for {what}, which is not supported"),
                None => write!(
                    f,
                    "the default material asks for {what}, which is not supported"
                ),
            },
        }
    }
}

impl std::error::Error for RenderError {}

impl From<TextureError> for RenderError {
    fn from(e: TextureError) -> Self {
        Self::Texture(e)
    }
}

impl From<RasterError> for RenderError {
    fn from(e: RasterError) -> Self {
        Self::Raster(e)
    }
}

/// A rendered image with its camera and statistics.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The image (linear light; `to_srgba8` encodes it).
    pub image: Framebuffer,
    /// The camera used.
    pub camera: RenderCamera,
    /// What happened.
    pub stats: RenderStats,
}

/// Renders `scene` as `options` ask.
///
/// # Errors
/// A zero or oversized image, an invalid sample count, a camera index beyond the scene's, a
/// scene with nothing to frame, or a texture that cannot be prepared.
///
/// ```
/// use barytex_render::{RenderOptions, Shading, auto_camera, render};
/// use glam::{Vec3, Vec4};
///
/// // An orange triangle, unlit, through the automatic camera.
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0, 1]}}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
///   "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// let options = RenderOptions { width: 32, height: 32, shading: Shading::Unlit, ..RenderOptions::default() };
/// let out = render(&scene, &options)?;
/// assert_eq!(out.camera, auto_camera(&scene, 1.0).unwrap());
/// // Where the camera sees the triangle's centroid, the pixel is the base colour exactly.
/// let clip = out.camera.projection * out.camera.view * Vec3::splat(1.0 / 3.0).with_z(0.0).extend(1.0);
/// let (x, y) = ((clip.x / clip.w + 1.0) * 16.0, (1.0 - clip.y / clip.w) * 16.0);
/// assert_eq!(out.image.pixel(x as u32, y as u32), Some(Vec4::new(1.0, 0.5, 0.0, 1.0)));
/// // A corner shows the background.
/// assert_eq!(out.image.pixel(31, 0), Some(options.background));
/// assert_eq!(out.stats.triangles, 1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<Rendered, RenderError> {
    render_with_progress(scene, options, &mut |_, _| {})
}

/// The passes over the scene `anti_aliasing` plans: `n²` for accumulated supersampling (`n > 5`),
/// at most `max(n, 4)` for adaptive sampling (it stops when every pixel has converged), else 1.
///
/// ```
/// use barytex_render::{AntiAliasing, planned_passes};
///
/// assert_eq!(planned_passes(AntiAliasing::None), 1);
/// assert_eq!(planned_passes(AntiAliasing::Msaa(8)), 1);
/// assert_eq!(planned_passes(AntiAliasing::Supersample(4)), 1); // up to 5×5 in one pass
/// assert_eq!(planned_passes(AntiAliasing::Supersample(6)), 36); // accumulated, one pass each
/// assert_eq!(planned_passes(AntiAliasing::Adaptive(2)), 4);
/// assert_eq!(planned_passes(AntiAliasing::Adaptive(16)), 16);
/// ```
#[must_use]
pub fn planned_passes(anti_aliasing: AntiAliasing) -> u32 {
    match anti_aliasing {
        AntiAliasing::Supersample(n) | AntiAliasing::Jitter(n) if (6..=16).contains(&n) => n * n,
        AntiAliasing::Adaptive(max) => max.max(4),
        _ => 1,
    }
}

/// [`render`], calling `on_pass(done, planned)` after each pass over the scene, with the
/// [`planned_passes`] (for a progress bar; adaptive sampling may finish before `planned`).
///
/// # Errors
/// As [`render`].
///
/// ```
/// use barytex_render::{AntiAliasing, RenderOptions, planned_passes, render_with_progress};
///
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0, 1]}}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
///   "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// let aa = AntiAliasing::Jitter(6);
/// let options = RenderOptions { width: 8, height: 8, anti_aliasing: aa, ..RenderOptions::default() };
/// let mut calls = Vec::new();
/// let out = render_with_progress(&scene, &options, &mut |done, planned| calls.push((done, planned)))?;
/// assert_eq!(calls.len(), 36);
/// assert_eq!(calls.last(), Some(&(36, planned_passes(aa))));
/// assert_eq!(out.stats.passes, 36);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn render_with_progress(
    scene: &Scene,
    options: &RenderOptions,
    on_pass: &mut dyn FnMut(u32, u32),
) -> Result<Rendered, RenderError> {
    render_varyings(scene, options, Varyings::Read, on_pass)
}

/// The three stages of a render: [`prepare`](prepare::prepare) (camera, world-space geometry,
/// textures, lights), [`draw_passes`](passes::draw_passes) (the shaders over every
/// anti-aliasing pass), and the [`RenderStats`] of both.
fn render_varyings(
    scene: &Scene,
    options: &RenderOptions,
    varyings: Varyings,
    on_pass: &mut dyn FnMut(u32, u32),
) -> Result<Rendered, RenderError> {
    PreparedScene::new(scene, options)?.render_varyings(varyings, on_pass)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::demo::{demo_options, demo_scene};

    fn pixels(scene: &Scene, options: &RenderOptions, varyings: Varyings) -> Vec<[u8; 4]> {
        let out = render_varyings(scene, options, varyings, &mut |_, _| {}).expect("renders");
        let image = out.image.to_srgba8().expect("small");
        image.texels().iter().map(|t| t.0).collect()
    }

    /// Interpolating only what a material reads changes no pixel by more than one sRGB step
    /// (the one difference: an absent vertex colour is exactly white instead of a weighted sum
    /// of whites), for every shading model and with and without fog; the unlit short path
    /// (taken only with `Varyings::Read`) is checked against the general one here too.
    #[test]
    fn skipping_unread_varyings_changes_no_pixel() {
        let scene = demo_scene();
        for shading in [
            Shading::Unlit,
            Shading::Flat,
            Shading::Gouraud,
            Shading::Phong,
            Shading::Hybrid,
        ] {
            for fog in [demo_options(1, 1).fog, None] {
                let options = RenderOptions {
                    shading,
                    fog,
                    ..demo_options(96, 54)
                };
                let everything = pixels(&scene, &options, Varyings::All);
                let read = pixels(&scene, &options, Varyings::Read);
                let worst = everything
                    .iter()
                    .zip(&read)
                    .flat_map(|(a, b)| (0..4).map(move |c| a[c].abs_diff(b[c])))
                    .max()
                    .unwrap_or(0);
                assert!(
                    worst <= 1,
                    "{shading:?}, fog {}: {worst} steps",
                    fog.is_some()
                );
            }
        }
    }
}

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
