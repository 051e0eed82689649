//! Drawing in batches (bins bounded by `max_entries`) gives the same target and statistics as
//! one batch, for `draw` and `draw_cleared`, one and four samples, blending and depth tests.

use glam::{Vec3, Vec4};

use super::{MAX_BIN_ENTRIES, draw_batched};
use crate::{
    Blend, CullMode, DepthCompare, DrawStats, Fragment, Framebuffer, PipelineState, SamplePattern,
    Shader, TargetLimits,
};

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

/// `n` random overlapping translucent triangles (perspective), a third of them larger than
/// the view (many tiles each), the rest a few pixels.
fn scene(n: usize, seed: u64) -> (Vec<(Vec4, Vec4)>, Vec<u32>) {
    let mut state = seed | 1;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut vertices = Vec::new();
    for k in 0..n {
        let size = if k % 3 == 0 { 2.5 } else { 0.1 };
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

/// The target's buffers and the statistics after drawing `scene` over an earlier picture with
/// bins of at most `max_entries`.
fn drawn(
    pattern: SamplePattern,
    state: &PipelineState,
    clear: Option<Vec4>,
    scene: &(Vec<(Vec4, Vec4)>, Vec<u32>),
    max_entries: usize,
) -> (Vec<Vec4>, Vec<f32>, DrawStats) {
    let limits = TargetLimits::default();
    let mut fb = Framebuffer::multisampled(200, 150, pattern, Vec4::ONE, &limits).expect("small");
    let earlier = self::scene(20, 0xEA21_1E12);
    let first = PipelineState {
        cull: CullMode::None,
        depth_compare: Some(DepthCompare::Less),
        ..PipelineState::default()
    };
    let input = (&earlier.0[..], &earlier.1[..]);
    draw_batched(&mut fb, None, &Colours, &first, input, MAX_BIN_ENTRIES);
    let input = (&scene.0[..], &scene.1[..]);
    let stats = draw_batched(&mut fb, clear, &Colours, state, input, max_entries);
    (fb.color.to_vec(), fb.depth.to_vec(), stats)
}

#[test]
fn batches_draw_what_one_batch_draws() {
    let scene = scene(60, 0x5EED_0B17);
    let states = [
        PipelineState {
            cull: CullMode::None,
            depth_compare: Some(DepthCompare::Less),
            ..PipelineState::default()
        },
        PipelineState {
            cull: CullMode::None,
            blend: Blend::Over,
            depth_compare: Some(DepthCompare::LessEqual),
            ..PipelineState::default()
        },
        PipelineState {
            blend: Blend::Over,
            depth_compare: None,
            ..PipelineState::default()
        },
    ];
    let mut batched_runs = 0;
    for pattern in [
        SamplePattern::Regular { n: 1 },
        SamplePattern::Regular { n: 2 },
    ] {
        for state in &states {
            for clear in [None, Some(Vec4::new(0.2, 0.4, 0.6, 0.8))] {
                let whole = drawn(pattern, state, clear, &scene, MAX_BIN_ENTRIES);
                assert!(whole.2.fragments_shaded > 10_000, "{:?}", whole.2);
                // One entry: every piece its own batch; 7 and 40: batches of a few pieces.
                for max_entries in [1, 7, 40] {
                    let batched = drawn(pattern, state, clear, &scene, max_entries);
                    assert!(
                        batched == whole,
                        "{pattern:?}, {state:?}, clear {clear:?}, {max_entries} entries"
                    );
                    batched_runs += 1;
                }
            }
        }
    }
    assert_eq!(batched_runs, 36);
}
