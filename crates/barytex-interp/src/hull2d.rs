//! The 2D convex hull with exact orientation (Buss 2003, ch. IV; Denisjuk, Theorem 15: the convex
//! hull of a set is the set of all convex combinations of its points, so every point is a convex
//! combination of the hull's vertices).
//!
//! Pipeline: one pass rejects non-finite points and finds the extreme points in eight directions;
//! an Akl–Toussaint prefilter drops every point strictly inside their polygon (most of a uniform
//! cloud); Andrew's monotone chain runs on the survivors, sorted once. Every turn is decided by
//! the exact orientation of `determinant.rs`, whose plain-f64 filter settles almost every call.

mod prefilter;
mod validate;

use alloc::vec::Vec;
use core::fmt;

use glam::Vec2;

use crate::determinant::orient2d_sign_det;

pub use validate::HullDefect2d;

/// What the hull reports of input points that lie on its boundary but are not corners.
///
/// The policy is the same for 3 or 3 000 collinear points: it depends only on where a point
/// lies, never on how many points share an edge.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CollinearPoints {
    /// Only strict corners: every reported vertex turns strictly left (the smallest vertex set).
    #[default]
    Drop,
    /// Every distinct input point on the boundary: corners and the points inside edges, the
    /// latter in order along their edge.
    Keep,
}

/// The dimension of the hull: what an input of 0, 1, equal or collinear points gives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HullShape2d {
    /// No input points: no vertices.
    Empty,
    /// All input points are equal: one vertex.
    Point,
    /// All input points lie on one line and are not all equal: the two endpoints (lowest, then
    /// highest in (x, y) order), with [`CollinearPoints::Keep`] also every distinct point
    /// between them, in order from the first endpoint to the second.
    Segment,
    /// The points span an area: a convex polygon of at least three strict corners.
    Polygon,
}

/// Why a hull could not be computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum HullError2d {
    /// Point `index` (the first such) has a NaN or infinite coordinate.
    NonFinite {
        /// Position of the point in the input slice.
        index: usize,
    },
}

impl fmt::Display for HullError2d {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { index } => {
                write!(f, "point {index} has a NaN or infinite coordinate")
            }
        }
    }
}

impl core::error::Error for HullError2d {}

/// The convex hull of a set of 2D points, as indices into the input slice.
///
/// - Vertices run **counter-clockwise** (y-up frame) and start at the input point of lowest x,
///   then lowest y.
/// - Points with equal coordinates (`-0.0` equals `0.0`) count once: the hull reports the
///   **lowest index** among them.
/// - [`shape`](Self::shape) says what degenerate inputs gave; see [`HullShape2d`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConvexHull2d {
    vertices: Vec<usize>,
    shape: HullShape2d,
    collinear: CollinearPoints,
}

impl ConvexHull2d {
    /// The hull's vertices as indices into the input, counter-clockwise from the lowest-x
    /// (then lowest-y) point.
    #[must_use]
    pub fn vertices(&self) -> &[usize] {
        &self.vertices
    }

    /// The vertices, consuming the hull.
    #[must_use]
    pub fn into_vertices(self) -> Vec<usize> {
        self.vertices
    }

    /// Empty, a single point, a segment or a polygon.
    #[must_use]
    pub fn shape(&self) -> HullShape2d {
        self.shape
    }

    /// The collinear-point policy the hull was computed with.
    #[must_use]
    pub fn collinear(&self) -> CollinearPoints {
        self.collinear
    }

    /// Number of vertices.
    #[must_use]
    pub fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Whether the hull has no vertex (the input was empty).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.vertices.is_empty()
    }

    /// The vertices' coordinates, looked up in `points` (the slice the hull was computed from);
    /// an index beyond `points` is skipped.
    pub fn positions<'a>(&'a self, points: &'a [Vec2]) -> impl Iterator<Item = Vec2> + 'a {
        self.vertices.iter().filter_map(|&i| points.get(i).copied())
    }

    /// Check that this is the exact hull of `points` under its policy; see [`HullDefect2d`] for
    /// what is checked. `O(n log n)`.
    ///
    /// # Errors
    /// The first defect found.
    pub fn validate(&self, points: &[Vec2]) -> Result<(), HullDefect2d> {
        validate::validate(self, points)
    }
}

/// The convex hull of `points`, with exact orientation tests.
///
/// Degenerate inputs are answered, not rejected: no points give [`HullShape2d::Empty`], equal
/// points [`HullShape2d::Point`], collinear points [`HullShape2d::Segment`] (see there for what
/// [`CollinearPoints::Keep`] lists). Duplicates count once (the lowest index is reported).
///
/// `O(n log n)` worst case; on inputs whose hull is small (uniform clouds), an Akl–Toussaint
/// prefilter discards most points in one linear pass before sorting.
///
/// # Errors
/// [`HullError2d::NonFinite`] naming the first point with a NaN or infinite coordinate.
///
/// # Accuracy
/// Exact: the vertex set is that of the exact hull of the f32 inputs, huge (1e38), tiny and
/// subnormal coordinates included (tests `hull_2d.rs::{grid_points_match_brute_force,
/// random_points_pass_invariants, total_on_any_bits, scale_invariant, hard_cases_are_exact,
/// million_points_on_a_circle}`, against a brute-force exact hull and spade).
///
/// ```
/// use barytex_interp::{CollinearPoints, HullShape2d, convex_hull_2d};
/// use glam::Vec2;
///
/// let points = [
///     Vec2::new(2.0, 0.0),
///     Vec2::new(0.0, 0.0),
///     Vec2::new(1.0, 0.0), // inside the bottom edge
///     Vec2::new(1.0, 1.0), // strictly inside
///     Vec2::new(2.0, 2.0),
///     Vec2::new(0.0, 2.0),
/// ];
/// let hull = convex_hull_2d(&points, CollinearPoints::Drop)?;
/// assert_eq!(hull.vertices(), &[1, 0, 4, 5]);
/// assert_eq!(hull.shape(), HullShape2d::Polygon);
/// let hull = convex_hull_2d(&points, CollinearPoints::Keep)?;
/// assert_eq!(hull.vertices(), &[1, 2, 0, 4, 5]);
/// hull.validate(&points).expect("exact hull");
/// # Ok::<(), barytex_interp::HullError2d>(())
/// ```
pub fn convex_hull_2d(
    points: &[Vec2],
    collinear: CollinearPoints,
) -> Result<ConvexHull2d, HullError2d> {
    let mut survivors = prefilter::survivors(points)?;
    survivors.sort_unstable();
    survivors.dedup_by_key(|entry| entry.0);
    let (vertices, shape) = match survivors.as_slice() {
        [] => (Vec::new(), HullShape2d::Empty),
        [(_, only)] => (alloc::vec![*only], HullShape2d::Point),
        sorted => hull_of_sorted(sorted, collinear),
    };
    Ok(ConvexHull2d {
        vertices,
        shape,
        collinear,
    })
}

/// A point's sort key: its coordinates mapped to integers in the same (x, then y) order, so one
/// integer comparison sorts lexicographically, equal points (`-0.0` and `0.0` too) get equal
/// keys, and the point can be read back from the key without touching the input again.
pub(crate) type Key = u64;

/// `x`'s bits reordered so that unsigned order is float order (`-0.0` mapped to `0.0`).
#[inline]
fn ordered_bits(x: f32) -> u32 {
    // `-0.0 + 0.0` is `+0.0`; every other value is unchanged.
    let bits = (x + 0.0).to_bits();
    if bits >> 31 == 1 {
        !bits
    } else {
        bits | 0x8000_0000
    }
}

#[inline]
fn from_ordered_bits(bits: u32) -> f32 {
    f32::from_bits(if bits >> 31 == 1 {
        bits & 0x7fff_ffff
    } else {
        !bits
    })
}

/// The sort key of a finite point.
#[inline]
pub(crate) fn key(p: Vec2) -> Key {
    (u64::from(ordered_bits(p.x)) << 32) | u64::from(ordered_bits(p.y))
}

/// The point a key was made from (`-0.0` read back as `0.0`).
#[inline]
pub(crate) fn point_of(key: Key) -> Vec2 {
    Vec2::new(
        from_ordered_bits((key >> 32) as u32),
        from_ordered_bits(key as u32),
    )
}

/// Whether the turn `a → b → c` removes `b` from a chain under the policy: a right turn always,
/// a straight one unless collinear points are kept.
#[inline]
fn pops(a: Vec2, b: Vec2, c: Vec2, collinear: CollinearPoints) -> bool {
    let det = orient2d_sign_det(a, b, c);
    match collinear {
        CollinearPoints::Drop => det <= 0.0,
        CollinearPoints::Keep => det < 0.0,
    }
}

/// The hull of at least two distinct points, sorted by key (lowest index first among equal keys,
/// duplicates removed).
fn hull_of_sorted(
    sorted: &[(Key, usize)],
    collinear: CollinearPoints,
) -> (Vec<usize>, HullShape2d) {
    let (first, last) = (point_of(sorted[0].0), point_of(sorted[sorted.len() - 1].0));
    let all_collinear = sorted
        .iter()
        .all(|&(k, _)| orient2d_sign_det(first, last, point_of(k)) == 0.0);
    if all_collinear {
        // Sorted (x, y) order is the order along the line.
        let vertices = match collinear {
            CollinearPoints::Drop => alloc::vec![sorted[0].1, sorted[sorted.len() - 1].1],
            CollinearPoints::Keep => sorted.iter().map(|&(_, i)| i).collect(),
        };
        return (vertices, HullShape2d::Segment);
    }
    (monotone_chain(sorted, collinear), HullShape2d::Polygon)
}

/// Andrew's monotone chain on points that are not all collinear: the lower chain left to right,
/// then the upper chain right to left, each popping what the policy says a turn removes.
fn monotone_chain(sorted: &[(Key, usize)], collinear: CollinearPoints) -> Vec<usize> {
    let mut chain: Vec<(Vec2, usize)> = Vec::new();
    let push = |chain: &mut Vec<(Vec2, usize)>, floor: usize, (k, i): (Key, usize)| {
        let p = point_of(k);
        while chain.len() >= floor + 2
            && pops(
                chain[chain.len() - 2].0,
                chain[chain.len() - 1].0,
                p,
                collinear,
            )
        {
            chain.pop();
        }
        chain.push((p, i));
    };
    for &entry in sorted {
        push(&mut chain, 0, entry);
    }
    // The upper chain may pop down to, never below, the last point of the lower one.
    let floor = chain.len() - 1;
    for &entry in sorted.iter().rev().skip(1) {
        push(&mut chain, floor, entry);
    }
    // The upper chain ends where the lower one started.
    chain.pop();
    chain.into_iter().map(|(_, i)| i).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_order_like_floats() {
        let values = [
            f32::MIN,
            -1.0,
            -f32::MIN_POSITIVE,
            -1e-45,
            0.0,
            1e-45,
            1.0,
            f32::MAX,
        ];
        for w in values.windows(2) {
            assert!(ordered_bits(w[0]) < ordered_bits(w[1]), "{w:?}");
        }
        assert_eq!(ordered_bits(-0.0), ordered_bits(0.0));
        for x in values {
            assert_eq!(from_ordered_bits(ordered_bits(x)), x);
        }
        let p = Vec2::new(-3.5, 1e-40);
        assert_eq!(point_of(key(p)), p);
    }
}
