//! glTF 2.0 and GLB scenes: a validating loader that never panics, flattened for rendering.
//!
//! Files are untrusted input. The GLB container is parsed here with every length checked; the
//! JSON is read field by field with JSON-pointer errors; every index, accessor range, stride,
//! attribute format, index value, sparse substitution and image header is checked before it is
//! used; sizes are compared with [`SceneLimits`] before anything of that size is allocated; and
//! the whole load runs under [`std::panic::catch_unwind`] as a last line of defence (a panic
//! becomes [`SceneError::Internal`], which is a bug).
//!
//! The result is a [`Scene`]: for the chosen scene (the `scene` property, or the first), every
//! mesh instance with its world matrix and decoded triangle primitives, cameras, lights
//! (`KHR_lights_punctual`), materials (with `KHR_materials_unlit` and `KHR_texture_transform`) and
//! the images those materials sample, decoded in the right colour space.
//!
//! ```
//! use barytex_gltf::{load_slice, LoadOptions};
//!
//! // One triangle: three float positions (36 bytes) in a base64 data URI.
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
//! println!("{} triangle(s)", scene.triangle_count());
//! assert_eq!(scene.triangle_count(), 1);
//! # Ok::<(), barytex_gltf::SceneError>(())
//! ```
//!
//! # File access
//!
//! A glTF's relative URIs (RFC 3986 §4.2; percent-decoded per §2.1, so `%2e%2e/` is `../`) read
//! only files under the model's folder, plus the folders in [`LoadOptions::allowed_roots`]. A
//! path that leaves them lexically is refused without asking the file system (a missing and an
//! existing outside file get the same error), and the canonical path (after symbolic links) is
//! checked again; either refusal is [`SceneError::Denied`] at the URI's JSON pointer. Only
//! regular files are read (not devices or FIFOs: the type is checked before opening and on the
//! opened handle), and never more than the limit, whatever the metadata claims; [`load_path`]
//! reads the model itself the same way. Absolute URLs (`http:`, `file:`) are never fetched. An
//! embedder that keeps assets elsewhere serves URIs itself through a [`UriResolver`] and
//! [`load_with_resolver`]. Error messages name objects by JSON pointer and elements by index,
//! never by values read from a file.
#![forbid(unsafe_code)]

mod access;
mod accessor;
mod animation;
mod buffer;
pub mod camera;
mod document;
mod error;
mod extensions;
mod glb;
mod image;
mod image_decode;
mod json;
pub mod light;
mod limits;
pub mod material;
pub mod mesh;
mod node;
pub mod portal;
mod portal_def;
pub mod sampler;
pub mod scene;
mod skin;
pub mod topology;
mod uri;
mod variants;

use std::path::{Path, PathBuf};

pub use access::{ResolveError, UriResolver, read_regular_file};
pub use camera::{DocumentCamera, Projection, SceneCamera};
pub use error::SceneError;
pub use glb::glb_chunks;
pub use light::{LightKind, PunctualLight, SceneLight};
pub use limits::SceneLimits;
pub use material::{AlphaMode, Material, TextureRef, TextureRole, TextureRoles};
pub use mesh::{Mesh, Primitive};
pub use portal::{MAX_PORTAL_VERTICES, Portal, PortalError};
pub use sampler::{MagFilter, MinFilter, SamplerParams, Wrap};
pub use scene::{MeshInstance, Scene, SceneImage, SceneStats, Texture};
pub use topology::Topology;

/// How to load.
///
/// ```
/// use barytex_gltf::{LoadOptions, SceneError, load_slice};
///
/// // Two scenes; the document's `scene` picks the second unless the options say otherwise.
/// let gltf = r#"{"asset": {"version": "2.0"}, "scene": 1,
///   "nodes": [{"name": "a"}, {"name": "b"}, {"name": "c"}],
///   "scenes": [{"name": "first", "nodes": [0]}, {"name": "second", "nodes": [1, 2]}]}"#;
/// let default = load_slice(gltf.as_bytes(), &LoadOptions::default())?;
/// assert_eq!((default.scene_index, default.name.as_deref()), (Some(1), Some("second")));
/// let first = load_slice(gltf.as_bytes(), &LoadOptions { scene: Some(0), ..LoadOptions::default() })?;
/// assert_eq!((first.stats.nodes_visited, first.scene_count), (1, 2));
/// # Ok::<(), SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadOptions {
    /// Size limits for untrusted input.
    pub limits: SceneLimits,
    /// Which scene to flatten; `None` is the document's `scene`, else the first.
    pub scene: Option<usize>,
    /// Whether to decode the images the scene's materials sample (their bytes are checked
    /// either way).
    pub decode_images: bool,
    /// Which textures the caller will sample (all by default). Images that the scene's
    /// materials sample only in the other roles are neither decoded nor required: one that is
    /// missing or broken is a warning, not an error — a renderer drawing unlit never reads
    /// normal or metallic-roughness maps. (An image no material samples is checked as always.)
    pub image_roles: TextureRoles,
    /// Folders besides the model's own that its relative URIs may reach (e.g. a shared
    /// textures folder beside the model's). Empty by default: a document reads only files under
    /// its own folder. A root that does not exist allows nothing.
    pub allowed_roots: Vec<PathBuf>,
    /// How many threads decode images (the calling thread and scoped helpers, each decoding
    /// one image at a time; 0: as many as the machine has). 1 by default: the caller decides
    /// whether a load may use more cores. The scene is the same for any count, errors
    /// included; each image decoding at once holds its own temporary buffers.
    pub decode_threads: usize,
}

impl Default for LoadOptions {
    fn default() -> Self {
        Self {
            limits: SceneLimits::default(),
            scene: None,
            decode_images: true,
            image_roles: TextureRoles::ALL,
            allowed_roots: Vec::new(),
            decode_threads: 1,
        }
    }
}

fn guarded(f: impl FnOnce() -> Result<Scene, SceneError>) -> Result<Scene, SceneError> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|payload| {
        let msg = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Err(SceneError::Internal(msg))
    })
}

/// Loads a glTF (JSON) or GLB held in memory. External files cannot be resolved (there is no
/// folder): buffers and images must be embedded (GLB chunk, `bufferView` or `data:` URI).
///
/// # Errors
/// Any [`SceneError`]: malformed container or JSON, an invalid object, a limit exceeded.
///
/// ```
/// use barytex_gltf::{LoadOptions, SceneError, load_slice};
///
/// // A buffer the loader cannot reach without a folder to resolve it in.
/// let external = br#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri": "triangle.bin"}]}"#;
/// let err = load_slice(external, &LoadOptions::default()).unwrap_err();
/// assert_eq!(err.pointer(), Some("/buffers/0/uri"));
/// // Not glTF at all.
/// assert!(matches!(load_slice(b"{", &LoadOptions::default()), Err(SceneError::Json(_))));
/// // A document with nothing to draw loads as an empty scene.
/// let empty = load_slice(br#"{"asset": {"version": "2.0"}}"#, &LoadOptions::default())?;
/// assert_eq!(empty.triangle_count(), 0);
/// # Ok::<(), SceneError>(())
/// ```
pub fn load_slice(bytes: &[u8], options: &LoadOptions) -> Result<Scene, SceneError> {
    guarded(|| document::load(bytes, None, false, options))
}

/// Loads a glTF or GLB held in memory whose relative URIs resolve against `base_dir`, confined
/// to it and to [`LoadOptions::allowed_roots`] (see the crate's file-access policy).
///
/// # Errors
/// As [`load_slice`], plus [`SceneError::Io`] for a missing external file and
/// [`SceneError::Denied`] for one outside the allowed folders or not a regular file.
///
/// ```
/// use barytex_gltf::{LoadOptions, SceneError, load_slice_with_base};
///
/// // The triangle's positions in an external .bin next to where the JSON "lives".
/// let dir = std::env::temp_dir().join(format!("barytex-doc-base-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).map_err(|e| SceneError::Io { path: dir.display().to_string(), source: e })?;
/// let positions: [f32; 9] = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
/// let bin: Vec<u8> = positions.iter().flat_map(|p| p.to_le_bytes()).collect();
/// std::fs::write(dir.join("triangle.bin"), bin).map_err(|e| SceneError::Io { path: "triangle.bin".into(), source: e })?;
/// let gltf = br#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri": "triangle.bin"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}"#;
/// let scene = load_slice_with_base(gltf, &dir, &LoadOptions::default());
/// let missing = load_slice_with_base(gltf, &dir.join("elsewhere"), &LoadOptions::default());
/// std::fs::remove_dir_all(&dir).ok();
/// assert_eq!(scene?.triangle_count(), 1);
/// assert!(matches!(missing, Err(SceneError::Io { .. })));
/// # Ok::<(), SceneError>(())
/// ```
pub fn load_slice_with_base(
    bytes: &[u8],
    base_dir: &Path,
    options: &LoadOptions,
) -> Result<Scene, SceneError> {
    let files = access::FolderResolver {
        base: base_dir,
        extra: &options.allowed_roots,
    };
    guarded(|| document::load(bytes, Some(&files), false, options))
}

/// Loads a glTF or GLB held in memory whose relative URIs `resolver` serves (see
/// [`UriResolver`], with an example). [`LoadOptions::allowed_roots`] is not used: the resolver
/// alone decides what a document may read.
///
/// # Errors
/// As [`load_slice`], plus [`SceneError::Denied`], [`SceneError::Io`] or
/// [`SceneError::TooLarge`] for a file the resolver refused or could not read.
pub fn load_with_resolver(
    bytes: &[u8],
    resolver: &dyn UriResolver,
    options: &LoadOptions,
) -> Result<Scene, SceneError> {
    guarded(|| document::load(bytes, Some(resolver), false, options))
}

/// Loads a `.gltf` or `.glb` file (a `.glb` extension, or the GLB magic, selects the binary
/// container); relative URIs resolve against the file's folder, confined to it and to
/// [`LoadOptions::allowed_roots`]. The file must be a regular file (not a device or a FIFO).
///
/// # Errors
/// As [`load_slice_with_base`].
///
/// ```
/// use barytex_gltf::{LoadOptions, SceneError, SceneLimits, load_path};
///
/// let io = |e| SceneError::Io { path: "temporary file".into(), source: e };
/// let path = std::env::temp_dir().join(format!("barytex-doc-path-{}.gltf", std::process::id()));
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [2, 0, 0]}], "scenes": [{"nodes": [0, 1]}]}"#;
/// std::fs::write(&path, gltf).map_err(io)?;
/// let scene = load_path(&path, &LoadOptions::default());
/// // The file size is checked before the file is read.
/// let tiny = LoadOptions { limits: SceneLimits { max_file_bytes: 100, ..SceneLimits::default() }, ..LoadOptions::default() };
/// let refused = load_path(&path, &tiny);
/// std::fs::remove_file(&path).ok();
/// assert_eq!(scene?.instances.len(), 2);
/// assert!(matches!(refused, Err(SceneError::TooLarge { what: "file bytes", limit: 100, .. })));
/// assert!(matches!(load_path(&path, &LoadOptions::default()), Err(SceneError::Io { .. })));
/// # Ok::<(), SceneError>(())
/// ```
pub fn load_path(path: impl AsRef<Path>, options: &LoadOptions) -> Result<Scene, SceneError> {
    let path = path.as_ref();
    guarded(|| {
        let io = |source| SceneError::Io {
            path: path.display().to_string(),
            source,
        };
        let limit = options.limits.max_file_bytes;
        let bytes = access::read_regular_file(path, limit).map_err(|e| match e {
            access::ResolveError::TooLarge(requested) => SceneError::TooLarge {
                pointer: String::new(),
                what: "file bytes",
                requested,
                limit,
            },
            access::ResolveError::Io(source) => io(source),
            other => io(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                other.to_string(),
            )),
        })?;
        let is_glb = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("glb"));
        let files = access::FolderResolver {
            base: path.parent().unwrap_or_else(|| Path::new(".")),
            extra: &options.allowed_roots,
        };
        document::load(&bytes, Some(&files), is_glb, options)
    })
}

/// The README's examples, compiled and run as doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
