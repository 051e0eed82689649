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
