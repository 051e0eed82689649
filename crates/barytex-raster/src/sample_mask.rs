//! Per-sample masks (a one-bit stencil): which samples of a target a set of triangles covers and
//! passes the depth test at, decided exactly as [`draw`](crate::draw) decides them — the same
//! fixed-point edge functions, the same top-left rule, the same sample positions, the same depth
//! interpolation — and a copy of the masked samples from one target into another.
//!
//! Together they are what stencil-masked rendering needs (a renderer's portals and mirrors:
//! mask the portal's visible samples, draw another view into a second target, copy those samples
//! back) without a stencil test in the per-fragment loop: a draw that does not use a mask pays
//! nothing for it.

use glam::Vec4;

use crate::assemble::assemble;
use crate::draw::{DrawStats, writable_rect};
use crate::error::{RasterError, try_filled};
use crate::state::{PipelineState, Viewport};
use crate::target::Framebuffer;

const ONE: i64 = 1 << crate::edge::SUBPIXEL_BITS;

/// One coverage word per pixel of a target: bit `k` set where sample `k` is in the mask.
///
/// Made by [`mask_samples`]; read with [`pixel`](Self::pixel); used by
/// [`Framebuffer::copy_samples`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SampleMask {
    width: u32,
    height: u32,
    samples: u32,
    /// Per pixel, in the target's tile layout ([`Framebuffer`]'s `pixel_index`).
    bits: Vec<u32>,
    /// Indices into `bits` of pixels whose word has any bit, ascending (for copies that visit
    /// only the masked pixels).
    pixels: Vec<usize>,
    count: u64,
}

impl SampleMask {
    /// Width in pixels (the target's).
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels (the target's).
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Samples per pixel (the target's).
    #[must_use]
    pub fn samples(&self) -> u32 {
        self.samples
    }

    /// The samples of pixel (x, y) in the mask, bit `k` for sample `k`; 0 outside the target.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> u32 {
        if x >= self.width || y >= self.height {
            return 0;
        }
        self.bits[pixel_index(self.width, x, y)]
    }

    /// Samples in the mask, over all pixels.
    #[must_use]
    pub fn count(&self) -> u64 {
        self.count
    }

    /// Whether no sample is in the mask.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }
}

/// The tile-layout index of pixel (x, y) in a target `width` pixels wide (as
/// [`Framebuffer`]'s).
fn pixel_index(width: u32, x: u32, y: u32) -> usize {
    let tile = crate::TILE;
    let tiles_x = width.div_ceil(tile) as usize;
    let t = (y / tile) as usize * tiles_x + (x / tile) as usize;
    t * (tile * tile) as usize + (y % tile * tile + x % tile) as usize
}

/// The samples of `target` that the triangles `indices` over the clip-space `positions` cover
/// and where they pass `state`'s depth test against the target's depth — exactly the samples a
/// [`draw`](crate::draw) of those triangles with `state` would write (same clipping, culling,
/// viewport, scissor, coverage rule and sample positions; the target's write mask is honoured).
/// Nothing is written to the target.
///
/// Nothing panics on bad input: out-of-range indices, non-finite positions, zero-area and fully
/// clipped triangles are dropped and counted in the returned [`DrawStats`], as by `draw`
/// (no fragment is shaded, so the fragment counts stay 0).
///
/// ```
/// use barytex_raster::{Framebuffer, PipelineState, SamplePattern, TargetLimits, mask_samples};
/// use glam::Vec4;
///
/// // The left half of a 4 × 2 target with 4 samples per pixel, up to x = 1.5 pixels: pixel
/// // column 1 is half inside (the two samples of Vulkan's 4× pattern left of its centre).
/// let fb = Framebuffer::multisampled(4, 2, SamplePattern::Standard { count: 4 }, Vec4::ZERO,
///     &TargetLimits::default())?;
/// let quad = [
///     Vec4::new(-1.0, -1.0, 0.5, 1.0), Vec4::new(-0.25, -1.0, 0.5, 1.0),
///     Vec4::new(-0.25, 1.0, 0.5, 1.0), Vec4::new(-1.0, 1.0, 0.5, 1.0),
/// ];
/// let (mask, stats) = mask_samples(&fb, &PipelineState::default(), &quad, &[0, 1, 2, 0, 2, 3])?;
/// assert_eq!(mask.pixel(0, 1), 0b1111);
/// assert_eq!(mask.pixel(1, 0), 0b0101); // samples at x = 6/16 and 2/16 of the pixel
/// assert_eq!(mask.pixel(2, 0), 0);
/// assert_eq!(mask.count(), 2 * (4 + 2));
/// assert_eq!(stats.triangles_in, 2);
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
///
/// # Errors
/// [`RasterError::OutOfMemory`] when the mask (4 bytes per pixel of the padded target) cannot be
/// allocated.
pub fn mask_samples(
    target: &Framebuffer,
    state: &PipelineState,
    positions: &[Vec4],
    indices: &[u32],
) -> Result<(SampleMask, DrawStats), RasterError> {
    let mut stats = DrawStats::default();
    let samples = target.samples();
    let mut bits = try_filled(target.color.len() / samples as usize, 0_u32)?;
    let shaded: Vec<(Vec4, ())> = positions.iter().map(|&p| (p, ())).collect();
    let viewport = state
        .viewport
        .unwrap_or_else(|| Viewport::full(target.width(), target.height()));
    let pieces = assemble(&shaded, indices, state, viewport, &mut stats);
    let rect = writable_rect(target, state, viewport);
    let pattern = target.pattern();
    let write_mask = target.mask.as_deref();
    for piece in &pieces {
        let edge = &piece.edge;
        edge.for_each_block_pixel(rect, (0, ONE - 1), (0, 0), |x, y, e, all| {
            let pixel = target.pixel_index(x as u32, y as u32);
            if write_mask.is_some_and(|m| !m[pixel]) {
                return;
            }
            let mut word = 0_u32;
            for k in 0..samples {
                let (ox, oy) = pattern.fixed_offset(x, y, k);
                let d = edge.offset(ox, oy);
                let s: [i64; 3] = core::array::from_fn(|i| e[i] + d[i]);
                if !(all || edge.covers(s)) {
                    continue;
                }
                // The depth exactly as the draw loops compute it.
                let lambda = edge.lambda(s);
                let z = (0..3).map(|i| lambda[i] * piece.depth[i]).sum::<f64>() as f32;
                let stored = target.depth[pixel * samples as usize + k as usize];
                if state.depth_compare.is_none_or(|op| op.passes(z, stored)) {
                    word |= 1 << k;
                }
            }
            bits[pixel] |= word;
        });
    }
    let pixels: Vec<usize> = (0..bits.len()).filter(|&i| bits[i] != 0).collect();
    let count = pixels
        .iter()
        .map(|&i| u64::from(bits[i].count_ones()))
        .sum();
    Ok((
        SampleMask {
            width: target.width(),
            height: target.height(),
            samples,
            bits,
            pixels,
            count,
        },
        stats,
    ))
}

impl Framebuffer {
    /// Copies the colour of the samples in `mask` from `from` (depth stays): the composite of a
    /// stencil-masked pass drawn into a second target.
    ///
    /// ```
    /// use barytex_raster::{Framebuffer, PipelineState, TargetLimits, mask_samples};
    /// use glam::Vec4;
    ///
    /// let limits = TargetLimits::default();
    /// let mut fb = Framebuffer::new(4, 4, Vec4::ZERO, &limits)?;
    /// let other = Framebuffer::new(4, 4, Vec4::ONE, &limits)?;
    /// // The upper-left triangle of the screen: the 6 pixels with x + y < 3.
    /// let tri = [Vec4::new(-1.0, 1.0, 0.5, 1.0), Vec4::new(-1.0, -1.0, 0.5, 1.0),
    ///     Vec4::new(1.0, 1.0, 0.5, 1.0)];
    /// let (mask, _) = mask_samples(&fb, &PipelineState::default(), &tri, &[0, 1, 2])?;
    /// fb.copy_samples(&other, &mask)?;
    /// assert_eq!(fb.pixel(0, 0), Some(Vec4::ONE));
    /// assert_eq!(fb.pixel(3, 3), Some(Vec4::ZERO));
    /// assert_eq!(mask.count(), 6);
    /// # Ok::<(), barytex_raster::RasterError>(())
    /// ```
    ///
    /// # Errors
    /// [`RasterError::InvalidParameter`] when `from` or `mask` differ from this target in size
    /// or samples per pixel, or `from` in sample pattern; nothing is copied then.
    pub fn copy_samples(&mut self, from: &Self, mask: &SampleMask) -> Result<(), RasterError> {
        let same_target = from.width() == self.width()
            && from.height() == self.height()
            && from.pattern() == self.pattern();
        let same_mask = mask.width == self.width()
            && mask.height == self.height()
            && mask.samples == self.samples();
        if !(same_target && same_mask) {
            return Err(RasterError::InvalidParameter {
                what: "copy_samples",
                reason: "the targets and the mask must have the same size and samples",
            });
        }
        let s = self.samples() as usize;
        for &pixel in &mask.pixels {
            let mut word = mask.bits[pixel];
            while word != 0 {
                let k = word.trailing_zeros() as usize;
                word &= word - 1;
                let i = pixel * s + k;
                self.color[i] = from.color[i];
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{SamplePattern, TargetLimits};

    #[test]
    fn pixel_indices_match_the_targets() {
        let fb = Framebuffer::new(130, 70, Vec4::ZERO, &TargetLimits::default()).expect("small");
        for (x, y) in [(0, 0), (63, 0), (64, 0), (129, 69), (5, 66)] {
            assert_eq!(pixel_index(130, x, y), fb.pixel_index(x, y), "({x}, {y})");
        }
    }

    #[test]
    fn mismatched_copies_are_refused() {
        let limits = TargetLimits::default();
        let mut a = Framebuffer::new(4, 4, Vec4::ZERO, &limits).expect("small");
        let b = Framebuffer::new(4, 5, Vec4::ONE, &limits).expect("small");
        let msaa = Framebuffer::multisampled(
            4,
            4,
            SamplePattern::Standard { count: 4 },
            Vec4::ONE,
            &limits,
        )
        .expect("small");
        let (mask, _) = mask_samples(&a, &PipelineState::default(), &[], &[]).expect("small");
        assert!(mask.is_empty());
        assert!(a.copy_samples(&b, &mask).is_err());
        assert!(a.copy_samples(&msaa, &mask).is_err());
        let (msaa_mask, _) =
            mask_samples(&msaa, &PipelineState::default(), &[], &[]).expect("small");
        assert!(a.copy_samples(&a.clone(), &msaa_mask).is_err());
        assert!(a.copy_samples(&a.clone(), &mask).is_ok());
    }
}
