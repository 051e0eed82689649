//! Size limits for untrusted scenes, checked against what a file *claims* before anything of
//! that size is allocated: a 100-byte glTF may declare a billion-element accessor.

/// The largest scene this crate will load. Every count is checked against the JSON's claims
/// before the matching allocation, so a hostile file fails fast instead of exhausting memory.
///
/// ```
/// use barytex_gltf::{LoadOptions, SceneError, SceneLimits, load_slice};
///
/// // A small file that claims an accessor of a billion zeros (no bufferView backs it).
/// let hostile = br#"{"asset": {"version": "2.0"},
///   "accessors": [{"componentType": 5126, "count": 1000000000, "type": "VEC3"}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]}"#;
/// let err = load_slice(hostile, &LoadOptions::default()).unwrap_err();
/// assert!(matches!(err, SceneError::TooLarge { .. }), "{err}");
/// assert_eq!(err.pointer(), Some("/accessors/0/count"));
/// // Limits can be tightened for a service that only expects small assets.
/// let small = SceneLimits { max_nodes: 1, ..SceneLimits::default() };
/// let two_nodes = br#"{"asset": {"version": "2.0"}, "nodes": [{}, {}]}"#;
/// let options = LoadOptions { limits: small, ..LoadOptions::default() };
/// assert!(matches!(load_slice(two_nodes, &options), Err(SceneError::TooLarge { .. })));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SceneLimits {
    /// Largest glTF/GLB file, in bytes.
    pub max_file_bytes: u64,
    /// Largest single buffer (GLB BIN chunk, external `.bin`, decoded data URI), in bytes.
    pub max_buffer_bytes: u64,
    /// Largest sum of all buffers, in bytes.
    pub max_total_buffer_bytes: u64,
    /// Largest image file (encoded bytes).
    pub max_image_file_bytes: u64,
    /// Image side and decoded-size limits, passed to `barytex_texture::load_from_memory`.
    pub image: barytex_texture::Limits,
    /// Most triangles over all decoded primitives.
    pub max_triangles: u64,
    /// Most elements in one accessor.
    pub max_accessor_elements: u64,
    /// Most elements in an accessor without a bufferView (all zeros, or zeros under sparse
    /// values): its memory is not paid for by bytes in the file, so a tiny file could otherwise
    /// ask for gigabytes.
    pub max_unbacked_accessor_elements: u64,
    /// Deepest node hierarchy (a root node has depth 1).
    pub max_node_depth: usize,
    /// Most nodes in the document.
    pub max_nodes: usize,
    /// Most mesh instances (node–mesh pairs) in the flattened scene.
    pub max_instances: usize,
}

impl Default for SceneLimits {
    /// Generous for real assets (a 2 GiB GLB, 50 M triangles), small enough that a forged file
    /// cannot exhaust a workstation.
    fn default() -> Self {
        Self {
            max_file_bytes: 2 << 30,
            max_buffer_bytes: 2 << 30,
            max_total_buffer_bytes: 4 << 30,
            max_image_file_bytes: 512 << 20,
            image: barytex_texture::Limits::default(),
            max_triangles: 50_000_000,
            max_accessor_elements: 100_000_000,
            max_unbacked_accessor_elements: 1 << 20,
            max_node_depth: 64,
            max_nodes: 1_000_000,
            max_instances: 1_000_000,
        }
    }
}
