//! The sampler's documented range and constant bounds at every scale of texel values: float
//! textures (`Rgba32f`) whose colours are scaled by `2^k`, `k ∈ [−30, 30]`, on random footprints
//! (random `uv`, derivatives from magnification to strong minification and anisotropy). The
//! bounds are relative to the largest texel magnitude — `4·ε·max|texel|` for nearest, bilinear
//! and trilinear, `16·ε·max|texel|` for B-spline, anisotropic probes and EWA — as for 8-bit
//! textures, whose values are at most 1.

use barytex_texture::sampler::{AddressMode, AnisotropicFilter, CubicKernel, FilterMode};
use barytex_texture::{
    MipChain, MipOptions, Rgba32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler,
};
use glam::{Vec2, Vec4};
use proptest::prelude::*;

/// The filters documented to stay within the texels' range, and whether they sum up to 16 terms.
fn range_preserving() -> Vec<(SamplerDescriptor, bool)> {
    let mut out = vec![
        (SamplerDescriptor::default(), false),
        (SamplerDescriptor::bilinear(), false),
        (SamplerDescriptor::trilinear(), false),
        (
            SamplerDescriptor {
                mag_filter: FilterMode::Cubic(CubicKernel::BSpline),
                min_filter: FilterMode::Cubic(CubicKernel::BSpline),
                ..SamplerDescriptor::trilinear()
            },
            true,
        ),
        (SamplerDescriptor::anisotropic(8), true),
        (
            SamplerDescriptor {
                anisotropic_filter: AnisotropicFilter::Ewa,
                ..SamplerDescriptor::anisotropic(16)
            },
            true,
        ),
    ];
    for (d, summed) in out.clone() {
        out.push((d.with_address_mode(AddressMode::Repeat), summed));
    }
    out
}

/// A `w × h` opaque float texture, colours pseudo-random in `[−1, 1]·2^k`.
fn texture(w: u32, h: u32, seed: u64, k: i32) -> Texture2d<Rgba32f> {
    let mut state = seed | 1;
    let scale = 2f32.powi(k);
    Texture2d::from_fn(w, h, |_, _| {
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            ((state >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0) * scale
        };
        Rgba32f([next(), next(), next(), 1.0])
    })
    .expect("small")
}

fn footprint() -> impl Strategy<Value = (Vec2, Vec2, Vec2)> {
    (
        (-1.0_f32..2.0, -1.0_f32..2.0),
        (-0.5_f32..0.5, -0.5_f32..0.5, -0.5_f32..0.5, -0.5_f32..0.5),
        -8_i32..2,
    )
        .prop_map(|((u, v), (a, b, c, d), e)| {
            let s = 2f32.powi(e);
            (Vec2::new(u, v), Vec2::new(a, b) * s, Vec2::new(c, d) * s)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// Range: every range-preserving filter's result is within the texels' range widened by
    /// `4·ε·max|texel|` (`16·ε·max|texel|` for the summing filters), at every value scale.
    #[test]
    fn range_bound_is_relative_to_the_largest_texel(
        w in 1_u32..12, h in 1_u32..12, seed in any::<u64>(), k in -30_i32..=30,
        (uv, ddx, ddy) in footprint(),
    ) {
        let base = texture(w, h, seed, k);
        let texels: Vec<Vec4> = base.texels().iter().map(|t| Vec4::from_array(t.0)).collect();
        let lo = texels.iter().fold(Vec4::splat(f32::INFINITY), |a, &b| a.min(b));
        let hi = texels.iter().fold(Vec4::splat(f32::NEG_INFINITY), |a, &b| a.max(b));
        let m = texels.iter().fold(0.0f32, |m, t| m.max(t.abs().max_element()));
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        for (desc, summed) in range_preserving() {
            let got = TextureSampler::new(chain.clone(), desc).sample(uv, ddx, ddy);
            let slack = if summed { 16.0 } else { 4.0 } * f32::EPSILON * m;
            prop_assert!(got.cmpge(lo - slack).all() && got.cmple(hi + slack).all(),
                "{desc:?} at scale 2^{k}: {got:?} not in {lo:?} … {hi:?} ± {slack:e}");
        }
    }

    /// Constants: a constant texture of value `c` samples to `c` within `2·ε·|c|` under nearest,
    /// bilinear and trilinear and `16·ε·|c|` under the others (Catmull-Rom and Mitchell too), at
    /// every value scale.
    #[test]
    fn constant_bound_is_relative_to_the_constant(
        w in 1_u32..12, h in 1_u32..12, c in -1.0_f32..1.0, k in -30_i32..=30,
        (uv, ddx, ddy) in footprint(),
    ) {
        let c = c * 2f32.powi(k);
        let base = Texture2d::from_fn(w, h, |_, _| Rgba32f([c, c, c, 1.0])).expect("small");
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        let mut filters = range_preserving();
        for kernel in [CubicKernel::CatmullRom, CubicKernel::Mitchell] {
            let cubic = FilterMode::Cubic(kernel);
            filters.push((SamplerDescriptor { mag_filter: cubic, min_filter: cubic, ..SamplerDescriptor::trilinear() }, true));
        }
        for (desc, summed) in filters {
            let got = TextureSampler::new(chain.clone(), desc).sample(uv, ddx, ddy);
            let slack = if summed { 16.0 } else { 2.0 } * f32::EPSILON * c.abs();
            prop_assert!((got.truncate() - c).abs().max_element() <= slack,
                "{desc:?}: constant {c:e} sampled as {got:?}");
        }
    }
}

/// Whether the absolute form of the range bound (`± 4 ε` / `± 16 ε` whatever the values) also
/// holds for float textures with large values (2²⁰): counted over seeded random footprints for
/// every range-preserving filter. The documentation states the relative form (which the
/// property tests above enforce); this records how far beyond the absolute slack results go.
#[test]
fn absolute_range_slack_at_large_values() {
    let mut beyond = 0;
    let mut worst = 0.0f32;
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    for seed in 1..60u64 {
        let base = texture(7, 5, seed, 20);
        let texels: Vec<Vec4> = base
            .texels()
            .iter()
            .map(|t| Vec4::from_array(t.0))
            .collect();
        let lo = texels
            .iter()
            .fold(Vec4::splat(f32::INFINITY), |a, &b| a.min(b));
        let hi = texels
            .iter()
            .fold(Vec4::splat(f32::NEG_INFINITY), |a, &b| a.max(b));
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        for (desc, summed) in range_preserving() {
            let sampler = TextureSampler::new(chain.clone(), desc);
            for _ in 0..40 {
                let uv = Vec2::new(next() * 3.0 - 1.0, next() * 3.0 - 1.0);
                let s = 2f32.powi((next() * 10.0) as i32 - 8);
                let ddx = Vec2::new(next() - 0.5, next() - 0.5) * s;
                let ddy = Vec2::new(next() - 0.5, next() - 0.5) * s;
                let got = sampler.sample(uv, ddx, ddy);
                let excess = (lo - got).max(got - hi).max_element();
                let slack = if summed { 16.0 } else { 4.0 } * f32::EPSILON;
                worst = worst.max(excess);
                if excess > slack {
                    beyond += 1;
                }
            }
        }
    }
    println!("values ~2^20: {beyond} results beyond the absolute slack, worst excess {worst:e}");
    // The relative slack covers every one of them (asserted on all scales above).
    assert!(worst <= 16.0 * f32::EPSILON * 2f32.powi(20));
}
