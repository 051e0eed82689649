//! The reference renderer: a flattened [`Scene`] (loaded by barytex-gltf, or
//! the built-in [`demo`] scene) drawn by barytex-raster with barytex-texture's
//! filters — cameras (the scene's or the automatic one), glTF materials (base colour, vertex
//! colours, alpha modes, emission, occlusion, unlit), punctual lights with Blinn–Phong, and
//! every anti-aliasing mode of the rasterizer.
//!
//! It models only what the image needs: textures are prepared only for materials the scene
//! draws, mip chains are built only for textures that end up minified on screen, and the
//! statistics say what was skipped.
//!
//! ```
//! use barytex_render::{render, RenderOptions};
//! use barytex_gltf::{load_slice, LoadOptions};
//!
//! let gltf = r#"{
//!   "asset": {"version": "2.0"},
//!   "buffers": [{"byteLength": 36, "uri":
//!     "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
//!   "bufferViews": [{"buffer": 0, "byteLength": 36}],
//!   "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
//!                  "min": [0, 0, 0], "max": [1, 1, 0]}],
//!   "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
//!   "nodes": [{"mesh": 0}],
//!   "scenes": [{"nodes": [0]}]
//! }"#;
//! let scene = load_slice(gltf.as_bytes(), &LoadOptions::default())?;
//! let out = render(&scene, &RenderOptions { width: 64, height: 48, ..RenderOptions::default() })?;
//! assert!(out.stats.draw.fragments_shaded > 0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod demo;
mod framing;
mod material_shader;
mod options;
mod raster_only;
mod surface;
mod textures;

use std::fmt;
use std::time::Instant;

use barytex_raster::{
    AdaptiveOptions, AdaptiveStats, Blend, CullMode, DrawStats, Framebuffer, FrontFace,
    PipelineState, RasterError, SamplePattern, TargetLimits, Viewport, draw, render_adaptive,
    render_supersampled,
};
use barytex_texture::TextureError;
use barytex_texture::load::ColorSpace;
use glam::{Mat3, Vec2, Vec3, Vec4};

pub use framing::{CameraSource, RenderCamera, auto_camera, scene_bounds, scene_camera};
pub use options::{AntiAliasing, CameraChoice, Filter, RenderOptions, Shading};

use barytex_gltf::light::LightKind;
use barytex_gltf::material::{AlphaMode, TextureRef};
use barytex_gltf::scene::Scene;
use material_shader::{Frequency, MaterialShader, ShaderMaterial, WorldLight, WorldPrimitive};
use raster_only::RasterOnly;
use surface::Reads;
use textures::Textures;

/// Why a scene could not be rendered.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum RenderError {
    /// The scene has no finite vertex to look at (and no camera was given).
    NothingToFrame,
    /// `--camera N` beyond the scene's cameras.
    NoSuchCamera {
        /// The index asked for.
        index: usize,
        /// Cameras in the scene.
        count: usize,
    },
    /// A parameter out of range (size, sample count).
    InvalidOption(String),
    /// A texture could not be allocated or built.
    Texture(TextureError),
    /// The target could not be made: an invalid sample count, a size over the limits, a failed
    /// allocation.
    Raster(RasterError),
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NothingToFrame => write!(f, "the scene has no finite vertex to frame"),
            Self::NoSuchCamera { index, count } => {
                write!(f, "camera {index} asked for, the scene has {count}")
            }
            Self::InvalidOption(why) => write!(f, "invalid render option: {why}"),
            Self::Texture(e) => write!(f, "{e}"),
            Self::Raster(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for RenderError {}

impl From<TextureError> for RenderError {
    fn from(e: TextureError) -> Self {
        Self::Texture(e)
    }
}

impl From<RasterError> for RenderError {
    fn from(e: RasterError) -> Self {
        Self::Raster(e)
    }
}

/// What a render did and how long each stage took.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RenderStats {
    /// Primitives drawn (opaque and masked first, then blended back to front).
    pub primitives: usize,
    /// Triangles submitted per pass.
    pub triangles: usize,
    /// Fragment and triangle counts, summed over passes.
    pub draw: DrawStats,
    /// Passes over the scene (more than one for accumulated and adaptive supersampling).
    pub passes: u32,
    /// Mean samples per pixel.
    pub samples_per_pixel: f64,
    /// The adaptive sampler's statistics, when it ran.
    pub adaptive: Option<AdaptiveStats>,
    /// Textures prepared (image × colour space × filter).
    pub textures: usize,
    /// Mip chains built.
    pub mip_chains: usize,
    /// Textures whose filter uses mipmaps but which are never minified (no chain built).
    pub mips_skipped: usize,
    /// Primitives whose tangents were generated (MikkTSpace) for a normal map.
    pub tangents_generated: usize,
    /// Hybrid shading: triangles the highlight test sent to Phong shading, and the rest
    /// (Gouraud).
    pub hybrid_phong_triangles: usize,
    /// Hybrid shading: triangles shaded Gouraud.
    pub hybrid_gouraud_triangles: usize,
    /// Varying floats interpolated per fragment, summed over the draws (a primitive split by
    /// hybrid shading counts twice): only what each material reads at its shading frequency.
    pub varyings_interpolated: usize,
    /// Varying floats not interpolated because the material never reads them, summed likewise
    /// (the full varying is 24 floats: position, normal, two uv sets, colour, Gouraud's vertex
    /// light, tangent).
    pub varyings_skipped: usize,
    /// Seconds preparing geometry, textures and mip chains.
    pub prepare_seconds: f64,
    /// Of `prepare_seconds`, those preparing mipmapped textures (level 0's copy and its chain).
    pub mip_seconds: f64,
    /// Seconds rasterizing and shading (the two are interleaved per pixel).
    pub draw_seconds: f64,
    /// With [`RenderOptions::measure_stages`]: seconds the same passes took with a fragment
    /// shader that returns a constant (vertex stage, clipping, coverage, depth test,
    /// interpolation of the varyings, writes). `draw_seconds` minus this is the shading's cost.
    /// Alpha-masked fragments are not discarded in that pass, so it may do slightly more work.
    pub raster_seconds: Option<f64>,
}

/// A rendered image with its camera and statistics.
#[derive(Clone, Debug)]
pub struct Rendered {
    /// The image (linear light; `to_srgba8` encodes it).
    pub image: Framebuffer,
    /// The camera used.
    pub camera: RenderCamera,
    /// What happened.
    pub stats: RenderStats,
}

/// One primitive ready to draw.
struct DrawItem<'a> {
    primitive: WorldPrimitive<'a>,
    indices: Vec<u32>,
    /// Under the hybrid mode, the triangles the H-test sent to Phong shading (the rest, in
    /// `indices`, are shaded Gouraud).
    phong_indices: Vec<u32>,
    vertices: Vec<u32>,
    material: ShaderMaterial,
    double_sided: bool,
    flips_winding: bool,
    blended: bool,
    /// View-space depth of the primitive's centre (for back-to-front blending).
    depth: f32,
    /// Per texture-coordinate set: the largest √(uv area / screen area) of its triangles.
    uv_per_pixel: [f32; 2],
}

/// The camera for `options`.
fn choose_camera(scene: &Scene, options: &RenderOptions) -> Result<RenderCamera, RenderError> {
    let aspect = options.width as f32 / options.height as f32;
    match options.camera {
        CameraChoice::Index(index) => {
            scene_camera(scene, index, aspect).ok_or(RenderError::NoSuchCamera {
                index,
                count: scene.cameras.len(),
            })
        }
        CameraChoice::First if !scene.cameras.is_empty() => scene_camera(scene, 0, aspect)
            .or_else(|| auto_camera(scene, aspect))
            .ok_or(RenderError::NothingToFrame),
        _ => auto_camera(scene, aspect).ok_or(RenderError::NothingToFrame),
    }
}

/// √(uv area / screen area) maximised over the triangles, per texture-coordinate set.
fn uv_per_pixel(
    clip: &[Vec4],
    uvs: [Option<&[Vec2]>; 2],
    triangles: &[[u32; 3]],
    size: Vec2,
) -> [f32; 2] {
    let mut out = [0.0_f32; 2];
    for t in triangles {
        let c = t.map(|i| clip.get(i as usize).copied().unwrap_or(Vec4::NAN));
        if c.iter().any(|p| !p.is_finite() || p.w <= 0.0) {
            continue;
        }
        let s = c.map(|p| Vec2::new(p.x / p.w, p.y / p.w) * size * 0.5);
        let screen = (s[1] - s[0]).perp_dot(s[2] - s[0]).abs() * 0.5;
        if screen < 1e-6 {
            continue;
        }
        for (k, set) in uvs.iter().enumerate() {
            if let Some(uv) = set {
                let u = t.map(|i| uv.get(i as usize).copied().unwrap_or(Vec2::ZERO));
                let area = (u[1] - u[0]).perp_dot(u[2] - u[0]).abs() * 0.5;
                out[k] = out[k].max((area / screen).sqrt());
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
fn flatten(item: &mut DrawItem<'_>, lights: &[WorldLight], eye: Vec3) {
    use std::borrow::Cow;
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
    let shininess = material_shader::shininess(item.material.roughness);
    let mut lighting = Vec::with_capacity(positions.len());
    for t in positions.chunks_exact(3) {
        let centroid = (t[0] + t[1] + t[2]) / 3.0;
        let view = (eye - centroid).normalize_or_zero();
        let mut n = (t[1] - t[0]).cross(t[2] - t[0]).normalize_or_zero();
        if n.dot(view) < 0.0 {
            n = -n;
        }
        let terms = material_shader::light_terms(lights, n, view, centroid, shininess);
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

/// The H-test's view of one material under the render's camera and lights: the same
/// normalized Blinn–Phong lobe the shader evaluates, as a `barytex_shade` scene.
fn highlight_scene(
    camera: &RenderCamera,
    lights: &[WorldLight],
    m: &ShaderMaterial,
) -> barytex_shade::ShadeContext {
    let shininess = material_shader::shininess(m.roughness);
    let base = m.base_color.truncate();
    let specular = Vec3::splat(0.04).lerp(base, m.metallic)
        * ((shininess + 8.0) / (8.0 * std::f32::consts::PI));
    let lights = lights
        .iter()
        .map(|l| match l.kind {
            LightKind::Directional => barytex_shade::Light::Directional {
                direction: l.direction,
                color: l.radiance,
            },
            LightKind::Point => barytex_shade::Light::Point {
                position: l.position,
                color: l.radiance,
                attenuation: barytex_shade::Attenuation::INVERSE_SQUARE,
            },
            LightKind::Spot {
                inner_cone_angle,
                outer_cone_angle,
            } => barytex_shade::Light::Spot {
                position: l.position,
                direction: l.direction,
                color: l.radiance,
                attenuation: barytex_shade::Attenuation::INVERSE_SQUARE,
                shape: barytex_shade::SpotShape::Cone {
                    inner: inner_cone_angle,
                    outer: outer_cone_angle,
                },
            },
        })
        .collect();
    barytex_shade::ShadeContext {
        camera: barytex_shade::Camera {
            eye: camera.eye,
            view: camera.view,
            projection: camera.projection,
        },
        lights,
        ambient: Vec3::ZERO,
        material: barytex_shade::PhongMaterial {
            emission: Vec3::ZERO,
            ambient: Vec3::ZERO,
            diffuse: Vec3::ZERO,
            specular,
            shininess,
            lobe: barytex_shade::Specular::BlinnPhong,
        },
        view: barytex_shade::ViewVector::Local,
    }
}

/// Renders `scene` as `options` ask.
///
/// # Errors
/// A zero or oversized image, an invalid sample count, a camera index beyond the scene's, a
/// scene with nothing to frame, or a texture that cannot be prepared.
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<Rendered, RenderError> {
    render_with_progress(scene, options, &mut |_, _| {})
}

/// The passes over the scene `anti_aliasing` plans: `n²` for accumulated supersampling (`n > 5`),
/// at most `max(n, 4)` for adaptive sampling (it stops when every pixel has converged), else 1.
#[must_use]
pub fn planned_passes(anti_aliasing: AntiAliasing) -> u32 {
    match anti_aliasing {
        AntiAliasing::Supersample(n) | AntiAliasing::Jitter(n) if (6..=16).contains(&n) => n * n,
        AntiAliasing::Adaptive(max) => max.max(4),
        _ => 1,
    }
}

/// [`render`], calling `on_pass(done, planned)` after each pass over the scene, with the
/// [`planned_passes`] (for a progress bar; adaptive sampling may finish before `planned`).
///
/// # Errors
/// As [`render`].
#[allow(clippy::too_many_lines)]
pub fn render_with_progress(
    scene: &Scene,
    options: &RenderOptions,
    on_pass: &mut dyn FnMut(u32, u32),
) -> Result<Rendered, RenderError> {
    let started = Instant::now();
    let (width, height) = (options.width, options.height);
    if width == 0 || height == 0 || width > 16_384 || height > 16_384 {
        return Err(RenderError::InvalidOption(format!(
            "image size {width}×{height} (each side 1 to 16384)"
        )));
    }
    let camera = choose_camera(scene, options)?;
    let view_projection = camera.projection * camera.view;
    let size = Vec2::new(width as f32, height as f32);
    let lit = options.shading != Shading::Unlit;

    // Geometry in world space, with what texture preparation needs to know about it.
    let mut items: Vec<DrawItem<'_>> = Vec::new();
    for instance in &scene.instances {
        let normal_matrix = Mat3::from_mat4(instance.world).inverse().transpose();
        for primitive in &instance.mesh.primitives {
            let positions: Vec<Vec3> = primitive
                .positions
                .iter()
                .map(|&p| instance.world.transform_point3(p))
                .collect();
            let normals = primitive.normals.as_ref().map(|n| {
                n.iter()
                    .map(|&v| (normal_matrix * v).normalize_or_zero())
                    .collect()
            });
            let clip: Vec<Vec4> = positions
                .iter()
                .map(|p| view_projection * p.extend(1.0))
                .collect();
            let uv0 = primitive.tex_coords0.as_deref();
            let uv1 = primitive.tex_coords1.as_deref();
            let material = scene.material(primitive.material);
            let centre = positions.iter().copied().sum::<Vec3>() / positions.len().max(1) as f32;
            items.push(DrawItem {
                uv_per_pixel: uv_per_pixel(&clip, [uv0, uv1], &primitive.triangles, size),
                indices: primitive.triangles.iter().flatten().copied().collect(),
                phong_indices: Vec::new(),
                vertices: (0..positions.len() as u32).collect(),
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
                    lit: lit && !material.unlit,
                },
                double_sided: material.double_sided,
                flips_winding: instance.flips_winding,
                blended: material.alpha_mode == AlphaMode::Blend,
                depth: (camera.view * centre.extend(1.0)).z,
            });
        }
    }
    // Textures: only those the drawn materials sample; mips only where minified.
    let mut textures = Textures::default();
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
    let minification = |r: &TextureRef, (w, h): (u32, u32)| -> f32 {
        let det = r
            .transform
            .x_axis
            .truncate()
            .perp_dot(r.transform.y_axis.truncate())
            .abs();
        let texels = (w as f32 * h as f32 * det).sqrt();
        items
            .iter()
            .zip(&item_images)
            .filter(|(_, images)| images.contains(&r.image))
            .map(|(item, _)| item.uv_per_pixel[(r.tex_coord as usize).min(1)] * texels)
            .fold(0.0, f32::max)
    };
    let mut slots = Vec::with_capacity(items.len());
    for material in &item_materials {
        let m = scene.material(*material);
        let mut slot = |r: &Option<TextureRef>, space| -> Result<_, TextureError> {
            match r {
                Some(r) => textures.slot(
                    scene,
                    r,
                    space,
                    options.filter.apply(r.sampler.to_descriptor()),
                    &minification,
                ),
                None => Ok(None),
            }
        };
        let base = slot(&m.base_color_texture, ColorSpace::Srgb)?;
        let (emissive, occlusion, metallic_roughness) = if lit && !m.unlit {
            (
                slot(&m.emissive_texture, ColorSpace::Srgb)?,
                slot(&m.occlusion_texture, ColorSpace::Linear)?,
                slot(&m.metallic_roughness_texture, ColorSpace::Linear)?,
            )
        } else {
            (None, None, None)
        };
        // Normal maps only under per-pixel shading, where they can show.
        let per_pixel = matches!(options.shading, Shading::Phong | Shading::Hybrid);
        let normal = if lit && !m.unlit && per_pixel {
            slot(&m.normal_texture, ColorSpace::Linear)?
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
        item.material.normal_texture = normal;
        if let Some(slot) = normal {
            let (tangents, generated) = world_tangents(instance, primitive, slot.tex_coord);
            tangents_generated += usize::from(generated);
            item.primitive.tangents = tangents;
        }
    }
    // Opaque and masked first, in scene order; blended after, back to front.
    let (mut order, mut blended): (Vec<usize>, Vec<usize>) =
        (0..items.len()).partition(|&i| !items[i].blended);
    blended.sort_by(|&a, &b| items[a].depth.total_cmp(&items[b].depth));
    order.extend(blended);
    // Lights in world space; a headlight when the scene has none.
    let forward = camera
        .view
        .inverse()
        .transform_vector3(Vec3::NEG_Z)
        .normalize_or_zero();
    let mut lights: Vec<WorldLight> = scene
        .lights
        .iter()
        .map(|l| WorldLight {
            kind: l.light.kind,
            radiance: l.light.color * l.light.intensity,
            position: l.position,
            direction: l.direction.normalize_or_zero(),
            range: l.light.range,
        })
        .collect();
    if lights.is_empty() {
        lights.push(WorldLight {
            kind: LightKind::Directional,
            radiance: Vec3::splat(std::f32::consts::PI),
            position: camera.eye,
            direction: forward,
            range: None,
        });
    }
    if options.shading == Shading::Flat {
        for item in &mut items {
            if item.material.lit {
                flatten(item, &lights, camera.eye);
            }
        }
    }
    let environment = match &scene.environment {
        Some(image) if lit => textures::environment(image)?,
        _ => None,
    };
    let (mut hybrid_phong, mut hybrid_gouraud) = (0, 0);
    if options.shading == Shading::Hybrid {
        for item in &mut items {
            if !item.material.lit || item.primitive.normals.is_none() {
                continue;
            }
            let test = highlight_scene(&camera, &lights, &item.material);
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
    }
    let prepare_seconds = started.elapsed().as_secs_f64();

    // The passes.
    let sample_shading = matches!(
        options.anti_aliasing,
        AntiAliasing::Supersample(_) | AntiAliasing::Jitter(_)
    );
    let frequency = match options.shading {
        Shading::Flat => Frequency::Flat,
        Shading::Gouraud | Shading::Hybrid => Frequency::Gouraud,
        Shading::Unlit | Shading::Phong => Frequency::Phong,
    };
    let items = &items;
    let shader_for = |i: usize, frequency| MaterialShader {
        frequency,
        environment: environment.as_ref(),
        fog: options.fog.map(|f| (f, forward)),
        view_projection,
        eye: camera.eye,
        primitive: &items[i].primitive,
        material: items[i].material,
        textures: &textures.list,
        lights: &lights,
        ambient: Vec3::splat(0.03),
    };
    // The varying floats each draw interpolates, and those it skips (never read).
    let (mut varyings_interpolated, mut varyings_skipped) = (0, 0);
    for (i, item) in items.iter().enumerate() {
        for (frequency, indices) in [
            (frequency, &item.indices),
            (Frequency::Phong, &item.phong_indices),
        ] {
            if !indices.is_empty() {
                let reads = shader_for(i, frequency).reads();
                for (part, _, floats) in Reads::PARTS {
                    if reads.contains(part) {
                        varyings_interpolated += floats;
                    } else {
                        varyings_skipped += floats;
                    }
                }
            }
        }
    }
    // Every item, in order, into `fb` shifted by `shift`; with a constant fragment stage when
    // `raster_only`.
    let draw_items = |fb: &mut Framebuffer, shift: Vec2, raster_only: bool| {
        let mut stats = DrawStats::default();
        for &i in &order {
            let item = &items[i];
            let passes: [(Frequency, &[u32]); 2] = [
                (frequency, &item.indices),
                (Frequency::Phong, &item.phong_indices),
            ];
            for (frequency, indices) in passes {
                if indices.is_empty() {
                    continue;
                }
                let shader = shader_for(i, frequency);
                let state = PipelineState {
                    cull: if item.double_sided {
                        CullMode::None
                    } else {
                        CullMode::Back
                    },
                    front_face: if item.flips_winding {
                        FrontFace::Cw
                    } else {
                        FrontFace::Ccw
                    },
                    viewport: Some(Viewport {
                        x: shift.x,
                        y: shift.y,
                        ..Viewport::full(width, height)
                    }),
                    blend: if item.blended {
                        Blend::Over
                    } else {
                        Blend::Replace
                    },
                    depth_write: !item.blended,
                    sample_shading,
                    ..PipelineState::default()
                };
                let s = if raster_only {
                    draw(fb, &RasterOnly(&shader), &state, &item.vertices, indices)
                } else {
                    draw(fb, &shader, &state, &item.vertices, indices)
                };
                stats += &s;
            }
        }
        stats
    };
    let mut total = DrawStats::default();
    let mut passes = 0_u32;
    // Seconds of the constant-shader passes, and of those passes with their copies (taken out
    // of the draw time).
    let (mut raster_seconds, mut measuring_seconds) = (0.0, 0.0);
    let mut draw_scene = |fb: &mut Framebuffer, shift: Vec2| {
        passes += 1;
        if options.measure_stages {
            // The same pass from the same state (depth, mask), into a copy that is dropped.
            let copying = Instant::now();
            let mut scratch = fb.clone();
            let started = Instant::now();
            draw_items(&mut scratch, shift, true);
            raster_seconds += started.elapsed().as_secs_f64();
            measuring_seconds += copying.elapsed().as_secs_f64();
        }
        total += &draw_items(fb, shift, false);
        on_pass(passes, planned_passes(options.anti_aliasing));
    };
    let limits = TargetLimits::default();
    let background = options.background;
    let drawing = Instant::now();
    let multisampled = |pattern: SamplePattern,
                        draw_scene: &mut dyn FnMut(&mut Framebuffer, Vec2)| {
        let mut fb = Framebuffer::multisampled(width, height, pattern, background, &limits)?;
        draw_scene(&mut fb, Vec2::ZERO);
        Ok::<_, RasterError>((fb, f64::from(pattern.count())))
    };
    let mut adaptive = None;
    let (image, samples_per_pixel) = match options.anti_aliasing {
        AntiAliasing::None => multisampled(SamplePattern::CENTRE, &mut draw_scene)?,
        AntiAliasing::Msaa(n) => {
            multisampled(SamplePattern::Standard { count: n }, &mut draw_scene)?
        }
        AntiAliasing::Supersample(n) | AntiAliasing::Jitter(n) if n == 0 || n > 16 => {
            return Err(RenderError::InvalidOption(format!(
                "{n}×{n} samples per pixel (n from 1 to 16)"
            )));
        }
        AntiAliasing::Supersample(n) if n <= 5 => {
            multisampled(SamplePattern::Regular { n }, &mut draw_scene)?
        }
        AntiAliasing::Jitter(n) if n <= 5 => {
            multisampled(SamplePattern::Jittered { n, seed: 1 }, &mut draw_scene)?
        }
        AntiAliasing::Supersample(n) => (
            render_supersampled(
                width,
                height,
                background,
                SamplePattern::Regular { n },
                &limits,
                &mut draw_scene,
            )?,
            f64::from(n * n),
        ),
        AntiAliasing::Jitter(n) => (
            render_supersampled(
                width,
                height,
                background,
                SamplePattern::Jittered { n, seed: 1 },
                &limits,
                &mut draw_scene,
            )?,
            f64::from(n * n),
        ),
        AntiAliasing::Adaptive(max) => {
            let adaptive_options = AdaptiveOptions {
                max_samples: max.max(4),
                ..AdaptiveOptions::default()
            };
            let (fb, stats) = render_adaptive(
                width,
                height,
                background,
                &adaptive_options,
                &limits,
                &mut draw_scene,
            )?;
            let spp = stats.mean_samples();
            adaptive = Some(stats);
            (fb, spp)
        }
    };
    let draw_seconds = drawing.elapsed().as_secs_f64() - measuring_seconds;
    Ok(Rendered {
        image,
        camera,
        stats: RenderStats {
            primitives: items.len(),
            triangles: items
                .iter()
                .map(|i| (i.indices.len() + i.phong_indices.len()) / 3)
                .sum(),
            draw: total,
            passes,
            samples_per_pixel,
            adaptive,
            textures: textures.list.len(),
            mip_chains: textures.mip_chains,
            mips_skipped: textures.mips_skipped,
            tangents_generated,
            hybrid_phong_triangles: hybrid_phong,
            hybrid_gouraud_triangles: hybrid_gouraud,
            varyings_interpolated,
            varyings_skipped,
            prepare_seconds,
            mip_seconds: textures.mip_seconds,
            draw_seconds,
            raster_seconds: options.measure_stages.then_some(raster_seconds),
        },
    })
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::Ordering;

    use super::*;
    use crate::demo::{demo_options, demo_scene};

    fn pixels(scene: &Scene, options: &RenderOptions) -> Vec<[u8; 4]> {
        let out = render(scene, options).expect("renders");
        let image = out.image.to_srgba8().expect("small");
        image.texels().iter().map(|t| t.0).collect()
    }

    /// Interpolating only what a material reads changes no pixel by more than one sRGB step
    /// (the one difference: an absent vertex colour is exactly white instead of a weighted sum
    /// of whites), for every shading model and with and without fog.
    #[test]
    fn skipping_unread_varyings_changes_no_pixel() {
        let scene = demo_scene();
        for shading in [
            Shading::Unlit,
            Shading::Flat,
            Shading::Gouraud,
            Shading::Phong,
            Shading::Hybrid,
        ] {
            for fog in [demo_options(1, 1).fog, None] {
                let options = RenderOptions {
                    shading,
                    fog,
                    ..demo_options(96, 54)
                };
                surface::INTERPOLATE_ALL.store(true, Ordering::Relaxed);
                let everything = pixels(&scene, &options);
                surface::INTERPOLATE_ALL.store(false, Ordering::Relaxed);
                let read = pixels(&scene, &options);
                let worst = everything
                    .iter()
                    .zip(&read)
                    .flat_map(|(a, b)| (0..4).map(move |c| a[c].abs_diff(b[c])))
                    .max()
                    .unwrap_or(0);
                assert!(
                    worst <= 1,
                    "{shading:?}, fog {}: {worst} steps",
                    fog.is_some()
                );
            }
        }
    }
}
