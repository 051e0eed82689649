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
                    return c.map(unpremultiply_texels::<T, true>);
                }
                LookupPath::TrilinearRepeatPow2 { opaque: false } => {
                    let c = self.resolved_quad::<false, false, false>(&q);
                    return c.map(unpremultiply_texels::<T, false>);
                }
                LookupPath::TrilinearResolved { opaque } => {
                    if let AtLod::ResolvedTrilinear { opaque: o, clamp } = self.at_lod {
                        let c = resolved_kernel!(o, clamp, self.resolved_quad(&q));
                        return if opaque {
                            c.map(unpremultiply_texels::<T, true>)
                        } else {
                            c.map(unpremultiply_texels::<T, false>)
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
        let size = self.chain.base().size();
        let rho_squared: [f64; 4] =
            core::array::from_fn(|k| lod::footprint_squared(q[k][1], q[k][2], size));
        // `sample` is `sample_biased` with a bias of 0, added as it adds it.
        let lods = rho_squared.map(|r| self.clamp_lod(lod::lod_of_footprint(r) + 0.0));
        let levels = self.chain.levels();
        let last = levels.len() - 1;
        let chosen = lods.map(|l| linear_levels(l, last));
        let uv = q.map(|l| l[0]);
        let (lo, hi) = (
            taps_quad::<CLAMP_U, CLAMP_V>(uv, chosen.map(|c| levels[c.0].size())),
            taps_quad::<CLAMP_U, CLAMP_V>(uv, chosen.map(|c| levels[c.1].size())),
        );
        core::array::from_fn(|k| {
            let (l0, l1, t) = chosen[k];
            let a = bilinear_texels::<T, OPAQUE>(&levels[l0], lo.0[k], lo.1[k]);
            // The second level only where it differs, as `resolved_at` reads it.
            if l1 == l0 {
                return a;
            }
            let b = bilinear_texels::<T, OPAQUE>(&levels[l1], hi.0[k], hi.1[k]);
            a + (b - a) * t
        })
    }
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
    uv: [Vec2; 4],
    sizes: [(u32, u32); 4],
) -> QuadTaps {
    // Lanes 2k and 2k + 1: lookup k's x and y.
    let side = |j: usize| {
        let (w, h) = sizes[j / 2];
        if j.is_multiple_of(2) { w } else { h }
    };
    let coordinate = |j: usize| {
        if j.is_multiple_of(2) { uv[j / 2].x } else { uv[j / 2].y }
    };
    let x: [f64; 8] = core::array::from_fn(|j| f64::from(coordinate(j)) * f64::from(side(j)) - 0.5);
    let (i0, frac): ([i64; 8], [f32; 8]) = if x.iter().all(|x| x.abs() < 2_147_483_648.0) {
        // |x| < 2³¹ (false for NaN): the truncation to i32 is exact; the floor is one below
        // it for a negative non-integer, and `x − ⌊x⌋` is exact in f64.
        let t: [f64; 8] = x.map(|x| f64::from(x as i32));
        let floor: [f64; 8] = core::array::from_fn(|j| if t[j] > x[j] { t[j] - 1.0 } else { t[j] });
        (
            floor.map(|f| i64::from(f as i32)),
            core::array::from_fn(|j| (x[j] - floor[j]) as f32),
        )
    } else {
        let taps: [_; 8] = core::array::from_fn(|j| linear_taps(coordinate(j), side(j)));
        (taps.map(|t| t.i0), taps.map(|t| t.frac))
    };
    let addresses = core::array::from_fn(|k| {
        let (w, h) = sizes[k];
        let (x0, x1) = resolved_pair::<CLAMP_U>(i0[2 * k], w);
        let (y0, y1) = resolved_pair::<CLAMP_V>(i0[2 * k + 1], h);
        [x0, x1, y0, y1]
    });
    (
        addresses,
        core::array::from_fn(|k| [frac[2 * k], frac[2 * k + 1]]),
    )
}
