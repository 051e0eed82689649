//! Normalized lerp of quaternions and Kapoulkine's corrections of its speed: the cheap members
//! of the SLERP family.
//!
//! nlerp follows the same great-circle arc as SLERP but not at constant speed: at 4D angle θ it
//! reaches angle `atan2(t·sin θ, 1 − t + t·cos θ)` instead of `t·θ`. Kapoulkine ("Approximating
//! slerp", 2015) reparametrizes `t` by a cubic whose coefficients are fitted polynomials in
//! `d = a·b`, which removes most of that error for the cost of a few multiply-adds.

use glam::{Quat, Vec4};

/// `b` on the short path from `a` (negated when `a·b < 0`) and `d = a·b ≥ 0` after that.
#[inline]
pub(crate) fn short_path(a: Vec4, b: Vec4) -> (Vec4, f32) {
    let d = a.dot(b);
    if d < 0.0 { (-b, -d) } else { (b, d) }
}

/// nlerp of `a` and `b` (the latter already on the short path) at parameter `t`; zero for
/// non-finite input.
#[inline]
fn normalized_lerp(a: Vec4, b: Vec4, t: f32) -> Quat {
    Quat::from_vec4((a + (b - a) * t).normalize_or_zero())
}

/// Normalized linear interpolation of unit quaternions on the short path: the fastest member of
/// the family, on the SLERP arc but not at constant speed.
///
/// Unlike nalgebra's `nlerp`, `b` is negated when `a·b < 0`, so the rotation takes the short way.
///
/// # Special values
/// Unit inputs are assumed (not checked); a non-finite input gives the zero quaternion. Never NaN.
///
/// # Accuracy
/// 4D angle to the exact SLERP within [`QuatInterpolation::Nlerp`](super::QuatInterpolation::Nlerp)'s
/// [`angle_bound`](super::QuatInterpolation::angle_bound) (7.1e-2 rad: the speed error at
/// θ = 90°, `t = ¼`), length within 2.4e-7 of 1 (test `approximation_bounds` in `tests/tests/interp/slerp.rs`).
///
/// ```
/// use barytex_interp::nlerp_quat;
/// use glam::Quat;
///
/// let q = nlerp_quat(Quat::IDENTITY, Quat::from_rotation_y(0.2), 0.5);
/// assert!(q.angle_between(Quat::from_rotation_y(0.1)) < 1e-6);
/// ```
#[must_use]
#[inline]
pub fn nlerp_quat(a: Quat, b: Quat, t: f32) -> Quat {
    let a = Vec4::from(a);
    let (b, _) = short_path(a, Vec4::from(b));
    normalized_lerp(a, b, t)
}

/// Which of Kapoulkine's two fits of the corrected `t` [`nlerp_corrected_quat`] uses.
///
/// ```
/// use barytex_interp::{nlerp_corrected_quat, slerp, NlerpCorrection, QuatInterpolation};
/// use glam::Quat;
///
/// let (a, b) = (Quat::IDENTITY, Quat::from_rotation_x(2.0));
/// let exact = slerp(a, b, 0.3);
/// // glam's `angle_between` is the rotation angle, twice the 4D angle of the bounds.
/// let fast = nlerp_corrected_quat(a, b, 0.3, NlerpCorrection::Fast).angle_between(exact);
/// assert!(fast <= 2.0 * QuatInterpolation::NlerpCorrectedFast.angle_bound());
/// let precise = nlerp_corrected_quat(a, b, 0.3, NlerpCorrection::Precise).angle_between(exact);
/// assert!(precise <= 2.0 * QuatInterpolation::NlerpCorrected.angle_bound());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NlerpCorrection {
    /// `k(d)` quadratic: `t' = t + t(t − ½)(t − 1)·k(d)`; the 4D angle to the exact SLERP is
    /// within the bound of
    /// [`QuatInterpolation::NlerpCorrectedFast`](super::QuatInterpolation::NlerpCorrectedFast).
    Fast,
    /// `k(t, d) = A(d)·(t − ½)² + B(d)` with `A` cubic and `B` quadratic in `d`; within
    /// [`QuatInterpolation::NlerpCorrected`](super::QuatInterpolation::NlerpCorrected)'s bound.
    Precise,
}

/// Kapoulkine's reparametrized `t` as a cubic in `d = a·b ∈ [0, 1]` whose coefficients depend
/// on `t` only: `t' = c₀ + c₁·d + c₂·d² + c₃·d³`, the coefficients in `x`, `y`, `z`, `w`.
///
/// `t' = t + s·k(t, d)` with `s = t(t − ½)(t − 1)`, and `k` is a polynomial in `d` (quadratic for
/// [`NlerpCorrection::Fast`]; `A(d)·(t − ½)² + B(d)` with `A` cubic and `B` quadratic for
/// [`NlerpCorrection::Precise`]), so `s·k` regroups by powers of `d`: `s·(A·(t − ½)² + B) + t`
/// with `A` and `B` the fits' coefficient vectors, four lanes at once. The coefficients need only
/// `t`, so they are computed while `a·b` is; what remains after the dot product is Estrin's
/// two-level evaluation ([`cubic_in_d`]), three dependent operations instead of the eight of
/// Horner's rule on `k` followed by `t + s·k`. At `t = 0` and `t = 1`, `s = 0` and the cubic is
/// exactly `t`.
#[inline]
pub(crate) fn corrected_t_coefficients(t: f32, correction: NlerpCorrection) -> Vec4 {
    let c = t - 0.5;
    let s = t * c * (t - 1.0);
    let t_first = Vec4::new(t, 0.0, 0.0, 0.0);
    match correction {
        NlerpCorrection::Fast => FAST_FIT * s + t_first,
        NlerpCorrection::Precise => (PRECISE_FIT_A * (c * c) + PRECISE_FIT_B) * s + t_first,
    }
}

/// Kapoulkine's quadratic `k(d)`, lowest power first.
const FAST_FIT: Vec4 = Vec4::new(0.931_872, -1.256_54, 0.331_442, 0.0);
/// `A(d)` of Kapoulkine's `t`-dependent fit, lowest power first.
const PRECISE_FIT_A: Vec4 = Vec4::new(1.0904, -3.2452, 3.556_45, -1.435_19);
/// `B(d)` of Kapoulkine's `t`-dependent fit, lowest power first.
const PRECISE_FIT_B: Vec4 = Vec4::new(0.848_013, -1.060_21, 0.215_638, 0.0);

/// The fit's `A` and `B` coefficient vectors, lowest power of `d` first (`A = 0` for the fast
/// fit, whose `k` does not depend on `t`).
#[inline]
pub(crate) fn fit(correction: NlerpCorrection) -> ([f32; 4], [f32; 4]) {
    match correction {
        NlerpCorrection::Fast => ([0.0; 4], FAST_FIT.to_array()),
        NlerpCorrection::Precise => (PRECISE_FIT_A.to_array(), PRECISE_FIT_B.to_array()),
    }
}

/// `c₀ + c₁·d + c₂·d² + c₃·d³` by Estrin's scheme: `(c₀ + c₁·d) + d²·(c₂ + c₃·d)`.
#[inline]
pub(crate) fn cubic_in_d(c: Vec4, d: f32) -> f32 {
    (c.x + c.y * d) + (d * d) * (c.z + c.w * d)
}

/// nlerp with Kapoulkine's corrected parameter: nearly constant speed for a few more
/// multiply-adds.
///
/// [`NlerpCorrection::Fast`] uses his quadratic fit `k(d)`, [`NlerpCorrection::Precise`] the fit
/// that also depends on `t`. Both are fitted for `t` in `[0, 1]`; outside it the result still
/// lies on the arc, with a larger speed error.
///
/// # Special values
/// Unit inputs are assumed (not checked); a non-finite input gives the zero quaternion. Never NaN.
///
/// # Accuracy
/// 4D angle to the exact SLERP within the `angle_bound` of
/// [`QuatInterpolation::NlerpCorrectedFast`](super::QuatInterpolation::NlerpCorrectedFast) or
/// [`QuatInterpolation::NlerpCorrected`](super::QuatInterpolation::NlerpCorrected) (5.4e-3 rad
/// fast, 5.0e-4 precise) for `t` in `[0, 1]`, length within 2.4e-7 of 1 (test
/// `approximation_bounds` in `tests/tests/interp/slerp.rs`).
///
/// ```
/// use barytex_interp::{nlerp_corrected_quat, slerp, NlerpCorrection};
/// use glam::Quat;
///
/// let (a, b) = (Quat::IDENTITY, Quat::from_rotation_x(2.0));
/// let exact = slerp(a, b, 0.3);
/// let q = nlerp_corrected_quat(a, b, 0.3, NlerpCorrection::Precise);
/// assert!(q.angle_between(exact) < 2e-4);
/// ```
#[must_use]
#[inline]
pub fn nlerp_corrected_quat(a: Quat, b: Quat, t: f32, correction: NlerpCorrection) -> Quat {
    let a = Vec4::from(a);
    // Independent of the inputs' dot product: computed while it is.
    let coefficients = corrected_t_coefficients(t, correction);
    let (b, d) = short_path(a, Vec4::from(b));
    normalized_lerp(a, b, cubic_in_d(coefficients, d))
}
