//! Trilinear interpolation: corners and trilinear functions reproduced exactly.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::trilinear;
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
