//! Combined Gouraud and Phong shading (the Finnish lecture notes *Valaistus ja sävytys*, p. 290;
//! see the crate's [References](crate#references)): most polygons of a curved object show no
//! highlight, so Phong shading them all is wasted work. Every triangle is Gouraud shaded (which
//! keeps the edges between neighbours smooth), and only the triangles that pass a **highlight
//! test** (H-test) are shaded per pixel. The test has to look not only at the vertices but also
//! along the edges and inside, where a highlight can hide between vertices that miss it.

use barytex_raster::{Fragment, Shader};
use barytex_uv::TriMesh;
use glam::{Mat3, Vec3, Vec4};

use crate::ShadeContext;
use crate::context::valid_triangles;

/// The five-stage highlight test, after one pre-check: a triangle that faces away from the eye
/// (its geometric normal points away from the camera) is culled by the rasterizer, so it is not
/// tested at all ([`HighlightVerdict::BackFacing`]).
///
/// 1. A material without a specular term has no highlight anywhere: **reject**.
/// 2. Any vertex whose specular light reaches `threshold`: **accept**.
/// 3. Any of `edge_samples` evenly spaced points per edge (normal lerped and renormalized, as
///    Phong shading will see it) reaching `threshold`: **accept**.
/// 4. The peak of a lobe inside: for some light, the half vector `H` at the centroid is a
///    non-negative combination of the three vertex normals (the interpolated normal passes
///    through `H`, where `R·V = 1`), or the centroid reaches `threshold`: **accept**.
/// 5. Otherwise **reject**: Gouraud shading is within `threshold` of Phong shading's specular
///    term on this triangle (up to the lobe's variation between samples).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HighlightTest {
    /// Specular intensity (largest channel) that counts as visible; the default is half an
    /// 8-bit step, 0.5/255.
    pub threshold: f32,
    /// Points tested inside each edge (stage 3).
    pub edge_samples: u32,
}

impl Default for HighlightTest {
    fn default() -> Self {
        Self {
            threshold: 0.5 / 255.0,
            edge_samples: 3,
        }
    }
}

/// Which stage of the [`HighlightTest`] decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HighlightVerdict {
    /// The pre-check: the triangle faces away from the eye (or is degenerate).
    BackFacing,
    /// Stage 1: the material has no specular term.
    NoSpecular,
    /// Stage 2: this vertex shows the highlight.
    Vertex(usize),
    /// Stage 3: the edge from this vertex to the next shows it.
    Edge(usize),
    /// Stage 4: the lobe's peak or the centroid lies inside.
    Interior,
    /// Stage 5: no visible highlight.
    None,
}

impl HighlightVerdict {
    /// Whether the triangle needs Phong shading.
    #[must_use]
    pub fn has_highlight(self) -> bool {
        matches!(self, Self::Vertex(_) | Self::Edge(_) | Self::Interior)
    }
}

impl HighlightTest {
    /// Runs the test on one triangle (world-space positions and unit vertex normals).
    ///
    /// ```
    /// use barytex_shade::{Camera, HighlightTest, HighlightVerdict, Light, PhongMaterial, ShadeContext, ViewVector};
    /// use glam::Vec3;
    ///
    /// let scene = ShadeContext {
    ///     camera: Camera::look_at(Vec3::Z * 5.0, Vec3::ZERO, Vec3::Y, 1.0, 1.0, 0.1, 10.0).expect("ok"),
    ///     lights: vec![Light::Directional { direction: -Vec3::Z, color: Vec3::ONE }],
    ///     ambient: Vec3::ZERO,
    ///     material: PhongMaterial { shininess: 200.0, ..PhongMaterial::default() },
    ///     view: ViewVector::Local,
    /// };
    /// // A big triangle facing the eye and the light, whose vertex normals all miss the
    /// // mirror direction: the highlight is inside.
    /// let p = [Vec3::new(-2.0, -2.0, 0.0), Vec3::new(2.0, -2.0, 0.0), Vec3::new(0.0, 2.0, 0.0)];
    /// let n = [Vec3::new(-0.5, -0.5, 1.0).normalize(), Vec3::new(0.5, -0.5, 1.0).normalize(),
    ///          Vec3::new(0.0, 0.7, 1.0).normalize()];
    /// assert_eq!(HighlightTest::default().run(&scene, p, n), HighlightVerdict::Interior);
    /// ```
    #[must_use]
    pub fn run(&self, scene: &ShadeContext, p: [Vec3; 3], n: [Vec3; 3]) -> HighlightVerdict {
        let m = &scene.material;
        if m.specular.max_element() <= 0.0
            || matches!(m.lobe, crate::Specular::None)
            || scene.lights.is_empty()
        {
            return HighlightVerdict::NoSpecular;
        }
        let eye = scene.camera.eye;
        let centroid = (p[0] + p[1] + p[2]) / 3.0;
        match crate::face_normal(p[0], p[1], p[2]) {
            Some(face) if face.dot(eye - centroid) > 0.0 => {}
            _ => return HighlightVerdict::BackFacing,
        }
        let visible = |q: Vec3, normal: Vec3| {
            scene
                .light(q, normal.normalize_or_zero())
                .specular
                .max_element()
                >= self.threshold
        };
        for k in 0..3 {
            if visible(p[k], n[k]) {
                return HighlightVerdict::Vertex(k);
            }
        }
        let steps = self.edge_samples.min(1024);
        for k in 0..3 {
            let j = (k + 1) % 3;
            for s in 1..=steps {
                let t = s as f32 / (steps + 1) as f32;
                if visible(p[k].lerp(p[j], t), n[k].lerp(n[j], t)) {
                    return HighlightVerdict::Edge(k);
                }
            }
        }
        if visible(centroid, n[0] + n[1] + n[2]) {
            return HighlightVerdict::Interior;
        }
        let normals = Mat3::from_cols(n[0], n[1], n[2]);
        let det = normals.determinant();
        if det.abs() > 1e-9 && det.is_finite() {
            let inverse = normals.inverse();
            let v = scene.view_vector(centroid);
            for light in &scene.lights {
                let Some(sample) = light.sample(centroid) else {
                    continue;
                };
                if sample.intensity.max_element() <= 0.0 {
                    continue;
                }
                let Some(h) = (sample.to_light + v).try_normalize() else {
                    continue;
                };
                if (inverse * h).min_element() >= 0.0 {
                    return HighlightVerdict::Interior;
                }
            }
        }
        HighlightVerdict::None
    }
}

/// A vertex of the combined shader: its Gouraud colour, and the position and normal Phong
/// shading needs, with the triangle's H-test outcome (`1.0`: Phong; `0.0`: Gouraud; triangles
/// are unwelded so the flag is constant on each).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HybridVertex {
    /// World-space position.
    pub position: Vec3,
    /// Unit vertex normal.
    pub normal: Vec3,
    /// The Gouraud colour (the scene lit at this vertex).
    pub colour: Vec3,
    /// 1 if the triangle takes the Phong path, else 0.
    pub phong: f32,
}

/// How many triangles took each path.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct HybridStats {
    /// Triangles prepared.
    pub triangles: usize,
    /// Triangles that passed the H-test (Phong path).
    pub phong: usize,
    /// Triangles not tested because they face away from the eye.
    pub back_facing: usize,
    /// Decided by stage 2 (a vertex).
    pub by_vertex: usize,
    /// Decided by stage 3 (an edge).
    pub by_edge: usize,
    /// Decided by stage 4 (the interior).
    pub by_interior: usize,
}

/// Runs the [`HighlightTest`] on every triangle of `mesh` (back faces included; the rasterizer
/// culls) and builds the unwelded vertices of [`HybridShader`].
#[must_use]
pub fn hybrid_vertices(
    mesh: &TriMesh,
    scene: &ShadeContext,
    test: &HighlightTest,
) -> (Vec<HybridVertex>, Vec<u32>, HybridStats) {
    let colours: Vec<Vec3> = (0..mesh.positions.len())
        .map(|i| {
            let n = mesh.normals.get(i).copied().unwrap_or(Vec3::ZERO);
            scene
                .light(mesh.positions[i], n.normalize_or_zero())
                .total()
        })
        .collect();
    let mut stats = HybridStats::default();
    let mut vertices = Vec::with_capacity(mesh.indices.len() * 3);
    for tri in valid_triangles(mesh) {
        let p = tri.map(|i| mesh.positions[i as usize]);
        let n = tri.map(|i| {
            mesh.normals
                .get(i as usize)
                .copied()
                .unwrap_or(Vec3::ZERO)
                .normalize_or_zero()
        });
        let verdict = test.run(scene, p, n);
        stats.triangles += 1;
        match verdict {
            HighlightVerdict::Vertex(_) => stats.by_vertex += 1,
            HighlightVerdict::Edge(_) => stats.by_edge += 1,
            HighlightVerdict::Interior => stats.by_interior += 1,
            HighlightVerdict::BackFacing => stats.back_facing += 1,
            HighlightVerdict::NoSpecular | HighlightVerdict::None => {}
        }
        let phong = if verdict.has_highlight() {
            stats.phong += 1;
            1.0
        } else {
            0.0
        };
        for k in 0..3 {
            vertices.push(HybridVertex {
                position: p[k],
                normal: n[k],
                colour: colours[tri[k] as usize],
                phong,
            });
        }
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices, stats)
}

/// Gouraud shading everywhere, Phong shading on the triangles that passed the highlight test.
#[derive(Clone, Copy, Debug)]
pub struct HybridShader<'a> {
    /// Camera, lights, material.
    pub scene: &'a ShadeContext,
}

impl Shader for HybridShader<'_> {
    type Vertex = HybridVertex;
    type Varying = (Vec3, Vec3, Vec3, f32);
    fn vertex(&self, v: &HybridVertex) -> (Vec4, (Vec3, Vec3, Vec3, f32)) {
        (
            self.scene.clip(v.position),
            (v.colour, v.position, v.normal, v.phong),
        )
    }
    fn fragment(&self, f: &Fragment<'_, (Vec3, Vec3, Vec3, f32)>) -> Option<Vec4> {
        let (colour, p, n, phong) = f.varying;
        if phong > 0.5 {
            Some(
                self.scene
                    .light(p, n.normalize_or_zero())
                    .total()
                    .extend(1.0),
            )
        } else {
            Some(colour.extend(1.0))
        }
    }
}
