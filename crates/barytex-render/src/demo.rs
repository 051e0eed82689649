//! The built-in demo scene (what `barytex` renders with no arguments), built in code: no files.
//!
//! At a glance: a checkerboard floor receding to the horizon (where aliasing,
//! mipmaps and anisotropic filtering differ most), a sphere with the equirectangular mapping, a
//! capped cylinder with the cylindrical mapping, a torus with its (u, v) parametrisation, each
//! with a texture that makes the mapping's distortion and seams visible, the torus also
//! bump-mapped through a normal texture; a mirror sphere reflecting an equirectangular sky
//! (environment mapping); a sun, a point light and a spot light.

use std::sync::Arc;

use barytex_texture::load::AnyTexture2d;
use barytex_texture::{Srgba8, Texture2d};
use barytex_uv::mappings::TexCoordMapping;
use glam::{Mat4, Quat, Vec3};

use crate::{AntiAliasing, Filter, RenderOptions};
use barytex_gltf::camera::{DocumentCamera, Projection, SceneCamera};
use barytex_gltf::light::{LightKind, PunctualLight, SceneLight};
use barytex_gltf::material::{Material, TextureRef};
use barytex_gltf::mesh::{Mesh, Primitive};
use barytex_gltf::sampler::{MagFilter, MinFilter, SamplerParams, Wrap};
use barytex_gltf::scene::{MeshInstance, Scene, SceneImage, Texture};
use barytex_gltf::topology::Topology;

/// A procedural sRGB image.
fn image(side: u32, f: impl Fn(u32, u32) -> [u8; 3]) -> SceneImage {
    // 512² at most: within the default limits; were it refused, the object is drawn untextured.
    let texture = Texture2d::from_fn(side, side, |x, y| {
        let [r, g, b] = f(x, y);
        Srgba8([r, g, b, 255])
    })
    .ok();
    SceneImage {
        name: None,
        srgb: texture.map(|t| Arc::new(AnyTexture2d::Srgba8(t))),
        linear: None,
    }
}

fn checker(side: u32, square: u32, a: [u8; 3], b: [u8; 3]) -> SceneImage {
    image(side, move |x, y| {
        if (x / square + y / square).is_multiple_of(2) {
            a
        } else {
            b
        }
    })
}

/// Latitude bands and meridians: shows the equirectangular mapping's pinching at the poles.
fn globe(side: u32) -> SceneImage {
    image(side, |x, y| {
        let band = y * 8 / side;
        let meridian = x % (side / 12) < 2 || y % (side / 6) < 2;
        if meridian {
            [250, 250, 240]
        } else if band.is_multiple_of(2) {
            [40, 110, 200]
        } else {
            [60, 170, 90]
        }
    })
}

/// Diagonal stripes: show a mapping's shear and the seam where u wraps.
fn stripes(side: u32) -> SceneImage {
    image(side, |x, y| {
        if ((x + y) / (side / 16)).is_multiple_of(2) {
            [230, 150, 40]
        } else {
            [120, 40, 30]
        }
    })
}

/// A tangent-space normal map (linear RGB, glTF's convention) of the bumps
/// `h(u, v) = sin(2π·16u)·sin(2π·8v)`: the torus gets bumps its silhouette does not show
/// (bump mapping, J. F. Blinn, "Simulation of wrinkled surfaces", *SIGGRAPH '78*, through glTF's
/// normal texture).
fn bumps(side: u32) -> SceneImage {
    let texture = Texture2d::from_fn(side, side, |x, y| {
        let (u, v) = (
            (x as f32 + 0.5) / side as f32,
            (y as f32 + 0.5) / side as f32,
        );
        let tau = std::f32::consts::TAU;
        let (fu, fv) = (16.0, 8.0);
        // ∂h/∂u and ∂h/∂v, scaled so the slopes stay moderate.
        let k = 0.02;
        let du = k * tau * fu * (tau * fu * u).cos() * (tau * fv * v).sin();
        let dv = k * tau * fv * (tau * fu * u).sin() * (tau * fv * v).cos();
        let n = Vec3::new(-du, -dv, 1.0).normalize();
        let byte = |c: f32| ((c * 0.5 + 0.5) * 255.0).round() as u8;
        barytex_texture::Rgba8([byte(n.x), byte(n.y), byte(n.z), 255])
    })
    .ok();
    SceneImage {
        name: Some("bumps".to_owned()),
        srgb: None,
        linear: texture.map(|t| Arc::new(AnyTexture2d::Rgba8(t))),
    }
}

/// The environment the mirror sphere reflects: an equirectangular sky in linear light — a
/// blue gradient, a skyline of coloured blocks on the horizon, the sun where the demo's sun
/// light comes from, and a brown ground with a grid below the horizon.
fn sky() -> Option<Arc<AnyTexture2d>> {
    let sun = Vec3::new(-6.0, 8.0, 6.0).normalize();
    let (w, h) = (512, 256);
    let texture = Texture2d::from_fn(w, h, |x, y| {
        let uv = glam::Vec2::new((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
        let d = barytex_uv::environment::equirect_direction(uv).unwrap_or(Vec3::Y);
        // A skyline of coloured blocks around the horizon makes the reflection readable.
        let azimuth = d.x.atan2(-d.z);
        let block = ((azimuth + std::f32::consts::PI) * 24.0 / std::f32::consts::TAU) as u32;
        let height = 0.06 + 0.05 * (block * 7 % 5) as f32;
        let palette = [
            Vec3::new(0.8, 0.15, 0.1),
            Vec3::new(0.9, 0.9, 0.85),
            Vec3::new(0.1, 0.5, 0.2),
            Vec3::new(0.9, 0.6, 0.1),
        ];
        let c = if d.dot(sun) > 0.9994 {
            Vec3::new(40.0, 38.0, 34.0)
        } else if d.y >= 0.0 && d.y < height {
            palette[(block % 4) as usize]
        } else if d.y >= 0.0 {
            let t = d.y.powf(0.4);
            Vec3::new(0.55, 0.65, 0.85).lerp(Vec3::new(0.08, 0.2, 0.65), t)
        } else {
            // The ground plane y = −1 seen from the centre: a grid every unit.
            let p = d * (-1.0 / d.y.min(-1e-3));
            let line = (p.x - p.x.round()).abs() < 0.04 || (p.z - p.z.round()).abs() < 0.04;
            if line && p.length() < 40.0 {
                Vec3::new(0.55, 0.5, 0.42)
            } else {
                Vec3::new(0.22, 0.18, 0.14)
            }
        };
        barytex_texture::Rgba32f([c.x, c.y, c.z, 1.0])
    })
    .ok()?;
    Some(Arc::new(AnyTexture2d::Rgba32f(texture)))
}

fn repeat_trilinear() -> SamplerParams {
    SamplerParams {
        mag_filter: MagFilter::Linear,
        min_filter: MinFilter::LinearMipmapLinear,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Repeat,
    }
}

fn primitive(mesh: barytex_uv::mesh::TriMesh, material: usize, uv_scale: f32) -> Primitive {
    Primitive {
        positions: mesh.positions,
        normals: Some(mesh.normals),
        tangents: Some(mesh.tangents),
        tex_coords0: Some(mesh.uvs.iter().map(|&uv| uv * uv_scale).collect()),
        tex_coords1: None,
        colors0: None,
        triangles: mesh.indices,
        indices: Vec::new(),
        material: Some(material),
        topology: Topology::Triangles,
    }
}

fn instance(index: usize, name: &str, primitive: Primitive, world: Mat4) -> MeshInstance {
    MeshInstance {
        node: index,
        node_name: Some(name.to_owned()),
        world,
        flips_winding: world.determinant() < 0.0,
        mesh: Arc::new(Mesh {
            index,
            name: Some(name.to_owned()),
            primitives: vec![primitive],
        }),
    }
}

fn textured(name: &str, texture: usize, roughness: f32) -> Material {
    Material {
        name: Some(name.to_owned()),
        base_color_texture: Some(TextureRef {
            texture,
            image: Some(texture),
            sampler: repeat_trilinear(),
            mapping: TexCoordMapping::new(0),
        }),
        roughness_factor: roughness,
        metallic_factor: 0.0,
        ..Material::default()
    }
}

fn light(node: usize, kind: LightKind, color: Vec3, intensity: f32, world: Mat4) -> SceneLight {
    SceneLight {
        node,
        light_index: node,
        light: PunctualLight {
            name: None,
            kind,
            color,
            intensity,
            range: None,
        },
        world,
        position: world.transform_point3(Vec3::ZERO),
        direction: world.transform_vector3(Vec3::NEG_Z).normalize_or_zero(),
    }
}

/// The camera-to-world matrix of an eye at `eye` looking at `target`, y up.
fn look_at(eye: Vec3, target: Vec3) -> Mat4 {
    let forward = (target - eye).normalize();
    let right = forward.cross(Vec3::Y).normalize();
    let up = right.cross(forward);
    Mat4::from_cols(
        right.extend(0.0),
        up.extend(0.0),
        (-forward).extend(0.0),
        eye.extend(1.0),
    )
}

/// Exponential fog density of the demo (per unit of distance): the floor fades into the
/// background towards the horizon.
pub const DEMO_FOG: f32 = 0.04;

/// The options `barytex` renders the demo with: anisotropic filtering (8 probes), 4× MSAA,
/// Blinn–Phong, fog in the background colour.
///
/// ```
/// use barytex_render::demo::{DEMO_FOG, demo_options};
/// use barytex_render::{AntiAliasing, Filter, RenderOptions};
///
/// let options = demo_options(320, 180);
/// assert_eq!((options.width, options.height), (320, 180));
/// assert_eq!((options.filter, options.anti_aliasing), (Filter::Anisotropic(8), AntiAliasing::Msaa(4)));
/// // The fog fades into the background colour.
/// let fog = options.fog.unwrap();
/// assert_eq!(fog.density, DEMO_FOG);
/// assert_eq!(fog.colour, RenderOptions::default().background.truncate());
/// ```
#[must_use]
pub fn demo_options(width: u32, height: u32) -> RenderOptions {
    let defaults = RenderOptions::default();
    RenderOptions {
        width,
        height,
        filter: Filter::Anisotropic(8),
        anti_aliasing: AntiAliasing::Msaa(4),
        fog: Some(barytex_shade::ExponentialFog {
            density: DEMO_FOG,
            colour: defaults.background.truncate(),
            distance: barytex_shade::FogDistance::Euclidean,
        }),
        ..defaults
    }
}

/// The demo scene. (The generated meshes use fixed, valid resolutions; were one ever refused,
/// it would be left empty rather than panic — the tests would catch it.)
///
/// ```
/// use barytex_render::demo::{demo_options, demo_scene};
/// use barytex_render::{CameraSource, render};
///
/// let scene = demo_scene();
/// assert_eq!(scene.lights.len(), 3); // sun, point and spot
/// assert!(scene.environment.is_some());
/// // The demo brings its own camera; a tiny render looks through it.
/// let out = render(&scene, &demo_options(24, 16))?;
/// assert_eq!(out.camera.source, CameraSource::Scene(0));
/// assert_eq!(out.stats.triangles, scene.triangle_count());
/// # Ok::<(), barytex_render::RenderError>(())
/// ```
#[must_use]
pub fn demo_scene() -> Scene {
    let images = vec![
        checker(256, 16, [225, 225, 225], [30, 30, 36]),
        globe(512),
        stripes(256),
        checker(256, 32, [240, 200, 60], [40, 60, 150]),
        bumps(256),
    ];
    let textures = (0..images.len())
        .map(|i| Texture {
            image: Some(i),
            sampler: repeat_trilinear(),
        })
        .collect();
    let materials = vec![
        textured("floor", 0, 0.6),
        textured("globe", 1, 0.3),
        textured("stripes", 2, 0.4),
        Material {
            normal_texture: Some(TextureRef {
                texture: 4,
                image: Some(4),
                sampler: repeat_trilinear(),
                mapping: TexCoordMapping::new(0),
            }),
            ..textured("bumpy checker", 3, 0.35)
        },
        Material {
            name: Some("mirror".to_owned()),
            base_color_factor: glam::Vec4::new(0.95, 0.95, 0.95, 1.0),
            metallic_factor: 1.0,
            roughness_factor: 0.02,
            ..Material::default()
        },
    ];
    let empty = barytex_uv::mesh::TriMesh {
        positions: Vec::new(),
        normals: Vec::new(),
        tangents: Vec::new(),
        uvs: Vec::new(),
        indices: Vec::new(),
    };
    let floor = barytex_uv::mesh::plane(8, 8).unwrap_or_else(|_| empty.clone());
    let sphere = barytex_uv::mesh::sphere(64, 32).unwrap_or_else(|_| empty.clone());
    let cylinder = barytex_uv::mesh::cylinder(48, 4, true).unwrap_or_else(|_| empty.clone());
    let torus = barytex_uv::mesh::torus(72, 32, 1.0, 0.35).unwrap_or_else(|_| empty.clone());
    let mirror = barytex_uv::mesh::sphere(48, 24).unwrap_or_else(|_| empty.clone());
    let instances = vec![
        // 80 × 80 units, the checker (16 squares a side) repeated 5 times: squares of 1 unit.
        instance(
            0,
            "floor",
            primitive(floor, 0, 40.0),
            Mat4::from_scale(Vec3::new(40.0, 1.0, 40.0)),
        ),
        instance(
            1,
            "sphere",
            primitive(sphere, 1, 1.0),
            Mat4::from_translation(Vec3::new(-2.6, 1.0, 0.0)),
        ),
        instance(
            2,
            "cylinder",
            primitive(cylinder, 2, 1.0),
            Mat4::from_scale_rotation_translation(
                Vec3::new(0.75, 1.0, 0.75),
                Quat::from_rotation_y(0.6),
                Vec3::new(0.0, 1.0, -1.2),
            ),
        ),
        instance(
            3,
            "torus",
            primitive(torus, 3, 1.0),
            Mat4::from_scale_rotation_translation(
                Vec3::splat(0.9),
                Quat::from_rotation_x(1.1) * Quat::from_rotation_z(0.3),
                Vec3::new(2.7, 1.1, 0.2),
            ),
        ),
        instance(
            4,
            "mirror sphere",
            primitive(mirror, 4, 1.0),
            Mat4::from_scale_rotation_translation(
                Vec3::splat(0.55),
                Quat::IDENTITY,
                Vec3::new(-0.9, 0.55, 2.0),
            ),
        ),
    ];
    let lights = vec![
        // A low sun from the left, behind the viewer.
        light(
            10,
            LightKind::Directional,
            Vec3::new(1.0, 0.95, 0.85),
            2.2,
            look_at(Vec3::new(-6.0, 8.0, 6.0), Vec3::ZERO),
        ),
        // A warm point light between the objects.
        light(
            11,
            LightKind::Point,
            Vec3::new(1.0, 0.7, 0.4),
            18.0,
            Mat4::from_translation(Vec3::new(0.0, 2.8, 1.8)),
        ),
        // A cool spot light on the torus.
        light(
            12,
            LightKind::Spot {
                inner_cone_angle: 0.25,
                outer_cone_angle: 0.45,
            },
            Vec3::new(0.5, 0.7, 1.0),
            60.0,
            look_at(Vec3::new(4.5, 5.0, 3.0), Vec3::new(2.7, 1.0, 0.2)),
        ),
    ];
    let camera = DocumentCamera {
        name: Some("demo".to_owned()),
        projection: Projection::Perspective {
            yfov: 45_f32.to_radians(),
            aspect_ratio: None,
            znear: 0.1,
            zfar: Some(200.0),
        },
    };
    let cameras = vec![SceneCamera {
        node: 20,
        camera: 0,
        name: camera.name.clone(),
        projection: camera.projection,
        world: look_at(Vec3::new(0.0, 2.4, 7.5), Vec3::new(0.0, 0.9, 0.0)),
    }];
    let triangles: usize = instances.iter().map(MeshInstance::triangle_count).sum();
    Scene {
        scene_index: Some(0),
        name: Some("barytex demo".to_owned()),
        scene_count: 1,
        instances,
        cameras,
        document_cameras: vec![camera],
        lights,
        materials,
        textures,
        images,
        warnings: Vec::new(),
        // The demo's images are generated, not decoded.
        decode_seconds: 0.0,
        environment: sky(),
        portals: Vec::new(),
        stats: barytex_gltf::scene::SceneStats {
            meshes_loaded: 5,
            primitives_loaded: 5,
            triangles,
            instanced_triangles: triangles,
            images_decoded: 5,
            ..barytex_gltf::scene::SceneStats::default()
        },
    }
}

/// The mirror of [`demo_scene_with_mirror`]: half its width, its height and its frame's width
/// (where it stands: [`mirror_placement`]).
const MIRROR_HALF_WIDTH: f32 = 3.4;
const MIRROR_HEIGHT: f32 = 2.9;
const MIRROR_FRAME: f32 = 0.14;

fn mirror_placement() -> Mat4 {
    // Leaning forward a little, as a shop mirror tilted down: it shows the floor around the
    // objects and their tops rather than the floor at the horizon, which only fogs and blurs
    // to grey.
    let turn = Quat::from_rotation_y(-0.22) * Quat::from_rotation_x(0.28);
    Mat4::from_rotation_translation(turn, Vec3::new(0.3, 0.0, -3.7))
}

/// A picture frame of four flat bars around the mirror, in the mirror's local space (the glass
/// at z = 0 facing +z, from y = 0 up); the bars stand a hair in front of the glass.
fn mirror_frame() -> Primitive {
    let (w, h, f, z) = (MIRROR_HALF_WIDTH, MIRROR_HEIGHT, MIRROR_FRAME, 0.01);
    let bars = [
        (-w - f, 0.0, -w, h + f),
        (w, 0.0, w + f, h + f),
        (-w, h, w, h + f),
        (-w, 0.0, w, f * 0.5),
    ];
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for (x0, y0, x1, y1) in bars {
        let base = positions.len() as u32;
        positions.extend([
            Vec3::new(x0, y0, z),
            Vec3::new(x1, y0, z),
            Vec3::new(x1, y1, z),
            Vec3::new(x0, y1, z),
        ]);
        triangles.extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
    }
    Primitive {
        normals: Some(vec![Vec3::Z; positions.len()]),
        positions,
        tangents: None,
        tex_coords0: None,
        tex_coords1: None,
        colors0: None,
        triangles,
        indices: Vec::new(),
        material: Some(5),
        topology: Topology::Triangles,
    }
}

/// The demo scene with a framed mirror standing behind the objects
/// ([`Portal`](barytex_gltf::Portal), drawn through an oblique near plane with the winding
/// swapped): it shows the objects' far sides, the floor towards the camera and the mirror
/// sphere from behind. `barytex demo --mirror` renders it.
///
/// ```
/// use barytex_render::demo::{demo_options, demo_scene, demo_scene_with_mirror};
/// use barytex_render::render;
///
/// let scene = demo_scene_with_mirror();
/// assert_eq!(scene.portals.len(), 1);
/// assert_eq!(scene.instances.len(), demo_scene().instances.len() + 1); // the frame
/// let out = render(&scene, &demo_options(32, 18))?;
/// assert_eq!(out.stats.portal_views, 1);
/// # Ok::<(), barytex_render::RenderError>(())
/// ```
#[must_use]
pub fn demo_scene_with_mirror() -> Scene {
    let mut scene = demo_scene();
    let placement = mirror_placement();
    let (w, h) = (MIRROR_HALF_WIDTH, MIRROR_HEIGHT);
    let glass = [
        Vec3::new(-w, 0.0, 0.0),
        Vec3::new(w, 0.0, 0.0),
        Vec3::new(w, h, 0.0),
        Vec3::new(-w, h, 0.0),
    ]
    .map(|p| placement.transform_point3(p))
    .to_vec();
    // A rectangle by construction: `mirror` cannot refuse it.
    if let Ok(mirror) = barytex_gltf::Portal::mirror(glass) {
        scene
            .portals
            .push(mirror.with_tint(glam::Vec4::new(0.55, 0.7, 0.8, 0.06)));
    }
    scene.materials.push(Material {
        name: Some("mirror frame".to_owned()),
        base_color_factor: glam::Vec4::new(0.09, 0.06, 0.04, 1.0),
        metallic_factor: 0.0,
        roughness_factor: 0.45,
        double_sided: true,
        ..Material::default()
    });
    scene
        .instances
        .push(instance(5, "mirror frame", mirror_frame(), placement));
    let triangles: usize = scene
        .instances
        .iter()
        .map(MeshInstance::triangle_count)
        .sum();
    scene.stats.meshes_loaded += 1;
    scene.stats.primitives_loaded += 1;
    scene.stats.triangles = triangles;
    scene.stats.instanced_triangles = triangles;
    scene
}
