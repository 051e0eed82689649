//! Four lookups at once, their coordinate arithmetic lane by lane.
//!
//! [`sample_pair`](TextureSampler::sample_pair) overlaps two lookups' dependency chains, but
//! each still spends an instruction (or two) per value on its footprint, level of detail, level
//! choice, tap positions and addresses, a few hundred instructions in all, near the processor's
//! issue width. Here those steps run over four lookups as arrays of four (eight for both axes),
//! each lane the same IEEE operations as the scalar path: compiled where AVX2 is enabled (the
//! renderer's fragment loop is), the compiler turns them into one instruction per step for all
//! four lanes; on the baseline target they are the scalar operations, as before. Only the
//! `log₂` stays per lane (glibc's, as in [`lod`](crate::sampler::lod::lod)), and the texel
//! reads, decoding and blends stay per lookup, after all the addresses are known.

#![allow(
    clippy::needless_range_loop,
    reason = "lane loops index several arrays in step; they unroll and vectorize"
)]

use glam::{Vec2, Vec4};

use super::{AtLod, LookupPath, TextureSampler, linear_levels};
use crate::addressing::linear_taps;
use crate::sampler::level_filters::{bilinear_texels, resolved_pair};
use crate::sampler::lod;
use crate::sampler::texel_fetch::unpremultiply_texels;
use crate::texel::Texel;

/// Four lookups' bilinear taps on one level each: the texel addresses `[x0, x1, y0, y1]` and
/// the fractions `[fx, fy]` of each lane.
type QuadTaps = ([[usize; 4]; 4], [[f32; 2]; 4]);

impl<T: Texel> TextureSampler<T> {
    /// Four lookups, each `[uv, ddx, ddy]` as [`Sampler::sample`](crate::Sampler::sample)
    /// takes them: `[self.sample(q[0]…), …, self.sample(q[3]…)]`, bit for bit, with the
    /// coordinate arithmetic of the four done lane by lane (see the module's documentation)
    /// where the sampler resolved a trilinear path; two [`sample_pair`](Self::sample_pair)s
    /// otherwise.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texture2d,
    ///     TextureSampler};
    /// use glam::Vec2;
    ///
    /// let base = Texture2d::from_fn(64, 64, |x, y| Srgba8([x as u8 * 4, y as u8 * 4, 90, 255]))?;
    /// let chain = MipChain::generate(base, &MipOptions::default())?;
    /// let sampler = TextureSampler::new(chain, SamplerDescriptor::trilinear());
    /// let q = [0.0_f32, 0.01, 0.02, 0.5].map(|k| {
    ///     [Vec2::new(0.3 + k, 0.6), Vec2::new(0.02 + k, 0.0), Vec2::new(0.0, 0.03)]
    /// });
    /// let colours = sampler.sample_quad(q);
    /// for (c, l) in colours.iter().zip(q) {
    ///     assert_eq!(*c, sampler.sample(l[0], l[1], l[2]));
    /// }
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    #[inline(always)]
    pub fn sample_quad(&self, q: [[Vec2; 3]; 4]) -> [Vec4; 4] {
        // Non-finite coordinates are a short path of `sample_biased`'s own: leave them to it.
        if q.iter().all(|l| l[0].is_finite()) {
            match self.path {
                LookupPath::TrilinearRepeatPow2 { opaque: true } => {
                    let c = self.resolved_quad::<true, false, false>(&q);
                    return unpremultiply_quad::<T, true>(c);
                }
                LookupPath::TrilinearRepeatPow2 { opaque: false } => {
                    let c = self.resolved_quad::<false, false, false>(&q);
                    return unpremultiply_quad::<T, false>(c);
                }
                LookupPath::TrilinearResolved { opaque } => {
                    if let AtLod::ResolvedTrilinear { opaque: o, clamp } = self.at_lod {
                        let c = resolved_kernel!(o, clamp, self.resolved_quad(&q));
                        return if opaque {
                            unpremultiply_quad::<T, true>(c)
                        } else {
                            unpremultiply_quad::<T, false>(c)
                        };
                    }
                }
                _ => {}
            }
        }
        let [a, b] = self.sample_pair(q[0], q[1]);
        let [c, d] = self.sample_pair(q[2], q[3]);
        [a, b, c, d]
    }

    /// [`resolved_at`](Self::resolved_at) at the levels of detail of the four lookups
    /// (computed as `sample` computes them, no bias): premultiplied.
    #[inline(always)]
    fn resolved_quad<const OPAQUE: bool, const CLAMP_U: bool, const CLAMP_V: bool>(
        &self,
        q: &[[Vec2; 3]; 4],
    ) -> [Vec4; 4] {
        // Plain loops over the lanes throughout this module: `array::map` and `from_fn` go
        // through closures that the compiler left out of line here (measured: 75 % more
        // instructions than the pair path), where loops unroll and vectorize.
        let size = self.chain.base().size();
        let levels = self.chain.levels();
        let last = levels.len() - 1;
        let mut rho_squared = [0.0_f64; 4];
        for k in 0..4 {
            rho_squared[k] = lod::footprint_squared(q[k][1], q[k][2], size);
        }
        let mut chosen = [(0_usize, 0_usize, 0.0_f32); 4];
        let mut uv = [Vec2::ZERO; 4];
        let (mut lo_sizes, mut hi_sizes) = ([(0_u32, 0_u32); 4], [(0_u32, 0_u32); 4]);
        for k in 0..4 {
            // `sample` is `sample_biased` with a bias of 0, added as it adds it.
            let lod = self.clamp_lod(lod::lod_of_footprint(rho_squared[k]) + 0.0);
            chosen[k] = linear_levels(lod, last);
            uv[k] = q[k][0];
            lo_sizes[k] = levels[chosen[k].0].size();
            hi_sizes[k] = levels[chosen[k].1].size();
        }
        let lo = taps_quad::<CLAMP_U, CLAMP_V>(&uv, &lo_sizes);
        let hi = taps_quad::<CLAMP_U, CLAMP_V>(&uv, &hi_sizes);
        let mut out = [Vec4::ZERO; 4];
        for k in 0..4 {
            let (l0, l1, t) = chosen[k];
            let a = bilinear_texels::<T, OPAQUE>(&levels[l0], lo.0[k], lo.1[k]);
            // The second level only where it differs, as `resolved_at` reads it.
            out[k] = if l1 == l0 {
                a
            } else {
                let b = bilinear_texels::<T, OPAQUE>(&levels[l1], hi.0[k], hi.1[k]);
                a + (b - a) * t
            };
        }
        out
    }
}

/// [`unpremultiply_texels`] of each of four colours.
#[inline(always)]
fn unpremultiply_quad<T: Texel, const OPAQUE: bool>(c: [Vec4; 4]) -> [Vec4; 4] {
    let mut out = c;
    for k in 0..4 {
        out[k] = unpremultiply_texels::<T, OPAQUE>(c[k]);
    }
    out
}

/// The bilinear taps of lookups at `uv[k]` on levels of `sizes[k]` texels, as
/// [`bilinear_resolved`](crate::sampler::level_filters::bilinear_resolved) finds them: the
/// same positions `u·w − ½` in f64, floors and fractions, then addresses clamped
/// (`CLAMP_*`) or masked.
///
/// When every position is within ±2³¹ (all of them, on any texture a lookup can reach
/// without wrapping many times), the floors come from 32-bit truncations of all eight lanes at
/// once, as `linear_taps_pair` computes them; otherwise each lane goes through
/// [`linear_taps`], which gives the same taps (tested there).
#[inline(always)]
fn taps_quad<const CLAMP_U: bool, const CLAMP_V: bool>(
    uv: &[Vec2; 4],
    sizes: &[(u32, u32); 4],
) -> QuadTaps {
    // Lanes 2k and 2k + 1: lookup k's x and y.
    let (mut coordinate, mut side) = ([0.0_f32; 8], [0_u32; 8]);
    for k in 0..4 {
        (coordinate[2 * k], coordinate[2 * k + 1]) = (uv[k].x, uv[k].y);
        (side[2 * k], side[2 * k + 1]) = sizes[k];
    }
    let mut x = [0.0_f64; 8];
    for j in 0..8 {
        x[j] = f64::from(coordinate[j]) * f64::from(side[j]) - 0.5;
    }
    let (mut i0, mut frac) = ([0_i64; 8], [0.0_f32; 8]);
    if x.iter().all(|x| x.abs() < 2_147_483_648.0) {
        // |x| < 2³¹ (false for NaN): the truncation to i32 is exact; the floor is one below
        // it for a negative non-integer, and `x − ⌊x⌋` is exact in f64.
        for j in 0..8 {
            let t = f64::from(x[j] as i32);
            let floor = if t > x[j] { t - 1.0 } else { t };
            i0[j] = i64::from(floor as i32);
            frac[j] = (x[j] - floor) as f32;
        }
    } else {
        for j in 0..8 {
            let taps = linear_taps(coordinate[j], side[j]);
            (i0[j], frac[j]) = (taps.i0, taps.frac);
        }
    }
    let mut taps: QuadTaps = ([[0; 4]; 4], [[0.0; 2]; 4]);
    for k in 0..4 {
        let (w, h) = sizes[k];
        let (x0, x1) = resolved_pair::<CLAMP_U>(i0[2 * k], w);
        let (y0, y1) = resolved_pair::<CLAMP_V>(i0[2 * k + 1], h);
        taps.0[k] = [x0, x1, y0, y1];
        taps.1[k] = [frac[2 * k], frac[2 * k + 1]];
    }
    taps
}
