//! The Mitchell–Netravali family of cubic filter kernels (Mitchell & Netravali, "Reconstruction
//! Filters in Computer Graphics", SIGGRAPH 1988).

use crate::sampler::CubicKernel;

impl CubicKernel {
    /// The kernel's `(B, C)` parameters.
    ///
    /// ```
    /// use barytex_texture::sampler::CubicKernel;
    ///
    /// assert_eq!(CubicKernel::CatmullRom.b_c(), (0.0, 0.5));
    /// assert_eq!(CubicKernel::BSpline.b_c(), (1.0, 0.0));
    /// // Mitchell–Netravali's recommended kernel lies on the line B + 2C = 1.
    /// let (b, c) = CubicKernel::Mitchell.b_c();
    /// assert!((b + 2.0 * c - 1.0).abs() < 1e-6);
    /// ```
    #[must_use]
    pub const fn b_c(self) -> (f32, f32) {
        match self {
            Self::CatmullRom => (0.0, 0.5),
            Self::BSpline => (1.0, 0.0),
            Self::Mitchell => (1.0 / 3.0, 1.0 / 3.0),
        }
    }

    /// The kernel value at distance `x` (in texels); zero for `|x| ≥ 2` and for a NaN `x`.
    ///
    /// ```
    /// use barytex_texture::sampler::CubicKernel;
    ///
    /// // Catmull–Rom interpolates: 1 at the centre, 0 at the other integers.
    /// let k = CubicKernel::CatmullRom;
    /// assert_eq!((k.weight(0.0), k.weight(1.0), k.weight(-1.0), k.weight(2.5)), (1.0, 0.0, 0.0, 0.0));
    /// // The B-spline does not: 2/3 at the centre, 1/6 at ±1.
    /// let b = CubicKernel::BSpline;
    /// assert!((b.weight(0.0) - 2.0 / 3.0).abs() < 1e-6 && (b.weight(1.0) - 1.0 / 6.0).abs() < 1e-6);
    /// assert_eq!(k.weight(f32::NAN), 0.0);
    /// ```
    #[must_use]
    pub fn weight(self, x: f32) -> f32 {
        let (b, c) = self.b_c();
        let x = x.abs();
        if x < 1.0 {
            ((12.0 - 9.0 * b - 6.0 * c) * x * x * x
                + (-18.0 + 12.0 * b + 6.0 * c) * x * x
                + (6.0 - 2.0 * b))
                / 6.0
        } else if x < 2.0 {
            ((-b - 6.0 * c) * x * x * x
                + (6.0 * b + 30.0 * c) * x * x
                + (-12.0 * b - 48.0 * c) * x
                + (8.0 * b + 24.0 * c))
                / 6.0
        } else {
            0.0
        }
    }

    /// The four tap weights for a sample at fraction `t ∈ [0, 1)` past tap 1 (taps at −1, 0, 1, 2),
    /// normalised to sum to 1. A `t` outside `[0, 1]` is clamped into it and NaN is read as 0, so
    /// the weights always sum to 1 (they were all NaN for a NaN or infinite `t`, and a far-off
    /// `t` divided by a zero sum).
    ///
    /// ```
    /// use barytex_texture::sampler::CubicKernel;
    ///
    /// // At t = 0 Catmull–Rom puts all weight on tap 1 (the sample's own texel).
    /// assert_eq!(CubicKernel::CatmullRom.taps(0.0), [0.0, 1.0, 0.0, 0.0]);
    /// // Halfway, the weights are symmetric and sum to 1; the outer ones are negative.
    /// let w = CubicKernel::CatmullRom.taps(0.5);
    /// assert_eq!((w[0], w[1]), (w[3], w[2]));
    /// assert!(w[0] < 0.0 && (w.iter().sum::<f32>() - 1.0).abs() < 1e-6);
    /// assert_eq!(CubicKernel::Mitchell.taps(f32::NAN), CubicKernel::Mitchell.taps(0.0));
    /// ```
    #[must_use]
    pub fn taps(self, t: f32) -> [f32; 4] {
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let w = [
            self.weight(t + 1.0),
            self.weight(t),
            self.weight(1.0 - t),
            self.weight(2.0 - t),
        ];
        let sum: f32 = w.iter().sum();
        // The family is a partition of unity; dividing removes the rounding of the polynomials.
        w.map(|x| x / sum)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kernels_are_partitions_of_unity_and_interpolate_where_they_should() {
        for kernel in [
            CubicKernel::CatmullRom,
            CubicKernel::BSpline,
            CubicKernel::Mitchell,
        ] {
            for i in 0..=64 {
                let t = i as f32 / 64.0;
                let raw = [
                    kernel.weight(t + 1.0),
                    kernel.weight(t),
                    kernel.weight(1.0 - t),
                    kernel.weight(2.0 - t),
                ];
                let sum: f32 = raw.iter().sum();
                assert!((sum - 1.0).abs() < 1e-6, "{kernel:?} t={t}: {sum}");
            }
        }
        // Catmull-Rom interpolates: weight 1 at 0, 0 at ±1, ±2.
        let cr = CubicKernel::CatmullRom;
        assert_eq!(cr.weight(0.0), 1.0);
        assert_eq!(cr.weight(1.0), 0.0);
        assert_eq!(cr.taps(0.0), [0.0, 1.0, 0.0, 0.0]);
        // The B-spline is non-negative everywhere (no overshoot); Catmull-Rom has negative lobes.
        assert!((0..200).all(|i| CubicKernel::BSpline.weight(i as f32 / 50.0) >= 0.0));
        assert!(cr.weight(1.5) < 0.0);
    }
}
