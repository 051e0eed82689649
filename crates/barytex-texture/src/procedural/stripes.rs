//! Stripes at any angle.

use glam::{Vec2, Vec4};

use crate::Sampler;

/// Parallel stripes: `on` for a fraction `duty` of each period, `off` for the rest, across the
/// direction at `angle` radians from the u axis. Point-sampled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stripes {
    /// Colour of the stripes.
    pub on: Vec4,
    /// Colour between them.
    pub off: Vec4,
    /// Direction across the stripes, radians from +u.
    pub angle: f32,
    /// Period in uv units.
    pub period: f32,
    /// Fraction of the period that is `on`, in [0, 1].
    pub duty: f32,
}

impl Stripes {
    /// The colour at `uv`; non-finite input gives transparent black.
    ///
    /// ```
    /// use barytex_texture::procedural::Stripes;
    /// use glam::{Vec2, Vec4};
    ///
    /// // Vertical stripes (varying along u), 0.25 wide on a period of 1.
    /// let stripes = Stripes { on: Vec4::ONE, off: Vec4::ZERO, angle: 0.0, period: 1.0, duty: 0.25 };
    /// assert_eq!(stripes.at(Vec2::new(0.1, 0.9)), Vec4::ONE);
    /// assert_eq!(stripes.at(Vec2::new(0.3, 0.9)), Vec4::ZERO);
    /// assert_eq!(stripes.at(Vec2::new(1.1, 0.0)), Vec4::ONE); // the next period
    /// // Turned a quarter turn, they vary along v instead.
    /// let turned = Stripes { angle: std::f32::consts::FRAC_PI_2, ..stripes };
    /// assert_eq!(turned.at(Vec2::new(0.3, 0.1)), Vec4::ONE);
    /// ```
    #[must_use]
    pub fn at(&self, uv: Vec2) -> Vec4 {
        let (s, c) = self.angle.sin_cos();
        let phase = (uv.x * c + uv.y * s) / self.period;
        if !phase.is_finite() {
            return Vec4::ZERO;
        }
        if phase - phase.floor() < self.duty {
            self.on
        } else {
            self.off
        }
    }
}

impl Sampler for Stripes {
    fn sample(&self, uv: Vec2, _ddx: Vec2, _ddy: Vec2) -> Vec4 {
        self.at(uv)
    }

    fn sample_level(&self, uv: Vec2, _lod: f32) -> Vec4 {
        self.at(uv)
    }
}
