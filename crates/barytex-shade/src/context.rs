//! What every shader of this crate needs: the camera, the lights, the ambient light, one
//! material, and how the view vector is found; plus the vertex type built from a
//! [`barytex_uv::TriMesh`].

use barytex_uv::TriMesh;
use glam::{Vec2, Vec3, Vec4};

use crate::{Camera, Light, Lighting, PhongMaterial};

/// How the vector `V` from the surface to the eye is found.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum ViewVector {
    /// `V = (eye − p)/|eye − p|` at every point (exact).
    #[default]
    Local,
    /// One constant unit `V` everywhere (a speed-up of the Finnish lecture notes *Valaistus ja
    /// sävytys*, p. 292: "the vector from the points to the eye can be imagined constant [0, 0,
    /// 1]"): no subtraction or normalization per point, but highlights shift and a whole polygon
    /// can flash when its mirror direction meets `V`.
    Constant(Vec3),
}

/// Camera, lights and material: the uniforms of this crate's shaders. Positions and normals are
/// in world space (transform meshes before drawing).
#[derive(Clone, Debug, PartialEq)]
pub struct ShadeContext {
    /// The camera.
    pub camera: Camera,
    /// The light sources.
    pub lights: Vec<Light>,
    /// The ambient intensity `I_a`.
    pub ambient: Vec3,
    /// The surface's material.
    pub material: PhongMaterial,
    /// How `V` is found.
    pub view: ViewVector,
}

impl ShadeContext {
    /// The unit view vector at `p` (zero when `p` is at the eye or not finite).
    #[must_use]
    #[inline]
    pub fn view_vector(&self, p: Vec3) -> Vec3 {
        match self.view {
            ViewVector::Local => (self.camera.eye - p).normalize_or_zero(),
            ViewVector::Constant(v) => v,
        }
    }

    /// The scene's material lit at `p` with the unit normal `n`.
    #[must_use]
    #[inline]
    pub fn light(&self, p: Vec3, n: Vec3) -> Lighting {
        self.light_with(&self.material, p, n)
    }

    /// `material` lit at `p` with the unit normal `n` (for textured materials).
    #[must_use]
    #[inline]
    pub fn light_with(&self, material: &PhongMaterial, p: Vec3, n: Vec3) -> Lighting {
        material.shade(p, n, self.view_vector(p), &self.lights, self.ambient)
    }

    /// `p` in clip space.
    #[must_use]
    #[inline]
    pub fn clip(&self, p: Vec3) -> Vec4 {
        self.camera.view_projection() * p.extend(1.0)
    }
}

/// One vertex of a mesh as the shaders read it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ShadeVertex {
    /// World-space position.
    pub position: Vec3,
    /// Unit normal (zero when unknown).
    pub normal: Vec3,
    /// Texture coordinate.
    pub uv: Vec2,
    /// Unit tangent with glTF handedness in `w` (zero when unknown).
    pub tangent: Vec4,
}

/// The vertices of `mesh` (missing attributes are zero) and its indices flattened, ready for
/// [`barytex_raster::draw`].
///
/// ```
/// let sphere = barytex_uv::mesh::sphere(8, 4).expect("valid");
/// let (vertices, indices) = barytex_shade::mesh_vertices(&sphere);
/// assert_eq!(vertices.len(), sphere.positions.len());
/// assert_eq!(indices.len(), 3 * sphere.indices.len());
/// ```
#[must_use]
pub fn mesh_vertices(mesh: &TriMesh) -> (Vec<ShadeVertex>, Vec<u32>) {
    let vertices = (0..mesh.positions.len())
        .map(|i| ShadeVertex {
            position: mesh.positions[i],
            normal: mesh.normals.get(i).copied().unwrap_or(Vec3::ZERO),
            uv: mesh.uvs.get(i).copied().unwrap_or(Vec2::ZERO),
            tangent: mesh.tangents.get(i).copied().unwrap_or(Vec4::ZERO),
        })
        .collect();
    (vertices, mesh.indices.iter().flatten().copied().collect())
}

/// The triangles of `mesh` whose three indices are in range, as position triples.
pub(crate) fn valid_triangles(mesh: &TriMesh) -> impl Iterator<Item = [u32; 3]> + '_ {
    let n = mesh.positions.len();
    mesh.indices
        .iter()
        .copied()
        .filter(move |t| t.iter().all(|&i| (i as usize) < n))
}
