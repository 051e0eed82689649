//! The options of [`crate::parameterize`]: method, segmentation threshold, distortion limits,
//! welding, seams, non-manifold policy.

use crate::UnwrapError;
use crate::embed::BoundaryShape;

/// The parameterization of each chart.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Method {
    /// Tutte's barycentric embedding (uniform weights), boundary on [`ParamOptions::boundary`].
    Tutte,
    /// Floater's mean-value embedding, boundary on [`ParamOptions::boundary`].
    MeanValue,
    /// The harmonic (cotangent-weight) embedding, boundary on [`ParamOptions::boundary`]. Not
    /// guaranteed bijective (negative weights); a chart it flips falls back to mean value.
    Harmonic,
    /// Least squares conformal maps with a free boundary; a chart it flips falls back to mean
    /// value.
    Lscm,
    /// LSCM (or its mean-value fallback), then as-rigid-as-possible refinement that never adds a
    /// flip.
    #[default]
    LscmArap,
}

/// What to do with a non-manifold edge or vertex.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NonManifold {
    /// Cut the surface there: triangles are not joined across a non-manifold edge, and a
    /// non-manifold vertex gets one chart vertex per fan.
    #[default]
    Cut,
    /// Fail with [`UnwrapError::NonManifoldEdge`] or [`UnwrapError::NonManifoldVertex`].
    Reject,
}

/// Options of [`crate::parameterize`].
#[derive(Clone, Debug, PartialEq)]
pub struct ParamOptions {
    /// The parameterization of each chart (default [`Method::LscmArap`]).
    pub method: Method,
    /// The boundary curve of the fixed-boundary methods (default circle).
    pub boundary: BoundaryShape,
    /// Segmentation threshold: a chart's triangle normals stay within this angle, in degrees,
    /// of the chart's mean normal (default 50; in `(0, 180]`). Smaller means more, flatter
    /// charts.
    pub cone_degrees: f64,
    /// A chart whose area-weighted mean angle distortion `σ1/σ2` exceeds this is split in two
    /// (default 1.5; at least 1; infinity never splits). Free-boundary methods only
    /// ([`Method::Lscm`], [`Method::LscmArap`]): a fixed boundary's distortion comes from the
    /// boundary curve, and halves of a chart are pinned to curves again.
    pub max_angle_distortion: f64,
    /// A chart whose area-weighted mean area distortion exceeds this is split in two (default
    /// 3; at least 1). Free-boundary methods only, as above.
    pub max_area_distortion: f64,
    /// ARAP iterations at most (default 20).
    pub max_iterations: u32,
    /// Weld vertices at equal positions before finding the connectivity (default `true`).
    pub weld: bool,
    /// Edges, as pairs of mesh vertices, that must be seams (charts never cross them).
    pub seams: Vec<[u32; 2]>,
    /// Non-manifold edges and vertices (default: cut there).
    pub non_manifold: NonManifold,
}

impl Default for ParamOptions {
    fn default() -> Self {
        Self {
            method: Method::LscmArap,
            boundary: BoundaryShape::Circle,
            // Measured with LscmArap against xatlas 0.0.11 (mean angle / area distortion; see
            // docs/report/unwrap.md): at 80° Suzanne gave 57 charts at 1.050 / 1.032 and the
            // 32×16 sphere 5 charts at 1.123 / 1.114, above xatlas's 1.032 / 1.100 and
            // 1.343 / 1.094 in one figure each; at 50° Suzanne gives 132 charts at 1.019 / 1.010,
            // the sphere 12 at 1.046 / 1.039, the torus 20 at 1.027 / 1.016 (xatlas 1.032 /
            // 1.056) and Avocado 20 at 1.021 / 1.015, every figure below xatlas's, with equal or
            // higher packing efficiency. Smaller cones (40°, 45°) lower distortion a little more
            // but cost efficiency (more padding between more charts). A cube's 90° creases are
            // never crossed at any cone below 90°.
            cone_degrees: 50.0,
            max_angle_distortion: 1.5,
            max_area_distortion: 3.0,
            max_iterations: 20,
            weld: true,
            seams: Vec::new(),
            non_manifold: NonManifold::Cut,
        }
    }
}

/// Checks the options against a mesh of `vertices` vertices.
pub(super) fn validate(options: &ParamOptions, vertices: u32) -> Result<(), UnwrapError> {
    if !(options.cone_degrees > 0.0 && options.cone_degrees <= 180.0) {
        return Err(UnwrapError::InvalidOption {
            name: "cone_degrees",
        });
    }
    if options.max_angle_distortion.is_nan() || options.max_angle_distortion < 1.0 {
        return Err(UnwrapError::InvalidOption {
            name: "max_angle_distortion",
        });
    }
    if options.max_area_distortion.is_nan() || options.max_area_distortion < 1.0 {
        return Err(UnwrapError::InvalidOption {
            name: "max_area_distortion",
        });
    }
    for (i, seam) in options.seams.iter().enumerate() {
        if let Some(&index) = seam.iter().find(|&&v| v >= vertices) {
            return Err(UnwrapError::IndexOutOfRange {
                triangle: i as u32,
                index,
                vertices,
            });
        }
    }
    Ok(())
}
