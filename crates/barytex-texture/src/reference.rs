//! The supersampled reference sampler (the "512× supersampling" reference of L. Yan's GAMES101,
//! Lecture 9, as ground truth): N×N stratified jittered point samples over the pixel footprint.

use glam::{Vec2, Vec4};

use crate::{Sampler, TextureError};

/// How samples over the footprint are weighted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PixelFilter {
    /// Equal weights over the footprint parallelogram `uv + s·ddx + t·ddy`, `s, t ∈ [−½, ½]`.
    #[default]
    Box,
    /// Gaussian weights (σ = ½ pixel), over `s, t ∈ [−1, 1]`.
    Gaussian,
}

/// A point-sampling function averaged over each pixel's footprint with N×N stratified, jittered
/// samples (deterministic: the jitter is a hash of the stratum, so results repeat exactly).
///
/// ```
/// use barytex_texture::procedural::Checkerboard;
/// use barytex_texture::reference::{PixelFilter, SupersampledReference};
/// use barytex_texture::Sampler;
/// use glam::{Vec2, Vec4};
///
/// let checker = Checkerboard { even: Vec4::ONE, odd: Vec4::ZERO, checks: 8.0 };
/// let truth = SupersampledReference::new(move |uv| checker.at(uv), 32, PixelFilter::Box)?;
/// // A footprint covering whole checks averages to grey.
/// let grey = truth.sample(Vec2::splat(0.5), Vec2::new(0.25, 0.0), Vec2::new(0.0, 0.25));
/// assert!((grey.x - 0.5).abs() < 0.01);
/// # Ok::<(), barytex_texture::TextureError>(())
/// ```
#[derive(Clone, Debug)]
pub struct SupersampledReference<F> {
    function: F,
    n: u32,
    filter: PixelFilter,
}

/// The largest grid side (32² = 1024 samples per pixel).
pub const MAX_SIDE: u32 = 32;

fn jitter(i: u32, j: u32, k: u32) -> f32 {
    let mut z = (u64::from(i) << 32 | u64::from(j)).wrapping_add(u64::from(k) << 48);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^= z >> 31;
    (z >> 40) as f32 / (1u64 << 24) as f32
}

impl<F: Fn(Vec2) -> Vec4> SupersampledReference<F> {
    /// `n × n` samples per pixel, `n` from 1 to [`MAX_SIDE`].
    ///
    /// # Errors
    /// [`TextureError::InvalidParameter`] for `n` outside 1..=32.
    ///
    /// ```
    /// use barytex_texture::TextureError;
    /// use barytex_texture::reference::{PixelFilter, SupersampledReference};
    /// use glam::{Vec2, Vec4};
    ///
    /// let constant = |_: Vec2| Vec4::ONE;
    /// assert!(SupersampledReference::new(constant, 32, PixelFilter::Gaussian).is_ok());
    /// assert!(matches!(
    ///     SupersampledReference::new(constant, 33, PixelFilter::Box),
    ///     Err(TextureError::InvalidParameter { what: "n", .. })
    /// ));
    /// assert!(SupersampledReference::new(constant, 0, PixelFilter::Box).is_err());
    /// ```
    pub fn new(function: F, n: u32, filter: PixelFilter) -> Result<Self, TextureError> {
        if !(1..=MAX_SIDE).contains(&n) {
            return Err(TextureError::InvalidParameter {
                what: "n",
                reason: "the grid side must be 1 to 32",
            });
        }
        Ok(Self {
            function,
            n,
            filter,
        })
    }

    /// Samples per pixel (`n²`).
    ///
    /// ```
    /// use barytex_texture::reference::{PixelFilter, SupersampledReference};
    /// use glam::{Vec2, Vec4};
    ///
    /// let truth = SupersampledReference::new(|_: Vec2| Vec4::ONE, 16, PixelFilter::Box)?;
    /// assert_eq!(truth.samples_per_pixel(), 256);
    /// # Ok::<(), barytex_texture::TextureError>(())
    /// ```
    #[must_use]
    pub fn samples_per_pixel(&self) -> u32 {
        self.n * self.n
    }
}

impl<F: Fn(Vec2) -> Vec4> Sampler for SupersampledReference<F> {
    /// The weighted average of `n²` samples over the footprint; derivatives of zero give the
    /// point sample.
    fn sample(&self, uv: Vec2, ddx: Vec2, ddy: Vec2) -> Vec4 {
        let n = self.n as f32;
        let (extent, sigma2) = match self.filter {
            PixelFilter::Box => (0.5, f32::INFINITY),
            PixelFilter::Gaussian => (1.0, 0.25),
        };
        let mut sum = Vec4::ZERO;
        let mut weights = 0.0;
        for j in 0..self.n {
            for i in 0..self.n {
                let s = ((i as f32 + jitter(i, j, 0)) / n * 2.0 - 1.0) * extent;
                let t = ((j as f32 + jitter(i, j, 1)) / n * 2.0 - 1.0) * extent;
                let w = if sigma2.is_finite() {
                    (-(s * s + t * t) / (2.0 * sigma2)).exp()
                } else {
                    1.0
                };
                sum += (self.function)(uv + ddx * s + ddy * t) * w;
                weights += w;
            }
        }
        sum / weights
    }

    fn sample_level(&self, uv: Vec2, _lod: f32) -> Vec4 {
        (self.function)(uv)
    }
}
