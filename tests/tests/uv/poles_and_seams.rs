//! The mappings at and next to their singular sets, where `mappings.rs` (regular points only)
//! does not look: `uv → point → uv` round trips on every row and column of uv including the
//! seams (`u = 0`, `u → 1`) and the poles (`v = 0`, `v = 1`), and the analytic Jacobian against
//! central differences whose step shrinks with the distance to the pole axis or the core circle
//! (so the finite differences stay meaningful there), at distances 1e-1 … 1e-12 and across the
//! seam.

use barytex_uv::PositionMapping;
use barytex_uv::mappings::{
    Cylindrical, InverseUvMapping, SphereProjection, Spherical, Torus, UvMapping64,
};
use glam::{DVec2, DVec3, Vec2, Vec3};

/// The documented round-trip bound (`ROUND_TRIP_BOUND` of `mappings.rs`): here in the surface's
/// own terms (see [`round_trips_on_every_row_and_column`]).
const ROUND_TRIP_BOUND: f64 = 1e-6;
/// The documented Jacobian bound (`FD_BOUND` of `mappings.rs`).
const FD_BOUND: f64 = 1e-7;

/// Distance between two values of a periodic coordinate (period 1).
fn wrapped(d: f64) -> f64 {
    let d = d.rem_euclid(1.0);
    d.min(1.0 - d)
}

/// Parameters on and next to 0 and 1 (and the middle): the seams and poles; plus 40 seeded
/// values within 1e-3 of 0 or 1.
fn edges() -> Vec<f32> {
    let mut rng = barytex_testkit::seeded::XorShift::new(0x5ea3);
    let near: Vec<f32> = (0..40)
        .map(|i| {
            let d = rng.f32_in(0.0, 1e-3);
            if i % 2 == 0 { d } else { 1.0 - d }
        })
        .collect();
    let mut out = vec![
        0.0,
        f32::from_bits(1),
        1e-7,
        1e-5,
        1e-3,
        0.25,
        0.5,
        1.0 - 1e-3,
        1.0 - 1e-5,
        1.0 - 1.2e-7,
        f32::from_bits(1f32.to_bits() - 1),
        1.0,
    ];
    out.extend(near);
    out
}

/// `cos φ` at `v` for the sphere's projection: the length of a turn of `u` on the unit sphere.
fn cos_latitude(projection: SphereProjection, v: f64) -> f64 {
    match projection {
        SphereProjection::Equirectangular => ((0.5 - v) * core::f64::consts::PI).cos(),
        SphereProjection::EqualArea => 2.0 * (v * (1.0 - v)).max(0.0).sqrt(),
    }
}

/// `uv → point → uv` on the grid of [`edges`] × [`edges`]. A periodic coordinate is compared
/// modulo 1 (across the seam); on the sphere an error in `u` is weighted by `cos φ`, the length
/// of a turn at that latitude (at a pole `u` is no position at all, and `uv` may be `None` when
/// the point lands on the axis). Bound: `ROUND_TRIP_BOUND` in `v` and in weighted `u`.
#[test]
fn round_trips_on_every_row_and_column() {
    let mut report = String::new();
    for projection in [
        SphereProjection::Equirectangular,
        SphereProjection::EqualArea,
    ] {
        let s = Spherical::new(2.0, projection).expect("valid");
        let mut worst = (0.0f64, 0.0f64);
        for u in edges() {
            for v in edges() {
                let p = s.point_at(Vec2::new(u, v)).expect("v in [0, 1]");
                let Some(back) = s.uv(p, p) else {
                    assert!(
                        p.x == 0.0 && p.z == 0.0,
                        "{projection:?} ({u}, {v}) → {p:?}"
                    );
                    continue;
                };
                let du = wrapped(f64::from(back.x) - f64::from(u))
                    * cos_latitude(projection, f64::from(v));
                let dv = (f64::from(back.y) - f64::from(v)).abs();
                assert!(
                    du <= ROUND_TRIP_BOUND && dv <= ROUND_TRIP_BOUND,
                    "{projection:?} ({u}, {v}) → {p:?} → {back:?}: {du:e} {dv:e}"
                );
                worst = (worst.0.max(du), worst.1.max(dv));
            }
        }
        report += &format!(
            "sphere {projection:?}: u·cos φ {:.2e}, v {:.2e}\n",
            worst.0, worst.1
        );
    }
    let cylinder = Cylindrical::new(1.5, 4.0).expect("valid");
    let torus = Torus::new(2.0, 0.5).expect("valid");
    let mut worst_cylinder = (0.0f64, 0.0f64);
    let mut worst_torus = (0.0f64, 0.0f64);
    for u in edges() {
        for v in edges() {
            let uv = Vec2::new(u, v);
            let p = cylinder.point_at(uv).expect("finite");
            let back = cylinder
                .uv(p, Vec3::new(p.x, 0.0, p.z))
                .expect("side point");
            let du = wrapped(f64::from(back.x) - f64::from(u));
            let dv = (f64::from(back.y) - f64::from(v)).abs();
            assert!(
                du <= ROUND_TRIP_BOUND && dv <= ROUND_TRIP_BOUND,
                "cylinder {uv:?} → {back:?}"
            );
            worst_cylinder = (worst_cylinder.0.max(du), worst_cylinder.1.max(dv));
            let p = torus.point_at(uv).expect("finite");
            let back = torus.uv(p, Vec3::Y).expect("off the core circle");
            let du = wrapped(f64::from(back.x) - f64::from(u));
            let dv = wrapped(f64::from(back.y) - f64::from(v));
            assert!(
                du <= ROUND_TRIP_BOUND && dv <= ROUND_TRIP_BOUND,
                "torus {uv:?} → {back:?}"
            );
            worst_torus = (worst_torus.0.max(du), worst_torus.1.max(dv));
        }
    }
    report += &format!(
        "cylinder: u {:.2e}, v {:.2e}\ntorus: u {:.2e}, v {:.2e}\n",
        worst_cylinder.0, worst_cylinder.1, worst_torus.0, worst_torus.1
    );
    println!("{report}");
}

/// `|J − J_fd| / |J|` (Frobenius) with central differences of step `h`, uv differences wrapped
/// to the nearest whole turn (a step across a seam). `v_periodic` wraps `v` too; `with_v` false
/// compares `∇u` only.
fn fd_relative_error(m: &dyn UvMapping64, p: DVec3, n: DVec3, h: f64, with_v: bool) -> f64 {
    let j = m.uv_and_jacobian_f64(p, n).expect("regular point");
    let mut err2 = 0.0;
    for (axis, e) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
        let plus = m.uv_and_jacobian_f64(p + h * e, n).expect("regular").uv;
        let minus = m.uv_and_jacobian_f64(p - h * e, n).expect("regular").uv;
        let mut d = plus - minus;
        d -= d.round();
        let fd = d / (2.0 * h);
        let exact = DVec2::new(j.du[axis], j.dv[axis]);
        let diff = fd - exact;
        err2 += diff.x * diff.x + if with_v { diff.y * diff.y } else { 0.0 };
    }
    let norm2 = j.du.length_squared() + if with_v { j.dv.length_squared() } else { 0.0 };
    (err2 / norm2).sqrt()
}

/// The Jacobian at distances `ρ = 10⁻¹ … 10⁻¹²` from the pole axis (sphere, cylinder, torus) and
/// `10⁻¹ … 10⁻³` from the torus's core circle, on the seam and 1e-9 rad either side of it, with steps
/// `h = 10⁻⁵·ρ`. Near the north pole the whole Jacobian is compared; near the south pole `v`
/// is within an f64 ulp of 1, too coarse for differences at that step, so `∇u` is compared there
/// and `∇v` checked against the exact mirror symmetry `y → −y` of its formula.
#[test]
fn jacobians_next_to_poles_and_seams() {
    let mut report = String::new();
    let seam_angles = [
        core::f64::consts::PI,
        core::f64::consts::PI - 1e-9,
        -core::f64::consts::PI + 1e-9,
        0.3,
    ];
    for projection in [
        SphereProjection::Equirectangular,
        SphereProjection::EqualArea,
    ] {
        let s = Spherical::new(2.0, projection).expect("valid");
        let mut worst = 0.0f64;
        for k in 1..=12 {
            let rho = 10f64.powi(-k);
            for angle in seam_angles {
                let (sa, ca) = angle.sin_cos();
                let y = (4.0 - rho * rho).sqrt();
                let north = DVec3::new(rho * sa, y, rho * ca);
                let south = DVec3::new(rho * sa, -y, rho * ca);
                let h = 1e-5 * rho;
                let e = fd_relative_error(&s, north, north, h, true)
                    .max(fd_relative_error(&s, south, south, h, false));
                assert!(
                    e <= FD_BOUND,
                    "{projection:?} ρ {rho:e} angle {angle}: {e:e}"
                );
                worst = worst.max(e);
                let jn = s.uv_and_jacobian_f64(north, north).expect("regular");
                let js = s.uv_and_jacobian_f64(south, south).expect("regular");
                assert_eq!(
                    (js.dv.x, js.dv.y, js.dv.z),
                    (-jn.dv.x, jn.dv.y, -jn.dv.z),
                    "{projection:?}: ∇v mirrors under y → −y"
                );
            }
        }
        report += &format!("sphere {projection:?} next to the poles and the seam: {worst:.2e}\n");
    }
    let cylinder = Cylindrical::new(1.5, 4.0).expect("valid");
    let torus = Torus::new(2.0, 0.5).expect("valid");
    let (mut worst_cylinder, mut worst_torus) = (0.0f64, 0.0f64);
    for k in 1..=12 {
        let rho = 10f64.powi(-k);
        for angle in seam_angles {
            let (sa, ca) = angle.sin_cos();
            // The cylinder next to its axis and on its seam.
            let p = DVec3::new(rho * sa, 0.7, rho * ca);
            let e = fd_relative_error(&cylinder, p, DVec3::new(p.x, 0.0, p.z), 1e-5 * rho, true);
            assert!(e <= FD_BOUND, "cylinder ρ {rho:e} angle {angle}: {e:e}");
            worst_cylinder = worst_cylinder.max(e);
            // The torus next to its axis (u) …
            let p = DVec3::new(rho * sa, 0.3, rho * ca);
            let e = fd_relative_error(&torus, p, DVec3::Y, 1e-5 * rho, true);
            assert!(e <= FD_BOUND, "torus axis ρ {rho:e} angle {angle}: {e:e}");
            worst_torus = worst_torus.max(e);
            // … and next to its core circle (v), on the v seam (the outer equator, y → 0⁻), down
            // to d = 1e-3: closer in, `√(x² + z²) − R` carries the rounding of the square root
            // (2⁻⁵³·R absolute), so the f64 Jacobian itself is only good to about 2⁻⁵²·R/d
            // relative, and so are the finite differences (see the mapping's Accuracy).
            if k <= 3 {
                let (sv, cv) = angle.sin_cos();
                let ring = 2.0 + rho * cv;
                let p = DVec3::new(ring * 0.6, rho * sv, ring * 0.8);
                let e = fd_relative_error(&torus, p, DVec3::Y, 1e-5 * rho, true);
                assert!(e <= FD_BOUND, "torus core d {rho:e} angle {angle}: {e:e}");
                worst_torus = worst_torus.max(e);
            }
        }
    }
    report += &format!(
        "cylinder next to the axis and the seam: {worst_cylinder:.2e}\ntorus next to the axis, the core circle and both seams: {worst_torus:.2e}\n"
    );
    println!("{report}");
}
