//! The 4-byte colour targets draw the float target's picture, rounded once per write: the same
//! pixels covered, the same depths, and each byte the float pixel quantized.

use barytex_raster::{
    Blend, ColorFormat, CullMode, DepthCompare, Fragment, Framebuffer, LinearRgba32f,
    PipelineState, Rgba8Unorm, SamplePattern, Shader, TargetLimits, draw,
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
        // Some out of [0, 1] on purpose: the 8-bit formats clamp.
        Some(f.varying)
    }
}

/// `n` random triangles, perspective (w in [1, 3]), overlapping, colours in `[lo, lo + span]`
/// with alpha `alpha`.
fn scene(n: usize, seed: u64, alpha: f32, (lo, span): (f32, f32)) -> (Vec<(Vec4, Vec4)>, Vec<u32>) {
    let mut state = seed | 1;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    let mut vertices = Vec::new();
    for _ in 0..n {
        let centre = Vec3::new(next() * 2.0 - 1.0, next() * 2.0 - 1.0, next());
        for _ in 0..3 {
            let w = 1.0 + 2.0 * next();
            let p = centre + Vec3::new(next() - 0.5, next() - 0.5, 0.0) * 0.8;
            let colour = Vec4::new(
                lo + next() * span,
                lo + next() * span,
                lo + next() * span,
                alpha,
            );
            vertices.push(((p * w).extend(w), colour));
        }
    }
    let indices = (0..vertices.len() as u32).collect();
    (vertices, indices)
}

/// Colours in [−0.2, 1.2]: some clamped by the 8-bit formats.
const WIDE: (f32, f32) = (-0.2, 1.4);

fn state(blend: Blend) -> PipelineState {
    PipelineState {
        cull: CullMode::None,
        depth_compare: Some(DepthCompare::Less),
        blend,
        ..PipelineState::default()
    }
}

fn drawn<C: ColorFormat>(
    pattern: SamplePattern,
    clear: Vec4,
    blend: Blend,
    alpha: f32,
    colours: (f32, f32),
) -> Framebuffer<C> {
    let mut fb = Framebuffer::<C>::with_format(97, 75, pattern, clear, &TargetLimits::default())
        .expect("small");
    let (vertices, indices) = scene(60, 0x5EED_1234, alpha, colours);
    draw(&mut fb, &Colours, &state(blend), &vertices, &indices);
    fb
}

#[test]
fn rgba8_target_is_the_float_target_quantized() {
    let clear = Vec4::new(0.1, 0.2, 0.3, 1.0);
    let float = drawn::<LinearRgba32f>(SamplePattern::CENTRE, clear, Blend::Replace, 1.0, WIDE);
    let bytes = drawn::<Rgba8Unorm>(SamplePattern::CENTRE, clear, Blend::Replace, 1.0, WIDE);
    let mut distinct = std::collections::HashSet::new();
    for y in 0..75 {
        for x in 0..97 {
            let p = float.pixel(x, y).expect("inside");
            let stored = bytes.stored(x, y).expect("inside");
            assert_eq!(stored, Rgba8Unorm::store(p), "pixel ({x}, {y})");
            assert_eq!(bytes.depth(x, y), float.depth(x, y), "pixel ({x}, {y})");
            // What the accessor reads back is the byte's value.
            assert_eq!(
                bytes.pixel(x, y),
                Some(Vec4::from_array(stored.map(|b| f32::from(b) / 255.0)))
            );
            distinct.insert(stored);
        }
    }
    // A picture, not a flat clear: many triangles, many colours, some clamped.
    assert!(distinct.len() > 1000, "{}", distinct.len());
    assert!(distinct.iter().any(|s| s[0] == 0) && distinct.iter().any(|s| s[1] == 255));
}

#[test]
fn rgba8_blending_rounds_once_per_write() {
    // Half-transparent triangles over an opaque clear: alpha stays 1, and each write's rounding
    // error (½ step) is halved by every later layer, so the total stays under 1 step. Colours
    // inside [0, 1]: the 8-bit target clamps every layer, the float target none.
    let clear = Vec4::new(0.0, 0.0, 0.0, 1.0);
    let (float, bytes) = (
        drawn::<LinearRgba32f>(SamplePattern::CENTRE, clear, Blend::Over, 0.5, (0.0, 1.0)),
        drawn::<Rgba8Unorm>(SamplePattern::CENTRE, clear, Blend::Over, 0.5, (0.0, 1.0)),
    );
    let (mut worst, mut differ) = (0.0_f32, 0);
    for y in 0..75 {
        for x in 0..97 {
            let (p, q) = (
                float.pixel(x, y).expect("in"),
                bytes.pixel(x, y).expect("in"),
            );
            worst = worst.max((p - q).abs().max_element());
            differ += usize::from(Rgba8Unorm::store(p) != bytes.stored(x, y).expect("in"));
        }
    }
    assert!(worst <= 1.0 / 255.0 + 1e-6, "{worst}");
    // The 8-bit target does round between layers (so this test can tell them apart).
    assert!(differ > 0);
}

#[test]
fn rgba8_multisampled_resolves_like_the_float_target() {
    let clear = Vec4::new(0.3, 0.3, 0.3, 1.0);
    let pattern = SamplePattern::Standard { count: 4 };
    // Colours inside [0, 1]: clamping the resolved mean is not the mean of clamped samples.
    let float = drawn::<LinearRgba32f>(pattern, clear, Blend::Replace, 1.0, (0.0, 1.0));
    let bytes = drawn::<Rgba8Unorm>(pattern, clear, Blend::Replace, 1.0, (0.0, 1.0));
    assert_eq!(bytes.samples(), 4);
    let mut edges = 0;
    for y in 0..75 {
        for x in 0..97 {
            let (p, q) = (
                float.pixel(x, y).expect("in"),
                bytes.pixel(x, y).expect("in"),
            );
            // Each sample is rounded by half a step at most.
            assert!(
                (p - q).abs().max_element() <= 0.5 / 255.0 + 1e-6,
                "({x}, {y}): {p} {q}"
            );
            // Pixels on an edge: their samples differ.
            edges += usize::from(p != float.stored(x, y).expect("in"));
        }
    }
    assert!(edges > 0);
}

#[cfg(feature = "texture")]
#[test]
fn srgb_target_is_the_float_target_encoded() {
    use barytex_raster::Srgba8Unorm;
    use barytex_texture::{Srgba8, Texel};
    let clear = Vec4::new(0.5, 0.2, 0.0, 1.0);
    let float = drawn::<LinearRgba32f>(SamplePattern::CENTRE, clear, Blend::Replace, 1.0, WIDE);
    let srgb = drawn::<Srgba8Unorm>(SamplePattern::CENTRE, clear, Blend::Replace, 1.0, WIDE);
    for y in 0..75 {
        for x in 0..97 {
            let p = float.pixel(x, y).expect("inside");
            assert_eq!(
                srgb.stored(x, y),
                Some(Srgba8::from_linear(p).0),
                "({x}, {y})"
            );
            assert_eq!(srgb.depth(x, y), float.depth(x, y));
        }
    }
    // The texture conversion of the sRGB target holds the same bytes.
    let image = srgb.to_srgba8().expect("small");
    assert_eq!(image.texel(5, 7).map(|t| t.0), srgb.stored(5, 7));
}
