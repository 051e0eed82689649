//! Value noise: deterministic, seeded, smooth.

use glam::{Vec2, Vec4};

use crate::Sampler;

/// Value noise: a random value in [0, 1] at each integer lattice point of `uv·frequency`
/// (a hash of the point and the seed), blended with the smoothstep-weighted bilinear
/// interpolation; grey, opaque. Point-sampled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValueNoise {
    /// Lattice cells per unit of uv.
    pub frequency: f32,
    /// Selects the pattern.
    pub seed: u32,
}

fn hash(x: i64, y: i64, seed: u32) -> f32 {
    // SplitMix64 of the packed lattice point: well mixed, no state.
    let mut z = (x as u64)
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add((y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F))
        .wrapping_add(u64::from(seed));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 40) as f32 / (1u64 << 24) as f32
}

impl ValueNoise {
    /// The noise value at `uv` as an opaque grey; non-finite input gives transparent black, and
    /// huge finite input (beyond 2⁶³ lattice cells) a grey value, never a panic.
    ///
    /// ```
    /// use barytex_texture::procedural::ValueNoise;
    /// use glam::{Vec2, Vec4};
    ///
    /// let noise = ValueNoise { frequency: 8.0, seed: 7 };
    /// let g = noise.at(Vec2::new(0.3, 0.6));
    /// // Grey, opaque, in [0, 1], and the same every time.
    /// assert!(g.x == g.y && g.y == g.z && g.w == 1.0 && (0.0..=1.0).contains(&g.x));
    /// assert_eq!(noise.at(Vec2::new(0.3, 0.6)), g);
    /// // Continuous: a tiny step changes the value only slightly.
    /// assert!((noise.at(Vec2::new(0.300_01, 0.6)).x - g.x).abs() < 1e-3);
    /// // Another seed, another pattern (at a lattice point the value is the hash itself).
    /// let other = ValueNoise { seed: 8, ..noise };
    /// assert_ne!(other.at(Vec2::new(0.25, 0.5)), noise.at(Vec2::new(0.25, 0.5)));
    /// assert_eq!(noise.at(Vec2::splat(f32::INFINITY)), Vec4::ZERO);
    /// ```
    #[must_use]
    pub fn at(&self, uv: Vec2) -> Vec4 {
        let p = uv * self.frequency;
        if !p.is_finite() {
            return Vec4::ZERO;
        }
        let (fx, fy) = (p.x.floor(), p.y.floor());
        let (x, y) = (fx as i64, fy as i64);
        let smooth = |t: f32| t * t * (3.0 - 2.0 * t);
        let (tx, ty) = (smooth(p.x - fx), smooth(p.y - fy));
        // Beyond 2⁶³ the cast saturates: the neighbour wraps around the lattice (the pattern is
        // arbitrary there anyway) instead of overflowing.
        let (x1, y1) = (x.wrapping_add(1), y.wrapping_add(1));
        let top = hash(x, y, self.seed) + (hash(x1, y, self.seed) - hash(x, y, self.seed)) * tx;
        let bottom =
            hash(x, y1, self.seed) + (hash(x1, y1, self.seed) - hash(x, y1, self.seed)) * tx;
        let g = (top + (bottom - top) * ty).clamp(0.0, 1.0);
        Vec4::new(g, g, g, 1.0)
    }
}

impl Sampler for ValueNoise {
    fn sample(&self, uv: Vec2, _ddx: Vec2, _ddy: Vec2) -> Vec4 {
        self.at(uv)
    }

    fn sample_level(&self, uv: Vec2, _lod: f32) -> Vec4 {
        self.at(uv)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_and_non_finite_coordinates_never_panic() {
        // uv·frequency finite but far beyond 2⁶³ lattice cells.
        let noise = ValueNoise {
            frequency: 2.0,
            seed: 7,
        };
        for uv in [Vec2::splat(1e30), Vec2::splat(-1e30), Vec2::new(1e30, 3.0)] {
            let c = noise.at(uv);
            assert!(c.is_finite() && c.w == 1.0, "{uv}: {c}");
        }
        assert_eq!(noise.at(Vec2::NAN), Vec4::ZERO);
    }
}
