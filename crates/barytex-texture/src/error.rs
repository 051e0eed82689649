//! The crate's error type.

use core::fmt;

/// Why a texture could not be built, loaded or sampled with the given parameters.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum TextureError {
    /// A width or height of zero.
    Empty {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// Larger than the [`Limits`](crate::Limits) allow; nothing was allocated.
    TooLarge {
        /// What was too large (`"width"`, `"height"`, `"bytes"`, …).
        what: &'static str,
        /// The size asked for.
        requested: u64,
        /// The limit.
        limit: u64,
    },
    /// The allocator could not provide the memory.
    OutOfMemory {
        /// Bytes asked for.
        bytes: u64,
    },
    /// A texel buffer whose length does not match `width × height`.
    DataLength {
        /// Texels needed.
        expected: u64,
        /// Texels given.
        actual: u64,
    },
    /// A parameter was NaN, infinite or out of its range.
    InvalidParameter {
        /// Which parameter.
        what: &'static str,
        /// Why it was refused.
        reason: &'static str,
    },
    /// An image could not be decoded or read.
    Decode(String),
}

impl fmt::Display for TextureError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Empty { width, height } => {
                write!(f, "a {width}×{height} texture has no texels")
            }
            Self::TooLarge {
                what,
                requested,
                limit,
            } => write!(f, "{what} {requested} exceeds the limit {limit}"),
            Self::OutOfMemory { bytes } => write!(f, "could not allocate {bytes} bytes"),
            Self::DataLength { expected, actual } => {
                write!(f, "expected {expected} texels, got {actual}")
            }
            Self::InvalidParameter { what, reason } => write!(f, "{what}: {reason}"),
            Self::Decode(message) => write!(f, "could not decode the image: {message}"),
        }
    }
}

impl std::error::Error for TextureError {}
