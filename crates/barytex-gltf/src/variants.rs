//! `KHR_materials_variants` is not applied (primitives keep their default material), but its
//! references are checked: the root's variant list, and each primitive's mappings (material and
//! variant indices in range, each variant mapped at most once).

use std::collections::BTreeSet;

use crate::SceneError;
use crate::json::{Obj, as_obj, child};

/// Reads the root extension: the number of variants, `None` when the extension is absent.
pub(crate) fn root_variants(root: Obj<'_>) -> Result<Option<usize>, SceneError> {
    let Some(ext) = root.extension("KHR_materials_variants")? else {
        return Ok(None);
    };
    let ptr = "/extensions/KHR_materials_variants";
    let ext = as_obj(ext, ptr)?;
    let variants = ext
        .opt_array("variants")?
        .ok_or_else(|| SceneError::invalid(ptr, "required property 'variants' is missing"))?;
    for (i, v) in variants.iter().enumerate() {
        let p = child(&ext.at("variants"), &i.to_string());
        as_obj(v, &p)?.req_str("name")?;
    }
    Ok(Some(variants.len()))
}

/// Checks a primitive's `KHR_materials_variants` object.
pub(crate) fn check_primitive(
    p: Obj<'_>,
    variants: Option<usize>,
    materials: usize,
) -> Result<(), SceneError> {
    let Some(ext) = p.extension("KHR_materials_variants")? else {
        return Ok(());
    };
    let ptr = child(&p.at("extensions"), "KHR_materials_variants");
    let Some(count) = variants else {
        return Err(SceneError::invalid(
            ptr,
            "the root defines no KHR_materials_variants variants",
        ));
    };
    let ext = as_obj(ext, &ptr)?;
    let mappings = ext
        .opt_array("mappings")?
        .ok_or_else(|| SceneError::invalid(&ptr, "required property 'mappings' is missing"))?;
    let mut seen = BTreeSet::new();
    for (i, m) in mappings.iter().enumerate() {
        let mp = child(&ext.at("mappings"), &i.to_string());
        let m = as_obj(m, &mp)?;
        m.req_index("material", materials, "material")?;
        let vs = m
            .opt_indices("variants", count, "variant")?
            .ok_or_else(|| SceneError::invalid(&mp, "required property 'variants' is missing"))?;
        for v in vs {
            if !seen.insert(v) {
                return Err(m.error("variants", format!("variant {v} is mapped twice")));
            }
        }
    }
    Ok(())
}
