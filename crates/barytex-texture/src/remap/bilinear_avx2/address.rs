//! The first pass over a block: each pixel's texel offsets and weights, four pixels a step, in
//! f64 lanes (every size the kernel takes).
//!
//! Per pixel the numbers of the SSE2 kernel (see `bilinear_sse2`): `[x, y] = [u·w − ½, v·h − ½]`,
//! exact in f64 (`u·w` has at most 24 + 24 bits, so the fused multiply-subtract rounds an exact
//! value, as the separate multiply and subtract do), clamped to the texel-centre range before
//! the floor, left tap limited to `w − 2`, fractions exact in f64 and rounded once to f32. The
//! offsets `y₀·w + x₀` and `y₁·w + x₀` (`y₁ = min(y₀ + 1, h − 1)`) are exact in f64 too (below
//! `2³¹`, which `applies` guarantees) and converted to i32.

use core::arch::x86_64::{__m128, __m128i, __m256, __m256d, __m256i};

use glam::Vec2;
use pulp::x86::V3;

use super::{BLOCK, Block};

/// The constants of the f64 addressing.
pub(super) struct Address64 {
    simd: V3,
    /// `[w, h, w, h]`.
    size: __m256d,
    /// The last texel centre on each axis, twice.
    last: __m256d,
    /// The last left tap (`w − 2`) and the last row, twice.
    last_tap: __m256d,
    /// `[1, w, 1, w]`: a tap pair's weights in the row-major offset.
    row_major: __m256d,
    /// `[0, w, 0, w]`: the step to the next row.
    next_row: __m256d,
}

impl Address64 {
    pub(super) fn new(simd: V3, w: u32, h: u32) -> Self {
        let (w, h) = (f64::from(w), f64::from(h));
        Self {
            simd,
            size: pulp::cast([w, h, w, h]),
            last: pulp::cast([w - 1.0, h - 1.0, w - 1.0, h - 1.0]),
            last_tap: pulp::cast([w - 2.0, h - 1.0, w - 2.0, h - 1.0]),
            row_major: pulp::cast([1.0, w, 1.0, w]),
            next_row: pulp::cast([0.0, w, 0.0, w]),
        }
    }

    /// Two pixels from the f64 lanes `[xa, ya, xb, yb]` (finite): their offsets
    /// `[top a, bottom a, top b, bottom b]` and weights `[fxa, fya, fxb, fyb]`.
    #[inline(always)]
    fn two(&self, uv: __m256d) -> (__m128i, __m128) {
        let (avx, fma) = (self.simd.avx, self.simd.fma);
        let position = fma._mm256_fmsub_pd(uv, self.size, avx._mm256_set1_pd(0.5));
        // max(x, 0) then min(·, last): x is finite, so neither sees a NaN.
        let clamped = avx._mm256_min_pd(
            avx._mm256_max_pd(position, avx._mm256_setzero_pd()),
            self.last,
        );
        // Non-negative: the floor is the truncation of the other kernels.
        let taps = avx._mm256_min_pd(avx._mm256_floor_pd(clamped), self.last_tap);
        let frac = avx._mm256_cvtpd_ps(avx._mm256_sub_pd(clamped, taps));
        // `[x₀, y₀·w]`, and `[0, w]` added where the row is not the last (the x lanes compare
        // against anything and are masked by the 0 of `next_row`).
        let top = avx._mm256_mul_pd(taps, self.row_major);
        let below = avx._mm256_and_pd(
            avx._mm256_cmp_pd::<{ core::arch::x86_64::_CMP_LT_OQ }>(taps, self.last_tap),
            self.next_row,
        );
        let bottom = avx._mm256_add_pd(top, below);
        let offsets = avx._mm256_hadd_pd(top, bottom);
        (avx._mm256_cvttpd_epi32(offsets), frac)
    }

    /// Four pixels from the lanes `[ua, va, ub, vb, uc, vc, ud, vd]` (finite).
    #[inline(always)]
    fn four(&self, uv: __m256) -> (__m256i, __m256) {
        let avx = self.simd.avx;
        let (o0, w0) = self.two(avx._mm256_cvtps_pd(avx._mm256_castps256_ps128(uv)));
        let (o1, w1) = self.two(avx._mm256_cvtps_pd(avx._mm256_extractf128_ps::<1>(uv)));
        (avx._mm256_set_m128i(o1, o0), avx._mm256_set_m128(w1, w0))
    }
}

impl Addressing for Address64 {
    #[inline(always)]
    fn simd(&self) -> V3 {
        self.simd
    }

    #[inline(always)]
    fn four(&self, uv: __m256) -> (__m256i, __m256) {
        Address64::four(self, uv)
    }
}

/// An addressing pass: four pixels' offsets and weights from their coordinates. (A trait, not a
/// closure: closures are not `#[inline(always)]`, and one compiled outside `vectorize`'s
/// features turns every intrinsic into a call.)
pub(super) trait Addressing {
    fn simd(&self) -> V3;
    /// Offsets `[top, bottom]` and weights `[fx, fy]` of four pixels from the lanes
    /// `[ua, va, ub, vb, uc, vc, ud, vd]` (finite).
    fn four(&self, uv: __m256) -> (__m256i, __m256);
}

/// Fills `block` from `BLOCK` coordinates, eight coordinate lanes a step; whether all of them
/// were finite (a non-finite one is replaced by 0, whose pixel the caller overwrites).
#[inline(always)]
pub(super) fn address_block(pass: &impl Addressing, coords: &[Vec2], block: &mut Block) -> bool {
    debug_assert_eq!(coords.len(), BLOCK);
    let avx = pass.simd().avx;
    let mut finite_all = avx._mm256_castsi256_ps(avx._mm256_set1_epi32(-1));
    for ((c, o), w) in coords
        .chunks_exact(4)
        .zip(block.offsets.chunks_exact_mut(8))
        .zip(block.weights.chunks_exact_mut(8))
    {
        let uv: __m256 = pulp::cast([
            c[0].x, c[0].y, c[1].x, c[1].y, c[2].x, c[2].y, c[3].x, c[3].y,
        ]);
        // `c − c` is 0 exactly for finite `c`, NaN for NaN and ±∞.
        let finite = avx._mm256_cmp_ps::<{ core::arch::x86_64::_CMP_EQ_OQ }>(
            avx._mm256_sub_ps(uv, uv),
            avx._mm256_setzero_ps(),
        );
        finite_all = avx._mm256_and_ps(finite_all, finite);
        let (offsets, weights) = pass.four(avx._mm256_and_ps(uv, finite));
        o.copy_from_slice(&pulp::cast::<__m256i, [u32; 8]>(offsets));
        w.copy_from_slice(&pulp::cast::<__m256, [f32; 8]>(weights));
    }
    avx._mm256_movemask_ps(finite_all) == 0xff
}
