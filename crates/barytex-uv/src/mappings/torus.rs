//! Torus mapping.

use core::f64::consts::TAU;

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{DUvJacobian, InverseUvMapping, UvMapping64, unit_turns, wrap_unit_f32};
use crate::{PositionMapping, UvError, UvJacobian};

/// The torus about the y axis of Buss, *3D Computer Graphics* (2003), ch. V (Figure V.6),
/// `P(θ, φ) = ((R + r cos φ) sin θ, r sin φ, (R + r cos φ) cos θ)`, with `s = θ/2π` and
/// `t = φ/2π`, both in `[0, 1)`, and `(u, v) = (s, 1 − t)` wrapped into `[0, 1)`: `φ = 0` (the
/// outer equator) is the top row, and `v` grows as `φ` goes down over the inside of the ring.
///
/// For any point, `θ = atan2(x, z)` and `φ = atan2(y, ρ − R)` with `ρ = √(x² + z²)` (the point
/// projected onto the tube through the nearest point of the core circle). Undefined, and
/// `None`, on the y axis (`ρ = 0`) and on the core circle (`ρ = R`, `y = 0`). Seams: `u` on
/// `x = 0, z < 0`; `v` on the outer equator.
///
/// Jacobian, with `q = ρ − R`: `∇u = (z, 0, −x)/(2πρ²)`,
/// `∇v = −∇φ/2π = −(−xy/ρ, q, −zy/ρ) / (2π(q² + y²))`.
///
/// # Accuracy
/// Evaluated in f64 and rounded once. The Jacobian matches central finite differences to a
/// relative 1e-7 at regular points, on both seams, and next to the axis down to a distance of
/// 1e-12 (measured 6.9e-9); next to the core circle it does so down to a distance `d = 1e-3`:
/// closer in, `d = √(x² + z²) − R` carries the rounding of the square root (up to 2⁻⁵³·R
/// absolute), so `∇v ∝ 1/d` is good to about `2⁻⁵²·R/d` relative (as is any f64 evaluation from
/// the rounded point) (`tests/tests/uv/mappings.rs::jacobian_matches_finite_differences`,
/// `tests/tests/uv/poles_and_seams.rs::jacobians_next_to_poles_and_seams`). `point_at` round trips
/// within 1e-6 in uv, both coordinates compared modulo 1 across the seams, at every `(u, v)`
/// (`tests/tests/uv/mappings.rs::round_trip_uv_point_uv`,
/// `tests/tests/uv/poles_and_seams.rs::round_trips_on_every_row_and_column`).
///
/// ```
/// use barytex_uv::mappings::{InverseUvMapping, Torus};
/// use barytex_uv::PositionMapping;
/// use glam::{Vec2, Vec3};
///
/// let torus = Torus::new(2.0, 0.5).expect("valid radii");
/// // The top of the tube above +z: θ = 0, φ = π/2, so v = 1 − 1/4.
/// let uv = torus.uv(Vec3::new(0.0, 0.5, 2.0), Vec3::Y).expect("regular point");
/// assert!((uv - Vec2::new(0.0, 0.75)).length() < 1e-6);
/// assert!((torus.point_at(uv).expect("finite") - Vec3::new(0.0, 0.5, 2.0)).length() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Torus {
    major: f64,
    minor: f64,
}

impl Torus {
    /// A torus of `major` radius `R` (centre of the tube) and `minor` radius `r` (the tube).
    ///
    /// # Errors
    /// [`UvError::NonFinite`] or [`UvError::OutOfRange`] unless both are finite and positive.
    pub fn new(major: f32, minor: f32) -> Result<Self, UvError> {
        Ok(Self {
            major: super::positive("major", major)?,
            minor: super::positive("minor", minor)?,
        })
    }
}

impl UvMapping64 for Torus {
    fn uv_and_jacobian_f64(&self, p: DVec3, normal: DVec3) -> Option<DUvJacobian> {
        if !(p.is_finite() && normal.is_finite()) {
            return None;
        }
        let rho2 = p.x * p.x + p.z * p.z;
        if rho2 == 0.0 {
            return None;
        }
        let rho = rho2.sqrt();
        let q = rho - self.major;
        let d2 = q * q + p.y * p.y;
        if d2 == 0.0 {
            return None;
        }
        let t = unit_turns(p.y.atan2(q));
        let dphi = DVec3::new(-p.x * p.y / rho, q, -p.z * p.y / rho) / d2;
        Some(DUvJacobian {
            uv: DVec2::new(
                unit_turns(p.x.atan2(p.z)),
                if t == 0.0 { 0.0 } else { 1.0 - t },
            ),
            du: DVec3::new(p.z, 0.0, -p.x) / (TAU * rho2),
            dv: -dphi / TAU,
        })
    }
}

impl PositionMapping for Torus {
    /// `None` for non-finite input, a point on the axis or the core circle, or a gradient
    /// beyond f32; `u, v ∈ [0, 1)`.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian> {
        let j = self
            .uv_and_jacobian_f64(position.as_dvec3(), normal.as_dvec3())?
            .to_f32()?;
        Some(wrap_unit_f32(j, true, true))
    }
}

impl InverseUvMapping for Torus {
    /// `P(2πu, 2π(1 − v))`; `None` for a non-finite `uv`.
    fn point_at(&self, uv: Vec2) -> Option<Vec3> {
        if !uv.is_finite() {
            return None;
        }
        let (sin_t, cos_t) = (TAU * f64::from(uv.x)).sin_cos();
        let (sin_p, cos_p) = (TAU * (1.0 - f64::from(uv.y))).sin_cos();
        let ring = self.major + self.minor * cos_p;
        let p = DVec3::new(ring * sin_t, self.minor * sin_p, ring * cos_t).as_vec3();
        p.is_finite().then_some(p)
    }
}
