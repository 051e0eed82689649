//! Sample masks: `mask_samples` marks exactly the samples a draw with the same state writes
//! (checked against per-sample shading, which shades each written sample once), for every
//! sample pattern, against a depth buffer with something already in it, under the write mask;
//! degenerate and non-finite input never panics; copies through the mask touch only its samples.

use std::collections::BTreeSet;
use std::sync::Mutex;

use barytex_raster::{
    CullMode, DepthCompare, Fragment, Framebuffer, PipelineState, SamplePattern, Shader,
    TargetLimits, draw, mask_samples,
};
use glam::Vec4;
use proptest::prelude::*;

/// Clip-space positions; records (x, y, coverage) of every fragment it shades.
struct Recorder(Mutex<Vec<(u32, u32, u32)>>);

impl Shader for Recorder {
    type Vertex = Vec4;
    type Varying = f32;
    fn vertex(&self, v: &Vec4) -> (Vec4, f32) {
        (*v, 0.0)
    }
    fn fragment(&self, f: &Fragment<'_, f32>) -> Option<Vec4> {
        self.0
            .lock()
            .expect("not poisoned")
            .push((f.pixel.x, f.pixel.y, f.coverage));
        Some(Vec4::ONE)
    }
}

const PATTERNS: [SamplePattern; 5] = [
    SamplePattern::CENTRE,
    SamplePattern::Standard { count: 4 },
    SamplePattern::Standard { count: 16 },
    SamplePattern::Regular { n: 3 },
    SamplePattern::Jittered { n: 2, seed: 7 },
];

/// The (x, y, sample) triples a per-sample-shaded draw of `tri` writes into `fb`.
fn drawn_samples(
    fb: &Framebuffer,
    state: &PipelineState,
    tri: &[Vec4],
) -> BTreeSet<(u32, u32, u32)> {
    let recorder = Recorder(Mutex::new(Vec::new()));
    let state = PipelineState {
        sample_shading: true,
        depth_write: false,
        ..*state
    };
    let mut scratch = fb.clone();
    draw(&mut scratch, &recorder, &state, tri, &[0, 1, 2]);
    let seen = recorder.0.into_inner().expect("not poisoned");
    seen.into_iter()
        .map(|(x, y, c)| (x, y, c.trailing_zeros()))
        .collect()
}

fn masked_samples(
    fb: &Framebuffer,
    state: &PipelineState,
    tri: &[Vec4],
) -> BTreeSet<(u32, u32, u32)> {
    let (mask, _) = mask_samples(fb, state, tri, &[0, 1, 2]).expect("small");
    let mut out = BTreeSet::new();
    for y in 0..fb.height() {
        for x in 0..fb.width() {
            let word = mask.pixel(x, y);
            for k in 0..32 {
                if word & (1 << k) != 0 {
                    out.insert((x, y, k));
                }
            }
        }
    }
    assert_eq!(mask.count(), out.len() as u64);
    out
}

fn vertex() -> impl Strategy<Value = Vec4> {
    (-1.6f32..1.6, -1.6f32..1.6, -0.2f32..1.2, 0.3f32..2.0)
        .prop_map(|(x, y, z, w)| Vec4::new(x * w, y * w, z * w, w))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Over a depth buffer holding another triangle, with culling, every pattern: the mask is
    /// the set of samples the draw writes.
    #[test]
    fn masks_are_the_samples_a_draw_writes(
        occluder in prop::array::uniform3(vertex()),
        tri in prop::array::uniform3(vertex()),
        pattern in 0usize..PATTERNS.len(),
        cull in 0usize..3,
        half_masked in any::<bool>(),
    ) {
        let mut fb = Framebuffer::multisampled(
            37, 29, PATTERNS[pattern], Vec4::ZERO, &TargetLimits::default(),
        ).expect("small");
        let none = PipelineState { cull: CullMode::None, ..PipelineState::default() };
        draw(&mut fb, &Recorder(Mutex::new(Vec::new())), &none, &occluder, &[0, 1, 2]);
        if half_masked {
            fb.set_mask(Some(&|x, y| (x + y) % 3 != 0)).expect("small");
        }
        let state = PipelineState {
            cull: [CullMode::None, CullMode::Back, CullMode::Front][cull],
            depth_compare: Some(DepthCompare::Less),
            ..PipelineState::default()
        };
        prop_assert_eq!(masked_samples(&fb, &state, &tri), drawn_samples(&fb, &state, &tri));
    }

    /// NaN, infinite, huge, collinear, zero-area and behind-the-eye triangles: no panic, and
    /// the mask is still exactly what the draw writes.
    #[test]
    fn degenerate_input_never_panics(
        raw in prop::array::uniform12(prop_oneof![
            Just(f32::NAN), Just(f32::INFINITY), Just(-f32::INFINITY), Just(0.0f32),
            Just(1e30f32), Just(-1e-30f32), -2.0f32..2.0,
        ]),
        pattern in 0usize..PATTERNS.len(),
    ) {
        let tri: Vec<Vec4> = raw.chunks_exact(4).map(Vec4::from_slice).collect();
        let fb = Framebuffer::multisampled(
            16, 16, PATTERNS[pattern], Vec4::ZERO, &TargetLimits::default(),
        ).expect("small");
        let state = PipelineState { cull: CullMode::None, ..PipelineState::default() };
        prop_assert_eq!(masked_samples(&fb, &state, &tri), drawn_samples(&fb, &state, &tri));
        // Out-of-range indices are dropped, not read.
        let (mask, stats) = mask_samples(&fb, &state, &tri, &[0, 1, 9]).expect("small");
        prop_assert!(mask.is_empty());
        prop_assert_eq!(stats.dropped_bad_index, 1);
    }
}

/// A copy through a mask changes exactly the masked samples (with 4 samples a pixel, the
/// resolved colour is the share of masked samples).
#[test]
fn copies_change_only_masked_samples() {
    let limits = TargetLimits::default();
    let pattern = SamplePattern::Standard { count: 4 };
    let mut fb = Framebuffer::multisampled(24, 24, pattern, Vec4::ZERO, &limits).expect("small");
    let white = Framebuffer::multisampled(24, 24, pattern, Vec4::ONE, &limits).expect("small");
    let tri = [
        Vec4::new(-0.9, -0.7, 0.5, 1.0),
        Vec4::new(0.8, -0.2, 0.5, 1.0),
        Vec4::new(-0.1, 0.95, 0.5, 1.0),
    ];
    let (mask, _) = mask_samples(&fb, &PipelineState::default(), &tri, &[0, 1, 2]).expect("small");
    assert!(mask.count() > 100);
    fb.copy_samples(&white, &mask).expect("same targets");
    let mut partial = 0;
    for y in 0..24 {
        for x in 0..24 {
            let share = mask.pixel(x, y).count_ones() as f32 / 4.0;
            let p = fb.pixel(x, y).expect("inside");
            // Premultiplied white over transparent black, resolved: every channel is the share.
            assert_eq!(p.w, share, "({x}, {y})");
            partial += usize::from(share > 0.0 && share < 1.0);
        }
    }
    assert!(partial > 10, "the triangle's edges cross pixels: {partial}");
}
