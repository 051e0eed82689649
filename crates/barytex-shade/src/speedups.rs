//! The shading speed-ups of the Finnish lecture notes *Valaistus ja sävytys* (p. 292; see the
//! crate's [References](crate#references)), each with its error measured in `tests/speedups.rs` and
//! in the report:
//!
//! - a constant view vector ([`ViewVector::Constant`](crate::ViewVector::Constant));
//! - pre-normalized normals (normalize once when the mesh is built; [`PhongShader`](crate::PhongShader)'s
//!   `renormalize: false` shows what skipping the *per-pixel* renormalization costs);
//! - vertex colours computed once for lights that do not move relative to the object
//!   ([`precomputed_vertex_colours`], drawn by [`ColouredShader`](crate::ColouredShader));
//! - a fast approximate Phong shading ([`fast_phong_vertices`] + [`FastPhongShader`]): the
//!   exact Phong colour at the three vertices and three edge midpoints of each triangle,
//!   interpolated quadratically inside — the second-order idea of Bishop and Weimer's "Fast Phong
//!   Shading" (1986) — so a pixel costs a handful of multiply-adds instead of a normalization
//!   and a power per light.

use barytex_raster::{Fragment, Shader};
use barytex_uv::TriMesh;
use glam::{Vec3, Vec4};

use crate::ShadeContext;
use crate::context::valid_triangles;
use crate::frequency::ColouredVertex;

/// Gouraud vertex colours computed once (static lights and eye): drawing them costs no lighting
/// at all. Exact while nothing moves; when the eye moves the specular term is stale.
///
/// ```
/// use barytex_shade::{precomputed_vertex_colours, Camera, Light, PhongMaterial, ShadeContext, ViewVector};
/// use glam::Vec3;
///
/// let scene = ShadeContext {
///     camera: Camera::look_at(Vec3::Z * 3.0, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 10.0).expect("ok"),
///     lights: vec![Light::Directional { direction: -Vec3::Z, color: Vec3::ONE }],
///     ambient: Vec3::ZERO, material: PhongMaterial::default(), view: ViewVector::Local,
/// };
/// let sphere = barytex_uv::mesh::sphere(8, 4).expect("valid");
/// let (vertices, indices) = precomputed_vertex_colours(&sphere, &scene);
/// assert_eq!(vertices.len(), sphere.positions.len());
/// assert_eq!(indices.len(), 3 * sphere.indices.len());
/// ```
#[must_use]
pub fn precomputed_vertex_colours(
    mesh: &TriMesh,
    scene: &ShadeContext,
) -> (Vec<ColouredVertex>, Vec<u32>) {
    let vertices = (0..mesh.positions.len())
        .map(|i| {
            let n = mesh.normals.get(i).copied().unwrap_or(Vec3::ZERO);
            ColouredVertex {
                position: mesh.positions[i],
                colour: scene
                    .light(mesh.positions[i], n.normalize_or_zero())
                    .total(),
            }
        })
        .collect();
    (vertices, mesh.indices.iter().flatten().copied().collect())
}

/// What [`FastPhongShader`] interpolates over one triangle, at its six nodes (vertices 0, 1, 2,
/// then the midpoints of edges 01, 12, 20).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FastPhongNodes {
    /// Everything but the key light's specular: emission, ambient, every diffuse term and the
    /// other lights' specular terms.
    pub smooth: [Vec3; 6],
    /// The key light's (the first light's) `cos α = R·V`, or −1 where it is behind the surface.
    pub cos_alpha: [f32; 6],
    /// The key light's `I_p k_s` at the centroid (constant over the triangle).
    pub specular: Vec3,
}

/// A vertex of [`FastPhongShader`]: its barycentric corner and its triangle's index into the
/// node table (as `f32`, constant over the triangle, so only four floats are interpolated).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FastPhongVertex {
    /// World-space position.
    pub position: Vec3,
    /// `(1, 0, 0)`, `(0, 1, 0)` or `(0, 0, 1)`.
    pub corner: Vec3,
    /// The triangle's index in the node table (exact in `f32` below 2²⁴ triangles).
    pub triangle: f32,
}

/// Prepares [`FastPhongShader`]: the lighting at six points per triangle (normals lerped and
/// renormalized, as Phong shading sees them) in a node table, and the unwelded triangles'
/// vertices and indices.
#[must_use]
pub fn fast_phong_vertices(
    mesh: &TriMesh,
    scene: &ShadeContext,
) -> (Vec<FastPhongVertex>, Vec<u32>, Vec<FastPhongNodes>) {
    let key = scene.lights.first();
    let rest = scene.lights.get(1..).unwrap_or(&[]);
    let m = &scene.material;
    let mut vertices = Vec::with_capacity(mesh.indices.len() * 3);
    let mut table = Vec::with_capacity(mesh.indices.len());
    for tri in valid_triangles(mesh) {
        let p = tri.map(|i| mesh.positions[i as usize]);
        let n = tri.map(|i| mesh.normals.get(i as usize).copied().unwrap_or(Vec3::ZERO));
        let node = |a: usize, b: usize| {
            let q = (p[a] + p[b]) * 0.5;
            let normal = ((n[a] + n[b]) * 0.5).normalize_or_zero();
            let v = scene.view_vector(q);
            let mut smooth = m.shade(q, normal, v, rest, scene.ambient).total();
            let mut cos = -1.0;
            if let Some(sample) = key.and_then(|l| l.sample(q)) {
                smooth += sample.intensity * m.diffuse * crate::lambert(normal, sample.to_light);
                let nl = normal.dot(sample.to_light);
                if nl > 0.0 {
                    cos = (2.0 * nl * normal - sample.to_light).dot(v);
                }
            }
            (smooth, cos)
        };
        let six = [
            node(0, 0),
            node(1, 1),
            node(2, 2),
            node(0, 1),
            node(1, 2),
            node(2, 0),
        ];
        let centroid = (p[0] + p[1] + p[2]) / 3.0;
        let specular = match (key.and_then(|l| l.sample(centroid)), m.lobe) {
            (Some(sample), crate::Specular::Phong | crate::Specular::BlinnPhong) => {
                sample.intensity * m.specular
            }
            _ => Vec3::ZERO,
        };
        let nodes = FastPhongNodes {
            smooth: six.map(|x| x.0),
            cos_alpha: six.map(|x| x.1),
            specular,
        };
        let triangle = table.len() as f32;
        table.push(nodes);
        for (k, corner) in [Vec3::X, Vec3::Y, Vec3::Z].into_iter().enumerate() {
            vertices.push(FastPhongVertex {
                position: p[k],
                corner,
                triangle,
            });
        }
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices, table)
}

/// The quadratic (6-node Lagrange) interpolation of six values at barycentrics `b` (nodes:
/// vertices 0, 1, 2, then the midpoints of edges 01, 12, 20).
///
/// # Accuracy
/// Exact (to rounding, 1e-6 on values of order 1) for values that are quadratic over the
/// triangle (`tests/speedups.rs::quadratic_interpolation_is_exact_for_quadratics`).
#[must_use]
#[inline]
pub fn quadratic_interpolate<T>(values: &[T; 6], b: Vec3) -> T
where
    T: Copy + core::ops::Mul<f32, Output = T> + core::ops::Add<Output = T>,
{
    let (a0, a1, a2) = (b.x, b.y, b.z);
    values[0] * (a0 * (2.0 * a0 - 1.0))
        + values[1] * (a1 * (2.0 * a1 - 1.0))
        + values[2] * (a2 * (2.0 * a2 - 1.0))
        + values[3] * (4.0 * a0 * a1)
        + values[4] * (4.0 * a1 * a2)
        + values[5] * (4.0 * a2 * a0)
}

/// Fast approximate Phong shading in the manner of Bishop and Weimer (1986): the smooth part of
/// the lighting and the key light's `cos α` are interpolated quadratically from six exact values
/// per triangle (prepared by [`fast_phong_vertices`]); per pixel only the power `(cos α)^n`
/// remains — no normalization, no vector algebra per light.
///
/// # Accuracy
/// On the 24 × 12 test sphere at 128² (shininess 40), against Phong shading: max error below
/// 0.03 per channel, mean error below a tenth of Gouraud's (measured: 0.022 and 7e-4, Gouraud
/// 0.25 and 0.011) (`tests/speedups.rs::fast_phong_error`).
#[derive(Clone, Copy, Debug)]
pub struct FastPhongShader<'a> {
    /// The scene (its camera and material are read).
    pub scene: &'a ShadeContext,
    /// The node table from [`fast_phong_vertices`].
    pub nodes: &'a [FastPhongNodes],
}

impl Shader for FastPhongShader<'_> {
    type Vertex = FastPhongVertex;
    type Varying = (Vec3, f32);
    fn vertex(&self, v: &FastPhongVertex) -> (Vec4, (Vec3, f32)) {
        (self.scene.clip(v.position), (v.corner, v.triangle))
    }
    fn fragment(&self, f: &Fragment<'_, (Vec3, f32)>) -> Option<Vec4> {
        let (b, triangle) = f.varying;
        // The constant index comes back within rounding of itself: round to the nearest.
        let nodes = self.nodes.get(triangle.round().max(0.0) as usize)?;
        let mut colour = quadratic_interpolate(&nodes.smooth, b);
        let c = quadratic_interpolate(&nodes.cos_alpha, b);
        colour += nodes.specular * crate::model::power(c, self.scene.material.shininess);
        Some(colour.max(Vec3::ZERO).extend(1.0))
    }
}
