//! Bad input to the targets, the sample patterns, the viewport and the anti-aliasing drivers,
//! and bit-identical output of `render_supersampled`, `render_adaptive`, affine spans and
//! per-sample shading for any number of threads.

use std::sync::atomic::{AtomicU32, Ordering};

use barytex_raster::{
    AdaptiveOptions, CullMode, Fragment, Framebuffer, Interpolation, MAX_COORDINATE, PipelineState,
    SamplePattern, Shader, TILE, Viewport, draw, render_adaptive, render_supersampled,
};
use barytex_raster::{RasterError, TargetLimits};
use glam::{Mat4, Vec2, Vec3, Vec4};

// ---------------------------------------------------------------------------------------------
// Framebuffer and SamplePattern
// ---------------------------------------------------------------------------------------------

#[test]
fn framebuffer_refuses_zero_sides_and_sizes_over_the_limits() {
    let limits = TargetLimits::default();
    // The zero side is named (the width when both are zero), and the message names no data.
    for (w, h, side) in [(0, 10, "width"), (10, 0, "height"), (0, 0, "width")] {
        let r = Framebuffer::new(w, h, Vec4::ZERO, &limits);
        assert!(
            matches!(r, Err(RasterError::InvalidParameter { what, .. }) if what == side),
            "{w}×{h}: {r:?}"
        );
        assert_eq!(
            r.expect_err("zero side").to_string(),
            format!("{side}: a target needs at least one pixel per side")
        );
        let r = Framebuffer::multisampled(
            w,
            h,
            SamplePattern::Standard { count: 4 },
            Vec4::ZERO,
            &limits,
        );
        assert!(
            matches!(r, Err(RasterError::InvalidParameter { what, .. }) if what == side),
            "{r:?}"
        );
    }
    // Sides beyond the limits, before anything is allocated (u32::MAX² would be 368 EB).
    let r = Framebuffer::new(u32::MAX, u32::MAX, Vec4::ZERO, &limits);
    assert!(
        matches!(r, Err(RasterError::TooLarge { what: "width", .. })),
        "{r:?}"
    );
    let r = Framebuffer::new(16, 16_385, Vec4::ZERO, &limits);
    assert!(
        matches!(
            r,
            Err(RasterError::TooLarge {
                what: "height",
                requested: 16_385,
                ..
            })
        ),
        "{r:?}"
    );
    // 20 bytes per sample of the target padded to whole 64 × 64 tiles (what is allocated): a
    // 16 × 16 target with 16 samples is one tile, 64 · 64 · 16 · 20 = 1 310 720 bytes.
    const { assert!(TILE == 64) };
    let tight = TargetLimits {
        max_bytes: 1_310_719,
        ..TargetLimits::default()
    };
    let pattern = SamplePattern::Standard { count: 16 };
    let r = Framebuffer::multisampled(16, 16, pattern, Vec4::ZERO, &tight);
    assert_eq!(
        r,
        Err(RasterError::TooLarge {
            what: "bytes",
            requested: 1_310_720,
            limit: 1_310_719
        })
    );
    let enough = TargetLimits {
        max_bytes: 1_310_720,
        ..TargetLimits::default()
    };
    let fb = Framebuffer::multisampled(16, 16, pattern, Vec4::ZERO, &enough).expect("at the limit");
    assert_eq!(fb.samples(), 16);
    // A one-pixel-wide column is padded to a tile's width: 64 · 16 384 · 25 · 20 = 524 288 000
    // bytes are counted (the unpadded 1 · 16 384 · 25 · 20 would be 64 times fewer).
    let r = Framebuffer::multisampled(
        1,
        16_384,
        SamplePattern::Regular { n: 5 },
        Vec4::ZERO,
        &TargetLimits {
            max_bytes: 524_287_999,
            ..limits
        },
    );
    assert_eq!(
        r,
        Err(RasterError::TooLarge {
            what: "bytes",
            requested: 524_288_000,
            limit: 524_287_999
        })
    );
    // Without limits a product beyond the address space is an error, not an abort: 2³² · 2³²
    // pixels overflow u64.
    let r = Framebuffer::new(u32::MAX, u32::MAX, Vec4::ZERO, &TargetLimits::UNLIMITED);
    assert_eq!(r, Err(RasterError::OutOfMemory { bytes: u64::MAX }));
    // The default limits refuse a 16 384² single-sample target (5 GiB at 20 B/px).
    let r = Framebuffer::new(16_384, 16_384, Vec4::ZERO, &limits);
    assert!(
        matches!(r, Err(RasterError::TooLarge { what: "bytes", .. })),
        "{r:?}"
    );
}

#[test]
fn framebuffer_refuses_invalid_sample_patterns() {
    for pattern in [
        SamplePattern::Standard { count: 0 },
        SamplePattern::Standard { count: 3 },
        SamplePattern::Standard { count: 32 },
        SamplePattern::Standard { count: u32::MAX },
        SamplePattern::Regular { n: 6 },
        SamplePattern::Jittered { n: 6, seed: 1 },
        SamplePattern::Regular { n: u32::MAX },
    ] {
        let r = Framebuffer::multisampled(8, 8, pattern, Vec4::ZERO, &TargetLimits::default());
        assert!(
            matches!(
                r,
                Err(RasterError::InvalidParameter {
                    what: "sample count",
                    ..
                })
            ),
            "{pattern:?}: {r:?}"
        );
    }
    // The pattern is checked before the size: an invalid pattern on a zero side names the pattern.
    let r = Framebuffer::multisampled(
        0,
        0,
        SamplePattern::Standard { count: 3 },
        Vec4::ZERO,
        &TargetLimits::default(),
    );
    assert!(
        matches!(r, Err(RasterError::InvalidParameter { .. })),
        "{r:?}"
    );
}

#[test]
fn sample_pattern_validate_and_count() {
    for count in [1, 2, 4, 8, 16] {
        assert!(
            SamplePattern::Standard { count }.validate().is_ok(),
            "{count}"
        );
        assert_eq!(SamplePattern::Standard { count }.count(), count);
    }
    for count in [0, 3, 5, 6, 7, 9, 15, 17, 32, 64, u32::MAX] {
        let r = SamplePattern::Standard { count }.validate();
        assert!(
            matches!(
                r,
                Err(RasterError::InvalidParameter {
                    what: "sample count",
                    ..
                })
            ),
            "{count}: {r:?}"
        );
    }
    for n in 0..=5 {
        assert!(SamplePattern::Regular { n }.validate().is_ok(), "{n}");
        assert!(
            SamplePattern::Jittered { n, seed: 9 }.validate().is_ok(),
            "{n}"
        );
        // n = 0 is treated as 1.
        assert_eq!(SamplePattern::Regular { n }.count(), n.max(1) * n.max(1));
    }
    for n in [6, 7, 64, 65_536, u32::MAX] {
        assert!(SamplePattern::Regular { n }.validate().is_err(), "{n}");
        assert!(
            SamplePattern::Jittered { n, seed: 0 }.validate().is_err(),
            "{n}"
        );
    }
    // `count` saturates rather than overflowing.
    assert_eq!(SamplePattern::Regular { n: 65_536 }.count(), u32::MAX);
    assert_eq!(
        SamplePattern::Jittered {
            n: u32::MAX,
            seed: 0
        }
        .count(),
        u32::MAX
    );
    // A zero grid is a 1 × 1 grid in a target too.
    let fb = Framebuffer::multisampled(
        4,
        4,
        SamplePattern::Regular { n: 0 },
        Vec4::ONE,
        &TargetLimits::default(),
    )
    .expect("n = 0 is one sample");
    assert_eq!(fb.samples(), 1);
    assert_eq!(fb.pixel(3, 3), Some(Vec4::ONE));
}

/// Regression: `offsets` of an invalid standard count used to list `count` copies of the centre
/// (`u32::MAX` of them: 32 GiB, an allocation abort), and `render_supersampled` drew that many
/// passes. Now it is the single centre sample, where `sample_offset` puts every such sample.
#[test]
fn invalid_standard_counts_give_one_centre_offset() {
    for count in [0, 3, 5, 1000, u32::MAX] {
        let pattern = SamplePattern::Standard { count };
        assert_eq!(pattern.offsets(), vec![Vec2::splat(0.5)], "{count}");
        assert_eq!(pattern.sample_offset(7, 3, 2), Vec2::splat(0.5), "{count}");
    }
    let mut passes = 0;
    let r = render_supersampled(
        4,
        4,
        Vec4::ZERO,
        SamplePattern::Standard { count: u32::MAX },
        &TargetLimits::default(),
        |_, _| passes += 1,
    );
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(passes, 1);
    // The valid counts keep their tables.
    for count in [1, 2, 4, 8, 16] {
        assert_eq!(
            SamplePattern::Standard { count }.offsets().len(),
            count as usize
        );
    }
}

#[test]
fn pixel_and_depth_outside_the_target_are_none() {
    // 10 × 7 lies inside one 64 × 64 tile: the padding pixels exist in memory but are outside.
    const { assert!(TILE > 10) };
    for pattern in [SamplePattern::CENTRE, SamplePattern::Standard { count: 4 }] {
        let fb = Framebuffer::multisampled(10, 7, pattern, Vec4::ONE, &TargetLimits::default())
            .expect("small");
        assert_eq!(fb.pixel(9, 6), Some(Vec4::ONE));
        assert_eq!(fb.depth(9, 6), Some(1.0));
        for (x, y) in [
            (10, 0),
            (0, 7),
            (10, 7),
            (TILE - 1, 0),
            (0, TILE - 1),
            (u32::MAX, 0),
            (0, u32::MAX),
            (u32::MAX, u32::MAX),
        ] {
            assert_eq!(fb.pixel(x, y), None, "pixel ({x}, {y})");
            assert_eq!(fb.depth(x, y), None, "depth ({x}, {y})");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Viewport and AffineSpans
// ---------------------------------------------------------------------------------------------

/// Positions in clip space (w = 1); counts the fragments shaded and checks they are on the target.
struct Counter {
    width: u32,
    height: u32,
    shaded: AtomicU32,
    outside: AtomicU32,
}

impl Counter {
    fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            shaded: AtomicU32::new(0),
            outside: AtomicU32::new(0),
        }
    }
}

impl Shader for Counter {
    type Vertex = Vec4;
    type Varying = f32;
    fn vertex(&self, v: &Vec4) -> (Vec4, f32) {
        (*v, 0.0)
    }
    fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
        self.shaded.fetch_add(1, Ordering::Relaxed);
        if f.pixel.x >= self.width || f.pixel.y >= self.height {
            self.outside.fetch_add(1, Ordering::Relaxed);
        }
        Some(Vec4::ONE)
    }
}

/// A triangle covering most of the viewport.
fn big_triangle() -> Vec<Vec4> {
    vec![
        Vec4::new(-0.9, -0.9, 0.5, 1.0),
        Vec4::new(0.9, -0.9, 0.5, 1.0),
        Vec4::new(0.0, 0.9, 0.5, 1.0),
    ]
}

#[test]
fn bad_viewports_are_degenerate_or_draw_nothing_outside() {
    const W: u32 = 32;
    const H: u32 = 24;
    let good = Viewport::full(W, H);
    let cases: Vec<(&str, Viewport, bool)> = vec![
        // (what, viewport, whether the triangle is dropped as degenerate)
        (
            "NaN x",
            Viewport {
                x: f32::NAN,
                ..good
            },
            true,
        ),
        (
            "NaN width",
            Viewport {
                width: f32::NAN,
                ..good
            },
            true,
        ),
        (
            "∞ height",
            Viewport {
                height: f32::INFINITY,
                ..good
            },
            true,
        ),
        (
            "−∞ y",
            Viewport {
                y: f32::NEG_INFINITY,
                ..good
            },
            true,
        ),
        ("huge width", Viewport { width: 1e9, ..good }, true),
        (
            "f32::MAX width",
            Viewport {
                width: f32::MAX,
                height: f32::MAX,
                ..good
            },
            true,
        ),
        ("far-off x", Viewport { x: -1e7, ..good }, true),
        (
            "just past MAX_COORDINATE",
            Viewport {
                x: MAX_COORDINATE,
                ..good
            },
            true,
        ),
        ("zero width", Viewport { width: 0.0, ..good }, true),
        (
            "zero height",
            Viewport {
                height: 0.0,
                ..good
            },
            true,
        ),
        // Off the target but inside the fixed-point range: set up, nothing shaded.
        ("off-target x", Viewport { x: 1e5, ..good }, false),
        ("off-target y", Viewport { y: -1e5, ..good }, false),
        // A negative width or height: set up (mirrored), but the viewport rectangle that may
        // be written, [x, x + width), is empty.
        (
            "negative width",
            Viewport {
                x: W as f32,
                width: -(W as f32),
                ..good
            },
            false,
        ),
        (
            "negative height",
            Viewport {
                y: H as f32,
                height: -(H as f32),
                ..good
            },
            false,
        ),
    ];
    for (what, viewport, degenerate) in cases {
        let shader = Counter::new(W, H);
        let mut fb = Framebuffer::new(W, H, Vec4::ZERO, &TargetLimits::default()).expect("small");
        let state = PipelineState {
            cull: CullMode::None,
            depth_compare: None,
            depth_write: false,
            viewport: Some(viewport),
            ..PipelineState::default()
        };
        let stats = draw(&mut fb, &shader, &state, &big_triangle(), &[0, 1, 2]);
        assert_eq!(stats.triangles_in, 1, "{what}");
        assert_eq!(stats.degenerate, u64::from(degenerate), "{what}: {stats:?}");
        assert_eq!(shader.outside.load(Ordering::Relaxed), 0, "{what}");
        let shaded = shader.shaded.load(Ordering::Relaxed);
        let written = (0..H)
            .flat_map(|y| (0..W).map(move |x| (x, y)))
            .filter(|&(x, y)| fb.pixel(x, y) != Some(Vec4::ZERO))
            .count();
        assert_eq!(u64::from(shaded), stats.fragments_shaded, "{what}");
        assert_eq!(
            written as u32, shaded,
            "{what}: every shaded fragment writes its pixel"
        );
        // Nothing is shaded in any of these cases (off-target, degenerate, or an empty
        // viewport rectangle).
        assert_eq!(shaded, 0, "{what}");
    }
}

#[test]
fn nan_depth_range_never_panics_and_fails_the_depth_test() {
    // A NaN depth range gives NaN fragment depths: `Less` is false for NaN, so nothing passes.
    const W: u32 = 16;
    let shader = Counter::new(W, W);
    let mut fb = Framebuffer::new(W, W, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let state = PipelineState {
        cull: CullMode::None,
        viewport: Some(Viewport {
            min_depth: f32::NAN,
            ..Viewport::full(W, W)
        }),
        ..PipelineState::default()
    };
    let stats = draw(&mut fb, &shader, &state, &big_triangle(), &[0, 1, 2]);
    assert_eq!(stats.degenerate, 0, "{stats:?}");
    assert!(stats.fragments_depth_failed > 0, "{stats:?}");
    assert_eq!(stats.fragments_shaded, 0, "{stats:?}");
    assert!((0..W).all(|y| {
        (0..W).all(|x| fb.pixel(x, y) == Some(Vec4::ZERO) && fb.depth(x, y) == Some(1.0))
    }));
}

/// uv on a slanted wall seen in perspective (so affine spans differ from perspective-correct).
struct PlaneUv {
    view_projection: Mat4,
}

impl Shader for PlaneUv {
    type Vertex = (Vec3, Vec2);
    type Varying = Vec2;
    fn vertex(&self, v: &(Vec3, Vec2)) -> (Vec4, Vec2) {
        (self.view_projection * v.0.extend(1.0), v.1)
    }
    fn fragment(&self, f: &Fragment<'_, Vec2>) -> Option<Vec4> {
        Some(Vec4::new(f.varying.x, f.varying.y, f.ddx().x, 1.0))
    }
}

fn plane_scene(w: u32, h: u32) -> (PlaneUv, Vec<(Vec3, Vec2)>, Vec<u32>) {
    // glam's DirectX-convention perspective (y up, depth in [0, w]), as the rasterizer takes it.
    let view_projection = glam::camera::rh::proj::directx::perspective(
        60_f32.to_radians(),
        w as f32 / h as f32,
        0.1,
        100.0,
    );
    // A wall slanted in x and y, so depth varies along rows and columns.
    let corners = [(-4.0, -3.0), (4.0, -3.0), (4.0, 3.0), (-4.0, 3.0)];
    let vertices = corners
        .iter()
        .map(|&(x, y)| {
            (
                Vec3::new(x, y, -3.0 - 1.2 * (x + 4.0) - 0.5 * (y + 3.0)),
                Vec2::new((x + 4.0) / 8.0, (y + 3.0) / 6.0),
            )
        })
        .collect();
    (
        PlaneUv { view_projection },
        vertices,
        vec![0, 2, 1, 0, 3, 2],
    )
}

/// Every bit of the resolved colour and the depth.
fn bits(fb: &Framebuffer) -> Vec<u32> {
    let mut out: Vec<u32> = fb
        .to_linear_rgba()
        .expect("resolve")
        .iter()
        .flat_map(|p| p.to_array().map(f32::to_bits))
        .collect();
    for y in 0..fb.height() {
        for x in 0..fb.width() {
            out.push(fb.depth(x, y).map_or(u32::MAX, f32::to_bits));
        }
    }
    out
}

fn draw_plane(w: u32, h: u32, pattern: SamplePattern, state: &PipelineState) -> Framebuffer {
    let (shader, vertices, indices) = plane_scene(w, h);
    let mut fb = Framebuffer::multisampled(w, h, pattern, Vec4::ZERO, &TargetLimits::default())
        .expect("small");
    let state = PipelineState {
        cull: CullMode::None,
        ..*state
    };
    let stats = draw(&mut fb, &shader, &state, &vertices, &indices);
    assert!(stats.fragments_shaded > 500, "{stats:?}");
    fb
}

fn spans(span: u32) -> PipelineState {
    PipelineState {
        interpolation: Interpolation::AffineSpans { span },
        ..PipelineState::default()
    }
}

#[test]
fn affine_span_lengths_are_clamped_to_2_through_256() {
    let (w, h) = (300, 64);
    let image = |span| bits(&draw_plane(w, h, SamplePattern::CENTRE, &spans(span)));
    let two = image(2);
    assert_eq!(image(0), two, "span 0 is span 2");
    assert_eq!(image(1), two, "span 1 is span 2");
    let max = image(256);
    assert_ne!(
        max, two,
        "256-pixel spans differ from 2-pixel spans under perspective"
    );
    assert_eq!(image(257), max, "span 257 is span 256");
    assert_eq!(image(u32::MAX), max, "span u32::MAX is span 256");
}

// ---------------------------------------------------------------------------------------------
// render_adaptive options
// ---------------------------------------------------------------------------------------------

#[test]
fn adaptive_option_errors_are_refused_before_drawing() {
    let good = AdaptiveOptions::default();
    let bad = [
        (
            "min_samples 0",
            AdaptiveOptions {
                min_samples: 0,
                ..good
            },
        ),
        (
            "min_samples 1",
            AdaptiveOptions {
                min_samples: 1,
                ..good
            },
        ),
        (
            "max < min",
            AdaptiveOptions {
                min_samples: 8,
                max_samples: 7,
                ..good
            },
        ),
        (
            "max 4097",
            AdaptiveOptions {
                max_samples: 4097,
                ..good
            },
        ),
        (
            "max u32::MAX",
            AdaptiveOptions {
                max_samples: u32::MAX,
                ..good
            },
        ),
        ("batch 0", AdaptiveOptions { batch: 0, ..good }),
        (
            "NaN threshold",
            AdaptiveOptions {
                threshold: f32::NAN,
                ..good
            },
        ),
        (
            "negative threshold",
            AdaptiveOptions {
                threshold: -1e-3,
                ..good
            },
        ),
        (
            "−∞ threshold",
            AdaptiveOptions {
                threshold: f32::NEG_INFINITY,
                ..good
            },
        ),
        (
            "NaN contrast",
            AdaptiveOptions {
                contrast: f32::NAN,
                ..good
            },
        ),
        (
            "negative contrast",
            AdaptiveOptions {
                contrast: -0.5,
                ..good
            },
        ),
    ];
    for (what, options) in bad {
        let mut passes = 0;
        let r = render_adaptive(
            8,
            8,
            Vec4::ZERO,
            &options,
            &TargetLimits::default(),
            |_, _| {
                passes += 1;
            },
        );
        assert!(
            matches!(
                r,
                Err(RasterError::InvalidParameter {
                    what: "adaptive options",
                    ..
                })
            ),
            "{what}: {r:?}"
        );
        assert_eq!(passes, 0, "{what}: nothing drawn");
    }
    // Edge values that are allowed: 2 = min = max, 4096, zero and +∞ thresholds, −0.0.
    for (what, options) in [
        (
            "min = max = 2",
            AdaptiveOptions {
                min_samples: 2,
                max_samples: 2,
                ..good
            },
        ),
        (
            "max 4096, threshold ∞",
            AdaptiveOptions {
                max_samples: 4096,
                threshold: f32::INFINITY,
                ..good
            },
        ),
        (
            "zero threshold and contrast",
            AdaptiveOptions {
                threshold: 0.0,
                contrast: -0.0,
                max_samples: 8,
                ..good
            },
        ),
    ] {
        let r = render_adaptive(
            4,
            4,
            Vec4::ZERO,
            &options,
            &TargetLimits::default(),
            |_, _| {},
        );
        assert!(r.is_ok(), "{what}: {r:?}");
    }
    // Target errors as Framebuffer::new.
    let r = render_adaptive(0, 4, Vec4::ZERO, &good, &TargetLimits::default(), |_, _| {});
    assert!(
        matches!(r, Err(RasterError::InvalidParameter { what: "width", .. })),
        "{r:?}"
    );
    let r = render_adaptive(
        64,
        64,
        Vec4::ZERO,
        &good,
        &TargetLimits {
            max_bytes: 1000,
            ..TargetLimits::default()
        },
        |_, _| {},
    );
    assert!(
        matches!(r, Err(RasterError::TooLarge { what: "bytes", .. })),
        "{r:?}"
    );
    // render_supersampled: the same target errors, and any pattern (it is not validated).
    let r = render_supersampled(
        4,
        0,
        Vec4::ZERO,
        SamplePattern::CENTRE,
        &TargetLimits::default(),
        |_, _| {},
    );
    assert!(
        matches!(r, Err(RasterError::InvalidParameter { what: "height", .. })),
        "{r:?}"
    );
    let mut passes = 0;
    let r = render_supersampled(
        4,
        4,
        Vec4::ZERO,
        SamplePattern::Standard { count: 3 },
        &TargetLimits::default(),
        |_, _| passes += 1,
    );
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(passes, 1, "an invalid standard count is one centre sample");
}

// ---------------------------------------------------------------------------------------------
// Determinism across thread counts
// ---------------------------------------------------------------------------------------------

fn with_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool")
        .install(f)
}

/// `f` gives the same bits with 1, 2 and 3 threads.
#[track_caller]
fn same_for_any_thread_count(what: &str, f: impl Fn() -> Vec<u32> + Sync) {
    let one = with_threads(1, &f);
    assert!(!one.is_empty(), "{what}");
    assert!(one == with_threads(2, &f), "{what}: 1 and 2 threads differ");
    assert!(one == with_threads(3, &f), "{what}: 1 and 3 threads differ");
    assert!(one == with_threads(1, &f), "{what}: two runs differ");
}

/// Draws the plane with its viewport shifted by `shift` (as the drivers ask).
fn draw_shifted(fb: &mut Framebuffer, shift: Vec2, state: &PipelineState) {
    let (w, h) = (fb.width(), fb.height());
    let (shader, vertices, indices) = plane_scene(w, h);
    let state = PipelineState {
        cull: CullMode::None,
        viewport: Some(Viewport {
            x: shift.x,
            y: shift.y,
            ..Viewport::full(w, h)
        }),
        ..*state
    };
    draw(fb, &shader, &state, &vertices, &indices);
}

#[test]
fn supersampled_and_adaptive_renders_are_bit_identical_for_any_thread_count() {
    let (w, h) = (150, 100);
    same_for_any_thread_count("render_supersampled, jittered 3 × 3", || {
        let fb = render_supersampled(
            w,
            h,
            Vec4::ZERO,
            SamplePattern::Jittered { n: 3, seed: 11 },
            &TargetLimits::default(),
            |fb, shift| draw_shifted(fb, shift, &PipelineState::default()),
        )
        .expect("small");
        bits(&fb)
    });
    same_for_any_thread_count("render_adaptive", || {
        let (fb, stats) = render_adaptive(
            w,
            h,
            Vec4::ZERO,
            &AdaptiveOptions::default(),
            &TargetLimits::default(),
            |fb, shift| draw_shifted(fb, shift, &PipelineState::default()),
        )
        .expect("small");
        let mut out = bits(&fb);
        out.extend(stats.histogram.iter().map(|&n| n as u32));
        out.push(stats.passes);
        out
    });
}

#[test]
fn affine_spans_and_per_sample_shading_are_bit_identical_for_any_thread_count() {
    let (w, h) = (200, 150);
    for span in [2, 8, 32] {
        same_for_any_thread_count(&format!("affine spans of {span}"), || {
            bits(&draw_plane(w, h, SamplePattern::CENTRE, &spans(span)))
        });
    }
    for pattern in [
        SamplePattern::Standard { count: 8 },
        SamplePattern::Jittered { n: 3, seed: 7 },
    ] {
        let state = PipelineState {
            sample_shading: true,
            ..PipelineState::default()
        };
        same_for_any_thread_count(&format!("per-sample shading, {pattern:?}"), || {
            bits(&draw_plane(w, h, pattern, &state))
        });
        let spans_per_sample = PipelineState {
            sample_shading: true,
            ..spans(16)
        };
        same_for_any_thread_count(
            &format!("per-sample shading with spans, {pattern:?}"),
            || bits(&draw_plane(w, h, pattern, &spans_per_sample)),
        );
    }
}
