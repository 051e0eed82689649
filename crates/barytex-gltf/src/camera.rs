//! Cameras (glTF 2.0 §3.10): the projection as the file gives it, placed by its node.

use glam::{Mat4, Vec4};

use crate::SceneError;
use crate::json::Obj;

/// A camera's projection, with the parameters glTF stores (not a matrix: the aspect ratio and
/// the infinite far plane are decisions for the renderer).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// Perspective projection.
    Perspective {
        /// Vertical field of view in radians.
        yfov: f32,
        /// Width / height; `None` means "use the viewport's".
        aspect_ratio: Option<f32>,
        /// Near plane distance (> 0).
        znear: f32,
        /// Far plane distance; `None` is an infinite far plane.
        zfar: Option<f32>,
    },
    /// Orthographic projection.
    Orthographic {
        /// Half the width of the view volume.
        xmag: f32,
        /// Half the height of the view volume.
        ymag: f32,
        /// Near plane distance (≥ 0).
        znear: f32,
        /// Far plane distance (> `znear`).
        zfar: f32,
    },
}

impl Projection {
    /// The projection matrix exactly as the glTF specification's appendix writes it (OpenGL clip
    /// space, z in [−1, 1]); `viewport_aspect` is used when the camera does not fix its own.
    ///
    /// ```
    /// use barytex_gltf::Projection;
    /// use glam::Vec4;
    ///
    /// // An infinite perspective: the near plane maps to NDC z = −1, the viewport sets the aspect.
    /// let p = Projection::Perspective { yfov: 1.0, aspect_ratio: None, znear: 0.5, zfar: None };
    /// let m = p.matrix(2.0);
    /// let clip = m * Vec4::new(0.0, 0.0, -0.5, 1.0);
    /// assert_eq!(clip.z / clip.w, -1.0);
    /// assert_eq!(m.x_axis.x * 2.0, m.y_axis.y);
    /// // Orthographic: the corner (xmag, ymag) at the far plane maps to (1, 1, 1).
    /// let o = Projection::Orthographic { xmag: 2.0, ymag: 1.0, znear: 0.0, zfar: 10.0 };
    /// assert_eq!(o.matrix(1.0) * Vec4::new(2.0, 1.0, -10.0, 1.0), Vec4::ONE);
    /// ```
    #[must_use]
    pub fn matrix(&self, viewport_aspect: f32) -> Mat4 {
        match *self {
            Self::Perspective {
                yfov,
                aspect_ratio,
                znear,
                zfar,
            } => {
                let aspect = aspect_ratio.unwrap_or(viewport_aspect);
                let t = (0.5 * yfov).tan();
                let (z2, z3) = match zfar {
                    Some(f) => ((f + znear) / (znear - f), 2.0 * f * znear / (znear - f)),
                    None => (-1.0, -2.0 * znear),
                };
                Mat4::from_cols(
                    Vec4::new(1.0 / (aspect * t), 0.0, 0.0, 0.0),
                    Vec4::new(0.0, 1.0 / t, 0.0, 0.0),
                    Vec4::new(0.0, 0.0, z2, -1.0),
                    Vec4::new(0.0, 0.0, z3, 0.0),
                )
            }
            Self::Orthographic {
                xmag,
                ymag,
                znear,
                zfar,
            } => Mat4::from_cols(
                Vec4::new(1.0 / xmag, 0.0, 0.0, 0.0),
                Vec4::new(0.0, 1.0 / ymag, 0.0, 0.0),
                Vec4::new(0.0, 0.0, 2.0 / (znear - zfar), 0.0),
                Vec4::new(0.0, 0.0, (zfar + znear) / (znear - zfar), 1.0),
            ),
        }
    }

    /// Reads `/cameras/i`, refusing degenerate projections (glTF 2.0 §5.12–5.14).
    pub(crate) fn parse(obj: Obj<'_>, warnings: &mut Vec<String>) -> Result<Self, SceneError> {
        let ty = obj.req_str("type")?;
        let persp = obj.opt_obj("perspective")?;
        let ortho = obj.opt_obj("orthographic")?;
        if persp.is_some() && ortho.is_some() {
            return Err(SceneError::invalid(
                obj.ptr,
                "both 'perspective' and 'orthographic' are defined",
            ));
        }
        match ty {
            "perspective" => {
                let ptr = obj.at("perspective");
                let p = persp.ok_or_else(|| {
                    SceneError::invalid(obj.ptr, "type is perspective but 'perspective' is missing")
                })?;
                let p = crate::json::as_obj(p, &ptr)?;
                let yfov = p.req_f32("yfov")?;
                let znear = p.req_f32("znear")?;
                let zfar = p.opt_f32("zfar")?;
                let aspect_ratio = p.opt_f32("aspectRatio")?;
                if yfov <= 0.0 {
                    return Err(p.error("yfov", format!("yfov {yfov} must be > 0")));
                }
                if yfov >= std::f32::consts::PI {
                    // Allowed by the schema (the validator does not object); useless to render.
                    warnings.push(format!("{}: yfov {yfov} is not below π", p.at("yfov")));
                }
                if znear <= 0.0 {
                    return Err(p.error("znear", format!("znear {znear} must be > 0")));
                }
                if let Some(a) = aspect_ratio
                    && a <= 0.0
                {
                    return Err(p.error("aspectRatio", format!("aspectRatio {a} must be > 0")));
                }
                if let Some(f) = zfar
                    && f <= znear
                {
                    return Err(p.error("zfar", format!("zfar {f} ≤ znear {znear}")));
                }
                Ok(Self::Perspective {
                    yfov,
                    aspect_ratio,
                    znear,
                    zfar,
                })
            }
            "orthographic" => {
                let ptr = obj.at("orthographic");
                let o = ortho.ok_or_else(|| {
                    SceneError::invalid(
                        obj.ptr,
                        "type is orthographic but 'orthographic' is missing",
                    )
                })?;
                let o = crate::json::as_obj(o, &ptr)?;
                let xmag = o.req_f32("xmag")?;
                let ymag = o.req_f32("ymag")?;
                let znear = o.req_f32("znear")?;
                let zfar = o.req_f32("zfar")?;
                if xmag == 0.0 || ymag == 0.0 {
                    return Err(SceneError::invalid(ptr, "xmag and ymag must not be zero"));
                }
                if znear < 0.0 {
                    return Err(o.error("znear", format!("znear {znear} must be ≥ 0")));
                }
                if zfar <= znear {
                    return Err(o.error("zfar", format!("zfar {zfar} ≤ znear {znear}")));
                }
                Ok(Self::Orthographic {
                    xmag,
                    ymag,
                    znear,
                    zfar,
                })
            }
            other => Err(obj.error("type", format!("unknown camera type {other:?}"))),
        }
    }
}

/// One of the document's `cameras` (glTF 2.0 §5.12), placed by any node or none.
///
/// [`Scene::document_cameras`](crate::Scene::document_cameras) keeps every one, by its index in
/// the document; [`Scene::cameras`](crate::Scene::cameras) keeps the placements.
///
/// ```
/// use barytex_gltf::{LoadOptions, Projection, load_slice};
///
/// // Two cameras; the scene places only the second, twice.
/// let gltf = br#"{"asset": {"version": "2.0"},
///   "cameras": [{"name": "spare", "type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}},
///               {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0, "zfar": 9}}],
///   "nodes": [{"camera": 1}, {"camera": 1, "translation": [0, 0, 5]}], "scenes": [{"nodes": [0, 1]}]}"#;
/// let scene = load_slice(gltf, &LoadOptions::default())?;
/// assert_eq!(scene.document_cameras.len(), 2);
/// assert_eq!(scene.document_cameras[0].name.as_deref(), Some("spare"));
/// assert!(matches!(scene.document_cameras[1].projection, Projection::Orthographic { .. }));
/// // The placements, in scene order, name the document index.
/// assert_eq!(scene.cameras.iter().map(|c| (c.node, c.camera)).collect::<Vec<_>>(), [(0, 1), (1, 1)]);
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct DocumentCamera {
    /// The camera's name, if any.
    pub name: Option<String>,
    /// The projection.
    pub projection: Projection,
}

/// A camera placed in the flattened scene.
///
/// ```
/// use barytex_gltf::{LoadOptions, Projection, load_slice};
/// use glam::Vec3;
///
/// let gltf = br#"{"asset": {"version": "2.0"},
///   "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
///   "nodes": [{"camera": 0, "translation": [0, 1, 5]}], "scenes": [{"nodes": [0]}]}"#;
/// let scene = load_slice(gltf, &LoadOptions::default())?;
/// let camera = &scene.cameras[0];
/// assert!(matches!(camera.projection, Projection::Perspective { zfar: None, .. }));
/// assert_eq!(camera.world.transform_point3(Vec3::ZERO), Vec3::new(0.0, 1.0, 5.0));
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SceneCamera {
    /// Index of the node carrying it.
    pub node: usize,
    /// Index into the document's `cameras` (and
    /// [`Scene::document_cameras`](crate::Scene::document_cameras)).
    pub camera: usize,
    /// The camera's name, if any.
    pub name: Option<String>,
    /// The projection.
    pub projection: Projection,
    /// Camera-to-world matrix (the camera looks down its local −Z, +Y up).
    pub world: Mat4,
}
