//! The camera a render looks through: a scene camera, or the automatic camera, which is fully
//! specified so that another renderer can reproduce it.

use glam::{Mat4, Vec3, Vec4};

use barytex_gltf::camera::Projection;
use barytex_gltf::scene::Scene;

/// View and projection of a render.
///
/// ```
/// use barytex_render::{CameraSource, scene_camera};
/// use glam::{Vec3, Vec4};
///
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, -2]}, {"camera": 0, "translation": [0, 1, 5]}],
///   "scenes": [{"nodes": [0, 1, 2]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// let camera = scene_camera(&scene, 0, 1.0).unwrap();
/// // A point straight ahead at the near plane lands at the centre, rasterizer depth 0.
/// let clip = camera.projection * camera.view * Vec4::new(0.0, 1.0, 4.9, 1.0);
/// assert!((clip / clip.w - Vec4::new(0.0, 0.0, 0.0, 1.0)).abs().max_element() < 1e-5);
/// assert_eq!(camera.source, CameraSource::Scene(0));
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderCamera {
    /// World → view (the camera looks down its −Z, y up).
    pub view: Mat4,
    /// View → clip as glTF writes it (OpenGL: z in [−w, w]).
    pub projection_gl: Mat4,
    /// View → clip as the rasterizer takes it (z in [0, w]): `projection_gl` followed by
    /// z′ = (z + w)/2.
    pub projection: Mat4,
    /// The eye in world space.
    pub eye: Vec3,
    /// Where the camera came from, for messages.
    pub source: CameraSource,
}

/// Where a render's camera came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraSource {
    /// The document's camera with this index (glTF `cameras[i]`), where the first node of the
    /// scene that instantiates it places it.
    Scene(usize),
    /// The automatic camera.
    Auto,
}

/// OpenGL clip z ∈ [−w, w] → Vulkan clip z ∈ [0, w].
fn gl_to_vulkan() -> Mat4 {
    Mat4::from_cols(
        Vec4::X,
        Vec4::Y,
        Vec4::new(0.0, 0.0, 0.5, 0.0),
        Vec4::new(0.0, 0.0, 0.5, 1.0),
    )
}

/// The world-space bounding box of every instance's vertices; `None` for a scene without
/// finite vertices.
///
/// ```
/// use barytex_render::scene_bounds;
/// use glam::Vec3;
///
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, -2]}, {"camera": 0, "translation": [0, 1, 5]}],
///   "scenes": [{"nodes": [0, 1, 2]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// // The triangle at z = 0 and its copy at z = −2; the camera is not geometry.
/// assert_eq!(scene_bounds(&scene), Some((Vec3::new(0.0, 0.0, -2.0), Vec3::new(1.0, 1.0, 0.0))));
/// assert_eq!(scene_bounds(&barytex_gltf::Scene::default()), None);
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[must_use]
pub fn scene_bounds(scene: &Scene) -> Option<(Vec3, Vec3)> {
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for instance in &scene.instances {
        for primitive in &instance.mesh.primitives {
            for &p in &primitive.positions {
                let w = instance.world.transform_point3(p);
                if w.is_finite() {
                    lo = lo.min(w);
                    hi = hi.max(w);
                }
            }
        }
    }
    (lo.cmple(hi).all()).then_some((lo, hi))
}

/// The automatic camera for an image of aspect `aspect` (width / height):
///
/// - perspective, vertical field of view 45°, the image's aspect;
/// - the bounding box of the scene's vertices (world space) has centre `c` and bounding sphere
///   radius `r` = half its diagonal (1 when that is 0);
/// - the eye is at `c + (0, 0, d)` looking toward −Z (y up), where `d = r / sin(θ)` and `θ` is
///   the smaller of the half vertical and half horizontal field of view — the distance at which
///   the sphere just fits;
/// - near = d/100, far = d·100.
///
/// `None` when the scene has no finite vertex.
///
/// ```
/// use barytex_render::{CameraSource, auto_camera, scene_bounds};
/// use glam::Vec3;
///
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, -2]}, {"camera": 0, "translation": [0, 1, 5]}],
///   "scenes": [{"nodes": [0, 1, 2]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// let camera = auto_camera(&scene, 2.0).unwrap();
/// assert_eq!(camera.source, CameraSource::Auto);
/// // On the +Z side of the bounds' centre, looking down −Z …
/// let (lo, hi) = scene_bounds(&scene).unwrap();
/// let centre = (lo + hi) / 2.0;
/// assert_eq!((camera.eye.x, camera.eye.y), (centre.x, centre.y));
/// assert!(camera.eye.z > hi.z && camera.forward() == Vec3::NEG_Z);
/// // … far enough that every corner of the bounds is in view.
/// for corner in 0..8 {
///     let p = Vec3::select(glam::BVec3::new(corner & 1 != 0, corner & 2 != 0, corner & 4 != 0), hi, lo);
///     let ndc = camera.projection.project_point3(camera.view.transform_point3(p));
///     assert!(ndc.x.abs() <= 1.0 && ndc.y.abs() <= 1.0 && (0.0..=1.0).contains(&ndc.z));
/// }
/// assert!(auto_camera(&barytex_gltf::Scene::default(), 1.0).is_none());
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[must_use]
pub fn auto_camera(scene: &Scene, aspect: f32) -> Option<RenderCamera> {
    let (lo, hi) = scene_bounds(scene)?;
    let centre = (lo + hi) * 0.5;
    let mut radius = (hi - lo).length() * 0.5;
    if radius <= 0.0 || !radius.is_finite() {
        radius = 1.0;
    }
    let yfov = 45_f32.to_radians();
    let half_y = yfov * 0.5;
    let half_x = (aspect * half_y.tan()).atan();
    let distance = radius / half_y.min(half_x).sin();
    let eye = centre + Vec3::new(0.0, 0.0, distance);
    let projection = Projection::Perspective {
        yfov,
        aspect_ratio: Some(aspect),
        znear: distance / 100.0,
        zfar: Some(distance * 100.0),
    };
    let projection_gl = projection.matrix(aspect);
    Some(RenderCamera {
        view: Mat4::from_translation(-eye),
        projection_gl,
        projection: gl_to_vulkan() * projection_gl,
        eye,
        source: CameraSource::Auto,
    })
}

/// The document's camera `index` (glTF `cameras[index]`, glTF 2.0 §3.10.2), placed by the first
/// node of the scene that instantiates it (depth-first, in the scene's node order, as
/// [`Scene::cameras`] lists the placements), for an image of aspect `aspect`; `None` when no
/// node of the scene places that camera or its placement is singular.
///
/// ```
/// use barytex_render::{CameraSource, scene_camera};
/// use glam::Vec3;
///
/// // Node 2 places camera 1 before node 3 places camera 0; node 4 places camera 0 again.
/// let gltf = r#"{"asset": {"version": "2.0"},
///   "buffers": [{"byteLength": 36, "uri":
///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
///               {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
///               {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
///   "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, -2]},
///             {"camera": 1, "translation": [0, 0, 9]}, {"camera": 0, "translation": [0, 1, 5]},
///             {"camera": 0, "translation": [7, 7, 7]}],
///   "scenes": [{"nodes": [0, 1, 2, 3, 4]}]}"#;
/// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
/// let camera = scene_camera(&scene, 0, 16.0 / 9.0).unwrap();
/// assert_eq!(camera.eye, Vec3::new(0.0, 1.0, 5.0));
/// assert_eq!(camera.source, CameraSource::Scene(0));
/// // The camera fixes no aspect ratio, so the image's is used: x is scaled by 9/16 of y.
/// assert!((camera.projection_gl.x_axis.x / camera.projection_gl.y_axis.y - 9.0 / 16.0).abs() < 1e-6);
/// assert_eq!(scene_camera(&scene, 1, 1.0).unwrap().eye, Vec3::new(0.0, 0.0, 9.0));
/// // Camera 2 is in the document but no node places it; there is no camera 3.
/// assert!(scene_camera(&scene, 2, 1.0).is_none() && scene_camera(&scene, 3, 1.0).is_none());
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[must_use]
pub fn scene_camera(scene: &Scene, index: usize, aspect: f32) -> Option<RenderCamera> {
    let camera = scene.cameras.iter().find(|c| c.camera == index)?;
    let view = camera.world.inverse();
    if !view.is_finite() {
        return None;
    }
    let projection_gl = camera.projection.matrix(aspect);
    Some(RenderCamera {
        view,
        projection_gl,
        projection: gl_to_vulkan() * projection_gl,
        eye: camera.world.transform_point3(Vec3::ZERO),
        source: CameraSource::Scene(index),
    })
}

impl RenderCamera {
    /// The unit direction the camera looks along (its −Z in world space).
    ///
    /// ```
    /// use barytex_render::scene_camera;
    /// use glam::Vec3;
    ///
    /// // A camera turned a quarter turn about +Y looks down −X.
    /// let gltf = br#"{"asset": {"version": "2.0"},
    ///   "cameras": [{"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 10}}],
    ///   "nodes": [{"camera": 0, "rotation": [0, 0.70710677, 0, 0.70710677]}], "scenes": [{"nodes": [0]}]}"#;
    /// let scene = barytex_gltf::load_slice(gltf, &barytex_gltf::LoadOptions::default())?;
    /// let forward = scene_camera(&scene, 0, 1.0).unwrap().forward();
    /// assert!((forward - Vec3::NEG_X).length() < 1e-6);
    /// # Ok::<(), barytex_gltf::SceneError>(())
    /// ```
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        self.view
            .inverse()
            .transform_vector3(Vec3::NEG_Z)
            .normalize_or_zero()
    }

    /// The matrices as text (column vectors written as rows of the printed matrix). Every number
    /// is written in the shortest form that reads back to the same `f32` (Rust's `Display`), so a
    /// printed camera can be rebuilt exactly; fixed decimals would round a near plane of 1e-4's
    /// projection terms to zero.
    ///
    /// ```
    /// use barytex_render::auto_camera;
    ///
    /// let gltf = r#"{"asset": {"version": "2.0"},
    ///   "buffers": [{"byteLength": 36, "uri":
    ///     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    ///   "bufferViews": [{"buffer": 0, "byteLength": 36}],
    ///   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
    ///                  "min": [0, 0, 0], "max": [1, 1, 0]}],
    ///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
    ///   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    ///   "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, -2]}, {"camera": 0, "translation": [0, 1, 5]}],
    ///   "scenes": [{"nodes": [0, 1, 2]}]}"#;
    /// let scene = barytex_gltf::load_slice(gltf.as_bytes(), &barytex_gltf::LoadOptions::default())?;
    /// let text = auto_camera(&scene, 1.0).unwrap().describe();
    /// assert!(text.starts_with("automatic camera, eye at (0.5, 0.5, "));
    /// assert_eq!(text.lines().count(), 1 + 3 * 5); // a heading, then three titled 4×4 matrices
    /// # Ok::<(), barytex_gltf::SceneError>(())
    /// ```
    #[must_use]
    pub fn describe(&self) -> String {
        let rows = |m: &Mat4| {
            let t = m.transpose();
            [t.x_axis, t.y_axis, t.z_axis, t.w_axis]
                .iter()
                .map(|r| format!("  [{:>14} {:>14} {:>14} {:>14}]", r.x, r.y, r.z, r.w))
                .collect::<Vec<_>>()
                .join("\n")
        };
        let source = match self.source {
            CameraSource::Scene(i) => format!("glTF camera {i}"),
            CameraSource::Auto => "automatic camera".to_owned(),
        };
        format!(
            "{source}, eye at ({}, {}, {})\nview (world → view):\n{}\nprojection \
             (glTF/OpenGL, z in [−w, w]):\n{}\nprojection used (z in [0, w]):\n{}",
            self.eye.x,
            self.eye.y,
            self.eye.z,
            rows(&self.view),
            rows(&self.projection_gl),
            rows(&self.projection)
        )
    }
}
