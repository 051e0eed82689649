//! Cylindrical mapping about the y axis, with optional planar caps.

use core::f64::consts::TAU;

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{DUvJacobian, InverseUvMapping, UvMapping64, unit_turns, wrap_unit_f32};
use crate::{PositionMapping, UvError, UvJacobian};

/// What the cylinder's caps get.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum CylinderCaps {
    /// No caps: every point gets the side's mapping.
    #[default]
    None,
    /// Points whose normal is mostly axial (`|n_y| > |(n_x, n_z)|`) get a planar mapping of the
    /// disc onto `[0, 1]²`: `u = 1/2 + x/2r`, `v = 1/2 ± z/2r` (`+` on the top cap seen from
    /// above, `−` on the bottom seen from below), as [`BoxMapping`](super::BoxMapping)'s ±y
    /// faces.
    Planar,
}

/// The cylinder of Buss, *3D Computer Graphics* (2003), ch. V (Figure V.3),
/// `p(θ, y) = (r sin θ, y, r cos θ)` of radius `r` and height `h` centred at the origin:
/// `s = θ/2π ∈ [0, 1)` with `θ = atan2(x, z)`, `t = (y + h/2)/h`, and `(u, v) = (s, 1 − t)` so the
/// top of the cylinder is the top of the image.
///
/// Points off the cylinder are projected radially (the radius only matters to
/// [`point_at`](InverseUvMapping::point_at) and the caps). The seam is the half-plane `x = 0`,
/// `z < 0`; the y axis itself has no `θ`, so points on it give `None` (unless a cap takes them).
///
/// Jacobian: `∇u = (z, 0, −x) / (2π(x² + z²))`, `∇v = (0, −1/h, 0)`.
///
/// # Accuracy
/// Evaluated in f64 and rounded once. The Jacobian matches central finite differences to a
/// relative 1e-7 at regular points, on the seam, and next to the axis down to a distance of
/// 1e-12 (with steps scaled to the distance; measured 4.8e-11)
/// (`tests/tests/uv/mappings.rs::jacobian_matches_finite_differences`,
/// `tests/tests/uv/poles_and_seams.rs::jacobians_next_to_poles_and_seams`). `point_at` round trips within
/// 1e-6 in uv on the side, `u` compared modulo 1 across the seam, at every `(u, v)`
/// (`tests/tests/uv/mappings.rs::round_trip_uv_point_uv`,
/// `tests/tests/uv/poles_and_seams.rs::round_trips_on_every_row_and_column`).
///
/// ```
/// use barytex_uv::mappings::{Cylindrical, InverseUvMapping};
/// use barytex_uv::PositionMapping;
/// use glam::{Vec2, Vec3};
///
/// let c = Cylindrical::new(1.0, 2.0).expect("valid");
/// // θ = π/2 (on +x), at the top rim.
/// let uv = c.uv(Vec3::new(1.0, 1.0, 0.0), Vec3::X).expect("off the axis");
/// assert!((uv - Vec2::new(0.25, 0.0)).length() < 1e-6);
/// let p = c.point_at(Vec2::new(0.5, 0.5)).expect("finite");
/// assert!((p - Vec3::new(0.0, 0.0, -1.0)).length() < 1e-6);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylindrical {
    radius: f64,
    height: f64,
    caps: CylinderCaps,
}

impl Cylindrical {
    /// A cylinder of `radius` and `height` about the y axis, centred at the origin, without caps.
    ///
    /// # Errors
    /// [`UvError::NonFinite`] or [`UvError::OutOfRange`] unless both are finite and positive.
    pub fn new(radius: f32, height: f32) -> Result<Self, UvError> {
        Ok(Self {
            radius: super::positive("radius", radius)?,
            height: super::positive("height", height)?,
            caps: CylinderCaps::None,
        })
    }

    /// The same cylinder with `caps`.
    #[must_use]
    pub const fn with_caps(mut self, caps: CylinderCaps) -> Self {
        self.caps = caps;
        self
    }

    /// The cap mode.
    #[must_use]
    pub const fn caps(&self) -> CylinderCaps {
        self.caps
    }

    /// Whether a point with `normal` is mapped by a planar cap rather than the side: caps are
    /// [`CylinderCaps::Planar`] and the normal is closer to ±y than to the side,
    /// `|n_y| > √(n_x² + n_z²)`, decided in f64 (the rule every evaluation follows).
    ///
    /// ```
    /// use barytex_uv::mappings::{CylinderCaps, Cylindrical};
    /// use glam::Vec3;
    ///
    /// let c = Cylindrical::new(1.0, 2.0).expect("valid").with_caps(CylinderCaps::Planar);
    /// assert!(c.on_cap(Vec3::Y));
    /// assert!(!c.on_cap(Vec3::new(1.0, 0.9, 0.0)));
    /// assert!(!Cylindrical::new(1.0, 2.0).expect("valid").on_cap(Vec3::Y));
    /// ```
    #[must_use]
    pub fn on_cap(&self, normal: Vec3) -> bool {
        self.on_cap_f64(normal.as_dvec3())
    }

    /// [`on_cap`](Self::on_cap) of an f64 normal.
    fn on_cap_f64(&self, n: DVec3) -> bool {
        self.caps == CylinderCaps::Planar && n.y.abs() > n.x.hypot(n.z)
    }
}

impl UvMapping64 for Cylindrical {
    fn uv_and_jacobian_f64(&self, p: DVec3, normal: DVec3) -> Option<DUvJacobian> {
        if !(p.is_finite() && normal.is_finite()) {
            return None;
        }
        if self.on_cap_f64(normal) {
            let k = 0.5 / self.radius;
            let sign = normal.y.signum();
            return Some(DUvJacobian {
                uv: DVec2::new(0.5 + p.x * k, 0.5 + sign * p.z * k),
                du: DVec3::new(k, 0.0, 0.0),
                dv: DVec3::new(0.0, 0.0, sign * k),
            });
        }
        let rho2 = p.x * p.x + p.z * p.z;
        if rho2 == 0.0 || !rho2.is_finite() {
            return None;
        }
        Some(DUvJacobian {
            uv: DVec2::new(unit_turns(p.x.atan2(p.z)), 0.5 - p.y / self.height),
            du: DVec3::new(p.z, 0.0, -p.x) / (TAU * rho2),
            dv: DVec3::new(0.0, -1.0 / self.height, 0.0),
        })
    }
}

impl PositionMapping for Cylindrical {
    /// `None` for non-finite input, a point on the axis (side mapping), or a result beyond f32;
    /// the side's `u` is in `[0, 1)`.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian> {
        // The side's `u` wraps into [0, 1), a cap's does not: decided as the f64 evaluation
        // decides. (An f32 test of the same rule disagreed with it on a normal 2·10⁻⁶ from the
        // boundary, and a cap's u, −1e28, was taken for the side's; a cap's u ≥ 1 would have
        // been reset to 0. Fuzz target `uv_mappings`.)
        let side = !self.on_cap(normal);
        let j = self
            .uv_and_jacobian_f64(position.as_dvec3(), normal.as_dvec3())?
            .to_f32()?;
        Some(wrap_unit_f32(j, side, false))
    }
}

impl InverseUvMapping for Cylindrical {
    /// The point of the side: `(r sin 2πu, (1/2 − v)h, r cos 2πu)`.
    fn point_at(&self, uv: Vec2) -> Option<Vec3> {
        if !uv.is_finite() {
            return None;
        }
        let (sin, cos) = (TAU * f64::from(uv.x)).sin_cos();
        let p = DVec3::new(
            self.radius * sin,
            (0.5 - f64::from(uv.y)) * self.height,
            self.radius * cos,
        )
        .as_vec3();
        p.is_finite().then_some(p)
    }
}
