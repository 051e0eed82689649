//! Anisotropic filtering against the footprint's true average, on a texture that varies along
//! the footprint's long axis (a texture constant along it cannot tell one probe from sixteen).

use barytex_texture::sampler::AddressMode;
use barytex_texture::{
    MipChain, MipOptions, R32f, Sampler, SamplerDescriptor, Texture2d, TextureSampler,
};
use glam::Vec2;
use proptest::prelude::*;

const SIZE: u32 = 64;

/// 64² texels, rows alternating 0 and 1.
fn rows() -> Texture2d<R32f> {
    Texture2d::from_fn(SIZE, SIZE, |_, y| R32f((y % 2) as f32)).expect("small")
}

/// Anisotropic ×`clamp` over trilinear, repeating (as the reference integrates).
fn sampler(clamp: u16) -> TextureSampler<R32f> {
    let chain = MipChain::generate(rows(), &MipOptions::default()).expect("small");
    let descriptor = SamplerDescriptor::anisotropic(clamp).with_address_mode(AddressMode::Repeat);
    TextureSampler::new(chain, descriptor)
}

/// The texture's exact average over the pixel footprint, the parallelogram
/// `uv + s·ddx + t·ddy` with `s, t ∈ [−½, ½]` (the texels as boxes, repeating), by a
/// 256 × 256 midpoint rule.
fn footprint_average(uv: Vec2, ddx: Vec2, ddy: Vec2) -> f32 {
    let n = 256;
    let mut sum = 0.0_f64;
    for i in 0..n {
        for j in 0..n {
            let s = (i as f32 + 0.5) / n as f32 - 0.5;
            let t = (j as f32 + 0.5) / n as f32 - 0.5;
            let p = (uv + s * ddx + t * ddy) * SIZE as f32;
            let row = p.y.floor().rem_euclid(SIZE as f32) as u32;
            sum += f64::from(row % 2);
        }
    }
    (sum / f64::from(n * n)) as f32
}

/// The footprint 0.7 texels wide and 8 texels tall, centred on a texel row: every clamp from ×1
/// to ×16 averages the rows it crosses to one half. (With the magnification shortcut taken on
/// the probes' level alone, ×8 and ×16 collapsed to the one centre probe and read 1.0.)
#[test]
fn probes_spread_along_a_long_axis_under_one_texel_per_probe() {
    let uv = Vec2::new(20.5, 31.5) / SIZE as f32;
    let (ddx, ddy) = (
        Vec2::new(0.7, 0.0) / SIZE as f32,
        Vec2::new(0.0, 8.0) / SIZE as f32,
    );
    let truth = footprint_average(uv, ddx, ddy);
    assert!((truth - 0.5).abs() < 1e-3, "{truth}");
    for clamp in [1, 2, 4, 8, 16] {
        let got = sampler(clamp).sample(uv, ddx, ddy).x;
        assert!((got - 0.5).abs() <= 0.1, "×{clamp}: {got}");
    }
}

/// The input on which `more_probes_are_not_worse` failed (CI, 2026-12-03): a nearly round
/// footprint (2 by 1.89 texels) across alternating rows. Two probes at the specifications'
/// `λ = log₂(major/2) = 0` read level 0 alone (0.86 where the footprint averages 0.53); with
/// the level never finer than the minor axis they read what one probe reads.
#[test]
fn two_probes_on_a_nearly_round_footprint_are_not_finer_than_it() {
    let uv = Vec2::new(0.0, 0.900_629_1);
    let (ddx, ddy) = (
        Vec2::new(2.0, 0.0) / SIZE as f32,
        Vec2::new(0.0, 1.892_822_5) / SIZE as f32,
    );
    let truth = footprint_average(uv, ddx, ddy);
    let one = sampler(1).sample(uv, ddx, ddy).x;
    let two = sampler(2).sample(uv, ddx, ddy).x;
    assert!((one - truth).abs() < 0.05, "×1 {one}, truth {truth}");
    assert!(
        (two - truth).abs() <= (one - truth).abs() + 0.05,
        "×2 {two}, ×1 {one}, truth {truth}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, failure_persistence: None, ..ProptestConfig::default() })]

    /// On random grazing footprints (major axis 2–24 texels, minor 0.05–2, any direction), more
    /// probes are never worse than half as many by more than 0.15 against the footprint's true
    /// average: the error may wobble with the probes' placement, but the clamp must not make
    /// filtering worse than trilinear's blur (the collapse made ×16 err by up to 0.5).
    #[test]
    fn more_probes_are_not_worse(
        u in 0.0f32..1.0, v in 0.0f32..1.0, angle in 0.0f32..std::f32::consts::PI,
        major in 2.0f32..24.0, minor in 0.05f32..2.0,
    ) {
        let along = Vec2::from_angle(angle);
        let ddx = along * major / SIZE as f32;
        let ddy = along.perp() * minor / SIZE as f32;
        let uv = Vec2::new(u, v);
        let truth = footprint_average(uv, ddx, ddy);
        let error = |clamp: u16| (sampler(clamp).sample(uv, ddx, ddy).x - truth).abs();
        for clamp in [2_u16, 4, 8, 16] {
            let (more, fewer) = (error(clamp), error(clamp / 2));
            prop_assert!(more <= fewer + 0.15, "×{clamp} {more} vs ×{} {fewer} (truth {truth})", clamp / 2);
        }
    }
}
/// Over 400 seeded grazing footprints (as in `more_probes_are_not_worse`), the mean error
/// against the true average falls with every doubling of the clamp, and ×16 at least halves
/// trilinear's (measured: 0.034, 0.032, 0.025, 0.018, 0.011 over 1500 footprints).
#[test]
fn mean_error_falls_with_the_clamp() {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let clamps = [1_u16, 2, 4, 8, 16];
    let samplers = clamps.map(sampler);
    let mut mean = [0.0_f32; 5];
    let n = 400;
    for _ in 0..n {
        let uv = Vec2::new(next(), next());
        let along = Vec2::from_angle(next() * std::f32::consts::PI);
        let (major, minor) = (2.0 + 22.0 * next(), 0.05 + 1.95 * next());
        let (ddx, ddy) = (
            along * major / SIZE as f32,
            along.perp() * minor / SIZE as f32,
        );
        let truth = footprint_average(uv, ddx, ddy);
        for (m, s) in mean.iter_mut().zip(&samplers) {
            *m += (s.sample(uv, ddx, ddy).x - truth).abs() / n as f32;
        }
    }
    println!("mean error ×1 … ×16: {mean:?}");
    for k in 1..5 {
        assert!(
            mean[k] < mean[k - 1],
            "×{} {} vs ×{} {}",
            clamps[k],
            mean[k],
            clamps[k - 1],
            mean[k - 1]
        );
    }
    assert!(mean[4] <= 0.5 * mean[0], "{mean:?}");
}

/// Issue 20, item 6: the documented "anisotropic probes and EWA vs trilinear" comparison on
/// random grazing footprints instead of the one 16:1 footprint of
/// `sampling.rs::anisotropic_filters_resolve_the_minor_axis`: 400 seeded footprints of
/// anisotropy 4 … 24 at every orientation over the alternating rows, against the footprint's
/// true average (`footprint_average`). The probes cut trilinear's mean error by more than half
/// (measured 0.023 against 0.074); EWA by less (measured 0.050: its one-footprint advantage of
/// the sampling test does not carry over in full), asserted below 0.8 of trilinear's.
#[test]
fn anisotropic_and_ewa_beat_trilinear_on_random_grazing_footprints() {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let chain = MipChain::generate(rows(), &MipOptions::default()).expect("small");
    let repeat = |d: SamplerDescriptor| {
        TextureSampler::new(chain.clone(), d.with_address_mode(AddressMode::Repeat))
    };
    let filters = [
        repeat(SamplerDescriptor::trilinear()),
        repeat(SamplerDescriptor::anisotropic(16)),
        repeat(SamplerDescriptor {
            anisotropic_filter: barytex_texture::sampler::AnisotropicFilter::Ewa,
            ..SamplerDescriptor::anisotropic(16)
        }),
    ];
    let mut mean = [0.0_f32; 3];
    let n = 400;
    for _ in 0..n {
        let uv = Vec2::new(next(), next());
        let along = Vec2::from_angle(next() * std::f32::consts::PI);
        let minor = 0.25 + 0.75 * next();
        let major = minor * (4.0 + 20.0 * next());
        let (ddx, ddy) = (
            along * major / SIZE as f32,
            along.perp() * minor / SIZE as f32,
        );
        let truth = footprint_average(uv, ddx, ddy);
        for (m, s) in mean.iter_mut().zip(&filters) {
            *m += (s.sample(uv, ddx, ddy).x - truth).abs() / n as f32;
        }
    }
    println!("mean error trilinear, ×16 probes, EWA: {mean:?}");
    assert!(mean[1] < 0.5 * mean[0], "{mean:?}");
    assert!(mean[2] < 0.8 * mean[0], "{mean:?}");
}
