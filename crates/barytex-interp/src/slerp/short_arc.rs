//! The f32 SLERP's fast path: arcs of at most 90° with `t` in `[0, 1]` (every short-path
//! quaternion interpolation, and vectors less than a right angle apart), by Eberly's series with
//! 16 factors in f64, evaluated for latency rather than with Horner's serial chain.
//!
//! With `x = a·b = cos θ ≥ 0` and `y = x − 1`, SLERP is `f(1 − t)·a + f(t)·b` where
//! `f(s) = s·(1 + h₁ + h₁h₂ + … + h₁⋯h₁₆)`, `hᵢ = (uᵢ s² − vᵢ)·y` (see [`super::eberly`]). The
//! 16 factors fall into 4 blocks of 4; each block's partial prefix sum and product take two
//! multiplies in depth, and the blocks combine by a 3-step Horner scheme — about 60 cycles of
//! dependency instead of Horner's ~110, and no division, square root or transcendental call.
//! With the error-balanced last factor the coefficient error is 3.1e-8 (`tools/fit_eberly_mu.py`,
//! n = 16), below the f32 rounding of the result, so the path meets the exact SLERP's bounds; the
//! tests measure it together with the trigonometric path.

use super::unit_vector::Ops;

/// Eberly's `(uᵢ, vᵢ)`, `i = 1 ..= 16`, the last pair scaled by `1 + μ₁₆`.
const UV: [(f64, f64); 16] = coefficients();

const fn coefficients() -> [(f64, f64); 16] {
    const ONE_PLUS_MU_16: f64 = 1.916_667_572_156_612;
    let mut table = [(0.0, 0.0); 16];
    let mut i = 1;
    while i <= 16 {
        let denominator = (2 * i + 1) as f64;
        let mut u = 1.0 / (i as f64 * denominator);
        let mut v = i as f64 / denominator;
        if i == 16 {
            u *= ONE_PLUS_MU_16;
            v *= ONE_PLUS_MU_16;
        }
        table[i - 1] = (u, v);
        i += 1;
    }
    table
}

/// `sin(sθ)/sin θ` for `s ∈ [0, 1]` and `y = cos θ − 1 ∈ [−1, 0]`.
#[inline]
fn weight(s: f64, y: f64) -> f64 {
    let s2 = s * s;
    let h: [f64; 16] = core::array::from_fn(|i| (UV[i].0 * s2 - UV[i].1) * y);
    // Per block of four: S = h₁ + h₁h₂ + h₁h₂h₃ + h₁h₂h₃h₄ and Q = h₁h₂h₃h₄.
    let block = |k: usize| {
        let [h1, h2, h3, h4] = [h[4 * k], h[4 * k + 1], h[4 * k + 2], h[4 * k + 3]];
        let p2 = h1 * h2;
        let p3 = p2 * h3;
        let p4 = p2 * (h3 * h4);
        ((h1 + p2) + (p3 + p4), p4)
    };
    let (s0, q0) = block(0);
    let (s1, q1) = block(1);
    let (s2b, q2) = block(2);
    let (s3, _) = block(3);
    let tail = s1 + q1 * (s2b + q2 * s3);
    s * ((1.0 + s0) + q0 * tail)
}

/// SLERP of the directions `a·ra` and `b·rb` (`ra`, `rb` the inverse lengths of `a`, `b`;
/// `y = (a·ra)·(b·rb) − 1 ∈ [−1, 0]`, at most 90° apart) at `t ∈ [0, 1]`. The inverse lengths are
/// folded into the two weights, so the inputs are never scaled as vectors.
#[inline]
pub(crate) fn slerp_short_arc<W: Ops<Scalar = f64>>(
    a: W,
    b: W,
    y: f64,
    (ra, rb): (f64, f64),
    t: f64,
) -> W {
    a.scale(weight(1.0 - t, y) * ra)
        .add(b.scale(weight(t, y) * rb))
}
