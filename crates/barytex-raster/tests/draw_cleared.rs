//! `draw_cleared` is `Framebuffer::clear` then `draw`, bit for bit: every pixel, every depth
//! and the statistics, over colour formats, sample patterns, masks, blending, scissors,
//! viewports, thread counts and draws that produce no pieces at all.

use barytex_raster::{
    Blend, ColorFormat, CullMode, DepthCompare, DrawStats, Fragment, Framebuffer, LinearRgba32f,
    PipelineState, Rgba8Unorm, SamplePattern, Scissor, Shader, TargetLimits, Viewport, draw,
    draw_cleared,
};
use glam::{Vec3, Vec4};

/// Clip-space positions with a colour per vertex.
struct Colours;

impl Shader for Colours {
    type Vertex = (Vec4, Vec4);
    type Varying = Vec4;
    fn vertex(&self, v: &(Vec4, Vec4)) -> (Vec4, Vec4) {
        *v
    }
    fn fragment(&self, f: &Fragment<'_, Vec4>) -> Option<Vec4> {
        Some(f.varying)
    }
}

/// `n` random overlapping triangles (perspective, w in [1, 3]) of translucent colours, some
/// larger than the view.
fn scene(n: usize, seed: u64, size: f32) -> (Vec<(Vec4, Vec4)>, Vec<u32>) {
    let mut state = seed | 1;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut vertices = Vec::new();
    for _ in 0..n {
        let centre = Vec3::new(next() * 2.4 - 1.2, next() * 2.4 - 1.2, next());
        for _ in 0..3 {
            let w = 1.0 + 2.0 * next();
            let p = centre + Vec3::new(next() - 0.5, next() - 0.5, 0.0) * size;
            let colour = Vec4::new(next(), next(), next(), 0.3 + 0.7 * next());
            vertices.push(((p * w).extend(w), colour));
        }
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices)
}

/// Every pixel's resolved colour and first depth.
type Contents = Vec<(Option<Vec4>, Option<f32>)>;

/// Every pixel's stored colour (resolved over its samples) and depth (first sample).
fn contents<C: ColorFormat>(fb: &Framebuffer<C>) -> Contents {
    (0..fb.height())
        .flat_map(|y| (0..fb.width()).map(move |x| (x, y)))
        .map(|(x, y)| (fb.pixel(x, y), fb.depth(x, y)))
        .collect()
}

/// Draws `indices` both ways into two targets that hold an earlier picture and returns their
/// contents and statistics: `clear` then `draw`, and `draw_cleared`.
fn both_ways<C: ColorFormat>(
    pattern: SamplePattern,
    mask: bool,
    state: &PipelineState,
    (vertices, indices): &(Vec<(Vec4, Vec4)>, Vec<u32>),
) -> [(Contents, DrawStats); 2] {
    let clear = Vec4::new(0.2, 0.4, 0.6, 0.8);
    let earlier = scene(30, 0xEA21_1E12, 0.9);
    let limits = TargetLimits::default();
    let mut fbs = [0, 1].map(|_| {
        let mut fb =
            Framebuffer::<C>::with_format(150, 90, pattern, Vec4::ONE, &limits).expect("small");
        let depth_less = PipelineState {
            cull: CullMode::None,
            depth_compare: Some(DepthCompare::Less),
            ..PipelineState::default()
        };
        draw(&mut fb, &Colours, &depth_less, &earlier.0, &earlier.1);
        if mask {
            fb.set_mask(Some(&|x, y| (x / 3 + y / 5) % 4 != 0))
                .expect("small");
        }
        fb
    });
    let [a, b] = &mut fbs;
    a.clear(clear);
    let stats_a = draw(a, &Colours, state, vertices, indices);
    let stats_b = draw_cleared(b, clear, &Colours, state, vertices, indices);
    [(contents(a), stats_a), (contents(b), stats_b)]
}

fn states() -> Vec<PipelineState> {
    let base = PipelineState {
        cull: CullMode::None,
        depth_compare: Some(DepthCompare::Less),
        ..PipelineState::default()
    };
    vec![
        base,
        PipelineState {
            blend: Blend::Over,
            ..base
        },
        PipelineState {
            cull: CullMode::Back,
            depth_compare: Some(DepthCompare::Greater),
            ..base
        },
        PipelineState {
            scissor: Some(Scissor {
                x0: 20,
                y0: 10,
                x1: 100,
                y1: 70,
            }),
            ..base
        },
        PipelineState {
            viewport: Some(Viewport {
                x: 70.0,
                y: 5.0,
                width: 60.0,
                height: 40.0,
                min_depth: 0.0,
                max_depth: 1.0,
            }),
            ..base
        },
        // Nothing is writable: the draw has no tiles to draw, only to clear.
        PipelineState {
            scissor: Some(Scissor {
                x0: 40,
                y0: 40,
                x1: 40,
                y1: 80,
            }),
            ..base
        },
    ]
}

fn check<C: ColorFormat>(threads: usize) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool");
    let scenes = [
        scene(80, 0x5EED_0001, 0.6),
        scene(400, 0x5EED_0002, 0.1),
        // No triangles at all, and triangles all behind the camera: no pieces.
        (Vec::new(), Vec::new()),
        (
            vec![(Vec4::new(0.0, 0.0, 0.5, -1.0), Vec4::ONE); 3],
            vec![0, 1, 2],
        ),
    ];
    for pattern in [SamplePattern::CENTRE, SamplePattern::Standard { count: 4 }] {
        for mask in [false, true] {
            for (s, state) in states().iter().enumerate() {
                for (k, scene) in scenes.iter().enumerate() {
                    let [a, b] = pool.install(|| both_ways::<C>(pattern, mask, state, scene));
                    assert!(
                        a == b,
                        "{pattern:?}, mask {mask}, state {s}, scene {k}, {threads} threads"
                    );
                }
            }
        }
    }
}

#[test]
fn draw_cleared_is_clear_then_draw_float_target() {
    check::<LinearRgba32f>(1);
    check::<LinearRgba32f>(2);
}

#[test]
fn draw_cleared_is_clear_then_draw_rgba8_target() {
    check::<Rgba8Unorm>(1);
    check::<Rgba8Unorm>(2);
}

#[test]
fn draw_cleared_clears_pixels_no_triangle_covers() {
    let mut fb = Framebuffer::new(70, 70, Vec4::ONE, &TargetLimits::default()).expect("small");
    let red = Vec4::new(1.0, 0.0, 0.0, 1.0);
    let stats = draw_cleared(&mut fb, red, &Colours, &PipelineState::default(), &[], &[]);
    assert_eq!(stats, DrawStats::default());
    assert!((0..70).all(|y| (0..70).all(|x| fb.pixel(x, y) == Some(red))));
    assert!((0..70).all(|y| (0..70).all(|x| fb.depth(x, y) == Some(1.0))));
}
