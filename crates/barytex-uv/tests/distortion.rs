//! Distortion: singular values against matrices of known SVD, a known affine map on a triangle
//! in any orientation, the plane's exact 1, and the sphere's two latitude mappings (equal-area
//! ≈ 1, equirectangular growing toward the poles and matching its closed-form mean).

use barytex_uv::distortion::{
    MeshDistortion, area_distortion, singular_values, triangle_distortion,
};
use barytex_uv::mesh::{self, SphereUv};
use glam::{DMat2, DQuat, DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;

fn svd_matrix(alpha: f64, beta: f64, s1: f64, s2: f64) -> DMat2 {
    DMat2::from_angle(alpha) * DMat2::from_diagonal(DVec2::new(s1, s2)) * DMat2::from_angle(beta)
}

proptest! {
    #[test]
    fn singular_values_match_their_construction(
        alpha in 0.0..std::f64::consts::TAU,
        beta in 0.0..std::f64::consts::TAU,
        s1 in 1e-3_f64..1e3,
        k in 0.0_f64..=1.0,
        mirror in any::<bool>(),
    ) {
        let s2 = s1 * k;
        let mut m = svd_matrix(alpha, beta, s1, s2);
        if mirror {
            m.x_axis = -m.x_axis;
        }
        let (a, b) = singular_values(m);
        prop_assert!(a >= b && b >= 0.0);
        prop_assert!((a - s1).abs() <= 1e-13 * s1, "σ1 {a} vs {s1}");
        prop_assert!((b - s2).abs() <= 1e-13 * s1, "σ2 {b} vs {s2}");
    }

    #[test]
    fn triangle_singular_values_of_a_known_affine_map(
        alpha in 0.0..std::f64::consts::TAU,
        beta in 0.0..std::f64::consts::TAU,
        s1 in 0.1_f64..10.0,
        k in 0.05_f64..=1.0,
        axis in prop::array::uniform3(-1.0_f64..1.0),
        angle in 0.0..std::f64::consts::PI,
        offset in prop::array::uniform3(-10.0_f64..10.0),
        scale in 0.01_f64..100.0,
    ) {
        let s2 = s1 * k;
        let m = svd_matrix(alpha, beta, s1, s2);
        // A well-shaped triangle (angles ≥ 20°) in any orientation, within 10 edge lengths of the
        // origin.
        let local = [DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(0.35, 0.9)].map(|q| q * scale);
        let axis = DVec3::from(axis).try_normalize().unwrap_or(DVec3::Z);
        let rotation = DQuat::from_axis_angle(axis, angle);
        let p = local.map(|q| (rotation * q.extend(0.0) + DVec3::from(offset) * scale).as_vec3());
        let uv = local.map(|q| (m * q / scale + DVec2::splat(0.5)).as_vec2());
        let d = triangle_distortion(p, uv).expect("non-degenerate");
        let (e1, e2) = (d.sigma_max * scale, d.sigma_min * scale);
        prop_assert!((e1 - s1).abs() <= 1e-5 * s1, "σ1 {e1} vs {s1}");
        prop_assert!((e2 - s2).abs() <= 1e-5 * s1, "σ2 {e2} vs {s2}");
    }

    /// Non-finite or degenerate input gives None, never a panic.
    #[test]
    fn triangle_distortion_is_total(bits in prop::array::uniform15(any::<u32>())) {
        let f = |i: usize| f32::from_bits(bits[i]);
        let p = [Vec3::new(f(0), f(1), f(2)), Vec3::new(f(3), f(4), f(5)), Vec3::new(f(6), f(7), f(8))];
        let uv = [Vec2::new(f(9), f(10)), Vec2::new(f(11), f(12)), Vec2::new(f(13), f(14))];
        if let Some(d) = triangle_distortion(p, uv) {
            prop_assert!(d.sigma_max.is_finite() && d.sigma_min >= 0.0 && d.sigma_min <= d.sigma_max);
        }
    }
}

#[test]
fn degenerate_triangles_are_refused() {
    let uv = [Vec2::ZERO, Vec2::X, Vec2::Y];
    assert_eq!(
        triangle_distortion([Vec3::ZERO, Vec3::X, Vec3::X * 2.0], uv),
        None
    );
    assert_eq!(triangle_distortion([Vec3::ZERO; 3], uv), None);
    assert_eq!(triangle_distortion([Vec3::NAN, Vec3::X, Vec3::Y], uv), None);
    // A degenerate uv triangle is measurable: infinite angle distortion, zero area.
    let d = triangle_distortion([Vec3::ZERO, Vec3::X, Vec3::Y], [Vec2::ZERO; 3]).expect("measured");
    assert_eq!(d.angle(), f64::INFINITY);
    assert_eq!(area_distortion(d.area_ratio(), 1.0), f64::INFINITY);
}

#[test]
fn the_plane_has_no_distortion() {
    for (nu, nv) in [(1, 1), (3, 7), (32, 32)] {
        let d = MeshDistortion::of(&mesh::plane(nu, nv).expect("valid")).expect("measurable");
        for value in [d.angle_mean, d.angle_max, d.area_mean, d.area_max] {
            assert!((value - 1.0).abs() < 1e-6, "{nu}×{nv}: {d:?}");
        }
        assert!((d.mean_area_ratio - 0.25).abs() < 1e-6);
        assert_eq!(d.skipped, 0);
    }
}

#[test]
fn the_cube_atlas_has_no_distortion() {
    // Square cells of side 1/3 for faces of side 2: every triangle is scaled by 1/6.
    for n in [1, 4, 9] {
        let d = MeshDistortion::of(&mesh::cube(n).expect("valid")).expect("measurable");
        for value in [d.angle_max, d.area_max] {
            assert!((value - 1.0).abs() < 1e-5, "cube({n}): {d:?}");
        }
        assert!(
            (d.mean_area_ratio - 1.0 / 36.0).abs() < 1e-7,
            "cube({n}): {d:?}"
        );
    }
}

/// The equirectangular sphere's area-weighted mean area distortion in closed form: the area
/// ratio at latitude φ is `ρ = 2/(π cos φ)` of the mean, so the mean of `max(ρ, 1/ρ)` is
/// `∫₀^φ₀ (π/2) cos²φ dφ + (π/2 − φ₀)·2/π` with `cos φ₀ = 2/π`.
fn equirectangular_area_mean() -> f64 {
    use std::f64::consts::{FRAC_PI_2, PI};
    let phi0 = (2.0 / PI).acos();
    FRAC_PI_2 * (phi0 / 2.0 + (2.0 * phi0).sin() / 4.0) + (FRAC_PI_2 - phi0) * 2.0 / PI
}

#[test]
fn equal_area_sphere_beats_equirectangular() {
    let expected = equirectangular_area_mean();
    for (segments, rings) in [(64, 32), (256, 128)] {
        let of = |uv| {
            MeshDistortion::of(&mesh::sphere_with(segments, rings, uv).expect("valid"))
                .expect("measurable")
        };
        let (equirectangular, equal_area) =
            (of(SphereUv::Equirectangular), of(SphereUv::EqualArea));
        println!(
            "sphere {segments}×{rings}: area distortion mean/max equirectangular {:.4}/{:.2}, \
             equal-area {:.4}/{:.2} (closed form {expected:.4}); angle mean equirectangular \
             {:.3}, equal-area {:.3}; equirectangular has {:.1}× more excess area distortion",
            equirectangular.area_mean,
            equirectangular.area_max,
            equal_area.area_mean,
            equal_area.area_max,
            equirectangular.angle_mean,
            equal_area.angle_mean,
            equirectangular.area_excess_ratio(&equal_area),
        );
        // Both meshes differ from their mappings by the flat triangles' discretization, measured
        // ≈ 1.6/rings (the two halves of a trapezoidal quad share its uv area equally but not its
        // surface area; the pole fans get half their quads' uv area).
        let discretization = 2.0 / f64::from(rings);
        assert!(
            equal_area.area_mean - 1.0 < discretization,
            "{equal_area:?}"
        );
        assert!(
            (equirectangular.area_mean - expected).abs() < discretization,
            "{equirectangular:?}"
        );
        assert!(equirectangular.area_excess_ratio(&equal_area) > 5.0);
        // Equirectangular stretches toward the poles: its worst triangle is far worse.
        assert!(equirectangular.area_max > 3.0 * equal_area.area_max);
    }
}

#[test]
fn equirectangular_area_distortion_grows_toward_the_poles() {
    let sphere = mesh::sphere(64, 32).expect("valid");
    let mean = MeshDistortion::of(&sphere)
        .expect("measurable")
        .mean_area_ratio;
    // Mean area distortion per band of latitude, equator to pole (northern hemisphere).
    let mut bands = vec![(0.0, 0.0); 16];
    for &corners in &sphere.indices {
        let p = corners.map(|i| sphere.positions[i as usize]);
        let uv = corners.map(|i| sphere.uvs[i as usize]);
        let centroid_y = (p[0].y + p[1].y + p[2].y) / 3.0;
        if centroid_y <= 0.0 {
            continue;
        }
        let d = triangle_distortion(p, uv).expect("non-degenerate");
        let band = ((f64::from(centroid_y).asin() / std::f64::consts::FRAC_PI_2) * 16.0) as usize;
        let entry = &mut bands[band.min(15)];
        entry.0 += area_distortion(d.area_ratio(), mean) * d.area_3d;
        entry.1 += d.area_3d;
    }
    let means: Vec<f64> = bands
        .iter()
        .filter(|b| b.1 > 0.0)
        .map(|b| b.0 / b.1)
        .collect();
    // Past the crossover (cos φ = 2/π, about 50°) it rises monotonically.
    let past = &means[means.len() / 2..];
    assert!(past.windows(2).all(|w| w[1] > w[0]), "{means:?}");
    assert!(past[past.len() - 1] > 5.0 * past[0].min(2.0), "{means:?}");
}
