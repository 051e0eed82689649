//! The input: an indexed triangle mesh, validated once.

use glam::DVec3;

use crate::UnwrapError;

/// The most vertices an [`UnwrapMesh`] may have (16 Mi).
pub const MAX_VERTICES: usize = 1 << 24;

/// The most triangles an [`UnwrapMesh`] may have (16 Mi).
pub const MAX_TRIANGLES: usize = 1 << 24;

/// An indexed triangle mesh to unwrap: positions (f64, so glTF's f32 positions are exact) and
/// counter-clockwise triangles. Built by [`UnwrapMesh::new`], which checks every index and
/// position, so later stages never meet an out-of-range index or a NaN.
///
/// ```
/// use barytex_unwrap::UnwrapMesh;
/// use glam::DVec3;
///
/// let square = UnwrapMesh::new(
///     vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
///     vec![[0, 1, 2], [0, 2, 3]],
/// )
/// .expect("a valid mesh");
/// assert_eq!(square.triangles().len(), 2);
/// assert!(UnwrapMesh::new(vec![DVec3::ZERO], vec![[0, 1, 2]]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct UnwrapMesh {
    positions: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
}

impl UnwrapMesh {
    /// Checks and wraps a mesh.
    ///
    /// # Errors
    /// [`UnwrapError::TooLarge`] beyond [`MAX_VERTICES`] or [`MAX_TRIANGLES`],
    /// [`UnwrapError::NonFinite`] for a NaN or infinite coordinate,
    /// [`UnwrapError::IndexOutOfRange`] for an index past the last vertex. Degenerate triangles
    /// (repeated indices, zero area) are accepted here; the stages that cannot use them say so.
    pub fn new(positions: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<Self, UnwrapError> {
        if positions.len() > MAX_VERTICES {
            return Err(UnwrapError::TooLarge {
                what: "vertices",
                requested: positions.len() as u64,
                limit: MAX_VERTICES as u64,
            });
        }
        if triangles.len() > MAX_TRIANGLES {
            return Err(UnwrapError::TooLarge {
                what: "triangles",
                requested: triangles.len() as u64,
                limit: MAX_TRIANGLES as u64,
            });
        }
        if let Some(vertex) = positions.iter().position(|p| !p.is_finite()) {
            // Bounded by MAX_VERTICES above.
            return Err(UnwrapError::NonFinite {
                vertex: vertex as u32,
            });
        }
        let vertices = positions.len() as u32;
        for (triangle, corners) in triangles.iter().enumerate() {
            if let Some(&index) = corners.iter().find(|&&i| i >= vertices) {
                return Err(UnwrapError::IndexOutOfRange {
                    triangle: triangle as u32,
                    index,
                    vertices,
                });
            }
        }
        Ok(Self {
            positions,
            triangles,
        })
    }

    /// The vertex positions.
    #[must_use]
    pub fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// The triangles, counter-clockwise seen from the front.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }
}
