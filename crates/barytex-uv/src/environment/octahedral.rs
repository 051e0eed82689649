//! The octahedral map (Cigolle, Donow, Evangelakos, Mara, McGuire, Meyer, "A Survey of
//! Efficient Representations for Independent Unit Vectors", JCGT 3(2), 2014): the sphere
//! projected onto the octahedron `|x| + |y| + |z| = 1`, the lower half folded out over the
//! corners of the square.

use glam::{Vec2, Vec3};

use super::reflect::unit;
use crate::UvJacobian;

/// `±1` by the sign bit, with `+1` for `+0.0` and `−1` for `−0.0` (the paper's `signNotZero`
/// uses `x ≥ 0`; the sign bit keeps the fold of `−0.0` on its side, which is what makes the
/// round trip exact on the folded edges).
fn sign_not_zero(v: Vec2) -> Vec2 {
    Vec2::new(1f32.copysign(v.x), 1f32.copysign(v.y))
}

/// The octahedral coordinate of `dir` (any finite nonzero length) in `[0, 1]²`, the paper's
/// `float32x3_to_oct` followed by `uv = ½p + ½`:
/// `p = (x, y)/(|x| + |y| + |z|)`, and for `z < 0` the fold `p ← (1 − |p.yx|)·sign(p)`.
///
/// Axes: `+z` is the centre `(½, ½)`, `−z` the four corners; `+x` is `(1, ½)` and `+y` is
/// `(½, 1)`, so in a v-down image `+y` is at the middle of the **bottom** edge. These are the
/// paper's coordinates unchanged, so maps baked by other implementations of it read the same.
///
/// `None` for a zero or non-finite `dir`.
///
/// # Accuracy
/// [`octahedral_decode`] of the result is within [`OCTAHEDRAL_ROUND_TRIP_BOUND`] radians of
/// `dir` (`environment.rs::octahedral_round_trips`).
///
/// ```
/// use barytex_uv::environment::octahedral_encode;
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(octahedral_encode(Vec3::Z), Some(Vec2::splat(0.5)));
/// assert_eq!(octahedral_encode(Vec3::X), Some(Vec2::new(1.0, 0.5)));
/// assert_eq!(octahedral_encode(Vec3::NEG_Z), Some(Vec2::new(1.0, 1.0)));
/// assert_eq!(octahedral_encode(Vec3::INFINITY), None);
/// ```
#[must_use]
pub fn octahedral_encode(dir: Vec3) -> Option<Vec2> {
    let d = unit(dir)?;
    let p = Vec2::new(d.x, d.y) / (d.x.abs() + d.y.abs() + d.z.abs());
    let p = if d.z < 0.0 {
        (1.0 - Vec2::new(p.y, p.x).abs()) * sign_not_zero(p)
    } else {
        p
    };
    Some((0.5 * p + 0.5).clamp(Vec2::ZERO, Vec2::ONE))
}

/// The unit direction at `uv`, the paper's `oct_to_float32x3`: with `p = 2uv − 1`,
/// `d = (p.x, p.y, 1 − |p.x| − |p.y|)`, unfolded by `d.xy ← (1 − |d.yx|)·sign(d.xy)` where
/// `d.z < 0`, then normalized.
///
/// `uv` outside `[0, 1]²` is clamped to the square first; every finite `uv` gives a unit vector.
/// `None` for a non-finite `uv`.
///
/// # Accuracy
/// Within [`OCTAHEDRAL_ROUND_TRIP_BOUND`] radians of the exact direction; `octahedral_encode`
/// of the result gives back `uv` within `1e-6` for `uv` in `[0, 1]²` away from the folds
/// (`environment.rs::octahedral_uv_round_trips`).
///
/// ```
/// use barytex_uv::environment::octahedral_decode;
/// use glam::{Vec2, Vec3};
///
/// assert_eq!(octahedral_decode(Vec2::splat(0.5)), Some(Vec3::Z));
/// assert_eq!(octahedral_decode(Vec2::ZERO), Some(Vec3::NEG_Z));
/// ```
#[must_use]
pub fn octahedral_decode(uv: Vec2) -> Option<Vec3> {
    if !uv.is_finite() {
        return None;
    }
    let p = 2.0 * uv.clamp(Vec2::ZERO, Vec2::ONE) - 1.0;
    let z = 1.0 - p.x.abs() - p.y.abs();
    let xy = if z < 0.0 {
        (1.0 - Vec2::new(p.y, p.x).abs()) * sign_not_zero(p)
    } else {
        p
    };
    unit(xy.extend(z))
}

/// Angle (radians) within which `octahedral_decode(octahedral_encode(d))` returns a unit
/// direction `d` (`environment.rs::octahedral_round_trips`).
pub const OCTAHEDRAL_ROUND_TRIP_BOUND: f32 = 1.0e-6;

/// [`octahedral_encode`] with the gradients of `u` and `v` with respect to the direction. On the
/// upper half `p = (x, y)/L₁` with `L₁ = |x| + |y| + |z|`, so
/// `∇p.x = (e_x − p.x·sign(d))/L₁`; on the lower half the fold gives
/// `∇p'.x = −sign(p.x)·sign(p.y)·∇p.y` and `∇p'.y = −sign(p.y)·sign(p.x)·∇p.x`; `uv = ½p + ½`.
///
/// The map is only piecewise smooth: across the coordinate planes the one-sided gradients
/// differ, and this returns the gradient of the piece `dir` lies on (its signs). `None` as for
/// `octahedral_encode`, or when a gradient overflows (`|dir|` below about `1e-38`).
///
/// # Accuracy
/// Relative to the largest gradient entry, within `1e-5` of the exact gradient away from the
/// coordinate planes (`environment.rs::octahedral_jacobian_matches_finite_differences`).
///
/// ```
/// use barytex_uv::environment::octahedral_uv_and_jacobian;
/// use glam::{Vec2, Vec3};
///
/// let j = octahedral_uv_and_jacobian(Vec3::Z).expect("nonzero");
/// assert_eq!(j.uv, Vec2::splat(0.5));
/// assert_eq!((j.du, j.dv), (Vec3::X * 0.5, Vec3::Y * 0.5));
/// ```
#[must_use]
pub fn octahedral_uv_and_jacobian(dir: Vec3) -> Option<UvJacobian> {
    let uv = octahedral_encode(dir)?;
    let m = dir.abs().max_element();
    let d = dir / m;
    let l1 = d.x.abs() + d.y.abs() + d.z.abs();
    let p = Vec2::new(d.x, d.y) / l1;
    let sign = Vec3::new(1f32.copysign(d.x), 1f32.copysign(d.y), 1f32.copysign(d.z));
    let gx = (Vec3::X - p.x * sign) / l1;
    let gy = (Vec3::Y - p.y * sign) / l1;
    let (gx, gy) = if d.z < 0.0 {
        let s = sign_not_zero(p);
        (-s.x * s.y * gy, -s.y * s.x * gx)
    } else {
        (gx, gy)
    };
    let (du, dv) = (0.5 * gx / m, 0.5 * gy / m);
    (du.is_finite() && dv.is_finite()).then_some(UvJacobian { uv, du, dv })
}
