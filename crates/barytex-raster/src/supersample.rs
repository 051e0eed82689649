//! Supersampling by accumulation: the scene is drawn once per sample position, with the
//! viewport shifted by that position's sub-pixel offset, and the passes are averaged (shading per
//! sample: every effect is anti-aliased, not only edges). Regular N×N grids and stratified
//! jittered positions (regular and jittered supersampling: Buss, *3D Computer Graphics*, 2003,
//! Figure V.7; Cook 1986).

use barytex_texture::{Limits, TextureError};
use glam::{Vec2, Vec4};

use crate::samples::SamplePattern;
use crate::target::Framebuffer;

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
