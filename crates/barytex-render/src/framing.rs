//! The camera a render looks through: a scene camera, or the automatic camera, which is fully
//! specified so that another renderer can reproduce it.

use glam::{Mat4, Vec3, Vec4};

use barytex_gltf::camera::Projection;
use barytex_gltf::scene::Scene;

/// View and projection of a render.
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
    /// The scene's camera with this index.
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

/// The scene's camera `index` for an image of aspect `aspect`; `None` when there is no such
/// camera or its placement is singular.
#[must_use]
pub fn scene_camera(scene: &Scene, index: usize, aspect: f32) -> Option<RenderCamera> {
    let camera = scene.cameras.get(index)?;
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
    #[must_use]
    pub fn forward(&self) -> Vec3 {
        self.view
            .inverse()
            .transform_vector3(Vec3::NEG_Z)
            .normalize_or_zero()
    }

    /// The matrices as text (column vectors written as rows of the printed matrix).
    #[must_use]
    pub fn describe(&self) -> String {
        let rows = |m: &Mat4| {
            let t = m.transpose();
            [t.x_axis, t.y_axis, t.z_axis, t.w_axis]
                .iter()
                .map(|r| {
                    format!(
                        "  [{:>12.6} {:>12.6} {:>12.6} {:>12.6}]",
                        r.x, r.y, r.z, r.w
                    )
                })
                .collect::<Vec<_>>()
                .join("\n")
        };
        let source = match self.source {
            CameraSource::Scene(i) => format!("scene camera {i}"),
            CameraSource::Auto => "automatic camera".to_owned(),
        };
        format!(
            "{source}, eye at ({:.6}, {:.6}, {:.6})\nview (world → view):\n{}\nprojection \
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
