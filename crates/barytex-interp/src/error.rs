//! The crate's error type.

use core::fmt;

/// Why an interpolation could not be computed.
///
/// Every function of the interpolation core that can reject its input returns
/// `Result<_, InterpError>` (the crate's error convention, see the crate docs); the variants carry
/// enough context to say which input was wrong.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum InterpError {
    /// An input coordinate, weight or `w` was NaN or infinite.
    NonFinite {
        /// Which input: `"point"`, `"triangle"`, `"quad"`, `"weights"`, or a parameter's name
        /// (`"a"`, `"b"`, `"t"`, …) where the function's inputs are named points.
        what: &'static str,
    },
    /// A vector or quaternion that must give a direction has zero length.
    ZeroLength {
        /// Which input: `"a"` or `"b"`.
        what: &'static str,
    },
    /// A homogeneous `w` is zero or negative (a vertex at or behind the eye: clip first).
    NonPositiveW {
        /// Position of the `w`.
        index: usize,
        /// Its value.
        w: f32,
    },
    /// The result is a point at infinity: perspective-correct weights whose denominator
    /// `Σ αⱼ/wⱼ` is zero (the screen point lies on the vanishing line of the primitive).
    AtInfinity,
    /// The triangle has zero area (its vertices are exactly collinear), so barycentric
    /// coordinates do not exist.
    DegenerateTriangle,
    /// The quad collapses so that the bilinear map is not invertible anywhere (for example all
    /// four corners collinear).
    DegenerateQuad,
    /// The two endpoints of a segment coincide, so no parameter identifies a point on it.
    DegenerateSegment,
    /// Weights of an affine or convex combination do not sum to one.
    WeightsDoNotSumToOne {
        /// The sum, computed in f64.
        sum: f64,
    },
    /// Slices that must have one entry each per element have different lengths.
    LengthMismatch {
        /// Which slice.
        what: &'static str,
        /// Its length.
        len: usize,
        /// The length of the output slice, which the others must have.
        expected: usize,
    },
    /// A convex combination was given a negative weight.
    NegativeWeight {
        /// Position of the weight.
        index: usize,
        /// Its value.
        weight: f32,
    },
}

impl fmt::Display for InterpError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { what } => write!(f, "{what} has a NaN or infinite component"),
            Self::ZeroLength { what } => write!(f, "{what} has zero length, so no direction"),
            Self::NonPositiveW { index, w } => {
                write!(f, "w {index} is {w}, not positive (behind the eye)")
            }
            Self::AtInfinity => f.write_str("the result is a point at infinity"),
            Self::DegenerateTriangle => {
                f.write_str("triangle has zero area (its vertices are collinear)")
            }
            Self::DegenerateQuad => f.write_str("quad is degenerate: the bilinear map collapses"),
            Self::DegenerateSegment => f.write_str("segment endpoints coincide"),
            Self::WeightsDoNotSumToOne { sum } => {
                write!(f, "weights sum to {sum}, not 1")
            }
            Self::LengthMismatch {
                what,
                len,
                expected,
            } => {
                write!(f, "{what} has {len} entries, the output {expected}")
            }
            Self::NegativeWeight { index, weight } => {
                write!(
                    f,
                    "weight {index} is negative ({weight}) in a convex combination"
                )
            }
        }
    }
}

impl core::error::Error for InterpError {}
