//! The crate's error type.

use core::fmt;

/// Why a mapping, mesh or picture could not be built.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum UvError {
    /// A parameter was NaN or infinite.
    NonFinite {
        /// Which parameter.
        what: &'static str,
    },
    /// A parameter was out of its range (a radius ≤ 0, a degenerate frame, a zero resolution…).
    OutOfRange {
        /// Which parameter.
        what: &'static str,
        /// The value given.
        value: f64,
    },
    /// A picture or mesh larger than the caller's limits.
    TooLarge {
        /// What was too large.
        what: &'static str,
        /// The size asked for.
        requested: u64,
        /// The limit.
        limit: u64,
    },
    /// Writing a picture failed.
    Io(String),
}

impl fmt::Display for UvError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { what } => write!(f, "{what} is not finite"),
            Self::OutOfRange { what, value } => write!(f, "{what} = {value} is out of range"),
            Self::TooLarge {
                what,
                requested,
                limit,
            } => write!(f, "{what}: {requested} exceeds the limit {limit}"),
            Self::Io(message) => write!(f, "i/o: {message}"),
        }
    }
}

impl core::error::Error for UvError {}
