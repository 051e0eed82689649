//! What [`crate::parameterize_with_report`] tells besides the charts.

use crate::arap::ArapReport;
use crate::sparse::SolveReport;
use crate::{Chart, Method};

/// How one chart was made.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChartReport {
    /// The method that produced the chart's uvs (the requested one, or the fallback).
    pub method: Option<Method>,
    /// Whether the requested method flipped a triangle and a fallback was used.
    pub fell_back: bool,
    /// Flips of the requested method before any fallback.
    pub flips_before_fallback: usize,
    /// The linear solve of the embedding (or LSCM).
    pub solve: SolveReport,
    /// The ARAP refinement, for [`Method::LscmArap`].
    pub arap: Option<ArapReport>,
    /// A chart made of one degenerate triangle (zero area or a repeated vertex), laid out as a
    /// right triangle rather than parameterized.
    pub degenerate: bool,
}

/// The charts with a report per chart and counts for the whole mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Parameterization {
    /// The charts.
    pub charts: Vec<Chart>,
    /// One report per chart, in the same order.
    pub reports: Vec<ChartReport>,
    /// Regions split because they were not disks, flipped, or exceeded the distortion limits.
    pub splits: usize,
    /// Edges where the surface was cut because they were non-manifold (each counted once per
    /// half-edge left unjoined).
    pub non_manifold_half_edges: usize,
}
