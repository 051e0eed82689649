//! Shading frequencies as [`Shader`]s (seeds 003, 004): how often the illumination model runs.
//!
//! | shader | lighting runs | interpolated |
//! |---|---|---|
//! | [`ColouredShader`] on [`flat_vertices`] | once per triangle, at its centroid with the face normal | nothing (one colour) |
//! | [`GouraudShader`] | once per vertex | colour |
//! | [`PhongShader`] | once per pixel | position and normal (renormalized) |
//! | [`HybridShader`](crate::HybridShader) | per vertex, and per pixel on triangles that pass the highlight test | colour, position, normal |
//! | [`ReferenceShader`] | once per pixel with the surface's exact normal | position |

use barytex_raster::{Fragment, Shader};
use barytex_uv::Mesh;
use glam::{Vec3, Vec4};

use crate::Scene;
use crate::scene::{ShadeVertex, valid_triangles};

/// A position with a colour already computed (flat shading, precomputed Gouraud).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ColouredVertex {
    /// World-space position.
    pub position: Vec3,
    /// Linear-light colour.
    pub colour: Vec3,
}

/// Draws [`ColouredVertex`]es, interpolating their colours: flat shading when the three vertices
/// of each triangle share one colour ([`flat_vertices`]), precomputed Gouraud shading otherwise
/// ([`precomputed_vertex_colours`](crate::precomputed_vertex_colours)).
#[derive(Clone, Copy, Debug)]
pub struct ColouredShader<'a> {
    /// The scene (only its camera is read).
    pub scene: &'a Scene,
}

impl Shader for ColouredShader<'_> {
    type Vertex = ColouredVertex;
    type Varying = Vec3;
    fn vertex(&self, v: &ColouredVertex) -> (Vec4, Vec3) {
        (self.scene.clip(v.position), v.colour)
    }
    fn fragment(&self, f: &Fragment<'_, Vec3>) -> Option<Vec4> {
        Some(f.varying.extend(1.0))
    }
}

/// Flat shading: every triangle lit once, at its centroid with its face normal (the seed's "one
/// colour per polygon, usually at its centre"); the triangles are unwelded so that each carries
/// its own colour. Degenerate triangles and those with an index out of range are left out.
///
/// ```
/// use barytex_shade::{flat_vertices, Camera, Light, Material, Scene, ViewVector};
/// use glam::Vec3;
///
/// let scene = Scene {
///     camera: Camera::look_at(Vec3::Z * 3.0, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 10.0).expect("ok"),
///     lights: vec![Light::Directional { direction: -Vec3::Z, color: Vec3::ONE }],
///     ambient: Vec3::ZERO,
///     material: Material::default(),
///     view: ViewVector::Local,
/// };
/// let sphere = barytex_uv::mesh::sphere(8, 4).expect("valid");
/// let (vertices, indices) = flat_vertices(&sphere, &scene);
/// assert_eq!(vertices.len(), indices.len());
/// // One colour per triangle.
/// assert!(vertices.chunks(3).all(|t| t[0].colour == t[1].colour && t[1].colour == t[2].colour));
/// ```
#[must_use]
pub fn flat_vertices(mesh: &Mesh, scene: &Scene) -> (Vec<ColouredVertex>, Vec<u32>) {
    let mut vertices = Vec::with_capacity(mesh.indices.len() * 3);
    for tri in valid_triangles(mesh) {
        let p = tri.map(|i| mesh.positions[i as usize]);
        let Some(n) = crate::face_normal(p[0], p[1], p[2]) else {
            continue;
        };
        let centroid = (p[0] + p[1] + p[2]) / 3.0;
        let colour = scene.light(centroid, n).total();
        vertices.extend(p.map(|position| ColouredVertex { position, colour }));
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices)
}

/// Gouraud shading: each vertex lit with its (renormalized) normal, colours interpolated.
#[derive(Clone, Copy, Debug)]
pub struct GouraudShader<'a> {
    /// Camera, lights, material.
    pub scene: &'a Scene,
}

impl Shader for GouraudShader<'_> {
    type Vertex = ShadeVertex;
    type Varying = Vec3;
    fn vertex(&self, v: &ShadeVertex) -> (Vec4, Vec3) {
        let n = v.normal.normalize_or_zero();
        (
            self.scene.clip(v.position),
            self.scene.light(v.position, n).total(),
        )
    }
    fn fragment(&self, f: &Fragment<'_, Vec3>) -> Option<Vec4> {
        Some(f.varying.extend(1.0))
    }
}

/// Phong shading: position and normal interpolated, the normal renormalized, lit per pixel.
#[derive(Clone, Copy, Debug)]
pub struct PhongShader<'a> {
    /// Camera, lights, material.
    pub scene: &'a Scene,
    /// Whether to renormalize the interpolated normal (seed 003). `false` is the "pre-normalized
    /// normals" shortcut taken too far: interpolated unit normals are shorter than 1 inside a
    /// triangle, which darkens the diffuse term and blunts the highlight (measured in
    /// `tests/speedups.rs`).
    pub renormalize: bool,
}

impl<'a> PhongShader<'a> {
    /// The exact variant (renormalizing).
    #[must_use]
    pub fn new(scene: &'a Scene) -> Self {
        Self {
            scene,
            renormalize: true,
        }
    }
}

impl Shader for PhongShader<'_> {
    type Vertex = ShadeVertex;
    type Varying = (Vec3, Vec3);
    fn vertex(&self, v: &ShadeVertex) -> (Vec4, (Vec3, Vec3)) {
        (self.scene.clip(v.position), (v.position, v.normal))
    }
    fn fragment(&self, f: &Fragment<'_, (Vec3, Vec3)>) -> Option<Vec4> {
        let (p, n) = f.varying;
        let n = if self.renormalize {
            n.normalize_or_zero()
        } else {
            n
        };
        Some(self.scene.light(p, n).total().extend(1.0))
    }
}

/// The ground truth for a surface whose exact normal is known everywhere (a sphere: the
/// normalized position): position interpolated, the normal computed from it, lit per pixel.
#[derive(Clone, Copy, Debug)]
pub struct ReferenceShader<'a, F> {
    /// Camera, lights, material.
    pub scene: &'a Scene,
    /// The exact unit normal at a surface point.
    pub normal: F,
}

impl<F: Fn(Vec3) -> Vec3 + Sync> Shader for ReferenceShader<'_, F> {
    type Vertex = ShadeVertex;
    type Varying = Vec3;
    fn vertex(&self, v: &ShadeVertex) -> (Vec4, Vec3) {
        (self.scene.clip(v.position), v.position)
    }
    fn fragment(&self, f: &Fragment<'_, Vec3>) -> Option<Vec4> {
        let p = f.varying;
        Some(self.scene.light(p, (self.normal)(p)).total().extend(1.0))
    }
}
