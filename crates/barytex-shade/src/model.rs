//! The local illumination models of Foley et al., *Computer Graphics: Principles and Practice*,
//! 2nd ed., 1990, §16.1, and Blinn–Phong (Blinn 1977), as pure functions: emission
//! `I = k_i`, ambient `I = I_a k_a`, Lambert's diffuse `I = I_p k_d (N·L)`, Phong's specular
//! `I = I_p W(θ) (cos α)^n` with `W(θ) = k_s`, and Blinn's half-vector variant — and a
//! [`PhongMaterial`] that sums them over lights. Usable by the rasterizer's shaders and by a ray
//! tracer alike: everything is in one space the caller chooses (world space in this crate's
//! shaders).

use glam::Vec3;

use crate::light::{Light, LightSample};

/// `max(x, 0)` that maps NaN to 0.
#[inline]
pub(crate) fn clamp_positive(x: f32) -> f32 {
    if x > 0.0 { x } else { 0.0 }
}

/// Lambert's cosine `max(N·L, 0)` for unit `n` and `l`, clamped to `[0, 1]` (NaN gives 0).
///
/// Clamping at 0 keeps light arriving from behind the surface from subtracting; clamping at 1
/// keeps slightly non-unit inputs from amplifying it.
#[must_use]
#[inline]
pub fn lambert(n: Vec3, l: Vec3) -> f32 {
    clamp_positive(n.dot(l)).min(1.0)
}

/// Phong's specular factor `(cos α)^n = max(R·V, 0)^n` with the mirror direction
/// `R = 2(N·L)N − L`, for unit `n` (normal), `l` (to the light), `v` (to the eye).
///
/// Zero when the light is behind the surface (`N·L ≤ 0`): a highlight cannot appear on the
/// unlit side. Always in `[0, 1]`; NaN input gives 0; `shininess ≤ 0` counts as 0 (the factor is
/// then 1 wherever `R·V > 0`).
#[must_use]
#[inline]
pub fn phong_specular(n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> f32 {
    let nl = n.dot(l);
    if nl.is_nan() || nl <= 0.0 {
        return 0.0;
    }
    let r = 2.0 * nl * n - l;
    power(r.dot(v), shininess)
}

/// Blinn's specular factor `max(N·H, 0)^n` with the half vector `H = (L + V)/|L + V|`, for unit
/// `n`, `l`, `v`. Zero when `N·L ≤ 0` or `L = −V`; in `[0, 1]`; NaN gives 0.
///
/// Cheaper than Phong's when the light and the eye are far away (`H` is then constant), and its
/// lobe is wider: `(N·H)^{4n}` approximates `(R·V)^n` near the peak.
#[must_use]
#[inline]
pub fn blinn_phong_specular(n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> f32 {
    let nl = n.dot(l);
    if nl.is_nan() || nl <= 0.0 {
        return 0.0;
    }
    let Some(h) = (l + v).try_normalize() else {
        return 0.0;
    };
    power(n.dot(h), shininess)
}

/// The energy-normalized Blinn lobe times the cosine of incidence,
/// `(n + 8)/(8π) · max(N·H, 0)^n · (N·L)` for unit `n`, `l`, `v` ([`Specular::NormalizedBlinnPhong`]).
///
/// Zero when `N·L ≤ 0` or `L = −V`; never negative; NaN input, and a result that would not be
/// finite (an infinite exponent or normal), give 0. Unlike the classic lobes it is not bounded by
/// 1: the normalization makes the lobe integrate to at most 1 over the hemisphere, so its peak
/// grows with `n`.
///
/// ```
/// use barytex_shade::normalized_blinn_phong_specular;
/// use glam::Vec3;
///
/// // Light and eye along the normal: the peak, (n + 8)/(8π).
/// let peak = normalized_blinn_phong_specular(Vec3::Z, Vec3::Z, Vec3::Z, 16.0);
/// assert!((peak - 24.0 / (8.0 * std::f32::consts::PI)).abs() < 1e-6);
/// assert_eq!(normalized_blinn_phong_specular(Vec3::Z, -Vec3::Z, Vec3::Z, 16.0), 0.0);
/// ```
#[must_use]
#[inline]
pub fn normalized_blinn_phong_specular(n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> f32 {
    let nl = n.dot(l);
    if nl.is_nan() || nl <= 0.0 {
        return 0.0;
    }
    let h = (l + v).normalize_or_zero();
    let shininess = clamp_positive(shininess);
    let lobe =
        (shininess + 8.0) / (8.0 * core::f32::consts::PI) * n.dot(h).max(0.0).powf(shininess);
    let out = nl * lobe;
    if out.is_finite() { out } else { 0.0 }
}

/// `clamp(c, 0, 1)^n`, 0 for NaN `c`, exponent clamped at 0.
#[inline]
pub(crate) fn power(c: f32, shininess: f32) -> f32 {
    let c = clamp_positive(c).min(1.0);
    if c == 0.0 {
        return 0.0;
    }
    c.powf(clamp_positive(shininess))
}

/// Which specular lobe a [`PhongMaterial`] uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Specular {
    /// Phong's `(R·V)^n` (Phong 1975; Foley et al. 1990, §16.1).
    #[default]
    Phong,
    /// Blinn's `(N·H)^n`.
    BlinnPhong,
    /// Blinn's lobe normalized to conserve energy and weighted by the cosine of incidence:
    /// `(n + 8)/(8π) · (N·H)^n · (N·L)` (Akenine-Möller, Haines, Hoffman, *Real-Time
    /// Rendering*, 3rd ed., §7.6, eq. 7.49). With `k_d = 1/π` this is the physically based
    /// Blinn–Phong that barytex-render lights glTF's metallic-roughness materials with.
    NormalizedBlinnPhong,
    /// No specular term.
    None,
}

impl Specular {
    /// The factor of this lobe for unit `n`, `l`, `v`.
    #[must_use]
    #[inline]
    pub fn factor(self, n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> f32 {
        match self {
            Self::Phong => phong_specular(n, l, v, shininess),
            Self::BlinnPhong => blinn_phong_specular(n, l, v, shininess),
            Self::NormalizedBlinnPhong => normalized_blinn_phong_specular(n, l, v, shininess),
            Self::None => 0.0,
        }
    }
}

/// Surface reflectances (linear light, per channel, usually in `[0, 1]`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhongMaterial {
    /// `k_i`: light the surface emits by itself.
    pub emission: Vec3,
    /// `k_a`: reflectance for the ambient light `I_a`.
    pub ambient: Vec3,
    /// `k_d`: Lambertian (matte) reflectance.
    pub diffuse: Vec3,
    /// `k_s = W(θ)`: specular reflectance.
    pub specular: Vec3,
    /// Phong exponent `n` (1 … several hundred; larger is a more perfect mirror).
    pub shininess: f32,
    /// The specular lobe.
    pub lobe: Specular,
}

impl Default for PhongMaterial {
    /// White plastic: `k_a = k_d = 0.7`, `k_s = 0.3`, `n = 32`, Phong lobe, no emission.
    fn default() -> Self {
        Self {
            emission: Vec3::ZERO,
            ambient: Vec3::splat(0.7),
            diffuse: Vec3::splat(0.7),
            specular: Vec3::splat(0.3),
            shininess: 32.0,
            lobe: Specular::Phong,
        }
    }
}

/// The terms of one evaluation, kept apart so that callers (texturing, Gouraud + Phong) can
/// recombine them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lighting {
    /// `k_i + I_a k_a`.
    pub ambient: Vec3,
    /// `Σ I_p k_d (N·L)`.
    pub diffuse: Vec3,
    /// `Σ I_p k_s (cos α)^n`.
    pub specular: Vec3,
}

impl Lighting {
    /// The sum of the terms.
    #[must_use]
    #[inline]
    pub fn total(self) -> Vec3 {
        self.ambient + self.diffuse + self.specular
    }
}

impl PhongMaterial {
    /// Lights the point `p` with unit normal `n` seen along the unit vector `v` (from the point
    /// to the eye) by `lights` and the ambient intensity `ambient`:
    /// `I = k_i + I_a k_a + Σ I_p (k_d (N·L) + k_s (cos α)^n)`.
    ///
    /// # Special values
    /// Non-finite or zero `n` or `v` give the ambient and emission terms only; lights that cannot
    /// be evaluated at `p` ([`Light::sample`] is `None`) are skipped. With non-negative
    /// reflectances and intensities no term is negative.
    ///
    /// ```
    /// use barytex_shade::{Light, PhongMaterial, Specular};
    /// use glam::Vec3;
    ///
    /// let m = PhongMaterial { specular: Vec3::ZERO, lobe: Specular::None, ..PhongMaterial::default() };
    /// let sun = Light::Directional { direction: -Vec3::Y, color: Vec3::ONE };
    /// // Lit head-on: k_d·I_p; no ambient light.
    /// let c = m.shade(Vec3::ZERO, Vec3::Y, Vec3::Y, &[sun], Vec3::ZERO);
    /// assert_eq!(c.total(), Vec3::splat(0.7));
    /// ```
    #[must_use]
    pub fn shade(&self, p: Vec3, n: Vec3, v: Vec3, lights: &[Light], ambient: Vec3) -> Lighting {
        let mut out = Lighting {
            ambient: self.emission + ambient * self.ambient,
            ..Lighting::default()
        };
        if !(n.is_finite() && v.is_finite()) || n == Vec3::ZERO || v == Vec3::ZERO {
            return out;
        }
        for light in lights {
            let Some(sample) = light.sample(p) else {
                continue;
            };
            // A light that does not reach the point (outside its cone or range) or lights it
            // from behind adds exactly zero: skip the lobe's normalization and power, the
            // costly part of a shaded pixel.
            if sample.intensity == Vec3::ZERO || n.dot(sample.to_light) <= 0.0 {
                continue;
            }
            let (d, s) = self.reflect(n, v, &sample);
            out.diffuse += d;
            out.specular += s;
        }
        out
    }

    /// Diffuse and specular light reflected from one light sample.
    #[must_use]
    #[inline]
    pub fn reflect(&self, n: Vec3, v: Vec3, sample: &LightSample) -> (Vec3, Vec3) {
        let l = sample.to_light;
        let diffuse = sample.intensity * self.diffuse * lambert(n, l);
        let spec = self.lobe.factor(n, l, v, self.shininess);
        (diffuse, sample.intensity * self.specular * spec)
    }
}
