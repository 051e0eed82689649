//! The loading pipeline: container → JSON → every object parsed and cross-checked (indices,
//! ranges, formats, hierarchy) → buffers read → data validated → the chosen scene flattened,
//! its meshes decoded and its materials' images decoded.
//!
//! Validation covers the whole document, used or not, wherever the check is cheap and the rule
//! is the specification's; decoding covers only what the chosen scene uses.

use std::collections::BTreeSet;
use std::sync::Arc;

use barytex_texture::load::ColorSpace;
use glam::{Mat4, Vec3};
use serde_json::Value;

use crate::accessor::{AccessorDef, Reader, ViewDef};
use crate::animation::{AnimationContext, KeyframeChecks};
use crate::buffer::{self, BufferDef, Source};
use crate::camera::{DocumentCamera, Projection, SceneCamera};
use crate::image::ImageDef;
use crate::image_decode::{self, WantedImages};
use crate::json::{Obj, as_obj, child};
use crate::light::{PunctualLight, SceneLight};
use crate::material::Material;
use crate::mesh::{Mesh, MeshContext, MeshDef};
use crate::node::{NodeDef, NodeRefs, check_forest};
use crate::portal_def::PortalKind;
use crate::sampler::SamplerParams;
use crate::scene::{MeshInstance, Scene, SceneStats, Texture};
use crate::skin::SkinDef;
use crate::{LoadOptions, SceneError, UriResolver, glb};

/// Extensions this loader implements (and so may appear in `extensionsRequired`).
const SUPPORTED_EXTENSIONS: [&str; 4] = [
    "KHR_lights_punctual",
    "KHR_materials_unlit",
    "KHR_texture_transform",
    "KHR_mesh_quantization",
];

/// Loads a glTF or GLB held in memory.
pub(crate) fn load(
    bytes: &[u8],
    files: Option<&dyn UriResolver>,
    force_glb: bool,
    options: &LoadOptions,
) -> Result<Scene, SceneError> {
    let limits = &options.limits;
    if bytes.len() as u64 > limits.max_file_bytes {
        return Err(SceneError::TooLarge {
            pointer: String::new(),
            what: "file bytes",
            requested: bytes.len() as u64,
            limit: limits.max_file_bytes,
        });
    }
    let mut warnings = Vec::new();
    let (json, bin, is_glb) = if force_glb || glb::is_glb(bytes) {
        let g = glb::parse(bytes)?;
        if g.trailing_bytes > 0 {
            warnings.push(format!(
                "{} bytes after the GLB's declared length ignored",
                g.trailing_bytes
            ));
        }
        (g.json, g.bin, true)
    } else {
        (bytes, None, false)
    };
    if json.starts_with(&[0xEF, 0xBB, 0xBF]) {
        return Err(SceneError::Json(
            "the JSON starts with a byte-order mark".to_owned(),
        ));
    }
    let root: Value = serde_json::from_slice(json).map_err(|e| SceneError::Json(e.to_string()))?;
    let root = as_obj(&root, "")
        .map_err(|_| SceneError::Json("the root is not a JSON object".to_owned()))?;
    crate::json::check_no_empty_arrays(root.value(), "", 0)?;
    let source = Source { files, bin, is_glb };
    Document::parse(root, source, options, &mut warnings)?.into_scene(source, options, warnings)
}

/// Every object of the document, parsed and cross-checked.
struct Document {
    buffers: Vec<BufferDef>,
    views: Vec<ViewDef>,
    accessors: Vec<AccessorDef>,
    images: Vec<ImageDef>,
    textures: Vec<Texture>,
    materials: Vec<Material>,
    cameras: Vec<(Option<String>, Projection)>,
    lights: Vec<Option<PunctualLight>>,
    meshes: Vec<MeshDef>,
    nodes: Vec<NodeDef>,
    /// (name, root nodes) per scene.
    scenes: Vec<(Option<String>, Vec<usize>)>,
    default_scene: Option<usize>,
    parents: Vec<Option<usize>>,
    skins: Vec<SkinDef>,
    keyframes: KeyframeChecks,
}

/// The objects of a top-level array (or an empty list when absent).
fn objects<'a>(root: Obj<'a>, key: &str) -> Result<Vec<(String, &'a Value)>, SceneError> {
    let Some(items) = root.opt_array(key)? else {
        return Ok(Vec::new());
    };
    let ptr = root.at(key);
    items
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let p = child(&ptr, &i.to_string());
            as_obj(v, &p)?;
            Ok((p, v))
        })
        .collect()
}

fn string_list(root: Obj<'_>, key: &str) -> Result<Vec<String>, SceneError> {
    let Some(items) = root.opt_array(key)? else {
        return Ok(Vec::new());
    };
    let mut out: Vec<String> = Vec::new();
    for (i, v) in items.iter().enumerate() {
        let p = child(&root.at(key), &i.to_string());
        let s = v
            .as_str()
            .ok_or_else(|| SceneError::invalid(&p, "expected a string"))?;
        if out.iter().any(|o| o == s) {
            return Err(SceneError::invalid(p, format!("duplicate entry {s:?}")));
        }
        out.push(s.to_owned());
    }
    Ok(out)
}

fn parse_version(s: &str) -> Option<(u64, u64)> {
    let (major, minor) = s.split_once('.')?;
    let num = |t: &str| {
        (!t.is_empty() && t.bytes().all(|b| b.is_ascii_digit()))
            .then(|| t.parse().ok())
            .flatten()
    };
    Some((num(major)?, num(minor)?))
}

fn check_asset(root: Obj<'_>) -> Result<(), SceneError> {
    let ptr = root.at("asset");
    let asset = root
        .get("asset")
        .ok_or_else(|| SceneError::invalid("", "required property 'asset' is missing"))?;
    let asset = as_obj(asset, &ptr)?;
    let version = asset.req_str("version")?;
    let (major, minor) = parse_version(version)
        .ok_or_else(|| asset.error("version", format!("version {version:?} is not MAJOR.MINOR")))?;
    if major != 2 {
        return Err(asset.error("version", format!("unsupported glTF major version {major}")));
    }
    if let Some(min) = asset.opt_str("minVersion")? {
        let parsed = parse_version(min).ok_or_else(|| {
            asset.error(
                "minVersion",
                format!("minVersion {min:?} is not MAJOR.MINOR"),
            )
        })?;
        if parsed > (major, minor) {
            return Err(asset.error("minVersion", "minVersion is greater than version"));
        }
        if parsed.0 != 2 || parsed.1 > 0 {
            return Err(asset.error(
                "minVersion",
                format!("glTF {min} is required, this loader reads 2.0"),
            ));
        }
    }
    Ok(())
}

impl Document {
    /// Node `n`'s world matrix in its own hierarchy (the forest is checked acyclic and within
    /// the depth limit before this runs).
    fn node_world(&self, n: usize) -> Mat4 {
        let mut world = Mat4::IDENTITY;
        let mut at = Some(n);
        while let Some(i) = at {
            let Some(node) = self.nodes.get(i) else { break };
            world = node.local * world;
            at = self.parents.get(i).copied().flatten();
        }
        world
    }

    #[allow(clippy::too_many_lines)]
    fn parse(
        root: Obj<'_>,
        source: Source<'_>,
        options: &LoadOptions,
        warnings: &mut Vec<String>,
    ) -> Result<Self, SceneError> {
        let limits = &options.limits;
        check_asset(root)?;
        let used = string_list(root, "extensionsUsed")?;
        let required = string_list(root, "extensionsRequired")?;
        for (i, r) in required.iter().enumerate() {
            if !used.contains(r) {
                return Err(SceneError::invalid(
                    format!("/extensionsRequired/{i}"),
                    format!("{r} is required but not in extensionsUsed"),
                ));
            }
            if !SUPPORTED_EXTENSIONS.contains(&r.as_str()) {
                return Err(SceneError::UnsupportedExtension(r.clone()));
            }
        }
        crate::extensions::check(root.value(), &used)?;
        let quantization = required.iter().any(|r| r == "KHR_mesh_quantization");
        let webp = used.iter().any(|u| u == "EXT_texture_webp");

        let mut buffers = Vec::new();
        for (p, v) in objects(root, "buffers")? {
            buffers.push(BufferDef::parse(as_obj(v, &p)?, limits)?);
        }
        if source.is_glb && source.bin.is_some() && buffers.first().is_none_or(|b| b.uri.is_some())
        {
            warnings.push("the GLB BIN chunk is not used by buffer 0".to_owned());
        }
        let lengths: Vec<u64> = buffers.iter().map(|b| b.byte_length).collect();
        let mut views = Vec::new();
        for (p, v) in objects(root, "bufferViews")? {
            views.push(ViewDef::parse(as_obj(v, &p)?, &lengths)?);
        }
        let mut accessors = Vec::new();
        for (p, v) in objects(root, "accessors")? {
            accessors.push(AccessorDef::parse(
                as_obj(v, &p)?,
                &views,
                limits,
                warnings,
            )?);
        }
        let mut samplers = Vec::new();
        for (p, v) in objects(root, "samplers")? {
            samplers.push(SamplerParams::parse(as_obj(v, &p)?, warnings)?);
        }
        let mut images = Vec::new();
        for (p, v) in objects(root, "images")? {
            images.push(ImageDef::parse(as_obj(v, &p)?, &views, webp, limits)?);
        }
        let mut textures = Vec::new();
        for (p, v) in objects(root, "textures")? {
            let t = as_obj(v, &p)?;
            let sampler = match t.opt_index("sampler", samplers.len(), "sampler")? {
                Some(s) => samplers.get(s).copied().unwrap_or_default(),
                None => SamplerParams::default(),
            };
            let image = t.opt_index("source", images.len(), "image")?;
            if let Some(ext) = t.extension("EXT_texture_webp")? {
                let eptr = child(&t.at("extensions"), "EXT_texture_webp");
                as_obj(ext, &eptr)?.opt_index("source", images.len(), "image")?;
            }
            if let Some(i) = image
                && images.get(i).and_then(|im| im.mime.as_deref()) == Some("image/webp")
            {
                return Err(t.error("source", "a core texture source must be PNG or JPEG"));
            }
            textures.push(Texture { image, sampler });
        }
        let texture_info: Vec<(Option<usize>, SamplerParams)> =
            textures.iter().map(|t| (t.image, t.sampler)).collect();
        let mut materials = Vec::new();
        for (p, v) in objects(root, "materials")? {
            materials.push(Material::parse(as_obj(v, &p)?, &texture_info, warnings)?);
        }
        let mut cameras = Vec::new();
        for (p, v) in objects(root, "cameras")? {
            let c = as_obj(v, &p)?;
            cameras.push((
                c.opt_str("name")?.map(str::to_owned),
                Projection::parse(c, warnings)?,
            ));
        }
        let mut lights = Vec::new();
        if let Some(ext) = root.extension("KHR_lights_punctual")? {
            let eptr = "/extensions/KHR_lights_punctual";
            let ext = as_obj(ext, eptr)?;
            if ext.get("lights").is_none() {
                return Err(SceneError::invalid(
                    eptr,
                    "required property 'lights' is missing",
                ));
            }
            for (p, v) in objects(ext, "lights")? {
                lights.push(PunctualLight::parse(as_obj(v, &p)?, warnings)?);
            }
        }
        let variants = crate::variants::root_variants(root)?;
        let mut view_use = vec![None; views.len()];
        let mut meshes = Vec::new();
        for (p, v) in objects(root, "meshes")? {
            let mut ctx = MeshContext {
                accessors: &accessors,
                views: &views,
                materials: &materials,
                quantization,
                variants,
                view_use: &mut view_use,
            };
            meshes.push(MeshDef::parse(as_obj(v, &p)?, &mut ctx, warnings)?);
        }
        let node_values = objects(root, "nodes")?;
        if node_values.len() > limits.max_nodes {
            return Err(SceneError::TooLarge {
                pointer: "/nodes".to_owned(),
                what: "nodes",
                requested: node_values.len() as u64,
                limit: limits.max_nodes as u64,
            });
        }
        let mut skins = Vec::new();
        for (p, v) in objects(root, "skins")? {
            skins.push(SkinDef::parse(
                as_obj(v, &p)?,
                node_values.len(),
                &accessors,
                &views,
            )?);
        }
        let refs = NodeRefs {
            nodes: node_values.len(),
            meshes: meshes.len(),
            cameras: cameras.len(),
            skins: skins.len(),
            lights: lights.len(),
        };
        let mesh_targets: Vec<(usize, bool)> = meshes
            .iter()
            .map(|m| (m.target_count, m.has_skin_attributes))
            .collect();
        let mut nodes = Vec::with_capacity(node_values.len());
        for (p, v) in &node_values {
            nodes.push(NodeDef::parse(as_obj(v, p)?, &refs, &mesh_targets)?);
        }
        let parents = check_forest(&nodes, limits)?;
        let mut scenes = Vec::new();
        for (p, v) in objects(root, "scenes")? {
            let s = as_obj(v, &p)?;
            let roots = s
                .opt_indices("nodes", nodes.len(), "node")?
                .unwrap_or_default();
            let mut seen = BTreeSet::new();
            for (k, &n) in roots.iter().enumerate() {
                let ptr = child(&s.at("nodes"), &k.to_string());
                if parents.get(n).copied().flatten().is_some() {
                    return Err(SceneError::invalid(
                        ptr,
                        format!("node {n} is not a root node"),
                    ));
                }
                if !seen.insert(n) {
                    return Err(SceneError::invalid(
                        ptr,
                        format!("node {n} is listed twice"),
                    ));
                }
            }
            scenes.push((s.opt_str("name")?.map(str::to_owned), roots));
        }
        let default_scene = root.opt_index("scene", scenes.len(), "scene")?;
        let scene_roots: Vec<Vec<usize>> = scenes.iter().map(|(_, r)| r.clone()).collect();
        for (s, skin) in skins.iter().enumerate() {
            let skinned: Vec<usize> = (0..nodes.len())
                .filter(|&n| nodes.get(n).is_some_and(|x| x.skin == Some(s)))
                .collect();
            skin.check_hierarchy(&parents, &skinned, &scene_roots)?;
        }
        let node_info: Vec<(bool, usize)> = nodes
            .iter()
            .map(|n| {
                (
                    n.has_matrix,
                    n.mesh
                        .and_then(|m| mesh_targets.get(m))
                        .map_or(0, |&(t, _)| t),
                )
            })
            .collect();
        let actx = AnimationContext {
            accessors: &accessors,
            views: &views,
            nodes: &node_info,
            pointer_extension: used.iter().any(|u| u == "KHR_animation_pointer"),
        };
        let mut keyframes = KeyframeChecks::default();
        for (p, v) in objects(root, "animations")? {
            crate::animation::check(as_obj(v, &p)?, &actx, &mut keyframes, warnings)?;
        }
        Ok(Self {
            buffers,
            views,
            accessors,
            images,
            textures,
            materials,
            cameras,
            lights,
            meshes,
            nodes,
            scenes,
            default_scene,
            parents,
            skins,
            keyframes,
        })
    }

    #[allow(clippy::too_many_lines)]
    fn into_scene(
        self,
        source: Source<'_>,
        options: &LoadOptions,
        mut warnings: Vec<String>,
    ) -> Result<Scene, SceneError> {
        let limits = &options.limits;
        let mut stats = SceneStats::default();
        let mut used_buffers = vec![false; self.buffers.len()];
        for v in &self.views {
            if let Some(u) = used_buffers.get_mut(v.buffer) {
                *u = true;
            }
        }
        let data = buffer::load_all(&self.buffers, &used_buffers, source, limits, &mut warnings)?;
        let reader = Reader {
            views: &self.views,
            buffers: &data,
        };
        let has_data = |view: Option<usize>| {
            view.and_then(|v| self.views.get(v))
                .is_none_or(|v| data.get(v.buffer).is_some_and(Option::is_some))
        };
        for acc in &self.accessors {
            let sparse_ok = acc
                .sparse
                .as_ref()
                .is_none_or(|s| has_data(Some(s.indices_view)) && has_data(Some(s.values_view)));
            if has_data(acc.view) && sparse_ok {
                reader.validate(acc)?;
            }
        }
        let readable = |a: &AccessorDef| {
            has_data(a.view)
                && a.sparse
                    .as_ref()
                    .is_none_or(|s| has_data(Some(s.indices_view)) && has_data(Some(s.values_view)))
        };
        let primitive_readable = |p: &crate::mesh::PrimitiveDef| {
            p.attributes
                .values()
                .chain(p.indices.as_ref())
                .all(|&i| self.accessors.get(i).is_some_and(readable))
        };
        for mesh in &self.meshes {
            for p in &mesh.primitives {
                if p.vertex_count.is_some() && primitive_readable(p) {
                    p.read_indices(&self.accessors, &reader)?;
                    p.check_attribute_values(&self.accessors, &reader)?;
                }
            }
        }
        for skin in &self.skins {
            if skin
                .inverse_bind_matrices
                .and_then(|i| self.accessors.get(i))
                .is_some_and(readable)
            {
                skin.check_data(&self.accessors, &reader)?;
            }
        }
        crate::animation::check_data(&self.keyframes, &self.accessors, &reader, readable)?;

        // The scene: the requested one, the default one, the first, or every root node.
        let scene_index = match options.scene {
            Some(i) => Some(crate::json::check_index(
                i as u64,
                self.scenes.len(),
                "scene",
                "/scenes",
            )?),
            None => self.default_scene.or(if self.scenes.is_empty() {
                None
            } else {
                Some(0)
            }),
        };
        let (name, roots) = match scene_index.and_then(|i| self.scenes.get(i)) {
            Some((name, roots)) => (name.clone(), roots.clone()),
            None => {
                if !self.nodes.is_empty() {
                    warnings.push("no scenes: every root node is shown".to_owned());
                }
                let roots = (0..self.nodes.len())
                    .filter(|&n| self.parents.get(n).copied().flatten().is_none())
                    .collect();
                (None, roots)
            }
        };

        // What one placement of each mesh costs, from declared counts: (triangles, vertices).
        let mesh_cost: Vec<(u64, u64)> = self
            .meshes
            .iter()
            .map(|m| {
                m.primitives.iter().fold((0u64, 0u64), |(t, v), p| {
                    (
                        t.saturating_add(p.claimed_triangles(&self.accessors)),
                        v.saturating_add(p.claimed_vertices()),
                    )
                })
            })
            .collect();
        let (mut instanced_triangles, mut instanced_vertices) = (0u64, 0u64);

        // Walk the forest (already checked acyclic and within the depth limit).
        let mut placed_meshes: Vec<(usize, usize, Mat4)> = Vec::new();
        let mut cameras = Vec::new();
        let mut lights = Vec::new();
        let mut portals = Vec::new();
        let mut stack: Vec<(usize, Mat4)> =
            roots.iter().rev().map(|&n| (n, Mat4::IDENTITY)).collect();
        while let Some((n, parent_world)) = stack.pop() {
            let node = self
                .nodes
                .get(n)
                .ok_or_else(|| SceneError::invalid(format!("/nodes/{n}"), "unresolved node"))?;
            stats.nodes_visited += 1;
            let world = parent_world * node.local;
            if let Some(m) = node.mesh {
                if placed_meshes.len() >= limits.max_instances {
                    return Err(SceneError::TooLarge {
                        pointer: format!("/nodes/{n}"),
                        what: "mesh instances",
                        requested: placed_meshes.len() as u64 + 1,
                        limit: limits.max_instances as u64,
                    });
                }
                let (triangles, vertices) = mesh_cost.get(m).copied().unwrap_or_default();
                instanced_triangles = instanced_triangles.saturating_add(triangles);
                instanced_vertices = instanced_vertices.saturating_add(vertices);
                for (what, requested, limit) in [
                    (
                        "instanced triangles",
                        instanced_triangles,
                        limits.max_instanced_triangles,
                    ),
                    (
                        "instanced vertices",
                        instanced_vertices,
                        limits.max_instanced_vertices,
                    ),
                ] {
                    if requested > limit {
                        return Err(SceneError::TooLarge {
                            pointer: format!("/nodes/{n}"),
                            what,
                            requested,
                            limit,
                        });
                    }
                }
                placed_meshes.push((n, m, world));
            }
            if let Some(c) = node.camera
                && let Some((cname, projection)) = self.cameras.get(c)
            {
                cameras.push(SceneCamera {
                    node: n,
                    camera: c,
                    name: cname.clone(),
                    projection: *projection,
                    world,
                });
            }
            if let Some(l) = node.light
                && let Some(Some(light)) = self.lights.get(l)
            {
                if lights.len() >= limits.max_lights {
                    return Err(SceneError::TooLarge {
                        pointer: format!("/nodes/{n}"),
                        what: "lights",
                        requested: lights.len() as u64 + 1,
                        limit: limits.max_lights as u64,
                    });
                }
                let direction = world.transform_vector3(Vec3::NEG_Z).normalize_or_zero();
                lights.push(SceneLight {
                    node: n,
                    light_index: l,
                    light: light.clone(),
                    world,
                    position: world.transform_point3(Vec3::ZERO),
                    direction,
                });
            }
            if let Some(def) = &node.portal {
                if portals.len() >= limits.max_portals {
                    return Err(SceneError::TooLarge {
                        pointer: format!("/nodes/{n}"),
                        what: "portals",
                        requested: portals.len() as u64 + 1,
                        limit: limits.max_portals as u64,
                    });
                }
                let target_world = match def.kind {
                    PortalKind::Target(t) => Some(self.node_world(t)),
                    PortalKind::Mirror => None,
                };
                portals.push(def.place(n, node.name.clone(), world, target_world)?);
            }
            for &c in node.children.iter().rev() {
                stack.push((c, world));
            }
        }

        // Decode each used mesh once, after checking the triangle budget from declared counts.
        let used_meshes: BTreeSet<usize> = placed_meshes.iter().map(|&(_, m, _)| m).collect();
        let claimed: u64 = used_meshes
            .iter()
            .filter_map(|&m| self.meshes.get(m))
            .flat_map(|m| &m.primitives)
            .map(|p| p.claimed_triangles(&self.accessors))
            .sum();
        if claimed > limits.max_triangles {
            return Err(SceneError::TooLarge {
                pointer: "/meshes".to_owned(),
                what: "triangles",
                requested: claimed,
                limit: limits.max_triangles,
            });
        }
        let mut decoded: Vec<Option<Arc<Mesh>>> = vec![None; self.meshes.len()];
        for &m in &used_meshes {
            let Some(def) = self.meshes.get(m) else {
                continue;
            };
            let mut primitives = Vec::new();
            for p in &def.primitives {
                if !primitive_readable(p) {
                    stats.primitives_skipped_other += 1;
                    warnings.push(format!(
                        "{}: primitive skipped, its buffers have no data",
                        p.ptr
                    ));
                    continue;
                }
                match p.decode(&self.accessors, &reader)? {
                    Some(prim) => {
                        stats.primitives_loaded += 1;
                        if !prim.topology.is_triangles() {
                            stats.primitives_points_lines += 1;
                        }
                        stats.triangles += prim.triangles.len();
                        primitives.push(prim);
                    }
                    None => {
                        stats.primitives_skipped_other += 1;
                        warnings.push(format!("{}: primitive without POSITION skipped", p.ptr));
                    }
                }
            }
            if let Some(slot) = decoded.get_mut(m) {
                *slot = Some(Arc::new(Mesh {
                    index: m,
                    name: def.name.clone(),
                    primitives,
                }));
            }
        }
        stats.meshes_loaded = used_meshes.len();
        stats.meshes_unused = self.meshes.len() - used_meshes.len();
        let mut instances = Vec::with_capacity(placed_meshes.len());
        for (n, m, world) in placed_meshes {
            let Some(mesh) = decoded.get(m).cloned().flatten() else {
                continue;
            };
            let instance = MeshInstance {
                node: n,
                node_name: self.nodes.get(n).and_then(|x| x.name.clone()),
                world,
                flips_winding: world.determinant() < 0.0,
                mesh,
            };
            stats.instanced_triangles += instance.triangle_count();
            instances.push(instance);
        }

        // Images: decoded only where a used material samples them in a role the caller reads.
        // Images sampled only in other roles are checked, and an error there is a warning.
        let mut wanted: BTreeSet<(usize, bool)> = BTreeSet::new();
        let mut unread: BTreeSet<usize> = BTreeSet::new();
        for mesh in decoded.iter().flatten() {
            for p in &mesh.primitives {
                if let Some(mat) = p.material.and_then(|i| self.materials.get(i)) {
                    for (role, t, cs) in mat.texture_roles() {
                        if let Some(image) = t.image {
                            if options.image_roles.contains(role) {
                                wanted.insert((image, cs == ColorSpace::Srgb));
                            } else {
                                unread.insert(image);
                            }
                        }
                    }
                }
            }
        }
        let decoded_images = image_decode::decode_images(
            &self.images,
            &reader,
            source,
            options,
            &WantedImages { wanted, unread },
            &mut warnings,
            &mut stats,
        )?;

        Ok(Scene {
            scene_index,
            name,
            scene_count: self.scenes.len(),
            instances,
            cameras,
            document_cameras: self
                .cameras
                .into_iter()
                .map(|(name, projection)| DocumentCamera { name, projection })
                .collect(),
            lights,
            materials: self.materials,
            textures: self.textures,
            images: decoded_images.images,
            warnings,
            stats,
            decode_seconds: decoded_images.seconds,
            environment: None,
            portals,
        })
    }
}
