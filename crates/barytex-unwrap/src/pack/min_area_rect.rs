//! The minimum-area bounding rectangle of a point set: one of its sides lies along an edge of
//! the convex hull (Freeman and Shapira, "Determining the minimum-area encasing rectangle for an
//! arbitrary closed curve", *Commun. ACM* 18(7), 1975), so trying each hull edge's direction
//! finds it.

use glam::DVec2;

use crate::overlap::orient;

/// The most hull edges whose directions are tried (a hull with more is sampled evenly), which
/// bounds the cost at `O(h · MAX_DIRECTIONS)` for a hull of `h` points.
const MAX_DIRECTIONS: usize = 256;

/// The convex hull of the finite points, counter-clockwise, without collinear points (Andrew's
/// monotone chain, with exact orientation tests).
pub(crate) fn convex_hull(points: &[DVec2]) -> Vec<DVec2> {
    let mut p: Vec<DVec2> = points.iter().copied().filter(|q| q.is_finite()).collect();
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut hull: Vec<DVec2> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &DVec2>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in iter {
            while hull.len() >= start + 2
                && orient(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

/// The unit direction `(cos θ, sin θ)` such that rotating the points by `−θ` puts them in a
/// minimum-area axis-aligned box (among the hull-edge directions tried); `DVec2::X` for fewer
/// than three hull points.
pub(crate) fn min_area_direction(points: &[DVec2]) -> DVec2 {
    let hull = convex_hull(points);
    if hull.len() < 3 {
        return DVec2::X;
    }
    let step = hull.len().div_ceil(MAX_DIRECTIONS).max(1);
    let mut best = (f64::INFINITY, DVec2::X);
    for i in (0..hull.len()).step_by(step) {
        let Some(d) = (hull[(i + 1) % hull.len()] - hull[i]).try_normalize() else {
            continue;
        };
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for &q in &hull {
            let r = DVec2::new(q.dot(d), d.perp_dot(q));
            lo = lo.min(r);
            hi = hi.max(r);
        }
        let area = (hi - lo).x * (hi - lo).y;
        if area < best.0 {
            best = (area, d);
        }
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tilted_rectangle_is_straightened() {
        let d = DVec2::from_angle(0.3);
        let corners = [
            DVec2::ZERO,
            DVec2::new(4.0, 0.0),
            DVec2::new(4.0, 1.0),
            DVec2::new(0.0, 1.0),
        ]
        .map(|p| d.rotate(p));
        let found = min_area_direction(&corners);
        // Parallel or perpendicular to the long side.
        assert!(found.perp_dot(d).abs() < 1e-12 || found.dot(d).abs() < 1e-12);
    }

    #[test]
    fn hull_drops_interior_and_collinear_points() {
        let pts = [
            DVec2::ZERO,
            DVec2::new(1.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 2.0),
        ];
        assert_eq!(convex_hull(&pts).len(), 4);
    }
}
