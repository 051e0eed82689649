//! A scene prepared once and drawn as often as asked: what an animation loop, a service that
//! redraws one model, or a benchmark of the draw alone needs — the preparation (camera,
//! world-space geometry, textures and their mip chains, lights) is paid once, and every later
//! draw reuses it and finds the allocator's memory already mapped (a first draw in a process
//! touches fresh pages for its target, vertex outputs and bins).

use barytex_gltf::scene::Scene;

use crate::framing::RenderCamera;
use crate::passes::{self, Varyings};
use crate::prepare::{self, Prepared};
use crate::{RenderError, RenderOptions, RenderStats, Rendered};

/// A scene prepared for drawing with fixed [`RenderOptions`]; [`render`](Self::render) draws it.
/// Each draw gives the same image as [`render`](crate::render) with the same options.
///
/// ```
/// use barytex_render::{PreparedScene, RenderOptions, Shading, render};
///
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// let options = RenderOptions { width: 32, height: 24, shading: Shading::Unlit, ..RenderOptions::default() };
/// let prepared = PreparedScene::new(&scene, &options)?;
/// let once = render(&scene, &options)?;
/// for _ in 0..3 {
///     let frame = prepared.render()?;
///     assert_eq!(frame.image.to_srgba8()?, once.image.to_srgba8()?);
///     assert_eq!(frame.stats.draw, once.stats.draw);
/// }
/// assert_eq!(prepared.camera(), &once.camera);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub struct PreparedScene<'a> {
    prepared: Prepared<'a>,
    options: RenderOptions,
}

impl<'a> PreparedScene<'a> {
    /// Prepares `scene` for drawing as `options` ask.
    ///
    /// # Errors
    /// As [`render`](crate::render): a zero or oversized image, a camera index beyond the
    /// scene's, a scene with nothing to frame, a texture that cannot be prepared (an invalid
    /// sample count shows at the first draw).
    pub fn new(scene: &'a Scene, options: &RenderOptions) -> Result<Self, RenderError> {
        let (width, height) = (options.width, options.height);
        if width == 0 || height == 0 || width > 16_384 || height > 16_384 {
            return Err(RenderError::InvalidOption(format!(
                "image size {width}×{height} (each side 1 to 16384)"
            )));
        }
        Ok(Self {
            prepared: prepare::prepare(scene, options)?,
            options: *options,
        })
    }

    /// The camera every draw uses.
    #[must_use]
    pub fn camera(&self) -> &RenderCamera {
        &self.prepared.camera
    }

    /// Draws the scene into a new target. The statistics repeat the preparation's figures
    /// (`prepare_seconds`, `mip_seconds`: the one preparation) beside this draw's own.
    ///
    /// # Errors
    /// An invalid sample count, or a target that cannot be allocated.
    pub fn render(&self) -> Result<Rendered, RenderError> {
        self.render_with_progress(&mut |_, _| {})
    }

    /// [`render`](Self::render), calling `on_pass(done, planned)` after each pass over the
    /// scene, as [`render_with_progress`](crate::render_with_progress) does.
    ///
    /// # Errors
    /// As [`render`](Self::render).
    pub fn render_with_progress(
        &self,
        on_pass: &mut dyn FnMut(u32, u32),
    ) -> Result<Rendered, RenderError> {
        self.render_varyings(Varyings::Read, on_pass)
    }

    /// A draw that interpolates the parts of the varying `varyings` says.
    pub(crate) fn render_varyings(
        &self,
        varyings: Varyings,
        on_pass: &mut dyn FnMut(u32, u32),
    ) -> Result<Rendered, RenderError> {
        let drawn = passes::draw_passes(&self.prepared, &self.options, varyings, on_pass)?;
        let stats = RenderStats::of(&self.prepared, &drawn);
        Ok(Rendered {
            image: drawn.image,
            camera: self.prepared.camera,
            stats,
        })
    }
}
