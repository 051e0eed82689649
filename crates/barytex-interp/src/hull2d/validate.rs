//! The exact validity check of a 2D hull, for tests and fuzzing: it re-derives nothing from the
//! hull algorithm, only checks the defining properties with exact orientation.

use alloc::vec::Vec;
use core::cmp::Ordering;
use core::fmt;

use glam::Vec2;

use super::{CollinearPoints, ConvexHull2d, HullShape2d, Key, key, point_of};
use crate::determinant::orient2d_sign_det;

/// Why a [`ConvexHull2d`] is not the exact hull of a point set under its policy.
///
/// [`ConvexHull2d::validate`] checks, in this order: the input is finite; every vertex index is in
/// range, names the lowest index of its coordinates and no two vertices coincide; the shape is
/// that of the input (all equal, all collinear, or spanning an area); the first vertex is the
/// lowest-x, then lowest-y point; for a polygon, every turn is strictly left
/// ([`CollinearPoints::Drop`]) or left or straight-ahead ([`CollinearPoints::Keep`]) and the
/// boundary winds once counter-clockwise; every input point lies inside or on the boundary; with
/// `Keep`, every input point on the boundary is a vertex (and a segment lists every distinct point
/// in order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum HullDefect2d {
    /// Input point `index` is NaN or infinite: no hull exists.
    NonFiniteInput {
        /// The first such point.
        index: usize,
    },
    /// Vertex `position` names a point beyond the input.
    IndexOutOfRange {
        /// Position in the vertex list.
        position: usize,
        /// The index it holds.
        index: usize,
    },
    /// Vertex `position` has the coordinates of an earlier vertex.
    RepeatedPoint {
        /// Position in the vertex list.
        position: usize,
    },
    /// Vertex `position` names a duplicate point but not the lowest index among its copies.
    NotLowestIndex {
        /// Position in the vertex list.
        position: usize,
        /// The index it holds.
        index: usize,
        /// The lowest index with the same coordinates.
        lowest: usize,
    },
    /// The hull claims a shape the input does not have.
    ShapeMismatch {
        /// What the hull says.
        claimed: HullShape2d,
        /// What the input is.
        actual: HullShape2d,
    },
    /// The number of vertices is impossible for the shape and policy.
    VertexCount {
        /// The shape.
        shape: HullShape2d,
        /// The number of vertices.
        count: usize,
    },
    /// The first vertex is not the input point of lowest x, then lowest y.
    WrongStart {
        /// The first vertex.
        found: usize,
        /// The lowest index of the lowest-x, lowest-y point.
        expected: usize,
    },
    /// The turn at vertex `position` is to the right, straight under `Drop`, or a reversal.
    NotConvex {
        /// Position in the vertex list.
        position: usize,
    },
    /// The vertices of a segment hull are not in order along the segment.
    OutOfOrder {
        /// Position in the vertex list.
        position: usize,
    },
    /// Every turn is left but the boundary winds around more than once.
    WindsMoreThanOnce,
    /// Input point `index` lies strictly outside the hull.
    PointOutside {
        /// The point.
        index: usize,
    },
    /// With `Keep`, input point `index` lies on the boundary but is not a vertex.
    MissingBoundaryPoint {
        /// The point.
        index: usize,
    },
}

impl fmt::Display for HullDefect2d {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::NonFiniteInput { index } => write!(f, "input point {index} is not finite"),
            Self::IndexOutOfRange { position, index } => {
                write!(f, "vertex {position} is index {index}, beyond the input")
            }
            Self::RepeatedPoint { position } => {
                write!(
                    f,
                    "vertex {position} repeats an earlier vertex's coordinates"
                )
            }
            Self::NotLowestIndex {
                position,
                index,
                lowest,
            } => write!(
                f,
                "vertex {position} is index {index}, not the lowest index {lowest} of its point"
            ),
            Self::ShapeMismatch { claimed, actual } => {
                write!(f, "hull claims {claimed:?}, the input is {actual:?}")
            }
            Self::VertexCount { shape, count } => {
                write!(f, "{count} vertices are impossible for a {shape:?} hull")
            }
            Self::WrongStart { found, expected } => {
                write!(
                    f,
                    "hull starts at {found}, not at the lowest point {expected}"
                )
            }
            Self::NotConvex { position } => {
                write!(
                    f,
                    "the turn at vertex {position} breaks convexity or the policy"
                )
            }
            Self::OutOfOrder { position } => {
                write!(f, "segment vertex {position} is out of order")
            }
            Self::WindsMoreThanOnce => f.write_str("the boundary winds around more than once"),
            Self::PointOutside { index } => write!(f, "input point {index} is outside the hull"),
            Self::MissingBoundaryPoint { index } => {
                write!(f, "input point {index} is on the boundary but not a vertex")
            }
        }
    }
}

impl core::error::Error for HullDefect2d {}

/// Where a point lies relative to a strictly convex polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Inside,
    Boundary,
    Outside,
}

pub(super) fn validate(hull: &ConvexHull2d, points: &[Vec2]) -> Result<(), HullDefect2d> {
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(HullDefect2d::NonFiniteInput { index });
    }
    // Every point once per distinct coordinates, lowest index first.
    let mut sorted: Vec<(Key, usize)> = points
        .iter()
        .enumerate()
        .map(|(i, &p)| (key(p), i))
        .collect();
    sorted.sort_unstable();
    sorted.dedup_by_key(|e| e.0);
    let lowest_of = |k: Key| {
        let at = sorted.partition_point(|e| e.0 < k);
        sorted[at].1
    };
    let vertices = hull.vertices();
    let mut vertex_keys = Vec::with_capacity(vertices.len());
    for (position, &index) in vertices.iter().enumerate() {
        let Some(&p) = points.get(index) else {
            return Err(HullDefect2d::IndexOutOfRange { position, index });
        };
        let lowest = lowest_of(key(p));
        if lowest != index {
            return Err(HullDefect2d::NotLowestIndex {
                position,
                index,
                lowest,
            });
        }
        vertex_keys.push((key(p), position));
    }
    vertex_keys.sort_unstable();
    if let Some(w) = vertex_keys.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(HullDefect2d::RepeatedPoint {
            position: w[0].1.max(w[1].1),
        });
    }
    let actual = shape_of(&sorted);
    if hull.shape() != actual {
        return Err(HullDefect2d::ShapeMismatch {
            claimed: hull.shape(),
            actual,
        });
    }
    let count_error = Err(HullDefect2d::VertexCount {
        shape: actual,
        count: vertices.len(),
    });
    let keep = hull.collinear() == CollinearPoints::Keep;
    match actual {
        HullShape2d::Empty if !vertices.is_empty() => return count_error,
        HullShape2d::Point if vertices.len() != 1 => return count_error,
        HullShape2d::Segment if vertices.len() != if keep { sorted.len() } else { 2 } => {
            return count_error;
        }
        HullShape2d::Polygon if vertices.len() < 3 => return count_error,
        _ => {}
    }
    if let (Some(&first), Some(&(_, expected))) = (vertices.first(), sorted.first())
        && first != expected
    {
        return Err(HullDefect2d::WrongStart {
            found: first,
            expected,
        });
    }
    let positions: Vec<Vec2> = hull.positions(points).collect();
    match actual {
        HullShape2d::Segment => check_segment(&positions, &sorted),
        HullShape2d::Polygon => check_polygon(&positions, &sorted, &vertex_keys, keep),
        HullShape2d::Empty | HullShape2d::Point => Ok(()),
    }
}

/// The shape of the distinct points `sorted` (by key).
fn shape_of(sorted: &[(Key, usize)]) -> HullShape2d {
    match sorted {
        [] => HullShape2d::Empty,
        [_] => HullShape2d::Point,
        [(first, _), .., (last, _)] => {
            let (a, b) = (point_of(*first), point_of(*last));
            if sorted
                .iter()
                .all(|&(k, _)| orient2d_sign_det(a, b, point_of(k)) == 0.0)
            {
                HullShape2d::Segment
            } else {
                HullShape2d::Polygon
            }
        }
    }
}

/// A segment hull (input all collinear, vertex count already checked): vertices in increasing
/// (x, y) order, the last one the highest point.
fn check_segment(positions: &[Vec2], sorted: &[(Key, usize)]) -> Result<(), HullDefect2d> {
    for (position, w) in positions.windows(2).enumerate() {
        if key(w[1]) <= key(w[0]) {
            return Err(HullDefect2d::OutOfOrder {
                position: position + 1,
            });
        }
    }
    match (positions.last(), sorted.last()) {
        (Some(&end), Some(&(highest, index))) if key(end) != highest => {
            Err(HullDefect2d::PointOutside { index })
        }
        _ => Ok(()),
    }
}

/// The sign of `b − a` as an ordering, exact.
fn step(a: f32, b: f32) -> Ordering {
    b.partial_cmp(&a).unwrap_or(Ordering::Equal)
}

fn check_polygon(
    positions: &[Vec2],
    sorted: &[(Key, usize)],
    vertex_keys: &[(Key, usize)],
    keep: bool,
) -> Result<(), HullDefect2d> {
    let n = positions.len();
    let mut corners = Vec::with_capacity(n);
    for position in 0..n {
        let a = positions[(position + n - 1) % n];
        let b = positions[position];
        let c = positions[(position + 1) % n];
        let det = orient2d_sign_det(a, b, c);
        let straight_ahead =
            det == 0.0 && step(a.x, b.x) == step(b.x, c.x) && step(a.y, b.y) == step(b.y, c.y);
        if det > 0.0 {
            corners.push(b);
        } else if !(keep && straight_ahead) {
            return Err(HullDefect2d::NotConvex { position });
        }
    }
    // With no right turn, the boundary winds once exactly when the sign of the x-step changes
    // twice around it (zero steps skipped).
    let signs: Vec<Ordering> = (0..n)
        .map(|i| step(positions[i].x, positions[(i + 1) % n].x))
        .filter(|&s| s != Ordering::Equal)
        .collect();
    let changes = (0..signs.len())
        .filter(|&i| signs[i] != signs[(i + 1) % signs.len()])
        .count();
    if changes != 2 || corners.len() < 3 {
        return Err(HullDefect2d::WindsMoreThanOnce);
    }
    for &(k, index) in sorted {
        match locate(&corners, point_of(k)) {
            Side::Inside => {}
            Side::Outside => return Err(HullDefect2d::PointOutside { index }),
            Side::Boundary => {
                if keep && vertex_keys.binary_search_by_key(&k, |e| e.0).is_err() {
                    return Err(HullDefect2d::MissingBoundaryPoint { index });
                }
            }
        }
    }
    Ok(())
}

/// `p` is on the closed segment `ab`, given that the three are collinear.
fn within(a: Vec2, b: Vec2, p: Vec2) -> bool {
    a.x.min(b.x) <= p.x && p.x <= a.x.max(b.x) && a.y.min(b.y) <= p.y && p.y <= a.y.max(b.y)
}

/// Where `p` lies relative to the strictly convex counter-clockwise polygon `s` (at least three
/// corners): a binary search over the fan from `s[0]`, `O(log n)` exact orientations.
fn locate(s: &[Vec2], p: Vec2) -> Side {
    let o = s[0];
    let last = s.len() - 1;
    let first_side = orient2d_sign_det(o, s[1], p);
    let last_side = orient2d_sign_det(o, s[last], p);
    if first_side < 0.0 || last_side > 0.0 {
        return Side::Outside;
    }
    for (side, end) in [(first_side, s[1]), (last_side, s[last])] {
        if side == 0.0 {
            return if within(o, end, p) {
                Side::Boundary
            } else {
                Side::Outside
            };
        }
    }
    // orient(o, s[lo], p) > 0 ≥ orient(o, s[hi], p).
    let (mut lo, mut hi) = (1, last);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if orient2d_sign_det(o, s[mid], p) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let edge = orient2d_sign_det(s[lo], s[hi], p);
    if edge > 0.0 {
        Side::Inside
    } else if edge == 0.0 {
        Side::Boundary
    } else {
        Side::Outside
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    fn hull(vertices: &[usize], shape: HullShape2d, collinear: CollinearPoints) -> ConvexHull2d {
        ConvexHull2d {
            vertices: vertices.to_vec(),
            shape,
            collinear,
        }
    }

    /// A square with a point inside its bottom edge, one inside it, and a copy of a corner.
    const SQUARE: [Vec2; 7] = [
        Vec2::new(0.0, 0.0),
        Vec2::new(1.0, 0.0),
        Vec2::new(2.0, 0.0),
        Vec2::new(2.0, 2.0),
        Vec2::new(0.0, 2.0),
        Vec2::new(1.0, 1.0),
        Vec2::new(2.0, 2.0),
    ];

    #[test]
    fn every_defect_is_detected() {
        use CollinearPoints::{Drop, Keep};
        use HullDefect2d as D;
        use HullShape2d::{Point, Polygon, Segment};
        let check =
            |vertices: &[usize], shape, policy| hull(vertices, shape, policy).validate(&SQUARE);
        assert_eq!(check(&[0, 2, 3, 4], Polygon, Drop), Ok(()));
        assert_eq!(check(&[0, 1, 2, 3, 4], Polygon, Keep), Ok(()));
        assert_eq!(
            check(&[0, 4, 3, 2], Polygon, Drop),
            Err(D::NotConvex { position: 0 })
        );
        assert_eq!(
            check(&[0, 1, 2, 3, 4], Polygon, Drop),
            Err(D::NotConvex { position: 1 })
        );
        assert_eq!(
            check(&[0, 2, 3, 4], Polygon, Keep),
            Err(D::MissingBoundaryPoint { index: 1 })
        );
        assert_eq!(
            check(&[0, 2, 3], Polygon, Drop),
            Err(D::PointOutside { index: 4 })
        );
        assert_eq!(
            check(&[2, 3, 4, 0], Polygon, Drop),
            Err(D::WrongStart {
                found: 2,
                expected: 0
            })
        );
        assert_eq!(
            check(&[0, 2, 6, 4], Polygon, Drop),
            Err(D::NotLowestIndex {
                position: 2,
                index: 6,
                lowest: 3
            })
        );
        assert_eq!(
            check(&[0, 9, 3, 4], Polygon, Drop),
            Err(D::IndexOutOfRange {
                position: 1,
                index: 9
            })
        );
        assert_eq!(
            check(&[0, 2, 3, 4, 0], Polygon, Drop),
            Err(D::RepeatedPoint { position: 4 })
        );
        assert_eq!(
            check(&[0, 3], Segment, Drop),
            Err(D::ShapeMismatch {
                claimed: Segment,
                actual: Polygon
            })
        );
        assert_eq!(
            check(&[0, 2], Polygon, Drop),
            Err(D::VertexCount {
                shape: Polygon,
                count: 2
            })
        );
        let mut bad = SQUARE;
        bad[1] = v(f32::NAN, 0.0);
        assert_eq!(
            hull(&[0], Point, Drop).validate(&bad),
            Err(D::NonFiniteInput { index: 1 })
        );
    }

    #[test]
    fn segments_and_windings() {
        use CollinearPoints::{Drop, Keep};
        use HullDefect2d as D;
        use HullShape2d::{Polygon, Segment};
        let line = [v(0.0, 0.0), v(2.0, 2.0), v(1.0, 1.0)];
        assert_eq!(hull(&[0, 1], Segment, Drop).validate(&line), Ok(()));
        assert_eq!(hull(&[0, 2, 1], Segment, Keep).validate(&line), Ok(()));
        assert_eq!(
            hull(&[0, 1, 2], Segment, Keep).validate(&line),
            Err(D::OutOfOrder { position: 2 })
        );
        assert_eq!(
            hull(&[0, 2], Segment, Drop).validate(&line),
            Err(D::PointOutside { index: 1 })
        );
        // A pentagram: every turn left, but it winds around twice.
        let star: [Vec2; 5] = core::array::from_fn(|k| {
            let a = core::f64::consts::TAU * k as f64 / 5.0;
            glam::DVec2::from_angle(a).as_vec2()
        });
        let lowest = (0..5)
            .min_by(|&a, &b| key(star[a]).cmp(&key(star[b])))
            .unwrap_or(0);
        let order: [usize; 5] = core::array::from_fn(|k| (lowest + 2 * k) % 5);
        assert_eq!(
            hull(&order, Polygon, Drop).validate(&star),
            Err(D::WindsMoreThanOnce)
        );
        let order: [usize; 5] = core::array::from_fn(|k| (lowest + k) % 5);
        assert_eq!(hull(&order, Polygon, Drop).validate(&star), Ok(()));
    }
}
