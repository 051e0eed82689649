//! Generalized barycentric coordinates over convex polygons (Wachspress, mean value).
//!
//! Splitting a quad or pentagon into triangles and interpolating per triangle makes the result
//! depend on the split: interpolated shading of a polygon that is not a triangle depends on the
//! polygon's orientation on screen (Foley, van Dam, Feiner and Hughes, *Computer Graphics:
//! Principles and Practice*, 2nd ed., 1990, "Problems with interpolated shading"). Generalized barycentric coordinates give every vertex one smooth weight
//! over the whole polygon instead: the weights are non-negative inside, sum to one, reproduce
//! the point (`Σ λᵢ·vᵢ = p`, linear precision), equal the ordinary barycentric coordinates on a
//! triangle, are linear along each edge and do not depend on where the vertex list starts.
//!
//! - [`wachspress_weights`]: rational functions of signed areas; needs a *strictly* convex
//!   polygon.
//! - [`mean_value_weights`]: Floater's mean value coordinates (Hormann & Floater's signed-angle
//!   form); also accepts vertices with collinear neighbours.
//!
//! Both classify the point exactly first (exact orientation signs): on a vertex the weights are
//! exactly that vertex's unit vector, on an edge exactly the linear interpolation along it with
//! every other weight `+0.0`.

mod mean_value;
mod shape;
mod wachspress;

use core::fmt;

use glam::Vec2;

use crate::Interpolate;

pub use mean_value::mean_value_weights;
pub use wachspress::wachspress_weights;

/// Where a point lies relative to a convex polygon, decided exactly.
///
/// Edge `i` runs from vertex `i` to vertex `i + 1` (cyclically): unlike a triangle's
/// [`Location`](crate::Location), where edge `i` is opposite vertex `i`, a polygon's edge has no
/// opposite vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PolygonLocation {
    /// Strictly inside: every weight is non-negative (positive unless it underflows f32).
    Inside,
    /// On the relative interior of edge `i` (from vertex `i` to vertex `(i + 1) % n`): the two
    /// weights of that edge are the linear interpolation along it, every other weight is `+0.0`.
    OnEdge(usize),
    /// Exactly on vertex `i`: weight `i` is `1.0`, every other weight `+0.0`.
    OnVertex(usize),
    /// Outside the closed polygon: the weights extrapolate, and at least one is negative.
    Outside,
}

impl PolygonLocation {
    /// Inside or on the boundary (edge or vertex) of the polygon.
    #[must_use]
    pub fn is_inside_closed(self) -> bool {
        !matches!(self, Self::Outside)
    }
}

/// Why generalized barycentric coordinates could not be computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum PolygonError {
    /// The polygon has fewer than three vertices.
    TooFewVertices {
        /// How many it has.
        count: usize,
    },
    /// The weights buffer does not have one entry per vertex.
    WeightsLength {
        /// Vertices of the polygon.
        vertices: usize,
        /// Length of the weights buffer.
        weights: usize,
    },
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// `"point"` or `"polygon"`.
        what: &'static str,
    },
    /// Vertex `index` equals the next vertex (cyclically): a zero-length edge.
    RepeatedVertex {
        /// The first of the two equal vertices.
        index: usize,
    },
    /// Every vertex lies on one line: the polygon has zero area.
    Collinear,
    /// The polygon is not convex at `vertex`: it turns the other way there, doubles back, or
    /// (for Wachspress, which needs strict convexity) does not turn at all.
    NotConvex {
        /// The vertex where the turn is wrong.
        vertex: usize,
    },
    /// Every turn has the same sign but the boundary winds around more than once (a star
    /// polygon such as a pentagram).
    SelfIntersecting,
    /// The point is outside and the coordinates have no finite value there: a pole of the
    /// Wachspress functions (their denominator vanishes), or weights beyond f32's range.
    Undefined,
}

impl fmt::Display for PolygonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::TooFewVertices { count } => {
                write!(f, "a polygon needs at least 3 vertices, got {count}")
            }
            Self::WeightsLength { vertices, weights } => write!(
                f,
                "weights buffer has {weights} entries for a polygon of {vertices} vertices"
            ),
            Self::NonFinite { what } => write!(f, "{what} has a NaN or infinite coordinate"),
            Self::RepeatedVertex { index } => {
                write!(
                    f,
                    "vertex {index} equals the next vertex (zero-length edge)"
                )
            }
            Self::Collinear => f.write_str("all vertices are collinear (zero area)"),
            Self::NotConvex { vertex } => write!(f, "polygon is not convex at vertex {vertex}"),
            Self::SelfIntersecting => f.write_str("polygon winds around more than once"),
            Self::Undefined => {
                f.write_str("the coordinates have a pole at this point outside the polygon")
            }
        }
    }
}

impl core::error::Error for PolygonError {}

/// A choice of generalized barycentric coordinates, for code that takes the method as data.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GeneralizedBarycentric {
    /// [`wachspress_weights`].
    Wachspress,
    /// [`mean_value_weights`].
    MeanValue,
}

impl GeneralizedBarycentric {
    /// Both methods, for tests and reports.
    pub const ALL: [Self; 2] = [Self::Wachspress, Self::MeanValue];

    /// The weights of `p` in `polygon` by this method, written into `weights`.
    ///
    /// # Errors
    /// As [`wachspress_weights`] or [`mean_value_weights`].
    ///
    /// # Accuracy
    /// As [`wachspress_weights`] or [`mean_value_weights`].
    ///
    /// ```
    /// use barytex_interp::{GeneralizedBarycentric, PolygonLocation};
    /// use glam::Vec2;
    /// let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
    /// let mut w = [0.0; 4];
    /// for method in GeneralizedBarycentric::ALL {
    ///     let loc = method.weights(Vec2::splat(0.5), &square, &mut w)?;
    ///     assert_eq!((loc, w), (PolygonLocation::Inside, [0.25; 4]));
    /// }
    /// # Ok::<(), barytex_interp::PolygonError>(())
    /// ```
    pub fn weights(
        self,
        p: Vec2,
        polygon: &[Vec2],
        weights: &mut [f32],
    ) -> Result<PolygonLocation, PolygonError> {
        match self {
            Self::Wachspress => wachspress_weights(p, polygon, weights),
            Self::MeanValue => mean_value_weights(p, polygon, weights),
        }
    }

    /// The method's name as the report and the tests print it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Wachspress => "wachspress",
            Self::MeanValue => "mean value",
        }
    }
}

/// `Σ wᵢ·valuesᵢ`: the value at a point from its polygon weights and the per-vertex values.
///
/// Weights `eᵢ` (a point on vertex `i`) return `values[i]` exactly for finite values.
///
/// # Errors
/// [`PolygonError::WeightsLength`] when the slices differ in length,
/// [`PolygonError::TooFewVertices`] when they are empty.
///
/// # Accuracy
/// One [`Interpolate::combine`]: the bound of the `Interpolate` laws
/// (`(n + 1)·ε·Σ|wᵢ|·max|valueᵢ|` per component) on top of the weights' own.
///
/// ```
/// use barytex_interp::{interpolate_polygon, mean_value_weights};
/// use glam::Vec2;
/// let quad = [Vec2::ZERO, Vec2::new(2.0, 0.0), Vec2::new(2.0, 2.0), Vec2::new(0.0, 2.0)];
/// let mut w = [0.0; 4];
/// mean_value_weights(Vec2::new(2.0, 1.0), &quad, &mut w)?;
/// let v = interpolate_polygon(&w, &[0.0f32, 1.0, 3.0, 0.0]);
/// assert_eq!(v, Ok(2.0)); // halfway along the edge from 1.0 to 3.0
/// # Ok::<(), barytex_interp::PolygonError>(())
/// ```
pub fn interpolate_polygon<T: Interpolate>(
    weights: &[f32],
    values: &[T],
) -> Result<T, PolygonError> {
    if weights.len() != values.len() {
        return Err(PolygonError::WeightsLength {
            vertices: values.len(),
            weights: weights.len(),
        });
    }
    T::combine(values.iter().copied().zip(weights.iter().copied()))
        .ok_or(PolygonError::TooFewVertices { count: 0 })
}
