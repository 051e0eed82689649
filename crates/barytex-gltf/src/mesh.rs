//! Meshes and primitives: attribute semantics and formats checked against the specification's
//! table (§3.7.2.1), index values checked against the vertex count, then decoded into plain
//! vectors, triangle lists and (for points and lines) index lists.

use std::collections::{BTreeMap, BTreeSet};

use glam::{Vec2, Vec3, Vec4};

use crate::SceneError;
use crate::accessor::{AccessorDef, ComponentType, ElementType, Reader, ViewDef};
use crate::json::{Obj, as_obj, child};
use crate::material::Material;
use crate::topology::{Topology, triangulate};

/// A decoded primitive: triangles, or points or lines (glTF 2.0 §3.7.2 "Meshes", modes 0–3)
/// kept as their index lists.
#[derive(Clone, Debug, PartialEq)]
pub struct Primitive {
    /// Object-space positions.
    pub positions: Vec<Vec3>,
    /// Object-space normals, if the file has them.
    pub normals: Option<Vec<Vec3>>,
    /// Tangents with the bitangent sign in `w`.
    pub tangents: Option<Vec<Vec4>>,
    /// `TEXCOORD_0`.
    pub tex_coords0: Option<Vec<Vec2>>,
    /// `TEXCOORD_1`.
    pub tex_coords1: Option<Vec<Vec2>>,
    /// `COLOR_0` as linear RGBA (RGB colours get alpha 1).
    pub colors0: Option<Vec<Vec4>>,
    /// Triangles as vertex indices, counter-clockwise front faces as in the file (empty for
    /// point and line topologies).
    pub triangles: Vec<[u32; 3]>,
    /// For `POINTS`, `LINES`, `LINE_LOOP` and `LINE_STRIP`: the vertex indices in primitive
    /// order (the `indices` accessor's values, or `0..count` without one), to be read as the
    /// topology says; empty for triangle topologies, whose indices are in `triangles`.
    pub indices: Vec<u32>,
    /// Index into [`Scene::materials`](crate::Scene::materials); `None` is the default material.
    pub material: Option<usize>,
    /// The primitive's `mode`: the topology the triangles were built from, or the point or
    /// line topology of `indices`.
    pub topology: Topology,
}

/// A decoded mesh: its primitives (those without `POSITION` or with an unknown mode are
/// skipped).
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh {
    /// Index into the document's `meshes`.
    pub index: usize,
    /// The mesh's name, if any.
    pub name: Option<String>,
    /// Triangle, point and line primitives.
    pub primitives: Vec<Primitive>,
}

/// A primitive as declared and validated.
#[derive(Clone, Debug)]
pub(crate) struct PrimitiveDef {
    pub(crate) ptr: String,
    pub(crate) attributes: BTreeMap<String, usize>,
    pub(crate) indices: Option<usize>,
    pub(crate) material: Option<usize>,
    pub(crate) topology: Option<Topology>,
    pub(crate) vertex_count: Option<u64>,
}

/// A mesh as declared and validated.
#[derive(Clone, Debug)]
pub(crate) struct MeshDef {
    pub(crate) name: Option<String>,
    pub(crate) primitives: Vec<PrimitiveDef>,
    pub(crate) target_count: usize,
    pub(crate) has_skin_attributes: bool,
}

/// How a bufferView is used, to catch one used both for indices and vertices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ViewUse {
    Vertex,
    Index,
}

/// Shared state for mesh validation.
pub(crate) struct MeshContext<'a> {
    pub(crate) accessors: &'a [AccessorDef],
    pub(crate) views: &'a [ViewDef],
    pub(crate) materials: &'a [Material],
    pub(crate) quantization: bool,
    /// Variants of `KHR_materials_variants`, `None` without the root extension.
    pub(crate) variants: Option<usize>,
    pub(crate) view_use: &'a mut Vec<Option<ViewUse>>,
}

fn semantic_ok(name: &str) -> Option<(&str, Option<u32>)> {
    if matches!(name, "POSITION" | "NORMAL" | "TANGENT") {
        return Some((name, None));
    }
    if name.starts_with('_') && name.len() > 1 {
        return Some((name, None));
    }
    let (base, n) = name.split_once('_')?;
    if !matches!(base, "TEXCOORD" | "COLOR" | "JOINTS" | "WEIGHTS") {
        return None;
    }
    if n.is_empty() || !n.bytes().all(|c| c.is_ascii_digit()) || (n.len() > 1 && n.starts_with('0'))
    {
        return None;
    }
    Some((base, Some(n.parse().ok()?)))
}

fn format_ok(base: &str, acc: &AccessorDef, quantization: bool) -> Result<(), String> {
    use ComponentType::{F32, I8, I16, U8, U16};
    use ElementType::{Vec2, Vec3, Vec4};
    let Some(layout) = acc.layout else {
        return Err("accessor has an unknown type or componentType".to_owned());
    };
    let (c, e, n) = (layout.component, layout.element, acc.normalized);
    let ok = match base {
        "POSITION" => e == Vec3 && (c == F32 || (quantization && matches!(c, I8 | U8 | I16 | U16))),
        "NORMAL" => e == Vec3 && (c == F32 || (quantization && n && matches!(c, I8 | I16))),
        "TANGENT" => e == Vec4 && (c == F32 || (quantization && n && matches!(c, I8 | I16))),
        "TEXCOORD" => {
            e == Vec2
                && (c == F32
                    || (n && matches!(c, U8 | U16))
                    || (quantization && matches!(c, I8 | U8 | I16 | U16)))
        }
        "COLOR" => matches!(e, Vec3 | Vec4) && (c == F32 || (n && matches!(c, U8 | U16))),
        "JOINTS" => e == Vec4 && !n && matches!(c, U8 | U16),
        "WEIGHTS" => {
            e == Vec4
                && (c == F32
                    || (n && matches!(c, U8 | U16))
                    || (quantization && n && matches!(c, I8 | I16)))
        }
        _ => c != ComponentType::U32,
    };
    if ok {
        Ok(())
    } else {
        Err(format!(
            "{base} does not allow {e:?} of {c:?} (normalized: {n})"
        ))
    }
}

fn claim_view(
    ctx: &mut MeshContext<'_>,
    view: usize,
    usage: ViewUse,
    ptr: &str,
) -> Result<(), SceneError> {
    let declared = ctx.views.get(view).and_then(|v| v.target);
    let conflict_target = match usage {
        ViewUse::Vertex => declared == Some(34963),
        ViewUse::Index => declared == Some(34962),
    };
    if conflict_target {
        return Err(SceneError::invalid(
            ptr,
            format!("bufferView {view} has a target that does not match its use as {usage:?} data"),
        ));
    }
    if let Some(slot) = ctx.view_use.get_mut(view) {
        match slot {
            Some(prev) if *prev != usage => {
                return Err(SceneError::invalid(
                    ptr,
                    format!("bufferView {view} is used for both vertex and index data"),
                ));
            }
            _ => *slot = Some(usage),
        }
    }
    Ok(())
}

fn check_vertex_accessor(
    ctx: &mut MeshContext<'_>,
    acc: &AccessorDef,
    ptr: &str,
) -> Result<(), SceneError> {
    let Some(view) = acc.view else {
        return Ok(());
    };
    claim_view(ctx, view, ViewUse::Vertex, ptr)?;
    let Some(layout) = acc.layout else {
        return Ok(());
    };
    let v = ctx.views.get(view);
    let stride = v.and_then(|v| v.stride).unwrap_or(layout.element_size());
    // Wrapping keeps the residue mod 4 (2⁶⁴ is a multiple of 4) without overflow.
    let start = v.map_or(0, |v| v.offset).wrapping_add(acc.offset);
    if !start.is_multiple_of(4) || stride % 4 != 0 {
        return Err(SceneError::invalid(
            ptr,
            "vertex attribute data must be aligned to 4-byte boundaries",
        ));
    }
    Ok(())
}

impl MeshDef {
    pub(crate) fn parse(
        obj: Obj<'_>,
        ctx: &mut MeshContext<'_>,
        warnings: &mut Vec<String>,
    ) -> Result<Self, SceneError> {
        let prims = obj.opt_array("primitives")?.ok_or_else(|| {
            SceneError::invalid(obj.ptr, "required property 'primitives' is missing")
        })?;
        let pptr = obj.at("primitives");
        let mut primitives = Vec::with_capacity(prims.len());
        let mut target_counts = BTreeSet::new();
        let mut has_skin_attributes = false;
        for (i, p) in prims.iter().enumerate() {
            let ptr = child(&pptr, &i.to_string());
            let p = as_obj(p, &ptr)?;
            let (def, targets) = parse_primitive(p, ctx, warnings)?;
            has_skin_attributes |= def.attributes.contains_key("JOINTS_0");
            target_counts.insert(targets);
            primitives.push(def);
        }
        if target_counts.len() > 1 {
            return Err(SceneError::invalid(
                obj.ptr,
                "all primitives must have the same number of morph targets",
            ));
        }
        let target_count = target_counts.into_iter().next().unwrap_or(0);
        if let Some(w) = obj.opt_array("weights")?
            && w.len() != target_count
        {
            return Err(obj.error(
                "weights",
                format!("{} weights for {target_count} morph targets", w.len()),
            ));
        }
        Ok(Self {
            name: obj.opt_str("name")?.map(str::to_owned),
            primitives,
            target_count,
            has_skin_attributes,
        })
    }
}

fn parse_primitive(
    p: Obj<'_>,
    ctx: &mut MeshContext<'_>,
    warnings: &mut Vec<String>,
) -> Result<(PrimitiveDef, usize), SceneError> {
    let aptr = p.at("attributes");
    let attrs = p
        .opt_obj("attributes")?
        .ok_or_else(|| SceneError::invalid(p.ptr, "required property 'attributes' is missing"))?;
    let mut attributes = BTreeMap::new();
    let mut sets: BTreeMap<&str, BTreeSet<u32>> = BTreeMap::new();
    let mut vertex_count: Option<u64> = None;
    // bufferView → the first accessor seen reading it without a byteStride.
    let mut unstrided_views: BTreeMap<usize, usize> = BTreeMap::new();
    if let serde_json::Value::Object(map) = attrs {
        if map.is_empty() {
            return Err(SceneError::invalid(&aptr, "attributes must not be empty"));
        }
        for (name, v) in map {
            let ptr = child(&aptr, name);
            let (base, set) = semantic_ok(name).ok_or_else(|| {
                SceneError::invalid(&ptr, format!("invalid attribute semantic {name:?}"))
            })?;
            if let Some(n) = set {
                sets.entry(base).or_default().insert(n);
            }
            let index = crate::json::check_index(
                crate::json::as_u64(v, &ptr)?,
                ctx.accessors.len(),
                "accessor",
                &ptr,
            )?;
            let acc = ctx
                .accessors
                .get(index)
                .ok_or_else(|| SceneError::invalid(&ptr, "unresolved accessor"))?;
            format_ok(base, acc, ctx.quantization).map_err(|r| SceneError::invalid(&ptr, r))?;
            if base == "POSITION" && !acc.has_bounds {
                return Err(SceneError::invalid(
                    &ptr,
                    "the POSITION accessor must define min and max",
                ));
            }
            match vertex_count {
                Some(c) if c != acc.count => {
                    return Err(SceneError::invalid(
                        &ptr,
                        format!(
                            "accessor count {} differs from the other attributes' {c}",
                            acc.count
                        ),
                    ));
                }
                _ => vertex_count = Some(acc.count),
            }
            check_vertex_accessor(ctx, acc, &ptr)?;
            // Two different accessors in one view need a stride to say how they interleave
            // (the same accessor used for two attributes is fine).
            if let Some(view) = acc.view
                && ctx.views.get(view).is_some_and(|v| v.stride.is_none())
                && *unstrided_views.entry(view).or_insert(index) != index
            {
                return Err(SceneError::invalid(
                    &ptr,
                    format!(
                        "attributes share bufferView {view}, which must then define byteStride"
                    ),
                ));
            }
            attributes.insert(name.clone(), index);
        }
    } else {
        return Err(SceneError::invalid(&aptr, "attributes must be an object"));
    }
    for (base, set) in &sets {
        if set
            .iter()
            .copied()
            .ne(0..u32::try_from(set.len()).unwrap_or(u32::MAX))
        {
            return Err(SceneError::invalid(
                &aptr,
                format!("{base}_n sets must be numbered 0, 1, 2, … without gaps"),
            ));
        }
    }
    if sets.get("JOINTS") != sets.get("WEIGHTS") {
        return Err(SceneError::invalid(
            &aptr,
            "JOINTS_n and WEIGHTS_n sets must match",
        ));
    }
    let indices = p.opt_index("indices", ctx.accessors.len(), "accessor")?;
    if let Some(i) = indices {
        let ptr = p.at("indices");
        let acc = ctx
            .accessors
            .get(i)
            .ok_or_else(|| SceneError::invalid(&ptr, "unresolved accessor"))?;
        let layout = acc.layout()?;
        if layout.element != ElementType::Scalar
            || !matches!(
                layout.component,
                ComponentType::U8 | ComponentType::U16 | ComponentType::U32
            )
            || acc.normalized
        {
            return Err(SceneError::invalid(
                &ptr,
                "indices must be SCALAR UNSIGNED_BYTE/SHORT/INT, not normalized",
            ));
        }
        if let Some(view) = acc.view {
            if ctx.views.get(view).is_some_and(|v| v.stride.is_some()) {
                return Err(SceneError::invalid(
                    &ptr,
                    "the indices' bufferView must not define byteStride",
                ));
            }
            claim_view(ctx, view, ViewUse::Index, &ptr)?;
        }
    }
    let material = p.opt_index("material", ctx.materials.len(), "material")?;
    crate::variants::check_primitive(p, ctx.variants, ctx.materials.len())?;
    let mode = p.opt_u64("mode")?.unwrap_or(4);
    let topology = Topology::from_gl(mode);
    if topology.is_none() {
        warnings.push(format!(
            "{}: unknown mode {mode}, primitive skipped",
            p.at("mode")
        ));
    }
    if let Some(m) = material.and_then(|m| ctx.materials.get(m)) {
        let have = sets.get("TEXCOORD").map_or(0, BTreeSet::len);
        for (t, _) in m.texture_refs() {
            if usize::try_from(t.mapping.set).unwrap_or(usize::MAX) >= have {
                return Err(SceneError::invalid(
                    p.at("material"),
                    format!(
                        "the material samples TEXCOORD_{} but the primitive has {have} sets",
                        t.mapping.set
                    ),
                ));
            }
        }
    }
    let mut target_count = 0;
    if let Some(targets) = p.opt_array("targets")? {
        target_count = targets.len();
        let tptr = p.at("targets");
        for (ti, t) in targets.iter().enumerate() {
            let ptr = child(&tptr, &ti.to_string());
            let t = as_obj(t, &ptr)?;
            if let serde_json::Value::Object(map) = t.value() {
                for (name, v) in map {
                    let aptr = child(&ptr, name);
                    let index = crate::json::check_index(
                        crate::json::as_u64(v, &aptr)?,
                        ctx.accessors.len(),
                        "accessor",
                        &aptr,
                    )?;
                    if !attributes.contains_key(name) {
                        return Err(SceneError::invalid(
                            &aptr,
                            format!("morph target {name} has no base attribute"),
                        ));
                    }
                    let acc = ctx
                        .accessors
                        .get(index)
                        .ok_or_else(|| SceneError::invalid(&aptr, "unresolved accessor"))?;
                    if vertex_count.is_some_and(|c| c != acc.count) {
                        return Err(SceneError::invalid(
                            &aptr,
                            "morph target count differs from the base attributes'",
                        ));
                    }
                    if name == "POSITION" && !acc.has_bounds {
                        return Err(SceneError::invalid(
                            &aptr,
                            "a POSITION morph target must define min and max",
                        ));
                    }
                    check_vertex_accessor(ctx, acc, &aptr)?;
                }
            }
        }
    }
    Ok((
        PrimitiveDef {
            ptr: p.ptr.to_owned(),
            attributes,
            indices,
            material,
            topology,
            vertex_count,
        },
        target_count,
    ))
}

impl PrimitiveDef {
    /// Reads the index accessor (or `0..n`), checking every index against the vertex count and
    /// refusing primitive-restart values.
    pub(crate) fn read_indices(
        &self,
        accessors: &[AccessorDef],
        reader: &Reader<'_>,
    ) -> Result<Vec<u32>, SceneError> {
        let n = self.vertex_count.unwrap_or(0);
        match self.indices {
            None => Ok((0..u32::try_from(n)
                .map_err(|_| SceneError::invalid(&self.ptr, "too many vertices"))?)
                .collect()),
            Some(i) => {
                let acc = accessors
                    .get(i)
                    .ok_or_else(|| SceneError::invalid(&self.ptr, "unresolved indices"))?;
                let restart = match acc.layout.map(|l| l.component) {
                    Some(ComponentType::U8) => u32::from(u8::MAX),
                    Some(ComponentType::U16) => u32::from(u16::MAX),
                    _ => u32::MAX,
                };
                let values = reader.read_u32(acc)?;
                for (k, &v) in values.iter().enumerate() {
                    if v == restart {
                        return Err(SceneError::invalid(
                            format!("{}/indices", self.ptr),
                            format!("index {k} is the primitive restart value {v}"),
                        ));
                    }
                    if u64::from(v) >= n {
                        return Err(SceneError::invalid(
                            format!("{}/indices", self.ptr),
                            format!("index {k} is beyond the {n} vertices"),
                        ));
                    }
                }
                Ok(values)
            }
        }
    }

    /// Attribute values with a fixed meaning: tangents' `w` is exactly ±1 (the bitangent sign),
    /// float colours lie in [0, 1].
    pub(crate) fn check_attribute_values(
        &self,
        accessors: &[AccessorDef],
        reader: &Reader<'_>,
    ) -> Result<(), SceneError> {
        for (name, &i) in &self.attributes {
            let Some(acc) = accessors.get(i).filter(|a| a.stores_data()) else {
                continue;
            };
            let float = acc
                .layout
                .is_some_and(|l| l.component == ComponentType::F32);
            if !(name.starts_with("COLOR_") && float) {
                continue;
            }
            let (values, n): (Vec<f32>, usize) = match acc.layout.map(|l| l.element) {
                Some(ElementType::Vec3) => (
                    reader.read_f32::<3>(acc)?.into_iter().flatten().collect(),
                    3,
                ),
                _ => (
                    reader.read_f32::<4>(acc)?.into_iter().flatten().collect(),
                    4,
                ),
            };
            // Named by position, never by value: the bytes may come from an external file.
            if let Some(at) = values.iter().position(|v| !(0.0..=1.0).contains(v)) {
                return Err(SceneError::invalid(
                    &acc.ptr,
                    format!(
                        "colour element {} component {} is outside [0, 1]",
                        at / n,
                        at % n
                    ),
                ));
            }
        }
        let Some(acc) = self
            .attributes
            .get("TANGENT")
            .and_then(|&i| accessors.get(i))
            .filter(|a| a.stores_data())
        else {
            return Ok(());
        };
        for (k, t) in reader.read_f32::<4>(acc)?.into_iter().enumerate() {
            if t[3] != 1.0 && t[3] != -1.0 {
                return Err(SceneError::invalid(
                    &acc.ptr,
                    format!("tangent {k} has a w that is not ±1"),
                ));
            }
        }
        Ok(())
    }

    /// Decodes the primitive; `None` when its mode is unknown or it has no positions.
    pub(crate) fn decode(
        &self,
        accessors: &[AccessorDef],
        reader: &Reader<'_>,
    ) -> Result<Option<Primitive>, SceneError> {
        let Some(topology) = self.topology else {
            return Ok(None);
        };
        let Some(&pos) = self.attributes.get("POSITION") else {
            return Ok(None);
        };
        let acc = |i: usize| {
            accessors
                .get(i)
                .ok_or_else(|| SceneError::invalid(&self.ptr, "unresolved accessor"))
        };
        let vec3 = |i: usize| -> Result<Vec<Vec3>, SceneError> {
            Ok(reader
                .read_f32::<3>(acc(i)?)?
                .into_iter()
                .map(Vec3::from)
                .collect())
        };
        let vec2 = |i: usize| -> Result<Vec<Vec2>, SceneError> {
            Ok(reader
                .read_f32::<2>(acc(i)?)?
                .into_iter()
                .map(Vec2::from)
                .collect())
        };
        let positions = vec3(pos)?;
        let normals = self
            .attributes
            .get("NORMAL")
            .map(|&i| vec3(i))
            .transpose()?;
        let tangents = self
            .attributes
            .get("TANGENT")
            .map(|&i| -> Result<Vec<Vec4>, SceneError> {
                Ok(reader
                    .read_f32::<4>(acc(i)?)?
                    .into_iter()
                    .map(Vec4::from)
                    .collect())
            })
            .transpose()?;
        let tex_coords0 = self
            .attributes
            .get("TEXCOORD_0")
            .map(|&i| vec2(i))
            .transpose()?;
        let tex_coords1 = self
            .attributes
            .get("TEXCOORD_1")
            .map(|&i| vec2(i))
            .transpose()?;
        let colors0 = match self.attributes.get("COLOR_0") {
            None => None,
            Some(&i) => {
                let a = acc(i)?;
                Some(match a.layout.map(|l| l.element) {
                    Some(ElementType::Vec3) => reader
                        .read_f32::<3>(a)?
                        .into_iter()
                        .map(|c| Vec3::from(c).extend(1.0))
                        .collect(),
                    _ => reader
                        .read_f32::<4>(a)?
                        .into_iter()
                        .map(Vec4::from)
                        .collect(),
                })
            }
        };
        let indices = self.read_indices(accessors, reader)?;
        let (triangles, indices) = if topology.is_triangles() {
            (triangulate(topology, &indices), Vec::new())
        } else {
            (Vec::new(), indices)
        };
        Ok(Some(Primitive {
            positions,
            normals,
            tangents,
            tex_coords0,
            tex_coords1,
            colors0,
            triangles,
            indices,
            material: self.material,
            topology,
        }))
    }

    /// Triangles this primitive will produce (0 for points, lines and primitives without
    /// positions), from declared counts only.
    pub(crate) fn claimed_triangles(&self, accessors: &[AccessorDef]) -> u64 {
        let Some(t) = self.topology.filter(|t| t.is_triangles()) else {
            return 0;
        };
        if !self.attributes.contains_key("POSITION") {
            return 0;
        }
        let n = match self.indices {
            Some(i) => accessors.get(i).map_or(0, |a| a.count),
            None => self.vertex_count.unwrap_or(0),
        };
        t.triangle_count(usize::try_from(n).unwrap_or(usize::MAX)) as u64
    }

    /// Vertices a decoded primitive holds (its attributes' count; 0 for one the loader skips:
    /// no positions or an unknown mode), from declared counts.
    pub(crate) fn claimed_vertices(&self) -> u64 {
        if self.topology.is_none() || !self.attributes.contains_key("POSITION") {
            return 0;
        }
        self.vertex_count.unwrap_or(0)
    }
}
