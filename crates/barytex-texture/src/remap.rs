//! Image remapping: every output pixel bilinearly samples the source at its own coordinate
//! (OpenCV's `remap` with `INTER_LINEAR`), with exact float weights.

use glam::Vec2;

use crate::addressing::linear_taps;
use crate::{Rgba8, Texture2d, TextureError};

#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod bilinear_sse2;

/// Bilinear remap of an 8-bit linear RGBA image, clamp-to-edge: output pixel `i` is the source
/// sampled at `coords[i]` (texture coordinates: (0, 0) the top-left corner, (1, 1) the
/// bottom-right, texel centres at `(x + ½)/w`).
///
/// The blend runs in byte units with f32 weights (no per-texel division, no lookup tables),
/// and is rounded once per channel; on x86-64 an SSE2 kernel computes the same bytes, four
/// channels of a pixel per register; a non-finite coordinate gives transparent black. Colours are
/// blended as stored, which is exact for opaque images (translucent images: premultiply first or
/// use [`TextureSampler`](crate::TextureSampler), which filters premultiplied).
///
/// # Errors
/// [`TextureError::DataLength`] when `out` and `coords` differ in length.
///
/// # Accuracy
/// Within 0.5 + 2⁻¹⁴ of a step of the exact bilinear value of the exact coordinate
/// (`u·w − ½` computed in f64, weights rounded once to f32; the blend of values ≤ 255 adds at most
/// 3·255·2⁻²⁴ before rounding). Test: `tests/remap.rs::remap_matches_exact_bilinear`.
///
/// ```
/// use barytex_texture::{Rgba8, Texture2d, remap::remap_bilinear_rgba8};
/// use glam::Vec2;
/// let src = Texture2d::from_texels(2, 1, vec![Rgba8([0, 0, 0, 255]), Rgba8([255, 255, 255, 255])])?;
/// let mut out = vec![Rgba8::default(); 1];
/// remap_bilinear_rgba8(&src, &[Vec2::new(0.5, 0.5)], &mut out)?;
/// assert_eq!(out[0].0, [128, 128, 128, 255]); // 127.5 rounds up
/// # Ok::<(), barytex_texture::TextureError>(())
/// ```
pub fn remap_bilinear_rgba8(
    source: &Texture2d<Rgba8>,
    coords: &[Vec2],
    out: &mut [Rgba8],
) -> Result<(), TextureError> {
    if coords.len() != out.len() {
        return Err(TextureError::DataLength {
            expected: coords.len() as u64,
            actual: out.len() as u64,
        });
    }
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    if bilinear_sse2::applies(source) {
        bilinear_sse2::remap(source, coords, out);
        return Ok(());
    }
    remap_scalar(source, coords, out);
    Ok(())
}

/// The reference path (every size, every target): one pixel at a time through glam's `Vec4`.
/// The SSE2 kernel computes bit-identical results (same operations in the same order); the unit
/// tests of `bilinear_sse2` compare the two.
fn remap_scalar(source: &Texture2d<Rgba8>, coords: &[Vec2], out: &mut [Rgba8]) {
    let (w, h) = source.size();
    let texels = source.texels();
    let (max_x, max_y) = (i64::from(w) - 1, i64::from(h) - 1);
    let stride = w as usize;
    for (uv, o) in coords.iter().zip(out.iter_mut()) {
        if !uv.is_finite() {
            *o = Rgba8([0; 4]);
            continue;
        }
        let tx = linear_taps(uv.x, w);
        let ty = linear_taps(uv.y, h);
        // Clamp to edge on the integer indices (Vulkan's rule).
        let x0 = tx.i0.clamp(0, max_x) as usize;
        let x1 = tx.i0.saturating_add(1).clamp(0, max_x) as usize;
        let y0 = ty.i0.clamp(0, max_y) as usize;
        let y1 = ty.i0.saturating_add(1).clamp(0, max_y) as usize;
        let load = |i: usize| glam::Vec4::from_array(texels[i].0.map(f32::from));
        let c00 = load(y0 * stride + x0);
        let c10 = load(y0 * stride + x1);
        let c01 = load(y1 * stride + x0);
        let c11 = load(y1 * stride + x1);
        let top = c00 + (c10 - c00) * tx.frac;
        let bottom = c01 + (c11 - c01) * tx.frac;
        let v = top + (bottom - top) * ty.frac + glam::Vec4::splat(0.5);
        // v ∈ [0.5, 255.5 + tiny]: the saturating cast truncates, i.e. rounds half up.
        *o = Rgba8(v.to_array().map(|c| c as u8));
    }
}
