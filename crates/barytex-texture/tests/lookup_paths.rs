//! The sampler resolves a short lookup path for nearest, bilinear and trilinear configurations
//! when it is built. Each must return, bit for bit, what the general machinery returns: the
//! level of detail computed from the derivatives (`TextureSampler::lod`) and then
//! `sample_level`, which selects and blends levels through the general filter dispatch.

use barytex_texture::sampler::{AddressMode, BorderColor, FilterMode, MipmapFilterMode};
use barytex_texture::{
    MipChain, MipOptions, Sampler, SamplerDescriptor, Srgba8, Texture2d, TextureSampler,
};
use glam::{Vec2, Vec4};
use proptest::prelude::*;

const ADDRESS_MODES: [AddressMode; 4] = [
    AddressMode::ClampToEdge,
    AddressMode::Repeat,
    AddressMode::MirrorRepeat,
    AddressMode::ClampToBorder,
];

/// Translucent sRGB texels (premultiplying matters), from a seed.
fn texture(w: u32, h: u32, seed: u64) -> Texture2d<Srgba8> {
    let mut state = seed | 1;
    Texture2d::from_fn(w, h, |_, _| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let b = state.to_le_bytes();
        Srgba8([b[0], b[1], b[2], b[3]])
    })
    .expect("small")
}

fn bits(c: Vec4) -> [u32; 4] {
    c.to_array().map(f32::to_bits)
}

/// The short paths' configurations, each over one level and over a full chain.
fn configurations() -> Vec<SamplerDescriptor> {
    let mut out = Vec::new();
    for filter in [FilterMode::Nearest, FilterMode::Linear] {
        for mipmap_filter in [MipmapFilterMode::Nearest, MipmapFilterMode::Linear] {
            out.push(SamplerDescriptor {
                mag_filter: filter,
                min_filter: filter,
                mipmap_filter,
                border_color: Some(BorderColor::OpaqueWhite),
                ..SamplerDescriptor::default()
            });
        }
    }
    // Clamps (no bias: `lod` applies the descriptor's bias and `sample_level` would apply it
    // again, while clamping twice changes nothing).
    out.push(SamplerDescriptor {
        lod_min_clamp: 0.5,
        lod_max_clamp: 2.25,
        ..SamplerDescriptor::trilinear()
    });
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn short_paths_equal_the_general_path(
        w in 1_u32..40,
        h in 1_u32..40,
        seed in any::<u64>(),
        mode_u in 0_usize..4,
        mode_v in 0_usize..4,
        uv in (-3.0_f32..3.0, -3.0_f32..3.0),
        ddx in (-0.5_f32..0.5, -0.5_f32..0.5),
        ddy in (-0.5_f32..0.5, -0.5_f32..0.5),
    ) {
        let base = texture(w, h, seed);
        let chain = MipChain::generate(base.clone(), &MipOptions::default()).expect("small");
        let (uv, ddx, ddy) = (Vec2::from(uv), Vec2::from(ddx), Vec2::from(ddy));
        for descriptor in configurations() {
            let descriptor = SamplerDescriptor {
                address_mode_u: ADDRESS_MODES[mode_u],
                address_mode_v: ADDRESS_MODES[mode_v],
                ..descriptor
            };
            for levels in [MipChain::single(base.clone()), chain.clone()] {
                let sampler = TextureSampler::new(levels, descriptor);
                let lod = sampler.lod(ddx, ddy, 0.0);
                prop_assert_eq!(
                    bits(sampler.sample(uv, ddx, ddy)),
                    bits(sampler.sample_level(uv, lod)),
                    "{:?}, {} levels, lod {}", descriptor, sampler.chain().len(), lod
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Power-of-two sides under repeat addressing take the trilinear path that masks indices
    /// (random sides above rarely are powers of two): far-away, huge and texel-aligned
    /// coordinates included, over translucent and over opaque textures.
    #[test]
    fn repeat_power_of_two_path_equals_the_general_path(
        log_w in 0_u32..7,
        log_h in 0_u32..7,
        seed in any::<u64>(),
        uv in (-3.0e3_f32..3.0e3, -3.0_f32..3.0),
        scale in prop_oneof![Just(1.0_f32), Just(1e-3), Just(1e6), Just(1e30)],
        ddx in (-0.5_f32..0.5, -0.5_f32..0.5),
        ddy in (-0.5_f32..0.5, -0.5_f32..0.5),
        opaque in any::<bool>(),
    ) {
        let mut base = texture(1 << log_w, 1 << log_h, seed);
        if opaque {
            // Every texel opaque: the path that does not premultiply.
            for t in base.texels_mut() {
                t.0[3] = 255;
            }
        }
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        let repeat = SamplerDescriptor::trilinear().with_address_mode(AddressMode::Repeat);
        let clamped = SamplerDescriptor { lod_min_clamp: 0.5, lod_max_clamp: 2.25, ..repeat };
        let (ddx, ddy) = (Vec2::from(ddx), Vec2::from(ddy));
        let uv = Vec2::new(uv.0 * scale, uv.1);
        let aligned = Vec2::new(
            (uv.x * 4.0).round() / (4 << log_w) as f32,
            (uv.y * 4.0).round() / (4 << log_h) as f32,
        );
        for descriptor in [repeat, clamped] {
            let sampler = TextureSampler::new(chain.clone(), descriptor);
            let lod = sampler.lod(ddx, ddy, 0.0);
            for uv in [uv, aligned, Vec2::new(uv.y, uv.x)] {
                prop_assert_eq!(
                    bits(sampler.sample(uv, ddx, ddy)),
                    bits(sampler.sample_level(uv, lod)),
                    "{:?} at {:?}, lod {}", descriptor, uv, lod
                );
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// An axis clamped to the edge (any side) beside one that repeats over power-of-two sides
    /// or is clamped too takes a trilinear path that clamps or masks indices: coordinates far
    /// outside the texture on both sides, texel-aligned ones, translucent and opaque texels.
    #[test]
    fn edge_clamped_paths_equal_the_general_path(
        w in 1_u32..50,
        log_h in 0_u32..7,
        seed in any::<u64>(),
        u in -3.0e3_f32..3.0e3,
        v in -3.0_f32..3.0,
        scale in prop_oneof![Just(1.0_f32), Just(1e-3), Just(1e6), Just(1e30)],
        ddx in (-0.5_f32..0.5, -0.5_f32..0.5),
        ddy in (-0.5_f32..0.5, -0.5_f32..0.5),
        opaque in any::<bool>(),
        both_clamped in any::<bool>(),
    ) {
        // u clamped over any width; v repeating over a power of two, or clamped as well.
        let h = 1 << log_h;
        let mut base = texture(w, h, seed);
        if opaque {
            for t in base.texels_mut() {
                t.0[3] = 255;
            }
        }
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        let v_mode = if both_clamped { AddressMode::ClampToEdge } else { AddressMode::Repeat };
        let (ddx, ddy) = (Vec2::from(ddx), Vec2::from(ddy));
        let uv = Vec2::new(u * scale, v);
        let aligned = Vec2::new(
            (uv.x * 4.0).round() / (4 * w) as f32,
            (uv.y * 4.0).round() / (4 * h) as f32,
        );
        for (mode_u, mode_v) in [(AddressMode::ClampToEdge, v_mode), (v_mode, AddressMode::ClampToEdge)] {
            let trilinear = SamplerDescriptor {
                address_mode_u: mode_u,
                address_mode_v: mode_v,
                ..SamplerDescriptor::trilinear()
            };
            let clamped = SamplerDescriptor { lod_min_clamp: 0.5, lod_max_clamp: 2.25, ..trilinear };
            for descriptor in [trilinear, clamped] {
                let sampler = TextureSampler::new(chain.clone(), descriptor);
                let lod = sampler.lod(ddx, ddy, 0.0);
                for uv in [uv, aligned, Vec2::new(uv.y, uv.x)] {
                    prop_assert_eq!(
                        bits(sampler.sample(uv, ddx, ddy)),
                        bits(sampler.sample_level(uv, lod)),
                        "{:?} at {:?}, lod {}", descriptor, uv, lod
                    );
                }
            }
        }
    }
}

/// Opaque float texels that are NaN or infinite: the path that skips premultiplying (by 1)
/// still turns a non-finite colour into black, as the general path does.
#[test]
fn opaque_non_finite_float_texels_take_the_documented_values() {
    use barytex_texture::Rgba32f;
    let texels = [f32::NAN, f32::INFINITY, -f32::INFINITY, 0.25]
        .into_iter()
        .cycle()
        .take(64)
        .enumerate()
        .map(|(i, x)| Rgba32f([x, i as f32 / 64.0, 0.5, 1.0]))
        .collect();
    let base = Texture2d::from_texels(8, 8, texels).expect("small");
    let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
    let sampler = TextureSampler::new(
        chain,
        SamplerDescriptor::trilinear().with_address_mode(AddressMode::Repeat),
    );
    let (ddx, ddy) = (Vec2::new(0.2, 0.0), Vec2::new(0.0, 0.15));
    for i in 0..200 {
        let uv = Vec2::new(i as f32 * 0.013 - 1.0, i as f32 * 0.007);
        let got = sampler.sample(uv, ddx, ddy);
        assert!(!got.is_nan(), "{uv:?}: {got:?}");
        assert_eq!(
            bits(got),
            bits(sampler.sample_level(uv, sampler.lod(ddx, ddy, 0.0)))
        );
    }
}

#[test]
fn short_paths_keep_the_documented_values_for_bad_input() {
    // Non-finite coordinates give transparent black on the nearest path (which tests them only
    // off its inside shortcut) and on the bilinear one.
    for descriptor in [SamplerDescriptor::default(), SamplerDescriptor::bilinear()] {
        let sampler = TextureSampler::single_level(texture(4, 4, 7), descriptor);
        for uv in [
            Vec2::NAN,
            Vec2::new(f32::INFINITY, 0.5),
            Vec2::new(0.5, f32::NEG_INFINITY),
            Vec2::new(0.5, f32::NAN),
        ] {
            assert_eq!(
                sampler.sample(uv, Vec2::ZERO, Vec2::ZERO),
                Vec4::ZERO,
                "{descriptor:?} at {uv}"
            );
        }
    }
    let sampler = TextureSampler::single_level(texture(4, 4, 7), SamplerDescriptor::bilinear());
    // A NaN derivative on a one-level sampler still reads level 0 (there is no other).
    let at_nan = sampler.sample(Vec2::splat(0.3), Vec2::NAN, Vec2::ZERO);
    assert_eq!(
        bits(at_nan),
        bits(sampler.sample_level(Vec2::splat(0.3), 0.0))
    );
    // Huge coordinates wrap without panicking.
    let repeat = TextureSampler::single_level(
        texture(3, 5, 9),
        SamplerDescriptor::bilinear().with_address_mode(AddressMode::Repeat),
    );
    assert!(
        repeat
            .sample(Vec2::splat(3.0e38), Vec2::ZERO, Vec2::ZERO)
            .is_finite()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// `sample_pair` gives what two `sample` calls give, bit for bit, on every path: power-of-two
    /// and other sides, every pair of address modes, opaque and translucent texels, clamped
    /// levels, two footprints that choose different levels, and non-finite coordinates.
    #[test]
    fn pairs_of_lookups_equal_single_lookups(
        log_w in 0_u32..7,
        log_h in 0_u32..7,
        odd in any::<bool>(),
        seed in any::<u64>(),
        mode_u in 0_usize..4,
        mode_v in 0_usize..4,
        uv in (-3.0e3_f32..3.0e3, -3.0_f32..3.0),
        ddx in (-0.5_f32..0.5, -0.5_f32..0.5),
        ddy in (-0.5_f32..0.5, -0.5_f32..0.5),
        other_scale in prop_oneof![Just(1.0_f32), Just(0.01), Just(40.0), Just(f32::NAN)],
        opaque in any::<bool>(),
    ) {
        let (w, h) = (1 << log_w, 1 << log_h);
        let (w, h) = if odd { (w + 3, h + 1) } else { (w, h) };
        let mut base = texture(w, h, seed);
        if opaque {
            for t in base.texels_mut() {
                t.0[3] = 255;
            }
        }
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        let modes = SamplerDescriptor {
            address_mode_u: ADDRESS_MODES[mode_u],
            address_mode_v: ADDRESS_MODES[mode_v],
            ..SamplerDescriptor::trilinear()
        };
        let clamped = SamplerDescriptor { lod_min_clamp: 0.5, lod_max_clamp: 2.25, ..modes };
        let repeat = SamplerDescriptor::trilinear().with_address_mode(AddressMode::Repeat);
        let (uv, ddx, ddy) = (Vec2::from(uv), Vec2::from(ddx), Vec2::from(ddy));
        let a = [uv, ddx, ddy];
        let b = [uv * 0.5 + Vec2::splat(0.25), ddx * other_scale, ddy];
        let non_finite = [Vec2::new(f32::NAN, 0.5), ddx, ddy];
        let mut descriptors = configurations();
        descriptors.extend([modes, clamped, repeat]);
        for descriptor in descriptors {
            let sampler = TextureSampler::new(chain.clone(), descriptor);
            for (a, b) in [(a, b), (b, a), (a, a), (non_finite, a), (a, non_finite)] {
                let [pa, pb] = sampler.sample_pair(a, b);
                prop_assert_eq!(bits(pa), bits(sampler.sample(a[0], a[1], a[2])), "{:?}", descriptor);
                prop_assert_eq!(bits(pb), bits(sampler.sample(b[0], b[1], b[2])), "{:?}", descriptor);
            }
        }
    }
}
