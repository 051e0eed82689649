//! Trilinear interpolation: corners and trilinear functions reproduced exactly, the condition
//! under which dyadic inputs are exact, and the accuracy bound with its underflow term.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::trilinear;
use barytex_testkit::exact::{Q, abs_diff, qf};
use glam::{Vec3, Vec4};
use proptest::prelude::*;

/// `f(x, y, z) = c₀ + c₁x + c₂y + c₃z + c₄xy + c₅xz + c₆yz + c₇xyz`.
fn trilinear_function(c: [f64; 8], t: [f64; 3]) -> f64 {
    let [x, y, z] = t;
    c[0] + c[1] * x
        + c[2] * y
        + c[3] * z
        + c[4] * x * y
        + c[5] * x * z
        + c[6] * y * z
        + c[7] * x * y * z
}

proptest! {
    /// Trilinear interpolation of a trilinear function's corner values reproduces the function;
    /// on dyadic parameters and small integer coefficients every step is exact, so equality is
    /// exact too.
    #[test]
    fn trilinear_reproduces_trilinear_functions(
        c in proptest::array::uniform8(-64i32..64),
        t in proptest::array::uniform3(0u32..=16),
    ) {
        let c = c.map(f64::from);
        let corners: [f64; 8] = core::array::from_fn(|n| {
            trilinear_function(c, [(n & 1) as f64, ((n >> 1) & 1) as f64, ((n >> 2) & 1) as f64])
        });
        let tf = t.map(|k| k as f32 / 16.0);
        let got = trilinear(corners, Vec3::from_array(tf));
        prop_assert_eq!(got, trilinear_function(c, tf.map(f64::from)));
    }

    /// The documented bound: ≤ 8·ε·max|corner| for t in [0,1]³ on arbitrary f32 corners.
    #[test]
    fn trilinear_accuracy_bound(corners in proptest::array::uniform8(-1e3f32..1e3), t in proptest::array::uniform3(0.0f32..=1.0)) {
        let got = trilinear(corners, Vec3::from_array(t));
        let [x, y, z] = t.map(f64::from);
        let w = |i: usize, s: f64| if i == 1 { s } else { 1.0 - s };
        let want: f64 = (0..8).map(|n| w(n & 1, x) * w((n >> 1) & 1, y) * w((n >> 2) & 1, z) * f64::from(corners[n])).sum();
        let m = corners.iter().fold(0.0f32, |m, c| m.max(c.abs()));
        prop_assert!((f64::from(got) - want).abs() <= 8.0 * f64::from(f32::EPSILON) * f64::from(m) + 1e-9);
    }
}

#[test]
fn corners_reproduced_exactly() {
    let corners: [Vec4; 8] =
        core::array::from_fn(|i| Vec4::new(i as f32 * 0.1, 1.0 / (i as f32 + 1.0), -3.7, i as f32));
    for (n, c) in corners.iter().enumerate() {
        let t = Vec3::new((n & 1) as f32, ((n >> 1) & 1) as f32, ((n >> 2) & 1) as f32);
        assert_eq!(trilinear(corners, t), *c);
    }
}

/// Exact trilinear interpolation of `corners` at `t` (rationals).
fn exact_trilinear(corners: [f32; 8], t: [f32; 3]) -> Q {
    let [x, y, z] = t.map(qf);
    let one = Q::from_integer(1.into());
    let w = |i: usize, s: &Q| if i == 1 { s.clone() } else { &one - s };
    (0..8)
        .map(|n| w(n & 1, &x) * w((n >> 1) & 1, &y) * w((n >> 2) & 1, &z) * qf(corners[n]))
        .sum()
}

/// Issue 20, item 4: exact on dyadic inputs *under a stated condition*. The claim without one
/// holds at `t = k/16` but fails at `k/256`: here the exact value −3204741/2²¹ is an f32, and
/// `trilinear` returns −1.528141. The condition (`trilinear`'s docs: `max|c| ≤ 2^(24+e−p−q−r)`)
/// is violated: p + q + r = 8 + 7 + 6, max|c| = 76 > 2³.
#[test]
fn dyadic_exactness_needs_its_condition() {
    let corners = [18.0f32, -13.0, -30.0, -59.0, 76.0, 56.0, -17.0, 26.0];
    let t = [0.691_406_25f32, 0.539_062_5, 0.421_875];
    let exact = exact_trilinear(corners, t);
    assert_eq!(exact, Q::new((-3_204_741).into(), (1 << 21).into()));
    let got = trilinear(corners, Vec3::from_array(t));
    assert_ne!(
        qf(got),
        exact,
        "outside the condition the result is rounded"
    );
    // Within the bound, though (8·ε·max|corner|).
    assert!(abs_diff(&qf(got), &exact) <= 8.0 * f64::from(f32::EPSILON) * 76.0);
}

/// Subnormal and smallest-normal f32 corners (exponent field 0, 1 or 2), either sign.
fn tiny_f32() -> impl Strategy<Value = f32> + Clone {
    (0u32..(3 << 23), any::<bool>())
        .prop_map(|(bits, negative)| f32::from_bits(bits | (u32::from(negative) << 31)))
}

proptest! {
    /// The exactness condition of `trilinear`'s docs: corners `Nᵢ·2^e` with `max|c| ≤
    /// 2^(24+e−p−q−r)` and `t` with components `k/2^p`, `k/2^q`, `k/2^r` in `[0, 1]` give the
    /// exact value, bit for bit, at every scale `2^e`.
    #[test]
    fn trilinear_is_exact_under_the_dyadic_condition(
        e in -120i32..100,
        pqr in (0i32..=10, 0i32..=10, 0i32..=10),
        n in proptest::array::uniform8(-(1i64 << 24)..=(1i64 << 24)),
        k in proptest::array::uniform3(0u32..=1024),
    ) {
        let (p, q_, r) = pqr;
        let headroom = 24 - p - q_ - r;
        prop_assume!(headroom >= 0);
        // max|N| ≤ 2^headroom, corners N·2^e.
        let limit = 1i64 << headroom;
        let corners: [f32; 8] = n.map(|v| (v.rem_euclid(2 * limit + 1) - limit) as f32 * 2f32.powi(e));
        prop_assume!(corners.iter().all(|c| c.is_finite()));
        let t = [
            (k[0] % ((1 << p) + 1)) as f32 / 2f32.powi(p),
            (k[1] % ((1 << q_) + 1)) as f32 / 2f32.powi(q_),
            (k[2] % ((1 << r) + 1)) as f32 / 2f32.powi(r),
        ];
        let got = trilinear(corners, Vec3::from_array(t));
        prop_assert_eq!(qf(got), exact_trilinear(corners, t), "{:?} at {:?}", corners, t);
    }

    /// Issue 20, item 3: the bound with its underflow term, `8·ε·max|corner| + 3·2⁻¹⁴⁹`, on
    /// subnormal corners (and mixed with ordinary tiny ones).
    #[test]
    fn trilinear_accuracy_bound_with_subnormals(
        corners in proptest::array::uniform8(prop_oneof![tiny_f32(), -1e-36f32..1e-36]),
        t in proptest::array::uniform3(0.0f32..=1.0),
    ) {
        let got = trilinear(corners, Vec3::from_array(t));
        let m = corners.iter().fold(0.0f32, |m, c| m.max(c.abs()));
        let bound = 8.0 * f64::from(f32::EPSILON) * f64::from(m) + 3.0 * 2f64.powi(-149);
        let err = abs_diff(&qf(got), &exact_trilinear(corners, t));
        prop_assert!(err <= bound, "{corners:?} at {t:?}: {got:e}, error {err:e} > {bound:e}");
    }
}
