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
        }
    }
}

impl core::error::Error for UnwrapError {}
