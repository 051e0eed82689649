//! Bad input the other tests do not feed: the documented *zero* results of the whole SLERP
//! family (not only "finite"), Eberly's `terms` out of range, `lerp_f64` with NaN/∞,
//! `inverse_lerp` overflowing, `perspective_interpolate`'s errors.

use barytex_interp::{
    InterpError, NlerpCorrection, NormalInterpolation, QuatInterpolation, QuatPath,
    interpolate_normal, inverse_lerp, lerp_f64, nlerp_corrected_quat, nlerp_quat,
    perspective_interpolate, slerp, slerp_along, slerp_eberly_quat, try_slerp, try_slerp_along,
};
use glam::{DQuat, DVec2, DVec3, DVec4, Quat, Vec2, Vec3, Vec3A, Vec4};

const BAD32: [f32; 4] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -f32::NAN];
const BAD64: [f64; 4] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -f64::NAN];

/// Asserts every component is exactly zero (either sign).
#[track_caller]
fn is_zero<const N: usize>(what: &str, v: [f32; N]) {
    assert!(v.iter().all(|&c| c == 0.0), "{what}: {v:?}");
}

#[track_caller]
fn is_zero64<const N: usize>(what: &str, v: [f64; N]) {
    assert!(v.iter().all(|&c| c == 0.0), "{what}: {v:?}");
}

/// `slerp(a, b, t)` for the bad cases of one type: zero or non-finite `a` or `b`, non-finite
/// `t`; `good` is a pair of unit vectors. `try_slerp` names the first bad input.
macro_rules! check_vector_slerp {
    ($v:ty, $bad:expr, $zero:ident, $a:expr, $b:expr) => {{
        let (a, b): ($v, $v) = ($a, $b);
        let non_finite = |what| InterpError::NonFinite { what };
        let zero_length = |what| InterpError::ZeroLength { what };
        let mut cases: Vec<($v, $v, _, InterpError)> = vec![
            (<$v>::ZERO, b, 0.5, zero_length("a")),
            (a, <$v>::ZERO, 0.5, zero_length("b")),
            (<$v>::ZERO, <$v>::ZERO, 0.5, zero_length("a")),
        ];
        for bad in $bad {
            cases.push((<$v>::splat(bad), b, 0.5, non_finite("a")));
            cases.push((a, <$v>::splat(bad), 0.5, non_finite("b")));
            cases.push((<$v>::ZERO, <$v>::splat(bad), 0.5, zero_length("a")));
            let mut one = a;
            one[0] = bad;
            cases.push((one, b, 0.25, non_finite("a")));
            cases.push((a, b, bad, non_finite("t")));
            cases.push((<$v>::ZERO, b, bad, non_finite("t")));
            // Even at the ends, where a good input is returned bit for bit.
            cases.push((<$v>::splat(bad), b, 0.0, non_finite("a")));
            cases.push((a, <$v>::splat(bad), 1.0, non_finite("b")));
        }
        for (x, y, t, error) in cases {
            let what = format!("slerp::<{}>({x}, {y}, {t})", stringify!($v));
            $zero(&what, slerp(x, y, t).to_array());
            assert_eq!(try_slerp(x, y, t), Err(error), "{what}");
        }
        // The good pair is answered.
        assert_eq!(try_slerp(a, b, 0.5), Ok(slerp(a, b, 0.5)), stringify!($v));
    }};
}

#[test]
fn every_vector_slerp_gives_zero_for_zero_or_non_finite_input() {
    check_vector_slerp!(Vec2, BAD32, is_zero, Vec2::X, Vec2::Y);
    check_vector_slerp!(Vec3, BAD32, is_zero, Vec3::X, Vec3::Z);
    check_vector_slerp!(Vec3A, BAD32, is_zero, Vec3A::X, Vec3A::Y);
    check_vector_slerp!(Vec4, BAD32, is_zero, Vec4::X, Vec4::W);
    check_vector_slerp!(DVec2, BAD64, is_zero64, DVec2::X, DVec2::Y);
    check_vector_slerp!(DVec3, BAD64, is_zero64, DVec3::Y, DVec3::Z);
    check_vector_slerp!(DVec4, BAD64, is_zero64, DVec4::Z, DVec4::W);
}

#[test]
fn quaternion_slerps_give_zero_for_zero_or_non_finite_input() {
    let (a, b) = (Quat::from_rotation_z(0.3), Quat::from_rotation_y(1.2));
    let zero = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    for path in [QuatPath::Shortest, QuatPath::AsGiven] {
        let mut cases = vec![(zero, b, 0.5), (a, zero, 0.5)];
        for bad in BAD32 {
            let q = Quat::from_xyzw(bad, 0.0, 0.0, 1.0);
            cases.extend([
                (q, b, 0.5),
                (a, q, 0.5),
                (a, b, bad),
                (q, b, 0.0),
                (a, q, 1.0),
            ]);
        }
        for (x, y, t) in cases {
            let what = format!("slerp_along({x}, {y}, {t}, {path:?})");
            is_zero(&what, slerp_along(x, y, t, path).to_array());
            assert!(try_slerp_along(x, y, t, path).is_err(), "{what}");
            if path == QuatPath::Shortest {
                is_zero(&what, slerp(x, y, t).to_array());
                assert!(try_slerp(x, y, t).is_err(), "{what}");
            }
        }
        let (a, b) = (a.as_dquat(), b.as_dquat());
        let zero = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
        let mut cases = vec![(zero, b, 0.5), (a, zero, 0.5)];
        for bad in BAD64 {
            let q = DQuat::from_xyzw(0.0, bad, 0.0, 1.0);
            cases.extend([(q, b, 0.5), (a, q, 0.5), (a, b, bad)]);
        }
        for (x, y, t) in cases {
            let what = format!("slerp_along({x}, {y}, {t}, {path:?})");
            is_zero64(&what, slerp_along(x, y, t, path).to_array());
            assert!(try_slerp_along(x, y, t, path).is_err(), "{what}");
            if path == QuatPath::Shortest {
                is_zero64(&what, slerp(x, y, t).to_array());
                assert!(try_slerp(x, y, t).is_err(), "{what}");
            }
        }
    }
}

/// The approximations: "a non-finite input gives the zero quaternion", in `a`, `b` or `t`.
#[test]
fn quaternion_approximations_give_zero_for_non_finite_input() {
    let (a, b) = (Quat::from_rotation_x(0.4), Quat::from_rotation_z(-0.9));
    let mut cases = Vec::new();
    for bad in BAD32 {
        for k in 0..4 {
            let mut v = Vec4::from(a);
            v[k] = bad;
            let q = Quat::from_vec4(v);
            cases.extend([(q, b, 0.5), (a, q, 0.5), (q, b, 0.0), (a, q, 1.0)]);
        }
        cases.push((a, b, bad));
    }
    let mut methods: Vec<QuatInterpolation> = QuatInterpolation::ALL.to_vec();
    methods.extend([
        QuatInterpolation::Eberly { terms: 0 },
        QuatInterpolation::Eberly { terms: 1 },
        QuatInterpolation::Eberly { terms: 255 },
    ]);
    for (x, y, t) in cases {
        let what = format!("({x}, {y}, {t})");
        is_zero(&format!("nlerp {what}"), nlerp_quat(x, y, t).to_array());
        for correction in [NlerpCorrection::Fast, NlerpCorrection::Precise] {
            is_zero(
                &format!("nlerp_corrected {correction:?} {what}"),
                nlerp_corrected_quat(x, y, t, correction).to_array(),
            );
        }
        is_zero(
            &format!("eberly 1 {what}"),
            slerp_eberly_quat::<1>(x, y, t).to_array(),
        );
        is_zero(
            &format!("eberly 8 {what}"),
            slerp_eberly_quat::<8>(x, y, t).to_array(),
        );
        is_zero(
            &format!("eberly 16 {what}"),
            slerp_eberly_quat::<16>(x, y, t).to_array(),
        );
        for m in &methods {
            is_zero(&format!("{m:?} {what}"), m.interpolate(x, y, t).to_array());
        }
    }
}

/// `QuatInterpolation::Eberly { terms }` outside 1…16 is clamped: 0 acts as 1, 17…255 as 16.
#[test]
fn eberly_terms_outside_1_through_16_are_clamped() {
    let (a, b) = (Quat::from_rotation_x(0.4), Quat::from_rotation_z(-0.9));
    let e = |terms| QuatInterpolation::Eberly { terms };
    for t in [0.0, 0.1, 0.5, 0.77, 1.0] {
        assert_eq!(
            e(0).interpolate(a, b, t),
            slerp_eberly_quat::<1>(a, b, t),
            "{t}"
        );
        for terms in [17, 100, 255] {
            assert_eq!(
                e(terms).interpolate(a, b, t),
                slerp_eberly_quat::<16>(a, b, t),
                "{terms} {t}"
            );
        }
    }
    assert_eq!(e(0).angle_bound(), e(1).angle_bound());
    assert_eq!(e(0).length_bound(), e(1).length_bound());
    assert_eq!(e(255).angle_bound(), e(16).angle_bound());
    assert_eq!(e(255).length_bound(), e(16).length_bound());
    // One factor is much worse than sixteen: the clamp is not a no-op.
    assert!(e(0).angle_bound() > 100.0 * e(255).angle_bound());
}

#[test]
fn interpolate_normal_gives_zero_for_zero_or_non_finite_normals() {
    for method in [NormalInterpolation::Renormalize, NormalInterpolation::Slerp] {
        let mut cases = vec![(Vec3::ZERO, Vec3::ZERO, 0.5)];
        for bad in BAD32 {
            let n = Vec3::new(bad, 0.0, 1.0);
            cases.extend([
                (n, Vec3::Y, 0.5),
                (Vec3::Y, n, 0.5),
                (Vec3::splat(bad), Vec3::splat(bad), 0.3),
            ]);
            cases.push((Vec3::X, Vec3::Y, bad));
        }
        for (n0, n1, t) in cases {
            is_zero(
                &format!("{method:?}({n0}, {n1}, {t})"),
                interpolate_normal(n0, n1, t, method).to_array(),
            );
        }
    }
    // Opposite normals halfway: Renormalize → zero; Slerp → slerp's perpendicular.
    let r = interpolate_normal(Vec3::Z, -Vec3::Z, 0.5, NormalInterpolation::Renormalize);
    assert_eq!(r, Vec3::ZERO);
    let s = interpolate_normal(Vec3::Z, -Vec3::Z, 0.5, NormalInterpolation::Slerp);
    assert_eq!(s, slerp(Vec3::Z, -Vec3::Z, 0.5));
    assert!(
        (s.length() - 1.0).abs() < 1e-6 && s.dot(Vec3::Z).abs() < 1e-6,
        "{s}"
    );
}

#[test]
fn lerp_f64_special_values() {
    for bad in [f64::NAN, -f64::NAN] {
        assert!(lerp_f64(bad, 1.0, 0.5).is_nan());
        assert!(lerp_f64(0.0, bad, 0.5).is_nan());
        assert!(lerp_f64(0.0, 1.0, bad).is_nan());
        assert!(lerp_f64(bad, 1.0, 0.0).is_nan());
        // t == 1 returns b as given, even when a is NaN.
        assert_eq!(lerp_f64(bad, 2.5, 1.0), 2.5);
    }
    // An infinite endpoint: an infinity or NaN (documented), never a finite value.
    let specials = [
        0.0,
        -0.0,
        1.0,
        -2.5,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    let ts = [0.0, 0.25, 0.5, 1.0, 1.5, -1.0, f64::INFINITY, f64::NAN];
    for a in specials {
        for b in specials {
            for t in ts {
                let r = lerp_f64(a, b, t);
                if (a.is_infinite() || b.is_infinite()) && !(t == 1.0 && b.is_finite()) {
                    assert!(!r.is_finite(), "lerp_f64({a}, {b}, {t}) = {r}");
                }
                // The same macro as `lerp`: the f32 function agrees on these values.
                #[allow(clippy::cast_possible_truncation)]
                let r32 = barytex_interp::lerp(a as f32, b as f32, t as f32);
                assert!(
                    (r.is_nan() && r32.is_nan()) || r == f64::from(r32),
                    "lerp_f64({a}, {b}, {t}) = {r}, lerp = {r32}"
                );
            }
        }
    }
    assert_eq!(lerp_f64(0.0, f64::INFINITY, 0.5), f64::INFINITY);
    assert_eq!(lerp_f64(f64::NEG_INFINITY, 0.0, 0.5), f64::NEG_INFINITY);
    // Opposite infinities strictly between the ends: NaN (documented); at the ends too, since
    // the opposite-sign branch computes `t·b + (1 − t)·a` and `0·∞` is NaN.
    assert!(lerp_f64(f64::NEG_INFINITY, f64::INFINITY, 0.5).is_nan());
    assert!(lerp_f64(f64::NEG_INFINITY, f64::INFINITY, 1.0).is_nan());
    assert!(lerp_f64(f64::NEG_INFINITY, f64::INFINITY, 0.0).is_nan());
    // Finite endpoints at the top of the range do not overflow.
    assert_eq!(lerp_f64(-f64::MAX, f64::MAX, 0.5), 0.0);
    assert_eq!(lerp_f64(f64::MAX, f64::MAX, 0.3), f64::MAX);
}

#[test]
fn inverse_lerp_overflows_to_signed_infinity() {
    assert_eq!(inverse_lerp(0.0, 1e-30, 1e30), Ok(f32::INFINITY));
    assert_eq!(inverse_lerp(0.0, 1e-30, -1e30), Ok(f32::NEG_INFINITY));
    assert_eq!(inverse_lerp(0.0, -1e-30, 1e30), Ok(f32::NEG_INFINITY));
    // Subnormal spans still answer.
    assert_eq!(inverse_lerp(0.0, 1e-45, 1e-45), Ok(1.0));
    // x − a beyond f32 on its own: f32::MAX − (−f32::MAX).
    let r = inverse_lerp(-f32::MAX, 0.0, f32::MAX).expect("finite inputs, a ≠ b");
    assert!(r == 2.0 || r == f32::INFINITY, "{r}");
}

#[test]
fn perspective_interpolate_fails_exactly_when_the_weights_do() {
    let values = [0.0_f32, 10.0, 20.0];
    let screen = [0.2, 0.3, 0.5];
    assert!(perspective_interpolate(values, screen, [1.0, 2.0, 4.0]).is_ok());
    for (screen, w) in [
        (screen, [0.0, 1.0, 1.0]),
        (screen, [-1.0, 1.0, 1.0]),
        (screen, [f32::NAN, 1.0, 1.0]),
        (screen, [f32::INFINITY, 1.0, 1.0]),
        ([f32::NAN, 0.5, 0.5], [1.0; 3]),
        ([0.0; 3], [1.0; 3]),
    ] {
        let error = barytex_interp::perspective_correct_weights(screen, w)
            .expect_err("bad input is rejected");
        assert_eq!(
            perspective_interpolate(values, screen, w),
            Err(error),
            "{screen:?} {w:?}"
        );
    }
}
