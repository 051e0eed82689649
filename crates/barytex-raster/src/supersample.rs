//! Supersampling by accumulation: the scene is drawn once per sample position, with the
//! viewport shifted by that position's sub-pixel offset, and the passes are averaged (shading per
//! sample: every effect is anti-aliased, not only edges). Regular N×N grids and stratified
//! jittered positions (regular and jittered supersampling: Buss, *3D Computer Graphics*, 2003,
//! Figure V.7; Cook 1986).

use glam::{Vec2, Vec4};

use crate::error::{RasterError, TargetLimits};
use crate::samples::SamplePattern;
use crate::target::Framebuffer;

/// Renders `draw_pass` once per sample of `pattern` and averages the passes.
///
/// `draw_pass(target, shift)` must draw the scene into the cleared `target` with its viewport
/// moved by `shift` pixels (a sample at offset `o` from the pixel corner is the centre of the
/// pixel when the image moves by `(½, ½) − o`); the result is the per-pixel mean of the passes,
/// in linear light on premultiplied colour. Two single-sample targets are alive at a time (the
/// sum and the pass), each checked against `limits`. The pattern is not validated: any grid up to
/// [`MAX_GRID`](crate::MAX_GRID) × [`MAX_GRID`](crate::MAX_GRID) passes works
/// ([`SamplePattern::offsets`]).
///
/// ```
/// use barytex_raster::{
///     Fragment, PipelineState, SamplePattern, Shader, TargetLimits, Viewport, draw,
///     render_supersampled,
/// };
/// use glam::{Vec3, Vec4};
///
/// struct White;
/// impl Shader for White {
///     type Vertex = Vec3;
///     type Varying = f32;
///     fn vertex(&self, v: &Vec3) -> (Vec4, f32) { (v.extend(1.0), 0.0) }
///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> { Some(Vec4::ONE) }
/// }
/// // The left half of a 4 × 4 target up to x = 2.5 (NDC x = 0.25): pixel column 2 is half covered.
/// let quad = [
///     Vec3::new(-1.0, -1.0, 0.5), Vec3::new(0.25, -1.0, 0.5),
///     Vec3::new(0.25, 1.0, 0.5), Vec3::new(-1.0, 1.0, 0.5),
/// ];
/// let fb = render_supersampled(4, 4, Vec4::new(0.0, 0.0, 0.0, 1.0), SamplePattern::Regular { n: 4 },
///     &TargetLimits::default(), |target, shift| {
///         let mut viewport = Viewport::full(4, 4);
///         viewport.x += shift.x;
///         viewport.y += shift.y;
///         let state = PipelineState { viewport: Some(viewport), ..PipelineState::default() };
///         draw(target, &White, &state, &quad, &[0, 1, 2, 0, 2, 3]);
///     })?;
/// assert_eq!(fb.pixel(1, 1), Some(Vec4::ONE));
/// assert_eq!(fb.pixel(2, 1), Some(Vec4::new(0.5, 0.5, 0.5, 1.0)));
/// assert_eq!(fb.pixel(3, 1), Some(Vec4::new(0.0, 0.0, 0.0, 1.0)));
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
///
/// # Errors
/// The errors of [`Framebuffer::new`] for the targets under `limits`.
pub fn render_supersampled(
    width: u32,
    height: u32,
    clear: Vec4,
    pattern: SamplePattern,
    limits: &TargetLimits,
    mut draw_pass: impl FnMut(&mut Framebuffer, Vec2),
) -> Result<Framebuffer, RasterError> {
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
