//! Distance attenuation of point and spot lights (Foley et al., *Computer Graphics: Principles and
//! Practice*, 2nd ed., 1990, §16.1): the physically right `1/d²` changes too little far away and
//! too fast close up, so the book uses the aesthetic compromise
//! `f_att = min(1/(c1 + c2·d + c3·d²), 1)`.

/// The coefficients of `f_att = min(1/(c1 + c2·d + c3·d²), 1)`.
///
/// `Attenuation::NONE` (`c1 = 1`, the rest 0) leaves the light at full strength everywhere.
///
/// ```
/// use barytex_shade::Attenuation;
///
/// let att = Attenuation { constant: 1.0, linear: 0.0, quadratic: 1.0 };
/// assert_eq!(att.factor(0.0), 1.0);
/// assert_eq!(att.factor(1.0), 0.5);
/// assert_eq!(att.factor(3.0), 0.1);
/// // Never above 1, even when the denominator is below 1.
/// assert_eq!(Attenuation { constant: 0.1, linear: 0.0, quadratic: 0.0 }.factor(0.0), 1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation {
    /// `c1`.
    pub constant: f32,
    /// `c2`, per unit of distance.
    pub linear: f32,
    /// `c3`, per unit of distance squared.
    pub quadratic: f32,
}

impl Default for Attenuation {
    fn default() -> Self {
        Self::NONE
    }
}

impl Attenuation {
    /// No attenuation: `f_att = 1`.
    pub const NONE: Self = Self {
        constant: 1.0,
        linear: 0.0,
        quadratic: 0.0,
    };

    /// The physical inverse-square law `1/d²` (capped at 1 inside unit distance).
    pub const INVERSE_SQUARE: Self = Self {
        constant: 0.0,
        linear: 0.0,
        quadratic: 1.0,
    };

    /// `min(1/(c1 + c2·d + c3·d²), 1)` at distance `d`.
    ///
    /// # Special values
    /// Always in `[0, 1]`, never NaN: negative or NaN coefficients and distances count as 0; a
    /// denominator of at most 1 (0 included) gives 1; an infinite one gives 0.
    #[must_use]
    #[inline]
    pub fn factor(self, distance: f32) -> f32 {
        let pos = |x: f32| if x > 0.0 { x } else { 0.0 };
        let d = pos(distance);
        // A zero coefficient contributes nothing even at infinite distance (no 0·∞ = NaN).
        let term = |c: f32, x: f32| if c > 0.0 && x > 0.0 { c * x } else { 0.0 };
        let denominator = pos(self.constant) + term(self.linear, d) + term(self.quadratic, d * d);
        if denominator <= 1.0 {
            return 1.0;
        }
        1.0 / denominator
    }
}
