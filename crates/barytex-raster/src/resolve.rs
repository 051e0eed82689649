//! Reading a target out row by row: the straight-alpha mean of each pixel's samples, as
//! [`Framebuffer::pixel`] gives it, for every pixel of an image row at once.
//!
//! In the tile-major buffers an image row is one contiguous run of samples per tile it
//! crosses ([`TILE`] pixels, or fewer in the last tile), so a row is resolved from a few
//! slices instead of through the tile layout's index arithmetic and bounds check per pixel.
//! The arithmetic per pixel is [`Framebuffer::pixel`]'s, in the same order, so the values are
//! the same bits (tested against it below, on every sample count, on targets that are not
//! multiples of a tile, with NaN, infinite, negative and zero-alpha samples).

use glam::Vec4;

use crate::format::ColorFormat;
use crate::target::{Framebuffer, TILE};

impl<C: ColorFormat> Framebuffer<C> {
    /// Image row `y` (below the height) resolved: `out[x] = f(self.pixel(x, y))` for every `x`
    /// below the width (`out` is one row long).
    #[inline]
    pub(crate) fn resolve_row<T>(&self, y: u32, out: &mut [T], f: impl Fn(Vec4) -> T) {
        debug_assert!(y < self.height() && out.len() == self.width() as usize);
        let s = self.samples() as usize;
        let tile = TILE as usize;
        // The first sample of row y in the first tile of its tile row.
        let row_start =
            ((y / TILE) as usize * self.tiles_x() as usize * tile + (y % TILE) as usize) * tile * s;
        for (k, pixels) in out.chunks_mut(tile).enumerate() {
            let start = row_start + k * tile * tile * s;
            let samples = &self.color[start..start + pixels.len() * s];
            if s == 1 {
                for (out, &c) in pixels.iter_mut().zip(samples) {
                    // `resolved`'s sum over one sample (`Sum` starts from zero) and its mean.
                    *out = f(unpremultiply_lanes((Vec4::ZERO + C::load(c)) / 1.0));
                }
            } else {
                for (out, pixel) in pixels.iter_mut().zip(samples.chunks_exact(s)) {
                    let sum: Vec4 = pixel.iter().map(|&c| C::load(c)).sum();
                    *out = f(unpremultiply_lanes(sum / s as f32));
                }
            }
        }
    }
}

/// `target::unpremultiply` with the three divisions in one register: each lane divides as the
/// scalar code does (IEEE division is exact to the rounding), so the same bits.
#[inline(always)]
fn unpremultiply_lanes(c: Vec4) -> Vec4 {
    if c.w > 0.0 {
        let rgb = (c / c.w).truncate();
        if rgb.is_finite() {
            return rgb.extend(c.w);
        }
    }
    Vec4::new(0.0, 0.0, 0.0, c.w.max(0.0))
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::TargetLimits;
    use crate::format::Rgba8Unorm;
    use crate::samples::SamplePattern;

    fn assert_rows_are_the_pixels<C: ColorFormat>(fb: &Framebuffer<C>) {
        let mut row = vec![Vec4::ZERO; fb.width() as usize];
        for y in 0..fb.height() {
            fb.resolve_row(y, &mut row, |c| c);
            for (x, got) in row.iter().enumerate() {
                let want = fb.pixel(x as u32, y).expect("inside");
                assert_eq!(
                    got.to_array().map(f32::to_bits),
                    want.to_array().map(f32::to_bits),
                    "pixel ({x}, {y}): {got} against {want}"
                );
            }
        }
    }

    /// Ordinary values and the hard ones: NaN, ±∞, ±0, negative, subnormal, above 1.
    fn component() -> impl Strategy<Value = f32> {
        prop_oneof![
            6 => 0.0_f32..=1.0,
            1 => prop::sample::select(vec![
                f32::NAN,
                f32::INFINITY,
                f32::NEG_INFINITY,
                -0.0,
                0.0,
                -1.0,
                1.0,
                1e-39,
                3.5,
            ]),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Every sample count, sizes around the tile's side, samples of every kind (stored
        /// premultiplied or not, so alphas of exactly 1 and others).
        #[test]
        fn rows_are_the_pixels_bit_for_bit(
            w in 1_u32..150,
            h in 1_u32..4,
            pattern in prop::sample::select(vec![
                SamplePattern::CENTRE,
                SamplePattern::Standard { count: 2 },
                SamplePattern::Standard { count: 4 },
                SamplePattern::Jittered { n: 3, seed: 5 },
            ]),
            values in prop::collection::vec(prop::array::uniform4(component()), 64),
        ) {
            let mut fb = Framebuffer::multisampled(w, h, pattern, Vec4::ZERO, &TargetLimits::default())
                .expect("small");
            for (i, c) in fb.color.iter_mut().enumerate() {
                *c = Vec4::from_array(values[i * 7 % values.len()]);
            }
            assert_rows_are_the_pixels(&fb);
        }
    }

    #[test]
    fn rows_of_a_four_byte_target_are_its_pixels() {
        let clear = Vec4::new(0.2, 0.7, 1.0, 0.5);
        let limits = TargetLimits::default();
        let fb =
            Framebuffer::<Rgba8Unorm>::with_format(70, 5, SamplePattern::CENTRE, clear, &limits)
                .expect("small");
        assert_rows_are_the_pixels(&fb);
    }
}
