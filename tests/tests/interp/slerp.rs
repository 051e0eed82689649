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
use barytex_testkit::precise;
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

/// The f32 `slerp` of `a`, `b` at `t` against the 200-bit reference of the directions, with the
/// perpendicular the code takes for exactly opposite inputs.
fn vec3_errors_precise(a: Vec3, b: Vec3, t: f32) -> (f64, f64) {
    let perp = a.as_dvec3().normalize().any_orthonormal_vector();
    let arc = precise::Arc::new(&f64s(a.to_array()), &f64s(b.to_array()), &perp.to_array())
        .expect("nonzero inputs");
    precise::errors(&f64s(slerp(a, b, t).to_array()), &arc.at(f64::from(t)))
}

/// As [`vec3_errors_precise`] for quaternions on `path`.
fn quat_errors_precise(a: Quat, b: Quat, t: f32, path: QuatPath) -> (f64, f64) {
    let r = slerp_along(a, b, t, path);
    let b = if path == QuatPath::Shortest && a.dot(b) < 0.0 {
        -b
    } else {
        b
    };
    let perp = Vec4::new(a.y, -a.x, a.w, -a.z);
    let arc = precise::Arc::new(
        &f64s(a.to_array()),
        &f64s(b.to_array()),
        &f64s(perp.to_array()),
    )
    .expect("nonzero inputs");
    precise::errors(&f64s(r.to_array()), &arc.at(f64::from(t)))
}

/// Whether the f32 SLERP uses `v` as given: its squared length, computed in f64 (exact products),
/// within `4·ε` of 1.
fn accepted_as_unit(v: &[f32]) -> bool {
    let len2: f64 = v.iter().map(|&x| f64::from(x) * f64::from(x)).sum();
    (len2 - 1.0).abs() <= 4.0 * f64::from(f32::EPSILON)
}

/// `u` scaled by `1 + δ` and rounded to f32: squared lengths spread over `1 ± 6ε`, across the
/// unit tolerance's edge on both sides.
fn near_unit(u: Vec3, rng: &mut XorShift) -> Vec3 {
    let delta = f64::from(rng.f32_in(-3.0, 3.0)) * f64::from(f32::EPSILON);
    (u.as_dvec3() * (1.0 + delta)).as_vec3()
}

/// Issue 20, item 1: at the edge of the unit tolerance all three claims hold together — ends bit
/// exact (for inputs the tolerance accepts), length within `SLERP_F32_LENGTH_BOUND` and angle
/// within `SLERP_F32_ANGLE_BOUND` of the SLERP of the inputs' directions — once the tolerance is
/// decided in f64 (so an accepted input is within 2.385e-7 of unit length) and the arc is
/// computed from the inputs divided by their f64 lengths.
#[test]
fn inputs_at_the_edge_of_the_unit_tolerance() {
    // The audit's cases: 2.48e-7 rad off at t = 0.99, and an input 3.06e-7 off unit length that
    // was accepted (by an f32 squared length within 4ε of 1) and returned at t = 0.
    let a = Vec3::new(0.804_116_25, 0.548_267_84, -0.229_782_48);
    let b = Vec3::new(-0.984_735_6, -0.038_564_228, 0.169_730_98);
    let (angle, length) = vec3_errors_precise(a, b, 0.99);
    assert!(angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{angle:e}");
    assert!(length <= f64::from(SLERP_F32_LENGTH_BOUND), "{length:e}");
    let a = Vec3::new(-0.411_605_72, 0.734_760_4, -0.539_173_9);
    let at_zero = slerp(a, Vec3::X, 0.0);
    assert_eq!(at_zero == a, accepted_as_unit(&a.to_array()));
    let (angle, length) = vec3_errors_precise(a, Vec3::X, 0.0);
    assert!(
        angle <= 1e-7 && length <= f64::from(SLERP_F32_LENGTH_BOUND),
        "{angle:e} {length:e}"
    );

    let mut rng = XorShift::new(0xed9e);
    let mut worst = Worst::default();
    let (mut accepted, mut rejected) = (0, 0);
    for (a, b, t) in sphere::vec3_pairs(&mut rng.clone(), 3_000, std::f32::consts::PI) {
        let (a, b) = (near_unit(a, &mut rng), near_unit(b, &mut rng));
        for (v, at) in [(a, 0.0f32), (b, 1.0)] {
            let end = slerp(a, b, at);
            if accepted_as_unit(&v.to_array()) {
                accepted += 1;
                assert_eq!(end, v, "accepted inputs are returned as given");
            } else {
                rejected += 1;
            }
        }
        for t in PARAMETERS.into_iter().chain([t, 0.99]) {
            worst.add(vec3_errors_precise(a, b, t), || {
                format!("{a:?} {b:?} t={t}")
            });
        }
    }
    println!(
        "edge of the unit tolerance ({accepted} ends as given, {rejected} normalized): {worst:?}"
    );
    assert!(
        accepted > 1000 && rejected > 1000,
        "both sides of the edge are sampled"
    );
    assert!(worst.angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{worst:?}");
    assert!(
        worst.length <= f64::from(SLERP_F32_LENGTH_BOUND),
        "{worst:?}"
    );
}

/// Issue 20, item 2: nearly opposite inputs that are not quite unit. The plane of the arc is set
/// by `b + a`, far smaller than the rounding of an f32 normalization; the arc is computed from the
/// exact inputs (their minors), so the bounds hold against the SLERP of the directions down to
/// exactly opposite. Reference: 200-bit fixed point from the exact inputs.
#[test]
fn nearly_opposite_not_quite_unit_inputs() {
    // The audit's case: 0.109 rad off when the inputs were normalized in f32 first.
    let a = Quat::from_xyzw(-0.301_563_83, 0.707_113, 0.553_461_1, 0.320_517_24);
    let b = Quat::from_xyzw(0.301_563_83, -0.707_113_3, -0.553_461_2, -0.320_517_24);
    let (angle, length) = quat_errors_precise(a, b, 0.521_981_8, QuatPath::AsGiven);
    println!("audit case: angle {angle:e}, length {length:e}");
    assert!(angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{angle:e}");
    assert!(length <= f64::from(SLERP_F32_LENGTH_BOUND), "{length:e}");

    let mut rng = XorShift::new(0x0bb0);
    let mut worst = Worst::default();
    for i in 0..1_500 {
        let u = sphere::unit_quat(&mut rng).to_array().map(f64::from);
        let dir = sphere::unit_quat(&mut rng).to_array().map(f64::from);
        // b = −u·(1 + δ) + 10^(−k)·dir: from 0.1 down to 1e-12 off opposite, lengths off unit by
        // up to 30 ε (outside the tolerance) or within it.
        let k = f64::from(1 + i % 12);
        let (da, db) = (
            f64::from(rng.f32_in(-30.0, 30.0)) * f64::from(f32::EPSILON),
            f64::from(rng.f32_in(-30.0, 30.0)) * f64::from(f32::EPSILON),
        );
        let a = Vec4::from_array(u.map(|x| (x * (1.0 + da)) as f32));
        let b = Vec4::from_array(core::array::from_fn(|j| {
            (-u[j] * (1.0 + db) + 10f64.powf(-k) * dir[j]) as f32
        }));
        let (a, b) = (Quat::from_vec4(a), Quat::from_vec4(b));
        for t in PARAMETERS
            .into_iter()
            .chain([rng.f32_in(0.0, 1.0), -1.5, 2.5])
        {
            let (angle, length) = quat_errors_precise(a, b, t, QuatPath::AsGiven);
            // Outside [0, 1] the angle bound grows with |t| (see the extrapolation test).
            let scale = f64::from(t.abs().max(1.0));
            worst.add((angle / scale, length), || format!("{a:?} {b:?} t={t}"));
        }
        // Vectors too: the first three components, as given and scaled by powers of two (exact,
        // same directions) to 2¹⁰⁰ and 2⁻¹²⁰.
        let (a3, b3) = (a.xyz(), b.xyz());
        for t in PARAMETERS {
            worst.add(vec3_errors_precise(a3, b3, t), || {
                format!("{a3:?} {b3:?} t={t}")
            });
            let (big, small) = (a3 * 2f32.powi(100), b3 * 2f32.powi(-120));
            worst.add(vec3_errors_precise(big, small, t), || {
                format!("{big:?} {small:?} t={t}")
            });
        }
    }
    // Exactly opposite but of different lengths: the documented perpendicular's half turn.
    let a = Vec3::new(0.6, 0.8, 0.0);
    for b in [-a, -2.0 * a, -0.5 * a] {
        worst.add(vec3_errors_precise(a, b, 0.5), || {
            format!("{a:?} {b:?} opposite")
        });
    }
    println!("nearly opposite, not quite unit: {worst:?}");
    assert!(worst.angle <= f64::from(SLERP_F32_ANGLE_BOUND), "{worst:?}");
    assert!(
        worst.length <= f64::from(SLERP_F32_LENGTH_BOUND),
        "{worst:?}"
    );
}

/// Issue 20, item 6: the f64 SLERPs against the 200-bit reference (an f64 reference cannot see
/// their errors). Inputs: f64 unit vectors at every angle, within 1e-12 of equal and opposite,
/// at the edge of the f64 unit tolerance, and quaternions on both paths.
#[test]
fn exact_slerp_f64_against_a_precise_reference() {
    let mut rng = XorShift::new(0xf64f);
    let mut worst = Worst::default();
    let mut worst_extrapolated = 0.0f64;
    let unit = |rng: &mut XorShift| {
        let v = DVec3::new(
            f64::from(rng.f32_in(-1.0, 1.0)) + f64::from(rng.f32_in(-1.0, 1.0)) * 1e-8,
            f64::from(rng.f32_in(-1.0, 1.0)) + f64::from(rng.f32_in(-1.0, 1.0)) * 1e-8,
            f64::from(rng.f32_in(-1.0, 1.0)),
        );
        v.normalize()
    };
    for i in 0..1_500 {
        let a = unit(&mut rng);
        let c = unit(&mut rng);
        let b = match i % 4 {
            0 => c,
            1 => (a + c * 10f64.powi(-(i % 13))).normalize(),
            2 => (-a + c * 10f64.powi(-(i % 13))).normalize(),
            // Off unit length by up to 3 ε: across the f64 tolerance's edge.
            _ => c * (1.0 + f64::from(rng.f32_in(-3.0, 3.0)) * f64::EPSILON),
        };
        let perp = a.normalize().any_orthonormal_vector();
        let arc =
            precise::Arc::new(&a.to_array(), &b.to_array(), &perp.to_array()).expect("nonzero");
        for t in PARAMETERS.map(f64::from) {
            let r = slerp(a, b, t);
            worst.add(precise::errors(&r.to_array(), &arc.at(t)), || {
                format!("{a:?} {b:?} t={t}")
            });
        }
        for t in [-2.0, 3.5] {
            let (angle, length) = precise::errors(&slerp(a, b, t).to_array(), &arc.at(t));
            worst_extrapolated = worst_extrapolated.max(angle / t.abs());
            assert!(
                length <= SLERP_F64_LENGTH_BOUND,
                "{a:?} {b:?} {t}: {length:e}"
            );
        }
        let (qa, qb) = (
            DQuat::from_axis_angle(a, f64::from(i) * 0.004),
            DQuat::from_axis_angle(c, 6.0 - f64::from(i) * 0.003),
        );
        for path in [QuatPath::Shortest, QuatPath::AsGiven] {
            let qb_path = if path == QuatPath::Shortest && qa.dot(qb) < 0.0 {
                -qb
            } else {
                qb
            };
            let perp = [qa.y, -qa.x, qa.w, -qa.z];
            let arc =
                precise::Arc::new(&qa.to_array(), &qb_path.to_array(), &perp).expect("nonzero");
            let t = f64::from(rng.f32_in(0.0, 1.0));
            let q = slerp_along(qa, qb, t, path);
            worst.add(precise::errors(&q.to_array(), &arc.at(t)), || {
                format!("{qa:?} {qb:?} t={t} {path:?}")
            });
        }
    }
    println!("f64 against 200-bit: {worst:?}; extrapolated per unit |t| {worst_extrapolated:e}");
    assert!(worst.angle <= SLERP_F64_ANGLE_BOUND, "{worst:?}");
    assert!(worst.length <= SLERP_F64_LENGTH_BOUND, "{worst:?}");
    assert!(
        worst_extrapolated <= SLERP_F64_ANGLE_BOUND,
        "{worst_extrapolated:e}"
    );
}

/// The slice functions give what the per-call functions give, element by element: bit for bit
/// on x86-64 (same operations in the same order, glam's SSE2 dot product order), within the
/// f32 rounding elsewhere. Lengths 0 to 13 reach the groups of four and every remainder; the
/// inputs mix signs of `a·b` (both paths of the select), non-unit, zero and non-finite
/// quaternions (zero in their own slot only).
#[test]
fn batch_equals_the_per_call_functions() {
    use barytex_interp::{
        NlerpCorrection, nlerp_corrected_quat, nlerp_corrected_quats, nlerp_quat, nlerp_quats,
    };
    let mut rng = XorShift::new(0xba7c);
    let mut pairs = sphere::quat_pairs(&mut rng, 400, std::f32::consts::PI);
    for (i, (_, b, t)) in pairs.iter_mut().enumerate() {
        if i % 3 == 0 {
            *b = -*b;
        }
        if i % 7 == 0 {
            *t = 1.7 * *t - 0.4;
        }
        match i % 50 {
            11 => *b = Quat::from_xyzw(f32::NAN, 0.0, 0.0, 1.0),
            23 => *b = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            37 => *b *= 3.0,
            41 => *t = f32::INFINITY,
            _ => {}
        }
    }
    let same = |batch: Quat, one: Quat, what: &str| {
        if cfg!(target_arch = "x86_64") {
            assert_eq!(
                batch.to_array().map(f32::to_bits),
                one.to_array().map(f32::to_bits),
                "{what}"
            );
        } else {
            assert!(
                (batch - one).length() <= 4.0 * f32::EPSILON,
                "{what}: {batch} vs {one}"
            );
        }
    };
    for start in 0..40 {
        for len in 0..=13 {
            let chunk = &pairs[start * 9..start * 9 + len];
            let a: Vec<Quat> = chunk.iter().map(|p| p.0).collect();
            let b: Vec<Quat> = chunk.iter().map(|p| p.1).collect();
            let t: Vec<f32> = chunk.iter().map(|p| p.2).collect();
            let mut out = vec![Quat::NAN; len];
            nlerp_quats(&a, &b, &t, &mut out).expect("same lengths");
            for i in 0..len {
                same(
                    out[i],
                    nlerp_quat(a[i], b[i], t[i]),
                    &format!("nlerp {i} of {len}"),
                );
            }
            for correction in [NlerpCorrection::Fast, NlerpCorrection::Precise] {
                nlerp_corrected_quats(&a, &b, &t, correction, &mut out).expect("same lengths");
                for i in 0..len {
                    same(
                        out[i],
                        nlerp_corrected_quat(a[i], b[i], t[i], correction),
                        &format!("{correction:?} {i} of {len}"),
                    );
                }
            }
        }
    }
    let q = [Quat::IDENTITY; 4];
    let mut out = [Quat::NAN; 4];
    assert_eq!(
        nlerp_quats(&q, &q[..3], &[0.5; 4], &mut out),
        Err(InterpError::LengthMismatch {
            what: "b",
            len: 3,
            expected: 4
        })
    );
    assert!(
        out.iter().all(|q| q.is_nan()),
        "nothing written on a length mismatch"
    );
}
