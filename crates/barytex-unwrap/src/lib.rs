//! Mesh UV parameterization: texture coordinates for an arbitrary triangle mesh.
//!
//! A user with a scanned model, a glTF without `TEXCOORD_0`, or a lightmap bake that needs a
//! second uv set gives an indexed triangle mesh ([`UnwrapMesh`]) and gets back charts
//! ([`Chart`]): pieces of the surface, each a topological disk, each flattened without a flipped
//! triangle (decided by exact orientation predicates), packed into the unit square.
//!
//! # References
//! - W. T. Tutte, "How to draw a graph", *Proc. London Math. Soc.* (3) 13, 1963: a
//!   convex-combination embedding of a 3-connected planar graph with a convex boundary is a
//!   bijection.
//! - M. S. Floater, "Mean value coordinates", *Computer Aided Geometric Design* 20(1), 2003.
//! - B. Lévy, S. Petitjean, N. Ray, J. Maillot, "Least squares conformal maps for automatic
//!   texture atlas generation", *ACM Trans. Graph.* 21(3) (SIGGRAPH), 2002.
//! - J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
//!   predicates", *Discrete & Computational Geometry* 18(3), 1997 (the exact `orient2d`).

mod atlas;
mod chart;
mod error;
mod mesh;
pub mod overlap;
pub mod pack;

pub use atlas::{
    Atlas, AtlasCheck, MIN_ASPECT, Method, StageTimes, UnwrapOptions, check_atlas, unwrap,
};
pub use chart::Chart;
pub use error::UnwrapError;
pub use mesh::{MAX_TRIANGLES, MAX_VERTICES, UnwrapMesh};

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
