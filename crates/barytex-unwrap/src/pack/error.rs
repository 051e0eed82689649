//! Why charts could not be packed.

use core::fmt;

/// Why charts could not be packed.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum PackError {
    /// A [`PackOptions`](super::PackOptions) field out of range.
    Options(&'static str),
    /// Even at the smallest scale (each chart one texel plus padding) the charts do not fit.
    TooManyCharts {
        /// The charts to pack.
        charts: usize,
        /// The texture side.
        size: u32,
        /// The padding.
        padding: u32,
    },
    /// A chart's uvs were not finite.
    NonFinite {
        /// The chart.
        chart: usize,
    },
}

impl fmt::Display for PackError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Options(what) => write!(f, "pack options: {what}"),
            Self::TooManyCharts {
                charts,
                size,
                padding,
            } => write!(
                f,
                "{charts} charts do not fit a {size}×{size} atlas with {padding} texels of \
                 padding even at one texel each; use a larger size or a smaller padding"
            ),
            Self::NonFinite { chart } => write!(f, "chart {chart} has non-finite uvs"),
        }
    }
}

impl core::error::Error for PackError {}
