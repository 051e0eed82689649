//! Separable windowed-sinc reductions (Kaiser, Lanczos-3) for any size, in two passes.

use glam::Vec4;

use super::{Plane, Source};
use crate::TextureError;

/// The window of the sinc.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Window {
    /// Kaiser window, α = 4, radius 3.
    Kaiser,
    /// Lanczos window `sinc(x/3)`, radius 3.
    Lanczos3,
}

const RADIUS: f64 = 3.0;

fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-12 {
        1.0
    } else {
        let px = core::f64::consts::PI * x;
        px.sin() / px
    }
}

/// The zeroth-order modified Bessel function of the first kind (power series).
fn bessel_i0(x: f64) -> f64 {
    let mut sum = 1.0;
    let mut term = 1.0;
    let q = x * x / 4.0;
    for k in 1..40 {
        term *= q / f64::from(k * k);
        sum += term;
        if term < sum * 1e-17 {
            break;
        }
    }
    sum
}

impl Window {
    /// The windowed sinc at `x` (in output texels).
    fn kernel(self, x: f64) -> f64 {
        if x.abs() >= RADIUS {
            return 0.0;
        }
        match self {
            Self::Lanczos3 => sinc(x) * sinc(x / RADIUS),
            Self::Kaiser => {
                const ALPHA: f64 = 4.0;
                let r = x / RADIUS;
                sinc(x) * bessel_i0(ALPHA * (1.0 - r * r).sqrt()) / bessel_i0(ALPHA)
            }
        }
    }
}

/// For each of `m` outputs, the source taps (clamped to the edge) and normalised weights.
fn axis_weights(n: u32, m: u32, window: Window) -> Vec<Vec<(u32, f32)>> {
    let scale = f64::from(n) / f64::from(m);
    (0..m)
        .map(|i| {
            let centre = (f64::from(i) + 0.5) * scale;
            let lo = (centre - RADIUS * scale).floor() as i64;
            let hi = (centre + RADIUS * scale).ceil() as i64;
            let mut taps: Vec<(u32, f64)> = Vec::new();
            for j in lo..=hi {
                let weight = window.kernel((j as f64 + 0.5 - centre) / scale);
                if weight == 0.0 {
                    continue;
                }
                // Clamp to the edge: fold the weight onto the border texel.
                let index = j.clamp(0, i64::from(n) - 1) as u32;
                match taps.last_mut() {
                    Some((last, w)) if *last == index => *w += weight,
                    _ => taps.push((index, weight)),
                }
            }
            let sum: f64 = taps.iter().map(|(_, w)| w).sum();
            taps.into_iter()
                .map(|(j, w)| (j, (w / sum) as f32))
                .collect()
        })
        .collect()
}

/// One reduction to `(⌊w/2⌋, ⌊h/2⌋)` (at least 1) with the windowed sinc.
pub(crate) fn reduce(source: &impl Source, window: Window) -> Result<Plane, TextureError> {
    let (w, h) = source.size();
    let (w2, h2) = ((w / 2).max(1), (h / 2).max(1));
    let xw = axis_weights(w, w2, window);
    let yw = axis_weights(h, h2, window);
    // Horizontal pass: w2 × h.
    let mut horizontal = Plane::with_capacity(w2, h)?;
    for y in 0..h {
        for taps in &xw {
            let sum = taps
                .iter()
                .fold(Vec4::ZERO, |acc, &(x, wt)| acc + source.get(x, y) * wt);
            horizontal.values.push(sum);
        }
    }
    // Vertical pass: w2 × h2.
    let mut out = Plane::with_capacity(w2, h2)?;
    for taps in &yw {
        for x in 0..w2 {
            let sum = taps
                .iter()
                .fold(Vec4::ZERO, |acc, &(y, wt)| acc + horizontal.get(x, y) * wt);
            out.values.push(sum);
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_are_normalised_and_symmetric() {
        for window in [Window::Kaiser, Window::Lanczos3] {
            for (n, m) in [(64, 32), (7, 3), (1, 1), (2, 1)] {
                for taps in axis_weights(n, m, window) {
                    let sum: f32 = taps.iter().map(|(_, w)| w).sum();
                    assert!((sum - 1.0).abs() < 1e-6, "{window:?} {n}->{m}: {sum}");
                }
            }
            // An interior output of an even reduction is symmetric about its centre.
            let taps = &axis_weights(64, 32, window)[16];
            let k = taps.len();
            for i in 0..k / 2 {
                assert!((taps[i].1 - taps[k - 1 - i].1).abs() < 1e-6);
            }
        }
    }
}
