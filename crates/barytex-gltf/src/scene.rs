//! The flattened scene a renderer consumes: mesh instances with world matrices, cameras, lights,
//! materials, textures and the decoded images, plus statistics on what was loaded and skipped.

use std::sync::Arc;

use barytex_texture::load::AnyTexture2d;
use glam::Mat4;

use crate::camera::{DocumentCamera, SceneCamera};
use crate::light::SceneLight;
use crate::material::Material;
use crate::mesh::Mesh;
use crate::portal::Portal;
use crate::sampler::SamplerParams;

/// One placement of a mesh in the world. Instances of the same mesh share its decoded data.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshInstance {
    /// Index of the node carrying the mesh.
    pub node: usize,
    /// The node's name, if any.
    pub node_name: Option<String>,
    /// Object-to-world matrix (parent · child, composed from the scene root).
    pub world: Mat4,
    /// The world matrix mirrors (determinant < 0): front faces turn clockwise, so a renderer must
    /// swap its winding test for this instance (glTF 2.0 §3.7.4).
    pub flips_winding: bool,
    /// The mesh (shared between instances).
    pub mesh: Arc<Mesh>,
}

impl MeshInstance {
    /// Triangles in this instance.
    ///
    /// ```
    /// use barytex_gltf::{LoadOptions, load_slice};
    ///
    /// // One triangle mesh placed by two nodes.
    /// let gltf = r#"{"asset": {"version": "2.0"},
    ///   "buffers": [{"byteLength": 36, "uri":
    ///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    ///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
    ///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
    ///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
    ///   "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 0.25}}],
    ///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    ///   "nodes": [{"mesh": 0}, {"mesh": 0, "scale": [-1, 1, 1]}], "scenes": [{"nodes": [0, 1]}]}"#;
    /// let scene = load_slice(gltf.as_bytes(), &LoadOptions::default())?;
    /// let counts: Vec<_> = scene.instances.iter().map(|i| i.triangle_count()).collect();
    /// assert_eq!(counts, [1, 1]);
    /// // The mirrored instance must swap its winding test.
    /// assert_eq!(scene.instances.iter().map(|i| i.flips_winding).collect::<Vec<_>>(), [false, true]);
    /// # Ok::<(), barytex_gltf::SceneError>(())
    /// ```
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.mesh.primitives.iter().map(|p| p.triangles.len()).sum()
    }
}

/// A texture: an image and how to sample it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Texture {
    /// Index into [`Scene::images`]; `None` when the texture has no core source (e.g. only an
    /// unsupported extension's).
    pub image: Option<usize>,
    /// The sampler (defaults when the texture has none).
    pub sampler: SamplerParams,
}

/// An image slot: decoded in the colour spaces the scene's materials need, or not at all.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneImage {
    /// The image's name, if any.
    pub name: Option<String>,
    /// Decoded as sRGB (used as a base colour or emissive texture).
    pub srgb: Option<Arc<AnyTexture2d>>,
    /// Decoded as linear data (normal, occlusion, metallic-roughness).
    pub linear: Option<Arc<AnyTexture2d>>,
}

/// What the loader did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SceneStats {
    /// Nodes visited in the chosen scene.
    pub nodes_visited: usize,
    /// Meshes decoded (used by the chosen scene).
    pub meshes_loaded: usize,
    /// Meshes in the document that the chosen scene does not use (validated, not decoded).
    pub meshes_unused: usize,
    /// Primitives decoded (triangles, points and lines).
    pub primitives_loaded: usize,
    /// Of those, point and line primitives (glTF modes 0–3).
    pub primitives_points_lines: usize,
    /// Primitives skipped for lacking `POSITION` or having an unknown mode.
    pub primitives_skipped_other: usize,
    /// Triangles over the decoded meshes (each mesh once).
    pub triangles: usize,
    /// Triangles over all instances.
    pub instanced_triangles: usize,
    /// Image decodes performed (an image used as colour and as data counts twice; image entries
    /// sharing a source share one decode).
    pub images_decoded: usize,
    /// Images no material of the chosen scene samples (checked, not decoded).
    pub images_skipped: usize,
}

/// A loaded, flattened glTF scene.
#[derive(Clone, Debug, Default)]
pub struct Scene {
    /// Which of the document's scenes this is (`None` when the document has no `scenes` and the
    /// loader used every root node).
    pub scene_index: Option<usize>,
    /// The scene's name, if any.
    pub name: Option<String>,
    /// How many scenes the document defines.
    pub scene_count: usize,
    /// Every mesh placement, in depth-first node order.
    pub instances: Vec<MeshInstance>,
    /// Cameras placed by the scene's nodes, in depth-first node order (a camera placed by two
    /// nodes appears twice; one placed by none is absent).
    pub cameras: Vec<SceneCamera>,
    /// The document's cameras, by index, whether the scene places them or not.
    pub document_cameras: Vec<DocumentCamera>,
    /// Lights placed by the scene's nodes.
    pub lights: Vec<SceneLight>,
    /// The document's materials, by index.
    pub materials: Vec<Material>,
    /// The document's textures, by index.
    pub textures: Vec<Texture>,
    /// The document's images, by index (decoded only where the scene uses them).
    pub images: Vec<SceneImage>,
    /// Non-fatal findings (skipped primitives, unknown enum values, extra bytes, …).
    pub warnings: Vec<String>,
    /// What was loaded and skipped.
    pub stats: SceneStats,
    /// Seconds the load spent decoding images (PNG/JPEG to texels). Kept out of
    /// [`SceneStats`], whose counts are the same on every run.
    pub decode_seconds: f64,
    /// An equirectangular environment panorama (linear light; `barytex_uv`'s equirect
    /// convention, −Z at the centre, +Y at the top) that lit materials reflect in proportion to
    /// their smoothness: environment mapping (J. F. Blinn, M. E. Newell, "Texture and reflection
    /// in computer generated images", *Communications of the ACM* 19(10), 1976). glTF has no such
    /// slot: files load with `None`; code (the demo) sets it.
    pub environment: Option<Arc<AnyTexture2d>>,
    /// Portals and mirrors placed by the scene's nodes (`extras.barytex_portal`, see
    /// [`Portal`]), in depth-first node order; code may add its own.
    pub portals: Vec<Portal>,
}

impl Scene {
    /// Triangles over all instances.
    ///
    /// ```
    /// use barytex_gltf::{LoadOptions, load_slice};
    ///
    /// // One triangle mesh placed by two nodes.
    /// let gltf = r#"{"asset": {"version": "2.0"},
    ///   "buffers": [{"byteLength": 36, "uri":
    ///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    ///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
    ///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
    ///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
    ///   "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 0.25}}],
    ///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    ///   "nodes": [{"mesh": 0}, {"mesh": 0, "scale": [-1, 1, 1]}], "scenes": [{"nodes": [0, 1]}]}"#;
    /// let scene = load_slice(gltf.as_bytes(), &LoadOptions::default())?;
    /// assert_eq!(scene.triangle_count(), 2);
    /// // The mesh itself is decoded once.
    /// assert_eq!((scene.stats.triangles, scene.stats.instanced_triangles), (1, 2));
    /// # Ok::<(), barytex_gltf::SceneError>(())
    /// ```
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.instances
            .iter()
            .map(MeshInstance::triangle_count)
            .sum()
    }

    /// The material a primitive uses (the glTF default material for `None`).
    ///
    /// ```
    /// use barytex_gltf::{LoadOptions, load_slice};
    ///
    /// // One triangle mesh placed by two nodes.
    /// let gltf = r#"{"asset": {"version": "2.0"},
    ///   "buffers": [{"byteLength": 36, "uri":
    ///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    ///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
    ///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
    ///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
    ///   "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 0.25}}],
    ///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    ///   "nodes": [{"mesh": 0}, {"mesh": 0, "scale": [-1, 1, 1]}], "scenes": [{"nodes": [0, 1]}]}"#;
    /// let scene = load_slice(gltf.as_bytes(), &LoadOptions::default())?;
    /// let primitive = &scene.instances[0].mesh.primitives[0];
    /// assert_eq!(scene.material(primitive.material).roughness_factor, 0.25);
    /// // No material (or a missing one): glTF's default material.
    /// assert_eq!(scene.material(None), barytex_gltf::Material::default());
    /// assert_eq!(scene.material(Some(9)).roughness_factor, 1.0);
    /// # Ok::<(), barytex_gltf::SceneError>(())
    /// ```
    #[must_use]
    pub fn material(&self, index: Option<usize>) -> Material {
        index
            .and_then(|i| self.materials.get(i))
            .cloned()
            .unwrap_or_default()
    }
}
