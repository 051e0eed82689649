//! Filtering within one mip level: nearest, bilinear, bicubic. All return **premultiplied**
//! linear colour; texel addressing follows the Vulkan formulas of [`crate::addressing`].

use glam::{Vec2, Vec4};

use crate::addressing::{linear_taps, nearest_index, wrap};
use crate::sampler::CubicKernel;
use crate::sampler::texel_fetch::{Addressing, fetch, fetch_wrapped};
use crate::{Texel, Texture2d};

/// The texel containing `uv` (`⌊u·w⌋`, `⌊v·h⌋`).
#[must_use]
#[inline(always)]
pub(crate) fn nearest<T: Texel>(level: &Texture2d<T>, uv: Vec2, a: &Addressing) -> Vec4 {
    let (w, h) = level.size();
    fetch(level, nearest_index(uv.x, w), nearest_index(uv.y, h), a)
}

/// Bilinear: two horizontal lerps, then one vertical (L. Yan, GAMES101, Lecture 9), in the form
/// `a + (b − a)·t`, so a texel centre returns that texel exactly and a constant stays constant
/// exactly.
#[must_use]
#[inline(always)]
pub(crate) fn bilinear<T: Texel>(level: &Texture2d<T>, uv: Vec2, a: &Addressing) -> Vec4 {
    let (w, h) = level.size();
    let tx = linear_taps(uv.x, w);
    let ty = linear_taps(uv.y, h);
    // Each axis index is wrapped once, not once per tap. Saturating: a saturated index's
    // neighbour is itself.
    let (x0, x1) = (wrap(tx.i0, w, a.u), wrap(tx.i0.saturating_add(1), w, a.u));
    let (y0, y1) = (wrap(ty.i0, h, a.v), wrap(ty.i0.saturating_add(1), h, a.v));
    let c00 = fetch_wrapped(level, x0, y0, a);
    let c10 = fetch_wrapped(level, x1, y0, a);
    let c01 = fetch_wrapped(level, x0, y1, a);
    let c11 = fetch_wrapped(level, x1, y1, a);
    let top = c00 + (c10 - c00) * tx.frac;
    let bottom = c01 + (c11 - c01) * tx.frac;
    top + (bottom - top) * ty.frac
}

/// Bicubic over the 4×4 texels around `uv`, separable, with the weights of `kernel`.
#[must_use]
pub(crate) fn bicubic<T: Texel>(
    level: &Texture2d<T>,
    uv: Vec2,
    kernel: CubicKernel,
    a: &Addressing,
) -> Vec4 {
    let (w, h) = level.size();
    let tx = linear_taps(uv.x, w);
    let ty = linear_taps(uv.y, h);
    let wx = kernel.taps(tx.frac);
    let wy = kernel.taps(ty.frac);
    let mut sum = Vec4::ZERO;
    for (j, wyj) in wy.iter().enumerate() {
        let y = ty.i0.saturating_add(j as i64 - 1);
        let mut row = Vec4::ZERO;
        for (i, wxi) in wx.iter().enumerate() {
            row += fetch(level, tx.i0.saturating_add(i as i64 - 1), y, a) * *wxi;
        }
        sum += row * *wyj;
    }
    sum
}
