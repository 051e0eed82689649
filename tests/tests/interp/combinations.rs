//! Affine and convex combinations (Denisjuk, Definition 2 and Theorem 3) and homogeneous
//! coordinates.
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::{
    AffineCombination, ConvexCombination, Homogeneous3, InterpError, barycentric_3d,
};
use barytex_testkit::strategies::{affine_weights3, convex_weights3, vec3_in};
use glam::{Mat3, Vec3};
use proptest::prelude::*;

fn affine_map() -> impl Strategy<Value = (Mat3, Vec3)> {
    (
        proptest::array::uniform9(-2.0f32..2.0),
        vec3_in(-10.0, 10.0),
    )
        .prop_map(|(m, t)| (Mat3::from_cols_array(&m), t))
}

proptest! {
    /// Theorem 3: an affine map A preserves affine combinations, A(Σαᵢxᵢ) = Σαᵢ A(xᵢ).
    #[test]
    fn affine_maps_preserve_affine_combinations(
        (m, t) in affine_map(),
        w in affine_weights3(),
        pts in [vec3_in(-10.0, 10.0), vec3_in(-10.0, 10.0), vec3_in(-10.0, 10.0)],
    ) {
        let c = AffineCombination::new(w).unwrap();
        let a = |p: Vec3| (m.as_dmat3() * p.as_dvec3() + t.as_dvec3()).as_vec3();
        let lhs = a(c.apply(pts));
        let rhs = c.apply(pts.map(a));
        let scale = 1.0 + pts.iter().map(|p| p.abs().max_element()).fold(0.0, f32::max) * 6.0;
        prop_assert!((lhs - rhs).abs().max_element() <= 1e-4 * scale * (1.0 + m.abs().to_cols_array().iter().sum::<f32>()), "{lhs:?} vs {rhs:?}");
    }

    /// Convex combinations of three points lie in their triangle (barycentric weights ≥ 0).
    #[test]
    fn convex_combinations_stay_in_the_triangle(
        w in convex_weights3(),
        pts in [vec3_in(-10.0, 10.0), vec3_in(-10.0, 10.0), vec3_in(-10.0, 10.0)],
    ) {
        let c = ConvexCombination::new(w).unwrap();
        let p = c.apply(pts);
        if let Ok(b) = barycentric_3d(p, pts) {
            let n = (pts[1] - pts[0]).cross(pts[2] - pts[0]).length();
            let e = (pts[1] - pts[0]).length().max((pts[2] - pts[0]).length()).max((pts[2] - pts[1]).length());
            let slack = 1e-5 * (1.0 + 20.0 * e * e / n.max(1e-30));
            prop_assert!(b.weights.iter().all(|&x| x >= -slack), "{b:?}");
        }
    }

    /// Buss 2003, ch. IV: convex combinations of homogeneous coordinates (x : w), w > 0, are homogeneous
    /// coordinates of a point of the convex hull — the segment here, with the weights
    /// αᵢwᵢ/Σαⱼwⱼ.
    #[test]
    fn convex_combinations_of_homogeneous_points(
        a in vec3_in(-10.0, 10.0), b in vec3_in(-10.0, 10.0),
        wa in 0.1f32..10.0, wb in 0.1f32..10.0, t in 0.0f32..=1.0,
    ) {
        let ha = Homogeneous3::new(a * wa, wa);
        let hb = Homogeneous3::new(b * wb, wb);
        let mix = ConvexCombination::new([1.0 - t, t]).unwrap_or_else(|_| ConvexCombination::normalized([1.0 - t, t]).unwrap());
        let p = mix.apply([ha, hb]).to_point().unwrap();
        let s = (t * wb) / ((1.0 - t) * wa + t * wb);
        let want = a.as_dvec3() + (b.as_dvec3() - a.as_dvec3()) * f64::from(s);
        prop_assert!((p.as_dvec3() - want).abs().max_element() <= 1e-5 * (1.0 + want.abs().max_element()));
        prop_assert!((-1e-6..=1.0 + 1e-6).contains(&s));
    }
}

#[test]
fn checked_weights_reject_what_they_must() {
    assert_eq!(
        AffineCombination::new([0.5, 0.6]),
        Err(InterpError::WeightsDoNotSumToOne {
            sum: f64::from(0.5f32) + f64::from(0.6f32)
        })
    );
    assert!(matches!(
        AffineCombination::new([f32::NAN, 1.0]),
        Err(InterpError::NonFinite { .. })
    ));
    assert!(AffineCombination::new([2.0, -1.0]).is_ok());
    assert_eq!(
        ConvexCombination::new([1.5, -0.5]),
        Err(InterpError::NegativeWeight {
            index: 1,
            weight: -0.5
        })
    );
    assert!(ConvexCombination::new([-0.0, 1.0]).is_ok());
    assert!(ConvexCombination::new([0.1, 0.2, 0.7]).is_ok());
    assert!(AffineCombination::<0>::new([]).is_err());
    assert!(matches!(
        AffineCombination::normalized([0.0, 0.0]),
        Err(InterpError::WeightsDoNotSumToOne { .. })
    ));
    let n = ConvexCombination::normalized([1.0, 3.0]).unwrap();
    assert_eq!(n.weights(), [0.25, 0.75]);
    assert_eq!(n.to_affine().weights(), [0.25, 0.75]);
    assert!(matches!(
        ConvexCombination::normalized([1.0, -3.0]),
        Err(InterpError::NegativeWeight { .. })
    ));
}

#[test]
fn homogeneous_points_at_infinity() {
    assert_eq!(Homogeneous3::new(Vec3::X, 0.0).to_point(), None);
    assert_eq!(Homogeneous3::new(Vec3::X, f32::NAN).to_point(), None);
    assert_eq!(Homogeneous3::new(Vec3::splat(1e30), 1e-30).to_point(), None);
    let v = glam::Vec4::new(2.0, 4.0, 6.0, 2.0);
    assert_eq!(
        Homogeneous3::from_vec4(v).to_point(),
        Some(Vec3::new(1.0, 2.0, 3.0))
    );
    assert_eq!(Homogeneous3::from_vec4(v).to_vec4(), v);
}

/// Review finding: a sum that cancels to a tiny value made `normalized` overflow to infinity.
#[test]
fn normalized_rejects_overflowing_quotients() {
    assert!(matches!(
        AffineCombination::normalized([3e38, -3e38, 1e-45]),
        Err(InterpError::NonFinite { .. })
    ));
}
