//! Animations are not loaded (the scene is flattened at rest), but a broken animation is a broken
//! file: references, accessor formats and counts are checked here, and the keyframe data (times
//! non-negative and increasing, rotations unit quaternions) once the buffers are read.

use std::collections::BTreeSet;

use crate::SceneError;
use crate::accessor::{AccessorDef, ComponentType, ElementType, Reader, ViewDef};
use crate::json::{Obj, as_obj, child};

/// What animation checks need to know about the rest of the document.
pub(crate) struct AnimationContext<'a> {
    pub(crate) accessors: &'a [AccessorDef],
    pub(crate) views: &'a [ViewDef],
    /// Per node: (defines a matrix, morph target count of its mesh).
    pub(crate) nodes: &'a [(bool, usize)],
    /// Whether `KHR_animation_pointer` is in `extensionsUsed`.
    pub(crate) pointer_extension: bool,
}

/// Data checks to run once the buffers are loaded: (input accessor, output accessor if it holds
/// rotations).
#[derive(Clone, Debug, Default)]
pub(crate) struct KeyframeChecks {
    pub(crate) inputs: BTreeSet<usize>,
    /// (output accessor, cubic spline: only every third element is a value).
    pub(crate) rotations: BTreeSet<(usize, bool)>,
}

fn accessor<'a>(
    ctx: &AnimationContext<'a>,
    s: Obj<'_>,
    key: &str,
) -> Result<(usize, &'a AccessorDef), SceneError> {
    let i = s.req_index(key, ctx.accessors.len(), "accessor")?;
    let acc = ctx
        .accessors
        .get(i)
        .ok_or_else(|| s.error(key, "unresolved accessor"))?;
    if acc
        .view
        .and_then(|v| ctx.views.get(v))
        .is_some_and(|v| v.stride.is_some())
    {
        return Err(s.error(
            key,
            "animation sampler accessors' bufferViews must not define byteStride",
        ));
    }
    Ok((i, acc))
}

/// Checks `/animations/i`.
pub(crate) fn check(
    a: Obj<'_>,
    ctx: &AnimationContext<'_>,
    checks: &mut KeyframeChecks,
    warnings: &mut Vec<String>,
) -> Result<(), SceneError> {
    let samplers_ptr = a.at("samplers");
    let samplers = a
        .opt_array("samplers")?
        .ok_or_else(|| SceneError::invalid(a.ptr, "required property 'samplers' is missing"))?;
    // (input index, input count, output accessor, cubic)
    let mut parsed = Vec::with_capacity(samplers.len());
    for (i, s) in samplers.iter().enumerate() {
        let p = child(&samplers_ptr, &i.to_string());
        let s = as_obj(s, &p)?;
        let (input_index, input) = accessor(ctx, s, "input")?;
        let (output_index, output) = accessor(ctx, s, "output")?;
        let ok = input
            .layout
            .is_some_and(|l| l.element == ElementType::Scalar && l.component == ComponentType::F32);
        if !ok {
            return Err(s.error("input", "keyframe times must be SCALAR FLOAT"));
        }
        if !input.has_bounds {
            return Err(s.error("input", "keyframe times must define min and max"));
        }
        let cubic = match s.opt_str("interpolation")? {
            None | Some("LINEAR" | "STEP") => false,
            Some("CUBICSPLINE") => true,
            Some(other) => {
                warnings.push(format!(
                    "{}: unknown interpolation {other:?}",
                    s.at("interpolation")
                ));
                false
            }
        };
        if cubic && input.count < 2 {
            return Err(s.error("input", "CUBICSPLINE needs at least two keyframes"));
        }
        checks.inputs.insert(input_index);
        parsed.push((input.count, output_index, output, cubic));
    }
    let channels_ptr = a.at("channels");
    let channels = a
        .opt_array("channels")?
        .ok_or_else(|| SceneError::invalid(a.ptr, "required property 'channels' is missing"))?;
    let mut targets = BTreeSet::new();
    for (i, c) in channels.iter().enumerate() {
        let p = child(&channels_ptr, &i.to_string());
        let c = as_obj(c, &p)?;
        let sampler = c.req_index("sampler", parsed.len(), "sampler")?;
        let tptr = c.at("target");
        let target = c
            .get("target")
            .ok_or_else(|| SceneError::invalid(c.ptr, "required property 'target' is missing"))?;
        let target = as_obj(target, &tptr)?;
        let node = target.opt_index("node", ctx.nodes.len(), "node")?;
        let path = target.req_str("path")?.to_owned();
        let path = path.as_str();
        let pointer_ext = target.extension("KHR_animation_pointer")?;
        if ctx.pointer_extension {
            if path == "pointer" {
                if node.is_some() {
                    return Err(target.error("node", "a 'pointer' target must not define node"));
                }
                let eptr = child(&target.at("extensions"), "KHR_animation_pointer");
                let ext = pointer_ext.ok_or_else(|| {
                    SceneError::invalid(&tptr, "a 'pointer' target needs KHR_animation_pointer")
                })?;
                let pointer = as_obj(ext, &eptr)?.req_str("pointer")?.to_owned();
                if !pointer.starts_with('/') {
                    return Err(SceneError::invalid(
                        eptr,
                        format!("{pointer:?} is not a JSON pointer"),
                    ));
                }
                continue;
            } else if pointer_ext.is_some() {
                return Err(target.error("path", "KHR_animation_pointer requires path 'pointer'"));
            }
        }
        let per_key = match path {
            "translation" | "rotation" | "scale" => 1,
            "weights" => match node.and_then(|n| ctx.nodes.get(n)) {
                Some(&(_, targets)) if targets > 0 => targets,
                Some(_) => {
                    return Err(
                        target.error("path", "animating weights of a node without morph targets")
                    );
                }
                None => 1,
            },
            other => {
                warnings.push(format!(
                    "{}: unknown path {other:?}, channel ignored",
                    target.at("path")
                ));
                continue;
            }
        };
        if let Some(n) = node {
            if path != "weights" && ctx.nodes.get(n).is_some_and(|&(matrix, _)| matrix) {
                return Err(target.error("node", "animating TRS of a node defined by a matrix"));
            }
            if !targets.insert((n, path.to_owned())) {
                return Err(SceneError::invalid(
                    &tptr,
                    format!("node {n} {path} is animated twice"),
                ));
            }
        }
        let (input_count, output_index, output, cubic) = parsed
            .get(sampler)
            .ok_or_else(|| c.error("sampler", "unresolved sampler"))?;
        let layout = output.layout()?;
        let normalized_int = output.normalized
            && matches!(
                layout.component,
                ComponentType::I8 | ComponentType::U8 | ComponentType::I16 | ComponentType::U16
            );
        let ok = match path {
            "translation" | "scale" => {
                layout.element == ElementType::Vec3 && layout.component == ComponentType::F32
            }
            "rotation" => {
                layout.element == ElementType::Vec4
                    && (layout.component == ComponentType::F32 || normalized_int)
            }
            _ => {
                layout.element == ElementType::Scalar
                    && (layout.component == ComponentType::F32 || normalized_int)
            }
        };
        let out_ptr = format!("{samplers_ptr}/{sampler}/output");
        if !ok {
            return Err(SceneError::invalid(
                out_ptr,
                format!("output format not allowed for {path}"),
            ));
        }
        let expected = input_count
            .saturating_mul(per_key as u64)
            .saturating_mul(if *cubic { 3 } else { 1 });
        if output.count != expected {
            return Err(SceneError::invalid(
                out_ptr,
                format!("{} output elements, expected {expected}", output.count),
            ));
        }
        if path == "rotation" && layout.component == ComponentType::F32 {
            checks.rotations.insert((*output_index, *cubic));
        }
    }
    Ok(())
}

/// Keyframe data checks, once the buffers are loaded.
pub(crate) fn check_data(
    checks: &KeyframeChecks,
    accessors: &[AccessorDef],
    reader: &Reader<'_>,
    readable: impl Fn(&AccessorDef) -> bool,
) -> Result<(), SceneError> {
    for &i in &checks.inputs {
        let Some(acc) = accessors.get(i).filter(|a| a.stores_data() && readable(a)) else {
            continue;
        };
        let times = reader.read_f32::<1>(acc)?;
        let mut prev = None;
        for (k, [t]) in times.into_iter().enumerate() {
            if t < 0.0 {
                return Err(SceneError::invalid(
                    &acc.ptr,
                    format!("keyframe {k} time is negative"),
                ));
            }
            if prev.is_some_and(|p| t <= p) {
                return Err(SceneError::invalid(
                    &acc.ptr,
                    format!("keyframe {k} time does not increase"),
                ));
            }
            prev = Some(t);
        }
    }
    for &(i, cubic) in &checks.rotations {
        let Some(acc) = accessors.get(i).filter(|a| a.stores_data() && readable(a)) else {
            continue;
        };
        for (k, q) in reader.read_f32::<4>(acc)?.into_iter().enumerate() {
            if cubic && k % 3 != 1 {
                continue; // in/out tangents need not be unit
            }
            let len = glam::Vec4::from(q).length();
            if (len - 1.0).abs() > 1e-3 {
                return Err(SceneError::invalid(
                    &acc.ptr,
                    format!("rotation keyframe {k} is not a unit quaternion"),
                ));
            }
        }
    }
    Ok(())
}
