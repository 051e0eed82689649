//! 3D barycentric coordinates: cross-product form in f64 against exact rationals, slivers, and
//! the Cramer form's 1/aspect² degradation measured.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::hard_cases::triangles_3d;
use barytex_interp::methods::{
    PrecomputedTriangle3, barycentric_3d_cramer_f32, barycentric_3d_cross_f32,
};
use barytex_interp::{InterpError, barycentric_3d};
use barytex_testkit::exact::{self, qf};
use barytex_testkit::strategies::vec3_in;
use barytex_testkit::ulp::ulp_f32;
use glam::Vec3;
use proptest::prelude::*;

/// κ for a 3D query: `max(|p|, |a|, |b|, |c|) · max edge / |2·area|`.
fn kappa(p: Vec3, [a, b, c]: [Vec3; 3]) -> f64 {
    let (p, a, b, c) = (p.as_dvec3(), a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
    let m = [p, a, b, c].iter().map(|v| v.length()).fold(0.0, f64::max);
    let e = (b - a).length().max((c - b).length()).max((a - c).length());
    m * e / (b - a).cross(c - a).length()
}

/// The documented bound of `barycentric_3d`: `1 ulp + 2⁻⁴⁶·κ`.
fn check(p: Vec3, tri: [Vec3; 3]) -> Result<(), String> {
    let got = barycentric_3d(p, tri).map_err(|e| e.to_string())?;
    let want = exact::barycentric_3d(p, tri).ok_or("degenerate")?;
    let k = kappa(p, tri);
    for (g, w) in got.weights.iter().zip(&want) {
        let w64 = exact::to_f64(w);
        if g.is_infinite() && *g == w64 as f32 {
            // The exact weight is beyond f32: its infinity is the rounded value.
            continue;
        }
        let err = exact::abs_diff(&qf(*g), w);
        let bound = ulp_f32(w64) + k * 2f64.powi(-46);
        if err > bound {
            return Err(format!(
                "{p:?} in {tri:?}: {g} vs {w64}, error {err:e} > {bound:e}"
            ));
        }
    }
    Ok(())
}

fn well_shaped_3d() -> impl Strategy<Value = [Vec3; 3]> {
    [
        vec3_in(-100.0, 100.0),
        vec3_in(-100.0, 100.0),
        vec3_in(-100.0, 100.0),
    ]
    .prop_filter("well shaped", |[a, b, c]| {
        let n = (*b - *a).cross(*c - *a).length();
        let e = (*b - *a)
            .length_squared()
            .max((*c - *a).length_squared())
            .max((*c - *b).length_squared());
        n >= 0.05 * e
    })
}

proptest! {
    #[test]
    fn barycentric_3d_within_bar(tri in well_shaped_3d(), t in (-0.5f32..1.5, -0.5f32..1.5), lift in -10.0f32..10.0) {
        let [a, b, c] = tri;
        let n = (b - a).cross(c - a).normalize();
        // A point off the plane: its weights are those of its projection.
        let p = a + (b - a) * t.0 + (c - a) * t.1 + n * lift;
        check(p, tri).map_err(TestCaseError::fail)?;
    }

    /// Buss's precomputed form and the f32 cross form agree with the default on
    /// well-shaped triangles (they differ only in how error grows on slivers).
    #[test]
    fn methods_agree_on_well_shaped(tri in well_shaped_3d(), t in (0.0f32..1.0, 0.0f32..1.0)) {
        let [a, b, c] = tri;
        let p = a + (b - a) * t.0 * 0.5 + (c - a) * t.1 * 0.5;
        let want = barycentric_3d(p, tri).unwrap().weights;
        let pre = PrecomputedTriangle3::new(tri).unwrap().weights(p);
        for got in [pre, barycentric_3d_cross_f32(p, tri), barycentric_3d_cramer_f32(p, tri)] {
            for (g, w) in got.iter().zip(want) {
                prop_assert!((g - w).abs() < 1e-3, "{got:?} vs {want:?}");
            }
        }
    }
}

/// The slivers of the hard-case table: the default stays within its bound at aspect 1e-7, and
/// the Cramer dot form is measurably worse — its error grows like 1/aspect².
#[test]
fn slivers_3d_within_bar() {
    let mut cramer_worst_at_1e_4 = 0.0f64;
    for case in triangles_3d() {
        check(case.point, case.triangle)
            .unwrap_or_else(|e| panic!("{} {}: {e}", case.name, case.parameter));
        let want = exact::barycentric_3d(case.point, case.triangle).unwrap();
        let cramer = barycentric_3d_cramer_f32(case.point, case.triangle);
        let err = cramer
            .iter()
            .zip(&want)
            .map(|(g, w)| {
                if g.is_finite() {
                    exact::abs_diff(&qf(*g), w)
                } else {
                    f64::INFINITY
                }
            })
            .fold(0.0, f64::max);
        println!(
            "{} {:e}: Cramer f32 max error {err:e}",
            case.name, case.parameter
        );
        if case.name == "tilted sliver" && case.parameter <= 1e-4 {
            cramer_worst_at_1e_4 = cramer_worst_at_1e_4.max(err);
        }
    }
    assert!(
        cramer_worst_at_1e_4 > 1e-2,
        "Cramer form unexpectedly accurate on slivers: {cramer_worst_at_1e_4}"
    );
}

#[test]
fn degenerate_and_non_finite_3d() {
    let line = [Vec3::ZERO, Vec3::ONE, Vec3::splat(2.0)];
    assert_eq!(
        barycentric_3d(Vec3::X, line),
        Err(InterpError::DegenerateTriangle)
    );
    assert_eq!(
        PrecomputedTriangle3::new(line),
        Err(InterpError::DegenerateTriangle)
    );
    for v in barytex_interp::hard_cases::NON_FINITE {
        let tri = [Vec3::X, Vec3::Y, Vec3::Z];
        assert_eq!(
            barycentric_3d(Vec3::splat(v), tri),
            Err(InterpError::NonFinite { what: "point" })
        );
        assert_eq!(
            barycentric_3d(Vec3::ZERO, [Vec3::X, Vec3::new(0.0, v, 0.0), Vec3::Z]),
            Err(InterpError::NonFinite { what: "triangle" })
        );
        assert!(PrecomputedTriangle3::new([Vec3::splat(v), Vec3::Y, Vec3::Z]).is_err());
    }
}

#[test]
fn vertices_and_centroid_3d() {
    let tri = [
        Vec3::new(1.0, 0.0, 2.0),
        Vec3::new(-1.0, 3.0, 0.5),
        Vec3::new(4.0, 1.0, -1.0),
    ];
    for (i, v) in tri.iter().enumerate() {
        let w = barycentric_3d(*v, tri).unwrap().weights;
        let mut want = [0.0; 3];
        want[i] = 1.0;
        assert_eq!(w, want);
    }
    let c = (tri[0] + tri[1] + tri[2]) / 3.0;
    for w in barycentric_3d(c, tri).unwrap().weights {
        assert!((w - 1.0 / 3.0).abs() < 1e-6);
    }
}

/// Review finding: collinearity is decided exactly, even with a large exponent gap where rounded
/// f64 differences would leave a tiny non-zero normal (and huge weights).
#[test]
fn exactly_collinear_with_exponent_gaps_is_degenerate() {
    let a = Vec3::new(1e-30, 2e-30, 3e-30);
    let d = Vec3::new(1.0, 2.0, 3.0);
    for t in [1e10f32, 3.0, 0.125] {
        let tri = [a, a + d, a + d * t];
        let exact_n = exact::barycentric_3d(Vec3::ZERO, tri);
        let got = barycentric_3d(Vec3::ONE, tri);
        match exact_n {
            None => assert_eq!(got, Err(InterpError::DegenerateTriangle), "{tri:?}"),
            Some(_) => check(Vec3::ONE, tri).unwrap(),
        }
    }
}

/// Points far from a small triangle (up to 2⁶⁰ of its size away, off its plane and in it), at
/// scales from 2⁻⁶⁰ to 2⁴⁰: the bound holds at every distance. The f64 form
/// `((b − p) × (c − p))·n` missed it beyond about 32 edge lengths (its rounding grows with the
/// square of the distance); the fuzz target `interp_3d` found the case below.
#[test]
fn far_points_within_bar() {
    // Fuzz `interp_3d` (`fuzz/regressions/interp_3d/crash-54d6…`): exact weight 6.24e50 (beyond
    // f32, so +∞), once computed as 0.
    let p = Vec3::new(0.25, 0.25, f32::from_bits(0x5555_5554));
    let tri = [
        Vec3::new(f32::from_bits(0xa2f7_a3ed), 0.0, f32::from_bits(3)),
        Vec3::new(
            f32::from_bits(0x3f00),
            f32::from_bits(0x80),
            f32::from_bits(0x00ff_ffff),
        ),
        Vec3::new(f32::from_bits(0xff00), -0.0, f32::from_bits(0x8000_003f)),
    ];
    check(p, tri).unwrap();
    let mut rng = barytex_testkit::seeded::XorShift::new(0xfa7);
    let mut worst_ratio = 0.0f64;
    for i in 0..4000 {
        let scale = 2f32.powi(-60 + (i % 100));
        let far = 2f32.powi(i % 61);
        let a = rng.vec3_in(-1.0, 1.0) * scale;
        let tri = [
            a,
            a + rng.vec3_in(-1.0, 1.0) * scale,
            a + rng.vec3_in(-1.0, 1.0) * scale,
        ];
        if exact::barycentric_3d(Vec3::ZERO, tri).is_none() {
            continue;
        }
        let p = a + rng.vec3_in(-1.0, 1.0) * (scale * far);
        check(p, tri).unwrap_or_else(|e| panic!("case {i}: {e}"));
        let got = barycentric_3d(p, tri).unwrap().weights;
        let want = exact::barycentric_3d(p, tri).unwrap();
        let k = kappa(p, tri);
        for (g, w) in got.iter().zip(&want) {
            if g.is_finite() {
                let excess = exact::abs_diff(&qf(*g), w) - ulp_f32(exact::to_f64(w));
                worst_ratio = worst_ratio.max(excess / (k * 2f64.powi(-46)));
            }
        }
    }
    println!("far points: worst (error − 1 ulp) / (2⁻⁴⁶·κ) = {worst_ratio:.3e}");
}
