//! The Mitchell–Netravali family of cubic filter kernels (Mitchell & Netravali, "Reconstruction
//! Filters in Computer Graphics", SIGGRAPH 1988).

use crate::sampler::CubicKernel;

impl CubicKernel {
    /// The kernel's `(B, C)` parameters.
    #[must_use]
    pub const fn b_c(self) -> (f32, f32) {
        match self {
            Self::CatmullRom => (0.0, 0.5),
            Self::BSpline => (1.0, 0.0),
            Self::Mitchell => (1.0 / 3.0, 1.0 / 3.0),
        }
    }

    /// The kernel value at distance `x` (in texels); zero for `|x| ≥ 2` and for a NaN `x`.
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
