//! Participating media (Foley et al., *Computer Graphics: Principles and Practice*, 2nd ed., 1990,
//! §16.1, atmospheric attenuation; the Finnish lecture notes *Valaistus ja sävytys*, p. 280, for
//! exponential and height-dependent fog): the atmosphere dims distant points and shifts them
//! towards its own colour. The final colour is `I' = s0·I + (1 − s0)·I_dc`, where `s0 ∈ [0, 1]`
//! says how much of the object's own colour survives:
//!
//! - [`DepthCue`]: linear between a front and a back plane;
//! - [`ExponentialFog`]: `s0 = e^(−d_f·z_p)`, with `z_p` the **Euclidean** distance to the eye (the
//!   lecture notes' recommendation) or the view-space depth (cheaper, but it changes when the eye
//!   turns in place: [`FogDistance::ViewDepth`]);
//! - [`HeightFog`]: density falling exponentially with height, integrated exactly along the ray.

use glam::Vec3;

/// `s0·colour + (1 − s0)·fog`: the depth-cueing blend of Foley et al. (1990), §16.1 (`s0` clamped
/// to `[0, 1]`, NaN counts as 0, i.e. the point is fully hidden).
///
/// ```
/// use barytex_shade::atmosphere::blend;
/// use glam::Vec3;
/// assert_eq!(blend(Vec3::ONE, Vec3::ZERO, 0.25), Vec3::splat(0.25));
/// ```
#[must_use]
#[inline]
pub fn blend(colour: Vec3, fog: Vec3, s0: f32) -> Vec3 {
    let s = if s0 > 0.0 { s0.min(1.0) } else { 0.0 };
    colour * s + fog * (1.0 - s)
}

/// Depth cueing: `s0 = s_f` in front of the front plane, `s_b` behind the back plane, linear in
/// between (distances measured along the view direction from the eye).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthCue {
    /// Distance of the front plane.
    pub front: f32,
    /// Distance of the back plane.
    pub back: f32,
    /// `s_f ∈ [0, 1]`: how much of the object's colour survives at and before the front plane.
    pub s_front: f32,
    /// `s_b ∈ [0, 1]`: how much survives at and beyond the back plane.
    pub s_back: f32,
    /// The atmosphere's colour `I_dc`.
    pub colour: Vec3,
}

impl DepthCue {
    /// `s0` at view depth `z` (≥ 0 in front of the eye).
    ///
    /// # Special values
    /// NaN `z` gives `s_b` (as far as possible); `back ≤ front` switches at `front`. The result
    /// is `s_f` or `s_b` or between them.
    ///
    /// ```
    /// use barytex_shade::DepthCue;
    /// use glam::Vec3;
    /// let cue = DepthCue { front: 1.0, back: 3.0, s_front: 1.0, s_back: 0.0, colour: Vec3::ZERO };
    /// assert_eq!(cue.factor(0.5), 1.0);
    /// assert_eq!(cue.factor(2.0), 0.5);
    /// assert_eq!(cue.factor(9.0), 0.0);
    /// ```
    #[must_use]
    pub fn factor(&self, z: f32) -> f32 {
        if z.is_nan() {
            return self.s_back;
        }
        if z <= self.front {
            return self.s_front;
        }
        if z >= self.back || self.back <= self.front {
            return self.s_back;
        }
        let t = (z - self.front) / (self.back - self.front);
        self.s_front + (self.s_back - self.s_front) * t
    }

    /// The depth-cued colour `s0·I + (1 − s0)·I_dc` at view depth `z`.
    #[must_use]
    pub fn apply(&self, colour: Vec3, z: f32) -> Vec3 {
        blend(colour, self.colour, self.factor(z))
    }
}

/// What distance exponential fog is computed from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum FogDistance {
    /// `|p − eye|`: unchanged when the eye turns in place (the recommendation of the Finnish
    /// lecture notes *Valaistus ja sävytys*, p. 280).
    #[default]
    Euclidean,
    /// `(p − eye)·forward`: the view-space depth. Cheaper (it is already known), but a point's
    /// fog changes when the eye merely rotates, and it is too thin at the edges of the view.
    ViewDepth,
}

/// Exponential fog `s0 = e^(−density·z_p)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExponentialFog {
    /// `d_f ≥ 0`, per unit of distance.
    pub density: f32,
    /// The fog's colour.
    pub colour: Vec3,
    /// Which distance `z_p` is.
    pub distance: FogDistance,
}

impl ExponentialFog {
    /// `s0` for the point `p` seen from `eye` looking along the unit `forward`.
    ///
    /// # Special values
    /// In `[0, 1]`; distances behind the eye (view depth < 0) count as 0; NaN gives 0 (hidden).
    ///
    /// # Accuracy
    /// As `f32::exp`: within 2 ulps of `e^(−d_f z_p)` for the rounded product
    /// (`tests/lighting.rs::exponential_fog_matches_f64`).
    ///
    /// ```
    /// use barytex_shade::{ExponentialFog, FogDistance};
    /// use glam::Vec3;
    /// let fog = ExponentialFog { density: 0.5, colour: Vec3::ONE, distance: FogDistance::Euclidean };
    /// let s = fog.factor(Vec3::ZERO, -Vec3::Z, Vec3::new(0.0, 0.0, -2.0));
    /// assert!((s - (-1.0f32).exp()).abs() < 1e-7);
    /// ```
    #[must_use]
    pub fn factor(&self, eye: Vec3, forward: Vec3, p: Vec3) -> f32 {
        let d = match self.distance {
            FogDistance::Euclidean => (p - eye).length(),
            FogDistance::ViewDepth => (p - eye).dot(forward),
        };
        let d = if d > 0.0 {
            d
        } else if d.is_nan() {
            return 0.0;
        } else {
            0.0
        };
        let density = if self.density > 0.0 {
            self.density
        } else {
            0.0
        };
        let s = (-density * d).exp();
        if s.is_nan() { 0.0 } else { s }
    }

    /// The fogged colour of `colour` at `p`.
    #[must_use]
    pub fn apply(&self, colour: Vec3, eye: Vec3, forward: Vec3, p: Vec3) -> Vec3 {
        blend(colour, self.colour, self.factor(eye, forward, p))
    }
}

/// Fog whose density depends on the height above the ground (the "advanced medium model" of the
/// Finnish lecture notes *Valaistus ja sävytys*, p. 280): `ρ(y) = density·e^(−falloff·(y − base))`,
/// integrated exactly along the segment from the eye to the point, `s0 = e^(−∫ρ)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeightFog {
    /// Density at height `base`, per unit of distance (≥ 0).
    pub density: f32,
    /// How fast the density falls with height, per unit (0: uniform exponential fog).
    pub falloff: f32,
    /// Height of the reference level.
    pub base: f32,
    /// The fog's colour.
    pub colour: Vec3,
}

impl HeightFog {
    /// The optical depth `∫ρ` along the segment from `eye` to `p` (f64 inside).
    ///
    /// With `Δy = p_y − eye_y`, `d = |p − eye|`, `x = falloff·Δy`:
    /// `∫ρ = density·e^(−falloff·(eye_y − base))·d·(1 − e^(−x))/x`, with `(1 − e^(−x))/x → 1`
    /// evaluated by `expm1` (no cancellation on level rays).
    ///
    /// # Accuracy
    /// Relative error below 1e-6 against 4096-step Simpson integration in f64
    /// (`tests/lighting.rs::height_fog_matches_quadrature`).
    ///
    /// # Special values
    /// Never negative; NaN input gives `f32::INFINITY` (the point is hidden).
    #[must_use]
    pub fn optical_depth(&self, eye: Vec3, p: Vec3) -> f32 {
        let (e, q) = (eye.as_dvec3(), p.as_dvec3());
        let d = (q - e).length();
        let density = f64::from(self.density.max(0.0));
        let b = f64::from(self.falloff);
        let x = b * (q.y - e.y);
        let shape = if x.abs() < 1e-12 {
            1.0 - 0.5 * x
        } else {
            -(-x).exp_m1() / x
        };
        let tau = density * (-b * (e.y - f64::from(self.base))).exp() * d * shape;
        if tau.is_nan() {
            f32::INFINITY
        } else {
            tau.max(0.0) as f32
        }
    }

    /// `s0 = e^(−∫ρ)` in `[0, 1]`.
    #[must_use]
    pub fn factor(&self, eye: Vec3, p: Vec3) -> f32 {
        (-self.optical_depth(eye, p)).exp()
    }

    /// The fogged colour of `colour` at `p` seen from `eye`.
    #[must_use]
    pub fn apply(&self, colour: Vec3, eye: Vec3, p: Vec3) -> Vec3 {
        blend(colour, self.colour, self.factor(eye, p))
    }
}
