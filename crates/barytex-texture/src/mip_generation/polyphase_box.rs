//! The box reduction for any size: 2 taps per axis for an even side, the 3-tap polyphase box
//! for an odd side (each output texel integrates exactly `w/⌊w/2⌋` source texels), a copy for a
//! side of 1.

use glam::{DVec4, Vec4};

use super::{Plane, Source};
use crate::TextureError;

/// The source taps and weights of output index `i` along an axis of `n` source texels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AxisTaps {
    pub(crate) first: u32,
    pub(crate) weights: [f64; 3],
    pub(crate) count: usize,
}

pub(crate) fn axis_taps(i: u32, n: u32) -> AxisTaps {
    if n <= 1 {
        AxisTaps {
            first: 0,
            weights: [1.0, 0.0, 0.0],
            count: 1,
        }
    } else if n.is_multiple_of(2) {
        AxisTaps {
            first: 2 * i,
            weights: [0.5, 0.5, 0.0],
            count: 2,
        }
    } else {
        // n = 2m + 1: output i covers source [i·n/m, (i + 1)·n/m); in units of 1/n of the
        // output footprint the three texels contribute m − i, m and i + 1.
        let m = n / 2;
        let nf = f64::from(n);
        AxisTaps {
            first: 2 * i,
            weights: [
                f64::from(m - i) / nf,
                f64::from(m) / nf,
                f64::from(i + 1) / nf,
            ],
            count: 3,
        }
    }
}

/// One box reduction of `source`.
pub(crate) fn reduce(source: &impl Source) -> Result<Plane, TextureError> {
    let (w, h) = source.size();
    let (w2, h2) = ((w / 2).max(1), (h / 2).max(1));
    let mut out = Plane::with_capacity(w2, h2)?;
    if w.is_multiple_of(2) && h.is_multiple_of(2) {
        // The common case: two rows at a time, pairs summed, no per-texel tap bookkeeping.
        let (mut buffer0, mut buffer1) = (Vec::new(), Vec::new());
        for y in 0..h2 {
            let row0 = source.row(2 * y, &mut buffer0);
            let row1 = source.row(2 * y + 1, &mut buffer1);
            out.values.extend(
                row0.chunks_exact(2)
                    .zip(row1.chunks_exact(2))
                    .map(|(a, b)| ((a[0] + a[1]) + (b[0] + b[1])) * 0.25),
            );
        }
        return Ok(out);
    }
    let x_taps: Vec<AxisTaps> = (0..w2).map(|x| axis_taps(x, w)).collect();
    for y in 0..h2 {
        let ty = axis_taps(y, h);
        for tx in &x_taps {
            out.values
                .push(weighted_sum(tx, &ty, |x, y| source.get(x, y)));
        }
    }
    Ok(out)
}

/// `Σ_b w_b · Σ_a w_a · texel(x_a, y_b)` over the taps of both axes, in f64 and rounded once:
/// with f32 weights and sums, the weights' rounding (their sum is not exactly 1) and the sums'
/// moved a constant float texel by up to 3 ulp at each odd reduction (an 11×11 level of
/// 0.74211603 became 0.7421162 two levels down); in f64 a constant comes back exactly (the
/// result is within 2⁻⁵⁰ of it, far inside half an f32 ulp).
#[inline]
pub(crate) fn weighted_sum(tx: &AxisTaps, ty: &AxisTaps, texel: impl Fn(u32, u32) -> Vec4) -> Vec4 {
    let mut sum = DVec4::ZERO;
    for b in 0..ty.count {
        let sy = ty.first + b as u32;
        let mut row = DVec4::ZERO;
        for a in 0..tx.count {
            row += texel(tx.first + a as u32, sy).as_dvec4() * tx.weights[a];
        }
        sum += row * ty.weights[b];
    }
    sum.as_vec4()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_source_texel_gets_the_same_total_weight() {
        for n in 1..40 {
            let m = (n / 2).max(1);
            let mut total = vec![0.0_f64; n as usize];
            for i in 0..m {
                let t = axis_taps(i, n);
                for a in 0..t.count {
                    total[(t.first as usize) + a] += t.weights[a];
                }
            }
            // Each source texel contributes m/n of an output texel (1 for n = 1).
            let want = f64::from(m) / f64::from(n);
            for (j, got) in total.iter().enumerate() {
                assert!((got - want).abs() < 1e-6, "n={n} j={j}: {got} vs {want}");
            }
        }
    }
}
