//! Skins are not applied (meshes are loaded in their bind pose), but a broken skin is a broken
//! file: joint and accessor references, the inverse-bind-matrix format and count, the joints'
//! common root, the skeleton node, and the matrices' affine last row are checked.

use crate::SceneError;
use crate::accessor::{AccessorDef, ComponentType, ElementType, Reader, ViewDef};
use crate::json::Obj;

/// A skin as declared.
#[derive(Clone, Debug)]
pub(crate) struct SkinDef {
    pub(crate) ptr: String,
    pub(crate) joints: Vec<usize>,
    pub(crate) skeleton: Option<usize>,
    pub(crate) inverse_bind_matrices: Option<usize>,
}

impl SkinDef {
    pub(crate) fn parse(
        s: Obj<'_>,
        nodes: usize,
        accessors: &[AccessorDef],
        views: &[ViewDef],
    ) -> Result<Self, SceneError> {
        let joints = s
            .opt_indices("joints", nodes, "node")?
            .ok_or_else(|| SceneError::invalid(s.ptr, "required property 'joints' is missing"))?;
        let skeleton = s.opt_index("skeleton", nodes, "node")?;
        let inverse_bind_matrices =
            s.opt_index("inverseBindMatrices", accessors.len(), "accessor")?;
        if let Some(i) = inverse_bind_matrices {
            let acc = accessors
                .get(i)
                .ok_or_else(|| s.error("inverseBindMatrices", "unresolved accessor"))?;
            let ok = acc.layout.is_some_and(|l| {
                l.element == ElementType::Mat4 && l.component == ComponentType::F32
            });
            if !ok {
                return Err(s.error(
                    "inverseBindMatrices",
                    "inverse bind matrices must be MAT4 FLOAT",
                ));
            }
            if acc.count < joints.len() as u64 {
                return Err(s.error(
                    "inverseBindMatrices",
                    "fewer inverse bind matrices than joints",
                ));
            }
            if acc
                .view
                .and_then(|v| views.get(v))
                .is_some_and(|v| v.stride.is_some())
            {
                return Err(s.error(
                    "inverseBindMatrices",
                    "the bufferView must not define byteStride",
                ));
            }
        }
        Ok(Self {
            ptr: s.ptr.to_owned(),
            joints,
            skeleton,
            inverse_bind_matrices,
        })
    }

    /// Hierarchy checks, given every node's parent and the scenes' root nodes: the joints share
    /// one root, the skeleton (if any) is an ancestor of every joint, and a skinned node's scene
    /// contains the joints.
    pub(crate) fn check_hierarchy(
        &self,
        parents: &[Option<usize>],
        skinned_nodes: &[usize],
        scenes: &[Vec<usize>],
    ) -> Result<(), SceneError> {
        let ancestors = |mut n: usize| {
            let mut chain = vec![n];
            while let Some(p) = parents.get(n).copied().flatten() {
                chain.push(p);
                n = p;
                if chain.len() > parents.len() {
                    break;
                }
            }
            chain
        };
        let root = |n: usize| ancestors(n).last().copied().unwrap_or(n);
        let Some(&first) = self.joints.first() else {
            return Ok(());
        };
        let common = root(first);
        if self.joints.iter().any(|&j| root(j) != common) {
            return Err(SceneError::invalid(
                format!("{}/joints", self.ptr),
                "joints do not share a common root",
            ));
        }
        if let Some(s) = self.skeleton
            && self.joints.iter().any(|&j| !ancestors(j).contains(&s))
        {
            return Err(SceneError::invalid(
                format!("{}/skeleton", self.ptr),
                format!("node {s} is not an ancestor of every joint"),
            ));
        }
        for &n in skinned_nodes {
            let r = root(n);
            for roots in scenes.iter().filter(|roots| roots.contains(&r)) {
                if !roots.contains(&common) {
                    return Err(SceneError::invalid(
                        format!("/nodes/{n}/skin"),
                        "the skinned node's scene does not contain the skin's joints",
                    ));
                }
            }
        }
        Ok(())
    }

    /// Inverse bind matrices must be affine (last row 0, 0, 0, 1).
    pub(crate) fn check_data(
        &self,
        accessors: &[AccessorDef],
        reader: &Reader<'_>,
    ) -> Result<(), SceneError> {
        let Some(acc) = self
            .inverse_bind_matrices
            .and_then(|i| accessors.get(i))
            .filter(|a| a.stores_data())
        else {
            return Ok(());
        };
        for (k, m) in reader.read_f32::<16>(acc)?.into_iter().enumerate() {
            if [m[3], m[7], m[11], m[15]] != [0.0, 0.0, 0.0, 1.0] {
                return Err(SceneError::invalid(
                    &acc.ptr,
                    format!("inverse bind matrix {k} is not affine"),
                ));
            }
        }
        Ok(())
    }
}
