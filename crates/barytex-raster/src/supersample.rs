//! Supersampling by accumulation: the scene is drawn once per sample position, with the
//! viewport shifted by that position's sub-pixel offset, and the passes are averaged (shading per
//! sample: every effect is anti-aliased, not only edges). Regular N×N grids and stratified
//! jittered positions (seed 000's supersampling, regular and stochastic).

use barytex_texture::{Limits, TextureError};
use glam::{Vec2, Vec4};

use crate::target::Framebuffer;

/// Where the samples of a pixel lie.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SamplePattern {
    /// The centres of an `n × n` grid of sub-pixel cells.
    Regular {
        /// Cells per side (1 is the pixel centre: no anti-aliasing).
        n: u32,
    },
    /// One random position in each cell of an `n × n` grid (stratified jitter), the same for
    /// every pixel of a pass; `seed` makes it repeatable.
    Jittered {
        /// Cells per side.
        n: u32,
        /// Selects the positions.
        seed: u64,
    },
}

impl SamplePattern {
    /// The sample offsets from the pixel's top-left corner, each in `[0, 1)²`.
    #[must_use]
    pub fn offsets(self) -> Vec<Vec2> {
        let (n, seed) = match self {
            Self::Regular { n } => (n.max(1), None),
            Self::Jittered { n, seed } => (n.max(1), Some(seed)),
        };
        let cell = 1.0 / n as f32;
        let mut out = Vec::with_capacity((n * n) as usize);
        for j in 0..n {
            for i in 0..n {
                let (u, v) = match seed {
                    None => (0.5, 0.5),
                    Some(seed) => (
                        hash01(seed, u64::from(j * n + i), 0),
                        hash01(seed, u64::from(j * n + i), 1),
                    ),
                };
                out.push(Vec2::new((i as f32 + u) * cell, (j as f32 + v) * cell));
            }
        }
        out
    }
}

/// A uniform value in [0, 1) from a seed, an index and a stream (SplitMix64).
fn hash01(seed: u64, index: u64, stream: u64) -> f32 {
    let mut z = seed
        .wrapping_add(index.wrapping_mul(0x9E37_79B9_7F4A_7C15))
        .wrapping_add(stream.wrapping_mul(0xD1B5_4A32_D192_ED03));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 40) as f32 / (1u64 << 24) as f32
}

/// Renders `draw_pass` once per sample of `pattern` and averages the passes.
///
/// `draw_pass(target, shift)` must draw the scene into the cleared `target` with its viewport
/// moved by `shift` pixels (a sample at offset `o` from the pixel corner is the centre of the
/// pixel when the image moves by `(½, ½) − o`); the result is the per-pixel mean of the passes,
/// in linear light on premultiplied colour.
///
/// # Errors
/// When a target cannot be allocated under `limits`.
pub fn render_supersampled(
    width: u32,
    height: u32,
    clear: Vec4,
    pattern: SamplePattern,
    limits: &Limits,
    mut draw_pass: impl FnMut(&mut Framebuffer, Vec2),
) -> Result<Framebuffer, TextureError> {
    let offsets = pattern.offsets();
    let mut sum = Framebuffer::new(width, height, Vec4::ZERO, limits)?;
    for &offset in &offsets {
        let mut pass = Framebuffer::new(width, height, clear, limits)?;
        draw_pass(&mut pass, Vec2::splat(0.5) - offset);
        for (s, c) in sum.color.iter_mut().zip(&pass.color) {
            *s += *c;
        }
    }
    let inv = 1.0 / offsets.len() as f32;
    for s in &mut sum.color {
        *s *= inv;
    }
    Ok(sum)
}
