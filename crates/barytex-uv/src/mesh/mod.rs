//! Parametric meshes: plane, cube, cylinder, sphere and torus as indexed triangle meshes with
//! positions, unit normals, tangents and uvs, at a resolution the caller chooses.
//!
//! Conventions shared by every generator (each checked by `crates/barytex-uv/tests/meshes.rs`):
//! - **Seams are duplicated**: the `u = 0` and `u = 1` columns (and the torus's `v = 0` and
//!   `v = 1` rows, the cube's face borders, the cylinder's cap rims) are separate vertices with
//!   *bit-identical* positions, so welding equal positions closes the surface and no triangle
//!   spans more than half the texture.
//! - **Winding** is counter-clockwise seen from outside: `(b − a) × (c − a)` points along the
//!   vertex normals.
//! - **uv** follows glTF: `(0, 0)` is the image's top-left, `v` down; every mapping is
//!   non-mirrored (the texture reads left-to-right, top-to-bottom when the surface is seen from
//!   outside).
//! - **Tangents** (`xyz`) are unit vectors along `∂p/∂u`, orthogonalised against the normal;
//!   `w = ±1` is glTF's handedness: the bitangent `w·(n × t)` points toward *decreasing* `v`
//!   (up in the image). All generated meshes have `w = +1`.
//! - Poles (the sphere's) keep one vertex per column, at the column's middle `u`, and the
//!   triangles that would have zero area there are left out.
//! - Requests larger than [`MAX_VERTICES`] are refused with [`UvError::TooLarge`](crate::UvError::TooLarge) before anything
//!   is allocated; a resolution below a shape's minimum gives [`UvError::OutOfRange`](crate::UvError::OutOfRange).
//!
//! ```
//! use barytex_uv::mesh;
//!
//! let sphere = mesh::sphere(32, 16).expect("a valid resolution");
//! assert!(sphere.validate().is_ok());
//! // The seam column is duplicated: 33 columns × 17 rows.
//! assert_eq!(sphere.positions.len(), 33 * 17);
//! assert!(mesh::sphere(0, 16).is_err());
//! ```

mod builder;
mod cube;
mod cylinder;
mod plane;
mod sphere;
mod torus;

use core::fmt;

use glam::{Vec2, Vec3, Vec4};

pub use cube::cube;
pub use cylinder::cylinder;
pub use plane::plane;
pub use sphere::{SphereUv, sphere, sphere_with};
pub use torus::torus;

/// The most vertices a generator will build (4 Mi: about 300 MiB with 72 bytes of attributes and
/// indices per vertex).
pub const MAX_VERTICES: u64 = 1 << 22;

/// Largest `| |n| − 1 |` that [`TriMesh::validate`] accepts for a normal or tangent.
pub const UNIT_TOLERANCE: f32 = 1e-4;

/// Largest `|n · t|` that [`TriMesh::validate`] accepts between a normal and its tangent.
pub const ORTHOGONAL_TOLERANCE: f32 = 1e-4;

/// An indexed triangle mesh with per-vertex attributes (all attribute arrays have one entry per
/// vertex).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriMesh {
    /// Object-space positions.
    pub positions: Vec<Vec3>,
    /// Unit normals, pointing outward.
    pub normals: Vec<Vec3>,
    /// Unit tangent along `∂p/∂u` in `xyz`; handedness `w = ±1` (glTF).
    pub tangents: Vec<Vec4>,
    /// Texture coordinates, `(0, 0)` top-left, `v` down.
    pub uvs: Vec<Vec2>,
    /// Counter-clockwise (seen from outside) triangles.
    pub indices: Vec<[u32; 3]>,
}

/// The first defect [`TriMesh::validate`] found.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum MeshDefect {
    /// The attribute arrays have different lengths.
    LengthMismatch {
        /// Which array differs from `positions`.
        what: &'static str,
        /// Its length.
        len: usize,
        /// The number of positions.
        positions: usize,
    },
    /// A triangle refers to a vertex that does not exist.
    IndexOutOfRange {
        /// The triangle.
        triangle: usize,
        /// The index it holds.
        index: u32,
    },
    /// An attribute of a vertex is NaN or infinite.
    NonFinite {
        /// The vertex.
        vertex: usize,
        /// Which attribute.
        what: &'static str,
    },
    /// A normal or tangent is not of unit length (within [`UNIT_TOLERANCE`]), or a handedness is
    /// not ±1.
    NotUnit {
        /// The vertex.
        vertex: usize,
        /// Which attribute.
        what: &'static str,
    },
    /// A tangent is not orthogonal to its normal (within [`ORTHOGONAL_TOLERANCE`]).
    TangentNotOrthogonal {
        /// The vertex.
        vertex: usize,
    },
}

impl fmt::Display for MeshDefect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::LengthMismatch {
                what,
                len,
                positions,
            } => write!(f, "{what} has {len} entries for {positions} positions"),
            Self::IndexOutOfRange { triangle, index } => {
                write!(f, "triangle {triangle} refers to missing vertex {index}")
            }
            Self::NonFinite { vertex, what } => write!(f, "vertex {vertex}: {what} is not finite"),
            Self::NotUnit { vertex, what } => write!(f, "vertex {vertex}: {what} is not unit"),
            Self::TangentNotOrthogonal { vertex } => {
                write!(
                    f,
                    "vertex {vertex}: tangent is not orthogonal to the normal"
                )
            }
        }
    }
}

impl core::error::Error for MeshDefect {}

impl TriMesh {
    /// Checks the mesh's invariants: equal attribute counts, indices in range, finite
    /// attributes, unit normals and tangents, `w = ±1`, tangents orthogonal to normals.
    ///
    /// # Errors
    /// The first [`MeshDefect`] found.
    ///
    /// ```
    /// use barytex_uv::mesh::{self, MeshDefect};
    ///
    /// let mut plane = mesh::plane(2, 2).expect("valid");
    /// assert!(plane.validate().is_ok());
    /// plane.indices.push([0, 1, 99]);
    /// assert!(matches!(plane.validate(), Err(MeshDefect::IndexOutOfRange { index: 99, .. })));
    /// ```
    pub fn validate(&self) -> Result<(), MeshDefect> {
        let positions = self.positions.len();
        for (what, len) in [
            ("normals", self.normals.len()),
            ("tangents", self.tangents.len()),
            ("uvs", self.uvs.len()),
        ] {
            if len != positions {
                return Err(MeshDefect::LengthMismatch {
                    what,
                    len,
                    positions,
                });
            }
        }
        for (triangle, corners) in self.indices.iter().enumerate() {
            if let Some(&index) = corners.iter().find(|&&i| i as usize >= positions) {
                return Err(MeshDefect::IndexOutOfRange { triangle, index });
            }
        }
        let unit = |x: f32| (x - 1.0).abs() <= UNIT_TOLERANCE;
        for vertex in 0..positions {
            let (p, n, t, uv) = (
                self.positions[vertex],
                self.normals[vertex],
                self.tangents[vertex],
                self.uvs[vertex],
            );
            for (what, finite) in [
                ("position", p.is_finite()),
                ("normal", n.is_finite()),
                ("tangent", t.is_finite()),
                ("uv", uv.is_finite()),
            ] {
                if !finite {
                    return Err(MeshDefect::NonFinite { vertex, what });
                }
            }
            if !unit(n.length()) {
                return Err(MeshDefect::NotUnit {
                    vertex,
                    what: "normal",
                });
            }
            if !unit(t.truncate().length()) {
                return Err(MeshDefect::NotUnit {
                    vertex,
                    what: "tangent",
                });
            }
            if t.w.abs() != 1.0 {
                return Err(MeshDefect::NotUnit {
                    vertex,
                    what: "handedness",
                });
            }
            if n.dot(t.truncate()).abs() > ORTHOGONAL_TOLERANCE {
                return Err(MeshDefect::TangentNotOrthogonal { vertex });
            }
        }
        Ok(())
    }
}
