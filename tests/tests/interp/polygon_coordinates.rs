//! Generalized barycentric coordinates over convex polygons (Wachspress, mean value): partition
//! of unity, linear precision, non-negativity, the triangle case, rotation invariance, the
//! Lagrange property, boundary linearity, scale and translation invariance, near-degenerate
//! polygons, typed errors, the hard-case table, and the split-dependence of interpolating over a polygon's triangles.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::hard_cases::polygons;
use barytex_interp::{
    GeneralizedBarycentric, PolygonError, PolygonLocation, barycentric_2d, interpolate_polygon,
    interpolate3, mean_value_weights, wachspress_weights,
};
use barytex_testkit::exact;
use barytex_testkit::polygon_invariants::{
    check_polygon_all, check_polygon_coordinates, exact_wachspress, expected_validation,
    mean_value_reference_f64, polygon_on_ellipse,
};
use barytex_testkit::strategies::{step_ulps, vec2_bits};
use barytex_testkit::ulp::ulp_f32;
use glam::Vec2;
use proptest::prelude::*;

use GeneralizedBarycentric::{MeanValue, Wachspress};

/// A convex polygon of 3 to 16 vertices on a perturbed ellipse in about `[-10, 10]²`, gaps
/// between angles at least a fifth of the mean, either orientation.
fn convex_polygon() -> impl Strategy<Value = Vec<Vec2>> {
    (
        prop::collection::vec(0.2f64..1.0, 3..=16),
        0.0f64..6.3,
        (0.5f32..5.0, 0.5f32..5.0),
        (-5.0f32..5.0, -5.0f32..5.0),
        any::<bool>(),
    )
        .prop_map(|(gaps, start, (rx, ry), (cx, cy), clockwise)| {
            let mut poly = polygon_on_ellipse(Vec2::new(cx, cy), Vec2::new(rx, ry), start, &gaps);
            if clockwise {
                poly.reverse();
            }
            poly
        })
        .prop_filter("strictly convex after rounding", |poly| {
            expected_validation(Wachspress, Vec2::ZERO, poly).is_ok()
        })
}

/// A point from affine weights over the polygon's vertices: mostly inside (convex weights),
/// sometimes outside.
fn point_in(poly: &[Vec2], raw: &[f32], outside: bool) -> Vec2 {
    let n = poly.len();
    let w: Vec<f64> = (0..n).map(|i| f64::from(raw[i % raw.len()])).collect();
    let sum: f64 = w.iter().sum();
    let mut p = glam::DVec2::ZERO;
    for (v, wi) in poly.iter().zip(&w) {
        p += v.as_dvec2() * (wi / sum);
    }
    if outside {
        // Reflect through vertex 0 and push further: outside the polygon.
        p = poly[0].as_dvec2() * 2.5 - p * 1.5;
    }
    p.as_vec2()
}

fn polygon_and_point() -> impl Strategy<Value = (Vec<Vec2>, Vec2)> {
    (
        convex_polygon(),
        prop::collection::vec(0.001f32..1.0, 1..=16),
        prop::bool::weighted(0.2),
    )
        .prop_map(|(poly, raw, outside)| {
            let p = point_in(&poly, &raw, outside);
            (poly, p)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Every documented property (exact location, partition of unity, linear precision,
    /// non-negativity inside, Wachspress within 1 ulp of exact, outside bounds) and bit-identical
    /// rotation invariance, for both methods.
    #[test]
    fn properties_hold_on_convex_polygons((poly, p) in polygon_and_point()) {
        prop_assert_eq!(check_polygon_all(p, &poly), Ok(()));
    }

    /// Scale invariance within the bound: the same checks at scales 1e-20 and 1e30 and at
    /// offset 1e6 (the polygon rounded to f32 there, so a different but still convex polygon).
    #[test]
    fn properties_hold_scaled_and_offset(
        (poly, p) in polygon_and_point(),
        which in 0usize..4,
    ) {
        let (scale, offset) = [(1e-20f32, 0.0f32), (1e30, 0.0), (1.0, 1e6), (1e-3, 1e3)][which];
        let map = |v: Vec2| v * scale + Vec2::splat(offset);
        let poly: Vec<Vec2> = poly.iter().copied().map(map).collect();
        for method in GeneralizedBarycentric::ALL {
            prop_assert_eq!(check_polygon_coordinates(method, map(p), &poly), Ok(()));
        }
    }

    /// Multiplying every coordinate by 2ᵏ changes nothing: the weights are bit-identical.
    #[test]
    fn power_of_two_scaling_is_bit_identical((poly, p) in polygon_and_point(), k in -60i32..60) {
        let s = 2f32.powi(k);
        let scaled: Vec<Vec2> = poly.iter().map(|&v| v * s).collect();
        for method in GeneralizedBarycentric::ALL {
            let mut a = vec![0.0; poly.len()];
            let mut b = vec![0.0; poly.len()];
            let ra = method.weights(p, &poly, &mut a);
            let rb = method.weights(p * s, &scaled, &mut b);
            prop_assert_eq!(ra, rb);
            prop_assert_eq!(a, b);
        }
    }

    /// Translating by an offset that keeps every coordinate exact (a multiple of 1/16 moved by
    /// 2¹⁸, where the f32 spacing is 2⁻⁵) is the same geometry: Wachspress weights within 2 ulp (each within 1 ulp of the same
    /// exact weight), mean value within the documented ε-level bound.
    #[test]
    fn exact_translation_is_invariant_within_bound(
        poly in convex_polygon(),
        raw in prop::collection::vec(0.001f32..1.0, 1..=16),
    ) {
        let grid = |v: Vec2| (v * 16.0).round() / 16.0;
        let poly: Vec<Vec2> = poly.iter().copied().map(grid).collect();
        prop_assume!(expected_validation(Wachspress, Vec2::ZERO, &poly).is_ok());
        let p = grid(point_in(&poly, &raw, false));
        let offset = Vec2::new(131_072.0, -262_144.0);
        let moved: Vec<Vec2> = poly.iter().map(|&v| v + offset).collect();
        for method in GeneralizedBarycentric::ALL {
            let mut a = vec![0.0; poly.len()];
            let mut b = vec![0.0; poly.len()];
            prop_assert_eq!(method.weights(p, &poly, &mut a), method.weights(p + offset, &moved, &mut b));
            for (x, y) in a.iter().zip(&b) {
                let bound = match method {
                    Wachspress => 2.0 * ulp_f32(f64::from(*x)),
                    MeanValue => 2.0 * f64::from(f32::EPSILON),
                };
                prop_assert!(f64::from((x - y).abs()) <= bound, "{method:?}: {a:?} vs {b:?}");
            }
        }
    }

    /// On a triangle both methods are the ordinary barycentric coordinates: Wachspress within
    /// 2 ulp of `barycentric_2d` (each within 1 ulp of the exact weight), mean value within
    /// 2 ulp + 2⁻²⁶.
    #[test]
    fn triangles_reduce_to_barycentric(
        (poly, p) in polygon_and_point().prop_filter("triangles", |(poly, _)| poly.len() == 3),
    ) {
        let tri = [poly[0], poly[1], poly[2]];
        let b = barycentric_2d(p, tri).unwrap();
        for method in GeneralizedBarycentric::ALL {
            let mut w = [0.0; 3];
            prop_assert!(method.weights(p, &poly, &mut w).is_ok());
            for (x, y) in w.iter().zip(b.weights) {
                let slack = if method == Wachspress { 0.0 } else { 2f64.powi(-26) };
                let bound = 2.0 * ulp_f32(f64::from(y)) + slack;
                prop_assert!(f64::from((x - y).abs()) <= bound, "{method:?}: {w:?} vs {:?}", b.weights);
            }
        }
    }

    /// Near-degenerate: a vertex inserted between two consecutive ones, at their midpoint moved
    /// a few ulps (collinear, slightly convex or slightly reflex), and points within 1e-7 of an
    /// edge or a vertex, or exactly on a vertex. Exact classification decides every case.
    #[test]
    fn near_degenerate_polygons_and_points(
        poly in convex_polygon(),
        edge in 0usize..16,
        k in -3i32..=3,
        t in 0.0f32..=1.0,
        which in 0usize..4,
        d in -1e-7f32..1e-7,
    ) {
        let n = poly.len();
        let i = edge % n;
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let m = a + (b - a) * 0.5;
        let mut nearly = poly.clone();
        nearly.insert(i + 1, Vec2::new(step_ulps(m.x, k), step_ulps(m.y, k)));
        let on_edge = a + (b - a) * t;
        let p = match which {
            0 => on_edge,
            1 => on_edge + Vec2::new(d, -d),
            2 => a + Vec2::splat(d),
            _ => a,
        };
        prop_assert_eq!(check_polygon_all(p, &poly), Ok(()));
        prop_assert_eq!(check_polygon_all(p, &nearly), Ok(()));
        prop_assert_eq!(check_polygon_all(m, &nearly), Ok(()));
    }

    /// Mean value weights agree with the textbook `atan2` formula in f64 within 2⁻²² on
    /// well-shaped polygons away from the boundary.
    #[test]
    fn mean_value_matches_atan2_reference((poly, p) in polygon_and_point()) {
        let mut w = vec![0.0; poly.len()];
        let loc = mean_value_weights(p, &poly, &mut w).unwrap();
        prop_assume!(loc == PolygonLocation::Inside);
        let reference = mean_value_reference_f64(p, &poly);
        for (x, r) in w.iter().zip(&reference) {
            prop_assert!((f64::from(*x) - r).abs() <= 2f64.powi(-22), "{w:?} vs {reference:?}");
        }
    }

    /// Total on arbitrary bits: NaN, infinities, subnormals, huge values, any vertex count;
    /// never a panic, and every invariant (mostly the typed errors) holds.
    #[test]
    fn total_on_any_bits(p in vec2_bits(), poly in prop::collection::vec(vec2_bits(), 0..7)) {
        prop_assert_eq!(check_polygon_all(p, &poly), Ok(()));
    }
}

/// Wachspress within 1 ulp of the exact rational weights inside, on a fixed regular pentagon
/// scanned on a grid (deterministic companion of the property test).
#[test]
fn wachspress_matches_exact() {
    let poly = barytex_interp::hard_cases::regular_polygon(5);
    let mut w = [0.0; 5];
    let mut inside = 0;
    for i in -20..=20 {
        for j in -20..=20 {
            let p = Vec2::new(i as f32 / 20.0, j as f32 / 20.0);
            let loc = wachspress_weights(p, &poly, &mut w).unwrap();
            if loc != PolygonLocation::Inside {
                continue;
            }
            inside += 1;
            let (exact_w, _) = exact_wachspress(p, &poly).unwrap();
            for (x, e) in w.iter().zip(&exact_w) {
                let err = exact::abs_diff(&exact::qf(*x), e);
                assert!(err <= ulp_f32(exact::to_f64(e)), "{p:?}: {w:?}");
            }
        }
    }
    assert!(inside > 500, "{inside} grid points inside");
}

/// Outside, Wachspress weights are within the documented condition-scaled bound of the exact
/// ones (checked by `check_polygon_coordinates`), including near its pole curve.
#[test]
fn wachspress_outside_within_condition_bound() {
    let poly = barytex_interp::hard_cases::regular_polygon(6);
    let mut undefined = 0;
    for i in -40..=40 {
        for j in -40..=40 {
            let p = Vec2::new(i as f32 / 10.0, j as f32 / 10.0 + 0.013);
            check_polygon_coordinates(Wachspress, p, &poly).unwrap();
            check_polygon_coordinates(MeanValue, p, &poly).unwrap();
            let mut w = [0.0; 6];
            if wachspress_weights(p, &poly, &mut w) == Err(PolygonError::Undefined) {
                undefined += 1;
            }
        }
    }
    // The grid misses the pole curve exactly; a pole is hit by construction below.
    assert_eq!(undefined, 0);
    // The lines of two non-adjacent edges of the square meet nowhere; of a pentagon's edges 0
    // and 2, they meet outside: every product-form numerator vanishes there.
    let pent = [
        Vec2::new(0.0, 0.0),
        Vec2::new(2.0, 0.0),
        Vec2::new(3.0, 1.0),
        Vec2::new(1.0, 3.0),
        Vec2::new(-1.0, 1.0),
    ];
    // Edge 0 is y = 0; edge 2 runs (3,1)→(1,3): x + y = 4; they meet at (4, 0).
    let mut w = [0.0; 5];
    assert_eq!(
        wachspress_weights(Vec2::new(4.0, 0.0), &pent, &mut w),
        Err(PolygonError::Undefined)
    );
    check_polygon_coordinates(MeanValue, Vec2::new(4.0, 0.0), &pent).unwrap();
}

/// The named hard cases: every invariant for both methods (Wachspress rejects the flat-vertex
/// cases with `NotConvex`), and the location the case pins down.
#[test]
fn hard_cases_hold() {
    let mut count = 0;
    for case in polygons() {
        count += 1;
        let check = check_polygon_all(case.point, &case.polygon);
        assert_eq!(check, Ok(()), "{} ({})", case.name, case.parameter);
        for method in GeneralizedBarycentric::ALL {
            let mut w = vec![0.0; case.polygon.len()];
            let got = method.weights(case.point, &case.polygon, &mut w);
            if method == Wachspress && !case.strictly_convex {
                assert!(
                    matches!(got, Err(PolygonError::NotConvex { .. })),
                    "{}: {got:?}",
                    case.name
                );
                continue;
            }
            if let Some(want) = case.expected {
                assert_eq!(
                    got,
                    Ok(want),
                    "{} ({}) {method:?}",
                    case.name,
                    case.parameter
                );
            }
        }
    }
    assert!(count >= 30, "{count} cases");
}

/// Lagrange property: on every vertex of a pentagon, exactly the unit vector.
#[test]
fn lagrange_at_vertices() {
    let poly = barytex_interp::hard_cases::regular_polygon(5);
    for method in GeneralizedBarycentric::ALL {
        for (i, &v) in poly.iter().enumerate() {
            let mut w = [f32::NAN; 5];
            assert_eq!(
                method.weights(v, &poly, &mut w),
                Ok(PolygonLocation::OnVertex(i))
            );
            let mut e = [0.0; 5];
            e[i] = 1.0;
            assert_eq!(w, e);
        }
    }
}

/// Along an edge both methods are the linear interpolation of its two vertices' values, exactly
/// where the parameter is dyadic.
#[test]
fn boundary_is_linear_on_edges() {
    let quad = [
        Vec2::new(0.0, 0.0),
        Vec2::new(4.0, 0.0),
        Vec2::new(5.0, 3.0),
        Vec2::new(0.0, 2.0),
    ];
    let values = [1.0f32, 5.0, -3.0, 2.0];
    for method in GeneralizedBarycentric::ALL {
        for i in 0..4 {
            let (a, b) = (quad[i], quad[(i + 1) % 4]);
            for k in 1..8 {
                let t = k as f32 / 8.0;
                let mut w = [0.0; 4];
                let loc = method.weights(a + (b - a) * t, &quad, &mut w).unwrap();
                assert_eq!(loc, PolygonLocation::OnEdge(i));
                let v = interpolate_polygon(&w, &values).unwrap();
                let want = values[i] * (1.0 - t) + values[(i + 1) % 4] * t;
                assert_eq!(v, want, "{method:?} edge {i} t {t}");
            }
        }
    }
}

/// Interpolated shading depends on the orientation of a polygon that is not a triangle (Foley et
/// al., *Computer Graphics: Principles and Practice*, 2nd ed., "Problems with interpolated
/// shading"). Shading a quad by splitting it into two triangles gives different values at its
/// centre for the two diagonals (and so for a rotated vertex list, which moves the split);
/// Wachspress and mean value give one value, bit-identical under every rotation.
#[test]
fn split_dependence_is_gone() {
    let quad = [
        Vec2::new(0.0, 0.0),
        Vec2::new(4.0, 0.0),
        Vec2::new(5.0, 3.0),
        Vec2::new(0.0, 2.0),
    ];
    let values = [0.0f32, 1.0, 0.0, 1.0];
    let centre = Vec2::new(2.25, 1.25);
    // Fan from vertex `start`: triangles (start, start+1, start+2) and (start, start+2, start+3).
    let fan = |start: usize| {
        let idx = |k: usize| (start + k) % 4;
        for tri in [[idx(0), idx(1), idx(2)], [idx(0), idx(2), idx(3)]] {
            let b = barycentric_2d(centre, tri.map(|i| quad[i])).unwrap();
            if b.location.is_inside_closed() {
                return interpolate3(tri.map(|i| values[i]), b.weights);
            }
        }
        unreachable!("the centre is in one of the two triangles")
    };
    let (diagonal_02, diagonal_13) = (fan(0), fan(1));
    assert!(
        (diagonal_02 - diagonal_13).abs() > 0.1,
        "split along 0–2 gives {diagonal_02}, along 1–3 {diagonal_13}"
    );
    for method in GeneralizedBarycentric::ALL {
        let mut reference = None;
        for shift in 0..4 {
            let rotated: Vec<Vec2> = (0..4).map(|i| quad[(i + shift) % 4]).collect();
            let vals: Vec<f32> = (0..4).map(|i| values[(i + shift) % 4]).collect();
            let mut w = [0.0; 4];
            method.weights(centre, &rotated, &mut w).unwrap();
            let v = interpolate_polygon(&w, &vals).unwrap();
            assert!(v > diagonal_02.min(diagonal_13) && v < diagonal_02.max(diagonal_13));
            assert_eq!(
                *reference.get_or_insert(v),
                v,
                "{method:?} rotation {shift}"
            );
        }
    }
}

/// Each invalid input gets its typed error; nothing panics.
#[test]
fn invalid_inputs_are_typed_errors() {
    let square = [Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y];
    let p = Vec2::splat(0.5);
    for method in GeneralizedBarycentric::ALL {
        let mut w = [0.0; 8];
        let mut run = |poly: &[Vec2], p: Vec2| method.weights(p, poly, &mut w[..poly.len()]);
        assert_eq!(run(&[], p), Err(PolygonError::TooFewVertices { count: 0 }));
        assert_eq!(
            run(&square[..2], p),
            Err(PolygonError::TooFewVertices { count: 2 })
        );
        assert_eq!(
            run(&square, Vec2::new(f32::NAN, 0.0)),
            Err(PolygonError::NonFinite { what: "point" })
        );
        let inf = [Vec2::ZERO, Vec2::X, Vec2::new(f32::INFINITY, 1.0)];
        assert_eq!(
            run(&inf, p),
            Err(PolygonError::NonFinite { what: "polygon" })
        );
        let repeated = [Vec2::ZERO, Vec2::X, Vec2::X, Vec2::Y];
        assert_eq!(
            run(&repeated, p),
            Err(PolygonError::RepeatedVertex { index: 1 })
        );
        let collinear = [Vec2::ZERO, Vec2::X, Vec2::new(3.0, 0.0)];
        assert_eq!(run(&collinear, p), Err(PolygonError::Collinear));
        let dart = [
            Vec2::ZERO,
            Vec2::new(2.0, 1.0),
            Vec2::new(4.0, 0.0),
            Vec2::new(2.0, 3.0),
        ];
        assert_eq!(run(&dart, p), Err(PolygonError::NotConvex { vertex: 1 }));
        let spike = [Vec2::ZERO, Vec2::new(2.0, 0.0), Vec2::X, Vec2::Y];
        assert!(matches!(
            run(&spike, p),
            Err(PolygonError::NotConvex { .. })
        ));
        let pentagram: Vec<Vec2> = (0..5)
            .map(|i| {
                let a = core::f32::consts::TAU * (2 * i) as f32 / 5.0;
                Vec2::new(a.cos(), a.sin())
            })
            .collect();
        assert_eq!(run(&pentagram, p), Err(PolygonError::SelfIntersecting));
    }
    let mut short = [0.0; 3];
    assert_eq!(
        wachspress_weights(p, &square, &mut short),
        Err(PolygonError::WeightsLength {
            vertices: 4,
            weights: 3
        })
    );
    assert_eq!(
        mean_value_weights(p, &square, &mut [0.0; 5]),
        Err(PolygonError::WeightsLength {
            vertices: 4,
            weights: 5
        })
    );
    // A flat vertex: mean value accepts it, Wachspress does not.
    let flat = [
        Vec2::ZERO,
        Vec2::X,
        Vec2::new(2.0, 0.0),
        Vec2::new(2.0, 1.0),
        Vec2::Y,
    ];
    let mut w = [0.0; 5];
    assert_eq!(
        wachspress_weights(p, &flat, &mut w),
        Err(PolygonError::NotConvex { vertex: 1 })
    );
    assert_eq!(
        mean_value_weights(p, &flat, &mut w),
        Ok(PolygonLocation::Inside)
    );
    assert!(w[1] > 0.0);
}

/// Polygons beyond the stack buffer (32 vertices) take the recomputing path: same properties,
/// and the same answer as the cached path would give (checked through rotation invariance and
/// the exact reference).
#[test]
fn large_polygons_take_the_second_pass() {
    let poly = barytex_interp::hard_cases::regular_polygon(40);
    for p in [
        Vec2::new(0.1, 0.2),
        Vec2::new(0.99, 0.0),
        Vec2::new(2.0, 1.0),
    ] {
        check_polygon_all(p, &poly).unwrap();
    }
}

/// `interpolate_polygon` rejects mismatched lengths and empty input.
#[test]
fn interpolate_polygon_lengths() {
    assert_eq!(
        interpolate_polygon::<f32>(&[1.0], &[]),
        Err(PolygonError::WeightsLength {
            vertices: 0,
            weights: 1
        })
    );
    assert_eq!(
        interpolate_polygon::<f32>(&[], &[]),
        Err(PolygonError::TooFewVertices { count: 0 })
    );
    assert_eq!(
        interpolate_polygon(&[0.25, 0.75], &[Vec2::ZERO, Vec2::splat(4.0)]),
        Ok(Vec2::splat(3.0))
    );
}

/// Found by `total_on_any_bits`: a point so far outside a huge sliver that the normalising sum
/// cancels completely (κ = 2.1e22). The computed weight has the wrong sign; the first-order bound
/// `2⁻²⁶(1 + κ)|λ*|` was exceeded by a factor 1 + 3e-7, which is why the documented bound is now
/// `d/(1 − d)` and promises nothing once `d ≥ ½`. The remaining invariants (finite, partition
/// of unity, rotation) must still hold.
#[test]
fn wachspress_complete_cancellation_far_outside() {
    let p = Vec2::new(-2.474_880_9e27, -6.412_152_6e22);
    let poly = [
        Vec2::new(-234_983.88, 0.0),
        Vec2::new(0.0, 0.0),
        Vec2::new(0.0, 2.012_659e37),
    ];
    assert_eq!(check_polygon_all(p, &poly), Ok(()));
    let mut w = [0.0; 3];
    assert_eq!(
        wachspress_weights(p, &poly, &mut w),
        Ok(PolygonLocation::Outside)
    );
    assert!(w.iter().all(|x| x.is_finite()), "{w:?}");
}
