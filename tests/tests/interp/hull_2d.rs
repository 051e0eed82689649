//! The 2D convex hull: the convex-hull theorem (every point is a convex combination of the hull's
//! vertices, which are input points), exactness against a brute-force rational hull and spade,
//! the collinear policy, duplicates, degenerate and non-finite inputs, the hard-case table.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::hard_cases::{NON_FINITE, hull_circle_2d, hulls_2d};
use barytex_interp::{
    CollinearPoints, ConvexCombination, HullError2d, HullShape2d, Location, barycentric_2d,
    convex_hull_2d, locate_2d,
};
use barytex_testkit::exact;
use barytex_testkit::invariants::check_convex_hull_2d;
use barytex_testkit::strategies::{vec2_bits, vec2_in};
use glam::Vec2;
use proptest::prelude::*;

const POLICIES: [CollinearPoints; 2] = [CollinearPoints::Drop, CollinearPoints::Keep];

fn hull(points: &[Vec2], collinear: CollinearPoints) -> (HullShape2d, Vec<usize>) {
    let h = convex_hull_2d(points, collinear).unwrap();
    h.validate(points).unwrap();
    (h.shape(), h.vertices().to_vec())
}

fn sorted(mut v: Vec<usize>) -> Vec<usize> {
    v.sort_unstable();
    v
}

/// Points on a small integer grid: many duplicates and collinear runs.
fn grid_points(max_len: usize) -> impl Strategy<Value = Vec<Vec2>> {
    prop::collection::vec((-4i8..=4, -4i8..=4), 0..max_len).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Vec2::new(f32::from(x), f32::from(y)))
            .collect()
    })
}

/// The hull as spade (Delaunay triangulation, f64) sees it: every vertex on the convex-hull
/// edges, which include collinear boundary points. `None` when spade rejects a coordinate (its
/// range is about [1.8e-43, 3.2e60] in magnitude) or all points are collinear (spade then has no
/// hull polygon).
fn spade_hull(points: &[Vec2]) -> Option<Vec<Vec2>> {
    use spade::{DelaunayTriangulation, Point2, Triangulation};
    let mut t: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    for p in points {
        t.insert(Point2::new(f64::from(p.x), f64::from(p.y))).ok()?;
    }
    if t.all_vertices_on_line() {
        return None;
    }
    Some(
        t.convex_hull()
            .map(|e| {
                let q = e.from().position();
                Vec2::new(q.x as f32, q.y as f32)
            })
            .collect(),
    )
}

/// Coordinates in (x, y) order, `-0.0` as `0.0`, for comparing vertex sets by position.
fn position_set(points: impl IntoIterator<Item = Vec2>) -> Vec<(u32, u32)> {
    let mut v: Vec<(u32, u32)> = points
        .into_iter()
        .map(|p| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits()))
        .collect();
    v.sort_unstable();
    v
}

#[test]
fn empty_single_and_two_points() {
    let a = Vec2::new(1.0, 2.0);
    let b = Vec2::new(-1.0, 5.0);
    for policy in POLICIES {
        assert_eq!(hull(&[], policy), (HullShape2d::Empty, vec![]));
        assert_eq!(hull(&[a], policy), (HullShape2d::Point, vec![0]));
        assert_eq!(hull(&[a, a], policy), (HullShape2d::Point, vec![0]));
        // The segment starts at the lowest x.
        assert_eq!(hull(&[a, b], policy), (HullShape2d::Segment, vec![1, 0]));
        assert_eq!(hull(&[b, a, b], policy), (HullShape2d::Segment, vec![0, 1]));
        let h = convex_hull_2d(&[], policy).unwrap();
        assert!(h.is_empty());
        assert_eq!(h.collinear(), policy);
    }
}

#[test]
fn non_finite_rejected_with_first_index() {
    for bad in NON_FINITE {
        for policy in POLICIES {
            for (position, point) in [Vec2::new(bad, 0.0), Vec2::new(0.0, bad)]
                .into_iter()
                .enumerate()
            {
                let mut points = vec![Vec2::ZERO, Vec2::X, Vec2::Y];
                points.insert(position + 1, point);
                points.push(Vec2::splat(bad));
                assert_eq!(
                    convex_hull_2d(&points, policy),
                    Err(HullError2d::NonFinite {
                        index: position + 1
                    })
                );
            }
        }
    }
    let e = HullError2d::NonFinite { index: 7 };
    assert_eq!(e.to_string(), "point 7 has a NaN or infinite coordinate");
}

/// The same policy for 3 and for 3000 collinear points: `Drop` keeps only the corners, `Keep`
/// every point of the edge, in order along it.
#[test]
fn collinear_policy_is_the_same_for_3_and_3000_points() {
    for n in [3usize, 30, 3000] {
        // n points on the bottom edge (0,0)–(n−1, 0), shuffled, then the apex.
        let order: Vec<usize> = (0..n).map(|i| i * 7 % n).collect();
        let n_f = (n - 1) as f32;
        let mut points: Vec<Vec2> = order.iter().map(|&i| Vec2::new(i as f32, 0.0)).collect();
        points.push(Vec2::new(n_f / 2.0, 10.0));
        let index_of_x = |x: usize| order.iter().position(|&i| i == x).unwrap();
        let (shape, drop) = hull(&points, CollinearPoints::Drop);
        assert_eq!(shape, HullShape2d::Polygon);
        assert_eq!(drop, vec![index_of_x(0), index_of_x(n - 1), n]);
        let (_, keep) = hull(&points, CollinearPoints::Keep);
        let mut want: Vec<usize> = (0..n).map(index_of_x).collect();
        want.push(n);
        assert_eq!(keep, want, "n = {n}");

        // All collinear: a segment; Keep lists every point from the first end to the last.
        points.pop();
        let (shape, drop) = hull(&points, CollinearPoints::Drop);
        assert_eq!(shape, HullShape2d::Segment);
        assert_eq!(drop, vec![index_of_x(0), index_of_x(n - 1)]);
        let (shape, keep) = hull(&points, CollinearPoints::Keep);
        assert_eq!(shape, HullShape2d::Segment);
        assert_eq!(keep, (0..n).map(index_of_x).collect::<Vec<_>>());
    }
}

/// Collinear runs on all four sides of a square, including the vertical ones, where sorted order
/// and boundary order disagree.
#[test]
fn collinear_runs_on_every_side() {
    let mut points = Vec::new();
    for i in 0..5 {
        for j in 0..5 {
            points.push(Vec2::new(i as f32, j as f32));
        }
    }
    let (_, drop) = hull(&points, CollinearPoints::Drop);
    assert_eq!(drop, vec![0, 20, 24, 4]);
    let (_, keep) = hull(&points, CollinearPoints::Keep);
    assert_eq!(
        keep,
        vec![0, 5, 10, 15, 20, 21, 22, 23, 24, 19, 14, 9, 4, 3, 2, 1]
    );
}

#[test]
fn duplicates_report_the_lowest_index() {
    let points = [
        Vec2::new(1.0, 1.0),
        Vec2::new(0.0, -0.0),
        Vec2::new(2.0, 0.0),
        Vec2::new(-0.0, 0.0),
        Vec2::new(2.0, 0.0),
        Vec2::new(1.0, 0.0),
        Vec2::new(1.0, 0.0),
    ];
    for policy in POLICIES {
        let (_, v) = hull(&points, policy);
        let want = match policy {
            CollinearPoints::Drop => vec![1, 2, 0],
            CollinearPoints::Keep => vec![1, 5, 2, 0],
        };
        assert_eq!(v, want);
    }
}

fn distinct(points: &[Vec2]) -> usize {
    position_set(points.iter().copied())
        .windows(2)
        .filter(|w| w[0] != w[1])
        .count()
        + usize::from(!points.is_empty())
}

#[test]
fn hard_cases_are_exact() {
    let mut compared = 0;
    for case in hulls_2d() {
        let name = format!("{} ({})", case.name, case.parameter);
        let points = &case.points;
        check_convex_hull_2d(points).unwrap_or_else(|e| panic!("{name}: {e}"));
        let drop = convex_hull_2d(points, CollinearPoints::Drop).unwrap();
        if let Some(corners) = case.corners {
            assert_eq!(drop.len(), corners, "{name}");
        }
        // The brute force is O(m³) in the m distinct points: run it where that is quick.
        if distinct(points) <= 80 {
            compared += 1;
            for (policy, keep) in [
                (CollinearPoints::Drop, false),
                (CollinearPoints::Keep, true),
            ] {
                let (_, got) = hull(points, policy);
                let want = exact::convex_hull_2d_vertex_set(points, keep);
                assert_eq!(sorted(got), want, "{name} {policy:?}");
            }
        }
        println!(
            "{name}: {} points, {} corners, {} boundary points",
            points.len(),
            drop.len(),
            convex_hull_2d(points, CollinearPoints::Keep).unwrap().len()
        );
    }
    assert!(compared >= 5, "brute force ran on only {compared} cases");
}

/// The hard case at full size: 10⁶ points on a circle, validated exactly (every point inside or
/// on the boundary, every turn strictly convex).
#[test]
fn million_points_on_a_circle() {
    let points = hull_circle_2d(1_000_000);
    for policy in POLICIES {
        let h = convex_hull_2d(&points, policy).unwrap();
        h.validate(&points).unwrap();
        assert_eq!(h.shape(), HullShape2d::Polygon);
        println!("circle 1e6, {policy:?}: {} vertices", h.len());
    }
}

/// Compare with spade's convex hull on the hard cases it accepts (Keep: spade's hull edges run
/// through collinear boundary points).
#[test]
fn hard_cases_match_spade() {
    let mut compared = 0;
    for case in hulls_2d() {
        let Some(theirs) = spade_hull(&case.points) else {
            continue;
        };
        let ours = convex_hull_2d(&case.points, CollinearPoints::Keep).unwrap();
        assert_eq!(
            position_set(ours.positions(&case.points)),
            position_set(theirs),
            "{}",
            case.name
        );
        compared += 1;
    }
    assert!(compared >= 5, "spade compared on only {compared} cases");
}

/// The convex-hull theorem (Denisjuk, Theorem 15), constructively: each input point is a convex combination of three hull
/// vertices, found by fanning the hull from its first vertex.
fn convex_combination_of_hull(points: &[Vec2]) -> Result<(), TestCaseError> {
    let h = convex_hull_2d(points, CollinearPoints::Drop).unwrap();
    if h.shape() != HullShape2d::Polygon {
        return Ok(());
    }
    let v: Vec<Vec2> = h.positions(points).collect();
    for &p in points {
        let found = v.windows(2).skip(1).find_map(|w| {
            let tri = [v[0], w[0], w[1]];
            locate_2d(p, tri)
                .unwrap()
                .is_inside_closed()
                .then(|| (tri, barycentric_2d(p, tri).unwrap()))
        });
        let Some((tri, b)) = found else {
            return Err(TestCaseError::fail(format!("{p:?} in no fan triangle")));
        };
        prop_assert_ne!(b.location, Location::Outside);
        let combination = ConvexCombination::new(b.weights)
            .map_err(|e| TestCaseError::fail(format!("{p:?}: weights {:?}: {e}", b.weights)))?;
        let q = combination.apply(tri);
        let scale = tri
            .iter()
            .map(|c| c.abs().max_element())
            .fold(p.abs().max_element(), f32::max);
        prop_assert!(
            (q - p).abs().max_element() <= 4.0 * f32::EPSILON * scale,
            "{p:?} → {q:?}"
        );
    }
    Ok(())
}

/// The convex-hull theorem, exactly: no input point is strictly right of any hull edge (rational
/// arithmetic, independent of the crate's predicates), and the hull vertices are input points.
fn exactly_inside_every_edge(points: &[Vec2]) -> Result<(), TestCaseError> {
    for policy in POLICIES {
        let h = convex_hull_2d(points, policy).unwrap();
        prop_assert!(h.vertices().iter().all(|&i| i < points.len()));
        if h.shape() != HullShape2d::Polygon {
            continue;
        }
        let v: Vec<Vec2> = h.positions(points).collect();
        for (k, &a) in v.iter().enumerate() {
            let b = v[(k + 1) % v.len()];
            for &p in points {
                prop_assert!(
                    exact::orient2d_sign(a, b, p) >= 0,
                    "{p:?} right of {a:?}→{b:?}"
                );
            }
        }
    }
    Ok(())
}

proptest! {
    #[test]
    fn random_points_pass_invariants(points in prop::collection::vec(vec2_in(-100.0, 100.0), 0..16)) {
        check_convex_hull_2d(&points).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn grid_points_match_brute_force(points in grid_points(40)) {
        check_convex_hull_2d(&points).map_err(TestCaseError::fail)?;
        for (policy, keep) in [(CollinearPoints::Drop, false), (CollinearPoints::Keep, true)] {
            let (_, got) = hull(&points, policy);
            prop_assert_eq!(sorted(got), exact::convex_hull_2d_vertex_set(&points, keep));
        }
    }

    #[test]
    fn hull_theorem_convex_combination(points in prop::collection::vec(vec2_in(-100.0, 100.0), 3..30)) {
        convex_combination_of_hull(&points)?;
        exactly_inside_every_edge(&points)?;
    }

    #[test]
    fn hull_theorem_on_grids(points in grid_points(60)) {
        convex_combination_of_hull(&points)?;
        exactly_inside_every_edge(&points)?;
    }

    #[test]
    fn total_on_any_bits(points in prop::collection::vec(vec2_bits(), 0..12)) {
        check_convex_hull_2d(&points).map_err(TestCaseError::fail)?;
    }

    /// Reordering the input changes which indices are reported, never the vertices' positions
    /// or their order (the start is the lowest point in both).
    #[test]
    fn permutation_invariant(points in grid_points(50), seed in any::<u64>()) {
        let mut perm: Vec<usize> = (0..points.len()).collect();
        let mut s = seed | 1;
        for i in (1..perm.len()).rev() {
            s ^= s << 13; s ^= s >> 7; s ^= s << 17;
            perm.swap(i, (s % (i as u64 + 1)) as usize);
        }
        let shuffled: Vec<Vec2> = perm.iter().map(|&i| points[i]).collect();
        for policy in POLICIES {
            let a = convex_hull_2d(&points, policy).unwrap();
            let b = convex_hull_2d(&shuffled, policy).unwrap();
            let pa: Vec<Vec2> = a.positions(&points).map(|p| p + Vec2::ZERO).collect();
            let pb: Vec<Vec2> = b.positions(&shuffled).map(|p| p + Vec2::ZERO).collect();
            prop_assert_eq!(pa, pb);
            prop_assert_eq!(a.shape(), b.shape());
        }
    }

    /// Scaling by a power of two is exact, so the hull's indices cannot change: huge and tiny
    /// coordinates are as exact as unit ones.
    #[test]
    fn scale_invariant(points in prop::collection::vec(vec2_in(-100.0, 100.0), 0..40), k in -120i32..=120) {
        let s = 2f32.powi(k);
        let scaled: Vec<Vec2> = points.iter().map(|&p| p * s).collect();
        prop_assume!(scaled.iter().zip(&points).all(|(&q, &p)| q / s == p && q.is_finite()));
        for policy in POLICIES {
            prop_assert_eq!(hull(&points, policy), hull(&scaled, policy));
        }
    }

    #[test]
    fn matches_spade(points in prop::collection::vec(vec2_in(-100.0, 100.0), 3..60)) {
        if let Some(theirs) = spade_hull(&points) {
            let ours = convex_hull_2d(&points, CollinearPoints::Keep).unwrap();
            prop_assert_eq!(position_set(ours.positions(&points)), position_set(theirs));
        }
    }

    #[test]
    fn grids_match_spade(points in grid_points(60)) {
        if let Some(theirs) = spade_hull(&points) {
            let ours = convex_hull_2d(&points, CollinearPoints::Keep).unwrap();
            prop_assert_eq!(position_set(ours.positions(&points)), position_set(theirs));
        }
    }
}
