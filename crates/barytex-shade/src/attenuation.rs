//! Distance attenuation of point and spot lights, in the two forms renderers use: the
//! polynomial compromise `f_att = min(1/(c1 + c2·d + c3·d²), 1)` of Foley, van Dam, Feiner and
//! Hughes (*Computer Graphics: Principles and Practice*, 2nd ed., §16.1.5, eq. 16.8) — the
//! physically right `1/d²` changes too little far away and too fast close up — and glTF's
//! `KHR_lights_punctual` inverse-square law windowed to the light's `range`.

/// How a point or spot light's intensity falls off with distance `d`.
///
/// [`Attenuation::NONE`] leaves the light at full strength everywhere.
///
/// ```
/// use barytex_shade::Attenuation;
///
/// let att = Attenuation::Polynomial { constant: 1.0, linear: 0.0, quadratic: 1.0 };
/// assert_eq!(att.factor(0.0), 1.0);
/// assert_eq!(att.factor(1.0), 0.5);
/// assert_eq!(att.factor(3.0), 0.1);
/// // Never above 1, even when the denominator is below 1.
/// assert_eq!(Attenuation::Polynomial { constant: 0.1, linear: 0.0, quadratic: 0.0 }.factor(0.0), 1.0);
/// // glTF: 1/d², windowed to zero at the range.
/// let gltf = Attenuation::Punctual { range: Some(4.0) };
/// assert_eq!(gltf.factor(0.5), 4.0 * (1.0 - 0.125_f32.powi(4)));
/// assert_eq!(gltf.factor(4.0), 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Attenuation {
    /// `min(1/(c1 + c2·d + c3·d²), 1)`.
    Polynomial {
        /// `c1`.
        constant: f32,
        /// `c2`, per unit of distance.
        linear: f32,
        /// `c3`, per unit of distance squared.
        quadratic: f32,
    },
    /// glTF `KHR_lights_punctual` (the extension's recommended falloff):
    /// `clamp(1 − (d/range)⁴, 0, 1) / max(d², 10⁻⁸)`. Not capped at 1: intensities are in
    /// candela, and the light is that bright at one unit of distance.
    Punctual {
        /// Where the light's influence ends; `None`, zero, negative or NaN is infinite.
        range: Option<f32>,
    },
}

impl Default for Attenuation {
    fn default() -> Self {
        Self::NONE
    }
}

impl Attenuation {
    /// No attenuation: `f_att = 1`.
    pub const NONE: Self = Self::Polynomial {
        constant: 1.0,
        linear: 0.0,
        quadratic: 0.0,
    };

    /// The inverse-square law `1/d²` capped at 1 inside unit distance.
    pub const INVERSE_SQUARE: Self = Self::Polynomial {
        constant: 0.0,
        linear: 0.0,
        quadratic: 1.0,
    };

    /// The factor at distance `d`.
    ///
    /// # Special values
    /// Never NaN or negative. Polynomial: in `[0, 1]`; negative or NaN coefficients and distances
    /// count as 0; a denominator of at most 1 (0 included) gives 1; an infinite one gives 0.
    /// Punctual: NaN, negative and infinite distances give 0; distances below 10⁻⁴ give 10⁸.
    #[must_use]
    #[inline]
    pub fn factor(self, distance: f32) -> f32 {
        match self {
            Self::Polynomial {
                constant,
                linear,
                quadratic,
            } => polynomial(constant, linear, quadratic, distance),
            Self::Punctual { range } => punctual(range, distance),
        }
    }
}

fn polynomial(constant: f32, linear: f32, quadratic: f32, distance: f32) -> f32 {
    let pos = |x: f32| if x > 0.0 { x } else { 0.0 };
    let d = pos(distance);
    // A zero coefficient contributes nothing even at infinite distance (no 0·∞ = NaN).
    let term = |c: f32, x: f32| if c > 0.0 && x > 0.0 { c * x } else { 0.0 };
    let denominator = pos(constant) + term(linear, d) + term(quadratic, d * d);
    if denominator <= 1.0 {
        return 1.0;
    }
    1.0 / denominator
}

fn punctual(range: Option<f32>, distance: f32) -> f32 {
    if !(distance >= 0.0 && distance.is_finite()) {
        return 0.0;
    }
    let window = match range {
        Some(r) if r > 0.0 => {
            let x = distance / r;
            (1.0 - x * x * x * x).clamp(0.0, 1.0)
        }
        _ => 1.0,
    };
    window / (distance * distance).max(1e-8)
}
