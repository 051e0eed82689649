//! The renderer is deterministic: the demo scene under every texture filter and every
//! anti-aliasing mode gives bit-identical images (every bit of the linear f32 colour, not only
//! the sRGB bytes) with 1 and 3 threads, and on a second run.

use barytex_gltf::Scene;
use barytex_render::demo::{demo_options, demo_scene};
use barytex_render::{AntiAliasing, Filter, RenderOptions};

mod common;

const WIDTH: u32 = 96;
const HEIGHT: u32 = 64;

const FILTERS: [Filter; 5] = [
    Filter::Nearest,
    Filter::Bilinear,
    Filter::Trilinear,
    Filter::Anisotropic(8),
    Filter::Ewa,
];

const ANTI_ALIASING: [AntiAliasing; 5] = [
    AntiAliasing::None,
    AntiAliasing::Supersample(2),
    AntiAliasing::Jitter(2),
    AntiAliasing::Msaa(4),
    AntiAliasing::Adaptive(16),
];

/// Every bit of the resolved linear colour, drawn on `threads` threads.
fn render_bits(scene: &Scene, options: &RenderOptions, threads: usize) -> Vec<u32> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool")
        .install(|| common::render_bits(scene, options))
}

#[track_caller]
fn check(scene: &Scene, options: &RenderOptions) {
    let what = format!("{:?} with {:?}", options.filter, options.anti_aliasing);
    let one = render_bits(scene, options, 1);
    assert_eq!(one.len(), (WIDTH * HEIGHT * 4) as usize, "{what}");
    // Not a blank picture: the comparison below would be vacuous.
    let distinct: std::collections::BTreeSet<u32> = one.iter().copied().collect();
    assert!(
        distinct.len() > 100,
        "{what}: only {} values",
        distinct.len()
    );
    let three = render_bits(scene, options, 3);
    assert!(one == three, "{what}: 1 and 3 threads differ");
    let again = render_bits(scene, options, 3);
    assert!(three == again, "{what}: two runs with 3 threads differ");
}

/// Every filter under one anti-aliasing mode.
fn every_filter_under(anti_aliasing: AntiAliasing) {
    let scene = demo_scene();
    for filter in FILTERS {
        check(
            &scene,
            &RenderOptions {
                filter,
                anti_aliasing,
                ..demo_options(WIDTH, HEIGHT)
            },
        );
    }
}

#[test]
fn every_filter_without_anti_aliasing_is_bit_identical_for_any_thread_count() {
    every_filter_under(ANTI_ALIASING[0]);
}

#[test]
fn every_filter_supersampled_is_bit_identical_for_any_thread_count() {
    every_filter_under(ANTI_ALIASING[1]);
}

#[test]
fn every_filter_jittered_is_bit_identical_for_any_thread_count() {
    every_filter_under(ANTI_ALIASING[2]);
}

#[test]
fn every_filter_with_msaa_is_bit_identical_for_any_thread_count() {
    every_filter_under(ANTI_ALIASING[3]);
}

#[test]
fn every_filter_adaptive_is_bit_identical_for_any_thread_count() {
    every_filter_under(ANTI_ALIASING[4]);
}
