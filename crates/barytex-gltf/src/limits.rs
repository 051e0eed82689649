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
    /// Most decoded bytes of all images together, as stored (4 bytes a texel for 8-bit colour,
    /// 1 for an 8-bit greyscale data map, 8 for 16-bit, 16 for float images). Each distinct
    /// source (a file, a `bufferView`, a data URI) counts once per colour space it is decoded
    /// in, and image entries sharing a source share its texture. Checked from each image's
    /// header before it is decoded.
    pub max_total_image_bytes: u64,
    /// Most triangles over all decoded primitives (each mesh counted once).
    pub max_triangles: u64,
    /// Most triangles over all mesh instances: a mesh counts once for every node placing it,
    /// since a renderer transforms and rasterizes every instance. Checked from the declared
    /// counts while the node hierarchy is walked, before any mesh is decoded.
    pub max_instanced_triangles: u64,
    /// Most vertices over all mesh instances (the `POSITION` count of every triangle primitive,
    /// once per node placing its mesh): a renderer copies every instance's vertices into world
    /// space. Checked with [`max_instanced_triangles`](Self::max_instanced_triangles).
    pub max_instanced_vertices: u64,
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
    /// Most lights (node–light pairs of `KHR_lights_punctual`) in the flattened scene: every
    /// light is evaluated at every shaded sample, so their number multiplies the render's
    /// cost. Refused, not culled: which lights matter depends on the view, which the loader
    /// does not know.
    pub max_lights: usize,
    /// Most portals and mirrors (nodes with `extras.barytex_portal`, see
    /// [`Portal`](crate::Portal)) in the flattened scene: a renderer may draw the whole scene
    /// again through each one it sees.
    pub max_portals: usize,
}

impl Default for SceneLimits {
    /// Generous for real assets (a 2 GiB GLB, 50 M triangles, 2 GiB of decoded images, 1024
    /// lights, 64 portals), small enough that a forged file cannot exhaust a workstation. Instanced
    /// vertices are three per instanced triangle, so a non-indexed scene at the triangle limit
    /// fits; the vertex limit bites on meshes with many more vertices than triangles.
    fn default() -> Self {
        Self {
            max_file_bytes: 2 << 30,
            max_buffer_bytes: 2 << 30,
            max_total_buffer_bytes: 4 << 30,
            max_image_file_bytes: 512 << 20,
            image: barytex_texture::Limits::default(),
            max_total_image_bytes: 2 << 30,
            max_triangles: 50_000_000,
            max_instanced_triangles: 50_000_000,
            max_instanced_vertices: 150_000_000,
            max_accessor_elements: 100_000_000,
            max_unbacked_accessor_elements: 1 << 20,
            max_node_depth: 64,
            max_nodes: 1_000_000,
            max_instances: 1_000_000,
            max_lights: 1024,
            max_portals: 64,
        }
    }
}
