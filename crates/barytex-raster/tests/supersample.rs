//! Supersampling: a half-plane edge against its exact per-pixel area coverage.

use barytex_raster::TargetLimits;
use barytex_raster::{
    AdaptiveOptions, CullMode, Fragment, Framebuffer, PipelineState, SamplePattern, Shader,
    Viewport, draw, render_adaptive, render_supersampled,
};
use glam::{Vec2, Vec4};

const SIZE: u32 = 32;

/// A huge triangle whose right edge is the line x + 0.3·y = 13.7 (screen pixels), white.
struct White;

impl Shader for White {
    type Vertex = Vec2;
    type Varying = f32;
    fn vertex(&self, p: &Vec2) -> (Vec4, f32) {
        let s = SIZE as f32;
        (
            Vec4::new(p.x / s * 2.0 - 1.0, 1.0 - p.y / s * 2.0, 0.5, 1.0),
            0.0,
        )
    }
    fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
        Some(Vec4::ONE)
    }
}

fn edge_triangle() -> Vec<Vec2> {
    let c = 13.7_f32;
    // Points on the line at y = −40 and y = 80, and far to the left.
    vec![
        Vec2::new(c + 0.3 * 40.0, -40.0),
        Vec2::new(c - 0.3 * 80.0, 80.0),
        Vec2::new(-200.0, 20.0),
    ]
}

/// The exact fraction of pixel (x, y) left of the line, by a 400² midpoint rule (error ≪ 1e-3).
fn coverage(x: u32, y: u32) -> f32 {
    let n = 400;
    let mut inside = 0;
    for j in 0..n {
        for i in 0..n {
            let px = x as f32 + (i as f32 + 0.5) / n as f32;
            let py = y as f32 + (j as f32 + 0.5) / n as f32;
            if px + 0.3 * py < 13.7 {
                inside += 1;
            }
        }
    }
    inside as f32 / (n * n) as f32
}

fn render(pattern: SamplePattern) -> Framebuffer {
    let vertices = edge_triangle();
    render_supersampled(
        SIZE,
        SIZE,
        Vec4::new(0.0, 0.0, 0.0, 1.0),
        pattern,
        &TargetLimits::default(),
        |fb, shift| {
            let state = PipelineState {
                cull: CullMode::None,
                viewport: Some(Viewport {
                    x: shift.x,
                    y: shift.y,
                    ..Viewport::full(SIZE, SIZE)
                }),
                ..PipelineState::default()
            };
            draw(fb, &White, &state, &vertices, &[0, 1, 2]);
        },
    )
    .expect("small")
}

/// Mean and max |rendered − exact coverage| over the pixels the edge crosses.
fn errors(fb: &Framebuffer) -> (f32, f32) {
    let (mut sum, mut max, mut count) = (0.0, 0.0_f32, 0);
    for y in 0..SIZE {
        for x in 0..SIZE {
            let exact = coverage(x, y);
            if exact > 0.0 && exact < 1.0 {
                let got = fb.pixel(x, y).expect("inside").x;
                let e = (got - exact).abs();
                sum += e;
                max = max.max(e);
                count += 1;
            }
        }
    }
    (sum / count as f32, max)
}

#[test]
fn supersampling_converges_to_the_exact_edge_coverage() {
    let (none_mean, _) = errors(&render(SamplePattern::Regular { n: 1 }));
    let (regular_mean, regular_max) = errors(&render(SamplePattern::Regular { n: 8 }));
    let (jitter_mean, jitter_max) = errors(&render(SamplePattern::Jittered { n: 8, seed: 7 }));
    // One sample per pixel: all-or-nothing, about ¼ off on average.
    assert!(none_mean > 0.15, "{none_mean}");
    // 64 samples: the error of counting an edge on an 8×8 grid, ≤ 1/8 per pixel.
    assert!(
        regular_mean < 0.03 && regular_max <= 0.125 + 1e-6,
        "{regular_mean} {regular_max}"
    );
    assert!(
        jitter_mean < 0.03 && jitter_max <= 0.2,
        "{jitter_mean} {jitter_max}"
    );
}

#[test]
fn patterns_stay_in_the_pixel_and_are_stratified() {
    for pattern in [
        SamplePattern::Regular { n: 4 },
        SamplePattern::Jittered { n: 4, seed: 1 },
    ] {
        let offsets = pattern.offsets();
        assert_eq!(offsets.len(), 16);
        for (k, o) in offsets.iter().enumerate() {
            let cell = Vec2::new((k % 4) as f32, (k / 4) as f32) / 4.0;
            assert!(
                o.cmpge(cell).all() && o.cmplt(cell + 0.25).all(),
                "{pattern:?} {o:?}"
            );
        }
        assert_eq!(offsets, pattern.offsets(), "deterministic");
    }
    assert_eq!(
        SamplePattern::Regular { n: 1 }.offsets(),
        [Vec2::splat(0.5)]
    );
}

/// Adaptive supersampling spends samples near the edge only: most pixels keep the minimum,
/// only pixels the edge crosses go past 16, and the error equals that of giving every pixel all
/// 40 samples, at a small fraction of the samples.
#[test]
fn adaptive_supersampling_refines_only_the_edge() {
    let vertices = edge_triangle();
    let options = AdaptiveOptions::default();
    let (fb, stats) = render_adaptive(
        SIZE,
        SIZE,
        Vec4::new(0.0, 0.0, 0.0, 1.0),
        &options,
        &TargetLimits::default(),
        |fb, shift| {
            let state = PipelineState {
                cull: CullMode::None,
                viewport: Some(Viewport {
                    x: shift.x,
                    y: shift.y,
                    ..Viewport::full(SIZE, SIZE)
                }),
                ..PipelineState::default()
            };
            draw(fb, &White, &state, &vertices, &[0, 1, 2]);
        },
    )
    .expect("small");
    let (adaptive_mean, adaptive_max) = errors(&fb);
    let uniform = AdaptiveOptions {
        min_samples: 40,
        ..options
    };
    let (everywhere, _) = render_adaptive(
        SIZE,
        SIZE,
        Vec4::new(0.0, 0.0, 0.0, 1.0),
        &uniform,
        &TargetLimits::default(),
        |fb, shift| {
            let state = PipelineState {
                cull: CullMode::None,
                viewport: Some(Viewport {
                    x: shift.x,
                    y: shift.y,
                    ..Viewport::full(SIZE, SIZE)
                }),
                ..PipelineState::default()
            };
            draw(fb, &White, &state, &vertices, &[0, 1, 2]);
        },
    )
    .expect("small");
    let (uniform_mean, _) = errors(&everywhere);
    let (grid4_mean, _) = errors(&render(SamplePattern::Regular { n: 2 }));
    let pixels = u64::from(SIZE * SIZE);
    let edge_pixels = (0..SIZE)
        .flat_map(|y| (0..SIZE).map(move |x| coverage(x, y)))
        .filter(|&c| c > 0.0 && c < 1.0)
        .count() as u64;
    let beyond_16: u64 = (17..=40).map(|n| stats.pixels_at(n)).sum();
    eprintln!(
        "adaptive: {:.2} samples/pixel, {} at 40, error mean {adaptive_mean:.4} max \
         {adaptive_max:.4}; 40 everywhere {uniform_mean:.4}; 2×2 grid {grid4_mean:.4}",
        stats.mean_samples(),
        stats.pixels_at(40)
    );
    assert_eq!(stats.histogram.iter().sum::<u64>(), pixels);
    assert!(
        beyond_16 > 0 && beyond_16 <= edge_pixels,
        "{beyond_16} > {edge_pixels}"
    );
    assert!(stats.pixels_at(4) >= pixels - 3 * edge_pixels);
    assert!(stats.mean_samples() < 8.0, "{}", stats.mean_samples());
    assert!(
        adaptive_mean <= uniform_mean * 1.05,
        "{adaptive_mean} vs {uniform_mean}"
    );
    assert!(
        adaptive_mean < grid4_mean / 2.0,
        "{adaptive_mean} vs {grid4_mean}"
    );
    // Bad options are an error, not a panic.
    let bad = AdaptiveOptions {
        min_samples: 1,
        ..options
    };
    assert!(render_adaptive(4, 4, Vec4::ZERO, &bad, &TargetLimits::default(), |_, _| {}).is_err());
}
