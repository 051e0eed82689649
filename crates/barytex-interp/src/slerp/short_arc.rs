//! The f32 SLERP's fast path: arcs of at most 90° with `t` in `[0, 1]` (every short-path
//! quaternion interpolation, and vectors less than a right angle apart), by three short
//! polynomials in f64 — no division, square root or transcendental call.
//!
//! With `x = a·b = cos θ ≥ 0` and `y = x − 1 ∈ [−1, 0]`, SLERP is `f(1 − t)·a + f(t)·b` where
//! `f(s) = sin(sθ)/sin θ`, and exactly
//!
//! `f(s) = s · sinc(sθ) / sinc(θ)`, `sinc(x) = sin(x)/x`.
//!
//! `θ²` and `θ/sin θ` are analytic functions of `y` on `[−1, 0]` (their nearest singularity is
//! `y = −2`, θ = π), so each is a polynomial in `y` of degree 10 to a few 1e-9; `sinc(sθ)` is a
//! polynomial of degree 4 in `z = s²θ²` (an entire even series). `θ²` and `θ/sin θ` share `y` and
//! run side by side in the two lanes of one register, and so do the two weights' `sinc`: about
//! 45 two-lane operations for both weights, by Estrin's scheme (the weights are on the critical
//! path of a call). This replaced Eberly's 16-factor series (Eberly, "A Fast and Accurate
//! Algorithm for Computing SLERP", JGT 2011; [`super::eberly`]): about 100 multiplies and as many
//! additions for the same two weights, with 3.1e-8 error.
//!
//! The coefficients are least-squares fits at Chebyshev nodes (`tools/fit_slerp_weight.py`,
//! which prints them), the constant terms fixed so that the weights are exactly `1 − t` and `t`
//! at θ = 0. The whole weight errs by at most 8.0e-9 over `(s, y) ∈ [0, 1] × [−1, 0]` (the
//! script's dense grid), below the f32 rounding of the result, so the path meets the exact
//! SLERP's bounds; the tests measure it together with the trigonometric path.

use glam::Vec4;

use super::pair::F64x2;
use super::unit_vector::{NEAR_UNIT, Ops, cosine_minus_one};

/// `θ²` as a polynomial in `y = cos θ − 1`, `θ ∈ [0, π/2]` (`tools/fit_slerp_weight.py`, absolute
/// error 7.7e-10).
const THETA2: [f64; 11] = [
    0.0,
    -1.9999999105653241,
    0.3333375031721363,
    -0.08882157100485966,
    0.029106811941336422,
    -0.007734641077574496,
    0.01053882351626329,
    0.010014272737815992,
    0.012870776185484812,
    0.00719978930862897,
    0.0022051240854918984,
];

/// `θ/sin θ` as a polynomial in `y = cos θ − 1`, `θ ∈ [0, π/2]` (`tools/fit_slerp_weight.py`,
/// relative error 2.3e-9).
const THETA_OVER_SIN: [f64; 11] = [
    1.0,
    -0.3333330686599538,
    0.1333460072151863,
    -0.056933599955866006,
    0.027092762303164767,
    -0.0037440557729563513,
    0.027130346392452938,
    0.03546486579316968,
    0.041702323598020556,
    0.02414507846918408,
    0.0071241035931409735,
];

/// `sin(r)/r` as a polynomial in `z = r²`, `r ∈ [0, π/2]` (`tools/fit_slerp_weight.py`, relative
/// error 6.3e-9).
const SINC: [f64; 5] = [
    1.0,
    -0.16666659352132845,
    0.008333062203729022,
    -0.00019809352237702268,
    2.605294329885933e-06,
];

/// The two weights `(sin((1 − t)θ)/sin θ, sin(tθ)/sin θ)` for `t ∈ [0, 1]` and
/// `y = cos θ − 1 ∈ [−1, 0]`, in the lanes `(lo, hi)`, each multiplied by its lane of `scale`
/// (alongside the polynomials, off their critical path).
#[inline(always)]
fn weights(t: f64, y: f64, scale: F64x2) -> F64x2 {
    // θ² and θ/sin θ side by side, one lane each, by Estrin's scheme: depth 4 instead of
    // Horner's 10 (with Horner a call measured 20 % slower: the weights are on the critical path
    // of a SLERP, after the dot product).
    let c = |i: usize| F64x2::new(THETA2[i], THETA_OVER_SIN[i]);
    let y1 = F64x2::splat(y);
    let y2 = y1.mul(y1);
    let y4 = y2.mul(y2);
    let y8 = y4.mul(y4);
    let p01 = c(0).add(c(1).mul(y1));
    let p23 = c(2).add(c(3).mul(y1));
    let p45 = c(4).add(c(5).mul(y1));
    let p67 = c(6).add(c(7).mul(y1));
    let p89 = c(8).add(c(9).mul(y1));
    let p03 = p01.add(p23.mul(y2));
    let p47 = p45.add(p67.mul(y2));
    let p8a = p89.add(c(10).mul(y2));
    let p = p03.add(p47.mul(y4)).add(p8a.mul(y8));
    let (theta2, theta_over_sin) = (F64x2::splat(p.lo()), F64x2::splat(p.hi()));
    // sinc(sθ) for both weights, one lane each, by Estrin's scheme; `s·θ/sin θ` alongside.
    let s = F64x2::new(1.0 - t, t);
    let z = s.mul(s).mul(theta2);
    let z2 = z.mul(z);
    let k = |i: usize| F64x2::splat(SINC[i]);
    let low = k(0).add(k(1).mul(z));
    let high = k(2).add(k(3).mul(z)).add(k(4).mul(z2));
    low.add(z2.mul(high)).mul(s.mul(theta_over_sin).mul(scale))
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
    let w = weights(t, y, F64x2::new(ra, rb));
    a.scale(w.lo()).add(b.scale(w.hi()))
}

/// The f32 quaternion SLERP's common case, or `None` outside it: `t` strictly inside `(0, 1)`,
/// `a ≠ b`, both within 2⁻²⁰ of unit squared length (so finite and nonzero), and `a·b ≥ 0` (the
/// short path, after its sign flip). It is the arithmetic of the general f32 path
/// (`try_slerp_f32` → `slerp_directions` → [`slerp_short_arc`]) with the checks reordered so
/// that one test decides the common case, and the 4-vectors kept as two two-lane halves: the dot
/// products are summed as `(x² + z²) + (y² + w²)` rather than left to right, which moves `y` and
/// the inverse lengths by an f64 rounding at most.
#[inline(always)]
pub(crate) fn slerp_quat_short_arc(a: Vec4, b: Vec4, t: f32) -> Option<Vec4> {
    if !(t > 0.0 && t < 1.0) || a == b {
        return None;
    }
    let ((a01, a23), (b01, b23)) = (F64x2::widen(a), F64x2::widen(b));
    let aa = a01.mul(a01).add(a23.mul(a23));
    let bb = b01.mul(b01).add(b23.mul(b23));
    let ab = a01.mul(b01).add(a23.mul(b23));
    // (a·a, b·b) in one register.
    let lengths = aa.los(bb).add(aa.his(bb));
    let d = lengths.sub(F64x2::splat(1.0));
    let ab = ab.lo() + ab.hi();
    // `is_near_unit`, both lanes at once.
    if !(d.both_within(NEAR_UNIT) && ab >= 0.0) {
        return None;
    }
    // `inverse_length_near` of both lengths at once.
    let inverse_lengths =
        F64x2::splat(1.0).sub(d.mul(F64x2::splat(0.5).sub(F64x2::splat(0.375).mul(d))));
    // `â·b̂ − 1` by the series in the lengths (not `ab·ra·rb − 1`, four instructions fewer but
    // two multiplies longer on the critical path: measured slower).
    let y = cosine_minus_one(ab, lengths.lo(), lengths.hi());
    let w = weights(f64::from(t), y, inverse_lengths);
    let (wa, wb) = (F64x2::splat(w.lo()), F64x2::splat(w.hi()));
    Some(F64x2::narrow(
        a01.mul(wa).add(b01.mul(wb)),
        a23.mul(wa).add(b23.mul(wb)),
    ))
}
