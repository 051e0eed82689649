//! The equirectangular (latitude–longitude) map: longitude along `u`, polar angle along `v`.

use core::f32::consts::{FRAC_1_PI, PI, TAU};

use glam::{Vec2, Vec3};

use crate::UvJacobian;

/// `u` and `v` of the direction `d` (any finite nonzero length), with `ρ = hypot(x, z)`:
/// `u = ½ + atan2(x, −z)/(2π)`, `v = atan2(ρ, y)/π`.
///
/// Axes (y up, right-handed, looking down `−z`): the image centre `(½, ½)` is `−z`, `u = ¾` is
/// `+x`, `u = ¼` is `−x`, the seam `u = 0 ≡ 1` is `+z`; `v = 0` (the top row) is `+y` and
/// `v = 1` is `−y`. At the poles (`x = z = 0`) `u` is undefined and returned as `½`.
///
/// `None` for a zero or non-finite `dir`; otherwise `u ∈ [0, 1]`, `v ∈ [0, 1]`.
///
/// # Accuracy
/// [`equirect_direction`] of the result is within [`EQUIRECT_ROUND_TRIP_BOUND`] radians of
/// `dir` (`environment.rs::equirect_round_trips`).
///
/// ```
/// use barytex_uv::environment::equirect_uv;
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(equirect_uv(Vec3::NEG_Z), Some(Vec2::new(0.5, 0.5)));
/// assert_eq!(equirect_uv(Vec3::Y), Some(Vec2::new(0.5, 0.0)));
/// assert_eq!(equirect_uv(Vec3::X), Some(Vec2::new(0.75, 0.5)));
/// assert_eq!(equirect_uv(Vec3::ZERO), None);
/// ```
#[must_use]
pub fn equirect_uv(dir: Vec3) -> Option<Vec2> {
    if !dir.is_finite() || dir == Vec3::ZERO {
        return None;
    }
    // Scaled to a largest component of 1: subnormal directions would lose their precision in
    // hypot. hypot and atan2 avoid the cancellation of acos near the poles.
    let dir = dir / dir.abs().max_element();
    let rho = dir.x.hypot(dir.z);
    let u = if rho == 0.0 {
        0.5
    } else {
        0.5 + dir.x.atan2(-dir.z) / TAU
    };
    let v = rho.atan2(dir.y) * FRAC_1_PI;
    Some(Vec2::new(u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)))
}

/// The unit direction at `uv`, the inverse of [`equirect_uv`]: with `φ = 2π(u − ½)` and
/// `θ = πv`, `(sin θ sin φ, cos θ, −sin θ cos φ)`.
///
/// Any finite `uv` works (`u` is periodic; `v` outside `[0, 1]` runs over the pole). `None` for
/// a non-finite `uv`.
///
/// # Accuracy
/// Unit length within `4e-7`; `equirect_uv` of the result gives back `uv` within
/// `2e-6` for `uv` in `[0, 1]²` away from the seam and the poles
/// (`environment.rs::equirect_uv_round_trips`).
///
/// ```
/// use barytex_uv::environment::equirect_direction;
/// use glam::{Vec2, Vec3};
///
/// let d = equirect_direction(Vec2::new(0.75, 0.5)).expect("finite");
/// assert!((d - Vec3::X).length() < 1e-6);
/// ```
#[must_use]
pub fn equirect_direction(uv: Vec2) -> Option<Vec3> {
    if !uv.is_finite() {
        return None;
    }
    // Reduce u (period 1) and v (period 2) before scaling, so that huge finite uv neither
    // overflow nor lose their fraction.
    let phi = TAU * (uv.x - uv.x.floor() - 0.5);
    let theta = PI * (uv.y - 2.0 * (0.5 * uv.y).floor());
    let (sin_p, cos_p) = phi.sin_cos();
    let (sin_t, cos_t) = theta.sin_cos();
    let d = Vec3::new(sin_t * sin_p, cos_t, -sin_t * cos_p);
    d.is_finite().then_some(d)
}

/// Angle (radians) within which `equirect_direction(equirect_uv(d))` returns a unit direction
/// `d` (`environment.rs::equirect_round_trips`).
pub const EQUIRECT_ROUND_TRIP_BOUND: f32 = 1.0e-6;

/// [`equirect_uv`] with the gradients of `u` and `v` with respect to the direction:
/// `∇u = (−z, 0, x)/(2πρ²)`, `∇v = (xy/ρ, −ρ, zy/ρ)/(π|d|²)`. Both are orthogonal to `dir`.
///
/// `None` where `equirect_uv` is `None`, at the poles (`ρ = 0`, where `∇u` is infinite) and
/// where a gradient overflows (directions within about `1e-19·|d|` of a pole, or shorter than
/// about `1e-19`).
///
/// # Accuracy
/// Relative to the largest gradient entry, within `1e-5` of the exact gradient
/// (`environment.rs::equirect_jacobian_matches_finite_differences`).
///
/// ```
/// use barytex_uv::environment::equirect_uv_and_jacobian;
/// use glam::{Vec2, Vec3};
/// use core::f32::consts::PI;
///
/// let j = equirect_uv_and_jacobian(Vec3::NEG_Z).expect("not a pole");
/// assert_eq!(j.uv, Vec2::splat(0.5));
/// assert!((j.du - Vec3::X / (2.0 * PI)).length() < 1e-7);
/// assert!((j.dv - Vec3::NEG_Y / PI).length() < 1e-7);
/// ```
#[must_use]
pub fn equirect_uv_and_jacobian(dir: Vec3) -> Option<UvJacobian> {
    let uv = equirect_uv(dir)?;
    // Degree-0 homogeneous: work with the direction scaled to a largest component of 1 so that
    // the squares stay finite, and scale the gradients back.
    let m = dir.abs().max_element();
    let d = dir / m;
    let rho2 = d.x * d.x + d.z * d.z;
    let rho = rho2.sqrt();
    let len2 = rho2 + d.y * d.y;
    let du = Vec3::new(-d.z, 0.0, d.x) / (TAU * rho2) / m;
    let dv = Vec3::new(d.x * d.y / rho, -rho, d.z * d.y / rho) / (PI * len2) / m;
    (rho > 0.0 && du.is_finite() && dv.is_finite()).then_some(UvJacobian { uv, du, dv })
}
