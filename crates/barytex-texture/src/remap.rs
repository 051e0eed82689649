//! Image remapping: every output pixel bilinearly samples the source at its own coordinate
//! (OpenCV's `remap` with `INTER_LINEAR`), with exact float weights.

use glam::Vec2;

use crate::addressing::linear_taps;
use crate::{Rgba8, Texture2d, TextureError};

#[cfg(target_arch = "x86_64")]
mod bilinear_avx2;
#[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
mod bilinear_sse2;

/// Bilinear remap of an 8-bit linear RGBA image, clamp-to-edge: output pixel `i` is the source
/// sampled at `coords[i]` (texture coordinates: (0, 0) the top-left corner, (1, 1) the
/// bottom-right, texel centres at `(x + ½)/w`).
///
/// The blend runs in byte units with f32 weights (no per-texel division, no lookup tables),
/// and is rounded once per channel; on x86-64 an AVX2 kernel (selected at run time where the CPU
/// has AVX2 and FMA: blocks of 64 pixels, addressed in one vectorized pass, then loaded and
/// blended two pixels per register) or else an SSE2 kernel (one pixel per register) computes the
/// same bytes; a non-finite coordinate gives transparent black. Colours are
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
    #[cfg(target_arch = "x86_64")]
    if bilinear_avx2::applies(source)
        && let Some(simd) = bilinear_avx2::token()
    {
        bilinear_avx2::remap(simd, source, coords, out);
        return Ok(());
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

/// Inputs shared by the kernels' bit-for-bit tests: random sources and coordinates inside, near
/// and far outside the texture, on texel centres and edges, and non-finite ones.
#[cfg(test)]
pub(crate) mod test_inputs {
    use glam::Vec2;

    use crate::{Rgba8, Texture2d};

    /// Deterministic pseudo-random numbers (xorshift), so a failure reproduces.
    fn next(state: &mut u64) -> u64 {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        *state
    }

    pub(crate) fn texture(w: u32, h: u32, seed: u64) -> Texture2d<Rgba8> {
        let mut s = seed;
        Texture2d::from_fn(w, h, |_, _| {
            let [r, g, b, a, ..] = next(&mut s).to_le_bytes();
            Rgba8([r, g, b, a])
        })
        .expect("small")
    }

    /// Coordinates inside, near and far outside the texture, on texel centres and edges, and
    /// non-finite ones.
    pub(crate) fn coords(w: u32, h: u32, seed: u64) -> Vec<Vec2> {
        let mut s = seed;
        let mut c = Vec::new();
        let specials = [
            0.0,
            -0.0,
            1.0,
            -1e-30,
            1e-30,
            0.5,
            -3.0,
            4.0,
            1e30,
            -1e30,
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::MIN_POSITIVE,
            f32::MAX,
            -f32::MAX,
            1e-45,
        ];
        for &a in &specials {
            for &b in &specials {
                c.push(Vec2::new(a, b));
            }
        }
        for _ in 0..20_000 {
            let r = next(&mut s);
            let unit = |bits: u64| (bits & 0xffff_ffff) as f32 / u32::MAX as f32;
            let u = unit(r) * 1.4 - 0.2;
            let v = unit(r >> 32) * 1.4 - 0.2;
            c.push(Vec2::new(u, v));
            // Exactly on texel centres and texel edges.
            let (i, j) = (
                (r % u64::from(w + 2)) as f32 - 1.0,
                ((r >> 20) % u64::from(h + 2)) as f32 - 1.0,
            );
            c.push(Vec2::new((i + 0.5) / w as f32, (j + 0.5) / h as f32));
            c.push(Vec2::new(i / w as f32, j / h as f32));
        }
        c
    }
}
