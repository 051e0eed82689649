//! The mapping laws, run for every mapping of `barytex_uv::mappings`: the analytic Jacobian
//! against central finite differences of the f64 evaluation (relative bound `FD_BOUND`) away from
//! seams and poles; `map` applies the chain rule; totality on any bits; `uv → point → uv` round
//! trips (bound `ROUND_TRIP_BOUND`) away from seams and poles. Plus each mapping's own
//! conventions (v down, poles, caps, faces) and the triplanar weights.

use core::f32::consts::{FRAC_PI_2, TAU};

use barytex_testkit::seeded::XorShift;
use barytex_testkit::strategies::{bits_f32, vec3_in};
use barytex_uv::mappings::{
    BoxFace, BoxMapping, CylinderCaps, Cylindrical, InverseUvMapping, Planar, SphereProjection,
    Spherical, Torus, UvMapping64, triplanar_weights,
};
use barytex_uv::{PositionMapping, SurfacePoint, UvError, UvMapping};
use glam::{DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;

/// Relative bound on `|J − J_fd| / |J|` (Frobenius), central differences with step 1e-5 in f64.
const FD_BOUND: f64 = 1e-7;
/// Bound on `|uv − uv(point_at(uv))|` (max norm) for the f32 round trip.
const ROUND_TRIP_BOUND: f32 = 1e-6;

trait Mapping: PositionMapping + UvMapping64 {}

/// A mapping, its inverse, and the surface normal at a point.
type Inverse = (
    &'static str,
    Box<dyn Mapping>,
    Box<dyn InverseUvMapping>,
    fn(Vec3) -> Vec3,
);
impl<T: PositionMapping + UvMapping64> Mapping for T {}

/// A named mapping and a sampler of regular points (away from axes, poles and singular sets)
/// with their normals.
struct Case {
    name: &'static str,
    mapping: Box<dyn Mapping>,
    sample: fn(&mut XorShift) -> (Vec3, Vec3),
}

fn radial(rng: &mut XorShift, rho: (f32, f32), y: (f32, f32)) -> Vec3 {
    let (s, c) = rng.f32_in(0.0, TAU).sin_cos();
    let r = rng.f32_in(rho.0, rho.1);
    Vec3::new(r * s, rng.f32_in(y.0, y.1), r * c)
}

fn sphere_point(rng: &mut XorShift) -> (Vec3, Vec3) {
    // Latitude within 80° keeps the poles (and their 1/ρ gradients) away.
    let lat = rng.f32_in(-1.4, 1.4);
    let (s, c) = rng.f32_in(0.0, TAU).sin_cos();
    let d = Vec3::new(lat.cos() * s, lat.sin(), lat.cos() * c);
    (d * rng.f32_in(0.3, 3.0), d)
}

fn cases() -> Vec<Case> {
    let planar = |o, u, v| Box::new(Planar::new(o, u, v).expect("valid frame"));
    vec![
        Case {
            name: "planar xz",
            mapping: Box::new(Planar::xz(2.0).expect("valid")),
            sample: |rng| (rng.vec3_in(-10.0, 10.0), Vec3::Y),
        },
        Case {
            name: "planar skew",
            mapping: planar(
                Vec3::new(1.0, -2.0, 0.5),
                Vec3::new(0.5, 0.25, 0.0),
                Vec3::new(0.3, -0.1, 2.0),
            ),
            sample: |rng| (rng.vec3_in(-10.0, 10.0), Vec3::Z),
        },
        Case {
            name: "box",
            mapping: Box::new(BoxMapping::new(Vec3::new(0.5, 0.0, -1.0), 3.0).expect("valid")),
            sample: |rng| (rng.vec3_in(-3.0, 3.0), rng.vec3_in(-1.0, 1.0)),
        },
        Case {
            name: "cylinder",
            mapping: Box::new(Cylindrical::new(1.5, 4.0).expect("valid")),
            sample: |rng| (radial(rng, (0.2, 3.0), (-3.0, 3.0)), Vec3::X),
        },
        Case {
            name: "cylinder with caps",
            mapping: Box::new(
                Cylindrical::new(1.5, 4.0)
                    .expect("valid")
                    .with_caps(CylinderCaps::Planar),
            ),
            sample: |rng| (radial(rng, (0.2, 3.0), (-3.0, 3.0)), rng.vec3_in(-1.0, 1.0)),
        },
        Case {
            name: "sphere equirectangular",
            mapping: Box::new(
                Spherical::new(2.0, SphereProjection::Equirectangular).expect("valid"),
            ),
            sample: sphere_point,
        },
        Case {
            name: "sphere equal-area",
            mapping: Box::new(Spherical::new(2.0, SphereProjection::EqualArea).expect("valid")),
            sample: sphere_point,
        },
        Case {
            name: "torus",
            mapping: Box::new(Torus::new(2.0, 0.5).expect("valid")),
            sample: |rng| {
                // Distance from the core circle in [0.1, 1.2]: off the core and the axis.
                let (sp, cp) = rng.f32_in(0.0, TAU).sin_cos();
                let d = rng.f32_in(0.1, 1.2);
                let (st, ct) = rng.f32_in(0.0, TAU).sin_cos();
                let ring = 2.0 + d * cp;
                (Vec3::new(ring * st, d * sp, ring * ct), Vec3::Y)
            },
        },
    ]
}

/// `|J − J_fd| / |J|` at `p` (Frobenius norms), differences wrapped to the nearest whole turn.
fn fd_relative_error(m: &dyn Mapping, p: DVec3, n: DVec3) -> f64 {
    let j = m.uv_and_jacobian_f64(p, n).expect("regular point");
    let h = 1e-5;
    let mut err2 = 0.0;
    for (axis, e) in [DVec3::X, DVec3::Y, DVec3::Z].into_iter().enumerate() {
        let plus = m.uv_and_jacobian_f64(p + h * e, n).expect("regular").uv;
        let minus = m.uv_and_jacobian_f64(p - h * e, n).expect("regular").uv;
        let mut d = plus - minus;
        d -= d.round(); // a step across a seam changes u by a whole turn
        let fd = d / (2.0 * h);
        let exact = DVec2::new(j.du[axis], j.dv[axis]);
        err2 += (fd - exact).length_squared();
    }
    let norm2 = j.du.length_squared() + j.dv.length_squared();
    (err2 / norm2).sqrt()
}

#[test]
fn jacobian_matches_finite_differences() {
    let mut rng = XorShift::new(0x7ac0);
    let mut report = String::new();
    for case in cases() {
        let mut worst = 0.0f64;
        for _ in 0..20_000 {
            let (p, n) = (case.sample)(&mut rng);
            let e = fd_relative_error(case.mapping.as_ref(), p.as_dvec3(), n.as_dvec3());
            assert!(
                e <= FD_BOUND,
                "{}: relative Jacobian error {e:e} at {p:?} (normal {n:?})",
                case.name
            );
            worst = worst.max(e);
        }
        report.push_str(&format!("{}: worst {worst:.2e}\n", case.name));
        // The bound is meaningful: the worst case is not zero (the mapping is non-linear) or the
        // mapping is affine (planar, box: exact up to rounding).
        assert!(worst < FD_BOUND);
    }
    println!("{report}");
}

#[test]
fn f32_result_is_the_f64_result_rounded() {
    let mut rng = XorShift::new(0xf32);
    for case in cases() {
        for _ in 0..2_000 {
            let (p, n) = (case.sample)(&mut rng);
            let j = case.mapping.uv_and_jacobian(p, n).expect("regular point");
            let d = case
                .mapping
                .uv_and_jacobian_f64(p.as_dvec3(), n.as_dvec3())
                .expect("regular point");
            let mut uv = d.uv.as_vec2();
            if uv.x == 1.0 {
                uv.x = 0.0; // folded into [0, 1)
            }
            if uv.y == 1.0 && case.name == "torus" {
                uv.y = 0.0;
            }
            assert_eq!(j.uv, uv, "{}", case.name);
            assert_eq!(
                (j.du, j.dv),
                (d.du.as_vec3(), d.dv.as_vec3()),
                "{}",
                case.name
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2_000))]

    /// `map` is the chain rule: `duvdx = (∇u·dpdx, ∇v·dpdx)`, likewise for y.
    #[test]
    fn map_applies_the_chain_rule(
        seed in any::<u64>(),
        dpdx in vec3_in(-0.1, 0.1),
        dpdy in vec3_in(-0.1, 0.1),
    ) {
        let mut rng = XorShift::new(seed | 1);
        for case in cases() {
            let (p, n) = (case.sample)(&mut rng);
            let j = case.mapping.uv_and_jacobian(p, n).expect("regular point");
            let s = case
                .mapping
                .map(&SurfacePoint::with_derivatives(p, n, dpdx, dpdy))
                .expect("regular point");
            prop_assert_eq!(s.uv, j.uv);
            prop_assert_eq!(s.duvdx, Vec2::new(j.du.dot(dpdx), j.dv.dot(dpdx)));
            prop_assert_eq!(s.duvdy, Vec2::new(j.du.dot(dpdy), j.dv.dot(dpdy)));
            // And the chain rule predicts the actual change of uv for a small pixel step.
            // (In f64, so only the mapping's curvature separates the two: relative 1e-2.)
            let step = (p.as_dvec3() + dpdx.as_dvec3() * 1e-3, n.as_dvec3());
            let step = case.mapping.uv_and_jacobian_f64(step.0, step.1).expect("regular point").uv;
            let base = case.mapping.uv_and_jacobian_f64(p.as_dvec3(), n.as_dvec3()).expect("regular").uv;
            let mut moved = step - base;
            moved -= moved.round();
            let predicted = s.duvdx.as_dvec2() * 1e-3;
            let scale = 1e-3 * f64::from(j.du.length() + j.dv.length()) * f64::from(dpdx.length());
            prop_assert!((moved - predicted).length() <= 1e-2 * scale + 1e-12,
                "{}: moved {:?} predicted {:?}", case.name, moved, predicted);
        }
    }

    /// Any bits in, no panic and no NaN inside `Some`; non-finite input gives `None`.
    #[test]
    fn total_on_any_bits(
        p in [bits_f32(), bits_f32(), bits_f32()],
        n in [bits_f32(), bits_f32(), bits_f32()],
        d in [bits_f32(), bits_f32(), bits_f32()],
    ) {
        let (p, n, d) = (Vec3::from_array(p), Vec3::from_array(n), Vec3::from_array(d));
        for case in cases() {
            let j = case.mapping.uv_and_jacobian(p, n);
            if let Some(j) = j {
                prop_assert!(j.uv.is_finite() && j.du.is_finite() && j.dv.is_finite(), "{}", case.name);
            }
            if !p.is_finite() || !n.is_finite() {
                prop_assert!(j.is_none(), "{}: {:?} {:?}", case.name, p, n);
            }
            if let Some(s) = case.mapping.map(&SurfacePoint::with_derivatives(p, n, d, -d)) {
                prop_assert!(s.uv.is_finite() && s.duvdx.is_finite() && s.duvdy.is_finite());
            }
        }
    }

    /// Any bits as parameters: constructors give `Ok` or an error, never a panic, and what they
    /// build is total too.
    #[test]
    fn constructors_total_on_any_bits(
        a in [bits_f32(), bits_f32(), bits_f32()],
        b in [bits_f32(), bits_f32(), bits_f32()],
        c in [bits_f32(), bits_f32(), bits_f32()],
        p in [bits_f32(), bits_f32(), bits_f32()],
    ) {
        let (a, b, c, p) = (Vec3::from_array(a), Vec3::from_array(b), Vec3::from_array(c), Vec3::from_array(p));
        let mut built: Vec<Box<dyn Mapping>> = Vec::new();
        if let Ok(m) = Planar::new(a, b, c) { built.push(Box::new(m)); }
        if let Ok(m) = Planar::xz(a.x) { built.push(Box::new(m)); }
        if let Ok(m) = BoxMapping::new(a, b.x) { built.push(Box::new(m)); }
        if let Ok(m) = Cylindrical::new(b.x, b.y) { built.push(Box::new(m.with_caps(CylinderCaps::Planar))); }
        for projection in [SphereProjection::Equirectangular, SphereProjection::EqualArea] {
            if let Ok(m) = Spherical::new(c.x, projection) { built.push(Box::new(m)); }
        }
        if let Ok(m) = Torus::new(c.y, c.z) { built.push(Box::new(m)); }
        for m in built {
            if let Some(j) = m.uv_and_jacobian(p, c) {
                prop_assert!(j.uv.is_finite() && j.du.is_finite() && j.dv.is_finite());
            }
        }
    }

    /// `uv → point → uv` away from seams (u ∈ [0.01, 0.99]) and poles (v ∈ [0.05, 0.95]).
    #[test]
    fn round_trip_uv_point_uv(u in 0.01f32..0.99, v in 0.05f32..0.95) {
        let uv = Vec2::new(u, v);
        let inverses = inverses();
        for (name, forward, inverse, normal) in inverses {
            let p = inverse.point_at(uv).expect("in range");
            let back = forward.uv(p, normal(p)).expect("regular point");
            prop_assert!((back - uv).abs().max_element() <= ROUND_TRIP_BOUND,
                "{}: {:?} → {:?} → {:?}", name, uv, p, back);
        }
        let cube = BoxMapping::new(Vec3::new(0.5, 0.0, -1.0), 3.0).expect("valid");
        for face in BoxFace::ALL {
            let p = cube.point_at(face, uv).expect("finite");
            let back = cube.uv(p, face.normal()).expect("regular");
            prop_assert!((back - uv).abs().max_element() <= ROUND_TRIP_BOUND, "{:?}", face);
            prop_assert_eq!(BoxFace::from_normal(face.normal()), Some(face));
        }
    }

    /// Triplanar weights are non-negative, sum to 1 and favour the dominant axis.
    #[test]
    fn triplanar_weights_sum_to_one(n in vec3_in(-1.0, 1.0), k in 0.0f32..64.0) {
        let w = triplanar_weights(n, k);
        prop_assert!(w.min_element() >= 0.0);
        prop_assert!((w.element_sum() - 1.0).abs() <= 4.0 * f32::EPSILON, "{:?}", w);
        let a = n.abs();
        if a.x > a.y && a.x > a.z {
            prop_assert!(w.x >= w.y && w.x >= w.z);
        }
    }
}

fn inverses() -> Vec<Inverse> {
    vec![
        ("planar skew", Box::new(skew()), Box::new(skew()), |_| {
            Vec3::Z
        }),
        (
            "cylinder",
            Box::new(cylinder()),
            Box::new(cylinder()),
            |p| Vec3::new(p.x, 0.0, p.z),
        ),
        (
            "sphere equirectangular",
            Box::new(sphere(SphereProjection::Equirectangular)),
            Box::new(sphere(SphereProjection::Equirectangular)),
            |p| p,
        ),
        (
            "sphere equal-area",
            Box::new(sphere(SphereProjection::EqualArea)),
            Box::new(sphere(SphereProjection::EqualArea)),
            |p| p,
        ),
        ("torus", Box::new(torus()), Box::new(torus()), |_| Vec3::Y),
    ]
}

/// The worst round-trip error over a grid (measured figure for the docs).
#[test]
fn round_trip_worst_case() {
    let mut worst = 0.0f32;
    for (name, forward, inverse, normal) in inverses() {
        for i in 0..=98 {
            for j in 0..=90 {
                let uv = Vec2::new(0.01 + i as f32 * 0.01, 0.05 + j as f32 * 0.01);
                let p = inverse.point_at(uv).expect("in range");
                let back = forward.uv(p, normal(p)).expect("regular point");
                let e = (back - uv).abs().max_element();
                assert!(e <= ROUND_TRIP_BOUND, "{name}: {uv:?} → {back:?}");
                worst = worst.max(e);
            }
        }
    }
    println!("round trip worst {worst:e}");
}

fn skew() -> Planar {
    Planar::new(
        Vec3::new(1.0, -2.0, 0.5),
        Vec3::new(0.5, 0.25, 0.0),
        Vec3::new(0.3, -0.1, 2.0),
    )
    .expect("valid frame")
}
fn cylinder() -> Cylindrical {
    Cylindrical::new(1.5, 4.0).expect("valid")
}
fn sphere(projection: SphereProjection) -> Spherical {
    Spherical::new(2.0, projection).expect("valid")
}
fn torus() -> Torus {
    Torus::new(2.0, 0.5).expect("valid")
}

#[test]
fn constructors_reject_bad_parameters() {
    assert_eq!(
        Planar::new(Vec3::ZERO, Vec3::X, Vec3::X * 2.0),
        Err(UvError::OutOfRange {
            what: "v_axis",
            value: 0.0
        })
    );
    assert!(matches!(
        Planar::new(Vec3::ZERO, Vec3::ZERO, Vec3::X),
        Err(UvError::OutOfRange { what: "u_axis", .. })
    ));
    assert!(matches!(
        Planar::new(Vec3::NAN, Vec3::Y, Vec3::X),
        Err(UvError::NonFinite { what: "origin" })
    ));
    assert!(matches!(Planar::xz(0.0), Err(UvError::OutOfRange { .. })));
    assert!(matches!(
        Planar::xz(f32::INFINITY),
        Err(UvError::NonFinite { .. })
    ));
    assert!(matches!(
        BoxMapping::new(Vec3::ZERO, -1.0),
        Err(UvError::OutOfRange { .. })
    ));
    assert!(matches!(
        Cylindrical::new(1.0, f32::NAN),
        Err(UvError::NonFinite { what: "height" })
    ));
    assert!(matches!(
        Spherical::new(0.0, SphereProjection::EqualArea),
        Err(UvError::OutOfRange { what: "radius", .. })
    ));
    assert!(matches!(
        Torus::new(1.0, -0.0),
        Err(UvError::OutOfRange { what: "minor", .. })
    ));
}

#[test]
fn poles_and_axes_are_none_only_on_the_axis() {
    for projection in [
        SphereProjection::Equirectangular,
        SphereProjection::EqualArea,
    ] {
        let s = sphere(projection);
        assert_eq!(s.uv(Vec3::Y, Vec3::Y), None);
        assert_eq!(s.uv(Vec3::NEG_Y * 3.0, Vec3::NEG_Y), None);
        assert_eq!(s.uv(Vec3::ZERO, Vec3::Y), None);
        // Just off the axis the mapping is defined, and v is next to the pole's row.
        let north = s
            .uv(Vec3::new(1e-20, 1.0, 0.0), Vec3::Y)
            .expect("off the axis");
        assert!(north.y < 1e-6, "{north:?}");
        let south = s
            .uv(Vec3::new(0.0, -1.0, 1e-20), Vec3::Y)
            .expect("off the axis");
        assert!(south.y > 1.0 - 1e-6, "{south:?}");
        // On the equator both projections give v = 1/2 and a horizontal derivative of zero.
        let j = s.uv_and_jacobian(Vec3::Z * 2.0, Vec3::Z).expect("regular");
        assert_eq!(j.uv, Vec2::new(0.0, 0.5));
        assert_eq!(j.dv.x, 0.0);
        assert!(j.dv.y < 0.0, "v grows downwards: {j:?}");
    }
    assert_eq!(cylinder().uv(Vec3::Y, Vec3::X), None);
    assert_eq!(torus().uv(Vec3::Y, Vec3::Y), None);
    assert_eq!(torus().uv(Vec3::Z * 2.0, Vec3::Y), None); // the core circle
}

#[test]
fn projections_match_buss_equations_v2_and_v3() {
    let equirect = sphere(SphereProjection::Equirectangular);
    let equal_area = sphere(SphereProjection::EqualArea);
    for lat_deg in [-80.0f32, -45.0, -10.0, 0.0, 30.0, 60.0, 89.0] {
        let phi = lat_deg.to_radians();
        let p = Vec3::new(phi.cos() * 0.6, phi.sin(), phi.cos() * 0.8) * 2.0;
        // Buss (2003), eqs. (V.2) and (V.3): t = φ/180 + 1/2 in degrees and t = sin φ/2 + 1/2;
        // v = 1 − t.
        let v1 = equirect.uv(p, p).expect("regular").y;
        let v2 = equal_area.uv(p, p).expect("regular").y;
        assert!(
            (v1 - (1.0 - (lat_deg / 180.0 + 0.5))).abs() < 1e-6,
            "{lat_deg}: {v1}"
        );
        assert!(
            (v2 - (1.0 - (phi.sin() / 2.0 + 0.5))).abs() < 1e-6,
            "{lat_deg}: {v2}"
        );
    }
    // s = θ/2π with θ = atan2(x, z): +z is 0, +x a quarter turn, −x three quarters.
    for (p, u) in [
        (Vec3::Z, 0.0),
        (Vec3::X, 0.25),
        (Vec3::NEG_Z, 0.5),
        (Vec3::NEG_X, 0.75),
    ] {
        for m in [
            &equirect as &dyn PositionMapping,
            &equal_area,
            &cylinder(),
            &torus(),
        ] {
            let got = m.uv(p * 2.2, Vec3::Y).expect("regular").x;
            assert!((got - u).abs() < 1e-6, "{p:?}: {got}");
        }
    }
    // Just before the seam u stays below 1 in f32.
    let before = equirect
        .uv(Vec3::new(-1e-9, 0.0, -1.0), Vec3::Z)
        .expect("regular");
    assert!(before.x < 1.0, "{before:?}");
}

#[test]
fn cylinder_caps_and_side_orientation() {
    let c = cylinder().with_caps(CylinderCaps::Planar);
    // Top of the side is v = 0, bottom v = 1.
    assert_eq!(
        cylinder().uv(Vec3::new(0.0, 2.0, 1.5), Vec3::Z),
        Some(Vec2::new(0.0, 0.0))
    );
    assert_eq!(
        cylinder().uv(Vec3::new(0.0, -2.0, 1.5), Vec3::Z),
        Some(Vec2::new(0.0, 1.0))
    );
    // Caps: the disc fills [0, 1]², the axis is the centre, top seen from above.
    assert_eq!(
        c.uv(Vec3::new(0.0, 2.0, 0.0), Vec3::Y),
        Some(Vec2::splat(0.5))
    );
    assert_eq!(
        c.uv(Vec3::new(1.5, 2.0, 1.5), Vec3::Y),
        Some(Vec2::new(1.0, 1.0))
    );
    assert_eq!(
        c.uv(Vec3::new(1.5, -2.0, 1.5), Vec3::NEG_Y),
        Some(Vec2::new(1.0, 0.0))
    );
    // A side normal still gets the side mapping.
    assert_eq!(c.uv(Vec3::new(0.0, 2.0, 1.5), Vec3::Z), Some(Vec2::ZERO));
}

#[test]
fn box_faces_follow_the_table() {
    let cube = BoxMapping::new(Vec3::ZERO, 2.0).expect("valid");
    // The top-left corner of each face seen from outside, side faces upright.
    let top_left = [
        (BoxFace::PosX, Vec3::new(1.0, 1.0, 1.0)),
        (BoxFace::NegX, Vec3::new(-1.0, 1.0, -1.0)),
        (BoxFace::PosY, Vec3::new(-1.0, 1.0, -1.0)),
        (BoxFace::NegY, Vec3::new(-1.0, -1.0, 1.0)),
        (BoxFace::PosZ, Vec3::new(-1.0, 1.0, 1.0)),
        (BoxFace::NegZ, Vec3::new(1.0, 1.0, -1.0)),
    ];
    for (face, corner) in top_left {
        assert_eq!(cube.uv(corner, face.normal()), Some(Vec2::ZERO), "{face:?}");
        let (u, v) = face.axes();
        // Looking at the face from outside, u × v points into the cube (right-handed, v down).
        assert_eq!(u.cross(v), -face.normal(), "{face:?}");
    }
    assert_eq!(
        BoxFace::from_normal(Vec3::new(0.5, -0.7, 0.1)),
        Some(BoxFace::NegY)
    );
    assert_eq!(
        BoxFace::from_normal(Vec3::new(1.0, 1.0, 1.0)),
        Some(BoxFace::PosX)
    );
    assert_eq!(BoxFace::from_normal(Vec3::ZERO), None);
    assert_eq!(cube.uv(Vec3::ZERO, Vec3::ZERO), None);
}

#[test]
fn triplanar_special_values() {
    assert_eq!(triplanar_weights(Vec3::NEG_Z, 1.0), Vec3::Z);
    assert_eq!(triplanar_weights(Vec3::NAN, 1.0), Vec3::splat(1.0 / 3.0));
    assert_eq!(triplanar_weights(Vec3::ZERO, 1.0), Vec3::splat(1.0 / 3.0));
    assert_eq!(triplanar_weights(Vec3::X, f32::NAN), Vec3::splat(1.0 / 3.0));
    assert_eq!(
        triplanar_weights(Vec3::new(0.9, 0.1, 0.0), -2.0),
        Vec3::splat(1.0 / 3.0)
    );
    // Huge sharpness picks the dominant axis instead of underflowing everything.
    assert_eq!(triplanar_weights(Vec3::new(0.8, 0.6, 0.0), 1e6), Vec3::X);
    assert_eq!(
        triplanar_weights(Vec3::new(0.8, 0.6, 0.0), f32::INFINITY),
        Vec3::X
    );
    let w = triplanar_weights(Vec3::new(3.0, 4.0, 0.0), 1.0);
    assert!((w - Vec3::new(3.0 / 7.0, 4.0 / 7.0, 0.0)).length() < 1e-6);
    // Sharpness 0 blends all three equally.
    assert_eq!(
        triplanar_weights(Vec3::new(0.9, 0.1, 0.0), 0.0),
        Vec3::splat(1.0 / 3.0)
    );
}

#[test]
fn pole_gradient_unbounded_but_finite_near_axis() {
    // |∇u| = 1/(2πρ): grows without bound towards the axis, as it must.
    let s = sphere(SphereProjection::Equirectangular);
    let j = s
        .uv_and_jacobian(Vec3::new(1e-3, 1.0, 0.0), Vec3::Y)
        .expect("regular");
    assert!((j.du.length() - 1.0 / (TAU * 1e-3)).abs() < 1e-2 * j.du.length());
    let _ = FRAC_PI_2;
}
