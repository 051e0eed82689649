//! Reading a node's `extras.barytex_portal` (the convention documented on
//! [`Portal`](crate::Portal)): counts bounded before anything is copied, every number checked,
//! errors by JSON pointer without the values read.

use glam::{Mat4, Vec3, Vec4};
use serde_json::Value;

use crate::SceneError;
use crate::json::{Obj, as_obj, child};
use crate::portal::{MAX_PORTAL_VERTICES, Portal, reflection};

/// What the portal sees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum PortalKind {
    /// The scene reflected about the polygon's plane.
    Mirror,
    /// The surroundings of this node.
    Target(usize),
}

/// A portal as declared: the polygon in the node's local space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PortalDef {
    pub(crate) polygon: Vec<Vec3>,
    pub(crate) kind: PortalKind,
    pub(crate) tint: Vec4,
    /// JSON pointer of the `barytex_portal` object, for errors found when it is placed.
    pub(crate) ptr: String,
}

/// A finite single-precision number (the value is never echoed: files are untrusted).
fn finite(value: &Value, ptr: &str) -> Result<f32, SceneError> {
    #[allow(clippy::cast_possible_truncation)]
    let f = value.as_f64().map(|f| f as f32);
    match f {
        Some(f) if f.is_finite() => Ok(f),
        Some(_) => Err(SceneError::invalid(
            ptr,
            "not a finite single-precision number",
        )),
        None => Err(SceneError::invalid(ptr, "expected a number")),
    }
}

impl PortalDef {
    /// The node's portal, if its `extras` (any JSON value, per glTF 2.0 §3.12) is an object
    /// with a `barytex_portal` member; that member must then follow the convention.
    pub(crate) fn parse(node: &Obj<'_>, nodes: usize) -> Result<Option<Self>, SceneError> {
        let Some(Value::Object(extras)) = node.get("extras") else {
            return Ok(None);
        };
        let Some(value) = extras.get("barytex_portal") else {
            return Ok(None);
        };
        let ptr = child(&node.at("extras"), "barytex_portal");
        let obj = as_obj(value, &ptr)?;
        let Some(points) = obj.opt_array("polygon")? else {
            return Err(obj.error("polygon", "required property 'polygon' is missing"));
        };
        if !(3..=MAX_PORTAL_VERTICES).contains(&points.len()) {
            return Err(obj.error(
                "polygon",
                format!("a portal polygon has 3 to {MAX_PORTAL_VERTICES} points"),
            ));
        }
        let polygon_ptr = obj.at("polygon");
        let mut polygon = Vec::with_capacity(points.len());
        for (i, point) in points.iter().enumerate() {
            let p = child(&polygon_ptr, &i.to_string());
            match point.as_array() {
                Some(xyz) if xyz.len() == 3 => {
                    let c = |k: usize| finite(&xyz[k], &child(&p, &k.to_string()));
                    polygon.push(Vec3::new(c(0)?, c(1)?, c(2)?));
                }
                _ => return Err(SceneError::invalid(p, "expected an array of 3 numbers")),
            }
        }
        let mirror = obj.opt_bool("mirror")?.unwrap_or(false);
        let target = obj.opt_index("target", nodes, "node")?;
        let kind = match (mirror, target) {
            (true, None) => PortalKind::Mirror,
            (false, Some(t)) => PortalKind::Target(t),
            (true, Some(_)) => {
                return Err(obj.error("target", "a portal is a mirror or has a target, not both"));
            }
            (false, None) => {
                return Err(SceneError::invalid(
                    ptr,
                    "a portal needs \"mirror\": true or a \"target\" node",
                ));
            }
        };
        let tint = match obj.get("tint") {
            None => Vec4::ZERO,
            Some(v) => {
                let tint_ptr = obj.at("tint");
                let Some(rgba) = v.as_array().filter(|a| a.len() == 4) else {
                    return Err(SceneError::invalid(tint_ptr, "expected 4 numbers"));
                };
                let mut out = [0.0; 4];
                for (k, (slot, c)) in out.iter_mut().zip(rgba).enumerate() {
                    let p = child(&tint_ptr, &k.to_string());
                    *slot = finite(c, &p)?;
                    if !(0.0..=1.0).contains(slot) {
                        return Err(SceneError::invalid(p, "tint channels are in [0, 1]"));
                    }
                }
                Vec4::from_array(out)
            }
        };
        Ok(Some(Self {
            polygon,
            kind,
            tint,
            ptr,
        }))
    }

    /// The world-space portal of the node `node` (world matrix `world`), whose target node (if
    /// any) has world matrix `target_world`.
    pub(crate) fn place(
        &self,
        node: usize,
        name: Option<String>,
        world: Mat4,
        target_world: Option<Mat4>,
    ) -> Result<Portal, SceneError> {
        let mut polygon: Vec<Vec3> = self
            .polygon
            .iter()
            .map(|&p| world.transform_point3(p))
            .collect();
        // A mirroring world matrix turns the order: keep the front the side the file names.
        if world.determinant() < 0.0 {
            polygon.reverse();
        }
        let mut portal = Portal {
            node: Some(node),
            name,
            polygon,
            transform: Mat4::IDENTITY,
            tint: self.tint,
        };
        let invalid = |e: crate::portal::PortalError| SceneError::invalid(&self.ptr, e.to_string());
        let plane = portal.check().map_err(invalid)?;
        portal.transform = match (self.kind, target_world) {
            (PortalKind::Target(_), Some(target))
                if target.determinant() != 0.0 && target.inverse().is_finite() =>
            {
                world * target.inverse()
            }
            (PortalKind::Target(_), _) => {
                return Err(invalid(crate::portal::PortalError::SingularTransform));
            }
            (PortalKind::Mirror, _) => reflection(plane),
        };
        portal.check().map_err(invalid)?;
        Ok(portal)
    }
}
