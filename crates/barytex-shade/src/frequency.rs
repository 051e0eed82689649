//! Shading frequencies as [`Shader`]s (Foley et al., *Computer Graphics: Principles and
//! Practice*, 2nd ed., 1990, §16.2; Gouraud 1971; Phong 1975): how often the illumination model
//! runs.
//!
//! | shader | lighting runs | interpolated |
//! |---|---|---|
//! | [`ColouredShader`] on [`flat_vertices`] | once per triangle, at its centroid with the face normal | nothing (one colour) |
//! | [`GouraudShader`] | once per vertex | colour |
//! | [`PhongShader`] | once per pixel | position and normal (renormalized) |
//! | [`SlerpPhongShader`] on [`slerp_vertices`] | once per pixel | position and barycentrics; the normal by SLERP |
//! | [`HybridShader`](crate::HybridShader) | per vertex, and per pixel on triangles that pass the highlight test | colour, position, normal |
//! | [`ReferenceShader`] | once per pixel with the surface's exact normal | position |

use barytex_interp::{NormalInterpolation, interpolate_normal};
use barytex_raster::{Fragment, Shader};
use barytex_uv::TriMesh;
use glam::{Vec3, Vec4};

use crate::ShadeContext;
use crate::context::{ShadeVertex, valid_triangles};

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
    pub scene: &'a ShadeContext,
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

/// Flat shading: every triangle lit once, at its centroid with its face normal (S. Schaefer's
/// *Shading/Texturing* slides: "apply same color across entire polygon … typically use center of
/// polygon"); the triangles are unwelded so that each carries its own colour. Degenerate triangles
/// and those with an index out of range are left out.
///
/// ```
/// use barytex_shade::{flat_vertices, Camera, Light, PhongMaterial, ShadeContext, ViewVector};
/// use glam::Vec3;
///
/// let scene = ShadeContext {
///     camera: Camera::look_at(Vec3::Z * 3.0, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 10.0).expect("ok"),
///     lights: vec![Light::Directional { direction: -Vec3::Z, color: Vec3::ONE }],
///     ambient: Vec3::ZERO,
///     material: PhongMaterial::default(),
///     view: ViewVector::Local,
/// };
/// let sphere = barytex_uv::mesh::sphere(8, 4).expect("valid");
/// let (vertices, indices) = flat_vertices(&sphere, &scene);
/// assert_eq!(vertices.len(), indices.len());
/// // One colour per triangle.
/// assert!(vertices.chunks(3).all(|t| t[0].colour == t[1].colour && t[1].colour == t[2].colour));
/// ```
#[must_use]
pub fn flat_vertices(mesh: &TriMesh, scene: &ShadeContext) -> (Vec<ColouredVertex>, Vec<u32>) {
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
    pub scene: &'a ShadeContext,
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
    pub scene: &'a ShadeContext,
    /// Whether to renormalize the interpolated normal (Phong 1975; Schaefer's slides: "must
    /// renormalize"). `false` is the "pre-normalized normals" shortcut taken too far: interpolated
    /// unit normals are shorter than 1 inside a triangle, which darkens the diffuse term and blunts
    /// the highlight (measured in `tests/speedups.rs`).
    pub renormalize: bool,
}

impl<'a> PhongShader<'a> {
    /// The exact variant (renormalizing).
    #[must_use]
    pub fn new(scene: &'a ShadeContext) -> Self {
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

/// A vertex of [`SlerpPhongShader`]: its barycentric corner and its triangle's index into the
/// table of vertex-normal triples (constant over the triangle).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SlerpVertex {
    /// World-space position.
    pub position: Vec3,
    /// `(1, 0, 0)`, `(0, 1, 0)` or `(0, 0, 1)`.
    pub corner: Vec3,
    /// The triangle's index in the normal table (exact in `f32` below 2²⁴ triangles).
    pub triangle: f32,
}

/// Prepares [`SlerpPhongShader`]: unwelded triangles and their unit vertex normals.
#[must_use]
pub fn slerp_vertices(mesh: &TriMesh) -> (Vec<SlerpVertex>, Vec<u32>, Vec<[Vec3; 3]>) {
    let mut vertices = Vec::with_capacity(mesh.indices.len() * 3);
    let mut table = Vec::with_capacity(mesh.indices.len());
    for tri in valid_triangles(mesh) {
        let triangle = table.len() as f32;
        table.push(tri.map(|i| {
            mesh.normals
                .get(i as usize)
                .copied()
                .unwrap_or(Vec3::ZERO)
                .normalize_or_zero()
        }));
        for (k, corner) in [Vec3::X, Vec3::Y, Vec3::Z].into_iter().enumerate() {
            vertices.push(SlerpVertex {
                position: mesh.positions[tri[k] as usize],
                corner,
                triangle,
            });
        }
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices, table)
}

/// The normal at barycentrics `b` by two SLERPs ([`interpolate_normal`] with
/// [`NormalInterpolation::Slerp`]): along edge 01 at `b1/(b0 + b1)`, then towards `n2` at `b2`.
/// Evenly spaced in angle along every edge (lerp + renormalize is not); not symmetric in the
/// three vertices inside. Zero normals give zero.
#[must_use]
pub fn slerp_triangle_normal(n: [Vec3; 3], b: Vec3) -> Vec3 {
    let s = b.x + b.y;
    let n01 = if s > 0.0 {
        interpolate_normal(n[0], n[1], b.y / s, NormalInterpolation::Slerp)
    } else {
        n[0]
    };
    interpolate_normal(n01, n[2], b.z, NormalInterpolation::Slerp)
}

/// Phong shading with the normal interpolated by SLERP ([`slerp_triangle_normal`]) instead of
/// lerp + renormalize: even angular spacing, a few times the cost per pixel.
#[derive(Clone, Copy, Debug)]
pub struct SlerpPhongShader<'a> {
    /// Camera, lights, material.
    pub scene: &'a ShadeContext,
    /// The normal table from [`slerp_vertices`].
    pub normals: &'a [[Vec3; 3]],
}

impl Shader for SlerpPhongShader<'_> {
    type Vertex = SlerpVertex;
    type Varying = (Vec3, Vec3, f32);
    fn vertex(&self, v: &SlerpVertex) -> (Vec4, (Vec3, Vec3, f32)) {
        (
            self.scene.clip(v.position),
            (v.position, v.corner, v.triangle),
        )
    }
    fn fragment(&self, f: &Fragment<'_, (Vec3, Vec3, f32)>) -> Option<Vec4> {
        let (p, b, triangle) = f.varying;
        let n = self.normals.get(triangle.round().max(0.0) as usize)?;
        let normal = slerp_triangle_normal(*n, b);
        Some(self.scene.light(p, normal).total().extend(1.0))
    }
}

/// The ground truth for a surface whose exact normal is known everywhere (a sphere: the
/// normalized position): position interpolated, the normal computed from it, lit per pixel.
#[derive(Clone, Copy, Debug)]
pub struct ReferenceShader<'a, F> {
    /// Camera, lights, material.
    pub scene: &'a ShadeContext,
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
