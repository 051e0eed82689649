//! The bilinear remap of RGBA8 in SSE2 (every x86-64 CPU has it; the intrinsics come through
//! `safe_arch`, which exposes them as safe functions where the build enables the feature),
//! bit-identical to the scalar reference path.
//!
//! Per output pixel:
//! - **addressing in one f64 pair** `[x, y] = [u·w − ½, v·h − ½]` (exact, as
//!   [`linear_taps`](crate::addressing::linear_taps) computes it), clamped to the texel-centre
//!   range `[0, w − 1] × [0, h − 1]` *before* flooring. Clamping first changes no result: left of
//!   the first centre (or above the first row) both taps of today's path read the edge texel, and
//!   the clamped coordinate reads it with weight 0 (see below for the right edge). The fraction
//!   `x − ⌊x⌋` is exact in f64 and rounded once to f32, as before.
//! - **the two texels of a row in one 8-byte read**: the left tap is limited to `w − 2`, so the
//!   right tap is always the next texel in memory. At the right edge the clamped coordinate is
//!   `w − 1`, i.e. tap `w − 2` with fraction 1, and `c + (d − c)·1 = d` exactly for byte values
//!   (the difference of two integers below 256 and the sum are exact in f32), which is what
//!   today's path gives (both taps on `w − 1`). Rows keep today's rule (`y₁ = min(y₀ + 1, h − 1)`)
//!   because the vertical lerp runs on rounded values, where `t + (b − t)·1 = b` need not hold.
//! - **one register per texel row pair**: the 16 bytes of the four texels are widened to four
//!   f32×4 and blended with the operations of the scalar path in the same order (`a + (b − a)·t`,
//!   no fused multiply-add), so every f32 result is the same; the final `+ ½`, truncating
//!   conversion and saturating packs give the byte the scalar path's saturating cast gives.

use safe_arch::{
    add_m128, cmp_eq_mask_m128, convert_to_m128_from_i32_m128i, convert_to_m128_from_m128d,
    convert_to_m128d_from_lower2_i32_m128i, convert_to_m128d_from_lower2_m128,
    get_i32_from_m128i_s, get_i64_from_m128i_s, m128, m128d, max_m128d, min_m128d,
    move_high_low_m128, move_mask_m128, mul_m128, mul_m128d, pack_i16_to_u8_m128i,
    pack_i32_to_i16_m128i, set_i64_m128i, set_m128, set_m128d, set_splat_m128, set_splat_m128d,
    shuffle_abi_f32_all_m128, sub_m128, sub_m128d, truncate_m128_to_m128i, truncate_m128d_to_m128i,
    unpack_high_i8_m128i, unpack_high_i16_m128i, unpack_low_i8_m128i, unpack_low_i16_m128i,
    zeroed_m128d, zeroed_m128i,
};

use glam::Vec2;

use crate::{Rgba8, Texture2d};

/// Whether the kernel handles `source`: at least two texels per row (the 8-byte row read) and
/// an index range where `y·w + x` fits the f64 → i32 conversion and `usize` arithmetic.
pub(super) fn applies(source: &Texture2d<Rgba8>) -> bool {
    let (w, h) = source.size();
    (2..(1 << 30)).contains(&w) && h < (1 << 30)
}

/// The texel pair `(i, i + 1)` as one little-endian `u64` (texel `i` in the low bytes).
#[inline(always)]
fn pair(texels: &[Rgba8], i: usize) -> i64 {
    // One bounds check for both texels, and bytes in memory order: one 8-byte load (two 4-byte
    // loads joined by a shift and an or did not merge).
    let [Rgba8([a0, a1, a2, a3]), Rgba8([b0, b1, b2, b3])] = texels[i..i + 2] else {
        unreachable!("a slice of two")
    };
    i64::from_le_bytes([a0, a1, a2, a3, b0, b1, b2, b3])
}

/// `a + (b − a)·t`, lane-wise.
#[inline(always)]
fn lerp(a: m128, b: m128, t: m128) -> m128 {
    add_m128(a, mul_m128(sub_m128(b, a), t))
}

/// The constants of one remap: the source and its clamp ranges as f64 pairs `[x, y]`.
struct Kernel<'a> {
    texels: &'a [Rgba8],
    stride: usize,
    last_row: usize,
    size: m128d,
    /// The last texel centre on each axis.
    last: m128d,
    /// The last left tap (`w − 2`) and the last row.
    last_tap: m128d,
}

impl Kernel<'_> {
    /// One output pixel at pixel-space `[x, y]` (finite).
    #[inline(always)]
    fn pixel(&self, xy: m128d) -> Rgba8 {
        let zero = zeroed_m128i();
        // max(x, 0) then min(·, last): x is finite, so neither sees a NaN.
        let clamped = min_m128d(max_m128d(xy, zeroed_m128d()), self.last);
        // Non-negative, so truncation is the floor; then limit the left tap.
        let taps = min_m128d(
            convert_to_m128d_from_lower2_i32_m128i(truncate_m128d_to_m128i(clamped)),
            self.last_tap,
        );
        let frac = convert_to_m128_from_m128d(sub_m128d(clamped, taps));
        let index = get_i64_from_m128i_s(truncate_m128d_to_m128i(taps));
        let (x0, y0) = (index as u32 as usize, (index >> 32) as u32 as usize);
        let y1 = if y0 < self.last_row { y0 + 1 } else { y0 };
        let rows = set_i64_m128i(
            pair(self.texels, y1 * self.stride + x0),
            pair(self.texels, y0 * self.stride + x0),
        );
        let (top_pair, bottom_pair) = (
            unpack_low_i8_m128i(rows, zero),
            unpack_high_i8_m128i(rows, zero),
        );
        let c00 = convert_to_m128_from_i32_m128i(unpack_low_i16_m128i(top_pair, zero));
        let c10 = convert_to_m128_from_i32_m128i(unpack_high_i16_m128i(top_pair, zero));
        let c01 = convert_to_m128_from_i32_m128i(unpack_low_i16_m128i(bottom_pair, zero));
        let c11 = convert_to_m128_from_i32_m128i(unpack_high_i16_m128i(bottom_pair, zero));
        let fx = shuffle_abi_f32_all_m128::<0b0000_0000>(frac, frac);
        let fy = shuffle_abi_f32_all_m128::<0b0101_0101>(frac, frac);
        let top = lerp(c00, c10, fx);
        let bottom = lerp(c01, c11, fx);
        let v = add_m128(lerp(top, bottom, fy), set_splat_m128(0.5));
        let bytes = truncate_m128_to_m128i(v);
        let packed = pack_i16_to_u8_m128i(pack_i32_to_i16_m128i(bytes, bytes), zero);
        Rgba8((get_i32_from_m128i_s(packed) as u32).to_le_bytes())
    }

    /// `[u·w − ½, v·h − ½]` from the two lower f32 lanes `[u, v]` (exact in f64).
    #[inline(always)]
    fn position(&self, uv: m128) -> m128d {
        sub_m128d(
            mul_m128d(convert_to_m128d_from_lower2_m128(uv), self.size),
            set_splat_m128d(0.5),
        )
    }
}

/// Remaps `coords` into `out` (same length, checked by the caller); `applies(source)` holds.
pub(super) fn remap(source: &Texture2d<Rgba8>, coords: &[Vec2], out: &mut [Rgba8]) {
    let (w, h) = source.size();
    let k = Kernel {
        texels: source.texels(),
        stride: w as usize,
        last_row: h as usize - 1,
        size: set_m128d(f64::from(h), f64::from(w)),
        last: set_m128d(f64::from(h - 1), f64::from(w - 1)),
        last_tap: set_m128d(f64::from(h - 1), f64::from(w - 2)),
    };
    // Two pixels a step: their four coordinates in one register, tested finite at once
    // (`c − c` is 0 exactly for finite `c`, NaN for NaN and ±∞).
    let mut pairs = coords.chunks_exact(2);
    let mut outs = out.chunks_exact_mut(2);
    for (c, o) in (&mut pairs).zip(&mut outs) {
        let uv = set_m128(c[1].y, c[1].x, c[0].y, c[0].x);
        if move_mask_m128(cmp_eq_mask_m128(sub_m128(uv, uv), set_splat_m128(0.0))) == 0b1111 {
            o[0] = k.pixel(k.position(uv));
            o[1] = k.pixel(k.position(move_high_low_m128(uv, uv)));
        } else {
            for (c, o) in c.iter().zip(o.iter_mut()) {
                *o = one(&k, *c);
            }
        }
    }
    for (c, o) in pairs.remainder().iter().zip(outs.into_remainder()) {
        *o = one(&k, *c);
    }
}

/// One pixel, any coordinate: non-finite gives transparent black.
fn one(k: &Kernel<'_>, uv: Vec2) -> Rgba8 {
    if uv.is_finite() {
        k.pixel(k.position(set_m128(0.0, 0.0, uv.y, uv.x)))
    } else {
        Rgba8([0; 4])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::remap::test_inputs::{coords, texture};

    #[test]
    fn sse2_kernel_matches_the_scalar_path_bit_for_bit() {
        for (w, h) in [(2, 1), (2, 2), (3, 5), (7, 3), (64, 64), (100, 37), (1, 9)] {
            let src = texture(w, h, u64::from(w * 131 + h));
            let mut c = coords(w, h, u64::from(w + 7 * h));
            if w % 2 == 1 {
                c.pop(); // an odd count: the last pixel takes the one-pixel path
            }
            let mut fast = vec![Rgba8::default(); c.len()];
            let mut reference = fast.clone();
            super::super::remap_scalar(&src, &c, &mut reference);
            if applies(&src) {
                remap(&src, &c, &mut fast);
                for (k, (f, r)) in fast.iter().zip(&reference).enumerate() {
                    assert_eq!(f, r, "{w}×{h} at {:?}", c[k]);
                }
            } else {
                assert_eq!(w, 1, "only a one-texel-wide source takes the scalar path");
            }
        }
    }
}
