//! The AVX2 + FMA build of the paired fragment loop (which unlit shading takes) draws what the
//! baseline build draws, to every bit of the linear colour: the demo scene, unlit, under each
//! filter, with and without the AVX2 build allowed (`barytex_raster::allow_avx2`). On a
//! processor without AVX2 both draws take the baseline build and the test still checks that
//! the setting changes nothing.
//!
//! The setting belongs to the process: this file is a test binary of its own, with one test.

use barytex_render::demo::{demo_options, demo_scene};
use barytex_render::{AntiAliasing, Filter, RenderOptions, Shading};

mod common;

/// Every bit of the demo drawn with `options`, the AVX2 build allowed or not.
fn bits(options: &RenderOptions, avx2: bool) -> Vec<u32> {
    barytex_raster::allow_avx2(avx2);
    let bits = common::render_bits(&demo_scene(), options);
    barytex_raster::allow_avx2(true);
    bits
}

#[test]
fn the_avx2_build_draws_what_the_baseline_draws() {
    eprintln!("AVX2 build in use: {}", barytex_raster::avx2_in_use());
    for filter in [
        Filter::Nearest,
        Filter::Bilinear,
        Filter::Trilinear,
        Filter::Anisotropic(4),
        Filter::Ewa,
    ] {
        let options = RenderOptions {
            shading: Shading::Unlit,
            fog: None,
            filter,
            anti_aliasing: AntiAliasing::None,
            ..demo_options(160, 96)
        };
        let (fast, baseline) = (bits(&options, true), bits(&options, false));
        let distinct: std::collections::BTreeSet<u32> = fast.iter().copied().collect();
        // The demo's textures have few colours: nearest draws 18 distinct values, the others
        // over a thousand.
        assert!(distinct.len() > 10, "{filter:?}: a blank picture");
        let differing = fast.iter().zip(&baseline).filter(|(a, b)| a != b).count();
        assert_eq!(differing, 0, "{filter:?}: {differing} values differ");
    }
}
