//! Level of detail from screen-space derivatives (L. Yan, GAMES101, Lecture 9: `D = log₂ L`;
//! Vulkan 1.3 "Scale Factor Operation" and "Level-of-Detail Operation"; OpenGL 4.6 core
//! §8.14.1).
//!
//! `ρ = max(|∂uv/∂x|, |∂uv/∂y|)` measured in texels of the base level, `λ = log₂ ρ`: the
//! footprint of one pixel is `2^λ` texels across, so level `λ` has about one texel per pixel.

use glam::Vec2;

/// The level of detail `log₂ max(|ddx·size|, |ddy·size|)` before bias and clamping.
///
/// `size` is the base level's `(width, height)` in texels. A zero footprint gives `−∞`
/// (magnification); a non-finite derivative gives `+∞` (the most blurred level: a footprint that
/// cannot be measured is treated as covering the whole texture, which never aliases).
///
/// # Accuracy
/// Within 2 ulp of `log₂` of the exactly computed `ρ` (the lengths are computed in f64 from f32
/// inputs, the logarithm by `f64::log2`, then rounded once).
///
/// ```
/// use barytex_texture::sampler::lod::lod;
/// use glam::Vec2;
///
/// // On a 256² texture, one pixel spanning 4 texels along x (and 1 along y) is level 2.
/// assert_eq!(lod(Vec2::new(4.0 / 256.0, 0.0), Vec2::new(0.0, 1.0 / 256.0), (256, 256)), 2.0);
/// assert_eq!(lod(Vec2::ZERO, Vec2::ZERO, (256, 256)), f32::NEG_INFINITY);
/// assert_eq!(lod(Vec2::NAN, Vec2::ZERO, (256, 256)), f32::INFINITY);
/// ```
#[must_use]
#[inline]
pub fn lod(ddx: Vec2, ddy: Vec2, size: (u32, u32)) -> f32 {
    let rho_squared = footprint_squared(ddx, ddy, size);
    if rho_squared.is_nan() || rho_squared == f64::INFINITY {
        return f32::INFINITY;
    }
    (0.5 * rho_squared.log2()) as f32
}

/// `ρ²` in f64: the larger squared length of the two derivative vectors in texels. NaN if a
/// derivative is NaN.
#[must_use]
#[inline]
pub(crate) fn footprint_squared(ddx: Vec2, ddy: Vec2, size: (u32, u32)) -> f64 {
    let (w, h) = (f64::from(size.0), f64::from(size.1));
    let len2 = |d: Vec2| {
        let (x, y) = (f64::from(d.x) * w, f64::from(d.y) * h);
        x * x + y * y
    };
    let (a, b) = (len2(ddx), len2(ddy));
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_texel_per_pixel_is_level_zero() {
        assert_eq!(
            lod(
                Vec2::new(1.0 / 256.0, 0.0),
                Vec2::new(0.0, 1.0 / 256.0),
                (256, 256)
            ),
            0.0
        );
        assert_eq!(
            lod(
                Vec2::new(4.0 / 256.0, 0.0),
                Vec2::new(0.0, 1.0 / 256.0),
                (256, 256)
            ),
            2.0
        );
        // The larger of the two axes decides.
        assert_eq!(
            lod(Vec2::new(0.0, 0.0), Vec2::new(0.0, 8.0 / 64.0), (256, 64)),
            3.0
        );
    }

    #[test]
    fn degenerate_footprints_have_documented_levels() {
        assert_eq!(lod(Vec2::ZERO, Vec2::ZERO, (16, 16)), f32::NEG_INFINITY);
        assert_eq!(lod(Vec2::NAN, Vec2::ZERO, (16, 16)), f32::INFINITY);
        assert_eq!(
            lod(Vec2::splat(f32::INFINITY), Vec2::ZERO, (16, 16)),
            f32::INFINITY
        );
        assert_eq!(
            lod(Vec2::splat(f32::MAX), Vec2::ZERO, (16, 16)),
            (0.5 * (2.0 * (f64::from(f32::MAX) * 16.0).powi(2)).log2()) as f32
        );
    }
}
