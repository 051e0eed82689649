//! The crate's error type.

use core::fmt;

/// Why a mesh could not be unwrapped.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum UnwrapError {
    /// A vertex position had a NaN or infinite coordinate.
    NonFinite {
        /// The vertex.
        vertex: u32,
    },
    /// A triangle named a vertex that does not exist.
    IndexOutOfRange {
        /// The triangle.
        triangle: u32,
        /// The index it named.
        index: u32,
        /// How many vertices there are.
        vertices: u32,
    },
    /// A mesh larger than the limits.
    TooLarge {
        /// What was too large.
        what: &'static str,
        /// The size given.
        requested: u64,
        /// The limit.
        limit: u64,
    },
    /// The charts could not be packed.
    Pack(crate::pack::PackError),
    /// An allocation the machine could not satisfy.
    OutOfMemory {
        /// What was being allocated.
        what: &'static str,
        /// The bytes asked for.
        bytes: u64,
    },
    /// A triangle names the same vertex twice (after welding, when welding is on).
    RepeatedIndex {
        /// The triangle.
        triangle: u32,
    },
    /// An edge shared by more than two triangles, or by two triangles that traverse it in the
    /// same direction (inconsistent orientation).
    NonManifoldEdge {
        /// One end of the edge.
        a: u32,
        /// The other end.
        b: u32,
    },
    /// A vertex whose triangles do not form one fan (two cones touching at a vertex).
    NonManifoldVertex {
        /// The vertex.
        vertex: u32,
    },
    /// A fixed-boundary embedding or LSCM was asked of a mesh that is not a topological disk.
    NotADisk {
        /// Connected components.
        components: u32,
        /// Boundary loops.
        boundary_loops: u32,
        /// Euler characteristic `V − E + F` of the whole mesh.
        euler_characteristic: i64,
    },
    /// An option out of its range (a NaN or negative threshold, zero iterations where at least
    /// one is needed).
    InvalidOption {
        /// The option.
        name: &'static str,
    },
}

impl fmt::Display for UnwrapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { vertex } => write!(f, "vertex {vertex} has a non-finite position"),
            Self::IndexOutOfRange {
                triangle,
                index,
                vertices,
            } => write!(
                f,
                "triangle {triangle} names vertex {index}, but there are {vertices} vertices"
            ),
            Self::TooLarge {
                what,
                requested,
                limit,
            } => write!(f, "{what}: {requested} exceeds the limit {limit}"),
            Self::Pack(e) => write!(f, "packing: {e}"),
            Self::OutOfMemory { what, bytes } => {
                write!(f, "out of memory allocating {bytes} bytes for {what}")
            }
            Self::RepeatedIndex { triangle } => {
                write!(f, "triangle {triangle} names the same vertex twice")
            }
            Self::NonManifoldEdge { a, b } => write!(
                f,
                "edge ({a}, {b}) is non-manifold: more than two triangles, or two with the same direction"
            ),
            Self::NonManifoldVertex { vertex } => {
                write!(
                    f,
                    "vertex {vertex} is non-manifold: its triangles form more than one fan"
                )
            }
            Self::NotADisk {
                components,
                boundary_loops,
                euler_characteristic,
            } => write!(
                f,
                "not a topological disk: {components} components, {boundary_loops} boundary loops, \
                 Euler characteristic {euler_characteristic}"
            ),
            Self::InvalidOption { name } => write!(f, "option {name} is out of range"),
        }
    }
}

impl core::error::Error for UnwrapError {}
