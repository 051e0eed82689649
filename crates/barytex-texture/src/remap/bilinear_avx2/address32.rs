//! The first pass over a block in f32 lanes, eight coordinates (four pixels) a register, for
//! sources whose sides are both powers of two: the same numbers as the f64 pass (`address`),
//! proved below, with half the lanes' work and no f64 conversions.
//!
//! With `w = 2ᵏ`, for every f32 `u`:
//! - `u·w` is exact in f32 (a change of exponent; an overflow gives ±∞, which the clamp sends to
//!   the same end as the f64 path's huge value), so the fused multiply-subtract and the f64 path
//!   round the same real number `u·w − ½`;
//! - that rounding is exact whenever `u·w − ½` lies in the clamp range `[0, w − 1]`: then
//!   `½ ≤ u·w < w ≤ 2²³`, so `ulp(u·w) ≤ ½`, the difference is a multiple of `ulp(u·w)` below
//!   `u·w`, and representable. Outside the range, rounding is monotone and `0`, `w − 1` are
//!   representable, so the rounded value clamps to the same end (`max` returns its second
//!   operand `+0` for `−0`);
//! - so the clamped coordinate equals the f64 path's exactly, and so do the floor, the tap
//!   limit and the fraction `x − x₀` (exact in f32: `x₀ ≤ x < x₀ + 1`, Sterbenz's lemma for
//!   `x₀ ≥ 1`, `x` itself for `x₀ = 0`), which the f64 path computes exactly and rounds to this
//!   same f32.
//!
//! The offsets are integer arithmetic: `x₀ + (y₀ << k)`, and `+ w` for the bottom row unless
//! `y₀ = h − 1`.

use core::arch::x86_64::{__m256, __m256i};

use pulp::x86::V3;

use super::address::Addressing;

/// The constants of the f32 addressing.
pub(super) struct Address32 {
    simd: V3,
    /// `[w, h] × 4`.
    size: __m256,
    /// The last texel centre on each axis.
    last: __m256,
    /// The last left tap (`w − 2`) and the last row.
    last_tap: __m256,
    /// `[0, log₂ w] × 4`: the shifts taking `[x₀, y₀]` to `[x₀, y₀·w]`.
    row_shift: __m256i,
    /// `[0, w] × 4`: the step to the next row.
    next_row: __m256i,
    /// `[w − 1, h − 1] × 4` as integers (`x₀ < w − 1` always, masked anyway).
    last_row: __m256i,
    /// The permutation of `[at bt ab bb | ct dt cb db]` into `[at ab bt bb | ct cb dt db]`.
    order: __m256i,
}

impl Address32 {
    /// For `w`, `h` powers of two (and the kernel's `applies`).
    pub(super) fn new(simd: V3, w: u32, h: u32) -> Self {
        debug_assert!(w.is_power_of_two() && h.is_power_of_two());
        let pairs = |x: f32, y: f32| pulp::cast([x, y, x, y, x, y, x, y]);
        let int_pairs = |x: u32, y: u32| pulp::cast([x, y, x, y, x, y, x, y]);
        let (wf, hf) = (w as f32, h as f32);
        Self {
            simd,
            size: pairs(wf, hf),
            last: pairs(wf - 1.0, hf - 1.0),
            last_tap: pairs(wf - 2.0, hf - 1.0),
            row_shift: int_pairs(0, w.trailing_zeros()),
            next_row: int_pairs(0, w),
            last_row: int_pairs(w - 1, h - 1),
            order: pulp::cast([0_u32, 2, 1, 3, 4, 6, 5, 7]),
        }
    }
}

impl Addressing for Address32 {
    #[inline(always)]
    fn simd(&self) -> V3 {
        self.simd
    }

    #[inline(always)]
    fn four(&self, uv: __m256) -> (__m256i, __m256) {
        let (avx, avx2, fma) = (self.simd.avx, self.simd.avx2, self.simd.fma);
        let position = fma._mm256_fmsub_ps(uv, self.size, avx._mm256_set1_ps(0.5));
        // max(x, 0) then min(·, last): x is finite or ±∞ (an overflow), never NaN.
        let clamped = avx._mm256_min_ps(
            avx._mm256_max_ps(position, avx._mm256_setzero_ps()),
            self.last,
        );
        let taps = avx._mm256_min_ps(avx._mm256_floor_ps(clamped), self.last_tap);
        let frac = avx._mm256_sub_ps(clamped, taps);
        let index = avx._mm256_cvttps_epi32(taps);
        let top = avx2._mm256_sllv_epi32(index, self.row_shift);
        let below =
            avx2._mm256_and_si256(avx2._mm256_cmpgt_epi32(self.last_row, index), self.next_row);
        // Per 128-bit lane: [top a, top b, bottom a, bottom b].
        let offsets = avx2._mm256_hadd_epi32(top, avx2._mm256_add_epi32(top, below));
        (avx2._mm256_permutevar8x32_epi32(offsets, self.order), frac)
    }
}
