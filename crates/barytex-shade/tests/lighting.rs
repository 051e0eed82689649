//! Property and example tests of the lights, illumination models and atmosphere.

use barytex_shade::atmosphere::blend;
use barytex_shade::{
    Attenuation, DepthCue, ExponentialFog, FogDistance, HeightFog, Light, PhongMaterial, Specular,
    SpotShape, blinn_phong_specular, lambert, phong_specular,
};
use glam::{DVec3, Vec3};
use proptest::prelude::*;

fn unit() -> impl Strategy<Value = Vec3> {
    (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
        .prop_filter_map("nonzero", |(x, y, z)| Vec3::new(x, y, z).try_normalize())
}

fn colour() -> impl Strategy<Value = Vec3> {
    (0.0f32..1.0, 0.0f32..1.0, 0.0f32..1.0).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        -1e6f32..1e6,
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(f32::MIN_POSITIVE),
        Just(f32::MAX),
    ]
}

fn light() -> impl Strategy<Value = Light> {
    let att =
        (0.0f32..2.0, 0.0f32..2.0, 0.0f32..2.0).prop_map(|(c, l, q)| Attenuation::Polynomial {
            constant: c,
            linear: l,
            quadratic: q,
        });
    let pos = (-5.0f32..5.0, -5.0f32..5.0, -5.0f32..5.0).prop_map(|(x, y, z)| Vec3::new(x, y, z));
    prop_oneof![
        (unit(), colour()).prop_map(|(direction, color)| Light::Directional { direction, color }),
        (pos.clone(), colour(), att.clone()).prop_map(|(position, color, attenuation)| {
            Light::Point {
                position,
                color,
                attenuation,
            }
        }),
        (
            pos,
            unit(),
            colour(),
            att,
            0.0f32..100.0,
            0.0f32..1.5,
            0.0f32..1.5,
            any::<bool>()
        )
            .prop_map(|(position, direction, color, attenuation, p, a, b, warn)| {
                let shape = if warn {
                    SpotShape::Warn { exponent: p }
                } else {
                    SpotShape::Cone {
                        inner: a.min(b),
                        outer: a.max(b),
                    }
                };
                Light::Spot {
                    position,
                    direction,
                    color,
                    attenuation,
                    shape,
                }
            }),
    ]
}

/// Materials with the classic lobes, bounded by 1 (the energy bounds below hold for them).
fn material() -> impl Strategy<Value = PhongMaterial> {
    material_with(&[Specular::Phong, Specular::BlinnPhong, Specular::None])
}

/// Materials with any of `lobes`.
fn material_with(lobes: &'static [Specular]) -> impl Strategy<Value = PhongMaterial> {
    (
        colour(),
        colour(),
        colour(),
        colour(),
        0.0f32..300.0,
        0..lobes.len(),
    )
        .prop_map(
            |(emission, ambient, diffuse, specular, shininess, lobe)| PhongMaterial {
                emission,
                ambient,
                diffuse,
                specular,
                shininess,
                lobe: lobes[lobe],
            },
        )
}

proptest! {
    #[test]
    fn no_negative_light(m in material_with(&[Specular::Phong, Specular::BlinnPhong, Specular::NormalizedBlinnPhong, Specular::None]), lights in prop::collection::vec(light(), 0..4),
                         n in unit(), v in unit(), p in (-3.0f32..3.0, -3.0f32..3.0, -3.0f32..3.0),
                         ambient in colour()) {
        let p = Vec3::new(p.0, p.1, p.2);
        let c = m.shade(p, n, v, &lights, ambient);
        for term in [c.ambient, c.diffuse, c.specular] {
            prop_assert!(term.min_element() >= 0.0, "{c:?}");
            prop_assert!(term.is_finite());
        }
    }

    #[test]
    fn lambert_is_clamped(x in any_f32(), y in any_f32(), z in any_f32(), l in unit()) {
        let d = lambert(Vec3::new(x, y, z), l);
        prop_assert!((0.0..=1.0).contains(&d));
    }

    #[test]
    fn specular_factors_are_in_unit_interval(n in unit(), l in unit(), v in unit(), s in any_f32()) {
        for f in [phong_specular(n, l, v, s), blinn_phong_specular(n, l, v, s)] {
            prop_assert!((0.0..=1.0).contains(&f), "{f}");
        }
        // No highlight on the unlit side.
        if n.dot(l) <= 0.0 {
            prop_assert_eq!(phong_specular(n, l, v, s), 0.0);
        }
    }

    /// Energy bound: the diffuse light reflected from one light never exceeds `I_p · k_d`, and the
    /// specular never `I_p · k_s`.
    #[test]
    fn energy_bounds(m in material(), light in light(), n in unit(), v in unit()) {
        let c = m.shade(Vec3::new(0.1, 0.2, 0.3), n, v, &[light], Vec3::ZERO);
        let ip = match light {
            Light::Directional { color, .. } | Light::Point { color, .. } | Light::Spot { color, .. } => color,
        };
        let eps = 1e-6;
        prop_assert!(c.diffuse.cmple(ip * m.diffuse + eps).all(), "{c:?}");
        prop_assert!(c.specular.cmple(ip * m.specular + eps).all(), "{c:?}");
        prop_assert_eq!(c.ambient, m.emission);
    }

    #[test]
    fn attenuation_is_at_most_one(c in any_f32(), l in any_f32(), q in any_f32(), d in any_f32()) {
        let f = Attenuation::Polynomial { constant: c, linear: l, quadratic: q }.factor(d);
        prop_assert!((0.0..=1.0).contains(&f), "{f}");
    }

    #[test]
    fn attenuation_never_grows_with_distance(c in 0.0f32..3.0, l in 0.0f32..3.0, q in 0.0f32..3.0,
                                             d in 0.0f32..100.0, e in 0.0f32..100.0) {
        let a = Attenuation::Polynomial { constant: c, linear: l, quadratic: q };
        prop_assert!(a.factor(d.max(e)) <= a.factor(d.min(e)));
    }

    #[test]
    fn spot_factor_is_in_unit_interval(c in any_f32(), p in any_f32(), a in any_f32(), b in any_f32()) {
        for shape in [SpotShape::Warn { exponent: p }, SpotShape::Cone { inner: a, outer: b }] {
            let f = shape.factor(c);
            prop_assert!((0.0..=1.0).contains(&f), "{shape:?} {c} -> {f}");
        }
    }

    #[test]
    fn lights_never_panic_and_give_unit_directions(light in light(), x in any_f32(), y in any_f32()) {
        if let Some(s) = light.sample(Vec3::new(x, y, 0.5)) {
            prop_assert!((s.to_light.length() - 1.0).abs() < 1e-5);
            prop_assert!(s.intensity.min_element() >= 0.0);
        }
    }

    #[test]
    fn fog_factors_are_in_unit_interval(x in any_f32(), y in any_f32(), z in any_f32(), density in any_f32()) {
        let p = Vec3::new(x, y, z);
        for distance in [FogDistance::Euclidean, FogDistance::ViewDepth] {
            let fog = ExponentialFog { density, colour: Vec3::ONE, distance };
            let s = fog.factor(Vec3::ZERO, -Vec3::Z, p);
            prop_assert!((0.0..=1.0).contains(&s));
        }
        let h = HeightFog { density: density.abs(), falloff: 0.3, base: 0.0, colour: Vec3::ONE };
        let s = h.factor(Vec3::ZERO, p);
        prop_assert!((0.0..=1.0).contains(&s));
    }

    #[test]
    fn exponential_fog_matches_f64(d in 0.0f32..100.0, density in 0.0f32..1.0) {
        let fog = ExponentialFog { density, colour: Vec3::ONE, distance: FogDistance::Euclidean };
        let s = fog.factor(Vec3::ZERO, -Vec3::Z, Vec3::new(0.0, d, 0.0));
        let exact = (-f64::from(-(-density * d))).exp();
        let ulp = f64::from(f32::EPSILON) * exact;
        prop_assert!((f64::from(s) - exact).abs() <= 2.0 * ulp + f64::from(f32::MIN_POSITIVE), "{s} {exact}");
    }

    #[test]
    fn height_fog_matches_quadrature(e in (-5.0f32..5.0, -2.0f32..5.0, -5.0f32..5.0),
                                     p in (-50.0f32..50.0, -2.0f32..20.0, -50.0f32..50.0),
                                     density in 0.001f32..0.5, falloff in -0.5f32..2.0) {
        let (e, p) = (Vec3::new(e.0, e.1, e.2), Vec3::new(p.0, p.1, p.2));
        let fog = HeightFog { density, falloff, base: 0.5, colour: Vec3::ONE };
        let tau = f64::from(fog.optical_depth(e, p));
        let (a, b) = (e.as_dvec3(), p.as_dvec3());
        let rho = |q: DVec3| f64::from(density) * (-f64::from(falloff) * (q.y - 0.5)).exp();
        let n = 4096;
        let h = 1.0 / f64::from(n);
        let mut sum = rho(a) + rho(b);
        for i in 1..n {
            let t = f64::from(i) * h;
            sum += if i % 2 == 1 { 4.0 } else { 2.0 } * rho(a + (b - a) * t);
        }
        let exact = sum * h / 3.0 * (b - a).length();
        prop_assert!((tau - exact).abs() <= 1e-6 * exact + 1e-30, "{tau} {exact}");
    }
}

#[test]
fn phong_peak_is_on_the_mirror_ray() {
    let n = Vec3::Y;
    let l = Vec3::new(1.0, 1.0, 0.0).normalize();
    let mirror = Vec3::new(-1.0, 1.0, 0.0).normalize();
    assert!((phong_specular(n, l, mirror, 50.0) - 1.0).abs() < 1e-4);
    assert!(phong_specular(n, l, Vec3::Y, 50.0) < 1e-3);
    // Blinn: N = H at the same configuration.
    assert!((blinn_phong_specular(n, l, mirror, 50.0) - 1.0).abs() < 1e-4);
    // (cos α)^n with α = 45° between R and V.
    let s = phong_specular(n, l, Vec3::Y, 2.0);
    assert!((s - 0.5).abs() < 1e-6, "{s}");
}

#[test]
fn ambient_and_emission() {
    let m = PhongMaterial {
        emission: Vec3::new(0.1, 0.0, 0.0),
        ambient: Vec3::splat(0.5),
        ..PhongMaterial::default()
    };
    // I = k_i + I_a k_a, whatever the geometry (even a NaN normal).
    for n in [Vec3::Y, Vec3::NAN, Vec3::ZERO] {
        let c = m.shade(Vec3::ZERO, n, Vec3::Y, &[], Vec3::splat(0.4));
        assert_eq!(c.total(), Vec3::new(0.3, 0.2, 0.2));
    }
}

#[test]
fn warn_spotlight_is_cos_power() {
    let spot = |p: f32| Light::Spot {
        position: Vec3::new(0.0, 1.0, 0.0),
        direction: -Vec3::Y,
        color: Vec3::ONE,
        attenuation: Attenuation::NONE,
        shape: SpotShape::Warn { exponent: p },
    };
    // A point seen 60° off the axis: cos α = ½.
    let q = Vec3::new(3.0f32.sqrt(), 0.0, 0.0);
    let s = spot(3.0).sample(q).expect("regular");
    assert!((s.intensity.x - 0.125).abs() < 1e-6);
    // p = 0: a plain point light in front, nothing behind.
    assert_eq!(spot(0.0).sample(q).expect("regular").intensity, Vec3::ONE);
    assert_eq!(
        spot(0.0)
            .sample(Vec3::new(0.0, 2.0, 0.0))
            .expect("regular")
            .intensity,
        Vec3::ZERO
    );
}

#[test]
fn gltf_cone_ramps_between_inner_and_outer() {
    let shape = SpotShape::Cone {
        inner: 0.2,
        outer: 0.4,
    };
    assert_eq!(shape.factor(0.1f32.cos()), 1.0);
    assert_eq!(shape.factor(0.5f32.cos()), 0.0);
    let mid = shape.factor((0.2f32.cos() + 0.4f32.cos()) / 2.0);
    assert!((mid - 0.25).abs() < 1e-3, "{mid}");
}

#[test]
fn attenuation_formula() {
    let a = Attenuation::Polynomial {
        constant: 1.0,
        linear: 0.5,
        quadratic: 0.25,
    };
    assert_eq!(a.factor(2.0), 1.0 / 3.0);
    assert_eq!(a.factor(f32::INFINITY), 0.0);
    assert_eq!(Attenuation::NONE.factor(f32::INFINITY), 1.0);
    assert_eq!(Attenuation::INVERSE_SQUARE.factor(0.5), 1.0);
    assert_eq!(Attenuation::INVERSE_SQUARE.factor(4.0), 1.0 / 16.0);
}

/// glTF's falloff: `1/d²` (not capped) inside the range, windowed by `1 − (d/r)⁴` to exactly 0
/// at the range; no range (or a meaningless one) is infinite; bad distances give 0, never NaN.
#[test]
fn punctual_attenuation_follows_khr_lights_punctual() {
    let open = Attenuation::Punctual { range: None };
    assert_eq!(open.factor(0.5), 4.0);
    assert_eq!(open.factor(2.0), 0.25);
    assert_eq!(open.factor(0.0), 1e8);
    let ranged = Attenuation::Punctual { range: Some(10.0) };
    assert_eq!(ranged.factor(5.0), (1.0 - 0.0625) / 25.0);
    assert_eq!(ranged.factor(10.0), 0.0);
    assert_eq!(ranged.factor(1e6), 0.0);
    for range in [Some(0.0), Some(-1.0), Some(f32::NAN)] {
        assert_eq!(
            Attenuation::Punctual { range }.factor(2.0),
            0.25,
            "{range:?}"
        );
    }
    for d in [f32::NAN, -1.0, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(open.factor(d), 0.0, "{d}");
        assert_eq!(ranged.factor(d), 0.0, "{d}");
    }
    // A point light through it: intensity 4 at distance 2 is 1.
    let lamp = Light::Point {
        position: Vec3::new(0.0, 2.0, 0.0),
        color: Vec3::splat(4.0),
        attenuation: open,
    };
    assert_eq!(
        lamp.sample(Vec3::ZERO).expect("regular").intensity,
        Vec3::ONE
    );
}

/// The normalized Blinn–Phong lobe: its peak is `(n + 8)/(8π)` times `N·L`, it vanishes for light
/// from behind, and it is never negative or NaN.
#[test]
fn normalized_blinn_phong_lobe() {
    let peak = Specular::NormalizedBlinnPhong.factor(Vec3::Z, Vec3::Z, Vec3::Z, 32.0);
    assert!(
        (peak - 40.0 / (8.0 * std::f32::consts::PI)).abs() < 1e-6,
        "{peak}"
    );
    // Light at 60° from the normal, the eye on the mirror ray: the lobe's peak times cos 60°.
    let l = Vec3::new(3.0_f32.sqrt() / 2.0, 0.0, 0.5);
    let v = Vec3::new(-l.x, 0.0, l.z);
    let tilted = Specular::NormalizedBlinnPhong.factor(Vec3::Z, l, v, 32.0);
    assert!((tilted - 0.5 * peak).abs() < 1e-5, "{tilted}");
    assert_eq!(
        Specular::NormalizedBlinnPhong.factor(Vec3::Z, -Vec3::Z, Vec3::Z, 32.0),
        0.0
    );
    for bad in [Vec3::NAN, Vec3::ZERO, Vec3::INFINITY] {
        let f = Specular::NormalizedBlinnPhong.factor(bad, Vec3::Z, Vec3::Z, 32.0);
        assert!(f >= 0.0 && f.is_finite(), "{bad:?}: {f}");
    }
    let huge = Specular::NormalizedBlinnPhong.factor(Vec3::Z, Vec3::Z, Vec3::Z, f32::INFINITY);
    assert!(huge >= 0.0 && huge.is_finite(), "{huge}");
}

#[test]
fn depth_cue_planes() {
    let cue = DepthCue {
        front: 2.0,
        back: 10.0,
        s_front: 0.9,
        s_back: 0.1,
        colour: Vec3::new(0.5, 0.5, 0.6),
    };
    assert_eq!(cue.factor(0.0), 0.9);
    assert_eq!(cue.factor(20.0), 0.1);
    assert!((cue.factor(6.0) - 0.5).abs() < 1e-6);
    assert_eq!(cue.factor(f32::NAN), 0.1);
    // I' = s0 I + (1 − s0) I_dc.
    let c = cue.apply(Vec3::ONE, 6.0);
    assert!((c - Vec3::new(0.75, 0.75, 0.8)).length() < 1e-6);
    let switch = DepthCue { back: 1.0, ..cue };
    assert_eq!(switch.factor(1.5), 0.9);
    assert_eq!(switch.factor(2.5), 0.1);
    assert_eq!(blend(Vec3::ONE, Vec3::ZERO, f32::NAN), Vec3::ZERO);
}

/// Finnish lecture notes *Valaistus ja sävytys*, p. 280: view-space z as the fog distance "works
/// wrongly when the eye is rotated in place". A point 10 units away stays 10 units away while the
/// eye turns, so Euclidean fog does not change; the z variant thins the fog as the point moves to
/// the edge of the view.
#[test]
fn view_depth_fog_changes_when_the_eye_rotates() {
    let p = Vec3::new(0.0, 0.0, -10.0);
    let fog = |distance| ExponentialFog {
        density: 0.1,
        colour: Vec3::ONE,
        distance,
    };
    let mut worst_z = 0.0f32;
    for degrees in [0.0f32, 10.0, 20.0, 30.0, 40.0] {
        let a = degrees.to_radians();
        let forward = Vec3::new(a.sin(), 0.0, -a.cos());
        let euclid = fog(FogDistance::Euclidean).factor(Vec3::ZERO, forward, p);
        let z = fog(FogDistance::ViewDepth).factor(Vec3::ZERO, forward, p);
        assert!((euclid - (-1.0f32).exp()).abs() < 1e-6);
        worst_z = worst_z.max((z - euclid).abs());
    }
    // At 40°: e^(−0.766) − e^(−1) = 0.097 — a tenth of the colour range.
    assert!(worst_z > 0.09, "{worst_z}");
}

#[test]
fn height_fog_without_falloff_is_exponential_fog() {
    let h = HeightFog {
        density: 0.2,
        falloff: 0.0,
        base: 0.0,
        colour: Vec3::ONE,
    };
    let e = ExponentialFog {
        density: 0.2,
        colour: Vec3::ONE,
        distance: FogDistance::Euclidean,
    };
    let p = Vec3::new(3.0, 4.0, -12.0);
    assert!((h.factor(Vec3::ZERO, p) - e.factor(Vec3::ZERO, -Vec3::Z, p)).abs() < 1e-6);
    // Denser below: a ray along the ground sees more fog than one at height 5.
    let thick = HeightFog { falloff: 1.0, ..h };
    assert!(
        thick.factor(Vec3::ZERO, Vec3::new(10.0, 0.0, 0.0))
            < thick.factor(Vec3::new(0.0, 5.0, 0.0), Vec3::new(10.0, 5.0, 0.0))
    );
    assert_eq!(thick.factor(Vec3::NAN, Vec3::ZERO), 0.0);
}

/// Tiny and huge directions and offsets still give unit `to_light` vectors: normalizing through
/// the squared length lost precision once that square was subnormal (a directional light along
/// `(5e-22, 5e-22, 5e-22)` came out 0.1 % too long; found by fuzz `shade`).
#[test]
fn tiny_and_huge_directions_give_unit_vectors() {
    let colour = Vec3::ONE;
    for s in [
        5.16524e-22f32,
        1e-30,
        1e-40,
        f32::from_bits(1),
        1e30,
        1e38,
        f32::MAX,
    ] {
        let d = Vec3::new(s, s, -s);
        let lights = [
            Light::Directional {
                direction: d,
                color: colour,
            },
            Light::Point {
                position: d,
                color: colour,
                attenuation: Attenuation::NONE,
            },
            Light::Spot {
                position: d,
                direction: -d,
                color: colour,
                attenuation: Attenuation::NONE,
                shape: SpotShape::Warn { exponent: 1.0 },
            },
        ];
        for light in lights {
            // Points f32::MAX·√3 away are beyond f32: no sample, documented as non-finite input.
            if let Some(sample) = light.sample(Vec3::ZERO) {
                let len = sample.to_light.length();
                assert!((len - 1.0).abs() < 1e-6, "{light:?}: |to_light| = {len}");
                assert!(sample.distance > 0.0, "{light:?}: {sample:?}");
            } else {
                assert!(s > 1e38, "{light:?} gave no sample");
            }
        }
    }
}
