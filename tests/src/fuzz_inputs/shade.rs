//! Byte layout and checks of the `shade` fuzz target: `PhongMaterial::shade` under arbitrary
//! lights, attenuations, spot shapes and specular lobes.
//!
//! Layout: byte 0: bits 0–1 the lobe (Phong, Blinn–Phong, normalized Blinn–Phong, none), bits 2–3
//! the number of lights (0–3), bit 4 normalizes `n` and `v` first (the functions expect unit
//! vectors; raw bits rarely are); bytes 1–3: light `i`'s kind (bits 0–1: directional, point,
//! spot, spot), bit 2 `Attenuation::Punctual` (else `Polynomial`), bit 3 no range, bit 4 a
//! `SpotShape::Cone` (else `Warn`). From byte 4, little-endian f32 words: `p`, `n`, `v`, the
//! ambient intensity, the material's emission, `k_a`, `k_d`, `k_s` (three words each), the
//! shininess; then per light 14 words: position, direction, colour (three each), the attenuation's
//! three coefficients (the first is the range of a punctual one), the spot's exponent or inner
//! angle, and its outer angle. Missing bytes read as zero.
//!
//! Geometry, shininess, attenuation and spot parameters are raw bits (NaN, ∞, ±0, subnormals).
//! Colours and reflectances are the documented domain of the "no term is negative" promise:
//! non-negative and finite — the sign bit is cleared, an infinite or NaN pattern loses its top
//! exponent bit — and at most `1e6`, so no product of them overflows.
//!
//! Invariants (barytex-shade's crate documentation: nothing panics, no term is ever negative; and
//! each function's `# Special values`): every term of `shade` is neither NaN nor negative;
//! a light's sample, when there is one, has a unit `to_light` (within `1e-5`, as
//! `tests/lighting.rs::lights_never_panic_and_give_unit_directions` in barytex-shade) and an intensity
//! that is neither NaN nor negative; `Attenuation::factor` is never NaN or negative, in `[0, 1]`
//! for `Polynomial`, at most `10⁸` for `Punctual`; `SpotShape::factor` is in `[0, 1]`; Phong's and
//! Blinn's specular factors are in `[0, 1]`, the normalized lobe finite and non-negative.

use std::fmt::Write as _;

use barytex_shade::{Attenuation, Light, PhongMaterial, Specular, SpotShape};
use glam::Vec3;

use super::word;

/// Words of one light.
const LIGHT_WORDS: usize = 14;
/// Words before the lights.
const MATERIAL_WORDS: usize = 25;
/// Bytes the target reads: the four header bytes and 25 + 3 · 14 words.
pub const SHADE_LEN: usize = 4 + 4 * (MATERIAL_WORDS + 3 * LIGHT_WORDS);

/// A decoded `shade` input.
#[derive(Clone, Debug)]
pub struct ShadeInput {
    /// The material.
    pub material: PhongMaterial,
    /// The point.
    pub p: Vec3,
    /// The normal.
    pub n: Vec3,
    /// Towards the eye.
    pub v: Vec3,
    /// The lights.
    pub lights: Vec<Light>,
    /// The ambient intensity.
    pub ambient: Vec3,
}

/// A colour component from raw bits: non-negative, finite, at most `1e6`.
fn colour(bits: u32) -> f32 {
    let mut bits = bits & 0x7fff_ffff;
    if bits >> 23 == 0xff {
        bits &= !(1 << 30);
    }
    f32::from_bits(bits).min(1e6)
}

/// Decodes `bytes` (any length).
#[must_use]
pub fn shade_input(bytes: &[u8]) -> ShadeInput {
    let byte = |i: usize| bytes.get(i).copied().unwrap_or(0);
    let raw = |w: usize| f32::from_bits(word(&bytes[4.min(bytes.len())..], w));
    let bits = |w: usize| word(&bytes[4.min(bytes.len())..], w);
    let v3 = |w: usize| Vec3::new(raw(w), raw(w + 1), raw(w + 2));
    let c3 = |w: usize| Vec3::new(colour(bits(w)), colour(bits(w + 1)), colour(bits(w + 2)));
    let head = byte(0);
    let lobe = [
        Specular::Phong,
        Specular::BlinnPhong,
        Specular::NormalizedBlinnPhong,
        Specular::None,
    ][usize::from(head & 3)];
    let material = PhongMaterial {
        emission: c3(12),
        ambient: c3(15),
        diffuse: c3(18),
        specular: c3(21),
        shininess: raw(24),
        lobe,
    };
    let (mut n, mut v) = (v3(3), v3(6));
    if head & 16 != 0 {
        n = n.try_normalize().unwrap_or(n);
        v = v.try_normalize().unwrap_or(v);
    }
    let lights = (0..usize::from((head >> 2) & 3))
        .map(|i| {
            let desc = byte(1 + i);
            let w = MATERIAL_WORDS + LIGHT_WORDS * i;
            let attenuation = if desc & 4 != 0 {
                Attenuation::Punctual {
                    range: (desc & 8 == 0).then(|| raw(w + 9)),
                }
            } else {
                Attenuation::Polynomial {
                    constant: raw(w + 9),
                    linear: raw(w + 10),
                    quadratic: raw(w + 11),
                }
            };
            let shape = if desc & 16 != 0 {
                SpotShape::Cone {
                    inner: raw(w + 12),
                    outer: raw(w + 13),
                }
            } else {
                SpotShape::Warn {
                    exponent: raw(w + 12),
                }
            };
            match desc & 3 {
                0 => Light::Directional {
                    direction: v3(w + 3),
                    color: c3(w + 6),
                },
                1 => Light::Point {
                    position: v3(w),
                    color: c3(w + 6),
                    attenuation,
                },
                _ => Light::Spot {
                    position: v3(w),
                    direction: v3(w + 3),
                    color: c3(w + 6),
                    attenuation,
                    shape,
                },
            }
        })
        .collect();
    ShadeInput {
        material,
        p: v3(0),
        n,
        v,
        lights,
        ambient: c3(9),
    }
}

fn bad(x: f32) -> bool {
    x.is_nan() || x < 0.0
}

fn check_attenuation(a: Attenuation, d: f32) -> Result<(), String> {
    let f = a.factor(d);
    let ok = match a {
        Attenuation::Polynomial { .. } => (0.0..=1.0).contains(&f),
        Attenuation::Punctual { .. } => (0.0..=1e8).contains(&f),
    };
    if ok {
        Ok(())
    } else {
        Err(format!("{a:?}.factor({d}) = {f}"))
    }
}

/// The invariants (see the module documentation).
///
/// # Errors
/// A description of the first violated invariant.
pub fn check_shade(bytes: &[u8]) -> Result<(), String> {
    let ShadeInput {
        material,
        p,
        n,
        v,
        lights,
        ambient,
    } = shade_input(bytes);
    for light in &lights {
        if let Some(s) = light.sample(p) {
            let len = s.to_light.length();
            let unit = (len - 1.0).abs() <= 1e-5;
            if !unit || s.intensity.to_array().into_iter().any(bad) {
                return Err(format!("{light:?}.sample({p:?}) = {s:?}"));
            }
            let factor = material.lobe.factor(n, s.to_light, v, material.shininess);
            let ok = match material.lobe {
                Specular::NormalizedBlinnPhong => factor.is_finite() && factor >= 0.0,
                _ => (0.0..=1.0).contains(&factor),
            };
            if !ok {
                return Err(format!(
                    "{:?}.factor({n:?}, {:?}, {v:?}, {}) = {factor}",
                    material.lobe, s.to_light, material.shininess
                ));
            }
        }
        match *light {
            Light::Point { attenuation, .. } => check_attenuation(attenuation, p.x)?,
            Light::Spot {
                attenuation, shape, ..
            } => {
                check_attenuation(attenuation, p.x)?;
                let f = shape.factor(p.y);
                if !(0.0..=1.0).contains(&f) {
                    return Err(format!("{shape:?}.factor({}) = {f}", p.y));
                }
            }
            Light::Directional { .. } => {}
        }
    }
    let lit = material.shade(p, n, v, &lights, ambient);
    for (name, term) in [
        ("ambient", lit.ambient),
        ("diffuse", lit.diffuse),
        ("specular", lit.specular),
    ] {
        if term.to_array().into_iter().any(bad) {
            return Err(format!(
                "{name} term {term:?} of {material:?} at {p:?}, n {n:?}, v {v:?}, lights {lights:?}, ambient {ambient:?}"
            ));
        }
    }
    Ok(())
}

/// A failing input as a Rust block for a regression test.
#[must_use]
pub fn shade_code(bytes: &[u8]) -> String {
    let input = shade_input(bytes);
    let mut out = String::from("{\n");
    let _ = writeln!(out, "    // {input:?}");
    let _ = writeln!(out, "    let bytes: &[u8] = &{bytes:?};");
    out.push_str("    assert_eq!(check_shade(bytes), Ok(()));\n}");
    out
}
