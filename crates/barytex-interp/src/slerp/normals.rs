//! Interpolating normals for Phong shading (Phong 1975): lerp and renormalize, or SLERP.
//!
//! Renormalized lerp stays on the great-circle arc but does not move along it at constant speed:
//! at angle θ between the normals it reaches `atan2(t·sin θ, 1 − t + t·cos θ)` instead of `t·θ`
//! (it "does not produce even spacing", in Schaefer's shading lecture; Shoemake 1985 for the
//! constant-speed alternative). [`renormalize_spacing_error`] gives that error;
//! for the small angles between the vertex normals of a finely tessellated mesh it is tiny, for a
//! coarse mesh it is not.

use glam::Vec3;

use super::exact::slerp;

/// How [`interpolate_normal`] moves from one normal to the other.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NormalInterpolation {
    /// Lerp, then renormalize: cheap, uneven angular spacing (see [`renormalize_spacing_error`]).
    #[default]
    Renormalize,
    /// [`slerp`]: even spacing, exact ends, a few times the cost.
    Slerp,
}

/// The normal at fraction `t` between unit normals `n0` and `n1`.
///
/// # Special values
/// Zero or non-finite normals give the zero vector; with `Renormalize`, opposite normals at
/// `t = ½` give the zero vector too (their lerp vanishes), with `Slerp` the deterministic
/// perpendicular of [`slerp`]. Never NaN.
///
/// # Accuracy
/// `Slerp`: as [`slerp`]. `Renormalize`: angle to the evenly spaced normal within
/// [`renormalize_spacing_error`]`(θ)` plus 2.4e-7 (test `normal_spacing` in `tests/tests/interp/slerp.rs`).
///
/// ```
/// use barytex_interp::{interpolate_normal, NormalInterpolation};
/// use glam::Vec3;
///
/// let n = interpolate_normal(Vec3::X, Vec3::Y, 0.25, NormalInterpolation::Renormalize);
/// // 19.5° instead of 22.5°: the uneven spacing.
/// assert!((n.angle_between(Vec3::X).to_degrees() - 18.43).abs() < 0.01);
/// ```
#[must_use]
#[inline]
pub fn interpolate_normal(n0: Vec3, n1: Vec3, t: f32, method: NormalInterpolation) -> Vec3 {
    match method {
        NormalInterpolation::Renormalize => (n0 + (n1 - n0) * t).normalize_or_zero(),
        NormalInterpolation::Slerp => slerp(n0, n1, t),
    }
}

/// The largest angular error (radians) of renormalized lerp against even spacing, over `t` in
/// `[0, 1]`, for normals `theta` radians apart (`0 ≤ θ < π`); NaN for other `theta`.
///
/// By symmetry the error is largest at the `t` where `d/dt atan2(t sin θ, 1 − t + t cos θ) = θ`;
/// it is found by golden-section search in f64.
///
/// # Accuracy
/// Within 1e-12 rad of the true maximum (test `spacing_error_formula` in `tests/tests/interp/slerp.rs`
/// compares against a dense sampling).
///
/// ```
/// use barytex_interp::renormalize_spacing_error;
///
/// // Normals 90° apart: lerp + renormalize is up to 4.1° off even spacing.
/// assert!((renormalize_spacing_error(std::f64::consts::FRAC_PI_2).to_degrees() - 4.07).abs() < 0.01);
/// ```
#[must_use]
pub fn renormalize_spacing_error(theta: f64) -> f64 {
    if !(0.0..core::f64::consts::PI).contains(&theta) {
        return f64::NAN;
    }
    let (sin_theta, cos_theta) = crate::math::sin_cos(theta);
    let error = |t: f64| theta * t - crate::math::atan2(t * sin_theta, 1.0 - t + t * cos_theta);
    // The error is positive and unimodal on (0, ½] and antisymmetric about ½.
    let (mut lo, mut hi) = (0.0f64, 0.5f64);
    let golden = 0.618_033_988_749_894_9;
    for _ in 0..100 {
        let m1 = hi - golden * (hi - lo);
        let m2 = lo + golden * (hi - lo);
        if error(m1) < error(m2) {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    error(0.5 * (lo + hi))
}
