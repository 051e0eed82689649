//! The OpenGL sphere map (`GL_SPHERE_MAP`): the picture of a mirrored ball seen from far away
//! along `+z`.

use glam::{Vec2, Vec3};

use super::reflect::unit;
use crate::UvJacobian;

/// `(s, t)` of the reflection direction `r` (normalized first; any finite nonzero length), the
/// OpenGL formula: `m = 2·sqrt(rx² + ry² + (rz + 1)²)`, `s = rx/m + ½`, `t = ry/m + ½`.
///
/// Axes: the viewer looks down `−z` at the ball, so `r = +z` (straight back at the viewer) is the
/// centre `(½, ½)`, `+x` is towards `s = 1`, and `+y` towards `t = 1`. The coordinates are GL's
/// `(s, t)` unchanged: with this crate's v-down images, `+y` is towards the **bottom** row
/// (flip `t` to `1 − t` for an image stored top row first with `+y` up).
///
/// Singular direction: `r = (0, 0, −1)` (directly away from the viewer) is the whole rim of the
/// disk, `m = 0`; it gives `None`, as do zero and non-finite `r`. Every other direction lands
/// inside the disk `|(s, t) − (½, ½)| ≤ ½`.
///
/// # Accuracy
/// `(s, t)` within `4e-7` of the exact value: `1 + rz` is computed as `(rx² + ry²)/(1 − rz)`
/// when `rz < 0`, so there is no cancellation near the singular direction. The round trip
/// through [`sphere_map_direction`] is within `SPHERE_MAP_ROUND_TRIP_BOUND / cos(α/2)` radians
/// of `r`, `α` the angle of `r` from `+z` (`cos(α/2) = sqrt((1 + rz)/2)`): a direction `δ` from
/// `−z` lies `≈ δ/4` from the rim, where the f32 resolution of `(s, t)` is spread over an angle
/// `4/δ` times larger (`environment.rs::sphere_map_round_trips`).
///
/// ```
/// use barytex_uv::environment::sphere_map_uv;
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(sphere_map_uv(Vec3::Z), Some(Vec2::splat(0.5)));
/// // Sideways reflections land on the circle of radius ½/√2.
/// let st = sphere_map_uv(Vec3::X).expect("not singular");
/// assert!((st - Vec2::new(0.5 + 0.5 / 2f32.sqrt(), 0.5)).length() < 1e-6);
/// assert_eq!(sphere_map_uv(Vec3::NEG_Z), None);
/// ```
#[must_use]
pub fn sphere_map_uv(r: Vec3) -> Option<Vec2> {
    let r = unit(r)?;
    let p = Vec2::new(r.x, r.y) / (2.0 * half_m(r)?);
    // |p| ≤ ½ exactly, but rounding can push a point a few ulps past the rim: pull it back.
    let len2 = p.length_squared();
    let p = if len2 > 0.25 {
        p * (0.5 / len2.sqrt())
    } else {
        p
    };
    let st = p + 0.5;
    st.is_finite().then_some(st)
}

/// `m/2 = sqrt(2(1 + rz))` for a unit `r`, free of cancellation and underflow: for `rz < 0`,
/// `1 + rz = ρ²/(1 − rz)` with `ρ = hypot(rx, ry)`, so `m/2 = ρ·sqrt(2/(1 − rz))`. `None` at
/// `−z` (`ρ = 0` there).
fn half_m(r: Vec3) -> Option<f32> {
    let h = if r.z >= 0.0 {
        (2.0 * (1.0 + r.z)).sqrt()
    } else {
        r.x.hypot(r.y) * (2.0 / (1.0 - r.z)).sqrt()
    };
    (h > 0.0).then_some(h)
}

/// The unit reflection direction at `(s, t)`, the inverse of [`sphere_map_uv`]: the ball's
/// normal is `n = (2s − 1, 2t − 1, sqrt(1 − nx² − ny²))` and `r = 2nz·n − (0, 0, 1)` (the view
/// vector is `+z`).
///
/// `None` for a non-finite `st` or one outside the disk (`nx² + ny² > 1 + 4ε`: points a few
/// ulps outside, where rounding puts some rim points, count as on the rim); the rim itself maps
/// to the singular direction `(0, 0, −1)`.
///
/// # Accuracy
/// Within `SPHERE_MAP_ROUND_TRIP_BOUND / sqrt(1 − ρ²)` radians of the exact direction at the
/// distance `ρ/2` from the centre (the direction's sensitivity to `(s, t)` grows towards the rim);
/// `sphere_map_uv` of the result gives back `st` within `1e-6` for `ρ < 0.998`
/// (`environment.rs::sphere_map_uv_round_trips`).
///
/// ```
/// use barytex_uv::environment::sphere_map_direction;
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(sphere_map_direction(Vec2::splat(0.5)), Some(Vec3::Z));
/// assert_eq!(sphere_map_direction(Vec2::new(1.0, 0.5)), Some(Vec3::NEG_Z));
/// assert_eq!(sphere_map_direction(Vec2::new(1.0, 1.0)), None);
/// ```
#[must_use]
pub fn sphere_map_direction(st: Vec2) -> Option<Vec3> {
    if !st.is_finite() {
        return None;
    }
    let p = 2.0 * st - 1.0;
    let rho2 = p.length_squared();
    // sphere_map_uv rounds points of the rim up to a few ulps outside it: they count as on it.
    if rho2 > 1.0 + 4.0 * f32::EPSILON {
        return None;
    }
    let nz = (1.0 - rho2).max(0.0).sqrt();
    // rz = 2nz² − 1 = 1 − 2ρ²: the second form is exact near the centre.
    unit(Vec3::new(2.0 * nz * p.x, 2.0 * nz * p.y, 1.0 - 2.0 * rho2))
}

/// Angle (radians) of the sphere-map round trip at the centre of the map; at an angle `α` from
/// `+z` the bound is this divided by `cos(α/2)` (`environment.rs::sphere_map_round_trips`).
pub const SPHERE_MAP_ROUND_TRIP_BOUND: f32 = 2.0e-6;

/// [`sphere_map_uv`] with the gradients of `s` and `t` with respect to the (not necessarily
/// unit) direction `d`: with `q = |d|(|d| + z)`, `s = ½ + x/(2√(2q))` and
/// `∇s = (e_x − x∇q/(2q))/(2√(2q))`, `∇q = (1 + (|d| + z)/|d|)d + |d|e_z`; likewise `t` with `y`.
/// The `z` entry of `∇q` is evaluated as `(|d| + z)²/|d|`, which does not cancel near `−z`.
///
/// `None` where `sphere_map_uv` is `None` or a gradient overflows (near the singular direction).
///
/// # Accuracy
/// Relative to the largest gradient entry, within `2e-6` of the exact gradient for directions
/// at least `1e-3` radians from `−z` (worst seen `8.4e-7` over 10⁶ directions between `1e-4`
/// and `0.2` radians from `−z`; `environment.rs::sphere_map_jacobian_matches_finite_differences`,
/// `sphere_map_jacobian_near_neg_z_regression`).
///
/// ```
/// use barytex_uv::environment::sphere_map_uv_and_jacobian;
/// use glam::{Vec2, Vec3};
///
/// let j = sphere_map_uv_and_jacobian(Vec3::Z).expect("not singular");
/// assert_eq!(j.uv, Vec2::splat(0.5));
/// assert_eq!((j.du, j.dv), (Vec3::X / 4.0, Vec3::Y / 4.0));
/// ```
#[must_use]
pub fn sphere_map_uv_and_jacobian(dir: Vec3) -> Option<UvJacobian> {
    let uv = sphere_map_uv(dir)?;
    let m = dir.abs().max_element();
    let d = dir / m;
    let len = d.length();
    let r = d / len;
    // |d| + z without cancellation, from the unit direction's 1 + rz.
    let len_plus_z = len * 0.5 * half_m(r)?.powi(2);
    let q = len * len_plus_z;
    // ∂q/∂z = (1 + (|d| + z)/|d|)z + |d| = (|d| + z)²/|d|: the first form cancels near −z,
    // where both terms are ≈ ±|d| and the gradient is largest.
    let grad_xy = 1.0 + len_plus_z / len;
    let grad_q = Vec3::new(grad_xy * d.x, grad_xy * d.y, len_plus_z * len_plus_z / len);
    let k = 1.0 / (2.0 * (2.0 * q).sqrt());
    let du = k * (Vec3::X - d.x * grad_q / (2.0 * q)) / m;
    let dv = k * (Vec3::Y - d.y * grad_q / (2.0 * q)) / m;
    (du.is_finite() && dv.is_finite()).then_some(UvJacobian { uv, du, dv })
}
