//! Bad input the other tests do not feed: NaN/∞ texels through every filter, the sRGB transfer
//! functions and `wrap` out of their domain, sampler descriptors out of range, mip options at
//! their edges, non-square cube faces, missing files and out-of-range texel accessors.

use barytex_texture::addressing::wrap;
use barytex_texture::load::{ColorSpace, load_from_path};
use barytex_texture::sampler::{
    AddressMode, AnisotropicFilter, CompareFunction, CubicKernel, FilterMode, MipmapFilterMode,
};
use barytex_texture::srgb::{from_linear, to_linear};
use barytex_texture::{
    CubeTexture, MipChain, MipOptions, R32f, Rgba8, Rgba32f, Sampler, SamplerDescriptor, Texture2d,
    Texture3d, TextureError, TextureSampler,
};
use glam::{Vec2, Vec3, Vec4};

#[test]
fn srgb_transfer_functions_clamp_and_map_nan_to_zero() {
    for f in [to_linear, from_linear] {
        assert_eq!(f(f32::NAN).to_bits(), 0.0_f32.to_bits());
        assert_eq!(f(-f32::NAN).to_bits(), 0.0_f32.to_bits());
        assert_eq!(f(f32::NEG_INFINITY), 0.0);
        assert_eq!(f(-1.0), 0.0);
        assert_eq!(f(-0.0), 0.0);
        assert_eq!(f(-f32::MIN_POSITIVE), 0.0);
        assert_eq!(f(1.0), f(2.0));
        assert_eq!(f(f32::INFINITY), f(1.0));
        assert_eq!(f(f32::MAX), f(1.0));
        assert!((f(1.0) - 1.0).abs() < 1e-6, "{}", f(1.0));
        // Subnormals stay finite and non-negative.
        let tiny = f(1e-40);
        assert!(tiny.is_finite() && tiny >= 0.0, "{tiny}");
    }
}

#[test]
fn wrap_treats_size_zero_as_one() {
    for i in [i64::MIN, -5, -1, 0, 1, 7, i64::MAX] {
        for mode in [
            AddressMode::ClampToEdge,
            AddressMode::Repeat,
            AddressMode::MirrorRepeat,
        ] {
            assert_eq!(wrap(i, 0, mode), Some(0), "{i} {mode:?}");
            assert_eq!(wrap(i, 0, mode), wrap(i, 1, mode), "{i} {mode:?}");
        }
        let border = wrap(i, 0, AddressMode::ClampToBorder);
        assert_eq!(border, (i == 0).then_some(0), "{i}");
    }
}

#[test]
fn cubic_weights_and_taps_of_bad_distances() {
    for kernel in [
        CubicKernel::CatmullRom,
        CubicKernel::BSpline,
        CubicKernel::Mitchell,
    ] {
        // Distances that are NaN or infinite are outside the support: weight 0.
        for x in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 2.0, -2.0, 1e30] {
            assert_eq!(kernel.weight(x), 0.0, "{kernel:?} {x}");
        }
        // `taps` clamps its fraction to [0, 1] (NaN → 0): always a partition of unity.
        let at_zero = kernel.taps(0.0);
        let at_one = kernel.taps(1.0);
        for (t, expected) in [
            (f32::NAN, at_zero),
            (f32::NEG_INFINITY, at_zero),
            (-3.0, at_zero),
            (f32::INFINITY, at_one),
            (7.5, at_one),
        ] {
            let taps = kernel.taps(t);
            assert_eq!(taps, expected, "{kernel:?} t = {t}");
            let sum: f32 = taps.iter().sum();
            assert!((sum - 1.0).abs() < 1e-6, "{kernel:?} t = {t}: {taps:?}");
        }
    }
}

#[test]
fn sampler_anisotropy_clamp_is_clamped_to_1_through_16() {
    let chain = MipChain::single(Texture2d::from_fn(4, 4, |_, _| Rgba8([9; 4])).expect("small"));
    for (asked, kept) in [(0, 1), (1, 1), (16, 16), (17, 16), (u16::MAX, 16)] {
        let d = SamplerDescriptor {
            anisotropy_clamp: asked,
            ..SamplerDescriptor::default()
        };
        let sampler = TextureSampler::new(chain.clone(), d);
        assert_eq!(sampler.descriptor().anisotropy_clamp, kept, "{asked}");
    }
    // And such samplers sample: an anisotropic footprint on a constant texture is the constant.
    for filter in [AnisotropicFilter::Probes, AnisotropicFilter::Ewa] {
        for asked in [0, u16::MAX] {
            let d = SamplerDescriptor {
                anisotropy_clamp: asked,
                anisotropic_filter: filter,
                mag_filter: FilterMode::Linear,
                min_filter: FilterMode::Linear,
                mipmap_filter: MipmapFilterMode::Linear,
                ..SamplerDescriptor::default()
            };
            let sampler = TextureSampler::new(chain.clone(), d);
            let c = sampler.sample(Vec2::splat(0.3), Vec2::new(0.9, 0.0), Vec2::new(0.0, 0.01));
            assert!(
                (c - Vec4::splat(9.0 / 255.0)).abs().max_element() < 1e-6,
                "{c}"
            );
        }
    }
}

#[test]
fn compare_sampling_with_a_non_finite_lod() {
    // A depth texture 0.25 | 0.75 (left | right); `Less`: passes where reference < stored.
    let base =
        Texture2d::from_fn(8, 8, |x, _| R32f(if x < 4 { 0.25 } else { 0.75 })).expect("small");
    let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
    let sampler = TextureSampler::new(
        chain,
        SamplerDescriptor {
            compare: Some(CompareFunction::Less),
            ..SamplerDescriptor::default()
        },
    );
    let uv = Vec2::new(0.9, 0.5);
    let level0 = sampler.sample_compare_level(uv, 0.5, 0.0);
    assert_eq!(level0, Some(1.0));
    // NaN LOD → the most blurred allowed level (the 1×1 mean, 0.5: `0.5 < 0.5` fails), the
    // same as +∞; −∞ → the base level.
    let last = sampler.sample_compare_level(uv, 0.5, 100.0);
    assert_eq!(sampler.sample_compare_level(uv, 0.5, f32::NAN), last);
    assert_eq!(sampler.sample_compare_level(uv, 0.5, f32::INFINITY), last);
    assert_eq!(
        sampler.sample_compare_level(uv, 0.5, f32::NEG_INFINITY),
        level0
    );
    for lod in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let r = sampler
            .sample_compare_level(uv, 0.5, lod)
            .expect("compare set");
        assert!((0.0..=1.0).contains(&r), "{lod}: {r}");
    }
}

/// Every filter the sampler has, with the mip filter that uses the chain.
fn all_filters() -> Vec<SamplerDescriptor> {
    let mut out = Vec::new();
    for filter in [
        FilterMode::Nearest,
        FilterMode::Linear,
        FilterMode::Cubic(CubicKernel::CatmullRom),
        FilterMode::Cubic(CubicKernel::BSpline),
    ] {
        for mip in [MipmapFilterMode::Nearest, MipmapFilterMode::Linear] {
            out.push(SamplerDescriptor {
                mag_filter: filter,
                min_filter: filter,
                mipmap_filter: mip,
                ..SamplerDescriptor::default().with_address_mode(AddressMode::Repeat)
            });
        }
    }
    for anisotropic_filter in [AnisotropicFilter::Probes, AnisotropicFilter::Ewa] {
        out.push(SamplerDescriptor {
            mag_filter: FilterMode::Linear,
            min_filter: FilterMode::Linear,
            mipmap_filter: MipmapFilterMode::Linear,
            anisotropy_clamp: 16,
            anisotropic_filter,
            ..SamplerDescriptor::default().with_address_mode(AddressMode::Repeat)
        });
    }
    out
}

/// An 8 × 8 opaque grey texture with `bad` at texel (1, 1).
fn poisoned(bad: [f32; 4]) -> Texture2d<Rgba32f> {
    Texture2d::from_fn(8, 8, |x, y| {
        if (x, y) == (1, 1) {
            Rgba32f(bad)
        } else {
            Rgba32f([0.5, 0.5, 0.5, 1.0])
        }
    })
    .expect("small")
}

/// Texels holding NaN or ±∞ (only `Rgba32f`-like formats can) never make a filter panic or
/// return NaN: the sampler works on premultiplied colour and un-premultiplies at the end, where
/// a non-finite colour becomes black (alpha kept) and a NaN or non-positive alpha becomes
/// transparent black. Where the footprint does not reach the bad texel, it has no effect.
#[test]
fn non_finite_texels_never_give_nan() {
    let bads: [[f32; 4]; 6] = [
        [f32::NAN, 0.5, 0.5, 1.0],
        [f32::INFINITY, 0.5, 0.5, 1.0],
        [f32::NEG_INFINITY, 0.0, 0.0, 1.0],
        [0.5, 0.5, 0.5, f32::NAN],
        [0.5, 0.5, 0.5, f32::INFINITY],
        [f32::NAN; 4],
    ];
    let clean = poisoned([0.5, 0.5, 0.5, 1.0]);
    let grey = Vec4::new(0.5, 0.5, 0.5, 1.0);
    for bad in bads {
        let base = poisoned(bad);
        // Level 0 only (a generated chain averages the bad texel into every coarser level).
        let single = MipChain::single(base.clone());
        let chain = MipChain::generate(base, &MipOptions::default()).expect("small");
        for descriptor in all_filters() {
            let what = format!("{bad:?} {descriptor:?}");
            let near = TextureSampler::new(single.clone(), descriptor);
            let full = TextureSampler::new(chain.clone(), descriptor);
            let reference = TextureSampler::new(MipChain::single(clean.clone()), descriptor);
            for j in 0..32 {
                for i in 0..32 {
                    let uv = Vec2::new(i as f32 + 0.5, j as f32 + 0.5) / 32.0;
                    for footprint in [0.0, 1.0 / 16.0, 0.5, f32::INFINITY] {
                        let ddx = Vec2::new(footprint, 0.0);
                        let ddy = Vec2::new(0.0, footprint / 4.0);
                        for sampler in [&near, &full] {
                            let c = sampler.sample(uv, ddx, ddy);
                            assert!(!c.is_nan(), "{what}: uv {uv} footprint {footprint}: {c}");
                        }
                    }
                    let c = near.sample_level(uv, 0.0);
                    assert!(!c.is_nan(), "{what}: uv {uv}: {c}");
                    // Texels 4..8 are at least two texels from (1, 1), out of every level-0
                    // kernel's reach (cubic: 2 texels), also through Repeat.
                    let (tx, ty) = ((uv.x * 8.0) as u32, (uv.y * 8.0) as u32);
                    if (4..=6).contains(&tx) && (4..=6).contains(&ty) {
                        assert_eq!(c, reference.sample_level(uv, 0.0), "{what}: uv {uv}");
                        assert!((c - grey).abs().max_element() < 1e-6, "{what}: {c}");
                    }
                }
            }
        }
    }
    // Nearest at the bad texel's centre: the documented un-premultiplied results.
    let nearest = SamplerDescriptor::default();
    let centre = Vec2::new(1.5, 1.5) / 8.0;
    let at = |bad: [f32; 4]| {
        TextureSampler::new(MipChain::single(poisoned(bad)), nearest).sample_level(centre, 0.0)
    };
    assert_eq!(at([f32::NAN, 0.5, 0.5, 1.0]), Vec4::new(0.0, 0.0, 0.0, 1.0));
    assert_eq!(
        at([f32::INFINITY, 0.5, 0.5, 1.0]),
        Vec4::new(0.0, 0.0, 0.0, 1.0)
    );
    assert_eq!(at([0.5, 0.5, 0.5, f32::NAN]), Vec4::ZERO);
    assert_eq!(at([0.5, 0.5, 0.5, f32::NEG_INFINITY]), Vec4::ZERO);
    assert_eq!(at([0.5, 0.5, 0.5, -1.0]), Vec4::ZERO);
    assert_eq!(
        at([0.5, 0.5, 0.5, f32::INFINITY]),
        Vec4::new(0.0, 0.0, 0.0, f32::INFINITY)
    );
}

#[test]
fn mip_options_at_their_edges() {
    let base = Texture2d::from_fn(16, 8, |x, y| {
        Rgba8([(x * 16) as u8, (y * 32) as u8, 0, 255])
    })
    .expect("small");
    // `max_levels: Some(0)` is read as 1: the base alone.
    for levels in [Some(0), Some(1)] {
        let chain = MipChain::generate(
            base.clone(),
            &MipOptions {
                max_levels: levels,
                ..MipOptions::default()
            },
        )
        .expect("small");
        assert_eq!(chain.len(), 1, "{levels:?}");
        assert_eq!(chain.base(), &base);
    }
    // More than a complete chain is cut to the complete chain.
    let chain = MipChain::generate(
        base.clone(),
        &MipOptions {
            max_levels: Some(usize::MAX),
            ..MipOptions::default()
        },
    )
    .expect("small");
    assert_eq!(chain.len(), 5);
    // A non-finite alpha-coverage reference is ignored: the chain without coverage scaling.
    let plain = MipChain::generate(base.clone(), &MipOptions::default()).expect("small");
    for reference in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let chain = MipChain::generate(
            base.clone(),
            &MipOptions {
                alpha_coverage: Some(reference),
                ..MipOptions::default()
            },
        )
        .expect("small");
        assert_eq!(chain, plain, "{reference}");
    }
}

#[test]
fn cube_faces_must_be_square() {
    let face = |w, h| {
        MipChain::single(Texture2d::from_fn(w, h, |_, _| Rgba8([1, 2, 3, 255])).expect("small"))
    };
    let r = CubeTexture::new(
        std::array::from_fn(|_| face(8, 4)),
        SamplerDescriptor::default(),
    );
    assert!(
        matches!(r, Err(TextureError::InvalidParameter { what: "faces", reason }) if reason.contains("square")),
        "{:?}",
        r.err()
    );
    // One non-square face among square ones is caught by the equal-size rule.
    let r = CubeTexture::new(
        std::array::from_fn(|i| if i == 3 { face(8, 4) } else { face(8, 8) }),
        SamplerDescriptor::default(),
    );
    assert!(matches!(
        r,
        Err(TextureError::InvalidParameter { what: "faces", .. })
    ));
    let ok = CubeTexture::new(
        std::array::from_fn(|_| face(8, 8)),
        SamplerDescriptor::default(),
    );
    assert!(ok.is_ok());
}

#[test]
fn accessors_outside_are_none() {
    let mut t = Texture2d::from_fn(3, 2, |x, y| Rgba8([x as u8, y as u8, 0, 255])).expect("small");
    for (x, y) in [(3, 0), (0, 2), (3, 2), (u32::MAX, 0), (0, u32::MAX)] {
        assert!(t.texel_mut(x, y).is_none(), "({x}, {y})");
        assert_eq!(t.linear(x, y), None, "({x}, {y})");
    }
    assert!(t.texel_mut(2, 1).is_some());
    assert!(t.linear(2, 1).is_some());
    let chain = MipChain::generate(t, &MipOptions::default()).expect("small");
    assert_eq!(chain.len(), 2);
    assert!(chain.level(1).is_some());
    assert!(chain.level(2).is_none());
    assert!(chain.level(usize::MAX).is_none());
    let volume = Texture3d::from_fn([2, 3, 4], &barytex_texture::Limits::default(), |x, y, z| {
        R32f((x + y + z) as f32)
    })
    .expect("small");
    assert_eq!(volume.texel(1, 2, 3), Some(R32f(6.0)));
    for (x, y, z) in [
        (2, 0, 0),
        (0, 3, 0),
        (0, 0, 4),
        (u32::MAX, u32::MAX, u32::MAX),
    ] {
        assert_eq!(volume.texel(x, y, z), None, "({x}, {y}, {z})");
    }
}

#[test]
fn volume_sampling_with_huge_finite_coordinates() {
    let volume = Texture3d::from_fn([4, 4, 4], &barytex_texture::Limits::default(), |x, y, z| {
        Rgba32f([x as f32, y as f32, z as f32, 1.0])
    })
    .expect("small");
    for mode in [
        AddressMode::ClampToEdge,
        AddressMode::Repeat,
        AddressMode::MirrorRepeat,
        AddressMode::ClampToBorder,
    ] {
        for filter in [FilterMode::Nearest, FilterMode::Linear] {
            let d = SamplerDescriptor {
                mag_filter: filter,
                min_filter: filter,
                ..SamplerDescriptor::default().with_address_mode(mode)
            };
            for uvw in [
                Vec3::splat(1e30),
                Vec3::splat(-1e30),
                Vec3::new(f32::MAX, -f32::MAX, 1e7),
                Vec3::new(1e-40, 3e38, -3e38),
            ] {
                let c = sampler_finite(volume.sample(uvw, &d));
                // Every result is a texel value or a blend of them (or the border): in [0, 3].
                assert!(
                    c.cmpge(Vec4::ZERO).all() && c.cmple(Vec4::splat(3.0)).all(),
                    "{mode:?} {filter:?} {uvw}: {c}"
                );
            }
        }
    }
}

#[track_caller]
fn sampler_finite(c: Vec4) -> Vec4 {
    assert!(c.is_finite(), "{c}");
    c
}

#[test]
fn load_from_path_of_a_missing_file_is_a_decode_error_naming_it() {
    let missing = std::env::temp_dir().join(format!(
        "barytex-texture-missing-{}.png",
        std::process::id()
    ));
    let r = load_from_path(
        &missing,
        ColorSpace::Srgb,
        &barytex_texture::Limits::default(),
    );
    match r {
        Err(TextureError::Decode(message)) => {
            assert!(message.contains("barytex-texture-missing"), "{message}");
        }
        other => panic!("expected a Decode error, got {:?}", other.err()),
    }
    // A folder is not an image either.
    let r = load_from_path(
        std::env::temp_dir(),
        ColorSpace::Linear,
        &barytex_texture::Limits::default(),
    );
    assert!(matches!(r, Err(TextureError::Decode(_))));
}

#[test]
fn save_png_into_a_missing_folder_is_a_decode_error() {
    let t = Texture2d::from_fn(2, 2, |_, _| Rgba8([0; 4])).expect("small");
    let path = std::env::temp_dir()
        .join(format!(
            "barytex-texture-no-such-dir-{}",
            std::process::id()
        ))
        .join("out.png");
    let r = barytex_texture::load::save_png(&t, &path);
    assert!(
        matches!(&r, Err(TextureError::Decode(m)) if m.contains("out.png")),
        "{r:?}"
    );
    assert!(!path.exists());
}

/// A cube map sanitises its descriptor like `TextureSampler::new`: a NaN `lod_min_clamp` made
/// `clamp_lod` panic (`f32::clamp` with a NaN bound; found by fuzz `textures_3d`).
#[test]
fn cube_sanitises_nan_lod_clamps_and_bias() {
    let face = || {
        MipChain::single(Texture2d::from_fn(4, 4, |_, _| Rgba8([10, 20, 30, 255])).expect("small"))
    };
    for (min, max, bias) in [
        (f32::NAN, 32.0, 0.0),
        (0.0, f32::NAN, 0.0),
        (f32::NAN, f32::NAN, f32::INFINITY),
        (2.0, 1.0, f32::NAN),
    ] {
        let d = SamplerDescriptor {
            lod_min_clamp: min,
            lod_max_clamp: max,
            lod_bias: bias,
            ..SamplerDescriptor::bilinear()
        };
        let cube = CubeTexture::new(std::array::from_fn(|_| face()), d).expect("square faces");
        for lod in [f32::NAN, f32::NEG_INFINITY, -1.0, 0.0, 3.0, f32::INFINITY] {
            let c = cube.sample_level(glam::Vec3::X, lod);
            assert!(
                (c - glam::Vec4::new(10.0, 20.0, 30.0, 255.0) / 255.0)
                    .abs()
                    .max_element()
                    < 1e-6
            );
        }
        let c = cube.sample(glam::Vec3::Y, glam::Vec3::NAN, glam::Vec3::ZERO);
        assert!(c.is_finite(), "{c:?}");
    }
}

/// A PNG whose palette chunk is 550 bytes (not whole three-byte entries) is refused with a
/// decode error. The `png` crate (0.18.1) panics on it in its palette expansion; the
/// `png_jpeg_loader` fuzz target found it (fuzzing builds skip the checksums), and this copy has
/// valid CRCs, so any build reaches the panic without the check. PNG §11.2.3 makes such a chunk
/// an error.
#[test]
fn a_palette_of_partial_entries_is_refused_not_a_panic() {
    use barytex_texture::Limits;
    use barytex_texture::load::load_from_memory;

    let bytes = include_bytes!("inputs/plte-length-550.png");
    // The fuzz target's small limits, and the defaults.
    let small = Limits {
        max_width: 64,
        max_height: 64,
        max_bytes: 64 * 64 * 16,
    };
    for (color_space, limits) in [ColorSpace::Srgb, ColorSpace::Linear]
        .into_iter()
        .flat_map(|c| [(c, small), (c, Limits::default())])
    {
        let result = load_from_memory(bytes, color_space, &limits);
        assert!(
            matches!(&result, Err(TextureError::Decode(m)) if m.contains("PLTE")),
            "{:?}",
            result.map(|t| t.size())
        );
    }
}
