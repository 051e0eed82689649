//! Exact 3D orientation: exact-rational agreement on random, near-coplanar, exactly coplanar,
//! huge, tiny and subnormal inputs; the sign convention; special values.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::methods::orient3d_naive_f64;
use barytex_interp::{InterpError, Orientation, orient3d};
use barytex_testkit::exact;
use barytex_testkit::invariants_3d::check_orient3d;
use barytex_testkit::seeded::XorShift;
use barytex_testkit::strategies::{bits_f32, finite_bits_f32, step_ulps, vec3_in};
use glam::Vec3;
use proptest::prelude::*;

fn vec3_bits() -> impl Strategy<Value = Vec3> + Clone {
    (bits_f32(), bits_f32(), bits_f32()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn vec3_finite_bits() -> impl Strategy<Value = Vec3> + Clone {
    (finite_bits_f32(), finite_bits_f32(), finite_bits_f32())
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// `a + u(b − a) + v(c − a)` rounded to f32, then one coordinate moved `k` ulps: within a few
/// ulps of the plane of `a, b, c`, often exactly on it.
fn near_coplanar([a, b, c]: [Vec3; 3], u: f32, v: f32, axis: usize, k: i32) -> Vec3 {
    let mut d = a + (b - a) * u + (c - a) * v;
    d[axis] = step_ulps(d[axis], k);
    d
}

#[test]
fn sign_convention() {
    // Positive: d on the side the normal (b − a) × (c − a) points to (a, b, c counter-clockwise
    // seen from d).
    let o = |a, b, c, d| orient3d(a, b, c, d).unwrap();
    assert_eq!(
        o(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z),
        Orientation::CounterClockwise
    );
    assert_eq!(
        o(Vec3::ZERO, Vec3::X, Vec3::Y, -Vec3::Z),
        Orientation::Clockwise
    );
    assert_eq!(
        o(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(5.0, -7.0, 0.0)),
        Orientation::Collinear
    );
    // The opposite of Shewchuk's (robust's) convention.
    assert_eq!(
        o(Vec3::Z, Vec3::ZERO, Vec3::X, Vec3::Y),
        Orientation::Clockwise
    );
}

proptest! {
    #[test]
    fn orient3d_matches_exact_rational(
        a in vec3_in(-1e3, 1e3), b in vec3_in(-1e3, 1e3),
        c in vec3_in(-1e3, 1e3), d in vec3_in(-1e3, 1e3),
    ) {
        check_orient3d(a, b, c, d).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn orient3d_exact_on_near_coplanar(
        a in vec3_in(-1e3, 1e3), b in vec3_in(-1e3, 1e3), c in vec3_in(-1e3, 1e3),
        u in -2.0f32..2.0, v in -2.0f32..2.0, axis in 0usize..3, k in -3i32..=3,
    ) {
        let d = near_coplanar([a, b, c], u, v, axis, k);
        check_orient3d(a, b, c, d).map_err(TestCaseError::fail)?;
        check_orient3d(d, a, b, c).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn orient3d_exact_on_any_finite_bits(
        a in vec3_finite_bits(), b in vec3_finite_bits(),
        c in vec3_finite_bits(), d in vec3_finite_bits(),
    ) {
        check_orient3d(a, b, c, d).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn orient3d_total_on_any_bits(a in vec3_bits(), b in vec3_bits(), c in vec3_bits(), d in vec3_bits()) {
        check_orient3d(a, b, c, d).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn orient3d_is_antisymmetric(
        a in vec3_in(-1e3, 1e3), b in vec3_in(-1e3, 1e3),
        c in vec3_in(-1e3, 1e3), d in vec3_in(-1e3, 1e3),
    ) {
        let s = orient3d(a, b, c, d).unwrap().sign();
        prop_assert_eq!(orient3d(b, a, c, d).unwrap().sign(), -s);
        prop_assert_eq!(orient3d(a, b, d, c).unwrap().sign(), -s);
        prop_assert_eq!(orient3d(b, c, d, a).unwrap().sign(), -s);
        prop_assert_eq!(orient3d(c, d, a, b).unwrap().sign(), s);
    }

    #[test]
    fn orient3d_exact_on_scaled_near_coplanar(
        a in vec3_in(-1.0, 1.0), b in vec3_in(-1.0, 1.0), c in vec3_in(-1.0, 1.0),
        u in -2.0f32..2.0, v in -2.0f32..2.0, axis in 0usize..3, k in -2i32..=2,
        exponent in -126i32..=126, offset in -1e3f32..1e3,
    ) {
        let scale = 2f32.powi(exponent);
        let [a, b, c] = [a, b, c].map(|p| p * scale + Vec3::splat(offset * scale));
        let d = near_coplanar([a, b, c], u, v, axis, k);
        check_orient3d(a, b, c, d).map_err(TestCaseError::fail)?;
    }
}

/// Near-coplanar points on a seeded batch: parallelograms of 24-bit integer corners (exactly
/// coplanar, `d = a + b − c`, every coordinate exact in f32) and the same with `d` one unit off in
/// one coordinate, at scales 2⁻⁶⁰ … 2⁶⁰. None wrong, while the naive f64 determinant (no filter;
/// its triple products need up to 75 bits) must get some wrong, or the batch is not hard.
#[test]
fn near_coplanar_batch_has_no_wrong_sign() {
    let mut rng = XorShift::new(0x03d);
    let (mut wrong, mut naive_wrong, mut coplanar) = (0, 0, 0);
    let half = 1 << 22;
    for _ in 0..20_000 {
        let corner = |rng: &mut XorShift| {
            Vec3::new(
                rng.i32_in(-half, half) as f32,
                rng.i32_in(-half, half) as f32,
                rng.i32_in(-half, half) as f32,
            )
        };
        let (a, b, c) = (corner(&mut rng), corner(&mut rng), corner(&mut rng));
        let mut d = a + b - c;
        d[(rng.next_u64() % 3) as usize] += rng.i32_in(-1, 1) as f32;
        let scale = 2f32.powi(rng.i32_in(-60, 60));
        let [a, b, c, d] = [a, b, c, d].map(|p| p * scale);
        let want = exact::orient3d_sign(a, b, c, d);
        wrong += usize::from(orient3d(a, b, c, d).unwrap().sign() != want);
        naive_wrong += usize::from(orient3d_naive_f64(a, b, c, d).sign() != want);
        coplanar += usize::from(want == 0);
    }
    println!(
        "near-coplanar 20 000: exact {wrong}, naive f64 {naive_wrong} wrong; {coplanar} coplanar"
    );
    assert_eq!(wrong, 0);
    assert!(
        naive_wrong > 0,
        "the batch must defeat the naive determinant"
    );
    assert!(coplanar > 0);
}

#[test]
fn extreme_magnitudes_are_exact() {
    let m = f32::MAX;
    let tiny = f32::from_bits(1);
    let cases = [
        // Largest magnitudes: products of three differences near 2³⁸⁷.
        [
            Vec3::splat(m),
            Vec3::splat(-m),
            Vec3::new(m, -m, m),
            Vec3::new(-m, m, -m),
        ],
        [
            Vec3::new(m, 0.0, 0.0),
            Vec3::new(0.0, m, 0.0),
            Vec3::new(0.0, 0.0, m),
            Vec3::new(-m, -m, -m),
        ],
        // Smallest: subnormal coordinates, products near 2⁻⁴⁴⁷.
        [
            Vec3::ZERO,
            Vec3::new(tiny, 0.0, 0.0),
            Vec3::new(0.0, tiny, 0.0),
            Vec3::new(0.0, 0.0, tiny),
        ],
        [
            Vec3::ZERO,
            Vec3::new(tiny, 0.0, 0.0),
            Vec3::new(0.0, tiny, 0.0),
            Vec3::new(tiny, tiny, 0.0),
        ],
        // Mixed: 1e-30 beside 1e30.
        [
            Vec3::splat(1e30),
            Vec3::new(1e-30, 0.0, 0.0),
            Vec3::new(0.0, 1e-30, 1e30),
            Vec3::new(1e-30, 1e-30, 1e-30),
        ],
        [
            Vec3::new(1e30, 1e30, 0.0),
            Vec3::new(-1e30, -1e30, 0.0),
            Vec3::ZERO,
            Vec3::new(0.0, 0.0, 1e-45),
        ],
        // Exactly coplanar at 1e30 with inexact-looking values.
        [
            Vec3::new(1e30, 3e30, 7e30),
            Vec3::new(2e30, 6e30, 14e30),
            Vec3::new(3e30, 9e30, 21e30),
            Vec3::new(0.1, 0.3, 0.7),
        ],
    ];
    for [a, b, c, d] in cases {
        check_orient3d(a, b, c, d).unwrap();
        check_orient3d(d, c, b, a).unwrap();
    }
    assert_eq!(
        orient3d(
            Vec3::ZERO,
            Vec3::new(tiny, 0.0, 0.0),
            Vec3::new(0.0, tiny, 0.0),
            Vec3::new(0.0, 0.0, tiny)
        ),
        Ok(Orientation::CounterClockwise)
    );
}

/// Points one ulp apart around 1.0: a tetrahedron of volume ~2⁻⁶⁹, decided exactly.
#[test]
fn last_ulp_tetrahedra_are_exact() {
    let one = 1.0f32;
    let up = |k: i32| step_ulps(one, k);
    for k in -2..=2 {
        for axis in 0..3 {
            let mut d = Vec3::new(up(1), up(1), one);
            d[axis] = step_ulps(d[axis], k);
            let (a, b, c) = (
                Vec3::ONE,
                Vec3::new(up(2), one, one),
                Vec3::new(one, up(2), one),
            );
            check_orient3d(a, b, c, d).unwrap();
        }
    }
}

#[test]
fn non_finite_is_an_error_naming_the_point() {
    let named = |what| Err(InterpError::NonFinite { what });
    for v in barytex_interp::hard_cases::NON_FINITE {
        let bad = [
            Vec3::new(v, 0.0, 0.0),
            Vec3::new(0.0, v, 0.0),
            Vec3::new(0.0, 0.0, v),
            Vec3::splat(v),
        ];
        for p in bad {
            assert_eq!(orient3d(p, Vec3::X, Vec3::Y, Vec3::Z), named("a"));
            assert_eq!(orient3d(Vec3::ZERO, p, Vec3::Y, Vec3::Z), named("b"));
            assert_eq!(orient3d(Vec3::ZERO, Vec3::X, p, Vec3::Z), named("c"));
            assert_eq!(orient3d(Vec3::ZERO, Vec3::X, Vec3::Y, p), named("d"));
        }
    }
    // Infinite but with zero cross terms, and opposite infinities that could cancel.
    let inf = f32::INFINITY;
    assert_eq!(
        orient3d(
            Vec3::new(inf, 0.0, 0.0),
            Vec3::new(inf, 0.0, 0.0),
            Vec3::ZERO,
            Vec3::ZERO
        ),
        named("a")
    );
    assert_eq!(
        orient3d(
            Vec3::new(inf, 0.0, 0.0),
            Vec3::new(-inf, 0.0, 0.0),
            Vec3::Y,
            Vec3::Z
        ),
        named("a")
    );
}
