//! The SLERP family against an f64 reference: exact SLERP within its stated bounds at every
//! angle (0, π, and 1e-8 from each), exact endpoints, extrapolation, totality; every
//! approximation within its stated bound (and the bound no more than twice what is measured);
//! the uneven spacing of renormalized normals.

use barytex_interp::hard_cases::{quaternion_pairs, vector_pairs};
use barytex_interp::{
    InterpError, NormalInterpolation, QuatInterpolation, QuatPath, SLERP_F32_ANGLE_BOUND,
    SLERP_F32_LENGTH_BOUND, SLERP_F64_ANGLE_BOUND, SLERP_F64_LENGTH_BOUND, interpolate_normal,
    renormalize_spacing_error, slerp, slerp_along, try_slerp, try_slerp_along,
};
use barytex_testkit::seeded::XorShift;
use barytex_testkit::sphere::{self, errors};
use barytex_testkit::strategies::bits_f32;
use glam::{DQuat, DVec3, Quat, Vec2, Vec3, Vec3A, Vec4};
use proptest::prelude::*;

fn f64s<const N: usize>(v: [f32; N]) -> Vec<f64> {
    v.iter().map(|&x| f64::from(x)).collect()
}

/// The largest angle and length errors seen, with the worst case's description.
#[derive(Default, Debug)]
struct Worst {
    angle: f64,
    length: f64,
    at: String,
}

impl Worst {
    fn add(&mut self, (angle, length): (f64, f64), at: impl FnOnce() -> String) {
        if angle > self.angle || length > self.length {
            self.at = at();
        }
        self.angle = self.angle.max(angle);
        self.length = self.length.max(length);
    }
}

/// f32 exact SLERP of a quaternion pair against the f64 reference.
fn quat_errors(a: Quat, b: Quat, t: f32, path: QuatPath) -> (f64, f64) {
    let r = slerp_along(a, b, t, path);
    let b = if path == QuatPath::Shortest && a.dot(b) < 0.0 {
        -b
    } else {
        b
    };
    let perp = Vec4::new(a.y, -a.x, a.w, -a.z);
    let reference = sphere::slerp(
        &f64s(a.to_array()),
        &f64s(b.to_array()),
        f64::from(t),
        &f64s(perp.to_array()),
    )
    .expect("unit inputs");
    errors(&f64s(r.to_array()), &reference)
}

/// f32 exact SLERP of a vector pair against the f64 reference.
fn vec3_errors(a: Vec3, b: Vec3, t: f32) -> (f64, f64) {
    let r = slerp(a, b, t);
    let reference = sphere::slerp(
        &f64s(a.to_array()),
        &f64s(b.to_array()),
        f64::from(t),
        &f64s(a.any_orthonormal_vector().to_array()),
    )
    .expect("unit inputs");
    errors(&f64s(r.to_array()), &reference)
}

const PARAMETERS: [f32; 9] = [0.0, 1e-7, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0 - 6e-8, 1.0];

#[test]
fn exact_slerp_quat_within_bounds() {
    let mut rng = XorShift::new(0x51e7);
    let mut worst = Worst::default();
    for (a, b, t) in sphere::quat_pairs(&mut rng, 20_000, std::f32::consts::PI) {
        for path in [QuatPath::Shortest, QuatPath::AsGiven] {
            for t in PARAMETERS.into_iter().chain([t]) {
                worst.add(quat_errors(a, b, t, path), || {
                    format!("{a:?} {b:?} t={t} {path:?}")
                });
            }
        }
    }
    for case in quaternion_pairs() {
        for path in [QuatPath::Shortest, QuatPath::AsGiven] {
            for t in PARAMETERS {
                worst.add(quat_errors(case.a, case.b, t, path), || {
                    format!("{} t={t} {path:?}", case.name)
                });
            }
        }
    }
    println!("quat f32: {worst:?}");
    assert!(worst.angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{worst:?}");
    assert!(
        worst.length <= f64::from(SLERP_F32_LENGTH_BOUND),
        "{worst:?}"
    );
}

#[test]
fn exact_slerp_vec3_within_bounds_at_every_angle() {
    let mut rng = XorShift::new(0x7ec3);
    let mut worst = Worst::default();
    for (a, b, t) in sphere::vec3_pairs(&mut rng, 20_000, std::f32::consts::PI) {
        for t in PARAMETERS.into_iter().chain([t]) {
            worst.add(vec3_errors(a, b, t), || format!("{a:?} {b:?} t={t}"));
        }
    }
    for case in vector_pairs() {
        for t in PARAMETERS {
            worst.add(vec3_errors(case.a, case.b, t), || {
                format!("{} t={t}", case.name)
            });
        }
    }
    println!("vec3 f32: {worst:?}");
    assert!(worst.angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{worst:?}");
    assert!(
        worst.length <= f64::from(SLERP_F32_LENGTH_BOUND),
        "{worst:?}"
    );
}

#[test]
fn exact_slerp_other_f32_vectors_within_bounds() {
    let mut rng = XorShift::new(0x2d4a);
    let mut worst = Worst::default();
    for (a, b, t) in sphere::vec3_pairs(&mut rng, 5_000, std::f32::consts::PI) {
        // 2D: the pair projected to the plane and renormalized; Vec3A: the same vectors.
        let (a2, b2) = (a.truncate().normalize(), b.truncate().normalize());
        let r2 = slerp(a2, b2, t);
        let reference2 = sphere::slerp(
            &f64s(a2.to_array()),
            &f64s(b2.to_array()),
            f64::from(t),
            &f64s(a2.perp().to_array()),
        )
        .expect("unit");
        worst.add(errors(&f64s(r2.to_array()), &reference2), || {
            format!("vec2 {a2:?} {b2:?} {t}")
        });
        let r3a = slerp(Vec3A::from(a), Vec3A::from(b), t);
        assert_eq!(Vec3::from(r3a), slerp(a, b, t), "Vec3A and Vec3 agree");
        let (a4, b4) = (a.extend(0.0), b.extend(0.0));
        let r4 = slerp(a4, b4, t);
        assert!((r4.truncate() - slerp(a, b, t)).length() <= 2.0 * SLERP_F32_ANGLE_BOUND);
    }
    println!("vec2 f32: {worst:?}");
    assert!(worst.angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{worst:?}");
    assert!(
        worst.length <= f64::from(SLERP_F32_LENGTH_BOUND),
        "{worst:?}"
    );
}

#[test]
fn exact_slerp_f64_within_bounds() {
    // The f64 code against the same construction in f64: the reference is not more precise, so
    // this checks that the two agree to the stated bound (both are a few ulps from the truth;
    // the algorithm is the one the f32 tests validate against an independent higher-precision
    // computation).
    let mut rng = XorShift::new(0xd64);
    let mut worst = Worst::default();
    for (a, b, t) in sphere::vec3_pairs(&mut rng, 5_000, std::f32::consts::PI) {
        let (a, b, t) = (
            a.as_dvec3().normalize(),
            b.as_dvec3().normalize(),
            f64::from(t),
        );
        let r = slerp(a, b, t);
        let reference = sphere::slerp(
            &a.to_array(),
            &b.to_array(),
            t,
            &a.any_orthonormal_vector().to_array(),
        )
        .expect("unit");
        worst.add(errors(&r.to_array(), &reference), || {
            format!("{a:?} {b:?} {t}")
        });
        // Quaternions: the same rotation pair in f64.
        let qa = DQuat::from_axis_angle(a, 0.3);
        let qb = DQuat::from_axis_angle(b, 1.9);
        let q = slerp_along(qa, qb, t, QuatPath::AsGiven);
        let reference =
            sphere::slerp(&qa.to_array(), &qb.to_array(), t, &[1.0, 0.0, 0.0, 0.0]).expect("unit");
        worst.add(errors(&q.to_array(), &reference), || {
            format!("dquat {qa:?} {qb:?} {t}")
        });
    }
    println!("f64: {worst:?}");
    assert!(worst.angle <= SLERP_F64_ANGLE_BOUND, "{worst:?}");
    assert!(worst.length <= SLERP_F64_LENGTH_BOUND, "{worst:?}");
}

#[test]
fn endpoints_are_exact() {
    let mut rng = XorShift::new(0xe9d);
    for (a, b, _) in sphere::quat_pairs(&mut rng, 2_000, std::f32::consts::PI) {
        assert_eq!(slerp_along(a, b, 0.0, QuatPath::AsGiven), a);
        assert_eq!(slerp_along(a, b, 1.0, QuatPath::AsGiven), b);
        let short_b = if a.dot(b) < 0.0 { -b } else { b };
        assert_eq!(slerp_along(a, b, 0.0, QuatPath::Shortest), a);
        assert_eq!(slerp_along(a, b, 1.0, QuatPath::Shortest), short_b);
    }
    for (a, b, _) in sphere::vec3_pairs(&mut rng, 2_000, std::f32::consts::PI) {
        assert_eq!(slerp(a, b, 0.0), a);
        assert_eq!(slerp(a, b, 1.0), b);
        assert_eq!(
            slerp(a, a, 0.37),
            a,
            "equal inputs give the input at every t"
        );
    }
}

#[test]
fn short_path_never_turns_more_than_half_a_turn() {
    let mut rng = XorShift::new(0x5407);
    for (a, b, t) in sphere::quat_pairs(&mut rng, 2_000, std::f32::consts::PI) {
        let q = slerp_along(a, b, t, QuatPath::Shortest);
        // The 4D angle from a grows at most to π/2 (a rotation of at most π).
        let angle = sphere::angle(&f64s(a.to_array()), &f64s(q.to_array())).expect("unit");
        assert!(
            angle <= std::f64::consts::FRAC_PI_2 + 1e-6,
            "{a:?} {b:?} {t}: {angle}"
        );
        // And -b gives the same result: the path does not depend on b's sign.
        assert_eq!(q, slerp_along(a, -b, t, QuatPath::Shortest));
    }
}

#[test]
fn extrapolation_continues_the_great_circle() {
    // glam #356: extrapolating between nearly equal rotations. Ours keeps constant angular speed
    // outside [0, 1] at every angle; the error grows with |t| as the angle's rounding does.
    let mut rng = XorShift::new(0xe7a);
    let mut worst = 0.0f64;
    for (a, b, _) in sphere::vec3_pairs(&mut rng, 2_000, std::f32::consts::PI) {
        for t in [-3.0f32, -1.0, -0.5, 1.5, 2.0, 4.0] {
            let (angle, length) = vec3_errors(a, b, t);
            worst = worst.max(angle / f64::from(t.abs()));
            assert!(
                length <= f64::from(SLERP_F32_LENGTH_BOUND),
                "{a:?} {b:?} {t}"
            );
        }
    }
    for case in quaternion_pairs() {
        for t in [-2.0f32, 3.0] {
            let (angle, _) = quat_errors(case.a, case.b, t, QuatPath::Shortest);
            worst = worst.max(angle / f64::from(t.abs()));
        }
    }
    println!("extrapolation: angle error per unit |t| ≤ {worst:e}");
    assert!(worst <= f64::from(SLERP_F32_ANGLE_BOUND), "{worst}");
}

#[test]
fn exactly_opposite_vectors_take_the_documented_axis() {
    for a in [
        Vec3::X,
        Vec3::Y,
        Vec3::Z,
        Vec3::new(0.267, -0.534, 0.802).normalize(),
    ] {
        let mid = slerp(a, -a, 0.5);
        let axis = a.any_orthonormal_vector();
        assert!(
            (mid - axis).length() <= 2.0 * SLERP_F32_ANGLE_BOUND,
            "{a:?}: {mid:?}"
        );
        assert!((slerp(a, -a, 0.25).length() - 1.0).abs() <= SLERP_F32_LENGTH_BOUND);
        // Deterministic: bit-identical on every call.
        assert_eq!(
            mid.to_array().map(f32::to_bits),
            slerp(a, -a, 0.5).to_array().map(f32::to_bits)
        );
    }
    let mid = slerp(Vec2::new(0.6, 0.8), Vec2::new(-0.6, -0.8), 0.5);
    assert!((mid - Vec2::new(-0.8, 0.6)).length() <= 2.0 * SLERP_F32_ANGLE_BOUND);
    // Quaternions as given, q to −q: the full turn about q's local z axis.
    let q = Quat::from_rotation_x(0.4);
    let half = slerp_along(q, -q, 0.5, QuatPath::AsGiven);
    assert!(half.angle_between(q * Quat::from_rotation_z(std::f32::consts::PI)) < 1e-6);
}

#[test]
fn glam_loses_length_near_antiparallel_where_we_do_not() {
    let mut glam_worst = 0.0f32;
    for case in vector_pairs().filter(|c| c.name.contains("from antiparallel")) {
        for t in PARAMETERS {
            let ours = slerp(case.a, case.b, t);
            assert!(
                (ours.length() - 1.0).abs() <= SLERP_F32_LENGTH_BOUND,
                "{}",
                case.name
            );
            glam_worst = glam_worst.max((case.a.slerp(case.b, t).length() - 1.0).abs());
        }
    }
    // Recorded for the docs: glam 0.34's `Vec3::slerp` within 1e-3 rad of antiparallel.
    println!("glam Vec3::slerp worst |length − 1| near antiparallel: {glam_worst}");
}

#[test]
fn try_variants_reject_what_slerp_maps_to_zero() {
    fn non_finite<T>(what: &'static str) -> Result<T, InterpError> {
        Err(InterpError::NonFinite { what })
    }
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let v = Vec3::new(bad, 0.0, 1.0);
        assert_eq!(try_slerp(v, Vec3::X, 0.5), non_finite("a"));
        assert_eq!(try_slerp(Vec3::X, v, 0.5), non_finite("b"));
        assert_eq!(try_slerp(Vec3::X, Vec3::Y, bad), non_finite("t"));
        assert_eq!(slerp(v, Vec3::X, 0.5), Vec3::ZERO);
        let q = Quat::from_xyzw(bad, 0.0, 0.0, 1.0);
        assert_eq!(
            try_slerp_along(q, Quat::IDENTITY, 0.5, QuatPath::Shortest),
            non_finite("a")
        );
        assert_eq!(try_slerp(Quat::IDENTITY, q, 0.5), non_finite("b"));
        assert_eq!(
            slerp_along(Quat::IDENTITY, q, 0.5, QuatPath::Shortest),
            Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)
        );
    }
    assert_eq!(
        try_slerp(Vec3::ZERO, Vec3::X, 0.5),
        Err(InterpError::ZeroLength { what: "a" })
    );
    // Huge and tiny (subnormal) vectors are directions like any other.
    let huge = try_slerp(
        Vec3::new(3e38, 3e38, 0.0),
        Vec3::new(0.0, 0.0, 1e-40),
        1.0 / 3.0,
    )
    .expect("finite, nonzero inputs");
    let expected = slerp(Vec3::new(1.0, 1.0, 0.0).normalize(), Vec3::Z, 1.0 / 3.0);
    assert!(
        (huge - expected).length() <= 2.0 * SLERP_F32_ANGLE_BOUND,
        "{huge:?}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4096))]

    /// Total: any bit patterns give a finite result (zero for invalid input), never NaN, never a
    /// panic; and valid inputs give a unit result.
    #[test]
    fn any_bits_give_a_finite_result(
        a in (bits_f32(), bits_f32(), bits_f32(), bits_f32()),
        b in (bits_f32(), bits_f32(), bits_f32(), bits_f32()),
        t in bits_f32(),
    ) {
        let (a4, b4) = (Vec4::new(a.0, a.1, a.2, a.3), Vec4::new(b.0, b.1, b.2, b.3));
        let q = slerp_along(Quat::from_vec4(a4), Quat::from_vec4(b4), t, QuatPath::Shortest);
        prop_assert!(q.is_finite());
        let v = slerp(a4.truncate(), b4.truncate(), t);
        prop_assert!(v.is_finite());
        let valid = a4.truncate().is_finite() && b4.truncate().is_finite() && t.is_finite()
            && a4.truncate() != Vec3::ZERO && b4.truncate() != Vec3::ZERO;
        prop_assert_eq!(v != Vec3::ZERO, valid, "{:?}", v);
        if valid {
            prop_assert!((v.length() - 1.0).abs() <= 4.0 * SLERP_F32_LENGTH_BOUND, "{:?}", v);
        }
        for method in QuatInterpolation::ALL {
            prop_assert!(method.interpolate(Quat::from_vec4(a4), Quat::from_vec4(b4), t).is_finite());
        }
        let n = interpolate_normal(a4.truncate(), b4.truncate(), t, NormalInterpolation::Renormalize);
        prop_assert!(n.is_finite());
        let d = slerp(a4.truncate().as_dvec3(), b4.truncate().as_dvec3(), f64::from(t));
        prop_assert!(d.is_finite());
    }
}

/// The largest 4D angle and length errors of `method` over a dense grid of angles in
/// `[0, π/2]` (the short path's range) and parameters in `[0, 1]`.
fn measure(method: QuatInterpolation) -> (f64, f64) {
    let mut rng = XorShift::new(0xa99);
    let mut worst = (0.0f64, 0.0f64);
    for (a, b, _) in sphere::quat_pairs(&mut rng, 600, std::f32::consts::FRAC_PI_2) {
        for i in 0..=40 {
            let t = i as f32 / 40.0;
            let r = method.interpolate(a, b, t);
            let b = if a.dot(b) < 0.0 { -b } else { b };
            let reference = sphere::slerp(
                &f64s(a.to_array()),
                &f64s(b.to_array()),
                f64::from(t),
                &[1.0, 0.0, 0.0, 0.0],
            )
            .expect("unit");
            let (angle, length) = errors(&f64s(r.to_array()), &reference);
            worst = (worst.0.max(angle), worst.1.max(length));
        }
    }
    worst
}

#[test]
fn approximation_bounds() {
    let mut report = String::new();
    let mut methods: Vec<QuatInterpolation> = QuatInterpolation::ALL.to_vec();
    methods.extend((1..=16).map(|terms| QuatInterpolation::Eberly { terms }));
    let mut failures = Vec::new();
    for method in methods {
        let (angle, length) = measure(method);
        let (angle_bound, length_bound) = (
            f64::from(method.angle_bound()),
            f64::from(method.length_bound()),
        );
        report += &format!(
            "{:<22} angle {angle:.3e} (bound {angle_bound:.1e})  length {length:.3e} (bound {length_bound:.1e})\n",
            method.name()
        );
        if angle > angle_bound || length > length_bound {
            failures.push(format!("{}: measured above its bound", method.name()));
        }
        // Honest in the other direction too: a bound more than twice what is measured (and
        // above the f32 rounding floor) is not a statement about this method.
        let floor = 3e-7;
        if angle_bound > 2.0 * angle.max(floor) || length_bound > 2.0 * length.max(floor) {
            failures.push(format!(
                "{}: bound more than twice the measured error",
                method.name()
            ));
        }
    }
    println!("{report}");
    assert!(failures.is_empty(), "{failures:#?}\n{report}");
}

#[test]
fn normal_spacing() {
    // Renormalized lerp is on the arc but unevenly spaced; slerp is even.
    for degrees in [10.0f32, 45.0, 90.0, 150.0] {
        let theta = degrees.to_radians();
        let n1 = Vec3::new(theta.cos(), theta.sin(), 0.0);
        let bound = renormalize_spacing_error(f64::from(theta));
        let mut worst = 0.0f64;
        for i in 0..=64 {
            let t = i as f32 / 64.0;
            let even = f64::from(t * theta);
            let lerped = interpolate_normal(Vec3::X, n1, t, NormalInterpolation::Renormalize);
            let slerped = interpolate_normal(Vec3::X, n1, t, NormalInterpolation::Slerp);
            let angle_of = |v: Vec3| f64::from(v.y).atan2(f64::from(v.x));
            worst = worst.max((angle_of(lerped) - even).abs());
            assert!((angle_of(slerped) - even).abs() <= 2.0 * f64::from(SLERP_F32_ANGLE_BOUND));
            assert!((angle_of(lerped) - even).abs() <= bound + f64::from(SLERP_F32_ANGLE_BOUND));
        }
        // The bound is attained (to the sampling of t), so the spacing error is real.
        assert!(worst >= 0.9 * bound, "{degrees}°: {worst} vs {bound}");
        println!(
            "{degrees}°: renormalized lerp up to {:.4}° off even spacing",
            bound.to_degrees()
        );
    }
}

#[test]
fn spacing_error_formula() {
    for theta in [0.01f64, 0.5, 1.0, 2.0, 3.0] {
        let (s, c) = theta.sin_cos();
        let dense = (0..=100_000)
            .map(|i| {
                let t = f64::from(i) / 100_000.0;
                (theta * t - (t * s).atan2(1.0 - t + t * c)).abs()
            })
            .fold(0.0f64, f64::max);
        let formula = renormalize_spacing_error(theta);
        assert!(
            (formula - dense).abs() <= 1e-9 * theta.max(1.0),
            "{theta}: {formula} vs {dense}"
        );
        assert!(formula >= dense - 1e-12);
    }
    assert!(renormalize_spacing_error(std::f64::consts::PI).is_nan());
    assert!(renormalize_spacing_error(f64::NAN).is_nan());
}

#[test]
fn f64_variants_agree_with_f32_on_easy_inputs() {
    let a = DVec3::new(0.6, 0.8, 0.0);
    let b = DVec3::Z;
    let r = slerp(a, b, 0.3);
    let r32 = slerp(a.as_vec3(), b.as_vec3(), 0.3);
    assert!((r.as_vec3() - r32).length() < 2.0 * SLERP_F32_ANGLE_BOUND);
}
