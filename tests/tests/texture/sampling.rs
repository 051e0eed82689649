//! The sampler against the Vulkan specification (dEQP-style allowed-result boxes) and its
//! invariants: constants, texel centres, ranges, periodicity, symmetry, LOD monotonicity, the
//! linear-light blend of sRGB texels, and hard inputs.

use barytex_testkit::sampling_invariants::check_sample_level;
use barytex_texture::sampler::{
    AddressMode, AnisotropicFilter, BorderColor, CubicKernel, FilterMode, MipmapFilterMode,
};
use barytex_texture::{
    MipChain, MipOptions, Rgba8, Rgba32f, Sampler, SamplerDescriptor, Srgba8, Texel, Texture2d,
    TextureSampler,
};
use glam::{Vec2, Vec4};
use proptest::prelude::*;

const ADDRESS_MODES: [AddressMode; 4] = [
    AddressMode::ClampToEdge,
    AddressMode::Repeat,
    AddressMode::MirrorRepeat,
    AddressMode::ClampToBorder,
];

fn texture(w: u32, h: u32, seed: u64) -> Texture2d<Rgba8> {
    let mut state = seed | 1;
    Texture2d::from_fn(w, h, |_, _| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let b = state.to_le_bytes();
        Rgba8([b[0], b[1], b[2], 255])
    })
    .expect("small")
}

fn chain(w: u32, h: u32, seed: u64) -> MipChain<Rgba8> {
    MipChain::generate(texture(w, h, seed), &MipOptions::default()).expect("small")
}

/// Every combination of in-level filters and mip filters the verifier covers.
fn descriptors() -> Vec<SamplerDescriptor> {
    let mut out = Vec::new();
    for mode in ADDRESS_MODES {
        for mag in [FilterMode::Nearest, FilterMode::Linear] {
            for min in [FilterMode::Nearest, FilterMode::Linear] {
                for mip in [MipmapFilterMode::Nearest, MipmapFilterMode::Linear] {
                    out.push(SamplerDescriptor {
                        mag_filter: mag,
                        min_filter: min,
                        mipmap_filter: mip,
                        border_color: Some(BorderColor::OpaqueWhite),
                        ..SamplerDescriptor::default().with_address_mode(mode)
                    });
                }
            }
        }
    }
    out
}

/// The filters whose result must stay within the texels' range (Catmull-Rom and Mitchell may
/// overshoot by design).
fn range_preserving() -> Vec<SamplerDescriptor> {
    let mut out = vec![
        SamplerDescriptor::default(),
        SamplerDescriptor::bilinear(),
        SamplerDescriptor::trilinear(),
        SamplerDescriptor {
            mag_filter: FilterMode::Cubic(CubicKernel::BSpline),
            min_filter: FilterMode::Cubic(CubicKernel::BSpline),
            ..SamplerDescriptor::trilinear()
        },
        SamplerDescriptor::anisotropic(8),
        SamplerDescriptor {
            anisotropic_filter: AnisotropicFilter::Ewa,
            ..SamplerDescriptor::anisotropic(16)
        },
    ];
    for d in out.clone() {
        out.push(d.with_address_mode(AddressMode::Repeat));
        out.push(d.with_address_mode(AddressMode::MirrorRepeat));
    }
    out
}

fn all_filters() -> Vec<SamplerDescriptor> {
    let mut out = range_preserving();
    for kernel in [CubicKernel::CatmullRom, CubicKernel::Mitchell] {
        out.push(SamplerDescriptor {
            mag_filter: FilterMode::Cubic(kernel),
            min_filter: FilterMode::Cubic(kernel),
            ..SamplerDescriptor::trilinear()
        });
    }
    out
}

fn uv_strategy() -> impl Strategy<Value = Vec2> {
    (-2.0_f32..3.0, -2.0_f32..3.0).prop_map(|(u, v)| Vec2::new(u, v))
}

fn derivative_strategy() -> impl Strategy<Value = (Vec2, Vec2)> {
    (
        -0.5_f32..0.5,
        -0.5_f32..0.5,
        -0.5_f32..0.5,
        -0.5_f32..0.5,
        -8_i32..2,
    )
        .prop_map(|(a, b, c, d, e)| {
            let s = 2f32.powi(e);
            (Vec2::new(a, b) * s, Vec2::new(c, d) * s)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// dEQP-style: every `sample_level` result lies in the set the Vulkan specification allows
    /// at its minimum precisions.
    #[test]
    fn sample_level_is_inside_the_allowed_set(
        w in 1_u32..12, h in 1_u32..12, seed in any::<u64>(),
        uv in uv_strategy(), lod in -1.0_f32..5.0, which in 0_usize..64,
    ) {
        let chain = chain(w, h, seed);
        let descriptors = descriptors();
        let desc = descriptors[which % descriptors.len()];
        let sampler = TextureSampler::new(chain.clone(), desc);
        let result = sampler.sample_level(uv, lod);
        prop_assert_eq!(check_sample_level(&chain, &desc, uv, lod, result, 1e-6), Ok(()));
    }

    /// A constant texture gives that constant under every filter: nearest, bilinear and trilinear
    /// within the 2 ε of un-premultiplying (their blends are exact on constants); cubic,
    /// anisotropic and EWA within 16 ε (they sum up to 16 weighted terms and normalise).
    #[test]
    fn constant_texture_is_constant_under_every_filter(
        w in 1_u32..12, h in 1_u32..12, value in any::<[u8; 4]>(),
        uv in uv_strategy(), (ddx, ddy) in derivative_strategy(),
    ) {
        let value = Rgba8([value[0], value[1], value[2], value[3].max(1)]);
        let base = Texture2d::new(w, h, value).expect("small");
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        let want = value.to_linear();
        for desc in all_filters() {
            let got = TextureSampler::new(chain.clone(), desc).sample(uv, ddx, ddy);
            let blends_exactly = desc.anisotropy_clamp == 1
                && !matches!(desc.mag_filter, FilterMode::Cubic(_))
                && !matches!(desc.min_filter, FilterMode::Cubic(_));
            let slack = if blends_exactly { 2.0 } else { 16.0 } * f32::EPSILON;
            prop_assert!((got - want).abs().max_element() <= slack,
                "{desc:?}: {got:?} vs {want:?}");
        }
    }

    /// Nearest, bilinear, trilinear, B-spline, anisotropic and EWA results stay within the
    /// range of the texture's values (opaque texture: no un-premultiplying).
    #[test]
    fn range_preserving_filters_stay_in_range(
        w in 1_u32..12, h in 1_u32..12, seed in any::<u64>(),
        uv in uv_strategy(), (ddx, ddy) in derivative_strategy(),
    ) {
        let chain = chain(w, h, seed);
        let texels: Vec<Vec4> = chain.base().texels().iter().map(|t| t.to_linear()).collect();
        let lo = texels.iter().fold(Vec4::splat(f32::INFINITY), |a, &b| a.min(b));
        let hi = texels.iter().fold(Vec4::splat(f32::NEG_INFINITY), |a, &b| a.max(b));
        for desc in range_preserving() {
            let got = TextureSampler::new(chain.clone(), desc).sample(uv, ddx, ddy);
            let summed = desc.anisotropy_clamp > 1
                || matches!(desc.min_filter, FilterMode::Cubic(_));
            let slack = if summed { 16.0 } else { 4.0 } * f32::EPSILON;
            prop_assert!(got.cmpge(lo - slack).all() && got.cmple(hi + slack).all(),
                "{desc:?}: {got:?} not in {lo:?} … {hi:?}");
        }
    }

    /// Bilinear at a texel centre returns that texel exactly, in every address mode. (The centre
    /// `(x + ½)/w` is an f32 exactly when `w` is a power of two; for other sides the nearest f32
    /// is off-centre by < 1 ulp and the result within 2 ulp, see the next test.)
    #[test]
    fn bilinear_at_texel_centres_is_exact(
        log_w in 0_u32..6, log_h in 0_u32..6, seed in any::<u64>(), x in 0_u32..32, y in 0_u32..32,
        which in 0_usize..4,
    ) {
        let (w, h) = (1 << log_w, 1 << log_h);
        let (x, y) = (x % w, y % h);
        let base = texture(w, h, seed);
        let want = base.linear(x, y).expect("inside");
        let desc = SamplerDescriptor::bilinear().with_address_mode(ADDRESS_MODES[which]);
        let sampler = TextureSampler::single_level(base, desc);
        let uv = Vec2::new((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
        prop_assert_eq!(sampler.sample_level(uv, 0.0), want);
    }

    /// At the f32 nearest a texel centre of any size, bilinear is within the error of that
    /// coordinate: the f32 `u` is off the centre by ≤ ½ulp(u), which moves the weight by
    /// ≤ ½ulp(u)·w, so the result is within `ε·max(w, h)·|Δtexel| + 2ε`.
    #[test]
    fn bilinear_near_texel_centres_of_any_size(
        w in 1_u32..40, h in 1_u32..40, seed in any::<u64>(), x in 0_u32..40, y in 0_u32..40,
    ) {
        let (x, y) = (x % w, y % h);
        let base = texture(w, h, seed);
        let want = base.linear(x, y).expect("inside");
        let sampler = TextureSampler::single_level(base, SamplerDescriptor::bilinear());
        let uv = Vec2::new((x as f32 + 0.5) / w as f32, (y as f32 + 0.5) / h as f32);
        let got = sampler.sample_level(uv, 0.0);
        let slack = f32::EPSILON * (w.max(h) as f32 + 2.0);
        prop_assert!((got - want).abs().max_element() <= slack, "{got:?} vs {want:?}");
    }

    /// Repeat is periodic with period 1 and MirrorRepeat is symmetric about 0 and periodic with
    /// period 2 (dyadic coordinates, so `u·w` is exact).
    #[test]
    fn repeat_is_periodic_and_mirror_is_symmetric(
        seed in any::<u64>(), k in -4096_i32..4096, l in -4096_i32..4096, which in 0_usize..2,
    ) {
        let (w, h) = (8, 4);
        let filter = [SamplerDescriptor::default(), SamplerDescriptor::bilinear()][which];
        let uv = Vec2::new(k as f32 / 1024.0, l as f32 / 1024.0);
        let repeat = TextureSampler::single_level(
            texture(w, h, seed), filter.with_address_mode(AddressMode::Repeat));
        prop_assert_eq!(
            repeat.sample_level(uv, 0.0),
            repeat.sample_level(uv + Vec2::new(1.0, -3.0), 0.0)
        );
        let mirror = TextureSampler::single_level(
            texture(w, h, seed), filter.with_address_mode(AddressMode::MirrorRepeat));
        // Nearest: −u lands in the mirrored texel (except exactly on texel boundaries), bit for
        // bit; bilinear blends the same two texels in the opposite order, `a + (b − a)·t` against
        // `b + (a − b)·(1 − t)`, equal within 2 ulp.
        let (here, mirrored) = (mirror.sample_level(uv, 0.0), mirror.sample_level(-uv, 0.0));
        if which == 0 && k % 128 != 0 && l % 256 != 0 {
            prop_assert_eq!(here, mirrored);
        } else if which == 1 {
            prop_assert!((here - mirrored).abs().max_element() <= 2.0 * f32::EPSILON,
                "{here:?} vs {mirrored:?}");
        }
        prop_assert_eq!(
            mirror.sample_level(uv, 0.0),
            mirror.sample_level(uv + Vec2::new(2.0, 4.0), 0.0)
        );
    }

    /// The level of detail never decreases when the footprint grows.
    #[test]
    fn lod_is_monotone_in_the_footprint(
        (ddx, ddy) in derivative_strategy(), scale in 1.0_f32..64.0,
    ) {
        let sampler = TextureSampler::new(chain(64, 32, 1), SamplerDescriptor::trilinear());
        let a = sampler.lod(ddx, ddy, 0.0);
        let b = sampler.lod(ddx * scale, ddy * scale, 0.0);
        prop_assert!(b >= a, "{a} > {b}");
    }

    /// Nothing panics and nothing is NaN, whatever the coordinates, derivatives and LOD.
    #[test]
    fn total_on_hostile_inputs(
        u in any::<u32>(), v in any::<u32>(), dx in any::<[u32; 2]>(), dy in any::<[u32; 2]>(),
        lod in any::<u32>(), which in 0_usize..16,
    ) {
        let uv = Vec2::new(f32::from_bits(u), f32::from_bits(v));
        let ddx = Vec2::new(f32::from_bits(dx[0]), f32::from_bits(dx[1]));
        let ddy = Vec2::new(f32::from_bits(dy[0]), f32::from_bits(dy[1]));
        let filters = all_filters();
        let desc = filters[which % filters.len()];
        let sampler = TextureSampler::new(chain(5, 3, 7), desc);
        let a = sampler.sample(uv, ddx, ddy);
        let b = sampler.sample_level(uv, f32::from_bits(lod));
        let c = sampler.sample_bias(uv, ddx, ddy, f32::from_bits(lod));
        prop_assert!(!a.is_nan() && !b.is_nan() && !c.is_nan(), "{a:?} {b:?} {c:?}");
        if !uv.is_finite() {
            prop_assert_eq!(a, Vec4::ZERO);
        }
    }
}

/// glTF's TextureLinearInterpolationTest: halfway between a black and a white sRGB texel the
/// filtered value is the linear-light mean 0.5 (sRGB byte 188), not the sRGB mean (byte 128).
#[test]
fn srgb_texels_blend_in_linear_light() {
    let base =
        Texture2d::from_texels(2, 1, vec![Srgba8([0, 0, 0, 255]), Srgba8([255; 4])]).expect("2×1");
    let sampler = TextureSampler::single_level(base, SamplerDescriptor::bilinear());
    let c = sampler.sample_level(Vec2::new(0.5, 0.5), 0.0);
    assert_eq!(c.x, 0.5);
    assert_eq!(Srgba8::from_linear(c).0, [188, 188, 188, 255]);
}

/// Premultiplied filtering: a transparent texel's colour does not bleed into the blend.
#[test]
fn transparent_texels_do_not_bleed() {
    let base = Texture2d::from_texels(
        2,
        1,
        vec![Rgba32f([1.0, 0.0, 0.0, 1.0]), Rgba32f([0.0, 1.0, 0.0, 0.0])],
    )
    .expect("2×1");
    let sampler = TextureSampler::single_level(base, SamplerDescriptor::bilinear());
    let c = sampler.sample_level(Vec2::new(0.5, 0.5), 0.0);
    assert_eq!(c, Vec4::new(1.0, 0.0, 0.0, 0.5));
}

/// Hard cases with documented values: 1×1 and 1×4096 textures, huge coordinates, zero and
/// infinite footprints, LOD far beyond the chain.
#[test]
fn hard_cases_have_documented_values() {
    let one = TextureSampler::new(chain(1, 1, 3), SamplerDescriptor::anisotropic(16));
    let texel = one.chain().base().linear(0, 0).expect("1×1");
    for uv in [Vec2::ZERO, Vec2::splat(1e7), Vec2::splat(-1e30)] {
        assert_eq!(one.sample(uv, Vec2::X, Vec2::Y), texel);
    }
    let tall = chain(1, 4096, 5);
    assert_eq!(tall.len(), 13);
    let sampler = TextureSampler::new(tall.clone(), SamplerDescriptor::trilinear());
    let last = tall.levels()[12].linear(0, 0).expect("1×1");
    // An infinite footprint and a LOD beyond the chain both read the last level.
    assert_eq!(
        sampler.sample(Vec2::splat(0.3), Vec2::INFINITY, Vec2::ZERO),
        last
    );
    assert_eq!(sampler.sample_level(Vec2::splat(0.3), 1e9), last);
    // A zero footprint magnifies: bilinear on the base level.
    let base_value = sampler.sample_level(Vec2::splat(0.3), 0.0);
    assert_eq!(
        sampler.sample(Vec2::splat(0.3), Vec2::ZERO, Vec2::ZERO),
        base_value
    );
    // NaN coordinates: transparent black.
    assert_eq!(
        sampler.sample(Vec2::NAN, Vec2::ZERO, Vec2::ZERO),
        Vec4::ZERO
    );
    // u = 1e7 with Repeat: the f32 coordinate is an integer, so texel 0's column.
    let repeat = TextureSampler::single_level(
        texture(4, 4, 9),
        SamplerDescriptor::default().with_address_mode(AddressMode::Repeat),
    );
    assert_eq!(
        repeat.sample_level(Vec2::new(1e7, 0.1), 0.0),
        repeat.sample_level(Vec2::new(0.0, 0.1), 0.0)
    );
}

/// Anisotropic filtering along a grazing footprint resolves the minor axis that trilinear
/// (which picks its level from the major axis) blurs away.
#[test]
fn anisotropic_filters_resolve_the_minor_axis() {
    // Vertical stripes two texels wide; the footprint is long in v (along the stripes), short
    // in u.
    let base = Texture2d::from_fn(64, 64, |x, _| {
        Rgba8([if x % 4 < 2 { 255 } else { 0 }, 0, 0, 255])
    })
    .expect("64²");
    let chain = MipChain::generate(base, &MipOptions::default()).expect("chain");
    let uv = Vec2::new(1.0 / 64.0, 0.5); // the centre of a bright stripe (texels 0–1)
    let (ddx, ddy) = (Vec2::new(0.5 / 64.0, 0.0), Vec2::new(0.0, 8.0 / 64.0));
    let truth = 1.0; // the footprint is half a texel wide, inside the stripe
    let tri =
        TextureSampler::new(chain.clone(), SamplerDescriptor::trilinear()).sample(uv, ddx, ddy);
    let aniso =
        TextureSampler::new(chain.clone(), SamplerDescriptor::anisotropic(16)).sample(uv, ddx, ddy);
    let ewa = TextureSampler::new(
        chain,
        SamplerDescriptor {
            anisotropic_filter: AnisotropicFilter::Ewa,
            ..SamplerDescriptor::anisotropic(16)
        },
    )
    .sample(uv, ddx, ddy);
    let err = |c: Vec4| (c.x - truth).abs();
    assert!(
        err(tri) > 0.3,
        "trilinear blurs across the stripes: {tri:?}"
    );
    assert!(
        err(aniso) < err(tri) / 2.0,
        "aniso {aniso:?} vs trilinear {tri:?}"
    );
    assert!(
        err(ewa) < err(tri) / 2.0,
        "EWA {ewa:?} vs trilinear {tri:?}"
    );
}

/// Comparison samplers (shadow maps): each texel compared with the reference, then filtered;
/// bilinear is 2×2 percentage-closer filtering.
#[test]
fn comparison_sampling_filters_the_comparisons() {
    use barytex_texture::R32f;
    use barytex_texture::sampler::CompareFunction;
    // Depths 0.2 | 0.8 side by side.
    let depth = Texture2d::from_texels(2, 1, vec![R32f(0.2), R32f(0.8)]).expect("2×1");
    let desc = |filter, op| SamplerDescriptor {
        mag_filter: filter,
        min_filter: filter,
        compare: Some(op),
        ..SamplerDescriptor::default()
    };
    let at = |filter, op, u: f32, reference: f32| {
        TextureSampler::single_level(depth.clone(), desc(filter, op))
            .sample_compare_level(Vec2::new(u, 0.5), reference, 0.0)
            .expect("a comparison sampler")
    };
    // Nearest: one texel decides.
    assert_eq!(
        at(FilterMode::Nearest, CompareFunction::Less, 0.25, 0.5),
        0.0
    );
    assert_eq!(
        at(FilterMode::Nearest, CompareFunction::Less, 0.75, 0.5),
        1.0
    );
    // Bilinear halfway: half the taps pass.
    assert_eq!(at(FilterMode::Linear, CompareFunction::Less, 0.5, 0.5), 0.5);
    assert_eq!(
        at(FilterMode::Linear, CompareFunction::Always, 0.5, 0.5),
        1.0
    );
    assert_eq!(
        at(FilterMode::Linear, CompareFunction::Never, 0.5, 0.5),
        0.0
    );
    assert_eq!(
        at(FilterMode::Linear, CompareFunction::GreaterEqual, 0.5, 0.1),
        0.0
    );
    // A sampler without a comparison function answers None; NaN input gives 0.
    let plain = TextureSampler::single_level(depth.clone(), SamplerDescriptor::bilinear());
    assert_eq!(plain.sample_compare_level(Vec2::splat(0.5), 0.5, 0.0), None);
    assert_eq!(
        at(FilterMode::Linear, CompareFunction::Always, f32::NAN, 0.5),
        0.0
    );
    assert_eq!(
        at(FilterMode::Linear, CompareFunction::Always, 0.5, f32::NAN),
        0.0
    );
}
