//! Perspective-correct (hyperbolic) interpolation: against the exact formula, exactly affine for
//! equal w, and equal to interpolating in 3D and projecting (Buss, *3D Computer Graphics*, 2003, §IV.5; Heckbert and Moreton, "Interpolation for
//! polygon texture mapping and shading", 1991).
#![allow(clippy::unwrap_used, missing_docs)]

use barytex_interp::{
    InterpError, barycentric_2d, perspective_correct_weights, perspective_interpolate,
};
use barytex_testkit::exact;
use barytex_testkit::strategies::{affine_weights3, convex_weights3, vec3_in};
use barytex_testkit::ulp::ulps_between_f32;
use glam::{Vec2, Vec3};
use proptest::prelude::*;

proptest! {
    /// The documented accuracy: within 1 ulp of the exact formula for convex screen weights.
    #[test]
    fn perspective_weights_within_ulps(a in convex_weights3(), w in proptest::array::uniform3(1e-3f32..1e4)) {
        let got = perspective_correct_weights(a, w).unwrap();
        let want = exact::perspective_weights(&a, &w).unwrap();
        for (g, e) in got.iter().zip(&want) {
            let nearest = exact::to_f64(e) as f32;
            prop_assert!(ulps_between_f32(*g, nearest) <= 1, "{g} vs {nearest}");
        }
    }

    /// With extrapolated (affine) weights the bound adds the cancellation term.
    #[test]
    fn perspective_weights_extrapolated(a in affine_weights3(), w in proptest::array::uniform3(0.1f32..100.0)) {
        let Ok(got) = perspective_correct_weights(a, w) else { return Ok(()); };
        let want = exact::perspective_weights(&a, &w).unwrap();
        let q: Vec<f64> = a.iter().zip(&w).map(|(&ai, &wi)| f64::from(ai) / f64::from(wi)).collect();
        let cond = q.iter().map(|x| x.abs()).sum::<f64>() / q.iter().sum::<f64>().abs();
        for (g, e) in got.iter().zip(&want) {
            let e64 = exact::to_f64(e);
            let bound = barytex_testkit::ulp::ulp_f32(e64) + 2f64.powi(-50) * cond * (1.0 + e64.abs());
            prop_assert!((f64::from(*g) - e64).abs() <= bound);
        }
    }

    /// All w equal: the projection is affine, and weights that sum to exactly 1 come back bit for
    /// bit (dyadic weights k/1024 do); others are only normalised.
    #[test]
    fn equal_w_is_exactly_affine(k in (-2048i32..2048, -2048i32..2048), w in 1e-3f32..1e4, other in affine_weights3()) {
        let a = [k.0 as f32 / 1024.0, k.1 as f32 / 1024.0, (1024 - k.0 - k.1) as f32 / 1024.0];
        prop_assert_eq!(perspective_correct_weights(a, [w; 3]), Ok(a));
        let v = [Vec3::X, Vec3::Y, Vec3::Z];
        prop_assert_eq!(perspective_interpolate(v, a, [w; 3]).ok(), barytex_interp::Interpolate::combine(v.into_iter().zip(a)));
        let sum: f64 = other.iter().map(|&x| f64::from(x)).sum();
        if let Ok(got) = perspective_correct_weights(other, [w; 3]) {
            for (g, o) in got.iter().zip(other) {
                let want = f64::from(o) / sum;
                prop_assert!((f64::from(*g) - want).abs() <= barytex_testkit::ulp::ulp_f32(want));
            }
        }
    }

    /// Hyperbolic interpolation equals interpolating in 3D and projecting: take a triangle in
    /// view space, project it, find a screen point's affine weights, correct them with w = depth,
    /// and compare with the 3D point on the triangle seen through that pixel (a ray cast).
    #[test]
    fn hyperbolic_equals_3d_then_project(
        verts in [vec3_in(-5.0, 5.0), vec3_in(-5.0, 5.0), vec3_in(-5.0, 5.0)],
        depths in proptest::array::uniform3(1.0f32..20.0),
        bary in convex_weights3(),
    ) {
        // View space: camera at the origin looking down +z; vertex i at depth zᵢ.
        let view = [0, 1, 2].map(|i| Vec3::new(verts[i].x, verts[i].y, depths[i]));
        let screen = view.map(|v| Vec2::new(v.x / v.z, v.y / v.z));
        // A 3D point on the triangle, its screen position, and the affine weights there.
        let p3 = view[0].as_dvec3() * f64::from(bary[0]) + view[1].as_dvec3() * f64::from(bary[1]) + view[2].as_dvec3() * f64::from(bary[2]);
        let ps = Vec2::new((p3.x / p3.z) as f32, (p3.y / p3.z) as f32);
        let Ok(affine) = barycentric_2d(ps, screen) else { return Ok(()); };
        let corrected = perspective_correct_weights(affine.weights, depths).unwrap();
        // Condition: how much screen-space rounding is amplified into weights.
        let area = (screen[1] - screen[0]).perp_dot(screen[2] - screen[0]).abs();
        prop_assume!(area > 1e-2);
        for (c, b) in corrected.iter().zip(bary) {
            prop_assert!((c - b).abs() <= 2e-4 / area.min(1.0), "{corrected:?} vs {bary:?}");
        }
        // Interpolating an attribute: u = x-coordinate in view space, recovered exactly.
        let u = perspective_interpolate(view.map(|v| v.x), affine.weights, depths).unwrap();
        prop_assert!((f64::from(u) - p3.x).abs() <= 1e-3 * (1.0 + p3.x.abs()) / f64::from(area.min(1.0)));
    }
}

#[test]
fn formula_on_a_line() {
    // Half-way on screen between depths 1 and 3 is a quarter of the way in 3D.
    assert_eq!(
        perspective_correct_weights([0.5, 0.5], [1.0, 3.0]),
        Ok([0.75, 0.25])
    );
    assert_eq!(
        perspective_interpolate([0.0f32, 1.0], [0.5, 0.5], [1.0, 3.0]),
        Ok(0.25)
    );
    // Endpoints stay endpoints.
    assert_eq!(
        perspective_correct_weights([1.0, 0.0, 0.0], [1.0, 2.0, 3.0]),
        Ok([1.0, 0.0, 0.0])
    );
}

#[test]
fn rejects_what_must_be_clipped_first() {
    assert_eq!(
        perspective_correct_weights([0.5, 0.5], [1.0, 0.0]),
        Err(InterpError::NonPositiveW { index: 1, w: 0.0 })
    );
    assert_eq!(
        perspective_correct_weights([0.5, 0.5], [1.0, -2.0]),
        Err(InterpError::NonPositiveW { index: 1, w: -2.0 })
    );
    assert_eq!(
        perspective_correct_weights([0.5, f32::NAN], [1.0, 2.0]),
        Err(InterpError::NonFinite { what: "screen" })
    );
    assert_eq!(
        perspective_correct_weights([0.5, 0.5], [1.0, f32::INFINITY]),
        Err(InterpError::NonFinite { what: "w" })
    );
    assert_eq!(
        perspective_correct_weights([1.0, -1.0], [2.0, 2.0]),
        Err(InterpError::AtInfinity)
    );
    assert_eq!(
        perspective_correct_weights([2.0, -1.0], [2.0, 1.0]),
        Err(InterpError::AtInfinity)
    );
    assert_eq!(
        perspective_interpolate([1.0f32, 2.0], [2.0, -1.0], [2.0, 1.0]),
        Err(InterpError::AtInfinity)
    );
    assert_eq!(
        perspective_correct_weights::<0>([], []),
        Err(InterpError::AtInfinity)
    );
}

/// Review finding: equal w took a fast path even for weights that do not sum to 1.
#[test]
fn equal_w_fast_path_only_for_unit_sums() {
    assert_eq!(
        perspective_correct_weights([0.0, 0.0], [1.0, 1.0]),
        Err(InterpError::AtInfinity)
    );
    let w = perspective_correct_weights([0.5, 0.6], [2.0, 2.0]).unwrap();
    assert!(
        (f64::from(w[0]) + f64::from(w[1]) - 1.0).abs() < 1e-7,
        "{w:?}"
    );
}
