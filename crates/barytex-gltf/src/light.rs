//! `KHR_lights_punctual` lights: directional, point and spot, placed by their node (a light
//! shines down its node's local −Z).

use glam::{Mat4, Vec3};

use crate::SceneError;
use crate::json::Obj;

/// The kind of a punctual light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// Parallel rays along the light's direction.
    Directional,
    /// Light from a point, in all directions.
    Point,
    /// A cone around the light's direction; full intensity inside `inner_cone_angle`, falling
    /// to zero at `outer_cone_angle` (radians from the axis).
    Spot {
        /// Angle where the falloff begins.
        inner_cone_angle: f32,
        /// Angle where the light ends.
        outer_cone_angle: f32,
    },
}

/// A light definition from the document's `KHR_lights_punctual.lights`.
#[derive(Clone, Debug, PartialEq)]
pub struct PunctualLight {
    /// The light's name, if any.
    pub name: Option<String>,
    /// Kind and cone.
    pub kind: LightKind,
    /// Linear RGB colour (default white).
    pub color: Vec3,
    /// Candela (point, spot) or lux (directional); default 1.
    pub intensity: f32,
    /// Distance where the light's influence ends; `None` is infinite.
    pub range: Option<f32>,
}

impl PunctualLight {
    /// Reads `/extensions/KHR_lights_punctual/lights/i`. Returns `None` (with a warning) for an
    /// unknown light type, which the extension allows future versions to add.
    pub(crate) fn parse(
        obj: Obj<'_>,
        warnings: &mut Vec<String>,
    ) -> Result<Option<Self>, SceneError> {
        let ty = obj.req_str("type")?;
        let color = obj.opt_f32s::<3>("color")?.map_or(Vec3::ONE, Vec3::from);
        if color.min_element() < 0.0 {
            return Err(obj.error("color", "colour components must be ≥ 0"));
        }
        let intensity = obj.opt_f32("intensity")?.unwrap_or(1.0);
        if intensity < 0.0 {
            return Err(obj.error("intensity", "intensity must be ≥ 0"));
        }
        let range = obj.opt_f32("range")?;
        if range.is_some_and(|r| r <= 0.0) {
            return Err(obj.error("range", "range must be > 0"));
        }
        let kind = match ty {
            "directional" => LightKind::Directional,
            "point" => LightKind::Point,
            "spot" => {
                let ptr = obj.at("spot");
                let spot = obj.opt_obj("spot")?.ok_or_else(|| {
                    SceneError::invalid(obj.ptr, "a spot light without a 'spot' object")
                })?;
                let spot = crate::json::as_obj(spot, &ptr)?;
                let inner = spot.opt_f32("innerConeAngle")?.unwrap_or(0.0);
                let outer = spot
                    .opt_f32("outerConeAngle")?
                    .unwrap_or(std::f32::consts::FRAC_PI_4);
                if !(0.0..outer).contains(&inner) || outer > std::f32::consts::FRAC_PI_2 {
                    return Err(SceneError::invalid(
                        ptr,
                        format!(
                            "cone angles must satisfy 0 ≤ inner < outer ≤ π/2, got {inner}, {outer}"
                        ),
                    ));
                }
                LightKind::Spot {
                    inner_cone_angle: inner,
                    outer_cone_angle: outer,
                }
            }
            other => {
                warnings.push(format!(
                    "{}: unknown light type {other:?}, ignored",
                    obj.ptr
                ));
                return Ok(None);
            }
        };
        Ok(Some(Self {
            name: obj.opt_str("name")?.map(str::to_owned),
            kind,
            color,
            intensity,
            range,
        }))
    }
}

/// A light placed in the flattened scene.
///
/// ```
/// use barytex_gltf::{LightKind, LoadOptions, load_slice};
/// use glam::Vec3;
///
/// // A spot light on a node turned a quarter turn about +X: it shines down −Y instead of −Z.
/// let gltf = br#"{"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
///   "extensions": {"KHR_lights_punctual": {"lights": [
///     {"type": "spot", "intensity": 20, "spot": {"outerConeAngle": 0.5}}]}},
///   "nodes": [{"translation": [0, 3, 0], "rotation": [-0.70710677, 0, 0, 0.70710677],
///              "extensions": {"KHR_lights_punctual": {"light": 0}}}],
///   "scenes": [{"nodes": [0]}]}"#;
/// let scene = load_slice(gltf, &LoadOptions::default())?;
/// let light = &scene.lights[0];
/// assert!(matches!(light.light.kind, LightKind::Spot { inner_cone_angle: 0.0, outer_cone_angle: 0.5 }));
/// assert_eq!((light.light.intensity, light.light.color, light.light.range), (20.0, Vec3::ONE, None));
/// assert_eq!(light.position, Vec3::new(0.0, 3.0, 0.0));
/// assert!((light.direction - Vec3::NEG_Y).length() < 1e-6);
/// # Ok::<(), barytex_gltf::SceneError>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SceneLight {
    /// Index of the node carrying it.
    pub node: usize,
    /// Index into the document's lights.
    pub light_index: usize,
    /// The light.
    pub light: PunctualLight,
    /// Light-to-world matrix.
    pub world: Mat4,
    /// World-space position (irrelevant for directional lights).
    pub position: Vec3,
    /// World-space unit direction the light shines along (the node's −Z).
    pub direction: Vec3,
}
