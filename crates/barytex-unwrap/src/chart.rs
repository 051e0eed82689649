//! The output: a chart, one flattened piece of the surface.

use glam::DVec2;

/// One piece of the surface with its texture coordinates.
///
/// A chart has its own vertices (a mesh vertex on a seam appears in every chart that touches
/// it): chart vertex `i` is mesh vertex `vertices[i]` with texture coordinate `uvs[i]`, and
/// chart triangle `j` (indices into the chart's vertices) is mesh triangle `faces[j]`, with its
/// corners in the mesh triangle's order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chart {
    /// The mesh triangle of each chart triangle.
    pub faces: Vec<u32>,
    /// The mesh vertex of each chart vertex.
    pub vertices: Vec<u32>,
    /// Chart triangles, as indices into [`Chart::vertices`] and [`Chart::uvs`].
    pub triangles: Vec<[u32; 3]>,
    /// The texture coordinate of each chart vertex.
    pub uvs: Vec<DVec2>,
}
