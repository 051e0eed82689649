//! The bilinear remap of RGBA8 in AVX2, selected at run time (through `pulp`, whose `V3` token
//! proves the CPU has AVX2 and FMA and runs a closure compiled for them; the workspace forbids
//! `unsafe`, and calling a `#[target_feature]` function directly needs it). Bit-identical to the
//! scalar reference and to the SSE2 kernel: the same operations in the same order, two output
//! pixels per 256-bit register instead of one per 128-bit register.
//!
//! Per pair of output pixels `a`, `b`:
//! - **addressing** exactly as in the SSE2 kernel (see `bilinear_sse2`), on the four f64 lanes
//!   `[xa, ya, xb, yb]` of one register: `u·w − ½` exact in f64, clamped to the texel-centre range
//!   before the floor, left tap limited to `w − 2` so the right tap is the next texel in memory,
//!   fractions exact in f64 and rounded once to f32;
//! - **texels**: the two 8-byte row pairs of each pixel in one 256-bit register, `a` in the low
//!   128-bit lane and `b` in the high one (`[c00 c10 c01 c11]` in each lane); one byte shuffle per
//!   corner widens it to 32-bit lanes for both pixels at once (`[c00a | c00b]`, …);
//! - **blend** in f32 in the scalar path's order (`a + (b − a)·t`, separate multiply and add: no
//!   fused multiply-add, whose single rounding would change results), `+ ½`, truncation and
//!   saturating packs, as in the SSE2 kernel.

use core::arch::x86_64::{__m128, __m256, __m256d, __m256i};

use glam::Vec2;
use pulp::x86::V3;

use crate::{Rgba8, Texture2d};

/// Whether the kernel handles `source` (the conditions of the SSE2 kernel: two texels per row
/// for the 8-byte row read, indices within the f64 → i32 conversion).
pub(super) fn applies(source: &Texture2d<Rgba8>) -> bool {
    let (w, h) = source.size();
    (2..(1 << 30)).contains(&w) && h < (1 << 30)
}

/// The AVX2 + FMA token when this CPU has them (detected once, then cached by `pulp`).
pub(super) fn token() -> Option<V3> {
    V3::try_new()
}

/// The texel pair `(i, i + 1)` as one little-endian 64-bit integer (texel `i` in the low bytes).
#[inline(always)]
fn pair(texels: &[Rgba8], i: usize) -> i64 {
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

/// How many texels ahead of a pixel's left tap its rows are prefetched: the warp moves about one
/// texel a pixel, so this is the data of the pixels 32 on (measured: 16, 32 and 64 all help, 32
/// most, ≈ 10 % of the run time).
const PREFETCH_AHEAD: usize = 32;

/// The constants of one remap.
struct Kernel<'a> {
    simd: V3,
    texels: &'a [Rgba8],
    stride: usize,
    last_row: usize,
    /// `[w, h, w, h]`.
    size: __m256d,
    /// The last texel centre on each axis, twice.
    last: __m256d,
    /// The last left tap (`w − 2`) and the last row, twice.
    last_tap: __m256d,
    /// Byte shuffles widening corner `k` of both pixels.
    corners: [__m256i; 4],
}

impl Kernel<'_> {
    /// `a + (b − a)·t` lane-wise, multiply and add rounded separately (as the scalar path).
    #[inline(always)]
    fn lerp(&self, a: __m256, b: __m256, t: __m256) -> __m256 {
        let avx = self.simd.avx;
        avx._mm256_add_ps(a, avx._mm256_mul_ps(avx._mm256_sub_ps(b, a), t))
    }

    /// Two output pixels from the four finite f32 lanes `[ua, va, ub, vb]`.
    #[inline(always)]
    fn two(&self, uv: __m128) -> [Rgba8; 2] {
        let (avx, avx2) = (self.simd.avx, self.simd.avx2);
        let position = avx._mm256_sub_pd(
            avx._mm256_mul_pd(avx._mm256_cvtps_pd(uv), self.size),
            avx._mm256_set1_pd(0.5),
        );
        // max(x, 0) then min(·, last): x is finite, so neither sees a NaN.
        let clamped = avx._mm256_min_pd(
            avx._mm256_max_pd(position, avx._mm256_setzero_pd()),
            self.last,
        );
        // Non-negative, so truncation is the floor; then limit the left tap.
        let taps = avx._mm256_min_pd(
            avx._mm256_cvtepi32_pd(avx._mm256_cvttpd_epi32(clamped)),
            self.last_tap,
        );
        let frac = avx._mm256_cvtpd_ps(avx._mm256_sub_pd(clamped, taps));
        let index: [i32; 4] = pulp::cast(avx._mm256_cvttpd_epi32(taps));
        // In [0, 2³⁰): non-negative.
        let [xa, ya, xb, yb] = index.map(|i| i as u32 as usize);
        let below = |y: usize| if y < self.last_row { y + 1 } else { y };
        // The texels 32 ahead in pixel a's two rows (two cache lines on): the loop otherwise
        // waits on these loads. (Prefetching is a hint: no effect on any result.)
        for row in [ya, below(ya)] {
            if let Some(t) = self.texels.get(row * self.stride + xa + PREFETCH_AHEAD) {
                safe_arch::prefetch_t0(t);
            }
        }
        let rows = avx._mm256_setr_epi64x(
            pair(self.texels, ya * self.stride + xa),
            pair(self.texels, below(ya) * self.stride + xa),
            pair(self.texels, yb * self.stride + xb),
            pair(self.texels, below(yb) * self.stride + xb),
        );
        let corner =
            |k: usize| avx._mm256_cvtepi32_ps(avx2._mm256_shuffle_epi8(rows, self.corners[k]));
        let weights = avx._mm256_castps128_ps256(frac);
        let fx = avx2._mm256_permutevar8x32_ps(weights, pulp::cast([0_u32, 0, 0, 0, 2, 2, 2, 2]));
        let fy = avx2._mm256_permutevar8x32_ps(weights, pulp::cast([1_u32, 1, 1, 1, 3, 3, 3, 3]));
        let top = self.lerp(corner(0), corner(1), fx);
        let bottom = self.lerp(corner(2), corner(3), fx);
        let v = avx._mm256_add_ps(self.lerp(top, bottom, fy), avx._mm256_set1_ps(0.5));
        let bytes = avx._mm256_cvttps_epi32(v);
        let words = avx2._mm256_packs_epi32(bytes, bytes);
        let packed: [u32; 8] = pulp::cast(avx2._mm256_packus_epi16(words, words));
        [
            Rgba8(packed[0].to_le_bytes()),
            Rgba8(packed[4].to_le_bytes()),
        ]
    }

    /// The pixels of `coords` into `out` (same length).
    #[inline(always)]
    fn run(&self, coords: &[Vec2], out: &mut [Rgba8]) {
        let sse = self.simd.sse;
        let mut pairs = coords.chunks_exact(2);
        let mut outs = out.chunks_exact_mut(2);
        for (c, o) in (&mut pairs).zip(&mut outs) {
            let uv: __m128 = pulp::cast([c[0].x, c[0].y, c[1].x, c[1].y]);
            // `c − c` is 0 exactly for finite `c`, NaN for NaN and ±∞.
            let finite = sse._mm_cmpeq_ps(sse._mm_sub_ps(uv, uv), sse._mm_setzero_ps());
            if sse._mm_movemask_ps(finite) == 0b1111 {
                let [a, b] = self.two(uv);
                o[0] = a;
                o[1] = b;
            } else {
                for (c, o) in c.iter().zip(o.iter_mut()) {
                    *o = self.one(*c);
                }
            }
        }
        for (c, o) in pairs.remainder().iter().zip(outs.into_remainder()) {
            *o = self.one(*c);
        }
    }

    /// One pixel, any coordinate: non-finite gives transparent black. (The second pixel of the
    /// pair reads texel `(0, 0)`, always present, and is discarded.)
    #[inline(always)]
    fn one(&self, uv: Vec2) -> Rgba8 {
        if uv.is_finite() {
            self.two(pulp::cast([uv.x, uv.y, 0.0, 0.0]))[0]
        } else {
            Rgba8([0; 4])
        }
    }
}

/// Remaps `coords` into `out` (same length, checked by the caller); `applies(source)` holds.
pub(super) fn remap(simd: V3, source: &Texture2d<Rgba8>, coords: &[Vec2], out: &mut [Rgba8]) {
    let (w, h) = source.size();
    let (w, h) = (f64::from(w), f64::from(h));
    let k = Kernel {
        simd,
        texels: source.texels(),
        stride: source.width() as usize,
        last_row: source.height() as usize - 1,
        size: pulp::cast([w, h, w, h]),
        last: pulp::cast([w - 1.0, h - 1.0, w - 1.0, h - 1.0]),
        last_tap: pulp::cast([w - 2.0, h - 1.0, w - 2.0, h - 1.0]),
        corners: [0, 1, 2, 3].map(|k| pulp::cast(widen(k))),
    };
    simd.vectorize(|| k.run(coords, out));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::remap::test_inputs::{coords, texture};

    #[test]
    fn avx2_kernel_matches_the_scalar_path_bit_for_bit() {
        let Some(simd) = token() else {
            eprintln!("skipped: this CPU has no AVX2/FMA");
            return;
        };
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
                remap(simd, &src, &c, &mut fast);
                for (k, (f, r)) in fast.iter().zip(&reference).enumerate() {
                    assert_eq!(f, r, "{w}×{h} at {:?}", c[k]);
                }
            } else {
                assert_eq!(w, 1, "only a one-texel-wide source takes the scalar path");
            }
        }
    }
}
