//! Shaders that take their fragments in pairs (`Shader::PAIRS`) draw exactly what they draw one
//! fragment at a time: the same image, depth and statistics, under every single-sample
//! depth/blend/mask combination, on small and large triangles, on 1 and 2 threads, in the
//! AVX2 + FMA build of the paired loop (where the processor has it; replace blending with the
//! depth written and no mask) and in the baseline build.

use barytex_raster::{
    Blend, CullMode, DepthCompare, DrawStats, Fragment, Framebuffer, PipelineState, Rgba8Unorm,
    SamplePattern, Shader, TargetLimits, draw,
};
use glam::Vec4;

/// A colour varying, discarding where its red exceeds 0.8 and reading its derivatives;
/// `PAIRED` decides whether the rasterizer pairs its fragments. The pair override shades the
/// second fragment first: the rasterizer must not depend on the order within a pair.
struct Colours<const PAIRED: bool>;

impl<const PAIRED: bool> Shader for Colours<PAIRED> {
    type Vertex = (Vec4, Vec4);
    type Varying = Vec4;
    fn vertex(&self, v: &(Vec4, Vec4)) -> (Vec4, Vec4) {
        *v
    }
    fn fragment(&self, f: &Fragment<'_, Vec4>) -> Option<Vec4> {
        if f.varying.x > 0.8 {
            return None;
        }
        let (dx, dy) = f.derivatives();
        Some((f.varying + (dx + dy) * 0.5).with_w(0.6))
    }
    const PAIRS: bool = PAIRED;
    fn fragment_pair(&self, a: &Fragment<'_, Vec4>, b: &Fragment<'_, Vec4>) -> [Option<Vec4>; 2] {
        let second = self.fragment(b);
        [self.fragment(a), second]
    }
}

/// `count` random triangles with sides up to `size` (clip units), random depths and colours.
fn triangles(count: usize, size: f32, seed: u64) -> Vec<(Vec4, Vec4)> {
    let mut state = seed | 1;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1 << 24) as f32
    };
    (0..count)
        .flat_map(|_| {
            let centre = (next() * 2.4 - 1.2, next() * 2.4 - 1.2);
            let z = next();
            let colour = Vec4::new(next(), next(), next(), 1.0);
            let mut corner = || {
                let clip = Vec4::new(
                    centre.0 + (next() - 0.5) * size,
                    centre.1 + (next() - 0.5) * size,
                    z + next() * 0.1,
                    1.0,
                );
                (clip, colour * (0.5 + next()))
            };
            [corner(), corner(), corner()]
        })
        .collect()
}

fn render<const PAIRED: bool>(
    vertices: &[(Vec4, Vec4)],
    state: &PipelineState,
    masked: bool,
    threads: usize,
) -> (Vec<[u8; 4]>, Vec<u32>, DrawStats) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("pool");
    pool.install(|| {
        let (w, h) = (150, 110);
        let background = Vec4::new(0.1, 0.2, 0.3, 1.0);
        let mut fb = Framebuffer::<Rgba8Unorm>::with_format(
            w,
            h,
            SamplePattern::CENTRE,
            background,
            &TargetLimits::default(),
        )
        .expect("small");
        if masked {
            fb.set_mask(Some(&|x, y| (x / 7 + y / 5) % 3 != 0))
                .expect("small");
        }
        let indices: Vec<u32> = (0..vertices.len() as u32).collect();
        let stats = draw(&mut fb, &Colours::<PAIRED>, state, vertices, &indices);
        let pixels = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| fb.stored(x, y).expect("inside"))
            .collect();
        let depths = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| fb.depth(x, y).expect("inside").to_bits())
            .collect();
        (pixels, depths, stats)
    })
}

#[test]
fn paired_fragments_draw_what_single_fragments_draw() {
    let states = [
        (Some(DepthCompare::Less), Blend::Replace, true),
        (Some(DepthCompare::LessEqual), Blend::Replace, true),
        (Some(DepthCompare::Less), Blend::Over, false),
        (Some(DepthCompare::Always), Blend::Replace, true),
        (None, Blend::Over, true),
        (Some(DepthCompare::Less), Blend::Replace, false),
    ];
    for (size, count) in [(0.05, 900), (0.4, 200), (2.5, 12)] {
        let vertices = triangles(count, size, 0x5eed + count as u64);
        for (depth_compare, blend, depth_write) in states {
            let state = PipelineState {
                depth_compare,
                blend,
                depth_write,
                cull: CullMode::None,
                ..PipelineState::default()
            };
            for masked in [false, true] {
                for threads in [1, 2] {
                    let single = render::<false>(&vertices, &state, masked, threads);
                    // Paired in the AVX2 build where the processor has it, then in the
                    // baseline build (the setting is the process's: this binary has no other
                    // test that could draw meanwhile).
                    let paired = render::<true>(&vertices, &state, masked, threads);
                    barytex_raster::allow_avx2(false);
                    let baseline = render::<true>(&vertices, &state, masked, threads);
                    barytex_raster::allow_avx2(true);
                    assert!(single.2.fragments_shaded > 0 && single.2.fragments_discarded > 0);
                    let what = format!(
                        "{size} {depth_compare:?} {blend:?} write {depth_write} mask {masked} \
                         threads {threads}"
                    );
                    assert_eq!(single, paired, "{what}");
                    assert_eq!(single, baseline, "{what}, baseline build");
                }
            }
        }
    }
}
