//! 3D textures and 2D arrays.

use barytex_texture::sampler::AddressMode;
use barytex_texture::{
    Limits, MipChain, R32f, Rgba32f, SamplerDescriptor, Texel, Texture2d, Texture2dArray, Texture3d,
};
use glam::{Vec2, Vec3, Vec4};
use proptest::prelude::*;

/// A trilinear function of the texel centre coordinates: `a + b·x + c·y + d·z + e·xy + f·yz +
/// g·xz + h·xyz` with small integer coefficients, so every value is exact in f32.
fn trilinear_fn(k: [i8; 8]) -> impl Fn(f64, f64, f64) -> f64 {
    move |x, y, z| {
        let k = k.map(f64::from);
        k[0] + k[1] * x
            + k[2] * y
            + k[3] * z
            + k[4] * x * y
            + k[5] * y * z
            + k[6] * x * z
            + k[7] * x * y * z
    }
}

proptest! {
    /// Trilinear interpolation reproduces trilinear functions: sampled at dyadic points inside the
    /// texel-centre lattice of a power-of-two volume, the result is the function's value within
    /// the f32 rounding of the lerps (|value| ≤ 127·(1 + 7 + 3 + 15 + 21 + 45 + 105 + 315) < 2¹⁶;
    /// 7 lerps: 8 ε·2¹⁶).
    #[test]
    fn trilinear_reproduces_trilinear_functions(
        k in any::<[i8; 8]>(), p in (0_u32..56, 0_u32..24, 0_u32..120),
    ) {
        let f = trilinear_fn(k);
        let (w, h, d) = (8_u32, 4_u32, 16_u32);
        let volume = Texture3d::from_fn([w, h, d], &Limits::default(), |x, y, z| {
            R32f(f(f64::from(x), f64::from(y), f64::from(z)) as f32)
        }).expect("small");
        // Points between texel centres: centre coordinate c ∈ [0, n − 1] in steps of 1/8.
        let (cx, cy, cz) = (f64::from(p.0) / 8.0, f64::from(p.1) / 8.0, f64::from(p.2) / 8.0);
        let uvw = Vec3::new(
            ((cx + 0.5) / f64::from(w)) as f32,
            ((cy + 0.5) / f64::from(h)) as f32,
            ((cz + 0.5) / f64::from(d)) as f32,
        );
        let got = volume.sample(uvw, &SamplerDescriptor::bilinear()).x;
        let want = f(cx, cy, cz);
        let scale = 65_536.0_f64;
        prop_assert!((f64::from(got) - want).abs() <= 8.0 * f64::from(f32::EPSILON) * scale,
            "{got} vs {want}");
    }
}

proptest! {
    /// The exactness condition of `Texture3d::sample`'s docs: integer texels with
    /// `max|texel| ≤ 2^(23 − p − q − r)`, sampled where the weights are multiples of 2⁻³ on
    /// every axis (p = q = r = 3: texels up to 2¹⁴), give the exact trilinear value, bit for bit.
    #[test]
    fn trilinear_is_exact_under_the_dyadic_condition(
        seed in any::<u64>(), p in (0_u32..56, 0_u32..24, 0_u32..120),
    ) {
        let (w, h, d) = (8_u32, 4_u32, 16_u32);
        let limit = 1_i64 << (23 - 9);
        let value = |x: u32, y: u32, z: u32| {
            let mut s = seed ^ (u64::from(x) << 40 | u64::from(y) << 20 | u64::from(z)) | 1;
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            ((s % (2 * limit as u64 + 1)) as i64 - limit) as f32
        };
        let volume = Texture3d::from_fn([w, h, d], &Limits::default(), |x, y, z| R32f(value(x, y, z)))
            .expect("small");
        let (cx, cy, cz) = (f64::from(p.0) / 8.0, f64::from(p.1) / 8.0, f64::from(p.2) / 8.0);
        let uvw = Vec3::new(
            ((cx + 0.5) / f64::from(w)) as f32,
            ((cy + 0.5) / f64::from(h)) as f32,
            ((cz + 0.5) / f64::from(d)) as f32,
        );
        let got = volume.sample(uvw, &SamplerDescriptor::bilinear()).x;
        // The exact trilinear value at the centre coordinate (cx, cy, cz), in f64 (exact: at
        // most 2¹⁴ times eighths cubed).
        let (x0, y0, z0) = (cx.floor() as u32, cy.floor() as u32, cz.floor() as u32);
        let (fx, fy, fz) = (cx.fract(), cy.fract(), cz.fract());
        let mut want = 0.0f64;
        for (i, j, k) in (0..8).map(|n| (n & 1, (n >> 1) & 1, (n >> 2) & 1)) {
            let wx = if i == 1 { fx } else { 1.0 - fx };
            let wy = if j == 1 { fy } else { 1.0 - fy };
            let wz = if k == 1 { fz } else { 1.0 - fz };
            let weight = wx * wy * wz;
            if weight != 0.0 {
                want += weight * f64::from(value(x0 + i, y0 + j, z0 + k));
            }
        }
        prop_assert_eq!(f64::from(got), want, "at ({}, {}, {})", cx, cy, cz);
    }
}

#[test]
fn texel_centres_are_exact_and_results_stay_in_range() {
    let volume = Texture3d::from_fn([5, 3, 4], &Limits::default(), |x, y, z| {
        Rgba32f([(x * 7 + y * 3 + z) as f32 / 40.0, 0.5, 0.25, 1.0])
    })
    .expect("small");
    let desc = SamplerDescriptor::bilinear().with_address_mode(AddressMode::Repeat);
    for z in 0..4 {
        for y in 0..3 {
            for x in 0..5 {
                let uvw = Vec3::new(
                    (x as f32 + 0.5) / 5.0,
                    (y as f32 + 0.5) / 3.0,
                    (z as f32 + 0.5) / 4.0,
                );
                let want = volume.texel(x, y, z).expect("inside").to_linear();
                let got = volume.sample(uvw, &desc);
                assert!(
                    (got - want).abs().max_element() <= 8.0 * f32::EPSILON,
                    "{got:?} {want:?}"
                );
            }
        }
    }
    for k in 0..500 {
        let uvw = Vec3::new(
            k as f32 * 0.0371 - 3.0,
            k as f32 * 0.013,
            1.0 - k as f32 * 0.007,
        );
        let c = volume.sample(uvw, &desc);
        assert!(c.x >= 0.0 && c.x <= 1.0 + 1e-6, "{c:?}");
    }
    assert_eq!(volume.sample(Vec3::NAN, &desc), Vec4::ZERO);
}

#[test]
fn volume_limits_are_checked_before_allocating() {
    let limits = Limits {
        max_bytes: 1 << 20,
        ..Limits::default()
    };
    assert!(Texture3d::from_fn([512, 512, 512], &limits, |_, _, _| R32f(0.0)).is_err());
    assert!(Texture3d::from_fn([4, 4, 0], &limits, |_, _, _| R32f(0.0)).is_err());
}

#[test]
fn array_layers_are_selected_as_vulkan_rounds_them() {
    let layers = (0..4)
        .map(|i| MipChain::single(Texture2d::new(2, 2, R32f(i as f32)).expect("2²")))
        .collect();
    let array = Texture2dArray::new(layers, SamplerDescriptor::bilinear()).expect("equal layers");
    let at = |layer: f32| array.sample_level(Vec2::splat(0.5), layer, 0.0).x;
    assert_eq!(at(0.0), 0.0);
    assert_eq!(at(1.4), 1.0);
    assert_eq!(at(1.5), 2.0); // ties to even
    assert_eq!(at(2.5), 2.0);
    assert_eq!(at(-7.0), 0.0);
    assert_eq!(at(99.0), 3.0);
    assert_eq!(at(f32::NAN), 0.0);
    let uneven = vec![
        MipChain::single(Texture2d::new(2, 2, R32f(0.0)).expect("2²")),
        MipChain::single(Texture2d::new(4, 2, R32f(0.0)).expect("4×2")),
    ];
    assert!(Texture2dArray::new(uneven, SamplerDescriptor::default()).is_err());
    assert!(Texture2dArray::<R32f>::new(vec![], SamplerDescriptor::default()).is_err());
}
