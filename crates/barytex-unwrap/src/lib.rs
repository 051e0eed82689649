//! Mesh UV parameterization: texture coordinates for an arbitrary triangle mesh.
//!
//! A user with a scanned model, a glTF without `TEXCOORD_0`, or a lightmap bake that needs a
//! second uv set gives an indexed triangle mesh ([`UnwrapMesh`]) and gets back charts
//! ([`Chart`]): pieces of the surface, each a topological disk, each flattened without a flipped
//! triangle (decided by exact orientation predicates), packed into the unit square.
//!
//! - [`parameterize`]: the pipeline — welding, segmentation into disk charts, one
//!   parameterization per chart ([`Method`]), exact flip checks with fallbacks;
//! - the pieces on their own: [`mesh_topology`] / [`HalfEdgeMesh`] (boundary loops, genus,
//!   non-manifold detection), [`embed_disk`] (Tutte, mean value, harmonic), [`lscm`],
//!   [`arap_refine`];
//! - measures: [`flipped_triangles`] (exact), [`chart_stats`] / [`atlas_stats`] (angle and area
//!   distortion, L2 stretch);
//! - [`shapes`]: generated spheres, tori, cubes and height-field grids to try it on.
//!
//! ```
//! use barytex_unwrap::{ParamOptions, flipped_triangles, parameterize, shapes};
//!
//! let sphere = shapes::sphere(12, 24); // closed: it must be cut into disks
//! let charts = parameterize(&sphere, &ParamOptions::default()).expect("unwrapped");
//! assert!(charts.len() > 1);
//! assert!(charts.iter().all(|c| flipped_triangles(c) == 0));
//! assert_eq!(charts.iter().map(|c| c.faces.len()).sum::<usize>(), sphere.triangles().len());
//! ```
//!
//! # References
//! - W. T. Tutte, "How to draw a graph", *Proc. London Math. Soc.* (3) 13, 1963: a
//!   convex-combination embedding of a 3-connected planar graph with a convex boundary is a
//!   bijection.
//! - M. S. Floater, "Mean value coordinates", *Computer Aided Geometric Design* 20(1), 2003.
//! - M. S. Floater, "One-to-one piecewise linear mappings over triangulations", *Mathematics of
//!   Computation* 72(242), 2003.
//! - B. Lévy, S. Petitjean, N. Ray, J. Maillot, "Least squares conformal maps for automatic
//!   texture atlas generation", *ACM Trans. Graph.* 21(3) (SIGGRAPH), 2002.
//! - L. Liu, L. Zhang, Y. Xu, C. Gotsman, S. J. Gortler, "A local/global approach to mesh
//!   parameterization", *Computer Graphics Forum* 27(5) (SGP), 2008.
//! - U. Pinkall, K. Polthier, "Computing discrete minimal surfaces and their conjugates",
//!   *Experimental Mathematics* 2(1), 1993 (the cotangent weights).
//! - P. V. Sander, J. Snyder, S. J. Gortler, H. Hoppe, "Texture mapping progressive meshes",
//!   *SIGGRAPH* 2001 (the stretch and conformality measures).
//! - T. A. Davis, "Algorithm 849: A concise sparse Cholesky factorization package", *ACM Trans.
//!   Math. Softw.* 31(4), 2005 (the sparse `L D Lᵀ`).
//! - J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
//!   predicates", *Discrete & Computational Geometry* 18(3), 1997 (the exact `orient2d`).

mod alloc;
mod arap;
mod atlas;
mod chart;
mod check;
mod distortion;
mod embed;
mod error;
mod geometry;
mod lscm;
mod mesh;
pub mod overlap;
pub mod pack;
mod param;
mod segment;
pub mod shapes;
mod sparse;
mod topology;

pub use arap::{ArapReport, BACKTRACKS, arap_refine};
pub use atlas::{
    Atlas, AtlasCheck, ChartMethod, MIN_ASPECT, StageTimes, UnwrapOptions, check_atlas, unwrap,
};
pub use chart::Chart;
pub use check::{flipped_triangles, is_positively_oriented};
pub use distortion::{ChartStats, atlas_stats, chart_stats};
pub use embed::{BoundaryShape, Embedding, Weights, embed_disk};
pub use error::UnwrapError;
pub use lscm::lscm;
pub use mesh::{MAX_TRIANGLES, MAX_VERTICES, UnwrapMesh};
pub use param::{
    ChartReport, Method, NonManifold, ParamOptions, Parameterization, parameterize,
    parameterize_with_report,
};
pub use sparse::SolveReport;
pub use topology::{Component, HalfEdgeMesh, NONE, TopologyOptions, mesh_topology, weld_positions};

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
