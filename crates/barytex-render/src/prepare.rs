//! Everything a render does before its passes: the camera, the primitives in world space, the
//! textures their materials sample (mip chains only where minified), the lights, and the
//! per-polygon or per-triangle work of flat and hybrid shading.

use std::borrow::Cow;
use std::time::Instant;

use barytex_gltf::Topology;
use barytex_gltf::material::{AlphaMode, TextureRef};
use barytex_gltf::scene::Scene;
use barytex_raster::LineTopology;
use barytex_shade::Light;
use barytex_texture::TextureError;
use barytex_texture::load::ColorSpace;
use glam::{Mat3, Vec2, Vec3, Vec4};

use crate::lights::{highlight_context, light_terms, shininess, world_lights};
use crate::material_shader::{ShaderMaterial, WorldPrimitive};
use crate::portals::{PreparedPortal, prepare_portals};
use crate::textures::{AlphaUse, PreparedTexture, Textures};
use crate::{
    CameraChoice, RenderCamera, RenderError, RenderOptions, Shading, auto_camera, scene_camera,
};

/// What an item's `indices` hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ItemKind {
    /// Index triples.
    Triangles,
    /// glTF `POINTS`: one index per point.
    Points,
    /// glTF `LINES`, `LINE_STRIP` or `LINE_LOOP`.
    Lines(LineTopology),
}

impl ItemKind {
    fn of(topology: Topology) -> Self {
        match topology {
            Topology::Points => Self::Points,
            Topology::Lines => Self::Lines(LineTopology::List),
            Topology::LineStrip => Self::Lines(LineTopology::Strip),
            Topology::LineLoop => Self::Lines(LineTopology::Loop),
            Topology::Triangles | Topology::TriangleStrip | Topology::TriangleFan => {
                Self::Triangles
            }
        }
    }
}

/// One primitive ready to draw.
pub(crate) struct DrawItem<'a> {
    pub(crate) primitive: WorldPrimitive<'a>,
    /// Triangles, points or lines, as `kind` says.
    pub(crate) kind: ItemKind,
    pub(crate) indices: Vec<u32>,
    /// Under the hybrid mode, the triangles the H-test sent to Phong shading (the rest, in
    /// `indices`, are shaded Gouraud).
    pub(crate) phong_indices: Vec<u32>,
    pub(crate) vertices: Vec<u32>,
    pub(crate) material: ShaderMaterial,
    pub(crate) double_sided: bool,
    pub(crate) flips_winding: bool,
    pub(crate) blended: bool,
    /// View-space depth of the primitive's centre (for back-to-front blending).
    pub(crate) depth: f32,
    /// Per texture-coordinate set: the most uv one pixel can cover ([`uv_per_pixel`]).
    pub(crate) uv_per_pixel: [f32; 2],
}

/// A scene ready for its passes.
pub(crate) struct Prepared<'a> {
    pub(crate) camera: RenderCamera,
    pub(crate) items: Vec<DrawItem<'a>>,
    /// Draw order: opaque and masked items in scene order, then blended ones back to front.
    pub(crate) order: Vec<usize>,
    pub(crate) textures: Textures,
    pub(crate) lights: Vec<Light>,
    pub(crate) environment: Option<PreparedTexture>,
    pub(crate) tangents_generated: usize,
    pub(crate) hybrid_phong_triangles: usize,
    pub(crate) hybrid_gouraud_triangles: usize,
    /// The scene's portals that can be drawn, and how many could not (see `Portal::check`).
    pub(crate) portals: Vec<PreparedPortal>,
    pub(crate) portals_skipped: usize,
    pub(crate) seconds: f64,
}

/// Prepares `scene` for the passes `options` ask for.
///
/// # Errors
/// A camera index beyond the scene's, a scene with nothing to frame, or a texture that cannot
/// be prepared.
pub(crate) fn prepare<'a>(
    scene: &'a Scene,
    options: &RenderOptions,
) -> Result<Prepared<'a>, RenderError> {
    let started = Instant::now();
    let (camera, mut items) = world_items(scene, options)?;
    let lit = options.shading != Shading::Unlit;
    let mut textures = Textures::default();
    let tangents_generated = prepare_textures(scene, options, &mut items, &mut textures)?;
    let order = draw_order(&items);
    let lights = world_lights(&scene.lights, &camera);
    if options.shading == Shading::Flat {
        for item in &mut items {
            if item.material.lit {
                flatten(item, &lights, camera.eye);
            }
        }
    }
    let environment = match &scene.environment {
        Some(image) if lit => crate::textures::environment(image)?,
        _ => None,
    };
    let (hybrid_phong_triangles, hybrid_gouraud_triangles) = if options.shading == Shading::Hybrid {
        split_by_highlight(&mut items, &camera, &lights)
    } else {
        (0, 0)
    };
    let (portals, portals_skipped) = prepare_portals(&scene.portals);
    Ok(Prepared {
        portals,
        portals_skipped,
        camera,
        items,
        order,
        textures,
        lights,
        environment,
        tangents_generated,
        hybrid_phong_triangles,
        hybrid_gouraud_triangles,
        seconds: started.elapsed().as_secs_f64(),
    })
}

/// The camera, and every primitive instance in world space with its material's factors.
fn world_items<'a>(
    scene: &'a Scene,
    options: &RenderOptions,
) -> Result<(RenderCamera, Vec<DrawItem<'a>>), RenderError> {
    let camera = choose_camera(scene, options)?;
    let (width, height) = (options.width, options.height);
    let view_projection = camera.projection * camera.view;
    let size = Vec2::new(width as f32, height as f32);
    let lit = options.shading != Shading::Unlit;

    // Geometry in world space, with what texture preparation needs to know about it. Every
    // instance gets its own copy, allocated fallibly: a scene may place a mesh many times.
    let item_count = scene
        .instances
        .iter()
        .fold(0usize, |n, i| n.saturating_add(i.mesh.primitives.len()));
    let mut items: Vec<DrawItem<'_>> = try_collect("primitive instances", item_count, [])?;
    for instance in &scene.instances {
        let normal_matrix = Mat3::from_mat4(instance.world).inverse().transpose();
        for primitive in &instance.mesh.primitives {
            let vertex_count = primitive.positions.len();
            let positions: Vec<Vec3> = try_collect(
                "world-space positions",
                vertex_count,
                primitive
                    .positions
                    .iter()
                    .map(|&p| instance.world.transform_point3(p)),
            )?;
            let normals = match primitive.normals.as_ref() {
                Some(n) => Some(try_collect(
                    "world-space normals",
                    n.len(),
                    n.iter().map(|&v| (normal_matrix * v).normalize_or_zero()),
                )?),
                None => None,
            };
            let clip: Vec<Vec4> = try_collect(
                "clip-space positions",
                vertex_count,
                positions.iter().map(|p| view_projection * p.extend(1.0)),
            )?;
            let kind = ItemKind::of(primitive.topology);
            let indices = if kind == ItemKind::Triangles {
                let index_count = primitive.triangles.len().saturating_mul(3);
                try_collect(
                    "triangle indices",
                    index_count,
                    primitive.triangles.iter().flatten().copied(),
                )?
            } else {
                // Points and lines: the file's index list, read by the topology when drawn.
                try_collect(
                    "point and line indices",
                    primitive.indices.len(),
                    primitive.indices.iter().copied(),
                )?
            };
            let vertex_ids = try_collect(
                "vertex indices",
                vertex_count,
                0..u32::try_from(vertex_count).unwrap_or(u32::MAX),
            )?;
            let uv0 = primitive.tex_coords0.as_deref();
            let uv1 = primitive.tex_coords1.as_deref();
            let material = scene.material(primitive.material);
            let centre = positions.iter().copied().sum::<Vec3>() / positions.len().max(1) as f32;
            items.push(DrawItem {
                uv_per_pixel: uv_per_pixel(&clip, [uv0, uv1], &primitive.triangles, size),
                kind,
                indices,
                phong_indices: Vec::new(),
                vertices: vertex_ids,
                primitive: WorldPrimitive {
                    positions,
                    normals,
                    uv0: uv0.map(std::borrow::Cow::Borrowed),
                    uv1: uv1.map(std::borrow::Cow::Borrowed),
                    colors: primitive.colors0.as_deref().map(std::borrow::Cow::Borrowed),
                    lighting: None,
                    tangents: None,
                },
                material: ShaderMaterial {
                    base_color: material.base_color_factor,
                    base_texture: None,
                    emissive: material.emissive_factor,
                    emissive_texture: None,
                    occlusion_texture: None,
                    occlusion_strength: material.occlusion_strength,
                    metallic_roughness_texture: None,
                    normal_texture: None,
                    normal_scale: material.normal_scale,
                    metallic: material.metallic_factor.clamp(0.0, 1.0),
                    roughness: material.roughness_factor.clamp(0.0, 1.0),
                    alpha_mode: material.alpha_mode,
                    // Points and lines have no surface to light: base colour factor × vertex
                    // colour (× base texture), as glTF's unlit model.
                    lit: lit && !material.unlit && kind == ItemKind::Triangles,
                },
                double_sided: material.double_sided,
                flips_winding: instance.flips_winding,
                blended: material.alpha_mode == AlphaMode::Blend,
                depth: (camera.view * centre.extend(1.0)).z,
            });
        }
    }
    Ok((camera, items))
}

/// Collects `items` (`len` of them) into a vector allocated fallibly: a refused allocation is
/// [`RenderError::OutOfMemory`] naming `what`, not an abort.
fn try_collect<T>(
    what: &'static str,
    len: usize,
    items: impl IntoIterator<Item = T>,
) -> Result<Vec<T>, RenderError> {
    let mut out = Vec::new();
    out.try_reserve_exact(len)
        .map_err(|_| RenderError::OutOfMemory { what, count: len })?;
    out.extend(items);
    Ok(out)
}

/// Prepares the textures the items' materials sample (only those; mips only where minified),
/// and the world-space tangents of normal-mapped items. Returns how many primitives had their
/// tangents generated.
fn prepare_textures(
    scene: &Scene,
    options: &RenderOptions,
    items: &mut [DrawItem<'_>],
    textures: &mut Textures,
) -> Result<usize, RenderError> {
    let lit = options.shading != Shading::Unlit;
    let item_materials: Vec<Option<usize>> = scene
        .instances
        .iter()
        .flat_map(|i| i.mesh.primitives.iter().map(|p| p.material))
        .collect();
    // The images each item's material samples, looked up once (the probe below runs per
    // texture over every item).
    let item_images: Vec<Vec<Option<usize>>> = item_materials
        .iter()
        .map(|&m| {
            let refs = scene.material(m).texture_refs();
            refs.iter().map(|(t, _)| t.image).collect()
        })
        .collect();
    // Texels per pixel, at most: the uv stretch per pixel times the largest stretch of
    // uv → texels (the texture's size after its KHR_texture_transform).
    // Through a portal a surface can be farther than the camera sees it: with portals to
    // draw, every texture whose filter reads mip levels gets its chain.
    let has_portals = scene.portals.iter().any(|p| p.check().is_ok());
    let minification = |r: &TextureRef, (w, h): (u32, u32)| -> f32 {
        if has_portals {
            return f32::INFINITY;
        }
        let m = r.mapping.transform;
        let (w, h) = (w as f32, h as f32);
        let texels = largest_stretch([
            Vec2::new(m.x_axis.x * w, m.y_axis.x * w),
            Vec2::new(m.x_axis.y * h, m.y_axis.y * h),
        ]);
        items
            .iter()
            .zip(&item_images)
            .filter(|(_, images)| images.contains(&r.image))
            .map(|(item, _)| item.uv_per_pixel[(r.mapping.set as usize).min(1)] * texels)
            .fold(0.0, f32::max)
    };
    let mut slots = Vec::with_capacity(items.len());
    for material in &item_materials {
        let m = scene.material(*material);
        // Only TEXCOORD_0 and _1 are decoded: refuse rather than sample another set.
        if let Some((r, _)) = m
            .texture_refs()
            .into_iter()
            .find(|(r, _)| r.mapping.set > 1)
        {
            return Err(RenderError::Unsupported {
                material: *material,
                what: format!("TEXCOORD_{}", r.mapping.set),
            });
        }
        let mut slot = |r: &Option<TextureRef>, space, alpha| -> Result<_, TextureError> {
            match r {
                Some(r) => textures.slot(scene, r, space, alpha, options.filter, &minification),
                None => Ok(None),
            }
        };
        // OPAQUE ignores the base colour's alpha; no material reads the others' alpha.
        let base_alpha = if m.alpha_mode == AlphaMode::Opaque {
            AlphaUse::Ignored
        } else {
            AlphaUse::Coverage
        };
        let base = slot(&m.base_color_texture, ColorSpace::Srgb, base_alpha)?;
        let (emissive, occlusion, metallic_roughness) = if lit && !m.unlit {
            (
                slot(&m.emissive_texture, ColorSpace::Srgb, AlphaUse::Ignored)?,
                slot(&m.occlusion_texture, ColorSpace::Linear, AlphaUse::Ignored)?,
                slot(
                    &m.metallic_roughness_texture,
                    ColorSpace::Linear,
                    AlphaUse::Ignored,
                )?,
            )
        } else {
            (None, None, None)
        };
        // Normal maps only under per-pixel shading, where they can show.
        let per_pixel = matches!(options.shading, Shading::Phong | Shading::Hybrid);
        let normal = if lit && !m.unlit && per_pixel {
            slot(&m.normal_texture, ColorSpace::Linear, AlphaUse::Ignored)?
        } else {
            None
        };
        slots.push((base, emissive, occlusion, metallic_roughness, normal));
    }
    let mut tangents_generated = 0;
    let primitives = scene
        .instances
        .iter()
        .flat_map(|i| i.mesh.primitives.iter().map(move |p| (i, p)));
    for ((item, (base, emissive, occlusion, metallic_roughness, normal)), (instance, primitive)) in
        items.iter_mut().zip(slots).zip(primitives)
    {
        item.material.base_texture = base;
        item.material.emissive_texture = emissive;
        item.material.occlusion_texture = occlusion;
        item.material.metallic_roughness_texture = metallic_roughness;
        // Points and lines are unlit: no normal map, no tangents.
        let normal = normal.filter(|_| item.kind == ItemKind::Triangles);
        item.material.normal_texture = normal;
        if let Some(slot) = normal {
            let (tangents, generated) = world_tangents(instance, primitive, slot.mapping.set);
            tangents_generated += usize::from(generated);
            item.primitive.tangents = tangents;
        }
    }
    Ok(tangents_generated)
}

/// Opaque and masked items first, in scene order; blended ones after, back to front.
fn draw_order(items: &[DrawItem<'_>]) -> Vec<usize> {
    let (mut order, mut blended): (Vec<usize>, Vec<usize>) =
        (0..items.len()).partition(|&i| !items[i].blended);
    blended.sort_by(|&a, &b| items[a].depth.total_cmp(&items[b].depth));
    order.extend(blended);
    order
}

/// Hybrid shading: runs the highlight test on every lit triangle with normals and moves those
/// with a visible highlight to the items' Phong index lists. Returns the (Phong, Gouraud)
/// triangle counts.
fn split_by_highlight(
    items: &mut [DrawItem<'_>],
    camera: &RenderCamera,
    lights: &[Light],
) -> (usize, usize) {
    let (mut hybrid_phong, mut hybrid_gouraud) = (0, 0);
    for item in items.iter_mut() {
        if !item.material.lit || item.primitive.normals.is_none() {
            continue;
        }
        let m = &item.material;
        let f0 = Vec3::splat(0.04).lerp(m.base_color.truncate(), m.metallic);
        let test = highlight_context(camera, lights, f0, m.roughness);
        let (mut phong, mut gouraud) = (Vec::new(), Vec::new());
        for t in item.indices.chunks_exact(3) {
            let p = [t[0], t[1], t[2]].map(|i| {
                item.primitive
                    .positions
                    .get(i as usize)
                    .copied()
                    .unwrap_or(Vec3::NAN)
            });
            let n = [t[0], t[1], t[2]].map(|i| {
                item.primitive
                    .normals
                    .as_ref()
                    .and_then(|n| n.get(i as usize))
                    .copied()
                    .unwrap_or_default()
            });
            let verdict = barytex_shade::HighlightTest::default().run(&test, p, n);
            if verdict.has_highlight() {
                phong.extend_from_slice(t);
            } else {
                gouraud.extend_from_slice(t);
            }
        }
        hybrid_phong += phong.len() / 3;
        hybrid_gouraud += gouraud.len() / 3;
        item.indices = gouraud;
        item.phong_indices = phong;
    }
    (hybrid_phong, hybrid_gouraud)
}

/// The camera a render of `scene` with `options` looks through ([`RenderOptions::camera`] at
/// the aspect of [`RenderOptions::width`] / [`RenderOptions::height`]), or why there is none:
/// what [`render`](crate::render) does first, for callers that check before they start.
///
/// # Errors
/// [`RenderError::NoSuchCamera`], [`RenderError::CameraNotPlaced`] and
/// [`RenderError::SingularCamera`] for a [`CameraChoice::Index`];
/// [`RenderError::NothingToFrame`] where the automatic camera has nothing to look at.
pub fn choose_camera(scene: &Scene, options: &RenderOptions) -> Result<RenderCamera, RenderError> {
    let aspect = options.width as f32 / options.height as f32;
    match options.camera {
        CameraChoice::Index(index) => {
            let Some(placed) = scene.cameras.iter().find(|c| c.camera == index) else {
                return Err(match scene.document_cameras.get(index) {
                    Some(camera) => RenderError::CameraNotPlaced {
                        index,
                        name: camera.name.clone(),
                        scene: scene.scene_index,
                    },
                    None => RenderError::NoSuchCamera {
                        index,
                        count: scene.document_cameras.len(),
                    },
                });
            };
            scene_camera(scene, index, aspect).ok_or(RenderError::SingularCamera {
                index,
                node: placed.node,
            })
        }
        CameraChoice::First => match scene.cameras.first() {
            Some(first) => scene_camera(scene, first.camera, aspect)
                .or_else(|| auto_camera(scene, aspect))
                .ok_or(RenderError::NothingToFrame),
            None => auto_camera(scene, aspect).ok_or(RenderError::NothingToFrame),
        },
        CameraChoice::Auto => auto_camera(scene, aspect).ok_or(RenderError::NothingToFrame),
    }
}

/// The largest singular value of a 2 × 2 matrix given by its rows: how far it stretches any
/// unit vector.
fn largest_stretch(rows: [Vec2; 2]) -> f32 {
    let [a, b] = rows;
    let sum = a.length_squared() + b.length_squared();
    let det = a.perp_dot(b);
    let root = (sum * sum - 4.0 * det * det).max(0.0).sqrt();
    ((sum + root) * 0.5).sqrt()
}

/// How much texture space one pixel can cover, per texture coordinate set: the largest stretch
/// of the screen → uv Jacobian (uv units per pixel along the worst direction, so anisotropic
/// minification counts), evaluated exactly under perspective at every vertex — the Jacobian's
/// extremes over a triangle are at its corners, where the far one minifies most — and maximised
/// over the triangles. Conservative: a triangle crossing the eye plane (a floor running under
/// the camera) counts as infinitely minified, since its visible part cannot be bounded here.
///
/// With screen positions `sᵢ`, screen-space barycentric gradients `∇bᵢ` and clip `wᵢ`, the
/// perspective-correct `uv = (Σ bᵢ uvᵢ/wᵢ) / (Σ bᵢ/wᵢ)` has at vertex `i` the Jacobian
/// `wᵢ (Q − uvᵢ Rᵀ)` with `Q = Σ uvⱼ/wⱼ ∇bⱼᵀ`, `R = Σ ∇bⱼ/wⱼ` (the quotient rule).
fn uv_per_pixel(
    clip: &[Vec4],
    uvs: [Option<&[Vec2]>; 2],
    triangles: &[[u32; 3]],
    size: Vec2,
) -> [f32; 2] {
    let mut out = [0.0_f32; 2];
    for t in triangles {
        let c = t.map(|i| clip.get(i as usize).copied().unwrap_or(Vec4::NAN));
        if c.iter().any(|p| !p.is_finite()) || c.iter().all(|p| p.w <= 0.0) {
            continue;
        }
        if c.iter().any(|p| p.w <= 0.0) {
            for (k, set) in uvs.iter().enumerate() {
                if set.is_some() {
                    out[k] = f32::INFINITY;
                }
            }
            continue;
        }
        let s = c.map(|p| Vec2::new(p.x / p.w, p.y / p.w) * size * 0.5);
        let twice_area = (s[1] - s[0]).perp_dot(s[2] - s[0]);
        if twice_area.abs() < 1e-6 {
            continue;
        }
        let gradient = |i: usize| {
            let (a, b) = (s[(i + 1) % 3], s[(i + 2) % 3]);
            Vec2::new(a.y - b.y, b.x - a.x) / twice_area
        };
        let grad = [gradient(0), gradient(1), gradient(2)];
        let inv_w = c.map(|p| 1.0 / p.w);
        let r = grad[0] * inv_w[0] + grad[1] * inv_w[1] + grad[2] * inv_w[2];
        for (k, set) in uvs.iter().enumerate() {
            let Some(uv) = set else { continue };
            let u = t.map(|i| uv.get(i as usize).copied().unwrap_or(Vec2::ZERO));
            let q_u = (0..3).map(|j| grad[j] * (u[j].x * inv_w[j])).sum::<Vec2>();
            let q_v = (0..3).map(|j| grad[j] * (u[j].y * inv_w[j])).sum::<Vec2>();
            for i in 0..3 {
                let w = c[i].w;
                let stretch = largest_stretch([(q_u - u[i].x * r) * w, (q_v - u[i].y * r) * w]);
                if stretch.is_finite() {
                    out[k] = out[k].max(stretch);
                } else {
                    out[k] = f32::INFINITY;
                }
            }
        }
    }
    out
}

/// World-space tangents of a normal-mapped primitive: the file's, else MikkTSpace's (generated
/// from the positions, normals and the normal map's texture coordinates), the bitangent sign
/// flipped under a mirroring world matrix. The flag says whether they were generated.
fn world_tangents(
    instance: &barytex_gltf::scene::MeshInstance,
    primitive: &barytex_gltf::mesh::Primitive,
    tex_coord: u32,
) -> (Option<Vec<Vec4>>, bool) {
    let mut generated = false;
    let object = primitive.tangents.clone().or_else(|| {
        let uvs = if tex_coord == 1 {
            primitive.tex_coords1.as_ref()
        } else {
            primitive.tex_coords0.as_ref()
        }?;
        let mesh = barytex_uv::mesh::TriMesh {
            positions: primitive.positions.clone(),
            normals: primitive.normals.clone()?,
            tangents: Vec::new(),
            uvs: uvs.clone(),
            indices: primitive.triangles.clone(),
        };
        generated = true;
        barytex_shade::generate_tangents(&mesh)
    });
    let linear = Mat3::from_mat4(instance.world);
    let sign = if instance.flips_winding { -1.0 } else { 1.0 };
    let world = object.map(|t| {
        t.iter()
            .map(|v| {
                (linear * v.truncate())
                    .normalize_or_zero()
                    .extend(v.w * sign)
            })
            .collect()
    });
    (world, generated && primitive.tangents.is_none())
}

/// Flat shading, one evaluation per polygon: unwelds the primitive (three vertices per
/// triangle) and gives each triangle's vertices the light at its centroid under its face
/// normal (turned towards the eye), so the shader interpolates a constant.
fn flatten(item: &mut DrawItem<'_>, lights: &[Light], eye: Vec3) {
    let p = &item.primitive;
    let corner = |k: u32| k as usize;
    let pick2 = |v: &Option<Cow<'_, [Vec2]>>| {
        v.as_ref().map(|v| {
            Cow::Owned(
                item.indices
                    .iter()
                    .map(|&k| v.get(corner(k)).copied().unwrap_or_default())
                    .collect(),
            )
        })
    };
    let uv0 = pick2(&p.uv0);
    let uv1 = pick2(&p.uv1);
    let colors = p.colors.as_ref().map(|v| {
        Cow::Owned(
            item.indices
                .iter()
                .map(|&k| v.get(corner(k)).copied().unwrap_or(Vec4::ONE))
                .collect(),
        )
    });
    let positions: Vec<Vec3> = item
        .indices
        .iter()
        .map(|&k| p.positions.get(corner(k)).copied().unwrap_or(Vec3::NAN))
        .collect();
    let shininess = shininess(item.material.roughness);
    let mut lighting = Vec::with_capacity(positions.len());
    for t in positions.chunks_exact(3) {
        let centroid = (t[0] + t[1] + t[2]) / 3.0;
        let view = (eye - centroid).normalize_or_zero();
        let mut n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
        if n.dot(view) < 0.0 {
            n = -n;
        }
        let terms = light_terms(lights, n, view, centroid, shininess);
        lighting.extend([terms; 3]);
    }
    let count = positions.len() as u32;
    item.primitive = WorldPrimitive {
        positions,
        normals: None,
        uv0,
        uv1,
        colors,
        lighting: Some(lighting),
        tangents: None,
    };
    item.indices = (0..count).collect();
    item.vertices = (0..count).collect();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn world_copies_that_cannot_be_allocated_are_errors() {
        // 2⁵⁶ positions are 864 PB: the allocator refuses (a `collect` would abort the
        // process); a count whose bytes overflow is refused as well (a `collect` would panic).
        for count in [1usize << 56, usize::MAX] {
            let r = try_collect::<Vec3>("world-space positions", count, std::iter::empty());
            assert_eq!(
                r.err(),
                Some(RenderError::OutOfMemory {
                    what: "world-space positions",
                    count
                })
            );
        }
        let error = RenderError::OutOfMemory {
            what: "triangle indices",
            count: 7,
        };
        assert_eq!(
            error.to_string(),
            "out of memory allocating 7 triangle indices"
        );
        // What fits is collected as given.
        let r = try_collect("vertex indices", 3, 0..3u32);
        assert_eq!(r.ok(), Some(vec![0, 1, 2]));
    }
}
