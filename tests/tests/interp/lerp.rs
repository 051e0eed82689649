//! `lerp`, `lerp_f64`, `inverse_lerp` and the segment projection: the four properties at once,
//! accuracy bounds against exact rationals.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::{
    InterpError, inverse_lerp, lerp, lerp_f64, segment_parameter_2d, segment_parameter_3d,
};
use barytex_testkit::exact::{Q, abs_diff, q, qf};
use barytex_testkit::strategies::{bounded_f32, finite_bits_f32, vec2_in, vec3_in};
use barytex_testkit::ulp::ulps_between_f32;
use glam::{Vec2, Vec3};
use proptest::prelude::*;

fn exact_lerp(a: f64, b: f64, t: f64) -> Q {
    let (a, b, t) = (q(a).unwrap(), q(b).unwrap(), q(t).unwrap());
    &a + &t * (&b - &a)
}

proptest! {
    #[test]
    fn exact_endpoints(a in finite_bits_f32(), b in finite_bits_f32()) {
        prop_assert_eq!(lerp(a, b, 0.0).to_bits(), a.to_bits());
        prop_assert_eq!(lerp(a, b, 1.0).to_bits(), b.to_bits());
    }

    #[test]
    fn consistent(a in finite_bits_f32(), t in bounded_f32(-1e6, 1e6)) {
        prop_assert_eq!(lerp(a, a, t), a);
        prop_assert_eq!(lerp_f64(f64::from(a), f64::from(a), f64::from(t)), f64::from(a));
    }

    #[test]
    fn monotonic(a in -1e30f32..1e30, b in -1e30f32..1e30, t1 in -2.0f32..3.0, t2 in -2.0f32..3.0) {
        let (lo, hi) = if t1 <= t2 { (t1, t2) } else { (t2, t1) };
        let (x, y) = (lerp(a, b, lo), lerp(a, b, hi));
        if b >= a { prop_assert!(x <= y, "{x} > {y}"); } else { prop_assert!(x >= y, "{x} < {y}"); }
    }

    #[test]
    fn bounded(a in finite_bits_f32(), b in finite_bits_f32(), t in 0.0f32..=1.0) {
        let x = lerp(a, b, t);
        if x.is_finite() {
            prop_assert!(x >= a.min(b) && x <= a.max(b), "lerp({a}, {b}, {t}) = {x}");
        }
    }

    /// The documented `# Accuracy` of `lerp`: ≤ 2·ε·max(|a|, |b|) for t in [0, 1].
    #[test]
    fn lerp_accuracy_bound(a in -1e30f32..1e30, b in -1e30f32..1e30, t in 0.0f32..=1.0) {
        let x = lerp(a, b, t);
        let err = abs_diff(&qf(x), &exact_lerp(a.into(), b.into(), t.into()));
        let bound = 2.0 * f64::from(f32::EPSILON) * f64::from(a.abs().max(b.abs()));
        prop_assert!(err <= bound, "lerp({a}, {b}, {t}) = {x}, error {err:e} > {bound:e}");
    }

    /// The documented `# Accuracy` of `lerp_f64`: ≤ 2·ε·max(|a|, |b|) for t in [0, 1].
    #[test]
    fn lerp_f64_accuracy_bound(a in -1e300f64..1e300, b in -1e300f64..1e300, t in 0.0f64..=1.0) {
        let x = lerp_f64(a, b, t);
        let err = abs_diff(&q(x).unwrap(), &exact_lerp(a, b, t));
        let bound = 2.0 * f64::EPSILON * a.abs().max(b.abs());
        prop_assert!(err <= bound, "lerp_f64({a}, {b}, {t}) = {x}, error {err:e} > {bound:e}");
    }

    /// `inverse_lerp` is within one ulp of the exact quotient.
    #[test]
    fn inverse_lerp_is_within_one_ulp(a in -1e6f32..1e6, b in -1e6f32..1e6, x in -1e6f32..1e6) {
        prop_assume!(a != b);
        let got = inverse_lerp(a, b, x).unwrap();
        let exact = (qf(x) - qf(a)) / (qf(b) - qf(a));
        let nearest = barytex_testkit::exact::to_f64(&exact) as f32;
        prop_assert!(ulps_between_f32(got, nearest) <= 1, "{got} vs {nearest}");
    }

    /// The projection formula (Buss 2003, ch. IV) inverts `lerp` on the segment, within 1 ulp of exact.
    #[test]
    fn segment_parameter_matches_exact(x1 in vec2_in(-100.0, 100.0), x2 in vec2_in(-100.0, 100.0), u in vec2_in(-300.0, 300.0)) {
        prop_assume!(x1 != x2);
        let got = segment_parameter_2d(u, x1, x2).unwrap();
        let d = [qf(x2.x) - qf(x1.x), qf(x2.y) - qf(x1.y)];
        let exact = ((qf(u.x) - qf(x1.x)) * &d[0] + (qf(u.y) - qf(x1.y)) * &d[1])
            / (&d[0] * &d[0] + &d[1] * &d[1]);
        let nearest = barytex_testkit::exact::to_f64(&exact) as f32;
        prop_assert!(ulps_between_f32(got, nearest) <= 1, "{got} vs {nearest}");
    }

    #[test]
    fn segment_parameter_round_trips_lerp(x1 in vec3_in(-100.0, 100.0), x2 in vec3_in(-100.0, 100.0), t in -1.0f32..2.0) {
        prop_assume!((x2 - x1).length() > 1e-2);
        let u = x1.as_dvec3() + (x2.as_dvec3() - x1.as_dvec3()) * f64::from(t);
        let got = segment_parameter_3d(u.as_vec3(), x1, x2).unwrap();
        let scale = f64::from(x1.abs().max(x2.abs()).max_element()) / (x2 - x1).as_dvec3().length();
        prop_assert!((f64::from(got) - f64::from(t)).abs() <= 1e-6 * (1.0 + scale), "{got} vs {t}");
    }
}

#[test]
fn extrapolates_along_the_line() {
    assert_eq!(lerp(1.0, 3.0, 1.5), 4.0);
    assert_eq!(lerp(1.0, 3.0, -0.5), 0.0);
    assert_eq!(lerp(-2.0, 2.0, 2.0), 6.0);
}

#[test]
fn special_values_never_panic() {
    for v in barytex_interp::hard_cases::NON_FINITE {
        let x = lerp(v, 1.0, 0.5);
        assert!(
            x.is_nan() || (v.is_infinite() && x.is_infinite()),
            "lerp({v}, 1, 0.5) = {x}"
        );
        assert!(lerp(1.0, v, 0.5).is_nan() || v.is_infinite());
        assert!(lerp(1.0, 2.0, v).is_nan() || v.is_infinite());
        assert_eq!(
            inverse_lerp(v, 1.0, 0.5),
            Err(InterpError::NonFinite { what: "a" })
        );
        assert_eq!(
            inverse_lerp(0.0, v, 0.5),
            Err(InterpError::NonFinite { what: "b" })
        );
        assert_eq!(
            inverse_lerp(0.0, 1.0, v),
            Err(InterpError::NonFinite { what: "x" })
        );
    }
    assert!(lerp(f32::NEG_INFINITY, f32::INFINITY, 0.5).is_nan());
    assert_eq!(lerp(f32::NAN, 2.0, 1.0), 2.0);
    assert!(lerp(f32::NAN, 2.0, 0.5).is_nan());
    assert!(lerp(f32::NAN, 2.0, 1.5).is_nan());
    assert!(lerp(1.0, f32::NAN, 0.5).is_nan());
    assert_eq!(
        inverse_lerp(2.0, 2.0, 2.0),
        Err(InterpError::DegenerateSegment)
    );
    assert_eq!(
        segment_parameter_2d(Vec2::ONE, Vec2::ZERO, Vec2::ZERO),
        Err(InterpError::DegenerateSegment)
    );
    assert!(matches!(
        segment_parameter_3d(Vec3::NAN, Vec3::ZERO, Vec3::ONE),
        Err(InterpError::NonFinite { .. })
    ));
}

#[test]
fn projection_example() {
    // u − x1 = α(x2 − x1) on the line, and the foot of the perpendicular off it.
    let x1 = Vec2::new(1.0, 1.0);
    let x2 = Vec2::new(5.0, 3.0);
    assert_eq!(segment_parameter_2d(x1.lerp(x2, 0.75), x1, x2), Ok(0.75));
    assert_eq!(segment_parameter_2d(Vec2::new(2.0, 4.0), x1, x2), Ok(0.5));
}

/// Subnormal and smallest-normal f32 values of either sign (exponent field 0, 1 or 2), where the
/// products of `lerp` round to the fixed spacing `2⁻¹⁴⁹` rather than relatively.
fn tiny_f32() -> impl Strategy<Value = f32> + Clone {
    (0u32..(3 << 23), any::<bool>())
        .prop_map(|(bits, negative)| f32::from_bits(bits | (u32::from(negative) << 31)))
}

/// As [`tiny_f32`] for f64 (exponent field 0, 1 or 2).
fn tiny_f64() -> impl Strategy<Value = f64> + Clone {
    (0u64..(3 << 52), any::<bool>())
        .prop_map(|(bits, negative)| f64::from_bits(bits | (u64::from(negative) << 63)))
}

/// Issue 20, item 3: the relative bound alone cannot hold where the result is subnormal (its
/// spacing is `2⁻¹⁴⁹`, not relative); `lerp(1e-45, 3e-45, 0.5)` is 7e-46 off.
#[test]
fn underflow_needs_the_absolute_term() {
    let (a, b) = (1e-45f32, 3e-45f32);
    let x = lerp(a, b, 0.5);
    let err = abs_diff(&qf(x), &exact_lerp(a.into(), b.into(), 0.5));
    let relative = 2.0 * f64::from(f32::EPSILON) * f64::from(a.abs().max(b.abs()));
    assert!(
        err > relative,
        "the example shows the relative term is not enough"
    );
    assert!(err <= relative + 2f64.powi(-149), "{err:e}");
}

proptest! {
    /// `lerp`'s bound with its underflow term, `2·ε·max(|a|, |b|) + 2⁻¹⁴⁹`, on subnormal and
    /// smallest-normal endpoints (also mixed with ordinary ones).
    #[test]
    fn lerp_accuracy_bound_with_subnormals(a in tiny_f32(), b in prop_oneof![tiny_f32(), -1e-30f32..1e-30], t in 0.0f32..=1.0) {
        for (a, b) in [(a, b), (b, a)] {
            let x = lerp(a, b, t);
            let err = abs_diff(&qf(x), &exact_lerp(a.into(), b.into(), t.into()));
            let bound = 2.0 * f64::from(f32::EPSILON) * f64::from(a.abs().max(b.abs())) + 2f64.powi(-149);
            prop_assert!(err <= bound, "lerp({a:e}, {b:e}, {t}) = {x:e}, error {err:e} > {bound:e}");
        }
    }

    /// `lerp_f64`'s bound with its underflow term, `2·ε·max(|a|, |b|) + 2⁻¹⁰⁷⁴`.
    #[test]
    fn lerp_f64_accuracy_bound_with_subnormals(a in tiny_f64(), b in prop_oneof![tiny_f64(), -1e-300f64..1e-300], t in 0.0f64..=1.0) {
        for (a, b) in [(a, b), (b, a)] {
            let x = lerp_f64(a, b, t);
            let err = abs_diff(&q(x).unwrap(), &exact_lerp(a, b, t));
            let bound = 2.0 * f64::EPSILON * a.abs().max(b.abs()) + 2f64.powi(-1074);
            prop_assert!(err <= bound, "lerp_f64({a:e}, {b:e}, {t}) = {x:e}, error {err:e} > {bound:e}");
        }
    }

    /// Issue 20, item 6: `inverse_lerp` is within one ulp of the exact quotient for any finite
    /// f32 inputs (any magnitudes, subnormals included), not only within 2²⁹ of each other: the
    /// f64 differences and quotient err by at most `3·2⁻⁵³` relative before the one rounding to f32.
    #[test]
    fn inverse_lerp_is_within_one_ulp_at_any_magnitude(a in finite_bits_f32(), b in finite_bits_f32(), x in finite_bits_f32()) {
        prop_assume!(a != b);
        let got = inverse_lerp(a, b, x).unwrap();
        let exact = (qf(x) - qf(a)) / (qf(b) - qf(a));
        let nearest = barytex_testkit::exact::to_f64(&exact) as f32;
        if nearest.is_infinite() {
            prop_assert_eq!(got, nearest);
        } else {
            prop_assert!(ulps_between_f32(got, nearest) <= 1, "inverse_lerp({a:e}, {b:e}, {x:e}) = {got:e} vs {nearest:e}");
        }
    }

    /// Issue 20, item 6: `segment_parameter_2d`/`_3d` at any magnitudes, against exact rationals:
    /// within `1 ulp + 2⁻⁴⁷·|u − x1|/|x2 − x1|` (the f64 rounding of the differences, the dot
    /// product and the quotient, at most `11·2⁻⁵³` times the condition `|u − x1|/|x2 − x1|`,
    /// then one rounding to f32), and within one ulp whenever that term is below half an ulp.
    #[test]
    fn segment_parameter_within_its_condition_bound(
        x1 in vec3_in(-1.0, 1.0), d in vec3_in(-1.0, 1.0), u in vec3_in(-1.0, 1.0),
        scales in (-40i32..40, -40i32..40, -40i32..40),
    ) {
        let (x1, d, u) = (x1 * 2f32.powi(scales.0), d * 2f32.powi(scales.1), u * 2f32.powi(scales.2));
        let x2 = x1 + d;
        prop_assume!(x1 != x2 && x2.is_finite());
        for dim in [2usize, 3] {
            let take = |v: Vec3| if dim == 2 { v.truncate().extend(0.0) } else { v };
            let (x1, x2, u) = (take(x1), take(x2), take(u));
            prop_assume!(x1 != x2);
            let got = if dim == 2 {
                segment_parameter_2d(u.truncate(), x1.truncate(), x2.truncate()).unwrap()
            } else {
                segment_parameter_3d(u, x1, x2).unwrap()
            };
            let dd: Vec<Q> = (0..3).map(|i| qf(x2[i]) - qf(x1[i])).collect();
            let uu: Vec<Q> = (0..3).map(|i| qf(u[i]) - qf(x1[i])).collect();
            let num: Q = (0..3).map(|i| &uu[i] * &dd[i]).sum();
            let den: Q = (0..3).map(|i| &dd[i] * &dd[i]).sum();
            let exact = num / den;
            let exact64 = barytex_testkit::exact::to_f64(&exact);
            let condition = (u.as_dvec3() - x1.as_dvec3()).length() / (x2.as_dvec3() - x1.as_dvec3()).length();
            let ulp = barytex_testkit::ulp::ulp_f32(exact64);
            let bound = ulp + 2f64.powi(-47) * condition;
            let err = abs_diff(&qf(got), &exact);
            prop_assert!(err <= bound, "{dim}D: {got:e} vs {exact64:e}, error {err:e} > {bound:e}");
            if 2f64.powi(-47) * condition <= 0.5 * ulp {
                prop_assert!(ulps_between_f32(got, exact64 as f32) <= 1, "{got:e} vs {exact64:e}");
            }
        }
    }
}
