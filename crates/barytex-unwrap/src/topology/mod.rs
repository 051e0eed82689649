//! Mesh topology: half-edges, boundary loops, components, Euler characteristic and genus,
//! non-manifold detection, welding of equal positions.

mod halfedge;
mod weld;

pub use halfedge::{Component, HalfEdgeMesh, NONE};
pub use weld::weld_positions;

use crate::{UnwrapError, UnwrapMesh};

/// Options of [`mesh_topology`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TopologyOptions {
    /// Weld vertices at equal positions first ([`weld_positions`]); default `true`.
    pub weld: bool,
}

impl Default for TopologyOptions {
    fn default() -> Self {
        Self { weld: true }
    }
}

/// The half-edge view of `mesh`, after welding when asked. The half-edge mesh's vertex `v` is
/// mesh vertex `v` (a welded vertex keeps the lowest index of its position; the others become
/// unused).
///
/// ```
/// use barytex_unwrap::{mesh_topology, TopologyOptions, UnwrapMesh};
/// use glam::DVec3;
///
/// // Two triangles with their own copies of the shared edge's vertices.
/// let p = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::X, DVec3::ONE, DVec3::Y];
/// let mesh = UnwrapMesh::new(p, vec![[0, 1, 2], [3, 4, 5]]).expect("valid");
/// let welded = mesh_topology(&mesh, TopologyOptions { weld: true }).expect("manifold");
/// assert_eq!(welded.components().len(), 1);
/// let apart = mesh_topology(&mesh, TopologyOptions { weld: false }).expect("manifold");
/// assert_eq!(apart.components().len(), 2);
/// ```
///
/// # Errors
/// As [`HalfEdgeMesh::from_triangles`]: repeated indices, non-manifold edges and vertices.
pub fn mesh_topology(
    mesh: &UnwrapMesh,
    options: TopologyOptions,
) -> Result<HalfEdgeMesh, UnwrapError> {
    let n = mesh.positions().len() as u32;
    if options.weld {
        let map = weld_positions(mesh.positions());
        let triangles: Vec<[u32; 3]> = mesh
            .triangles()
            .iter()
            .map(|t| t.map(|v| map[v as usize]))
            .collect();
        HalfEdgeMesh::from_triangles(n, &triangles)
    } else {
        HalfEdgeMesh::from_triangles(n, mesh.triangles())
    }
}
