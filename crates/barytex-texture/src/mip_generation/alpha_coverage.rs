//! Alpha-coverage preservation (Castaño, "Computing Alpha Mipmaps", 2010): scale a level's alpha
//! so that the fraction of texels passing an alpha test matches the base level's.

use crate::{Texel, Texture2d};

/// The fraction of texels whose alpha is at least `reference`.
pub(crate) fn coverage<T: Texel>(texture: &Texture2d<T>, reference: f32) -> f32 {
    let passing = texture
        .texels()
        .iter()
        .filter(|t| t.to_linear().w >= reference)
        .count();
    passing as f32 / texture.texels().len() as f32
}

/// Scales `level`'s alpha by the factor (found by bisection) that brings its coverage closest to
/// `target`; alpha is clamped to [0, 1].
pub(crate) fn preserve<T: Texel>(level: &mut Texture2d<T>, reference: f32, target: f32) {
    let alphas: Vec<f32> = level.texels().iter().map(|t| t.to_linear().w).collect();
    let covered = |scale: f32| {
        alphas
            .iter()
            .filter(|&&a| (a * scale).min(1.0) >= reference)
            .count() as f32
            / alphas.len() as f32
    };
    // Coverage grows with the scale; bisect in [0, 64].
    let (mut lo, mut hi) = (0.0_f32, 64.0_f32);
    for _ in 0..24 {
        let mid = 0.5 * (lo + hi);
        if covered(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let scale = if (covered(hi) - target).abs() <= (covered(lo) - target).abs() {
        hi
    } else {
        lo
    };
    for texel in level.texels_mut() {
        let mut c = texel.to_linear();
        c.w = (c.w * scale).min(1.0);
        *texel = T::from_linear(c);
    }
}
