//! 2D barycentric coordinates: Denisjuk's worked examples and theorems, the accuracy bar, the
//! hard-case table, special values.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::hard_cases::triangles_2d;
use barytex_interp::methods::{
    barycentric_2d_dop_f32, barycentric_2d_f64, barycentric_2d_naive_f32,
};
use barytex_interp::{InterpError, Location, barycentric_2d, interpolate3, locate_2d};
use barytex_testkit::exact::{self, Q, qf};
use barytex_testkit::invariants::{barycentric_bar, barycentric_condition, check_barycentric_2d};
use barytex_testkit::strategies::{
    near_degenerate_triangle_2d, scaled_triangle_2d, triangle_2d, vec2_bits, vec2_in,
};
use glam::Vec2;
use num_bigint::BigInt;
use proptest::prelude::*;

const EXAMPLE_TRIANGLE: [Vec2; 3] = [
    Vec2::new(0.0, 0.0),
    Vec2::new(2.0, 3.0),
    Vec2::new(3.0, 1.0),
];

fn ratio(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// Assert that f32 weights are the correctly rounded exact rationals (error ≤ ½ ulp).
fn assert_weights(got: [f32; 3], want: [(i64, i64); 3]) {
    for (g, (n, d)) in got.iter().zip(want) {
        let exact = ratio(n, d);
        let nearest = exact::to_f64(&exact) as f32;
        assert_eq!(*g, nearest, "weight {g} vs {n}/{d}");
    }
}

/// Denisjuk, Example 7: the weights it lists, from the points they give.
#[test]
fn denisjuk_example_7() {
    let cases = [
        (
            Vec2::new(2.0, 3.0),
            [(0, 1), (1, 1), (0, 1)],
            Location::OnVertex(1),
        ),
        (
            Vec2::new(2.0 / 3.0, 1.0),
            [(2, 3), (1, 3), (0, 1)],
            Location::OnEdge(2),
        ),
        (
            Vec2::new(-5.0 / 3.0, 1.0),
            [(4, 3), (2, 3), (-1, 1)],
            Location::Outside,
        ),
    ];
    for (p, want, location) in cases {
        // The f32 point is not exactly the rational one; compare with the exact weights of the
        // f32 point and also check they round to the text's answer.
        let b = barycentric_2d(p, EXAMPLE_TRIANGLE).unwrap();
        check_barycentric_2d(p, EXAMPLE_TRIANGLE).unwrap();
        if p == Vec2::new(2.0, 3.0) {
            assert_eq!(b.weights, [0.0, 1.0, 0.0]);
            // The example's triangle is clockwise: zero weights must still be +0.0, not -0.0.
            assert!(
                b.weights.iter().all(|w| w.is_sign_positive()),
                "{:?}",
                b.weights
            );
        }
        for (g, (n, d)) in b.weights.iter().zip(want) {
            assert!(
                (f64::from(*g) - n as f64 / d as f64).abs() < 1e-6,
                "{g} vs {n}/{d}"
            );
        }
        if p.x.fract() == 0.0 {
            assert_eq!(b.location, location);
        }
    }
}

/// Denisjuk, Example 9: the points u = (2,3), (11/3,2), (3/2,3/2), (1,0) in the same triangle.
#[test]
fn denisjuk_example_9() {
    let b = barycentric_2d(Vec2::new(2.0, 3.0), EXAMPLE_TRIANGLE).unwrap();
    assert_weights(b.weights, [(0, 1), (1, 1), (0, 1)]);
    let b = barycentric_2d(Vec2::new(1.5, 1.5), EXAMPLE_TRIANGLE).unwrap();
    assert_weights(b.weights, [(5, 14), (3, 7), (3, 14)]);
    assert_eq!(b.location, Location::Inside);
    let b = barycentric_2d(Vec2::new(1.0, 0.0), EXAMPLE_TRIANGLE).unwrap();
    assert_weights(b.weights, [(5, 7), (-1, 7), (3, 7)]);
    assert_eq!(b.location, Location::Outside);
    // 11/3 is not an f32: the weights are those of the nearest f32 point, close to (−1/3, 1/3, 1).
    let p = Vec2::new(11.0 / 3.0, 2.0);
    let b = barycentric_2d(p, EXAMPLE_TRIANGLE).unwrap();
    check_barycentric_2d(p, EXAMPLE_TRIANGLE).unwrap();
    for (g, want) in b.weights.iter().zip([-1.0 / 3.0, 1.0 / 3.0, 1.0]) {
        assert!((f64::from(*g) - want).abs() < 1e-6);
    }
    assert_eq!(b.location, Location::Outside);
}

/// The centroid has (1/3, 1/3, 1/3); a vertex has (1, 0, 0).
#[test]
fn centroid_and_vertex() {
    let tri = [
        Vec2::new(0.0, 0.0),
        Vec2::new(3.0, 0.0),
        Vec2::new(0.0, 3.0),
    ];
    let b = barycentric_2d(Vec2::new(1.0, 1.0), tri).unwrap();
    assert_weights(b.weights, [(1, 3), (1, 3), (1, 3)]);
    assert_eq!(b.location, Location::Inside);
    for (i, v) in tri.iter().enumerate() {
        let b = barycentric_2d(*v, tri).unwrap();
        let mut want = [0.0; 3];
        want[i] = 1.0;
        assert_eq!(b.weights, want);
        assert_eq!(b.location, Location::OnVertex(i));
    }
}

proptest! {
    /// Theorems 4 and 5 (existence, uniqueness) and reconstruction: the weights reproduce the
    /// point, and the exact weights are the unique solution.
    #[test]
    fn existence_uniqueness_reconstruction(tri in triangle_2d(), p in vec2_in(-200.0, 200.0)) {
        let b = barycentric_2d(p, tri).unwrap();
        let back = interpolate3(tri.map(|v| v.as_dvec2()), b.weights);
        let err = (back - p.as_dvec2()).length();
        let kappa = barycentric_condition(p, tri);
        let size = tri.iter().map(|v| v.length()).fold(p.length(), f32::max);
        prop_assert!(err <= 8.0 * f64::from(f32::EPSILON) * f64::from(size) * (1.0 + kappa), "reconstruction error {err}");
        let sum: f64 = b.weights.iter().map(|&w| f64::from(w)).sum();
        prop_assert!((sum - 1.0).abs() <= 1e-6 * (1.0 + kappa));
        check_barycentric_2d(p, tri).map_err(TestCaseError::fail)?;
    }

    /// Theorem 8: weight i is the area of the sub-triangle opposite vertex i over the total.
    #[test]
    fn area_ratio_formula(tri in triangle_2d(), p in vec2_in(-200.0, 200.0)) {
        let b = barycentric_2d(p, tri).unwrap();
        let total = exact::orient2d_det(tri[0], tri[1], tri[2]);
        let areas = [
            exact::orient2d_det(p, tri[1], tri[2]),
            exact::orient2d_det(tri[0], p, tri[2]),
            exact::orient2d_det(tri[0], tri[1], p),
        ];
        for (w, a) in b.weights.iter().zip(&areas) {
            let want = exact::to_f64(&(a / &total));
            prop_assert!((f64::from(*w) - want).abs() <= 2.0 * barytex_testkit::ulp::ulp_f32(want));
        }
        // Sign pattern: inside iff all areas have the triangle's sign.
        let inside = areas.iter().all(|a| exact::to_f64(a).signum() == exact::to_f64(&total).signum());
        prop_assert_eq!(b.location == Location::Inside, inside && areas.iter().all(|a| exact::to_f64(a) != 0.0));
    }

    /// The default is within the bar (and its own tighter bound) on well-shaped triangles at
    /// any scale and offset.
    #[test]
    fn barycentric_2d_within_bar(tri in triangle_2d(), p in vec2_in(-150.0, 150.0)) {
        check_barycentric_2d(p, tri).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn barycentric_2d_within_bar_scaled(
        scale in prop::sample::select(vec![1e-30f32, 1e-10, 1e-3, 1.0, 1e3, 1e10, 1e30]),
        offset in prop::sample::select(vec![0.0f32, 1e4, 1e7, -1e7]),
        tri_seed in triangle_2d(),
        t in (0.0f32..1.0, 0.0f32..1.0),
    ) {
        let tri = tri_seed.map(|v| v * (scale / 100.0) + Vec2::splat(offset));
        let p = tri[0] + (tri[1] - tri[0]) * t.0 + (tri[2] - tri[0]) * t.1 * 0.5;
        check_barycentric_2d(p, tri).map_err(TestCaseError::fail)?;
    }

    /// Exact classification on points placed on edges and vertices and a few ulps off them.
    #[test]
    fn locate_matches_exact_rational(tri in near_degenerate_triangle_2d(), p in vec2_in(-100.0, 100.0)) {
        check_barycentric_2d(p, tri).map_err(TestCaseError::fail)?;
        // A point on the (near-)degenerate triangle's long edge.
        check_barycentric_2d(tri[2], [tri[0], tri[1], p]).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn total_on_any_bits(p in vec2_bits(), a in vec2_bits(), b in vec2_bits(), c in vec2_bits()) {
        check_barycentric_2d(p, [a, b, c]).map_err(TestCaseError::fail)?;
    }

    /// Affine maps preserve barycentric coordinates (Theorem 3 applied to Theorem 4).
    #[test]
    fn affine_invariance(tri in scaled_triangle_2d(10.0, 0.0), t in (0.0f32..1.0, 0.0f32..1.0)) {
        let p = tri[0] + (tri[1] - tri[0]) * t.0 * 0.5 + (tri[2] - tri[0]) * t.1 * 0.5;
        let b = barycentric_2d(p, tri).unwrap();
        // An affine map that rounds nothing (powers of two and an axis swap) leaves every
        // determinant scaled by the same power of two, so the weights are bit-identical.
        let map = |v: Vec2| Vec2::new(v.y * 0.5, v.x * 4.0);
        let b2 = barycentric_2d(map(p), tri.map(map)).unwrap();
        prop_assert_eq!(b.weights, b2.weights);
        prop_assert_eq!(b.location, b2.location);
    }
}

/// Acceptance: every 2D hard case is classified exactly and every weight is within the bar;
/// the naive f32 method is measured on the same cases to show the table is hard.
#[test]
fn hard_cases_within_bar() {
    let mut naive_over_bar = 0;
    for case in triangles_2d() {
        check_barycentric_2d(case.point, case.triangle)
            .unwrap_or_else(|e| panic!("{} ({}): {e}", case.name, case.parameter));
        if let Some(want) = case.expected {
            assert_eq!(
                locate_2d(case.point, case.triangle).unwrap(),
                want,
                "{}",
                case.name
            );
        }
        let exact_w = exact::barycentric_2d(case.point, case.triangle).unwrap();
        let kappa = barycentric_condition(case.point, case.triangle);
        // The other methods must not panic on the table either.
        let _ = barycentric_2d_dop_f32(case.point, case.triangle);
        let _ = barycentric_2d_f64(case.point, case.triangle);
        let w = barycentric_2d_naive_f32(case.point, case.triangle);
        for (wi, e) in w.iter().zip(&exact_w) {
            let err = if wi.is_finite() {
                exact::abs_diff(&qf(*wi), e)
            } else {
                f64::INFINITY
            };
            if err > barycentric_bar(exact::to_f64(e), kappa) {
                naive_over_bar += 1;
            }
        }
    }
    println!("naive f32 weights over the bar on the hard-case table: {naive_over_bar}");
    assert!(
        naive_over_bar > 0,
        "the hard-case table no longer challenges the naive formula"
    );
}

#[test]
fn degenerate_and_non_finite() {
    let line = [Vec2::ZERO, Vec2::ONE, Vec2::splat(2.0)];
    assert_eq!(
        barycentric_2d(Vec2::X, line),
        Err(InterpError::DegenerateTriangle)
    );
    assert_eq!(locate_2d(Vec2::X, line), Ok(Location::Degenerate));
    let point = [Vec2::ONE; 3];
    assert_eq!(
        barycentric_2d(Vec2::ONE, point),
        Err(InterpError::DegenerateTriangle)
    );
    for v in barytex_interp::hard_cases::NON_FINITE {
        assert_eq!(
            barycentric_2d(Vec2::new(v, 0.0), EXAMPLE_TRIANGLE),
            Err(InterpError::NonFinite { what: "point" })
        );
        assert_eq!(
            locate_2d(Vec2::ZERO, [Vec2::ZERO, Vec2::new(1.0, v), Vec2::Y]),
            Err(InterpError::NonFinite { what: "triangle" })
        );
    }
}

#[test]
fn clockwise_triangles_give_the_same_weights() {
    let ccw = [
        Vec2::new(0.0, 0.0),
        Vec2::new(4.0, 1.0),
        Vec2::new(1.0, 3.0),
    ];
    let cw = [ccw[0], ccw[2], ccw[1]];
    let p = Vec2::new(1.5, 1.25);
    let a = barycentric_2d(p, ccw).unwrap();
    let b = barycentric_2d(p, cw).unwrap();
    assert_eq!(a.weights, [b.weights[0], b.weights[2], b.weights[1]]);
    assert_eq!(a.location, Location::Inside);
    assert_eq!(b.location, Location::Inside);
}
