//! Multisampled targets: coverage per sample equals an independent exact oracle for every
//! pattern, shared edges cover each sample once, MSAA shades once per pixel and per-sample
//! shading once per sample, MSAA approaches exact area coverage; affine spans; the write mask.

mod common;

use barytex_raster::TargetLimits;
use barytex_raster::{
    Blend, Fragment, Framebuffer, Interpolation, PipelineState, SamplePattern, Shader, draw,
};
use common::no_depth;
use glam::{Mat4, Vec2, Vec3, Vec4};
use proptest::prelude::*;

/// Screen positions (pixels, y down) in a `size × size` target, drawn in one colour.
struct Flat {
    size: f32,
    color: Vec4,
}

impl Shader for Flat {
    type Vertex = Vec2;
    type Varying = f32;
    fn vertex(&self, p: &Vec2) -> (Vec4, f32) {
        (
            Vec4::new(
                p.x / self.size * 2.0 - 1.0,
                1.0 - p.y / self.size * 2.0,
                0.5,
                1.0,
            ),
            0.0,
        )
    }
    fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> {
        Some(self.color)
    }
}

/// The oracle: whether the point `s` (1/256-pixel integers) is covered by the triangle `v`
/// (same units) under the top-left rule — written independently of the rasterizer.
fn covers(v: [(i64, i64); 3], s: (i64, i64)) -> bool {
    let area = (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[1].1 - v[0].1) * (v[2].0 - v[0].0);
    if area == 0 {
        return false;
    }
    // Make it clockwise on screen (y down) = positive edge functions inside.
    let v = if area > 0 { v } else { [v[0], v[2], v[1]] };
    (0..3).all(|i| {
        let (p, q) = (v[i], v[(i + 1) % 3]);
        let e = (q.0 - p.0) * (s.1 - p.1) - (q.1 - p.1) * (s.0 - p.0);
        let top = q.1 == p.1 && q.0 > p.0;
        let left = q.1 < p.1;
        e > 0 || (e == 0 && (top || left))
    })
}

fn fixed(p: Vec2) -> (i64, i64) {
    ((p.x * 256.0).round() as i64, (p.y * 256.0).round() as i64)
}

const PATTERNS: [SamplePattern; 5] = [
    SamplePattern::Standard { count: 4 },
    SamplePattern::Standard { count: 8 },
    SamplePattern::Standard { count: 16 },
    SamplePattern::Regular { n: 3 },
    SamplePattern::Jittered { n: 4, seed: 11 },
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 40, ..ProptestConfig::default() })]

    /// Every pixel's resolved coverage is (covered samples)/(samples), the samples decided by
    /// the oracle at the positions the pattern reports — for every pattern, per-pixel jitter
    /// included, and with vertices on the sub-pixel grid so edges pass through samples often.
    #[test]
    fn coverage_per_sample_matches_the_exact_oracle(
        coords in prop::array::uniform6(0_i32..24 * 16),
        pattern in prop::sample::select(PATTERNS.to_vec()),
    ) {
        const SIZE: u32 = 24;
        let v: Vec<Vec2> = coords
            .chunks(2)
            .map(|c| Vec2::new(c[0] as f32, c[1] as f32) / 16.0)
            .collect();
        let mut fb = Framebuffer::multisampled(SIZE, SIZE, pattern, Vec4::ZERO, &TargetLimits::default())
            .expect("small");
        let shader = Flat { size: SIZE as f32, color: Vec4::ONE };
        draw(&mut fb, &shader, &no_depth(), &v, &[0, 1, 2]);
        let tri = [fixed(v[0]), fixed(v[1]), fixed(v[2])];
        let n = pattern.count();
        for y in 0..SIZE {
            for x in 0..SIZE {
                let count = (0..n)
                    .filter(|&k| {
                        let o = pattern.sample_offset(x, y, k) * 256.0;
                        covers(tri, (i64::from(x) * 256 + o.x as i64, i64::from(y) * 256 + o.y as i64))
                    })
                    .count();
                let got = fb.pixel(x, y).expect("inside").w;
                prop_assert_eq!(got, count as f32 / n as f32, "pixel ({}, {}) {:?}", x, y, pattern);
            }
        }
    }
}

/// A jittered mesh over the whole target, half-transparent, blended "over": a sample covered
/// twice would hold alpha 0.75 and a gap 0 — every resolved pixel must be exactly 0.5.
#[test]
fn shared_edges_cover_every_sample_exactly_once() {
    const SIZE: u32 = 40;
    let (vertices, indices) = common::jittered_grid(7, SIZE, SIZE, 0x9E37_79B9);
    for pattern in PATTERNS {
        for sample_shading in [false, true] {
            let mut fb = Framebuffer::multisampled(
                SIZE,
                SIZE,
                pattern,
                Vec4::ZERO,
                &TargetLimits::default(),
            )
            .expect("small");
            let shader = Flat {
                size: SIZE as f32,
                color: Vec4::new(1.0, 1.0, 1.0, 0.5),
            };
            let state = PipelineState {
                blend: Blend::Over,
                sample_shading,
                ..no_depth()
            };
            draw(&mut fb, &shader, &state, &vertices, &indices);
            for y in 0..SIZE {
                for x in 0..SIZE {
                    let a = fb.pixel(x, y).expect("inside").w;
                    assert_eq!(a, 0.5, "pixel ({x}, {y}) {pattern:?} {sample_shading}");
                }
            }
        }
    }
}

/// MSAA runs the fragment stage once per touched pixel; per-sample shading once per covered
/// sample; one sample per pixel once per covered centre.
#[test]
fn shading_rate_follows_the_state() {
    const SIZE: u32 = 32;
    let v = vec![
        Vec2::new(1.3, 2.1),
        Vec2::new(30.2, 9.7),
        Vec2::new(11.6, 29.9),
    ];
    let shader = Flat {
        size: SIZE as f32,
        color: Vec4::ONE,
    };
    let pattern = SamplePattern::Standard { count: 8 };
    let run = |sample_shading: bool| {
        let mut fb =
            Framebuffer::multisampled(SIZE, SIZE, pattern, Vec4::ZERO, &TargetLimits::default())
                .expect("small");
        let state = PipelineState {
            sample_shading,
            ..no_depth()
        };
        let stats = draw(&mut fb, &shader, &state, &v, &[0, 1, 2]);
        (fb, stats.fragments_shaded)
    };
    let (fb, msaa) = run(false);
    let (_, ssaa) = run(true);
    let mut touched = 0;
    let mut samples = 0;
    for y in 0..SIZE {
        for x in 0..SIZE {
            let a = fb.pixel(x, y).expect("inside").w;
            touched += u64::from(a > 0.0);
            samples += (a * 8.0).round() as u64;
        }
    }
    assert_eq!(msaa, touched);
    assert_eq!(ssaa, samples);
    assert!(ssaa > 4 * msaa, "{ssaa} vs {msaa}");
}

/// The exact area of pixel (x, y) left of the line x + 0.3·y = 13.7, by a 400² midpoint rule.
fn area_left_of_line(x: u32, y: u32) -> f32 {
    let n = 400;
    let mut inside = 0;
    for j in 0..n {
        for i in 0..n {
            let px = x as f32 + (i as f32 + 0.5) / n as f32;
            let py = y as f32 + (j as f32 + 0.5) / n as f32;
            inside += u32::from(px + 0.3 * py < 13.7);
        }
    }
    inside as f32 / (n * n) as f32
}

/// On a steep edge, 16 standard samples resolve coverage to within 1/16 on average and far
/// better than one sample; per-pixel jitter is unbiased (mean signed error near 0).
#[test]
fn msaa_approaches_the_exact_area_coverage() {
    const SIZE: u32 = 32;
    let c = 13.7_f32;
    let v = vec![
        Vec2::new(c + 0.3 * 40.0, -40.0),
        Vec2::new(c - 0.3 * 80.0, 80.0),
        Vec2::new(-200.0, 20.0),
    ];
    let shader = Flat {
        size: SIZE as f32,
        color: Vec4::ONE,
    };
    let errors = |pattern: SamplePattern| {
        let mut fb =
            Framebuffer::multisampled(SIZE, SIZE, pattern, Vec4::ZERO, &TargetLimits::default())
                .expect("small");
        draw(&mut fb, &shader, &no_depth(), &v, &[0, 1, 2]);
        let (mut abs, mut signed, mut n) = (0.0, 0.0, 0.0);
        for y in 0..SIZE {
            for x in 9..20 {
                let d = fb.pixel(x, y).expect("inside").w - area_left_of_line(x, y);
                abs += d.abs();
                signed += d;
                n += 1.0;
            }
        }
        (abs / n, signed / n)
    };
    let (one, _) = errors(SamplePattern::CENTRE);
    let (standard, _) = errors(SamplePattern::Standard { count: 16 });
    let (jitter, jitter_bias) = errors(SamplePattern::Jittered { n: 4, seed: 3 });
    eprintln!(
        "mean |error|: 1 sample {one:.4}, standard 16 {standard:.4}, jittered 16 {jitter:.4} (bias {jitter_bias:.4})"
    );
    assert!(standard < 1.0 / 32.0, "{standard}");
    assert!(jitter < 1.0 / 16.0, "{jitter}");
    assert!(jitter_bias.abs() < 0.01, "{jitter_bias}");
    assert!(one > 4.0 * standard, "{one} vs {standard}");
}

/// A textured ground plane under perspective: u along the depth, in a 256² target.
struct Ground {
    mvp: Mat4,
}

impl Shader for Ground {
    type Vertex = (Vec3, f32);
    type Varying = f32;
    fn vertex(&self, &(p, u): &(Vec3, f32)) -> (Vec4, f32) {
        (self.mvp * p.extend(1.0), u)
    }
    fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
        Some(Vec4::new(f.varying, 0.0, 0.0, 1.0))
    }
}

/// Affine spans: exact at span starts, errors growing with the span, all below plain affine.
#[test]
fn affine_spans_trade_error_for_fewer_divisions() {
    const SIZE: u32 = 256;
    // Vulkan-style perspective, 60° vertical, looking down −z at the slanted plane
    // x + y = −1.2 (depth varies along rows and columns: on a level floor every row has one
    // depth and spans would be exact), u = −z/40.
    // glam's DirectX-convention perspective (y up, depth in [0, w]), as the rasterizer takes it.
    let projection =
        glam::camera::rh::proj::directx::perspective(60_f32.to_radians(), 1.0, 0.1, 100.0);
    let shader = Ground { mvp: projection };
    let on_plane = |s: f32, z: f32| {
        (
            Vec3::new(
                -0.6 + s * std::f32::consts::FRAC_1_SQRT_2,
                -0.6 - s * std::f32::consts::FRAC_1_SQRT_2,
                z,
            ),
            -z / 40.0,
        )
    };
    let vertices = vec![
        on_plane(-40.0, -1.0),
        on_plane(40.0, -1.0),
        on_plane(40.0, -40.0),
        on_plane(-40.0, -40.0),
    ];
    let indices = [0, 1, 2, 0, 2, 3];
    let render = |interpolation: Interpolation| {
        let mut fb =
            Framebuffer::new(SIZE, SIZE, Vec4::ZERO, &TargetLimits::default()).expect("small");
        let state = PipelineState {
            interpolation,
            ..no_depth()
        };
        draw(&mut fb, &shader, &state, &vertices, &indices);
        fb
    };
    let exact = render(Interpolation::Perspective);
    let max_error = |fb: &Framebuffer| {
        let mut worst = 0.0_f32;
        let mut at_starts = 0.0_f32;
        for y in 0..SIZE {
            for x in 0..SIZE {
                let (e, g) = (exact.pixel(x, y).expect("in"), fb.pixel(x, y).expect("in"));
                if e.w == 0.0 {
                    continue;
                }
                let d = (e.x - g.x).abs();
                worst = worst.max(d);
                if x % 32 == 0 {
                    at_starts = at_starts.max(d);
                }
            }
        }
        (worst, at_starts)
    };
    let spans: Vec<(f32, f32)> = [8, 16, 32]
        .map(|span| max_error(&render(Interpolation::AffineSpans { span })))
        .to_vec();
    let (affine, _) = max_error(&render(Interpolation::Affine));
    eprintln!("max |Δu|: spans 8/16/32 {spans:?}, affine {affine}");
    for (worst, at_starts) in &spans {
        assert!(*at_starts < 1e-5, "span starts are exact: {at_starts}");
        assert!(*worst < affine / 2.0, "{worst} vs affine {affine}");
    }
    assert!(
        spans[0].0 < spans[1].0 && spans[1].0 < spans[2].0,
        "{spans:?}"
    );
    assert!(spans[0].0 > 0.0);
}

/// Masked pixels are neither shaded nor written.
#[test]
fn the_write_mask_protects_pixels() {
    const SIZE: u32 = 70;
    let v = vec![
        Vec2::new(-5.0, -5.0),
        Vec2::new(200.0, -5.0),
        Vec2::new(-5.0, 200.0),
    ];
    let shader = Flat {
        size: SIZE as f32,
        color: Vec4::ONE,
    };
    let mut fb = Framebuffer::new(SIZE, SIZE, Vec4::ZERO, &TargetLimits::default()).expect("small");
    let keep = |x: u32, y: u32| (x / 3 + y / 5).is_multiple_of(2);
    fb.set_mask(Some(&keep)).expect("small");
    let stats = draw(&mut fb, &shader, &no_depth(), &v, &[0, 1, 2]);
    let mut kept = 0;
    for y in 0..SIZE {
        for x in 0..SIZE {
            let a = fb.pixel(x, y).expect("inside").w;
            assert_eq!(a, if keep(x, y) { 1.0 } else { 0.0 }, "({x}, {y})");
            kept += u64::from(keep(x, y));
        }
    }
    assert_eq!(stats.fragments_shaded, kept);
}

/// Multisampled output is bit-identical for 1 and 3 threads.
#[test]
fn multisampled_output_is_deterministic() {
    const SIZE: u32 = 150;
    let v: Vec<Vec2> = (0..300)
        .map(|i| {
            let t = i as f32 * 0.618;
            Vec2::new((t * 7.3).sin() * 80.0 + 75.0, (t * 5.1).cos() * 80.0 + 75.0)
        })
        .collect();
    let indices: Vec<u32> = (0..300).collect();
    let render = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        pool.install(|| {
            let mut fb = Framebuffer::multisampled(
                SIZE,
                SIZE,
                SamplePattern::Jittered { n: 3, seed: 5 },
                Vec4::ZERO,
                &TargetLimits::default(),
            )
            .expect("small");
            let shader = Flat {
                size: SIZE as f32,
                color: Vec4::new(0.2, 0.5, 0.9, 0.4),
            };
            let state = PipelineState {
                blend: Blend::Over,
                ..no_depth()
            };
            draw(&mut fb, &shader, &state, &v, &indices);
            fb
        })
    };
    assert_eq!(render(1), render(3));
}
