//! Hard cases for generalized barycentric coordinates over polygons.

use alloc::vec::Vec;

use glam::Vec2;

use crate::PolygonLocation;

/// A named convex polygon and query point.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonCase {
    /// What makes it hard.
    pub name: &'static str,
    /// The case's parameter (scale, offset, distance, …), 0 when it has none.
    pub parameter: f32,
    /// The vertices, counter-clockwise unless the name says otherwise.
    pub polygon: Vec<Vec2>,
    /// The query point.
    pub point: Vec2,
    /// The location when the case pins it down by construction.
    pub expected: Option<PolygonLocation>,
    /// Whether Wachspress accepts the polygon (it needs strict convexity; mean value does not).
    pub strictly_convex: bool,
}

fn v(x: f32, y: f32) -> Vec2 {
    Vec2::new(x, y)
}

/// The regular `n`-gon of circumradius 1 around the origin, counter-clockwise from angle 0.
#[must_use]
pub fn regular_polygon(n: usize) -> Vec<Vec2> {
    (0..n)
        .map(|i| {
            let angle = core::f64::consts::TAU * i as f64 / n as f64;
            let (s, c) = (libm_free_sin(angle), libm_free_cos(angle));
            Vec2::new(c as f32, s as f32)
        })
        .collect()
}

// `core` has no sin/cos; a short Taylor series after reduction to [−π/4, π/4] is exact enough
// for test geometry (the cases never depend on the last bit of a vertex).
fn libm_free_sin(x: f64) -> f64 {
    let (quadrant, r) = reduce(x);
    match quadrant {
        0 => sin_series(r),
        1 => cos_series(r),
        2 => -sin_series(r),
        _ => -cos_series(r),
    }
}

fn libm_free_cos(x: f64) -> f64 {
    libm_free_sin(x + core::f64::consts::FRAC_PI_2)
}

fn reduce(x: f64) -> (u32, f64) {
    let q = (x / core::f64::consts::FRAC_PI_2 + 0.5) as i64;
    let r = x - q as f64 * core::f64::consts::FRAC_PI_2;
    ((q.rem_euclid(4)) as u32, r)
}

fn sin_series(x: f64) -> f64 {
    let x2 = x * x;
    let mut term = x;
    let mut sum = x;
    for k in 1..12 {
        term *= -x2 / ((2 * k) as f64 * (2 * k + 1) as f64);
        sum += term;
    }
    sum
}

fn cos_series(x: f64) -> f64 {
    let x2 = x * x;
    let mut term = 1.0;
    let mut sum = 1.0;
    for k in 1..12 {
        term *= -x2 / ((2 * k - 1) as f64 * (2 * k) as f64);
        sum += term;
    }
    sum
}

/// The polygon table: the centre of a quad whose split changes the result, regular polygons up to 16 sides, nearly collinear
/// consecutive vertices (1e-6 relative and one ulp), points 1e-7 and one ulp from an edge or a
/// vertex, exactly on edges with inexact parameters and on vertices, scales 1e-20, 1e-30 and
/// 1e30, offsets 1e6 and 1e7, subnormal and huge coordinates, a sliver quad, a clockwise
/// pentagon, a flat (collinear) vertex for mean value, and outside points.
pub fn polygons() -> impl Iterator<Item = PolygonCase> {
    let quad = [v(0.0, 0.0), v(4.0, 0.0), v(5.0, 3.0), v(0.0, 2.0)];
    let case = |name: &'static str,
                parameter: f32,
                polygon: Vec<Vec2>,
                point: Vec2,
                expected: Option<PolygonLocation>| PolygonCase {
        name,
        parameter,
        polygon,
        point,
        expected,
        strictly_convex: true,
    };
    let inside = Some(PolygonLocation::Inside);
    let mut cases = Vec::new();
    cases.push(case(
        "split-dependent quad centre",
        0.0,
        quad.to_vec(),
        v(2.25, 1.25),
        inside,
    ));
    for n in [5, 6, 8, 16] {
        cases.push(case(
            "regular polygon, near centre",
            n as f32,
            regular_polygon(n),
            v(0.1, -0.05),
            inside,
        ));
    }
    for k in [1e-6f32, 1e-7] {
        // Vertex 1 pushed out of the line through its neighbours by a relative k.
        cases.push(case(
            "nearly collinear consecutive vertices",
            k,
            [
                v(0.0, 0.0),
                v(1.0, -k),
                v(2.0, 0.0),
                v(2.0, 1.0),
                v(0.0, 1.0),
            ]
            .to_vec(),
            v(1.0, 0.5),
            inside,
        ));
    }
    let mid_up = f32::from_bits(0.5f32.to_bits() - 1);
    cases.push(case(
        "nearly collinear, one ulp",
        0.0,
        [
            v(0.0, 0.5),
            v(0.5, mid_up),
            v(1.0, 0.5),
            v(1.0, 1.0),
            v(0.0, 1.0),
        ]
        .to_vec(),
        v(0.5, 0.75),
        inside,
    ));
    for d in [1e-7f32, 1e-20] {
        cases.push(case(
            "point near an edge",
            d,
            quad.to_vec(),
            v(2.0, d),
            inside,
        ));
        cases.push(case(
            "point near a vertex",
            d,
            quad.to_vec(),
            v(4.0 - d, d),
            inside,
        ));
    }
    cases.push(case(
        "one ulp inside an edge",
        0.0,
        quad.to_vec(),
        v(2.0, f32::from_bits(1)),
        inside,
    ));
    cases.push(case(
        "one ulp outside an edge",
        0.0,
        quad.to_vec(),
        v(2.0, -f32::from_bits(1)),
        Some(PolygonLocation::Outside),
    ));
    cases.push(case(
        "on edge, inexact parameter",
        0.0,
        [v(0.1, 0.1), v(0.7, 0.1), v(0.8, 0.6), v(0.3, 0.9)].to_vec(),
        v(0.3, 0.1),
        Some(PolygonLocation::OnEdge(0)),
    ));
    cases.push(case(
        "on vertex",
        0.0,
        quad.to_vec(),
        v(5.0, 3.0),
        Some(PolygonLocation::OnVertex(2)),
    ));
    for s in [1e-20f32, 1e-30, 1e30] {
        cases.push(case(
            "scaled",
            s,
            quad.iter().map(|&c| c * s).collect(),
            v(2.25, 1.25) * s,
            inside,
        ));
    }
    for o in [1e6f32, 1e7] {
        cases.push(case(
            "offset",
            o,
            quad.iter().map(|&c| c * 64.0 + Vec2::splat(o)).collect(),
            v(2.25, 1.25) * 64.0 + Vec2::splat(o),
            inside,
        ));
    }
    cases.push(case(
        "subnormal size",
        1e-40,
        quad.iter().map(|&c| c * 1e-40).collect(),
        v(2e-40, 1e-40),
        inside,
    ));
    cases.push(case(
        "huge",
        1e38,
        [
            v(-3e38, -3e38),
            v(3e38, -3e38),
            v(3e38, 3e38),
            v(-3e38, 3e38),
        ]
        .to_vec(),
        v(1e37, -2e38),
        inside,
    ));
    cases.push(case(
        "sliver quad",
        1e-6,
        [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1e-6), v(0.0, 2e-6)].to_vec(),
        v(0.5, 1e-6),
        inside,
    ));
    cases.push(case(
        "clockwise pentagon",
        0.0,
        regular_polygon(5).into_iter().rev().collect(),
        v(-0.2, 0.3),
        inside,
    ));
    cases.push(case(
        "outside, beyond a vertex",
        0.0,
        quad.to_vec(),
        v(6.0, 4.0),
        Some(PolygonLocation::Outside),
    ));
    cases.push(case(
        "outside, on an edge's line",
        0.0,
        quad.to_vec(),
        v(-3.0, 0.0),
        Some(PolygonLocation::Outside),
    ));
    cases.push(case(
        "outside, far away",
        1e6,
        regular_polygon(6),
        v(1e6, 3e5),
        Some(PolygonLocation::Outside),
    ));
    cases.push(PolygonCase {
        name: "flat vertex (mean value only)",
        parameter: 0.0,
        polygon: [
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(2.0, 0.0),
            v(2.0, 1.0),
            v(0.0, 1.0),
        ]
        .to_vec(),
        point: v(0.5, 0.0),
        expected: Some(PolygonLocation::OnEdge(0)),
        strictly_convex: false,
    });
    cases.push(PolygonCase {
        name: "flat vertex, inside (mean value only)",
        parameter: 0.0,
        polygon: [
            v(0.0, 0.0),
            v(1.0, 0.0),
            v(2.0, 0.0),
            v(2.0, 1.0),
            v(0.0, 1.0),
        ]
        .to_vec(),
        point: v(1.0, 1e-7),
        expected: inside,
        strictly_convex: false,
    });
    cases.into_iter()
}
