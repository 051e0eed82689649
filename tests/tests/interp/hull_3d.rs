//! The 3D convex hull: validity on random clouds, the convex-hull theorem checked with exact
//! rationals, a brute-force exact reference, permutation and scale invariance, degenerate and
//! non-finite inputs, the hard-case table.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::hard_cases::hulls_3d;
use barytex_interp::{ConvexHull3d, HullDefect3d, HullError3d, convex_hull_3d};
use barytex_testkit::exact;
use barytex_testkit::invariants_3d::{
    BRUTE_FORCE_MAX_POINTS, check_convex_hull_3d, reference_hull_vertices, sorted_vertices,
};
use barytex_testkit::seeded::XorShift;
use barytex_testkit::strategies::{step_ulps, vec3_in};
use glam::Vec3;
use proptest::prelude::*;

/// The convex-hull theorem (Denisjuk, Theorem 15), checked independently of `orient3d` with exact rationals: every input
/// point is on the inner side of (or on) every facet, so it is a convex combination of the
/// hull's corners; and the corners are input points (indices in range).
fn assert_hull_theorem(points: &[Vec3], hull: &ConvexHull3d) {
    for &v in hull.vertices() {
        assert!(v < points.len());
    }
    for &[a, b, c] in hull.facets() {
        for (i, &p) in points.iter().enumerate() {
            let s = exact::orient3d_sign(points[a], points[b], points[c], p);
            assert!(s <= 0, "point {i} is outside facet {:?}", [a, b, c]);
        }
    }
}

/// The most rational point-facet tests one hull-theorem check may make (about a second).
const RATIONAL_BUDGET: usize = 40_000;

fn corner_points(points: &[Vec3], hull: &ConvexHull3d) -> Vec<[u32; 3]> {
    let mut v: Vec<[u32; 3]> = hull
        .vertices()
        .iter()
        .map(|&i| {
            let p = points[i] + Vec3::ZERO; // -0.0 + 0.0 = +0.0: compare values, not signs of zero
            [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
        })
        .collect();
    v.sort_unstable();
    v
}

fn cloud(rng: &mut XorShift, n: usize, shape: &str) -> Vec<Vec3> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        let p = rng.vec3_in(-1.0, 1.0);
        let len = p.length();
        match shape {
            "cube" => out.push(p),
            "ball" if len <= 1.0 => out.push(p),
            "sphere" if len > 0.1 && len <= 1.0 => out.push(p / len),
            "grid" => out.push((p * 3.0).round()),
            _ => {}
        }
    }
    out
}

#[test]
fn random_clouds_are_valid() {
    let mut rng = XorShift::new(0x3d);
    for shape in ["cube", "ball", "sphere", "grid"] {
        for n in [4, 5, 10, 50, 300] {
            let mut points = cloud(&mut rng, n, shape);
            // Duplicates of a few points.
            let dups: Vec<Vec3> = points.iter().step_by(7).copied().collect();
            points.extend(dups);
            check_convex_hull_3d(&points).unwrap_or_else(|e| panic!("{shape} {n}: {e}"));
            let hull = convex_hull_3d(&points).unwrap();
            if points.len() * hull.facets().len() <= RATIONAL_BUDGET {
                assert_hull_theorem(&points, &hull);
            }
        }
    }
}

#[test]
fn sphere_surface_points_are_all_corners() {
    let mut rng = XorShift::new(0x5f);
    let points = cloud(&mut rng, 500, "sphere");
    let hull = convex_hull_3d(&points).unwrap();
    hull.validate(&points).unwrap();
    // Points on a sphere (to f32 rounding) are in convex position unless rounding flattens one:
    // at this density none are.
    assert_eq!(hull.vertices().len(), 500);
    assert_eq!(hull.facets().len(), 2 * 500 - 4);
}

#[test]
fn integer_grid_is_a_cube() {
    // The full grid [-3, 3]³ (343 points, 7² coplanar on each face, 7 collinear on each edge),
    // twice, in a seeded shuffled order.
    let mut points: Vec<Vec3> = (0..2 * 343)
        .map(|i| {
            let i = i % 343;
            Vec3::new((i % 7) as f32, ((i / 7) % 7) as f32, (i / 49) as f32) - Vec3::splat(3.0)
        })
        .collect();
    let mut rng = XorShift::new(7);
    for i in (1..points.len()).rev() {
        points.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
    }
    let hull = convex_hull_3d(&points).unwrap();
    hull.validate(&points).unwrap();
    assert_hull_theorem(&points, &hull);
    let corners: Vec<Vec3> = hull.vertices().iter().map(|&i| points[i]).collect();
    assert_eq!(corners.len(), 8, "{corners:?}");
    assert!(corners.iter().all(|c| c.abs() == Vec3::splat(3.0)));
    assert_eq!(hull.facets().len(), 12);
    // Of two equal corners, the lower index represents both.
    for &v in hull.vertices() {
        assert_eq!(points.iter().position(|&p| p == points[v]), Some(v));
    }
}

proptest! {
    /// Small inputs against the brute-force exact reference (inside `check_convex_hull_3d`):
    /// integer points of a 3³ grid, so coplanar, collinear and equal points are common.
    #[test]
    fn small_grid_inputs_match_brute_force(
        points in proptest::collection::vec(
            (0i32..3, 0i32..3, 0i32..3).prop_map(|(x, y, z)| Vec3::new(x as f32, y as f32, z as f32)),
            0..=BRUTE_FORCE_MAX_POINTS,
        )
    ) {
        check_convex_hull_3d(&points).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn small_random_inputs_match_brute_force(
        points in proptest::collection::vec(vec3_in(-1e3, 1e3), 0..=BRUTE_FORCE_MAX_POINTS)
    ) {
        check_convex_hull_3d(&points).map_err(TestCaseError::fail)?;
    }

    /// Last-ulp clouds: coordinates 1 + (0..4) ulps, flat and degenerate at every turn.
    #[test]
    fn last_ulp_inputs_match_brute_force(
        points in proptest::collection::vec(
            (0u32..4, 0u32..4, 0u32..4).prop_map(|(x, y, z)| {
                let f = |k: u32| f32::from_bits(1.0f32.to_bits() + k);
                Vec3::new(f(x), f(y), f(z))
            }),
            0..=BRUTE_FORCE_MAX_POINTS,
        )
    ) {
        check_convex_hull_3d(&points).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn larger_inputs_are_valid(
        points in proptest::collection::vec(
            prop_oneof![
                vec3_in(-1.0, 1.0),
                (0i32..4, 0i32..4, 0i32..4).prop_map(|(x, y, z)| Vec3::new(x as f32, y as f32, z as f32)),
            ],
            0..80,
        )
    ) {
        check_convex_hull_3d(&points).map_err(TestCaseError::fail)?;
    }

    /// The vertex set (as points) does not depend on the input order.
    #[test]
    fn vertex_set_is_permutation_invariant(
        points in proptest::collection::vec(
            (0i32..4, 0i32..4, 0i32..4).prop_map(|(x, y, z)| Vec3::new(x as f32, y as f32, z as f32)),
            0..60,
        ),
        seed in 1u64..u64::MAX,
    ) {
        let hull = convex_hull_3d(&points).unwrap();
        let mut shuffled = points.clone();
        let mut rng = XorShift::new(seed);
        for i in (1..shuffled.len()).rev() {
            shuffled.swap(i, (rng.next_u64() % (i as u64 + 1)) as usize);
        }
        let again = convex_hull_3d(&shuffled).unwrap();
        prop_assert_eq!(corner_points(&points, &hull), corner_points(&shuffled, &again));
    }

    /// Scaling by a power of two is exact, so the hull's indices do not change at all, from
    /// 2⁻¹⁰⁰ (coordinates near 1e-30) to 2¹⁰⁰ (near 1e30).
    #[test]
    fn power_of_two_scaling_keeps_the_hull(
        points in proptest::collection::vec(vec3_in(-1.0, 1.0), 0..40),
        exponent in -100i32..=100,
    ) {
        let hull = convex_hull_3d(&points).unwrap();
        let scaled: Vec<Vec3> = points.iter().map(|&p| p * 2f32.powi(exponent)).collect();
        prop_assert_eq!(convex_hull_3d(&scaled).unwrap(), hull);
    }
}

#[test]
fn hard_cases_are_valid() {
    for case in hulls_3d() {
        let label = format!("{} ({})", case.name, case.parameter);
        check_convex_hull_3d(&case.points).unwrap_or_else(|e| panic!("{label}: {e}"));
        let hull = convex_hull_3d(&case.points).unwrap();
        if case.points.len() * hull.facets().len() <= RATIONAL_BUDGET {
            assert_hull_theorem(&case.points, &hull);
        }
        if let Some(corners) = case.corners {
            assert_eq!(hull.vertices().len(), corners, "{label}: {hull:?}");
        }
        println!(
            "{label}: {} points, {} corners",
            case.points.len(),
            hull.vertices().len()
        );
    }
}

#[test]
fn degenerate_inputs_are_typed() {
    assert_eq!(convex_hull_3d(&[]).unwrap(), ConvexHull3d::Empty);
    assert_eq!(
        convex_hull_3d(&[Vec3::ONE]).unwrap(),
        ConvexHull3d::Point { index: 0 }
    );
    assert_eq!(
        convex_hull_3d(&[Vec3::ONE, Vec3::ONE, Vec3::new(1.0, -0.0, 1.0) + Vec3::Y]).unwrap(),
        ConvexHull3d::Point { index: 0 }
    );
    let line: Vec<Vec3> = [3.0, -1.0, 7.0, 2.0, -1.0, 7.0]
        .iter()
        .map(|&t| Vec3::new(t, 2.0 * t, -t))
        .collect();
    assert_eq!(
        convex_hull_3d(&line).unwrap(),
        ConvexHull3d::Segment { ends: [1, 2] }
    );
    // A square in the plane x = 2 with a centre point and a point on an edge: a polygon,
    // counter-clockwise seen from +x in (y, z), starting at the lowest index.
    let square = [
        Vec3::new(2.0, 1.0, 1.0),
        Vec3::new(2.0, 0.0, 0.0),
        Vec3::new(2.0, 0.5, 0.5),
        Vec3::new(2.0, 0.0, 1.0),
        Vec3::new(2.0, 1.0, 0.0),
        Vec3::new(2.0, 0.5, 0.0),
    ];
    assert_eq!(
        convex_hull_3d(&square).unwrap(),
        ConvexHull3d::Polygon {
            vertices: vec![0, 3, 1, 4],
            dropped_axis: 0
        }
    );
    check_convex_hull_3d(&square).unwrap();
    // A tetrahedron: four facets, outward.
    let tet = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    let hull = convex_hull_3d(&tet).unwrap();
    assert_eq!(
        hull,
        ConvexHull3d::Polytope {
            vertices: vec![0, 1, 2, 3],
            facets: vec![[0, 1, 3], [0, 2, 1], [0, 3, 2], [1, 2, 3]],
        }
    );
    assert_eq!(reference_hull_vertices(&tet), vec![0, 1, 2, 3]);
}

#[test]
fn non_finite_input_names_the_point() {
    for v in barytex_interp::hard_cases::NON_FINITE {
        let points = [Vec3::ZERO, Vec3::X, Vec3::new(0.0, v, 0.0), Vec3::splat(v)];
        assert_eq!(
            convex_hull_3d(&points),
            Err(HullError3d::NonFinite { index: 2 })
        );
        check_convex_hull_3d(&points).unwrap();
    }
}

#[test]
fn validate_finds_defects() {
    let cube: Vec<Vec3> = (0..8)
        .map(|i| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, (i >> 2) as f32))
        .collect();
    let ConvexHull3d::Polytope { vertices, facets } = convex_hull_3d(&cube).unwrap() else {
        panic!("a cube is a polytope");
    };
    // A facet flipped: its edges no longer pair up.
    let mut flipped = facets.clone();
    flipped[0].swap(1, 2);
    let bad = ConvexHull3d::Polytope {
        vertices: vertices.clone(),
        facets: flipped,
    };
    assert!(bad.validate(&cube).is_err());
    // A point added outside.
    let mut more = cube.clone();
    more.push(Vec3::splat(2.0));
    let hull = ConvexHull3d::Polytope {
        vertices: vertices.clone(),
        facets: facets.clone(),
    };
    assert!(matches!(
        hull.validate(&more),
        Err(HullDefect3d::PointOutside { point: 8, .. })
    ));
    // A face centre made a vertex (flat): fan the bottom face around it.
    let mut flat = cube.clone();
    flat.push(Vec3::new(0.5, 0.5, 0.0));
    let mut fan: Vec<[usize; 3]> = facets
        .iter()
        .copied()
        .filter(|f| !f.iter().all(|&i| cube[i].z == 0.0))
        .collect();
    // Bottom face corners 0 (0,0), 1 (1,0), 3 (1,1), 2 (0,1); seen from below (outside) they run
    // clockwise in (x, y): 0 → 2 → 3 → 1.
    for [a, b] in [[0, 2], [2, 3], [3, 1], [1, 0]] {
        fan.push([a, b, 8]);
    }
    let mut with_centre = vertices.clone();
    with_centre.push(8);
    let flat_hull = ConvexHull3d::Polytope {
        vertices: with_centre,
        facets: fan,
    };
    assert_eq!(
        flat_hull.validate(&flat),
        Err(HullDefect3d::NotStrictCorner { vertex: 8 })
    );
    assert_eq!(
        ConvexHull3d::Point { index: 0 }.validate(&cube),
        Err(HullDefect3d::WrongKind { point: 1 })
    );
}

/// Points that differ in the last ulp around a large offset, and a box whose sides are single
/// ulps: still exact.
#[test]
fn last_ulp_boxes_are_exact() {
    for offset in [1.0f32, 1e7, 1e30, 1e-30] {
        let f = |k: i32| step_ulps(offset, k);
        let mut points = Vec::new();
        for i in 0..3 {
            for j in 0..3 {
                for k in 0..3 {
                    points.push(Vec3::new(f(i), f(j), f(k)));
                }
            }
        }
        let hull = convex_hull_3d(&points).unwrap();
        check_convex_hull_3d(&points).unwrap();
        assert_eq!(hull.vertices().len(), 8, "offset {offset}");
        assert_eq!(sorted_vertices(&hull), vec![0, 2, 6, 8, 18, 20, 24, 26]);
    }
}
