//! Adaptive supersampling (pixels "selectively supersampled up to a maximum of 40 times", as in
//! Figure IX.9 of Buss, *3D Computer Graphics*, 2003): every pixel gets a few samples, and only
//! pixels whose samples disagree (or, after the first round, whose mean stands out from a
//! neighbour's) get more, batch by batch, until their mean is known well enough or they reach the
//! maximum.
//!
//! Each batch is a set of passes over the whole scene with the viewport shifted by the sample
//! offset, as in [`render_supersampled`](crate::render_supersampled), but drawn through a write
//! mask: pixels that are done are neither rasterized into nor shaded. Sample positions follow
//! the 2D Sobol sequence, so the prefixes of 4, 8, 16 and 32 samples stratify the pixel.

use glam::{Vec2, Vec4};

use crate::error::{RasterError, TargetLimits, try_filled};
use crate::target::Framebuffer;

/// When a pixel is refined and how far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdaptiveOptions {
    /// Samples every pixel gets (at least 2: one sample has no spread).
    pub min_samples: u32,
    /// The most samples a pixel gets (40 in Buss's Figure IX.9).
    pub max_samples: u32,
    /// Samples added per refinement round.
    pub batch: u32,
    /// A pixel is refined while the standard error of its mean (the largest over the four
    /// premultiplied linear channels) exceeds this.
    pub threshold: f32,
    /// A pixel with fewer than [`neighbour_samples`](Self::neighbour_samples) samples whose
    /// mean differs from a 4-neighbour's by more than this (largest channel) is refined even if
    /// its own samples agree: an edge can cross a pixel between all of its first samples
    /// (Mitchell's neighbour test).
    pub contrast: f32,
    /// Up to how many samples the neighbour test applies.
    pub neighbour_samples: u32,
}

impl Default for AdaptiveOptions {
    /// 4 samples, up to 40 in batches of 4, standard error 1/512 (below an 8-bit step over
    /// most of the range), neighbour contrast 1/32 up to 16 samples.
    fn default() -> Self {
        Self {
            min_samples: 4,
            max_samples: 40,
            batch: 4,
            threshold: 1.0 / 512.0,
            contrast: 1.0 / 32.0,
            neighbour_samples: 16,
        }
    }
}

/// What the adaptive render took.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AdaptiveStats {
    /// Samples drawn, over all pixels.
    pub samples: u64,
    /// Passes over the scene (one per sample position).
    pub passes: u32,
    /// `histogram[n]`: pixels that ended with `n` samples.
    pub histogram: Vec<u64>,
}

impl AdaptiveStats {
    /// Mean samples per pixel.
    ///
    /// ```
    /// use barytex_raster::AdaptiveStats;
    ///
    /// // Three pixels stopped at 2 samples, one went on to 4.
    /// let stats = AdaptiveStats { samples: 10, passes: 4, histogram: vec![0, 0, 3, 0, 1] };
    /// assert_eq!(stats.mean_samples(), 2.5);
    /// assert_eq!((stats.pixels_at(2), stats.pixels_at(4), stats.pixels_at(40)), (3, 1, 0));
    /// assert_eq!(AdaptiveStats::default().mean_samples(), 0.0);
    /// ```
    #[must_use]
    pub fn mean_samples(&self) -> f64 {
        let pixels: u64 = self.histogram.iter().sum();
        self.samples as f64 / pixels.max(1) as f64
    }

    /// Pixels that ended with `samples` samples (0 beyond the histogram).
    #[must_use]
    pub fn pixels_at(&self, samples: u32) -> u64 {
        self.histogram.get(samples as usize).copied().unwrap_or(0)
    }
}

/// Sample `k` of the 2D Sobol sequence in [0, 1)², shifted by (⅛, ⅛) modulo 1: every prefix
/// of 2ᵐ samples is a (0, m, 2)-net — one sample in each of the 2ᵐ equal-area dyadic boxes of
/// every shape — so 4, 8, 16, 32 samples stratify a pixel as well as a grid does, and better on
/// edges at any angle (the first four form the rotated grid of 4× MSAA).
fn sobol(k: u32) -> Vec2 {
    let x = k.reverse_bits();
    let (mut y, mut v, mut i) = (0_u32, 1_u32 << 31, k);
    while i != 0 {
        if i & 1 != 0 {
            y ^= v;
        }
        i >>= 1;
        v ^= v >> 1;
    }
    let unit = |b: u32| (f64::from(b) / 4_294_967_296.0 + 0.125).fract() as f32;
    Vec2::new(unit(x), unit(y))
}

/// Renders with adaptive supersampling: `draw_pass(target, shift)` draws the scene into the
/// cleared `target` with the viewport moved by `shift` pixels, as for
/// [`render_supersampled`](crate::render_supersampled); the target carries a write mask, which
/// [`draw`](crate::draw) honours.
///
/// Besides two single-sample targets (each checked against `limits`) it keeps 39 bytes per
/// pixel of running sums and flags (the sides padded to multiples of [`TILE`](crate::TILE)),
/// each buffer smaller than a target and allocated fallibly.
///
/// ```
/// use barytex_raster::{
///     AdaptiveOptions, Fragment, PipelineState, Shader, TargetLimits, Viewport, draw,
///     render_adaptive,
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
/// // A triangle with a slanted edge across a 16 × 16 target.
/// let tri = [Vec3::new(-1.0, -1.0, 0.5), Vec3::new(1.0, -1.0, 0.5), Vec3::new(-1.0, 0.9, 0.5)];
/// let options = AdaptiveOptions::default();
/// let (fb, stats) = render_adaptive(16, 16, Vec4::new(0.0, 0.0, 0.0, 1.0), &options,
///     &TargetLimits::default(), |target, shift| {
///         let mut viewport = Viewport::full(16, 16);
///         viewport.x += shift.x;
///         viewport.y += shift.y;
///         let state = PipelineState { viewport: Some(viewport), ..PipelineState::default() };
///         draw(target, &White, &state, &tri, &[0, 1, 2]);
///     })?;
/// // Far from the edge four samples agree; on it pixels get more, up to the maximum.
/// assert_eq!(fb.pixel(0, 15), Some(Vec4::ONE));
/// assert_eq!(fb.pixel(15, 0), Some(Vec4::new(0.0, 0.0, 0.0, 1.0)));
/// assert!(stats.pixels_at(options.min_samples) > 0);
/// assert!(stats.pixels_at(options.max_samples) > 0);
/// assert!(stats.mean_samples() > 4.0 && stats.mean_samples() < 40.0);
/// assert_eq!(stats.histogram.iter().sum::<u64>(), 16 * 16);
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
///
/// # Errors
/// [`RasterError::InvalidParameter`] for options out of range (`min_samples < 2`,
/// `max_samples < min_samples`, `max_samples > 4096`, `batch = 0`, a negative or NaN threshold
/// or contrast), checked before anything is allocated; the errors of [`Framebuffer::new`] for
/// the targets; [`RasterError::OutOfMemory`] for the running sums.
pub fn render_adaptive(
    width: u32,
    height: u32,
    clear: Vec4,
    options: &AdaptiveOptions,
    limits: &TargetLimits,
    mut draw_pass: impl FnMut(&mut Framebuffer, Vec2),
) -> Result<(Framebuffer, AdaptiveStats), RasterError> {
    let o = *options;
    if o.min_samples < 2
        || o.max_samples < o.min_samples
        || o.max_samples > 4096
        || o.batch == 0
        || o.threshold.is_nan()
        || o.threshold < 0.0
        || o.contrast.is_nan()
        || o.contrast < 0.0
    {
        return Err(RasterError::InvalidParameter {
            what: "adaptive options",
            reason: "need 2 ≤ min_samples ≤ max_samples ≤ 4096, batch ≥ 1, threshold and contrast ≥ 0",
        });
    }
    let mut pass = Framebuffer::new(width, height, clear, limits)?;
    let mut result = Framebuffer::new(width, height, clear, limits)?;
    // Per pixel (tile layout, padding included and never active): running sums.
    let n = result.color.len();
    let mut sum = try_filled(n, Vec4::ZERO)?;
    let mut sum_sq = try_filled(n, Vec4::ZERO)?;
    let mut count = try_filled(n, 0_u32)?;
    pass.set_mask(Some(&|_, _| true))?;
    // The pixels still refined (padding never), a copy taken before each update, and the mask
    // handed to the passes: allocated once.
    let mut active = pass.mask.take().unwrap_or_default();
    let mut before = try_filled(n, false)?;
    let mut mask = try_filled(n, false)?;
    let mut stats = AdaptiveStats::default();
    let mut k = 0;
    while k < o.max_samples && active.contains(&true) {
        let round = if k == 0 { o.min_samples } else { o.batch };
        for _ in 0..round.min(o.max_samples - k) {
            pass.clear(clear);
            mask.copy_from_slice(&active);
            pass.mask = Some(mask);
            draw_pass(&mut pass, Vec2::splat(0.5) - sobol(k));
            // Take the mask back (or a new one, should the pass have replaced it).
            mask = match pass.mask.take() {
                Some(m) if m.len() == n => m,
                _ => try_filled(n, false)?,
            };
            if k == 0 {
                result.depth.copy_from_slice(&pass.depth);
            }
            for i in 0..n {
                if active[i] {
                    let c = pass.color[i];
                    sum[i] += c;
                    sum_sq[i] += c * c;
                    count[i] += 1;
                    stats.samples += 1;
                }
            }
            stats.passes += 1;
            k += 1;
        }
        before.copy_from_slice(&active);
        for y in 0..height {
            for x in 0..width {
                let i = result.pixel_index(x, y);
                if !before[i] {
                    continue;
                }
                let m = count[i] as f32;
                let mean = sum[i] / m;
                let variance = (sum_sq[i] / m - mean * mean).max(Vec4::ZERO) * (m / (m - 1.0));
                let mut refine = (variance / m).max_element().sqrt() > o.threshold;
                if !refine && count[i] < o.neighbour_samples {
                    let neighbours = [
                        (x > 0).then(|| (x - 1, y)),
                        (x + 1 < width).then(|| (x + 1, y)),
                        (y > 0).then(|| (x, y - 1)),
                        (y + 1 < height).then(|| (x, y + 1)),
                    ];
                    refine = neighbours.into_iter().flatten().any(|(nx, ny)| {
                        let j = result.pixel_index(nx, ny);
                        let other = sum[j] / count[j].max(1) as f32;
                        (other - mean).abs().max_element() > o.contrast
                    });
                }
                active[i] = refine && count[i] < o.max_samples;
            }
        }
    }
    pass.mask = None;
    stats.histogram = vec![0; o.max_samples as usize + 1];
    for y in 0..height {
        for x in 0..width {
            let i = result.pixel_index(x, y);
            stats.histogram[count[i] as usize] += 1;
            result.color[i] = sum[i] / count[i].max(1) as f32;
        }
    }
    Ok((result, stats))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sobol_prefixes_are_nets() {
        // 16 samples: one in each cell of every 2^a × 2^b dyadic grid with a + b = 4.
        for a in 0..=4 {
            let (nx, ny) = (1 << a, 1 << (4 - a));
            let mut seen = [false; 16];
            for k in 0..16 {
                // Undo the shift: the net property holds for the unshifted points.
                let p = sobol(k) - Vec2::splat(0.125);
                let p = Vec2::new(p.x.rem_euclid(1.0), p.y.rem_euclid(1.0));
                let cell = (p.y * ny as f32) as usize * nx + (p.x * nx as f32) as usize;
                assert!(!seen[cell], "a = {a}, k = {k}");
                seen[cell] = true;
            }
        }
    }
}
