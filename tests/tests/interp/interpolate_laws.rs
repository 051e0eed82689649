//! One generic test of the `Interpolate` laws, run for every implementation.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::{Homogeneous3, Interpolate, interpolate3};
use barytex_testkit::components::Components;
use glam::{DVec2, DVec3, DVec4, Vec2, Vec3, Vec3A, Vec4};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};

/// Build a value of `T` from a slice of components in [-1e3, 1e3].
trait FromComponents: Sized {
    const LEN: usize;
    fn from_components(c: &[f32]) -> Self;
}

impl FromComponents for f32 {
    const LEN: usize = 1;
    fn from_components(c: &[f32]) -> Self {
        c[0]
    }
}
impl FromComponents for f64 {
    const LEN: usize = 1;
    fn from_components(c: &[f32]) -> Self {
        f64::from(c[0]) * 1.000_000_1
    }
}
macro_rules! from_vec {
    ($t:ty, $n:expr, $ctor:expr) => {
        impl FromComponents for $t {
            const LEN: usize = $n;
            fn from_components(c: &[f32]) -> Self {
                $ctor(c)
            }
        }
    };
}
from_vec!(Vec2, 2, |c: &[f32]| Vec2::new(c[0], c[1]));
from_vec!(Vec3, 3, |c: &[f32]| Vec3::new(c[0], c[1], c[2]));
from_vec!(Vec3A, 3, |c: &[f32]| Vec3A::new(c[0], c[1], c[2]));
from_vec!(Vec4, 4, |c: &[f32]| Vec4::new(c[0], c[1], c[2], c[3]));
from_vec!(DVec2, 2, |c: &[f32]| Vec2::new(c[0], c[1]).as_dvec2() / 3.0);
from_vec!(DVec3, 3, |c: &[f32]| Vec3::new(c[0], c[1], c[2]).as_dvec3()
    / 3.0);
from_vec!(DVec4, 4, |c: &[f32]| Vec4::new(c[0], c[1], c[2], c[3])
    .as_dvec4()
    / 3.0);
from_vec!([f32; 3], 3, |c: &[f32]| [c[0], c[1], c[2]]);
from_vec!((f32, Vec2), 3, |c: &[f32]| (c[0], Vec2::new(c[1], c[2])));
from_vec!((Vec3, f64, [Vec2; 2]), 8, |c: &[f32]| (
    Vec3::new(c[0], c[1], c[2]),
    f64::from(c[3]),
    [Vec2::new(c[4], c[5]), Vec2::new(c[6], c[7])]
));
from_vec!((f32, f32, f32, f32), 4, |c: &[f32]| (
    c[0], c[1], c[2], c[3]
));

fn check_laws<T>(name: &str)
where
    T: Interpolate + FromComponents + Components + core::fmt::Debug,
{
    let mut runner = TestRunner::new(Config {
        cases: 128,
        ..Config::default()
    });
    let n = T::LEN;
    let strategy = (
        proptest::collection::vec(-1e3f32..1e3, n),
        proptest::collection::vec(-1e3f32..1e3, n),
        -2.0f32..3.0,
        (-3.0f32..3.0, -3.0f32..3.0),
    );
    runner
        .run(&strategy, |(ca, cb, t, (w0, w1))| {
            let a = T::from_components(&ca);
            let b = T::from_components(&cb);
            // 1. exact endpoints
            prop_assert_eq!(
                a.lerp(b, 0.0).components(),
                a.components(),
                "{} endpoint 0",
                name
            );
            prop_assert_eq!(
                a.lerp(b, 1.0).components(),
                b.components(),
                "{} endpoint 1",
                name
            );
            // 2. consistency
            prop_assert_eq!(
                a.lerp(a, t).components(),
                a.components(),
                "{} lerp(a, a, t)",
                name
            );
            // 3. partition of unity, 4. weights summing to zero
            let w = [w0, w1, 1.0 - w0 - w1];
            let wsum: f64 = w.iter().map(|&x| f64::from(x)).sum();
            let wabs: f64 = w.iter().map(|&x| f64::from(x).abs()).sum();
            let eps = f64::from(f32::EPSILON);
            let one = interpolate3([a, a, a], w).components();
            for (got, want) in one.iter().zip(a.components()) {
                let bound = 4.0 * eps * wabs * want.abs() + (wsum - 1.0).abs() * want.abs();
                prop_assert!(
                    (got - want).abs() <= bound,
                    "{} partition of unity: {} vs {}",
                    name,
                    got,
                    want
                );
            }
            let dw = [w0, w1, -w0 - w1];
            let dabs: f64 = dw.iter().map(|&x| f64::from(x).abs()).sum();
            let zero = T::combine3([a, a, a], dw).components();
            for (got, want) in zero.iter().zip(a.components()) {
                let bound = 4.0 * eps * dabs * want.abs() + f64::from(-w0 - w1 + w0 + w1).abs();
                prop_assert!(got.abs() <= bound, "{} zero-sum weights gave {}", name, got);
            }
            // 5. linearity, component by component
            let lin = a.scale(w0).add(b.scale(w1)).components();
            for ((got, ai), bi) in lin.iter().zip(a.components()).zip(b.components()) {
                let want_scale = ai * f64::from(w0);
                let want = ai.mul_add(f64::from(w0), bi * f64::from(w1));
                let bound = 4.0 * eps * (want_scale.abs() + (bi * f64::from(w1)).abs());
                prop_assert!(
                    (got - want).abs() <= bound.max(1e-300),
                    "{} linearity",
                    name
                );
            }
            // combine agrees with combine3
            let c3 = T::combine3([a, b, a], w).components();
            let cn = T::combine([(a, w[0]), (b, w[1]), (a, w[2])])
                .unwrap()
                .components();
            prop_assert_eq!(c3, cn, "{} combine vs combine3", name);
            Ok(())
        })
        .unwrap();
}

#[test]
fn laws_hold_for_every_impl() {
    check_laws::<f32>("f32");
    check_laws::<f64>("f64");
    check_laws::<Vec2>("Vec2");
    check_laws::<Vec3>("Vec3");
    check_laws::<Vec3A>("Vec3A");
    check_laws::<Vec4>("Vec4");
    check_laws::<DVec2>("DVec2");
    check_laws::<DVec3>("DVec3");
    check_laws::<DVec4>("DVec4");
    check_laws::<[f32; 3]>("[f32; 3]");
    check_laws::<(f32, Vec2)>("(f32, Vec2)");
    check_laws::<(Vec3, f64, [Vec2; 2])>("(Vec3, f64, [Vec2; 2])");
    check_laws::<(f32, f32, f32, f32)>("(f32, f32, f32, f32)");
}

#[test]
fn homogeneous_points_follow_the_laws() {
    let a = Homogeneous3::new(Vec3::new(1.0, 2.0, 3.0), 2.0);
    let b = Homogeneous3::new(Vec3::new(-4.0, 0.5, 9.0), 0.5);
    assert_eq!(a.lerp(b, 0.0), a);
    assert_eq!(a.lerp(b, 1.0), b);
    assert_eq!(a.lerp(a, 0.37), a);
}

/// Issue 20, item 3: the partition-of-unity bound keeps its underflow term `n·2⁻¹⁴⁹` for f32
/// components: subnormal values times weights round to the fixed subnormal spacing.
#[test]
fn partition_of_unity_with_subnormals() {
    let mut runner = TestRunner::new(Config {
        cases: 512,
        ..Config::default()
    });
    let tiny = (0u32..(3 << 23), any::<bool>())
        .prop_map(|(bits, negative)| f32::from_bits(bits | (u32::from(negative) << 31)));
    runner
        .run(&(tiny, (-3.0f32..3.0, -3.0f32..3.0)), |(a, (w0, w1))| {
            let w = [w0, w1, 1.0 - w0 - w1];
            let wsum: f64 = w.iter().map(|&x| f64::from(x)).sum();
            let wabs: f64 = w.iter().map(|&x| f64::from(x).abs()).sum();
            let eps = f64::from(f32::EPSILON);
            let want = f64::from(a);
            for got in [
                f64::from(interpolate3([a, a, a], w)),
                f64::from(interpolate3([Vec3::splat(a); 3], w).y),
            ] {
                let bound = 4.0 * eps * wabs * want.abs()
                    + (wsum - 1.0).abs() * want.abs()
                    + 3.0 * 2f64.powi(-149);
                prop_assert!((got - want).abs() <= bound, "{a:e} {w:?}: {got:e}");
            }
            Ok(())
        })
        .unwrap();
}
