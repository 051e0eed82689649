//! Nodes and their hierarchy: local transforms (a matrix, or translation · rotation · scale with
//! a unit quaternion), and the checks that make the node graph a forest — no cycles, no node with
//! two parents, scene roots really roots, depth within limits — before anything walks it.

use glam::{Mat4, Quat, Vec3};

use crate::json::Obj;
use crate::portal_def::PortalDef;
use crate::{SceneError, SceneLimits};

/// A node as declared.
#[derive(Clone, Debug)]
pub(crate) struct NodeDef {
    pub(crate) name: Option<String>,
    pub(crate) children: Vec<usize>,
    pub(crate) mesh: Option<usize>,
    pub(crate) camera: Option<usize>,
    pub(crate) light: Option<usize>,
    pub(crate) skin: Option<usize>,
    pub(crate) has_matrix: bool,
    pub(crate) local: Mat4,
    /// `extras.barytex_portal`, when declared.
    pub(crate) portal: Option<PortalDef>,
}

/// Counts of the arrays a node may refer to.
pub(crate) struct NodeRefs {
    pub(crate) nodes: usize,
    pub(crate) meshes: usize,
    pub(crate) cameras: usize,
    pub(crate) skins: usize,
    pub(crate) lights: usize,
}

impl NodeDef {
    pub(crate) fn parse(
        obj: Obj<'_>,
        refs: &NodeRefs,
        mesh_targets: &[(usize, bool)],
    ) -> Result<Self, SceneError> {
        let children = obj
            .opt_indices("children", refs.nodes, "node")?
            .unwrap_or_default();
        let mesh = obj.opt_index("mesh", refs.meshes, "mesh")?;
        let camera = obj.opt_index("camera", refs.cameras, "camera")?;
        let skin = obj.opt_index("skin", refs.skins, "skin")?;
        let light = match obj.extension("KHR_lights_punctual")? {
            None => None,
            Some(ext) => {
                let ptr = crate::json::child(&obj.at("extensions"), "KHR_lights_punctual");
                let ext = crate::json::as_obj(ext, &ptr)?;
                Some(ext.req_index("light", refs.lights, "light")?)
            }
        };
        if skin.is_some() && mesh.is_none() {
            return Err(obj.error("skin", "a skin requires a mesh on the same node"));
        }
        if skin.is_some()
            && mesh
                .and_then(|m| mesh_targets.get(m))
                .is_some_and(|&(_, skinned)| !skinned)
        {
            return Err(obj.error("skin", "the node's mesh has no JOINTS_0/WEIGHTS_0 to skin"));
        }
        if let Some(w) = obj.opt_array("weights")? {
            let Some(m) = mesh else {
                return Err(obj.error("weights", "weights require a mesh"));
            };
            let targets = mesh_targets.get(m).map_or(0, |&(t, _)| t);
            if w.len() != targets {
                return Err(obj.error(
                    "weights",
                    format!(
                        "{} weights for a mesh with {targets} morph targets",
                        w.len()
                    ),
                ));
            }
        }
        let matrix = obj.opt_f32s::<16>("matrix")?;
        let translation = obj.opt_f32s::<3>("translation")?;
        let rotation = obj.opt_f32s::<4>("rotation")?;
        let scale = obj.opt_f32s::<3>("scale")?;
        let local = match matrix {
            Some(m) => {
                if translation.is_some() || rotation.is_some() || scale.is_some() {
                    return Err(obj.error(
                        "matrix",
                        "matrix and translation/rotation/scale are both defined",
                    ));
                }
                let m = Mat4::from_cols_array(&m);
                // A node matrix must decompose into TRS: no projective row (glTF 2.0 §3.5.2).
                if m.row(3) != glam::Vec4::W {
                    return Err(obj.error(
                        "matrix",
                        "the matrix is not affine (last row is not 0, 0, 0, 1)",
                    ));
                }
                m
            }
            None => {
                let t = translation.map_or(Vec3::ZERO, Vec3::from);
                let s = scale.map_or(Vec3::ONE, Vec3::from);
                let r = match rotation {
                    None => Quat::IDENTITY,
                    Some(q) => {
                        if q.iter().any(|c| !(-1.0..=1.0).contains(c)) {
                            return Err(
                                obj.error("rotation", "quaternion components must be in [−1, 1]")
                            );
                        }
                        let q = Quat::from_array(q);
                        let len = q.length();
                        // Exporters write unit quaternions to about 7 digits; anything far off
                        // is not a rotation (the validator's ROTATION_NON_UNIT).
                        // (Components are finite and within [−1, 1], so `len` is never NaN.)
                        if (len - 1.0).abs() > 1e-3 {
                            return Err(
                                obj.error("rotation", format!("quaternion length {len} is not 1"))
                            );
                        }
                        // Normalised: tiny export errors must not become scale.
                        q / len
                    }
                };
                Mat4::from_scale_rotation_translation(s, r, t)
            }
        };
        if !local.is_finite() {
            return Err(SceneError::invalid(obj.ptr, "non-finite transform"));
        }
        let portal = PortalDef::parse(&obj, refs.nodes)?;
        Ok(Self {
            portal,
            name: obj.opt_str("name")?.map(str::to_owned),
            children,
            mesh,
            camera,
            light,
            skin,
            has_matrix: matrix.is_some(),
            local,
        })
    }
}

/// The parent of every node, after checking the hierarchy is a forest within `limits`.
pub(crate) fn check_forest(
    nodes: &[NodeDef],
    limits: &SceneLimits,
) -> Result<Vec<Option<usize>>, SceneError> {
    let mut parent: Vec<Option<usize>> = vec![None; nodes.len()];
    for (p, node) in nodes.iter().enumerate() {
        for (k, &c) in node.children.iter().enumerate() {
            let ptr = format!("/nodes/{p}/children/{k}");
            if c == p {
                return Err(SceneError::invalid(
                    ptr,
                    format!("node {p} is its own child"),
                ));
            }
            let slot = parent
                .get_mut(c)
                .ok_or_else(|| SceneError::invalid(&ptr, format!("unresolved node {c}")))?;
            if let Some(prev) = *slot {
                return Err(SceneError::invalid(
                    ptr,
                    format!("node {c} has two parents ({prev} and {p})"),
                ));
            }
            *slot = Some(p);
        }
    }
    // With at most one parent each, a cycle is a parent chain that never reaches a root.
    // depth[i] = 0 unknown; memoised walk up the chain.
    let mut depth = vec![0usize; nodes.len()];
    let mut chain = Vec::new();
    for start in 0..nodes.len() {
        chain.clear();
        let mut at = start;
        let base = loop {
            let d = depth.get(at).copied().unwrap_or(0);
            if d > 0 {
                break d;
            }
            chain.push(at);
            if chain.len() > nodes.len() {
                return Err(SceneError::invalid(
                    format!("/nodes/{start}"),
                    "the node hierarchy contains a cycle",
                ));
            }
            match parent.get(at).copied().flatten() {
                Some(p) => at = p,
                None => break 0,
            }
        };
        for (k, &n) in chain.iter().rev().enumerate() {
            let d = base + k + 1;
            if d > limits.max_node_depth {
                return Err(SceneError::TooLarge {
                    pointer: format!("/nodes/{n}"),
                    what: "node depth",
                    requested: d as u64,
                    limit: limits.max_node_depth as u64,
                });
            }
            if let Some(slot) = depth.get_mut(n) {
                *slot = d;
            }
        }
    }
    Ok(parent)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn node(children: Vec<usize>) -> NodeDef {
        NodeDef {
            name: None,
            children,
            mesh: None,
            camera: None,
            light: None,
            skin: None,
            has_matrix: false,
            local: Mat4::IDENTITY,
            portal: None,
        }
    }

    #[test]
    fn forests_cycles_and_depth() {
        let limits = SceneLimits::default();
        assert!(check_forest(&[node(vec![1]), node(vec![2]), node(vec![])], &limits).is_ok());
        assert!(check_forest(&[node(vec![1]), node(vec![0])], &limits).is_err());
        assert!(check_forest(&[node(vec![2]), node(vec![2]), node(vec![])], &limits).is_err());
        assert!(check_forest(&[node(vec![0])], &limits).is_err());
        let chain: Vec<NodeDef> = (0..100)
            .map(|i| node(if i < 99 { vec![i + 1] } else { vec![] }))
            .collect();
        assert!(matches!(
            check_forest(&chain, &limits),
            Err(SceneError::TooLarge { .. })
        ));
    }
}
