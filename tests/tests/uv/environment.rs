//! Environment maps against f64 references: reflection, cube-face selection against a
//! brute-force argmax with the Vulkan tie rule, round trips direction → uv → direction (within
//! each map's stated angle) and uv → direction → uv (away from seams), analytic Jacobians
//! against central differences in f64, and totality on any bit pattern.

use barytex_testkit::seeded::XorShift;
use barytex_testkit::strategies::bits_f32;
use barytex_uv::environment::{
    CUBE_ROUND_TRIP_BOUND, CubeFace, EQUIRECT_ROUND_TRIP_BOUND, EnvironmentMap, EnvironmentMapping,
    Lookup, OCTAHEDRAL_ROUND_TRIP_BOUND, SPHERE_MAP_ROUND_TRIP_BOUND, cube_direction, cube_face_uv,
    cube_face_uv_and_jacobian, equirect_direction, equirect_uv, equirect_uv_and_jacobian,
    octahedral_decode, octahedral_encode, octahedral_uv_and_jacobian, reflect, reflect_normalized,
    sphere_map_direction, sphere_map_uv, sphere_map_uv_and_jacobian,
};
use barytex_uv::{PositionMapping, SurfacePoint, UvJacobian, UvMapping};
use glam::{DVec2, DVec3, Vec2, Vec3};
use proptest::prelude::*;

// ---------------------------------------------------------------- f64 references

fn d64(v: Vec3) -> DVec3 {
    v.as_dvec3()
}

/// The angle between two directions, accurate at small angles.
fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

fn frame64(face: CubeFace) -> [DVec3; 3] {
    face.frame().map(d64)
}

fn cube64(face: CubeFace, d: DVec3) -> DVec2 {
    let [a, b, c] = frame64(face);
    0.5 * (DVec2::new(a.dot(d), b.dot(d)) / c.dot(d) + 1.0)
}

fn equirect64(d: DVec3) -> DVec2 {
    let rho = d.x.hypot(d.z);
    DVec2::new(
        0.5 + d.x.atan2(-d.z) / std::f64::consts::TAU,
        rho.atan2(d.y) / std::f64::consts::PI,
    )
}

fn sphere64(d: DVec3) -> DVec2 {
    let r = d.normalize();
    let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0).powi(2)).sqrt();
    DVec2::new(r.x / m + 0.5, r.y / m + 0.5)
}

fn oct64(d: DVec3) -> DVec2 {
    let p = DVec2::new(d.x, d.y) / (d.x.abs() + d.y.abs() + d.z.abs());
    let p = if d.z < 0.0 {
        let s = DVec2::new(1f64.copysign(p.x), 1f64.copysign(p.y));
        (1.0 - DVec2::new(p.y, p.x).abs()) * s
    } else {
        p
    };
    0.5 * p + 0.5
}

/// The f64 reference of `map` at `d` (the face for the cube taken from the f32 selection).
fn uv64(map: EnvironmentMap, face: CubeFace, d: DVec3) -> DVec2 {
    match map {
        EnvironmentMap::Cube => cube64(face, d),
        EnvironmentMap::Equirect => equirect64(d),
        EnvironmentMap::SphereMap => sphere64(d),
        EnvironmentMap::Octahedral => oct64(d),
    }
}

/// Central-difference gradients of `f` at `d`, step `h`.
fn fd_gradient(f: impl Fn(DVec3) -> DVec2, d: DVec3, h: f64) -> (DVec3, DVec3) {
    let mut du = DVec3::ZERO;
    let mut dv = DVec3::ZERO;
    for i in 0..3 {
        let mut e = DVec3::ZERO;
        e[i] = h;
        let g = (f(d + e) - f(d - e)) / (2.0 * h);
        du[i] = g.x;
        dv[i] = g.y;
    }
    (du, dv)
}

/// Largest entry error of the analytic gradients against the finite differences, relative to
/// the largest entry.
fn gradient_error(du: Vec3, dv: Vec3, fd: (DVec3, DVec3)) -> f64 {
    let scale = fd.0.abs().max_element().max(fd.1.abs().max_element());
    let err = (d64(du) - fd.0)
        .abs()
        .max_element()
        .max((d64(dv) - fd.1).abs().max_element());
    err / scale
}

// ---------------------------------------------------------------- strategies

/// A direction in the unit cube, not too short.
fn direction() -> impl Strategy<Value = Vec3> {
    (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
        .prop_filter("not tiny", |d| d.length() > 1e-3)
}

/// A direction scaled by `2^k`, `k` in −120…120: the maps are scale-invariant.
fn scaled_direction() -> impl Strategy<Value = Vec3> {
    (direction(), -120i32..120).prop_map(|(d, k)| d * 2f32.powi(k))
}

/// A direction `10^e` radians from `−z`, `e` in −3…−1, scaled by `2^k`: where the sphere map's
/// gradients are largest (uniform directions come this close once in 10⁵).
fn near_neg_z_direction() -> impl Strategy<Value = Vec3> {
    (-3.0f64..-1.0, 0.0f64..core::f64::consts::TAU, -60i32..60).prop_map(|(e, t, k)| {
        let a = 10f64.powf(e);
        let s = 2f64.powi(k);
        let d = DVec3::new(a.sin() * t.cos(), a.sin() * t.sin(), -a.cos()) * s;
        d.as_vec3()
    })
}

/// Directions with components from a small set, so that ties between axes are common.
fn tie_direction() -> impl Strategy<Value = Vec3> {
    let c = prop::sample::select(vec![-2.0f32, -1.0, -0.5, -0.0, 0.0, 0.5, 1.0, 2.0]);
    (c.clone(), c.clone(), c).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn any_vec3() -> impl Strategy<Value = Vec3> {
    (bits_f32(), bits_f32(), bits_f32()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn any_vec2() -> impl Strategy<Value = Vec2> {
    (bits_f32(), bits_f32()).prop_map(|(x, y)| Vec2::new(x, y))
}

fn face() -> impl Strategy<Value = CubeFace> {
    prop::sample::select(CubeFace::ALL.to_vec())
}

/// Brute force: the axes of largest magnitude, the last of them winning (z over y over x).
fn argmax_face(d: Vec3) -> Option<CubeFace> {
    let a = d.abs().to_array();
    let max = a.iter().copied().fold(0.0f32, f32::max);
    if max == 0.0 || !d.is_finite() {
        return None;
    }
    let axis = (0..3).rev().find(|&i| a[i] == max).expect("a maximum");
    let layer = 2 * axis as u32 + u32::from(d[axis] < 0.0);
    CubeFace::from_layer(layer)
}

// ---------------------------------------------------------------- reflection

proptest! {
    #[test]
    fn reflect_matches_f64(n in direction(), v in direction()) {
        let (n, v) = (n.normalize(), v.normalize());
        let (n64, v64) = (d64(n), d64(v));
        let exact = 2.0 * n64.dot(v64) * n64 - v64;
        let r = reflect(n, v);
        let eps = f64::from(f32::EPSILON);
        prop_assert!((d64(r).length() - exact.length()).abs() <= 4.0 * eps, "{r:?} vs {exact:?}");
        if exact.length() > 0.5 {
            prop_assert!(angle(d64(r), exact) <= 4.0 * eps);
        }
        let rn = reflect_normalized(n * 7.0, v * 1e-30).expect("nonzero");
        prop_assert!((d64(rn).length() - 1.0).abs() <= 2.0 * eps);
        prop_assert!(angle(d64(rn), exact) <= 8.0 * eps, "{}", angle(d64(rn), exact) / eps);
        // Mirror symmetry: reflecting twice gives v back, and n·r = n·v.
        prop_assert!((n.dot(r) - n.dot(v)).abs() <= 8.0 * f32::EPSILON);
    }

    #[test]
    fn reflect_normalized_is_total(n in any_vec3(), v in any_vec3()) {
        let valid = |d: Vec3| d.is_finite() && d != Vec3::ZERO;
        match reflect_normalized(n, v) {
            Some(r) => {
                prop_assert!(valid(n) && valid(v));
                prop_assert!((r.length() - 1.0).abs() <= 4.0 * f32::EPSILON);
            }
            None => prop_assert!(!(valid(n) && valid(v))),
        }
    }
}

// ---------------------------------------------------------------- cube

proptest! {
    #[test]
    fn cube_face_agrees_with_argmax(d in prop_oneof![tie_direction(), scaled_direction()]) {
        let expected = argmax_face(d);
        prop_assert_eq!(CubeFace::of(d), expected);
        prop_assert_eq!(cube_face_uv(d).map(|(f, _)| f), expected);
        if let Some((face, st)) = cube_face_uv(d) {
            prop_assert!(st.cmpge(Vec2::ZERO).all() && st.cmple(Vec2::ONE).all(), "{st:?}");
            // The face's outward normal has a positive dot product with d.
            prop_assert!(face.frame()[2].dot(d) > 0.0);
        }
    }

    #[test]
    fn cube_round_trips(d in scaled_direction()) {
        let (face, st) = cube_face_uv(d).expect("nonzero");
        let back = cube_direction(face, st).expect("finite");
        prop_assert!((back.length() - 1.0).abs() <= 2.0 * f32::EPSILON);
        prop_assert!(angle(d64(back), d64(d)) <= f64::from(CUBE_ROUND_TRIP_BOUND));
        let exact = cube64(face, d64(d));
        prop_assert!((DVec2::new(f64::from(st.x), f64::from(st.y)) - exact).abs().max_element() <= 2.4e-7);
    }

    #[test]
    fn cube_uv_round_trips(face in face(), u in 0.001f32..0.999, v in 0.001f32..0.999) {
        let uv = Vec2::new(u, v);
        let d = cube_direction(face, uv).expect("finite");
        let (f, back) = cube_face_uv(d).expect("unit");
        prop_assert_eq!(f, face);
        prop_assert!((back - uv).abs().max_element() <= 4e-7, "{uv:?} → {back:?}");
    }

    #[test]
    fn cube_jacobian_matches_finite_differences(d in direction()) {
        let (face, j) = cube_face_uv_and_jacobian(d).expect("nonzero");
        let a = d.abs();
        let mut sorted = a.to_array();
        sorted.sort_by(f32::total_cmp);
        // Away from the face edges, where the face (and so the formula) changes.
        prop_assume!(sorted[1] < 0.99 * sorted[2]);
        prop_assert_eq!(Some((face, j.uv)), cube_face_uv(d));
        let fd = fd_gradient(|p| cube64(face, p), d64(d), 1e-6 * f64::from(sorted[2]));
        prop_assert!(gradient_error(j.du, j.dv, fd) <= 1e-6, "{j:?} vs {fd:?}");
        // Degree-0 homogeneous: the gradients are orthogonal to d.
        prop_assert!(j.du.dot(d).abs() <= 1e-6 && j.dv.dot(d).abs() <= 1e-6);
    }
}

// ---------------------------------------------------------------- equirect

proptest! {
    #[test]
    fn equirect_round_trips(d in scaled_direction()) {
        let uv = equirect_uv(d).expect("nonzero");
        prop_assert!(uv.cmpge(Vec2::ZERO).all() && uv.cmple(Vec2::ONE).all());
        let back = equirect_direction(uv).expect("finite");
        prop_assert!((back.length() - 1.0).abs() <= 4e-7);
        prop_assert!(angle(d64(back), d64(d)) <= f64::from(EQUIRECT_ROUND_TRIP_BOUND));
    }

    #[test]
    fn equirect_uv_round_trips(u in 0.001f32..0.999, v in 0.001f32..0.999) {
        let uv = Vec2::new(u, v);
        let back = equirect_uv(equirect_direction(uv).expect("finite")).expect("unit");
        prop_assert!((back - uv).abs().max_element() <= 2e-6, "{uv:?} → {back:?}");
    }

    #[test]
    fn equirect_jacobian_matches_finite_differences(d in scaled_direction()) {
        let j = equirect_uv_and_jacobian(d).expect("not a pole");
        prop_assert_eq!(Some(j.uv), equirect_uv(d));
        let d64 = d64(d);
        // Away from the seam (u = 0 ≡ 1 at +z) and the poles.
        prop_assume!(d64.x.hypot(d64.z) > 1e-2 * d64.length());
        prop_assume!(!(d64.z > 0.0 && d64.x.abs() < 1e-2 * d64.length()));
        let fd = fd_gradient(equirect64, d64, 1e-6 * d64.length());
        prop_assert!(gradient_error(j.du, j.dv, fd) <= 1e-5, "{j:?} vs {fd:?}");
    }
}

// ---------------------------------------------------------------- sphere map

/// The angle of `d` from the singular direction `−z`.
fn from_neg_z(d: Vec3) -> f64 {
    angle(d64(d), DVec3::NEG_Z)
}

/// `cos(α/2)` for the angle `α` of `d` from `+z`: the sphere map's round-trip bound is
/// `SPHERE_MAP_ROUND_TRIP_BOUND` divided by it.
fn sphere_weight(d: Vec3) -> f64 {
    (angle(d64(d), DVec3::Z) / 2.0).cos()
}

proptest! {
    #[test]
    fn sphere_map_round_trips(d in scaled_direction()) {
        prop_assume!(from_neg_z(d) >= 1e-6);
        let st = sphere_map_uv(d).expect("not singular");
        prop_assert!((st - 0.5).length() <= 0.5);
        let back = sphere_map_direction(st).expect("inside");
        prop_assert!((back.length() - 1.0).abs() <= 4e-7);
        let bound = f64::from(SPHERE_MAP_ROUND_TRIP_BOUND) / sphere_weight(d);
        prop_assert!(angle(d64(back), d64(d)) <= bound, "{d:?}");
        let exact = sphere64(d64(d));
        prop_assert!((DVec2::new(f64::from(st.x), f64::from(st.y)) - exact).abs().max_element() <= 4e-7);
    }

    #[test]
    fn sphere_map_near_singular_direction(k in -40i32..-10, t in 0.0f32..core::f32::consts::TAU) {
        // Tiny tilts off −z still map inside the disk, near its rim, and come back.
        let e = 2f32.powi(k);
        let d = Vec3::new(e * t.cos(), e * t.sin(), -1.0);
        let st = sphere_map_uv(d).expect("not exactly singular");
        prop_assert!((st - 0.5).length() <= 0.5 + 1e-7);
        let back = sphere_map_direction(st);
        prop_assert!(back.is_none_or(|b| b.is_finite() && angle(d64(b), DVec3::NEG_Z) <= 1e-3));
    }

    #[test]
    fn sphere_map_uv_round_trips(r in 0.0f32..0.499, t in 0.0f32..core::f32::consts::TAU) {
        let st = Vec2::new(0.5 + r * t.cos(), 0.5 + r * t.sin());
        let d = sphere_map_direction(st).expect("inside");
        // The direction against the f64 inverse.
        let p = 2.0 * (DVec2::new(f64::from(st.x), f64::from(st.y)) - 0.5);
        let nz = (1.0 - p.length_squared()).sqrt();
        let exact = DVec3::new(2.0 * nz * p.x, 2.0 * nz * p.y, 2.0 * nz * nz - 1.0);
        let bound = f64::from(SPHERE_MAP_ROUND_TRIP_BOUND) / nz;
        prop_assert!(angle(d64(d), exact) <= bound, "{st:?}: {d:?} vs {exact:?}");
        let back = sphere_map_uv(d).expect("not singular");
        prop_assert!((back - st).abs().max_element() <= 1e-6, "{st:?} → {back:?}");
    }

    #[test]
    fn sphere_map_jacobian_matches_finite_differences(
        d in prop_oneof![scaled_direction(), near_neg_z_direction()],
    ) {
        prop_assume!(from_neg_z(d) >= 1e-3);
        let j = sphere_map_uv_and_jacobian(d).expect("not singular");
        prop_assert_eq!(Some(j.uv), sphere_map_uv(d));
        let (err, fd) = sphere_jacobian_error(d, &j);
        prop_assert!(err <= 2e-6, "{err:e}: {j:?} vs {fd:?}");
    }
}

/// The sphere map's gradients `j` at `d` against f64 central differences (returned too):
/// `(s, t)` varies on the scale of the angle from −z, so the step follows it.
fn sphere_jacobian_error(d: Vec3, j: &UvJacobian) -> (f64, (DVec3, DVec3)) {
    let step = 1e-5 * from_neg_z(d).min(1.0) * d64(d).length();
    let fd = fd_gradient(sphere64, d64(d), step);
    (gradient_error(j.du, j.dv, fd), fd)
}

/// CI's failing input (2026-12-04): `∂q/∂z` was `(1 + (|d| + z)/|d|)z + |d|`, two terms of
/// ≈ ±|d| cancelling near `−z`, which put the `z` entries 1.2e-5 (relative) off.
#[test]
fn sphere_map_jacobian_near_neg_z_regression() {
    let d = Vec3::new(0.007_958_334, -0.000_487_267_9, -0.783_317_7);
    let j = sphere_map_uv_and_jacobian(d).expect("not singular");
    let (err, fd) = sphere_jacobian_error(d, &j);
    assert!(err <= 2e-6, "{err:e}: {j:?} vs {fd:?}");
}

// ---------------------------------------------------------------- octahedral

proptest! {
    #[test]
    fn octahedral_round_trips(d in prop_oneof![scaled_direction(), tie_direction()]) {
        prop_assume!(d != Vec3::ZERO);
        let uv = octahedral_encode(d).expect("nonzero");
        prop_assert!(uv.cmpge(Vec2::ZERO).all() && uv.cmple(Vec2::ONE).all());
        let back = octahedral_decode(uv).expect("finite");
        prop_assert!((back.length() - 1.0).abs() <= 2.0 * f32::EPSILON);
        prop_assert!(angle(d64(back), d64(d)) <= f64::from(OCTAHEDRAL_ROUND_TRIP_BOUND), "{d:?}");
        let exact = oct64(d64(d));
        prop_assert!((DVec2::new(f64::from(uv.x), f64::from(uv.y)) - exact).abs().max_element() <= 4e-7);
    }

    #[test]
    fn octahedral_uv_round_trips(u in 0.0f32..=1.0, v in 0.0f32..=1.0) {
        let uv = Vec2::new(u, v);
        let p = 2.0 * uv - 1.0;
        // Away from the folds |p.x| + |p.y| = 1 and the edges of the square, whose points have
        // two codes (the edges fold onto themselves).
        prop_assume!((p.x.abs() + p.y.abs() - 1.0).abs() > 1e-3 && p.abs().max_element() < 0.999);
        let back = octahedral_encode(octahedral_decode(uv).expect("finite")).expect("unit");
        prop_assert!((back - uv).abs().max_element() <= 1e-6, "{uv:?} → {back:?}");
    }

    #[test]
    fn octahedral_jacobian_matches_finite_differences(d in scaled_direction()) {
        let a = d.abs();
        // Away from the coordinate planes, where the pieces meet.
        prop_assume!(a.min_element() > 1e-2 * a.max_element());
        let j = octahedral_uv_and_jacobian(d).expect("nonzero");
        prop_assert_eq!(Some(j.uv), octahedral_encode(d));
        let fd = fd_gradient(oct64, d64(d), 1e-6 * f64::from(a.min_element()));
        prop_assert!(gradient_error(j.du, j.dv, fd) <= 1e-5, "{j:?} vs {fd:?}");
    }
}

// ---------------------------------------------------------------- the UvMapping

fn point() -> impl Strategy<Value = Vec3> {
    (-10.0f32..10.0, -10.0f32..10.0, -10.0f32..10.0).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn map() -> impl Strategy<Value = EnvironmentMap> {
    prop::sample::select(EnvironmentMap::ALL.to_vec())
}

/// The f64 reflection lookup of the mapping.
fn reflected64(eye: DVec3, p: DVec3, n: DVec3) -> DVec3 {
    let v = (eye - p).normalize();
    2.0 * n.dot(v) * n - v
}

proptest! {
    #![proptest_config(ProptestConfig { max_global_rejects: 1 << 20, ..ProptestConfig::default() })]

    #[test]
    fn mapping_jacobian_matches_finite_differences(
        map in map(), p in point(), eye in point(), n in direction(),
    ) {
        prop_assume!(eye.distance(p) > 0.5);
        let n = n.normalize();
        let mapping = EnvironmentMapping { map, lookup: Lookup::Reflect { eye } };
        let r = reflect(n, (eye - p).normalize());
        let a = r.abs();
        let mut sorted = a.to_array();
        sorted.sort_by(f32::total_cmp);
        // Away from every map's seams, folds and singular points.
        prop_assume!(sorted[1] < 0.95 * sorted[2] && a.min_element() > 0.05);
        prop_assume!(r.z < 0.0 || r.x.abs() > 0.05);
        let Some(j) = mapping.uv_and_jacobian(p, n) else {
            return Err(TestCaseError::fail(format!("None at {p:?} {n:?} {r:?}")));
        };
        let face = CubeFace::of(r).expect("nonzero");
        let (eye64, n64) = (d64(eye), d64(n));
        let fd = fd_gradient(|q| uv64(map, face, reflected64(eye64, q, n64)), d64(p), 1e-5);
        prop_assert!(gradient_error(j.du, j.dv, fd) <= 1e-3, "{map:?} {j:?} vs {fd:?}");
        let normal = EnvironmentMapping { map, lookup: Lookup::Normal };
        let jn = normal.uv_and_jacobian(p, n).expect("defined");
        prop_assert_eq!((jn.du, jn.dv), (Vec3::ZERO, Vec3::ZERO));
        let uv = map.uv(n).expect("defined");
        prop_assert!((jn.uv - uv).abs().max_element() <= 1e-6);
        // Looking the reflected ray up as a direction gives the same coordinate, and the chain
        // rule through the direction's own derivatives.
        let direct = EnvironmentMapping { map, lookup: Lookup::Direction };
        let jd = direct.uv_and_jacobian(r, Vec3::ZERO).expect("defined");
        let jr = map.uv_and_direction_jacobian(r).expect("defined");
        prop_assert_eq!(jd, jr);
        prop_assert!((jd.uv - j.uv).abs().max_element() <= 1e-6);
        let (dx, dy) = (Vec3::new(1e-3, 0.0, 0.0), Vec3::new(0.0, 0.0, -1e-3));
        let sample = direct.map(&SurfacePoint::with_derivatives(r, Vec3::ZERO, dx, dy)).expect("finite");
        prop_assert_eq!(sample.duvdx, Vec2::new(jr.du.dot(dx), jr.dv.dot(dx)));
        prop_assert_eq!(sample.duvdy, Vec2::new(jr.du.dot(dy), jr.dv.dot(dy)));
    }

    #[test]
    fn mapping_is_total(map in map(), p in any_vec3(), n in any_vec3(), eye in any_vec3()) {
        for lookup in [Lookup::Normal, Lookup::Reflect { eye }, Lookup::Direction] {
            let mapping = EnvironmentMapping { map, lookup };
            if let Some(j) = mapping.uv_and_jacobian(p, n) {
                prop_assert!(j.uv.is_finite() && j.du.is_finite() && j.dv.is_finite());
                prop_assert!(j.uv.cmpge(Vec2::ZERO).all() && j.uv.cmple(Vec2::ONE).all());
            }
        }
    }
}

// ---------------------------------------------------------------- totality

proptest! {
    #[test]
    fn forward_maps_are_total(d in prop_oneof![any_vec3(), tie_direction()]) {
        let valid = d.is_finite() && d != Vec3::ZERO;
        let in_unit = |uv: Vec2| uv.is_finite() && uv.cmpge(Vec2::ZERO).all() && uv.cmple(Vec2::ONE).all();
        prop_assert_eq!(cube_face_uv(d).is_some(), valid);
        prop_assert!(cube_face_uv(d).is_none_or(|(_, st)| in_unit(st)));
        prop_assert_eq!(equirect_uv(d).is_some(), valid);
        prop_assert!(equirect_uv(d).is_none_or(in_unit));
        prop_assert_eq!(octahedral_encode(d).is_some(), valid);
        prop_assert!(octahedral_encode(d).is_none_or(in_unit));
        let st = sphere_map_uv(d);
        prop_assert!(valid || st.is_none());
        // Only the singular direction (after normalization) is refused among valid ones.
        let singular = valid && d.x == 0.0 && d.y == 0.0 && d.z < 0.0;
        prop_assert!(st.is_some() || !valid || singular || from_neg_z(d) < 1e-3, "{d:?}");
        prop_assert!(st.is_none_or(|st| in_unit(st) && (st - 0.5).length() <= 0.5 + 1e-7));
        for map in EnvironmentMap::ALL {
            if let Some(j) = map.uv_and_direction_jacobian(d) {
                prop_assert!(valid && in_unit(j.uv) && j.du.is_finite() && j.dv.is_finite());
            }
        }
    }

    #[test]
    fn inverse_maps_are_total(uv in any_vec2(), face in face()) {
        let unit = |d: Vec3| d.is_finite() && (d.length() - 1.0).abs() <= 1e-6;
        let finite = uv.is_finite();
        prop_assert!(equirect_direction(uv).is_none_or(unit));
        prop_assert!(octahedral_decode(uv).is_none_or(unit));
        prop_assert_eq!(octahedral_decode(uv).is_some(), finite);
        prop_assert!(sphere_map_direction(uv).is_none_or(unit));
        prop_assert!(cube_direction(face, uv).is_none_or(unit));
        if !finite {
            prop_assert!(equirect_direction(uv).is_none() && sphere_map_direction(uv).is_none());
            prop_assert!(cube_direction(face, uv).is_none());
        }
    }
}

#[test]
fn special_values() {
    for d in [
        Vec3::ZERO,
        Vec3::splat(-0.0),
        Vec3::NAN,
        Vec3::INFINITY,
        Vec3::new(1.0, f32::NAN, 0.0),
    ] {
        assert_eq!(cube_face_uv(d), None);
        assert_eq!(equirect_uv(d), None);
        assert_eq!(sphere_map_uv(d), None);
        assert_eq!(octahedral_encode(d), None);
    }
    // The singular direction of the sphere map, at any length.
    assert_eq!(sphere_map_uv(Vec3::NEG_Z * 1e-40), None);
    assert_eq!(sphere_map_uv(Vec3::NEG_Z * f32::MAX), None);
    // Huge and subnormal lengths work.
    assert_eq!(equirect_uv(Vec3::X * f32::MAX), equirect_uv(Vec3::X));
    assert_eq!(
        cube_face_uv(Vec3::splat(1e-45)),
        Some((CubeFace::PositiveZ, Vec2::new(1.0, 0.0)))
    );
    assert_eq!(octahedral_encode(Vec3::Z * 1e-45), Some(Vec2::splat(0.5)));
    // Poles of the equirectangular map: u = ½ by convention, no Jacobian.
    assert_eq!(equirect_uv(Vec3::NEG_Y), Some(Vec2::new(0.5, 1.0)));
    assert_eq!(equirect_uv_and_jacobian(Vec3::Y), None);
    // Rim of the sphere map: the singular direction.
    let rim = sphere_map_direction(Vec2::new(0.5, 0.0)).expect("on the rim");
    assert!(angle(d64(rim), DVec3::NEG_Z) < 1e-6);
    // Huge uv: inverses stay unit or refuse.
    assert!(
        cube_direction(CubeFace::PositiveX, Vec2::splat(f32::MAX)).is_none_or(|d| d.is_finite())
    );
    assert!(
        equirect_direction(Vec2::splat(f32::MAX)).is_some_and(|d| (d.length() - 1.0).abs() < 1e-6)
    );
}

#[test]
fn cube_faces_follow_the_vulkan_table() {
    // The centre of each face is its axis; s grows along sc, t along tc (Vulkan table).
    let cases = [
        (CubeFace::PositiveX, Vec3::X, Vec3::NEG_Z, Vec3::NEG_Y),
        (CubeFace::NegativeX, Vec3::NEG_X, Vec3::Z, Vec3::NEG_Y),
        (CubeFace::PositiveY, Vec3::Y, Vec3::X, Vec3::Z),
        (CubeFace::NegativeY, Vec3::NEG_Y, Vec3::X, Vec3::NEG_Z),
        (CubeFace::PositiveZ, Vec3::Z, Vec3::X, Vec3::NEG_Y),
        (CubeFace::NegativeZ, Vec3::NEG_Z, Vec3::NEG_X, Vec3::NEG_Y),
    ];
    for (layer, (face, axis, s_dir, t_dir)) in cases.into_iter().enumerate() {
        assert_eq!(face.layer() as usize, layer);
        assert_eq!(CubeFace::from_layer(layer as u32), Some(face));
        assert_eq!(cube_face_uv(axis), Some((face, Vec2::splat(0.5))));
        let (f, st) = cube_face_uv(axis + 0.5 * s_dir).expect("nonzero");
        assert_eq!((f, st), (face, Vec2::new(0.75, 0.5)));
        let (f, st) = cube_face_uv(axis + 0.5 * t_dir).expect("nonzero");
        assert_eq!((f, st), (face, Vec2::new(0.5, 0.75)));
        assert_eq!(cube_direction(face, Vec2::splat(0.5)), Some(axis));
    }
    assert_eq!(CubeFace::from_layer(6), None);
}

/// Worst round-trip angle of a map over a deterministic sweep, to check that the stated bounds
/// hold and are not loose (bound ≤ 8× measured).
fn sweep(
    name: &str,
    bound: f32,
    weight: impl Fn(Vec3) -> f64,
    round: impl Fn(Vec3) -> Option<Vec3>,
) {
    let mut rng = XorShift::new(0x005e_ede4_u64);
    let mut worst = 0.0f64;
    let mut at = Vec3::ZERO;
    for _ in 0..200_000 {
        let d = rng.vec3_in(-1.0, 1.0);
        if d.length() < 1e-3 {
            continue;
        }
        let back = round(d).unwrap_or_else(|| panic!("{name}: None at {d:?}"));
        let e = angle(d64(back), d64(d)) * weight(d);
        if e > worst {
            worst = e;
            at = d;
        }
    }
    println!(
        "{name}: worst (weighted) round-trip angle {worst:.3e} rad at {at:?} (bound {bound:e})"
    );
    assert!(worst <= f64::from(bound), "{name}: {worst} at {at:?}");
    assert!(
        f64::from(bound) <= 8.0 * worst,
        "{name}: bound {bound} loose (measured {worst})"
    );
}

#[test]
fn round_trip_bounds_are_tight() {
    sweep(
        "cube",
        CUBE_ROUND_TRIP_BOUND,
        |_| 1.0,
        |d| {
            let (f, st) = cube_face_uv(d)?;
            cube_direction(f, st)
        },
    );
    sweep(
        "equirect",
        EQUIRECT_ROUND_TRIP_BOUND,
        |_| 1.0,
        |d| equirect_direction(equirect_uv(d)?),
    );
    sweep(
        "sphere map",
        SPHERE_MAP_ROUND_TRIP_BOUND,
        sphere_weight,
        |d| sphere_map_direction(sphere_map_uv(d)?),
    );
    sweep(
        "octahedral",
        OCTAHEDRAL_ROUND_TRIP_BOUND,
        |_| 1.0,
        |d| octahedral_decode(octahedral_encode(d)?),
    );
}
