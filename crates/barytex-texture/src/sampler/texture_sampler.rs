//! `TextureSampler`: a mip chain plus a [`SamplerDescriptor`], implementing [`Sampler`] the way
//! the Vulkan specification defines texel filtering.

use glam::{Vec2, Vec4};

use crate::sampler::texel_fetch::{Addressing, premultiply, unpremultiply, unpremultiply_texels};
use crate::sampler::{
    AddressMode, AnisotropicFilter, FilterMode, MipmapFilterMode, Sampler, SamplerDescriptor,
    anisotropic, compare, ewa, level_filters, lod,
};
use crate::{MipChain, Texel, Texture2d};

/// `$sampler.$method::<OPAQUE, CLAMP_U, CLAMP_V>($args)` for the run-time flags `$opaque` and
/// `$clamp` (`[u, v]`): the eight instances of a resolved kernel, chosen in one place.
macro_rules! resolved_kernel {
    ($opaque:expr, $clamp:expr, $sampler:ident.$method:ident($($arg:expr),*)) => {
        match ($opaque, $clamp) {
            (true, [false, false]) => $sampler.$method::<true, false, false>($($arg),*),
            (true, [false, true]) => $sampler.$method::<true, false, true>($($arg),*),
            (true, [true, false]) => $sampler.$method::<true, true, false>($($arg),*),
            (true, [true, true]) => $sampler.$method::<true, true, true>($($arg),*),
            (false, [false, false]) => $sampler.$method::<false, false, false>($($arg),*),
            (false, [false, true]) => $sampler.$method::<false, false, true>($($arg),*),
            (false, [true, false]) => $sampler.$method::<false, true, false>($($arg),*),
            (false, [true, true]) => $sampler.$method::<false, true, true>($($arg),*),
        }
    };
}
// After the macro: the module uses it.
mod lookup_pair;

/// A texture (its mip chain) with the sampler state that filters it.
///
/// ```
/// use barytex_texture::{MipChain, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texture2d, TextureSampler};
/// use glam::Vec2;
///
/// // A 64² black-and-white checker of 1-texel squares, with its linear-light mip chain.
/// let base = Texture2d::from_fn(64, 64, |x, y| Srgba8(if (x + y) % 2 == 0 { [0, 0, 0, 255] } else { [255; 4] }))?;
/// let chain = MipChain::generate(base, &MipOptions::default())?;
/// let sampler = TextureSampler::new(chain, SamplerDescriptor::trilinear());
/// // A pixel covering 4×4 texels reads level 2: the linear-light mean grey 0.5 (stored as the
/// // sRGB byte 188, which decodes to 0.503).
/// let c = sampler.sample(Vec2::splat(0.5), Vec2::new(4.0 / 64.0, 0.0), Vec2::new(0.0, 4.0 / 64.0));
/// assert!((c.x - 0.5).abs() < 0.004);
/// # Ok::<(), barytex_texture::TextureError>(())
/// ```
///
/// # Documented values for bad input
/// - a non-finite `uv` gives transparent black `(0, 0, 0, 0)`;
/// - a zero footprint magnifies (level 0, `mag_filter`); a NaN or infinite derivative is treated
///   as an unmeasurably large footprint: the most blurred level the clamps allow;
/// - a level of detail beyond the chain uses its last level;
/// - texels are not checked, but a NaN or infinite texel (possible in float formats) never
///   makes the result NaN: filtering runs on premultiplied colour and un-premultiplies at the
///   end, where a non-finite colour becomes black with the filtered alpha, a NaN or
///   non-positive alpha gives transparent black, and a +∞ alpha stays +∞ (with black colour).
///   Texels outside the filter's footprint have no effect (but a generated mip chain averages
///   such a texel into its coarser levels).
///
/// # Accuracy
/// Texel indices and weights are those of the Vulkan formulas evaluated exactly (f64), each
/// weight rounded once to f32 (see [`crate::addressing`]); every `sample_level` result lies in the
/// set the specification allows at its minimum precisions (dEQP-style check,
/// `tests/sampling.rs::sample_level_is_inside_the_allowed_set`). Bilinear blends in the form
/// `a + (b − a)·t`: an exact texel centre returns its texel exactly; a constant texture `c`
/// returns the constant within `2·ε·|c|` (un-premultiplying) under nearest, bilinear and
/// trilinear and within `16·ε·|c|` under cubic, anisotropic and EWA; nearest, bilinear and
/// trilinear results lie within the texels' range widened by `4·ε·m`, B-spline, anisotropic and
/// EWA results within it widened by `16·ε·m` (they sum and normalise up to 16 weighted terms),
/// `m` the largest texel magnitude — relative, not absolute: float texels near 2²⁰ go beyond an
/// absolute 4 ε by up to 0.125. Tested in `tests/sampling.rs` (8-bit texels, `m ≤ 1`),
/// `tests/value_scale.rs` (float texels scaled by 2⁻³⁰ … 2³⁰, random footprints) and by the
/// `sampling` fuzz target.
#[derive(Clone, Debug)]
pub struct TextureSampler<T> {
    chain: MipChain<T>,
    descriptor: SamplerDescriptor,
    addressing: Addressing,
    /// The lookup resolved once, when sampler and texture meet.
    path: LookupPath,
    /// How filtering at a given level of detail runs (each anisotropic probe, among others).
    at_lod: AtLod,
}

/// Which lookup a sampler runs: the common configurations get a short path the compiler can
/// inline into the caller's loop; everything else takes the general one. Every path computes
/// exactly what the general path computes for its configuration (same formulas, same order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum LookupPath {
    /// One level, nearest for magnification and minification, no anisotropy: every level of
    /// detail gives the same result, so it is never computed.
    SingleLevelNearest,
    /// One level, bilinear for magnification and minification, no anisotropy.
    SingleLevelBilinear,
    /// Bilinear within levels, linear between them, no anisotropy (trilinear).
    Trilinear,
    /// [`Trilinear`](Self::Trilinear) under repeat addressing on both axes over levels whose
    /// sides are all powers of two: the address mode resolved at construction (a mask per axis).
    /// `opaque`: every texel of every level is opaque, so texels are not premultiplied (by 1).
    TrilinearRepeatPow2 { opaque: bool },
    /// [`Trilinear`](Self::Trilinear) through any other [`AtLod::ResolvedTrilinear`] kernel (an
    /// axis clamped to the edge).
    TrilinearResolved { opaque: bool },
    /// Anything else.
    General,
}

impl LookupPath {
    fn of<T: Texel>(d: &SamplerDescriptor, levels: &[Texture2d<T>], at_lod: AtLod) -> Self {
        let filter = (d.mag_filter == d.min_filter).then_some(d.mag_filter);
        match (
            filter,
            d.anisotropy_clamp <= 1,
            levels.len() == 1,
            d.mipmap_filter,
        ) {
            (Some(FilterMode::Nearest), true, true, _) => Self::SingleLevelNearest,
            (Some(FilterMode::Linear), true, true, _) => Self::SingleLevelBilinear,
            (Some(FilterMode::Linear), true, false, MipmapFilterMode::Linear) => match at_lod {
                AtLod::ResolvedTrilinear {
                    opaque,
                    clamp: [false, false],
                } => Self::TrilinearRepeatPow2 { opaque },
                AtLod::ResolvedTrilinear { opaque, .. } => Self::TrilinearResolved { opaque },
                AtLod::General => Self::Trilinear,
            },
            _ => Self::General,
        }
    }
}

/// How a sampler filters at a given (biased, clamped) level of detail — what a trilinear
/// lookup does once and an anisotropic one once a probe — resolved when sampler and texture
/// meet. Both compute the same values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AtLod {
    /// [`TextureSampler::filter_premultiplied`]: every configuration.
    General,
    /// Bilinear within levels and linear between them with each axis's address mode resolved
    /// ([`level_filters::bilinear_resolved`]): `clamp[axis]` false for repeat over levels whose
    /// sides along it are all powers of two (a mask), true for clamp-to-edge (a clamp).
    /// `opaque`: every texel of every level is opaque, so texels are not premultiplied (by 1).
    ResolvedTrilinear { opaque: bool, clamp: [bool; 2] },
}

impl AtLod {
    fn of<T: Texel>(d: &SamplerDescriptor, levels: &[Texture2d<T>]) -> Self {
        let linear = d.mag_filter == FilterMode::Linear
            && d.min_filter == FilterMode::Linear
            && d.mipmap_filter == MipmapFilterMode::Linear;
        // Per axis: `Some(clamp)` where the kernel resolves its address mode.
        let axis = |mode: AddressMode, side: fn(&Texture2d<T>) -> u32| match mode {
            AddressMode::ClampToEdge => Some(true),
            AddressMode::Repeat if levels.iter().all(|l| side(l).is_power_of_two()) => Some(false),
            _ => None,
        };
        let u = axis(d.address_mode_u, |l| l.size().0);
        let v = axis(d.address_mode_v, |l| l.size().1);
        match (linear, u, v) {
            (true, Some(clamp_u), Some(clamp_v)) => Self::ResolvedTrilinear {
                opaque: levels.iter().all(all_opaque),
                clamp: [clamp_u, clamp_v],
            },
            _ => Self::General,
        }
    }
}

/// Whether every texel of `level` is opaque; in blocks without an early exit, which the
/// compiler vectorizes (a 2048² sRGB level takes about a millisecond).
fn all_opaque<T: Texel>(level: &Texture2d<T>) -> bool {
    level
        .texels()
        .chunks(4096)
        .all(|block| block.iter().fold(true, |all, t| all & t.is_opaque()))
}

impl<T: Texel> TextureSampler<T> {
    /// A sampler over `chain`. The descriptor is sanitised: NaN LOD clamps and bias become the
    /// defaults (0, 32, 0), `lod_max_clamp < lod_min_clamp` is raised to `lod_min_clamp`, and
    /// `anisotropy_clamp` is clamped to 1..=16.
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, TextureSampler};
    ///
    /// let chain = MipChain::single(Texture2d::new(4, 4, R8(0))?);
    /// let wild = SamplerDescriptor {
    ///     lod_min_clamp: 3.0,
    ///     lod_max_clamp: 1.0, // below the minimum
    ///     lod_bias: f32::NAN,
    ///     anisotropy_clamp: 100,
    ///     ..SamplerDescriptor::default()
    /// };
    /// let d = *TextureSampler::new(chain, wild).descriptor();
    /// assert_eq!((d.lod_min_clamp, d.lod_max_clamp, d.lod_bias), (3.0, 3.0, 0.0));
    /// assert_eq!(d.anisotropy_clamp, 16);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn new(chain: MipChain<T>, descriptor: SamplerDescriptor) -> Self {
        let d = descriptor.sanitized();
        let addressing = Addressing::new(d.address_mode_u, d.address_mode_v, d.border_color);
        let at_lod = AtLod::of(&d, chain.levels());
        let path = LookupPath::of(&d, chain.levels(), at_lod);
        Self {
            chain,
            descriptor: d,
            addressing,
            path,
            at_lod,
        }
    }

    /// A sampler over a single-level texture (no mip chain: minification aliases).
    ///
    /// ```
    /// use barytex_texture::{R8, Sampler, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// let texture = Texture2d::from_fn(4, 4, |x, _| R8(if x % 2 == 0 { 0 } else { 255 }))?;
    /// let sampler = TextureSampler::single_level(texture, SamplerDescriptor::default());
    /// assert_eq!(sampler.chain().len(), 1);
    /// // Even a 4-texel-wide footprint reads a single texel: minification aliases.
    /// let c = sampler.sample(Vec2::new(0.375, 0.5), Vec2::new(1.0, 0.0), Vec2::new(0.0, 1.0));
    /// assert_eq!(c.x, 1.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn single_level(texture: Texture2d<T>, descriptor: SamplerDescriptor) -> Self {
        Self::new(MipChain::single(texture), descriptor)
    }

    /// The mip chain.
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R8, SamplerDescriptor, Texture2d, TextureSampler};
    ///
    /// let chain = MipChain::generate(Texture2d::new(8, 8, R8(1))?, &MipOptions::default())?;
    /// let sampler = TextureSampler::new(chain.clone(), SamplerDescriptor::trilinear());
    /// assert_eq!(sampler.chain(), &chain);
    /// assert_eq!(sampler.chain().len(), 4);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn chain(&self) -> &MipChain<T> {
        &self.chain
    }

    /// The (sanitised) descriptor.
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, TextureSampler};
    ///
    /// let chain = MipChain::single(Texture2d::new(1, 1, R8(0))?);
    /// let sampler = TextureSampler::new(chain, SamplerDescriptor::trilinear());
    /// assert_eq!(sampler.descriptor(), &SamplerDescriptor::trilinear());
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn descriptor(&self) -> &SamplerDescriptor {
        &self.descriptor
    }

    /// The level of detail for a footprint: `log₂ ρ` (see [`lod::lod`]) plus the descriptor's
    /// bias plus `extra_bias`, clamped to `[lod_min_clamp, lod_max_clamp]`.
    ///
    /// ```
    /// use barytex_texture::{MipChain, R8, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// let chain = MipChain::single(Texture2d::new(8, 8, R8(0))?);
    /// let d = SamplerDescriptor { lod_bias: 0.25, lod_max_clamp: 2.0, ..SamplerDescriptor::trilinear() };
    /// let sampler = TextureSampler::new(chain, d);
    /// // A pixel spanning 2 texels: log₂ 2 = 1, plus the descriptor's bias, plus the extra bias.
    /// let (ddx, ddy) = (Vec2::new(2.0 / 8.0, 0.0), Vec2::new(0.0, 2.0 / 8.0));
    /// assert_eq!(sampler.lod(ddx, ddy, 0.5), 1.75);
    /// // Clamped to lod_max_clamp.
    /// assert_eq!(sampler.lod(ddx, ddy, 4.0), 2.0);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn lod(&self, ddx: Vec2, ddy: Vec2, extra_bias: f32) -> f32 {
        let raw = lod::lod(ddx, ddy, self.chain.base().size());
        self.clamp_lod(raw + extra_bias)
    }

    /// `sample` with an extra LOD bias (GLSL `texture(s, uv, bias)`).
    ///
    /// ```
    /// use barytex_texture::{MipChain, MipOptions, R32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// let base = Texture2d::from_texels(2, 1, vec![R32f(0.0), R32f(1.0)])?;
    /// let chain = MipChain::generate(base, &MipOptions::default())?;
    /// let sampler = TextureSampler::new(chain, SamplerDescriptor::trilinear());
    /// // One texel per pixel (LOD 0) at texel 0's centre reads 0; a bias of 1 reads level 1, the mean.
    /// let (uv, ddx, ddy) = (Vec2::new(0.25, 0.5), Vec2::new(0.5, 0.0), Vec2::new(0.0, 1.0));
    /// assert_eq!(sampler.sample(uv, ddx, ddy).x, 0.0);
    /// assert_eq!(sampler.sample_bias(uv, ddx, ddy, 1.0).x, 0.5);
    /// // A non-finite bias is ignored.
    /// assert_eq!(sampler.sample_bias(uv, ddx, ddy, f32::NAN), sampler.sample(uv, ddx, ddy));
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn sample_bias(&self, uv: Vec2, ddx: Vec2, ddy: Vec2, bias: f32) -> Vec4 {
        let bias = if bias.is_finite() { bias } else { 0.0 };
        self.sample_biased(uv, ddx, ddy, bias)
    }

    /// Bias and clamp a level of detail (NaN → the maximum level, as an unmeasurable footprint).
    #[inline]
    fn clamp_lod(&self, lod: f32) -> f32 {
        let d = &self.descriptor;
        let biased = lod + d.lod_bias;
        // `f32::clamp` written out: the same comparisons, without its `min ≤ max` assertion
        // (sanitising guarantees it), which kept it out of line — a call per lookup.
        if biased.is_nan() {
            d.lod_max_clamp
        } else if biased < d.lod_min_clamp {
            d.lod_min_clamp
        } else if biased > d.lod_max_clamp {
            d.lod_max_clamp
        } else {
            biased
        }
    }

    #[inline(always)]
    fn sample_biased(&self, uv: Vec2, ddx: Vec2, ddy: Vec2, bias: f32) -> Vec4 {
        let levels = self.chain.levels();
        match self.path {
            // Level 0 under the one filter whatever the footprint (see `across_levels`). Tested
            // for non-finite coordinates only off its inside shortcut, which rejects them.
            LookupPath::SingleLevelNearest => unpremultiply_texels::<T, false>(
                nearest_inside_first(&levels[0], uv, &self.addressing),
            ),
            _ if !uv.is_finite() => Vec4::ZERO,
            LookupPath::SingleLevelBilinear => unpremultiply_texels::<T, false>(
                level_filters::bilinear(&levels[0], uv, &self.addressing),
            ),
            LookupPath::Trilinear => {
                let lod = self.clamp_lod(lod::lod(ddx, ddy, self.chain.base().size()) + bias);
                unpremultiply_texels::<T, false>(self.across_levels(lod, |level, _| {
                    level_filters::bilinear(&levels[level], uv, &self.addressing)
                }))
            }
            LookupPath::TrilinearRepeatPow2 { opaque: true } => {
                self.trilinear_repeat_pow2::<true>(uv, ddx, ddy, bias)
            }
            LookupPath::TrilinearRepeatPow2 { opaque: false } => {
                self.trilinear_repeat_pow2::<false>(uv, ddx, ddy, bias)
            }
            LookupPath::TrilinearResolved { opaque } => {
                let lod = self.clamp_lod(lod::lod(ddx, ddy, self.chain.base().size()) + bias);
                let c = self.at_lod_premultiplied(uv, lod);
                if opaque {
                    unpremultiply_texels::<T, true>(c)
                } else {
                    unpremultiply_texels::<T, false>(c)
                }
            }
            LookupPath::General => self.sample_general(uv, ddx, ddy, bias),
        }
    }

    /// `across_levels` for [`LookupPath::TrilinearRepeatPow2`] (both filters linear, linear
    /// between levels) written out, so that both levels' lookups inline into the caller.
    #[inline(always)]
    fn trilinear_repeat_pow2<const OPAQUE: bool>(
        &self,
        uv: Vec2,
        ddx: Vec2,
        ddy: Vec2,
        bias: f32,
    ) -> Vec4 {
        let lod = self.clamp_lod(lod::lod(ddx, ddy, self.chain.base().size()) + bias);
        unpremultiply_texels::<T, OPAQUE>(self.resolved_at::<OPAQUE, false, false>(uv, lod))
    }

    /// [`filter_premultiplied`](Self::filter_premultiplied) through the kernel
    /// [`AtLod`] chose: the same values.
    #[inline(always)]
    fn at_lod_premultiplied(&self, uv: Vec2, lod: f32) -> Vec4 {
        let AtLod::ResolvedTrilinear { opaque, clamp } = self.at_lod else {
            return self.filter_premultiplied(uv, lod);
        };
        resolved_kernel!(opaque, clamp, self.resolved_at(uv, lod))
    }

    /// The mean of the plan's probes at a (biased, clamped) level of detail, premultiplied:
    /// `Σᵢ at_lod_premultiplied(uv + offset(i), lod) / count`, with the kernel and the two
    /// levels chosen once for all probes rather than once a probe (the same operations on
    /// each probe, in the same order: the same values).
    fn probes_premultiplied(&self, uv: Vec2, plan: &anisotropic::ProbePlan, lod: f32) -> Vec4 {
        let AtLod::ResolvedTrilinear { opaque, clamp } = self.at_lod else {
            let mut sum = Vec4::ZERO;
            for i in 0..plan.count {
                sum += self.filter_premultiplied(uv + plan.offset(i), lod);
            }
            return sum / plan.count as f32;
        };
        resolved_kernel!(opaque, clamp, self.probes_resolved(uv, plan, lod))
    }

    /// [`probes_premultiplied`](Self::probes_premultiplied) through one resolved kernel:
    /// [`resolved_at`](Self::resolved_at) per probe with the levels chosen once.
    #[inline(always)]
    fn probes_resolved<const OPAQUE: bool, const CLAMP_U: bool, const CLAMP_V: bool>(
        &self,
        uv: Vec2,
        plan: &anisotropic::ProbePlan,
        lod: f32,
    ) -> Vec4 {
        let levels = self.chain.levels();
        let (lo, hi, t) = linear_levels(lod, levels.len() - 1);
        let kernel = level_filters::bilinear_resolved::<T, OPAQUE, CLAMP_U, CLAMP_V>;
        let same = hi == lo;
        let (lo, hi) = (&levels[lo], &levels[hi]);
        let mut sum = Vec4::ZERO;
        if same {
            for i in 0..plan.count {
                sum += kernel(lo, uv + plan.offset(i));
            }
        } else {
            for i in 0..plan.count {
                let p = uv + plan.offset(i);
                let a = kernel(lo, p);
                let b = kernel(hi, p);
                sum += a + (b - a) * t;
            }
        }
        sum / plan.count as f32
    }

    /// `across_levels` for [`AtLod::ResolvedTrilinear`] written out (below λ = 0 the linear
    /// level choice gives level 0 alone, as magnification does): premultiplied.
    #[inline(always)]
    fn resolved_at<const OPAQUE: bool, const CLAMP_U: bool, const CLAMP_V: bool>(
        &self,
        uv: Vec2,
        lod: f32,
    ) -> Vec4 {
        let levels = self.chain.levels();
        let (lo, hi, t) = linear_levels(lod, levels.len() - 1);
        let kernel = level_filters::bilinear_resolved::<T, OPAQUE, CLAMP_U, CLAMP_V>;
        let a = kernel(&levels[lo], uv);
        if hi == lo {
            return a;
        }
        let b = kernel(&levels[hi], uv);
        a + (b - a) * t
    }

    /// Every configuration: anisotropic probes or EWA, cubic, mixed filters.
    #[inline(never)]
    fn sample_general(&self, uv: Vec2, ddx: Vec2, ddy: Vec2, bias: f32) -> Vec4 {
        let d = &self.descriptor;
        if d.anisotropy_clamp > 1 {
            let footprint = anisotropic::Footprint::new(ddx, ddy, self.chain.base().size());
            if let Some(footprint) = footprint {
                let max = f32::from(d.anisotropy_clamp);
                return match d.anisotropic_filter {
                    AnisotropicFilter::Probes => {
                        let plan = footprint.probes(max);
                        let lod = self.clamp_lod(plan.lod + bias);
                        if plan.count == 1 || !plan.spread {
                            unpremultiply(self.at_lod_premultiplied(uv, lod))
                        } else {
                            unpremultiply(self.probes_premultiplied(uv, &plan, lod))
                        }
                    }
                    AnisotropicFilter::Ewa => {
                        let ellipse = footprint.ewa_ellipse(max);
                        let lod = self.clamp_lod(ellipse.lod + bias);
                        unpremultiply(self.ewa_premultiplied(uv, &ellipse, lod))
                    }
                };
            }
        }
        let lod = self.clamp_lod(lod::lod(ddx, ddy, self.chain.base().size()) + bias);
        unpremultiply(self.at_lod_premultiplied(uv, lod))
    }

    /// Mag/min/mip filtering at a (biased, clamped) level of detail; premultiplied result.
    fn filter_premultiplied(&self, uv: Vec2, lod: f32) -> Vec4 {
        self.across_levels(lod, |level, filter| self.filter_level(level, uv, filter))
    }

    /// Vulkan's level selection and blending at a (biased, clamped) LOD around an in-level
    /// filter `filter_level(level, filter)`.
    #[inline]
    fn across_levels(&self, lod: f32, filter_level: impl Fn(usize, FilterMode) -> Vec4) -> Vec4 {
        let d = &self.descriptor;
        if lod <= 0.0 {
            return filter_level(0, d.mag_filter);
        }
        let last = self.chain.len() - 1;
        match d.mipmap_filter {
            MipmapFilterMode::Nearest => {
                // Vulkan: d = ⌈λ + ½⌉ − 1, clamped to the chain.
                let level = ((lod + 0.5).ceil() - 1.0).max(0.0);
                filter_level(to_level(level, last), d.min_filter)
            }
            MipmapFilterMode::Linear => {
                let (lo, hi, t) = linear_levels(lod, last);
                let a = filter_level(lo, d.min_filter);
                if hi == lo {
                    return a;
                }
                let b = filter_level(hi, d.min_filter);
                a + (b - a) * t
            }
        }
    }

    /// A depth-comparison (shadow-map) lookup at an explicit LOD: each texel's first channel `d`
    /// passes when `compare(reference, d)` holds (wgpu/Vulkan order: `Less` passes when the
    /// reference is less than the stored depth); the 0/1 results are filtered with the
    /// descriptor's filters (bilinear = 2×2 percentage-closer filtering) and mip selection. Texels
    /// outside under `ClampToBorder` compare the border colour's first channel. `None` when the
    /// descriptor has no comparison function; a non-finite `uv` or NaN reference gives 0.
    ///
    /// ```
    /// use barytex_texture::sampler::CompareFunction;
    /// use barytex_texture::{R32f, SamplerDescriptor, Texture2d, TextureSampler};
    /// use glam::Vec2;
    ///
    /// // A 2×1 depth map: 0.2 on the left, 0.8 on the right.
    /// let depth = Texture2d::from_texels(2, 1, vec![R32f(0.2), R32f(0.8)])?;
    /// let shadow = SamplerDescriptor { compare: Some(CompareFunction::Less), ..SamplerDescriptor::bilinear() };
    /// let sampler = TextureSampler::single_level(depth.clone(), shadow);
    /// // Reference 0.5 passes (0.5 < depth) on the right only; between the texels PCF gives ½.
    /// assert_eq!(sampler.sample_compare_level(Vec2::new(0.25, 0.5), 0.5, 0.0), Some(0.0));
    /// assert_eq!(sampler.sample_compare_level(Vec2::new(0.75, 0.5), 0.5, 0.0), Some(1.0));
    /// assert_eq!(sampler.sample_compare_level(Vec2::new(0.5, 0.5), 0.5, 0.0), Some(0.5));
    /// // No comparison function, no comparison.
    /// let plain = TextureSampler::single_level(depth, SamplerDescriptor::bilinear());
    /// assert_eq!(plain.sample_compare_level(Vec2::splat(0.5), 0.5, 0.0), None);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn sample_compare_level(&self, uv: Vec2, reference: f32, lod: f32) -> Option<f32> {
        let compare = self.descriptor.compare?;
        if !uv.is_finite() || reference.is_nan() {
            return Some(0.0);
        }
        let lod = self.clamp_lod(lod);
        let result = self.across_levels(lod, |level, filter| {
            let texture = &self.chain.levels()[level];
            Vec4::splat(compare::filter_level(
                texture,
                uv,
                filter,
                &self.addressing,
                |depth| compare::passes(compare, reference, depth),
            ))
        });
        Some(result.x)
    }

    fn filter_level(&self, level: usize, uv: Vec2, filter: FilterMode) -> Vec4 {
        let texture = &self.chain.levels()[level];
        match filter {
            FilterMode::Nearest => level_filters::nearest(texture, uv, &self.addressing),
            FilterMode::Linear => level_filters::bilinear(texture, uv, &self.addressing),
            FilterMode::Cubic(kernel) => {
                level_filters::bicubic(texture, uv, kernel, &self.addressing)
            }
        }
    }

    /// EWA between the two levels around `lod`. Where a LOD clamp forces a level so fine that
    /// the ellipse spans more than [`ewa::MAX_TEXELS`] texels, the level the ellipse itself selects
    /// is used instead: the clamp is honoured wherever it can be at bounded cost.
    fn ewa_premultiplied(&self, uv: Vec2, ellipse: &ewa::Ellipse, lod: f32) -> Vec4 {
        let last = self.chain.len() - 1;
        if lod >= last as f32 {
            // The footprint covers the whole texture: its last level.
            return level_filters::bilinear(&self.chain.levels()[last], uv, &self.addressing);
        }
        let floor = lod.floor();
        let lo = to_level(floor, last);
        let hi = to_level(floor + 1.0, last);
        let levels = self.chain.levels();
        let filtered = ewa::filter(&levels[lo], uv, ellipse, &self.addressing).and_then(|a| {
            if hi == lo {
                return Some(a);
            }
            let b = ewa::filter(&levels[hi], uv, ellipse, &self.addressing)?;
            Some(a + (b - a) * (lod - floor))
        });
        match filtered {
            Some(c) => c,
            None if ellipse.lod > lod => self.ewa_premultiplied(uv, ellipse, ellipse.lod),
            None => level_filters::bilinear(&levels[last], uv, &self.addressing),
        }
    }
}

/// [`level_filters::nearest`] with a shortcut for a coordinate inside the texture, the common
/// case: there `⌊u·w⌋` is the truncation (`u·w ≥ 0`, exact in f64) and every address mode maps an
/// inside index to itself, so the texel is read directly, without the general saturating floor
/// and `wrap`. The same texel, so the same value (`tests/lookup_paths.rs` compares this path with
/// the general one, which keeps `level_filters::nearest`). Transparent black for a non-finite
/// coordinate, as every lookup gives.
#[inline(always)]
fn nearest_inside_first<T: Texel>(level: &Texture2d<T>, uv: Vec2, a: &Addressing) -> Vec4 {
    let (w, h) = level.size();
    let (x, y) = (
        f64::from(uv.x) * f64::from(w),
        f64::from(uv.y) * f64::from(h),
    );
    if x >= 0.0 && x < f64::from(w) && y >= 0.0 && y < f64::from(h) {
        let (i, j) = (x as u32 as usize, y as u32 as usize);
        return premultiply(level.texels()[j * w as usize + i].to_linear());
    }
    if !uv.is_finite() {
        return Vec4::ZERO;
    }
    level_filters::nearest(level, uv, a)
}

/// Vulkan's linear blend between levels at a (biased, clamped) level of detail: the levels
/// `⌊λ⌋` and `⌊λ⌋ + 1` clamped to the chain (equal at its end, where only the first is read) and
/// the weight `λ − ⌊λ⌋` of the second. Level 0 alone below λ = 0 (magnification): `lo = hi = 0`.
#[inline(always)]
fn linear_levels(lod: f32, last: usize) -> (usize, usize, f32) {
    if lod <= 0.0 {
        return (0, 0, 0.0);
    }
    if lod < 8_388_608.0 {
        // 0 < λ < 2²³, the common case: the floor is the truncation, an exact integer, and the
        // levels are integer minima — what the general lines below compute, without float
        // comparisons and saturating float-to-integer casts.
        let i = lod as u32;
        let floor = i as f32;
        let i = i as usize;
        return (i.min(last), (i + 1).min(last), lod - floor);
    }
    let floor = floor_f32(lod);
    (
        to_level(floor, last),
        to_level(floor + 1.0, last),
        lod - floor,
    )
}

/// `x.floor()` without the library call it is on the x86-64 baseline (no SSE4.1): truncation,
/// corrected below negative non-integers. Identical to `f32::floor` for every f32 (tested).
#[inline]
fn floor_f32(x: f32) -> f32 {
    // 2²³: from there on every f32 is an integer (and ±∞, NaN pass through).
    if x.abs() < 8_388_608.0 {
        let t = x as i32 as f32;
        if t == x {
            x // keeps −0.0
        } else if t > x {
            t - 1.0
        } else {
            t
        }
    } else {
        x
    }
}

/// A non-negative, finite level number as an index clamped to `last`.
fn to_level(level: f32, last: usize) -> usize {
    if level >= last as f32 {
        last
    } else {
        // 0 ≤ level < last ≤ usize range.
        level.max(0.0) as usize
    }
}

impl<T: Texel> Sampler for TextureSampler<T> {
    #[inline]
    fn sample(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4 {
        self.sample_biased(uv, ddx, ddy, 0.0)
    }

    fn sample_level(&self, uv: Vec2, lod: f32) -> Vec4 {
        if !uv.is_finite() {
            return Vec4::ZERO;
        }
        unpremultiply(self.filter_premultiplied(uv, self.clamp_lod(lod)))
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec2;
    use proptest::prelude::*;

    use super::{AtLod, TextureSampler, floor_f32, linear_levels, to_level};
    use crate::sampler::{AddressMode, AnisotropicFilter, SamplerDescriptor};
    use crate::{MipChain, MipOptions, Sampler, Srgba8, Texture2d};

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// The resolved kernels that anisotropic probes (and the general path's plain
        /// trilinear filtering) take — each axis repeating over power-of-two levels or clamped
        /// to the edge over levels of any size — give the general filtering's bits, over
        /// translucent and over opaque textures, near and far away; a repeating axis whose
        /// sides are not powers of two keeps the general filtering.
        #[test]
        fn probes_through_the_resolved_kernels_equal_the_general_filtering(
            w in 1_u32..70,
            h in 1_u32..70,
            clamp_u in any::<bool>(),
            clamp_v in any::<bool>(),
            seed in any::<u32>(),
            opaque in any::<bool>(),
            anisotropy in prop_oneof![Just(1_u16), Just(4), Just(16)],
            uv in (-3.0e3_f32..3.0e3, -3.0_f32..3.0),
            ddx in (-0.5_f32..0.5, -0.5_f32..0.5),
            ddy in (-0.05_f32..0.05, -0.05_f32..0.05),
            bias in -1.0_f32..3.0,
        ) {
            // Repeating axes mostly over powers of two (random sides rarely are).
            let side = |n: u32, clamp: bool| if clamp || n.is_multiple_of(4) { n } else { n.next_power_of_two() };
            let (w, h) = (side(w, clamp_u), side(h, clamp_v));
            let base = Texture2d::from_fn(w, h, |x, y| {
                let v = (x.wrapping_mul(2_654_435_761) ^ y.wrapping_mul(40_503) ^ seed).to_le_bytes();
                Srgba8([v[0], v[1], v[2], if opaque { 255 } else { v[3] }])
            }).expect("small");
            let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
            let mode = |clamp: bool| if clamp { AddressMode::ClampToEdge } else { AddressMode::Repeat };
            let descriptor = SamplerDescriptor {
                anisotropy_clamp: anisotropy,
                anisotropic_filter: AnisotropicFilter::Probes,
                lod_bias: bias,
                address_mode_u: mode(clamp_u),
                address_mode_v: mode(clamp_v),
                ..SamplerDescriptor::trilinear()
            };
            let fast = TextureSampler::new(chain, descriptor);
            let resolved = (clamp_u || w.is_power_of_two()) && (clamp_v || h.is_power_of_two());
            let expected = if resolved {
                AtLod::ResolvedTrilinear { opaque, clamp: [clamp_u, clamp_v] }
            } else {
                AtLod::General
            };
            prop_assert_eq!(fast.at_lod, expected);
            let general = TextureSampler { at_lod: AtLod::General, ..fast.clone() };
            let (uv, ddx, ddy) = (Vec2::from(uv), Vec2::from(ddx), Vec2::from(ddy));
            let bits = |s: &TextureSampler<Srgba8>| s.sample(uv, ddx, ddy).to_array().map(f32::to_bits);
            prop_assert_eq!(bits(&fast), bits(&general));
        }
    }

    #[test]
    fn linear_levels_short_path_is_the_general_formula() {
        let general = |lod: f32, last: usize| {
            if lod <= 0.0 {
                return (0, 0, 0.0);
            }
            let floor = floor_f32(lod);
            (
                to_level(floor, last),
                to_level(floor + 1.0, last),
                lod - floor,
            )
        };
        let mut lods: Vec<f32> = (0..=u32::MAX)
            .step_by(4099)
            .map(f32::from_bits)
            .filter(|x| *x > 0.0 && x.is_finite())
            .collect();
        for i in 0..40_u32 {
            let x = i as f32;
            lods.extend([x, x.next_up(), x.next_down(), x + 0.5]);
        }
        lods.extend([
            8_388_607.5,
            8_388_608.0,
            8_388_609.0,
            f32::MAX,
            f32::INFINITY,
        ]);
        for last in [0, 1, 5, 11, 31] {
            for &lod in &lods {
                let (a, b) = (linear_levels(lod, last), general(lod, last));
                assert!(
                    a.0 == b.0 && a.1 == b.1 && a.2.to_bits() == b.2.to_bits(),
                    "{lod:e}, last {last}: {a:?} vs {b:?}"
                );
            }
        }
    }

    #[test]
    fn floor_f32_is_the_library_floor_bit_for_bit() {
        let check = |x: f32| {
            let (got, want) = (floor_f32(x), x.floor());
            assert!(
                got.to_bits() == want.to_bits() || (got.is_nan() && want.is_nan()),
                "{x:e}: {got:e} vs {want:e}"
            );
        };
        // A stride through every bit pattern (both signs, subnormals, ±∞, NaN payloads)...
        for bits in (0..=u32::MAX).step_by(97) {
            check(f32::from_bits(bits));
        }
        // ...and every f32 next to the integers where the floor changes, and near 2²³.
        for i in -300_i32..300 {
            let x = i as f32;
            for d in -3_i32..=3 {
                check(f32::from_bits((x.to_bits() as i32 + d) as u32));
            }
        }
        for x in [
            0.0,
            -0.0,
            8_388_607.5,
            -8_388_607.5,
            8_388_608.0,
            -8_388_609.0,
        ] {
            check(x);
        }
    }
}
