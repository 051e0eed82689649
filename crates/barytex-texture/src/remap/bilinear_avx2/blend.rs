//! The second pass over a block: each pixel's four texels loaded at the offsets of the first
//! pass and blended, four pixels a step (two per 256-bit register).
//!
//! - **texels**: the two 8-byte row pairs of each pixel in one 256-bit register, pixel `a` in
//!   the low 128-bit lane and `b` in the high one (`[c00 c10 c01 c11]` in each lane); one byte
//!   shuffle per corner widens it to 32-bit lanes for both pixels at once;
//! - **blend** in f32 in the scalar path's order (`a + (b − a)·t`, separate multiply and add: no
//!   fused multiply-add, whose single rounding would change results), `+ ½`, truncation;
//! - **bytes**: the saturating packs of both registers at once, one lane permutation into pixel
//!   order, one 16-byte store;
//! - **prefetch**: every four pixels, the two rows of the pixel `BLOCK` on, at its exact offsets
//!   (the next block's addressing is done first). The loop otherwise waits on these loads: the
//!   warp moves to another source row every few pixels, and the bottom row is new data.

use core::arch::x86_64::{__m256, __m256i};

use pulp::x86::V3;

use super::Block;
use crate::Rgba8;

/// The texel pair `(i, i + 1)` as one little-endian 64-bit integer (texel `i` in the low bytes).
#[inline(always)]
fn pair(texels: &[Rgba8], i: u32) -> i64 {
    let i = i as usize;
    // One bounds check for both texels, and bytes in memory order: one 8-byte load.
    let [Rgba8([a0, a1, a2, a3]), Rgba8([b0, b1, b2, b3])] = texels[i..i + 2] else {
        unreachable!("a slice of two")
    };
    i64::from_le_bytes([a0, a1, a2, a3, b0, b1, b2, b3])
}

/// The `pshufb` control that widens texel `k` (bytes `4k … 4k + 3`) of each 128-bit lane to
/// four 32-bit lanes (`0x80`: a zero byte).
const fn widen(k: u8) -> [u8; 32] {
    let mut m = [0x80; 32];
    let mut lane = 0;
    while lane < 2 {
        let mut c = 0;
        while c < 4 {
            m[16 * lane + 4 * c] = 4 * k + c as u8;
            c += 1;
        }
        lane += 1;
    }
    m
}

/// The constants of the blend.
pub(super) struct Blend<'a> {
    simd: V3,
    texels: &'a [Rgba8],
    /// Byte shuffles widening corner `k` of both pixels.
    corners: [__m256i; 4],
    /// Lane permutations spreading four pixels' `[fx, fy]` to `fx` of a, b; `fy` of a, b; `fx`
    /// of c, d; `fy` of c, d (each pixel's weight over its four channel lanes).
    spread: [__m256i; 4],
    /// The permutation of packed 32-bit pixels `[a c a c b d b d]` into `[a b c d …]`.
    order: __m256i,
}

impl<'a> Blend<'a> {
    pub(super) fn new(simd: V3, texels: &'a [Rgba8]) -> Self {
        Self {
            simd,
            texels,
            corners: [0, 1, 2, 3].map(|k| pulp::cast(widen(k))),
            spread: [0, 1, 4, 5].map(|k: u32| pulp::cast([k, k, k, k, k + 2, k + 2, k + 2, k + 2])),
            order: pulp::cast([0_u32, 4, 1, 5, 0, 0, 0, 0]),
        }
    }

    /// `a + (b − a)·t` lane-wise, multiply and add rounded separately (as the scalar path).
    #[inline(always)]
    fn lerp(&self, a: __m256, b: __m256, t: __m256) -> __m256 {
        let avx = self.simd.avx;
        avx._mm256_add_ps(a, avx._mm256_mul_ps(avx._mm256_sub_ps(b, a), t))
    }

    /// One corner of both pixels in `rows`, widened by the byte shuffle `k`, in f32.
    #[inline(always)]
    fn corner(&self, rows: __m256i, k: __m256i) -> __m256 {
        let (avx, avx2) = (self.simd.avx, self.simd.avx2);
        avx._mm256_cvtepi32_ps(avx2._mm256_shuffle_epi8(rows, k))
    }

    /// A weight of two pixels over their channel lanes: the permutation `k` of `[fx, fy]` × 4.
    #[inline(always)]
    fn weight(&self, w: __m256, k: __m256i) -> __m256 {
        self.simd.avx2._mm256_permutevar8x32_ps(w, k)
    }

    /// Two pixels' blended channels `+ ½` (pixel `a` in the low lane): offsets
    /// `[top a, bottom a, top b, bottom b]`, weights `fx`, `fy` broadcast per lane.
    #[inline(always)]
    fn two(&self, offsets: &[u32], fx: __m256, fy: __m256) -> __m256 {
        let avx = self.simd.avx;
        let rows = avx._mm256_setr_epi64x(
            pair(self.texels, offsets[0]),
            pair(self.texels, offsets[1]),
            pair(self.texels, offsets[2]),
            pair(self.texels, offsets[3]),
        );
        let [c00, c10, c01, c11] = self.corners;
        let (c00, c10) = (self.corner(rows, c00), self.corner(rows, c10));
        let (c01, c11) = (self.corner(rows, c01), self.corner(rows, c11));
        let top = self.lerp(c00, c10, fx);
        let bottom = self.lerp(c01, c11, fx);
        avx._mm256_add_ps(self.lerp(top, bottom, fy), avx._mm256_set1_ps(0.5))
    }

    /// The `BLOCK` pixels of `block` into `out`.
    #[inline(always)]
    pub(super) fn block(&self, block: &Block, ahead: &Block, out: &mut [Rgba8]) {
        let (avx, avx2) = (self.simd.avx, self.simd.avx2);
        for (((offsets, weights), o), ahead) in block
            .offsets
            .chunks_exact(8)
            .zip(block.weights.chunks_exact(8))
            .zip(out.chunks_exact_mut(4))
            .zip(ahead.offsets.chunks_exact(8))
        {
            // Pixel a's two rows `BLOCK` pixels on (a hint: no effect on any result).
            for &row in &ahead[..2] {
                if let Some(t) = self.texels.get(row as usize) {
                    safe_arch::prefetch_t0(t);
                }
            }
            let w: __m256 = pulp::cast(<[f32; 8]>::try_from(weights).expect("eight"));
            let [fx_ab, fy_ab, fx_cd, fy_cd] = self.spread;
            let ab = self.two(&offsets[..4], self.weight(w, fx_ab), self.weight(w, fy_ab));
            let cd = self.two(&offsets[4..], self.weight(w, fx_cd), self.weight(w, fy_cd));
            // v ∈ [0.5, 255.5 + tiny]: truncation rounds half up; the packs saturate.
            let words =
                avx2._mm256_packs_epi32(avx._mm256_cvttps_epi32(ab), avx._mm256_cvttps_epi32(cd));
            // 32-bit lanes [a c a c | b d b d] → [a b c d …].
            let bytes = avx2
                ._mm256_permutevar8x32_epi32(avx2._mm256_packus_epi16(words, words), self.order);
            let pixels: [u32; 4] = pulp::cast(avx._mm256_castsi256_si128(bytes));
            for (o, p) in o.iter_mut().zip(pixels) {
                *o = Rgba8(p.to_le_bytes());
            }
        }
    }
}
