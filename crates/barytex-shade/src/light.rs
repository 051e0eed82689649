//! Light sources: directional (far away, one direction `L` everywhere), point (attenuated with
//! distance) and spot (a point light shaped by Warn's `(cos α)^p` lobe or by glTF's inner/outer
//! cone), evaluated at a surface point as a direction towards the light and an intensity.

use glam::Vec3;

use crate::Attenuation;

/// How a spot light's intensity falls off away from its axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpotShape {
    /// Warn's model (Warn 1983; Foley et al. 1990, §16.1): `I_p (cos α)^p`, α the angle between the
    /// spot axis and the ray from the light to the point; `p` is the reflector's specular exponent
    /// — the smaller, the wider the light spreads (`p = 0`: an ordinary point light over the front
    /// hemisphere).
    Warn {
        /// `p ≥ 0` (negative values count as 0).
        exponent: f32,
    },
    /// glTF `KHR_lights_punctual`: full intensity inside `inner`, none outside `outer` (both
    /// half-angles in radians), and between them the square of the linear ramp in `cos α`.
    Cone {
        /// Inner half-angle.
        inner: f32,
        /// Outer half-angle.
        outer: f32,
    },
}

impl SpotShape {
    /// The factor in `[0, 1]` for `cos α` (the cosine between the spot axis and the ray from the
    /// light to the point).
    ///
    /// # Special values
    /// NaN `cos α` gives 0; `cos α ≤ 0` gives 0 (nothing behind the spot); a cone with
    /// `inner ≥ outer` has a hard edge at `outer` (the ramp's width is clamped at 0.001 in cosine
    /// as in the glTF reference code).
    #[must_use]
    pub fn factor(self, cos_alpha: f32) -> f32 {
        if cos_alpha.is_nan() || cos_alpha <= 0.0 {
            return 0.0;
        }
        let c = cos_alpha.min(1.0);
        match self {
            Self::Warn { exponent } => {
                let p = if exponent > 0.0 { exponent } else { 0.0 };
                c.powf(p)
            }
            Self::Cone { inner, outer } => {
                let (cos_inner, cos_outer) = (inner.cos(), outer.cos());
                let scale = 1.0 / (cos_inner - cos_outer).max(0.001);
                let t = ((c - cos_outer) * scale).clamp(0.0, 1.0);
                if t.is_nan() { 0.0 } else { t * t }
            }
        }
    }
}

/// A light source. Colours are linear-light intensities `I_p` per channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// Infinitely far: every ray has the direction `direction` (the way the light travels).
    Directional {
        /// Direction of travel (need not be unit; zero or non-finite lights nothing).
        direction: Vec3,
        /// Intensity `I_p`.
        color: Vec3,
    },
    /// A point light.
    Point {
        /// Position.
        position: Vec3,
        /// Intensity `I_p` before attenuation.
        color: Vec3,
        /// Distance attenuation.
        attenuation: Attenuation,
    },
    /// A spot light: a point light with an angular falloff around `direction`.
    Spot {
        /// Position.
        position: Vec3,
        /// The spot axis, the way the light travels (need not be unit).
        direction: Vec3,
        /// Intensity `I_p` on the axis before attenuation.
        color: Vec3,
        /// Distance attenuation.
        attenuation: Attenuation,
        /// Angular falloff.
        shape: SpotShape,
    },
}

/// What a light delivers at one surface point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit vector from the point towards the light (`L`).
    pub to_light: Vec3,
    /// Intensity arriving at the point: `I_p` × attenuation × spot factor (each channel ≥ 0
    /// when the light's colour is).
    pub intensity: Vec3,
    /// Distance to the light (`f32::INFINITY` for directional lights).
    pub distance: f32,
}

impl Light {
    /// The light arriving at `point`, or `None` when it cannot be evaluated: a zero or
    /// non-finite direction, a point at the light's position, or non-finite input.
    ///
    /// ```
    /// use barytex_shade::{Attenuation, Light};
    /// use glam::Vec3;
    ///
    /// let light = Light::Point { position: Vec3::new(0.0, 2.0, 0.0), color: Vec3::ONE,
    ///     attenuation: Attenuation::INVERSE_SQUARE };
    /// let s = light.sample(Vec3::ZERO).expect("a regular point");
    /// assert_eq!(s.to_light, Vec3::Y);
    /// assert_eq!(s.intensity, Vec3::splat(0.25));
    /// ```
    #[must_use]
    pub fn sample(&self, point: Vec3) -> Option<LightSample> {
        match *self {
            Self::Directional { direction, color } => Some(LightSample {
                to_light: unit(-direction)?,
                intensity: color,
                distance: f32::INFINITY,
            }),
            Self::Point {
                position,
                color,
                attenuation,
            } => {
                let (to_light, distance) = towards(point, position)?;
                Some(LightSample {
                    to_light,
                    intensity: color * attenuation.factor(distance),
                    distance,
                })
            }
            Self::Spot {
                position,
                direction,
                color,
                attenuation,
                shape,
            } => {
                let (to_light, distance) = towards(point, position)?;
                let axis = unit(direction)?;
                let spot = shape.factor(axis.dot(-to_light));
                Some(LightSample {
                    to_light,
                    intensity: color * (attenuation.factor(distance) * spot),
                    distance,
                })
            }
        }
    }
}

/// Unit direction and distance from `from` to `to`; `None` when they coincide or are not finite
/// (the distance too: points more than `f32::MAX` apart).
fn towards(from: Vec3, to: Vec3) -> Option<(Vec3, f32)> {
    let d = to - from;
    let squared = d.length_squared();
    if squared.is_normal() {
        // The common case, on every shaded pixel: the squared length neither underflowed nor
        // overflowed, so one square root gives both.
        let distance = squared.sqrt();
        return Some((d / distance, distance));
    }
    let to_light = unit(d)?;
    // |d| = m·|d/m| with m the largest component: no underflow for subnormal offsets.
    let m = d.abs().max_element();
    let distance = m * (d / m).length();
    if !distance.is_finite() {
        return None;
    }
    Some((to_light, distance))
}

/// `v / |v|`, `None` for a zero or non-finite `v`. When the squared length underflows or
/// overflows, `v` is scaled by its largest component first (a direction of length 1e-22
/// normalized through its subnormal square came out 0.1 % too long).
fn unit(v: Vec3) -> Option<Vec3> {
    if v.length_squared().is_normal() {
        return v.try_normalize();
    }
    let m = v.abs().max_element();
    if !(m.is_finite() && m > 0.0) {
        return None;
    }
    (v / m).try_normalize()
}
