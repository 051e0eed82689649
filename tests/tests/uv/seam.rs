//! Seam repair: Figure V.4 of Buss, *3D Computer Graphics* (2003), the half-texture property (a
//! triangle that fits in half a turn never spans more than half the texture after repair),
//! whole-turn shifts only, and pole handling on the sphere.

use barytex_testkit::strategies::bits_f32;
use barytex_uv::PositionMapping;
use barytex_uv::mappings::{InverseUvMapping, SphereProjection, Spherical};
use barytex_uv::seam::{repair_seam, repair_sphere_triangle};
use glam::{Vec2, Vec3};
use proptest::prelude::*;

fn u_span(t: [Vec2; 3]) -> f32 {
    let us = t.map(|p| p.x);
    us.iter().copied().fold(f32::NEG_INFINITY, f32::max)
        - us.iter().copied().fold(f32::INFINITY, f32::min)
}

/// Buss (2003), Figure V.4: a quad whose `s` runs 0.9 → 0.1 across the seam; both of its triangles
/// must run 0.9 → 1.1, not back across the texture.
#[test]
fn buss_figure_v4() {
    let (a, b, c, d) = (
        Vec2::new(0.9, 0.3),
        Vec2::new(0.1, 0.3),
        Vec2::new(0.1, 0.6),
        Vec2::new(0.9, 0.6),
    );
    for tri in [[a, b, c], [a, c, d], [b, c, d], [c, d, a]] {
        let fixed = repair_seam(tri);
        for (before, after) in tri.iter().zip(fixed) {
            let expected = if before.x == 0.1 { 1.1 } else { 0.9 };
            assert_eq!(after, Vec2::new(expected, before.y), "{tri:?} → {fixed:?}");
        }
        assert!(u_span(fixed) < 0.2 + 1e-6);
    }
}

/// The same, built from the cylinder mapping: a quad straddling θ = π.
#[test]
fn figure_v4_from_a_sphere_mapping() {
    let s = Spherical::new(1.0, SphereProjection::Equirectangular).expect("valid");
    let corner = |u: f32, v: f32| {
        let p = s.point_at(Vec2::new(u, v)).expect("in range");
        s.uv(p, p).expect("regular")
    };
    let tri = [corner(0.95, 0.4), corner(0.05, 0.4), corner(0.05, 0.5)];
    assert!(
        u_span(tri) > 0.8,
        "the raw triangle straddles the seam: {tri:?}"
    );
    let fixed = repair_seam(tri);
    assert!(u_span(fixed) < 0.1 + 1e-5, "{fixed:?}");
    assert!(fixed[1].x > 1.0 && fixed[0].x < 1.0);
}

#[test]
fn unchanged_when_not_straddling_or_not_finite() {
    let t = [
        Vec2::new(0.2, 0.0),
        Vec2::new(0.6, 1.0),
        Vec2::new(0.4, 0.5),
    ];
    assert_eq!(repair_seam(t), t);
    let nan = [
        Vec2::new(f32::NAN, 0.0),
        Vec2::new(0.9, 0.0),
        Vec2::new(0.1, 0.0),
    ];
    assert_eq!(
        repair_seam(nan).map(|p| p.x.to_bits()),
        nan.map(|p| p.x.to_bits())
    );
    // Spread over the circle: the given range 0.6 is already the shortest arc.
    let spread = [
        Vec2::new(0.0, 0.0),
        Vec2::new(0.3, 0.0),
        Vec2::new(0.6, 0.0),
    ];
    assert_eq!(repair_seam(spread), spread);
}

#[test]
fn pole_vertex_takes_the_mean_u() {
    // A cap triangle across the seam: the pole vertex lies between the other two.
    let t = [
        Vec2::new(0.3, 0.0),
        Vec2::new(0.95, 0.1),
        Vec2::new(0.05, 0.1),
    ];
    let fixed = repair_sphere_triangle(t);
    assert!((fixed[0].x - 1.0).abs() < 1e-6, "{fixed:?}");
    assert!((fixed[2].x - 1.05).abs() < 1e-6, "{fixed:?}");
    assert!(u_span(fixed) <= 0.1 + 1e-6);
    // South pole, no seam.
    let t = [
        Vec2::new(0.2, 0.9),
        Vec2::new(0.8, 1.0),
        Vec2::new(0.3, 0.9),
    ];
    let fixed = repair_sphere_triangle(t);
    assert!(
        (fixed[1].x - 0.25).abs() < 1e-6 && fixed[1].y == 1.0,
        "{fixed:?}"
    );
    // Two pole vertices take the third's u; no pole is plain seam repair.
    let t = [
        Vec2::new(0.2, 0.0),
        Vec2::new(0.8, 1.0),
        Vec2::new(0.6, 0.5),
    ];
    assert_eq!(repair_sphere_triangle(t).map(|p| p.x), [0.6; 3]);
    let t = [
        Vec2::new(0.9, 0.3),
        Vec2::new(0.1, 0.3),
        Vec2::new(0.1, 0.6),
    ];
    assert_eq!(repair_sphere_triangle(t), repair_seam(t));
}

fn wrapped(u: f32) -> f32 {
    u.rem_euclid(1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(5_000))]

    /// A triangle that fits in half a turn, wrapped into [0, 1) at an arbitrary place: the
    /// repaired triangle spans at most half the texture, is the unwrapped triangle shifted by a
    /// whole turn, and keeps v.
    #[test]
    fn repaired_triangles_span_at_most_half(
        start in -3.0f32..3.0,
        offsets in [0.0f32..0.5, 0.0f32..0.5],
        vs in [0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0],
        order in 0usize..3,
    ) {
        let mut us = [start, start + offsets[0], start + offsets[1]];
        us.rotate_left(order);
        let raw: [Vec2; 3] = core::array::from_fn(|i| Vec2::new(wrapped(us[i]), vs[i]));
        let fixed = repair_seam(raw);
        prop_assert!(u_span(fixed) <= 0.5 + 1e-6, "{:?} → {:?}", raw, fixed);
        for i in 0..3 {
            prop_assert_eq!(fixed[i].y, raw[i].y);
            let turns = fixed[i].x - raw[i].x;
            prop_assert!((turns - turns.round()).abs() <= 1e-6, "{:?} → {:?}", raw, fixed);
            // Relative to the true (unwrapped) coordinates, one common shift.
            let shift = (fixed[i].x - us[i]) - (fixed[0].x - us[0]);
            prop_assert!(shift.abs() <= 1e-5, "{:?} → {:?}", raw, fixed);
        }
    }

    /// Any triangle: the u range never grows, shifts are whole turns, v is kept.
    #[test]
    fn repair_never_widens(us in [-4.0f32..4.0, -4.0f32..4.0, -4.0f32..4.0]) {
        let raw = us.map(|u| Vec2::new(u, 0.5));
        let fixed = repair_seam(raw);
        prop_assert!(u_span(fixed) <= u_span(raw) + 1e-6);
        prop_assert!(u_span(fixed) <= 2.0 / 3.0 + 1e-5, "{:?} → {:?}", raw, fixed);
        for i in 0..3 {
            let turns = fixed[i].x - raw[i].x;
            prop_assert!((turns - turns.round()).abs() <= 1e-5);
        }
    }

    /// Any bits: no panic; finite inputs give finite outputs.
    #[test]
    fn total_on_any_bits(bits in [bits_f32(), bits_f32(), bits_f32(), bits_f32(), bits_f32(), bits_f32()]) {
        let t = [Vec2::new(bits[0], bits[1]), Vec2::new(bits[2], bits[3]), Vec2::new(bits[4], bits[5])];
        for fixed in [repair_seam(t), repair_sphere_triangle(t)] {
            if t.iter().all(|p| p.is_finite()) {
                prop_assert!(fixed.iter().all(|p| p.is_finite()), "{:?} → {:?}", t, fixed);
            }
            for i in 0..3 {
                prop_assert_eq!(fixed[i].y.to_bits(), t[i].y.to_bits());
            }
        }
    }
}

#[test]
fn sphere_mesh_ring_repairs_cleanly() {
    // Every triangle of a 16 × 8 UV sphere, with uvs from the mapping (so the seam column gets
    // u ≈ 0.94 and 0): after repair none spans more than one column.
    let s = Spherical::new(1.0, SphereProjection::EqualArea).expect("valid");
    let (nu, nv) = (16, 8);
    let at = |i: usize, j: usize| {
        let theta = core::f32::consts::TAU * i as f32 / nu as f32 + 0.01;
        let phi = core::f32::consts::PI * (0.5 - j as f32 / nv as f32);
        // Pole vertices exactly on the axis (cos(π/2) is not 0 in f32), as a mesh builder
        // writes them: the mapping has no u there, the pole row is v = 0 or 1.
        let ring = if j == 0 || j == nv { 0.0 } else { phi.cos() };
        let p = Vec3::new(ring * theta.sin(), phi.sin(), ring * theta.cos());
        match s.uv(p, p) {
            Some(uv) => uv,
            None => Vec2::new(0.0, if j == 0 { 0.0 } else { 1.0 }),
        }
    };
    let mut worst = 0.0f32;
    for i in 0..nu {
        for j in 0..nv {
            for tri in [
                [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
            ] {
                worst = worst.max(u_span(repair_sphere_triangle(tri)));
            }
        }
    }
    assert!(worst <= 1.0 / nu as f32 + 1e-5, "{worst}");
}
