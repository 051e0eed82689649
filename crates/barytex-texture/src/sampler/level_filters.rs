//! Filtering within one mip level: nearest, bilinear, bicubic. All return **premultiplied**
//! linear colour; texel addressing follows the Vulkan formulas of [`crate::addressing`].

use glam::{Vec2, Vec4};

use crate::addressing::{LinearTaps, linear_taps, nearest_index, wrap};
use crate::sampler::CubicKernel;
use crate::sampler::texel_fetch::{Addressing, fetch, fetch_wrapped, premultiply};
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

/// [`bilinear`] with each axis's address mode resolved when sampler and texture meet: under
/// [`AddressMode::Repeat`] over a power-of-two side (`CLAMP_*` false) [`wrap`] is `i & (size − 1)`
/// for every index, inside or not (its power-of-two branch; an inside index keeps its low
/// bits); under [`AddressMode::ClampToEdge`] (`CLAMP_*` true) it is `i.clamp(0, size − 1)` for
/// every index (an inside index is its own clamp). Repeat on both axes is the configuration
/// most textures are sampled with, clamp-to-edge the other one glTF samplers name, and
/// environment maps repeat across and clamp down. The in-range test and the address-mode
/// dispatch go and the four texel reads need no border case. The same indices and weights in
/// the same order, so the same value (bit for bit; `tests/lookup_paths.rs` compares the two).
///
/// [`AddressMode::Repeat`]: crate::sampler::AddressMode::Repeat
/// [`AddressMode::ClampToEdge`]: crate::sampler::AddressMode::ClampToEdge
///
/// `OPAQUE`: every texel of the level is opaque ([`Texel::is_opaque`]), so premultiplying
/// (a product by exactly 1) is skipped; the same result, bit for bit.
#[must_use]
#[inline(always)]
pub(crate) fn bilinear_resolved<
    T: Texel,
    const OPAQUE: bool,
    const CLAMP_U: bool,
    const CLAMP_V: bool,
>(
    level: &Texture2d<T>,
    uv: Vec2,
) -> Vec4 {
    let (w, h) = level.size();
    let (tx, ty) = linear_taps_pair(uv, w, h);
    let (x0, x1) = resolved_pair::<CLAMP_U>(tx.i0, w);
    let (y0, y1) = resolved_pair::<CLAMP_V>(ty.i0, h);
    let (texels, stride) = (level.texels(), w as usize);
    let (row0, row1) = (
        &texels[y0 * stride..][..stride],
        &texels[y1 * stride..][..stride],
    );
    let fetch = |t: T| {
        if OPAQUE {
            t.to_linear_opaque()
        } else {
            premultiply(t.to_linear())
        }
    };
    let c00 = fetch(row0[x0]);
    let c10 = fetch(row0[x1]);
    let c01 = fetch(row1[x0]);
    let c11 = fetch(row1[x1]);
    let top = c00 + (c10 - c00) * tx.frac;
    let bottom = c01 + (c11 - c01) * tx.frac;
    top + (bottom - top) * ty.frac
}

/// The addresses of taps `i0` and `i0 + 1` on an axis of `size` texels (≥ 1): clamped to the
/// edge, or masked (repeat over a power-of-two side). Saturating as in `bilinear`: a saturated
/// index's neighbour is itself.
#[inline(always)]
fn resolved_pair<const CLAMP: bool>(i0: i64, size: u32) -> (usize, usize) {
    let last = i64::from(size) - 1;
    let i1 = i0.saturating_add(1);
    if CLAMP {
        (i0.clamp(0, last) as usize, i1.clamp(0, last) as usize)
    } else {
        ((i0 & last) as usize, (i1 & last) as usize)
    }
}

/// [`linear_taps`] on both axes at once. On x86-64 the common case — both `u·w − ½` and
/// `v·h − ½` within ±2³¹ — runs in one SSE2 register pair: the products are the same exact f64
/// values, truncation to i32 is exact there, the floor is the truncation less one below a
/// negative non-integer, and the fraction `x − ⌊x⌋` is exact in f64 and rounded once to f32 (as
/// in `linear_taps`); the general scalar path takes everything else (huge or non-finite
/// coordinates). The same taps for every input (tested against `linear_taps`).
#[inline(always)]
pub(crate) fn linear_taps_pair(uv: Vec2, w: u32, h: u32) -> (LinearTaps, LinearTaps) {
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    {
        use safe_arch::{
            bitand_m128d, cmp_gt_mask_m128d, cmp_lt_mask_m128d, convert_to_m128_from_m128d,
            convert_to_m128d_from_lower2_i32_m128i, get_i64_from_m128i_s, move_mask_m128d,
            mul_m128d, set_m128d, set_splat_m128d, sub_m128d, truncate_m128d_to_m128i,
        };
        let x = sub_m128d(
            mul_m128d(
                set_m128d(f64::from(uv.y), f64::from(uv.x)),
                set_m128d(f64::from(h), f64::from(w)),
            ),
            set_splat_m128d(0.5),
        );
        // |x| < 2³¹ on both lanes (false for NaN): i32 truncation is exact.
        let magnitude = bitand_m128d(x, set_splat_m128d(f64::from_bits(!(1 << 63))));
        if move_mask_m128d(cmp_lt_mask_m128d(
            magnitude,
            set_splat_m128d(2_147_483_648.0),
        )) == 0b11
        {
            let t = convert_to_m128d_from_lower2_i32_m128i(truncate_m128d_to_m128i(x));
            // t > x: a negative non-integer, whose floor is one below its truncation.
            let floor = sub_m128d(
                t,
                bitand_m128d(cmp_gt_mask_m128d(t, x), set_splat_m128d(1.0)),
            );
            let [fx, fy, ..] = convert_to_m128_from_m128d(sub_m128d(x, floor)).to_array();
            let i = get_i64_from_m128i_s(truncate_m128d_to_m128i(floor));
            return (
                LinearTaps {
                    i0: i64::from(i as i32),
                    frac: fx,
                },
                LinearTaps {
                    i0: i >> 32,
                    frac: fy,
                },
            );
        }
    }
    (linear_taps(uv.x, w), linear_taps(uv.y, h))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_taps_pair_equals_linear_taps_per_axis() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut values = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            1e-30,
            -1e-30,
            f32::MIN_POSITIVE,
            1e9,
            -1e9,
            3e38,
            -3e38,
            f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        for _ in 0..20_000 {
            let r = next();
            // Small coordinates, texel centres and edges, and arbitrary bit patterns.
            values.push((r as u32 as f32 / u32::MAX as f32) * 8.0 - 4.0);
            values.push(((r >> 32) % 4096) as f32 / 1024.0 - 2.0);
            values.push(f32::from_bits(r as u32));
        }
        // Coordinates just below and above ±2³¹ texels on a 2¹⁰ side.
        for k in -8_i32..=8 {
            let edge = 2_147_483_648.0_f32 / 1024.0;
            values.push(f32::from_bits((edge.to_bits() as i32 + k) as u32));
            values.push(-f32::from_bits((edge.to_bits() as i32 + k) as u32));
        }
        let sizes = [1, 2, 3, 4, 64, 1024, 1 << 20, u32::MAX];
        for (k, &u) in values.iter().enumerate() {
            let v = values[(k * 7 + 3) % values.len()];
            let (w, h) = (sizes[k % sizes.len()], sizes[(k / 3) % sizes.len()]);
            let (tx, ty) = linear_taps_pair(Vec2::new(u, v), w, h);
            let (ex, ey) = (linear_taps(u, w), linear_taps(v, h));
            assert_eq!(
                (tx.i0, tx.frac.to_bits(), ty.i0, ty.frac.to_bits()),
                (ex.i0, ex.frac.to_bits(), ey.i0, ey.frac.to_bits()),
                "({u:e}, {v:e}) on {w}×{h}"
            );
        }
    }
}
