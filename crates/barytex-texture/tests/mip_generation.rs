//! Mip-chain generation: sizes for every shape, the box filter's exactness (mean preserved,
//! odd sides integrated exactly), constants, linear light vs sRGB-naive, alpha coverage, limits.

use barytex_texture::mip_chain::{full_length, level_size};
use barytex_texture::{
    Limits, MipChain, MipColorSpace, MipFilter, MipOptions, Rgba32f, Srgba8, Texel, Texture2d,
    TextureError,
};
use glam::{DVec4, Vec4};
use proptest::prelude::*;

const FILTERS: [MipFilter; 3] = [MipFilter::Box, MipFilter::Kaiser, MipFilter::Lanczos3];

fn random_f32(w: u32, h: u32, seed: u64) -> Texture2d<Rgba32f> {
    let mut state = seed | 1;
    Texture2d::from_fn(w, h, |_, _| {
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        Rgba32f([next(), next(), next(), 1.0])
    })
    .expect("small")
}

fn mean(texture: &Texture2d<Rgba32f>) -> DVec4 {
    let sum: DVec4 = texture
        .texels()
        .iter()
        .map(|t| Vec4::from_array(t.0).as_dvec4())
        .sum();
    sum / texture.texels().len() as f64
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Level sizes halve (rounded down, at least 1) down to 1×1, for every shape and filter.
    #[test]
    fn chains_have_the_halving_sizes(w in 1_u32..70, h in 1_u32..70, which in 0_usize..3) {
        let options = MipOptions { filter: FILTERS[which], ..MipOptions::default() };
        let chain = MipChain::generate(random_f32(w, h, 1), &options).expect("small");
        prop_assert_eq!(chain.len(), full_length(w, h));
        prop_assert!(chain.is_complete());
        for (i, level) in chain.levels().iter().enumerate() {
            prop_assert_eq!(level.size(), level_size(w, h, i));
        }
    }

    /// The box filter preserves the mean for every size: each level's mean equals the base mean
    /// within `4·ε·L` (texels in [0, 1)), even and odd sides alike.
    #[test]
    fn box_preserves_the_mean(w in 1_u32..70, h in 1_u32..70, seed in any::<u64>()) {
        let base = random_f32(w, h, seed);
        let want = mean(&base);
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        for (level, texture) in chain.levels().iter().enumerate() {
            let got = mean(texture);
            let bound = 4.0 * f64::from(f32::EPSILON) * level as f64;
            prop_assert!((got - want).abs().max_element() <= bound,
                "level {level} of {w}×{h}: {got:?} vs {want:?}");
        }
    }

    /// A constant texture stays constant under every filter and colour space.
    #[test]
    fn constant_stays_constant(w in 1_u32..40, h in 1_u32..40, value in any::<[u8; 4]>(),
                               which in 0_usize..3, linear in any::<bool>()) {
        let base = Texture2d::new(w, h, Srgba8(value)).expect("small");
        let options = MipOptions {
            filter: FILTERS[which],
            color_space: if linear { MipColorSpace::LinearLight } else { MipColorSpace::SrgbNaive },
            ..MipOptions::default()
        };
        let chain = MipChain::generate(base, &options).expect("small");
        for level in chain.levels() {
            // Transparent texels keep no colour through premultiplication: compare alpha then.
            for t in level.texels() {
                if value[3] == 0 && linear {
                    prop_assert_eq!(t.0[3], 0);
                } else {
                    prop_assert_eq!(t.0, value);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// A constant float texture stays exactly constant through the box filter, odd sides
    /// included (the 3-tap polyphase weights and sums in f32 once moved 0.74211603 on an 11×11
    /// texture to 0.7421162 two levels down, found by `value_scale.rs`).
    #[test]
    fn float_constants_stay_exactly_constant(
        w in 1_u32..40, h in 1_u32..40, c in -1.0_f32..1.0, k in -30_i32..=30,
    ) {
        let c = c * 2f32.powi(k);
        let base = Texture2d::new(w, h, Rgba32f([c, -c, c * 0.5, 1.0])).expect("small");
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        for (i, level) in chain.levels().iter().enumerate() {
            for t in level.texels() {
                prop_assert_eq!(t.0, [c, -c, c * 0.5, 1.0], "level {}", i);
            }
        }
    }
}

/// An odd side is integrated exactly: level 1 of a 5×1 texture is the exact box average of the
/// source over each output's footprint [2.5·i, 2.5·(i + 1)).
#[test]
fn odd_sides_integrate_the_footprint_exactly() {
    let values = [0.1_f32, 0.7, 0.3, 0.9, 0.5];
    let base =
        Texture2d::from_fn(5, 1, |x, _| Rgba32f([values[x as usize], 0.0, 0.0, 1.0])).expect("5×1");
    let chain = MipChain::generate(base, &MipOptions::default()).expect("chain");
    let level = &chain.levels()[1];
    let v: Vec<f64> = values.iter().map(|&x| f64::from(x)).collect();
    let exact = [
        (v[0] * 1.0 + v[1] * 1.0 + v[2] * 0.5) / 2.5,
        (v[2] * 0.5 + v[3] * 1.0 + v[4] * 1.0) / 2.5,
    ];
    for (i, want) in exact.iter().enumerate() {
        let got = f64::from(level.texels()[i].0[0]);
        assert!(
            (got - want).abs() < 4.0 * f64::from(f32::EPSILON),
            "{i}: {got} vs {want}"
        );
    }
}

/// Linear light vs sRGB-naive on a black-and-white checker: the linear-light reduction gives
/// the true mean grey (byte 188), the naive one the darker byte 128 — the difference the report
/// shows.
#[test]
fn linear_light_and_naive_differ_as_expected() {
    let checker = Texture2d::from_fn(2, 2, |x, y| {
        Srgba8(if (x + y) % 2 == 0 {
            [0, 0, 0, 255]
        } else {
            [255; 4]
        })
    })
    .expect("2×2");
    let linear = MipChain::generate(checker.clone(), &MipOptions::default()).expect("chain");
    let naive = MipChain::generate(
        checker,
        &MipOptions {
            color_space: MipColorSpace::SrgbNaive,
            ..MipOptions::default()
        },
    )
    .expect("chain");
    assert_eq!(linear.levels()[1].texels()[0].0, [188, 188, 188, 255]);
    assert_eq!(naive.levels()[1].texels()[0].0, [128, 128, 128, 255]);
}

/// Alpha-coverage preservation keeps the fraction of texels passing the alpha test close to the
/// base's, where plain averaging lets sparse foliage vanish.
#[test]
fn alpha_coverage_is_preserved() {
    // Foliage-like noise: alpha uniform in [0, 1], about 20 % of texels pass alpha ≥ 0.8.
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    let base = Texture2d::from_fn(64, 64, |_, _| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        Srgba8([40, 160, 40, (state >> 56) as u8])
    })
    .expect("64²");
    let coverage = |t: &Texture2d<Srgba8>| {
        t.texels().iter().filter(|t| t.to_linear().w >= 0.8).count() as f32
            / t.texels().len() as f32
    };
    let target = coverage(&base);
    assert!((target - 0.2).abs() < 0.03, "{target}");
    let plain = MipChain::generate(base.clone(), &MipOptions::default()).expect("chain");
    let kept = MipChain::generate(
        base,
        &MipOptions {
            alpha_coverage: Some(0.8),
            ..MipOptions::default()
        },
    )
    .expect("chain");
    // Averaging pulls alpha towards the mean ½: by level 3 (8²) almost nothing passes.
    assert!(
        coverage(&plain.levels()[3]) < 0.05,
        "{}",
        coverage(&plain.levels()[3])
    );
    // Preserved: within one texel's share (or 0.03) of the base coverage down to 4×4.
    for level in &kept.levels()[1..5] {
        let texels = level.texels().len() as f32;
        assert!(
            (coverage(level) - target).abs() <= (1.0 / texels).max(0.03),
            "coverage {} vs {target} at {:?}",
            coverage(level),
            level.size()
        );
    }
}

/// The chain's total bytes count against the limits before anything is allocated.
#[test]
fn limits_count_every_level() {
    let base = Texture2d::new(512, 512, Srgba8([0; 4])).expect("512²");
    let limits = Limits {
        max_bytes: 512 * 512 * 4 + 1000,
        ..Limits::default()
    };
    let result = MipChain::generate_with_limits(base, &MipOptions::default(), &limits);
    assert!(matches!(
        result,
        Err(TextureError::TooLarge {
            what: "mip chain bytes",
            ..
        })
    ));
}

/// `max_levels` stops the chain early.
#[test]
fn partial_chains_stop_where_asked() {
    let chain = MipChain::generate(
        random_f32(64, 16, 3),
        &MipOptions {
            max_levels: Some(3),
            ..MipOptions::default()
        },
    )
    .expect("chain");
    assert_eq!(chain.len(), 3);
    assert!(!chain.is_complete());
}
