//! Spherical mapping in the two projections of Buss, *3D Computer Graphics* (2003), eqs. (V.2)
//! and (V.3).

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{DUvJacobian, InverseUvMapping, UvMapping64, unit_turns, wrap_unit_f32};
use crate::{PositionMapping, UvError, UvJacobian};

/// How latitude `φ ∈ [−π/2, π/2]` becomes Buss's `t` (and `v = 1 − t`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SphereProjection {
    /// `t = φ/π + 1/2` (latitude linear; Buss's eq. (V.2), `φ/180 + 1/2` in degrees):
    /// `v = 1/2 − φ/π`.
    #[default]
    Equirectangular,
    /// `t = sin φ/2 + 1/2` (Buss's eq. (V.3), the cylindrical projection: Lambert's cylindrical
    /// equal-area): `v = (1 − sin φ)/2`.
    EqualArea,
}

/// The sphere about the origin of Buss, *3D Computer Graphics* (2003), ch. V (Figure V.5):
/// `s = θ/2π ∈ [0, 1)` with `θ = atan2(x, z)`, latitude `φ = atan2(y, √(x² + z²))`, `t` from the
/// [`SphereProjection`], and `(u, v) = (s, 1 − t)`: the north pole (+y) is the top row of the image
/// (`v = 0`), the south pole the bottom (`v = 1`).
///
/// Points off the sphere are projected radially (the radius only matters to
/// [`point_at`](InverseUvMapping::point_at)). The seam is the half-plane `x = 0`, `z < 0`. On
/// the pole axis (`x = z = 0`) `θ` and the Jacobian are undefined: `None` there, and only
/// there in f64 (in f32, also where `|∇u| ~ 1/(2π√(x² + z²))` overflows, within ~1e-39 of the
/// axis).
///
/// Jacobian, with `ρ² = x² + z²`, `|p|² = ρ² + y²`: `∇u = (z, 0, −x)/(2πρ²)`;
/// `∇φ = (−xy/ρ, ρ, −zy/ρ)/|p|²`, so `∇v = −∇φ/π` (equirectangular) or
/// `∇v = −cos φ ∇φ / 2` (equal-area).
///
/// # Accuracy
/// Evaluated in f64 and rounded once. The Jacobian matches central finite differences to a
/// relative 1e-7 at regular points, on the seam, and next to both poles down to a distance of
/// 1e-12 from the axis (steps scaled to the distance; measured 4.9e-11). Near the south pole `v`
/// is within an f64 ulp of 1, too coarse for differences there, so `∇v` is checked by its exact
/// mirror symmetry `y → −y` instead (`tests/tests/uv/mappings.rs::jacobian_matches_finite_differences`,
/// `tests/tests/uv/poles_and_seams.rs::jacobians_next_to_poles_and_seams`). `point_at` round trips at
/// every `(u, v)`, poles and seam included: `v` within 1e-6, `u` within 1e-6 modulo 1 once
/// weighted by `cos φ` (the length of a turn at that latitude; at a pole `u` names no position,
/// and `uv` is `None` when the point lands on the axis)
/// (`tests/tests/uv/mappings.rs::round_trip_uv_point_uv`,
/// `tests/tests/uv/poles_and_seams.rs::round_trips_on_every_row_and_column`).
///
/// ```
/// use barytex_uv::mappings::{InverseUvMapping, SphereProjection, Spherical};
/// use barytex_uv::PositionMapping;
/// use glam::{Vec2, Vec3};
///
/// let s = Spherical::new(1.0, SphereProjection::EqualArea).expect("valid");
/// // 30° north on +z: sin φ = 1/2, so v = 1/4.
/// let p = Vec3::new(0.0, 0.5, 0.75f32.sqrt());
/// let uv = s.uv(p, p).expect("off the axis");
/// assert!((uv - Vec2::new(0.0, 0.25)).length() < 1e-6);
/// assert!((s.point_at(uv).expect("in range") - p).length() < 1e-6);
/// assert_eq!(s.uv(Vec3::Y, Vec3::Y), None); // the pole
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spherical {
    radius: f64,
    projection: SphereProjection,
}

impl Spherical {
    /// A sphere of `radius` about the origin.
    ///
    /// # Errors
    /// [`UvError::NonFinite`] or [`UvError::OutOfRange`] unless `radius` is finite and positive.
    pub fn new(radius: f32, projection: SphereProjection) -> Result<Self, UvError> {
        Ok(Self {
            radius: super::positive("radius", radius)?,
            projection,
        })
    }

    /// The projection.
    #[must_use]
    pub const fn projection(&self) -> SphereProjection {
        self.projection
    }
}

impl UvMapping64 for Spherical {
    fn uv_and_jacobian_f64(&self, p: DVec3, normal: DVec3) -> Option<DUvJacobian> {
        if !(p.is_finite() && normal.is_finite()) {
            return None;
        }
        let rho2 = p.x * p.x + p.z * p.z;
        if rho2 == 0.0 {
            return None;
        }
        let rho = rho2.sqrt();
        let r2 = rho2 + p.y * p.y;
        let phi = p.y.atan2(rho);
        let dphi = DVec3::new(-p.x * p.y / rho, rho, -p.z * p.y / rho) / r2;
        let (v, dv) = match self.projection {
            SphereProjection::Equirectangular => (0.5 - phi / PI, -dphi / PI),
            SphereProjection::EqualArea => (0.5 - 0.5 * phi.sin(), -0.5 * phi.cos() * dphi),
        };
        Some(DUvJacobian {
            uv: DVec2::new(unit_turns(p.x.atan2(p.z)), v),
            du: DVec3::new(p.z, 0.0, -p.x) / (TAU * rho2),
            dv,
        })
    }
}

impl PositionMapping for Spherical {
    /// `None` for non-finite input, a point on the pole axis, or a gradient beyond f32;
    /// `u ∈ [0, 1)`, `v ∈ [0, 1]`.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian> {
        let j = self
            .uv_and_jacobian_f64(position.as_dvec3(), normal.as_dvec3())?
            .to_f32()?;
        Some(wrap_unit_f32(j, true, false))
    }
}

impl InverseUvMapping for Spherical {
    /// `r (cos φ sin 2πu, sin φ, cos φ cos 2πu)` with `φ` from `v`; `None` unless `uv` is finite
    /// and `v ∈ [0, 1]`.
    fn point_at(&self, uv: Vec2) -> Option<Vec3> {
        if !uv.is_finite() || !(0.0..=1.0).contains(&uv.y) {
            return None;
        }
        let v = f64::from(uv.y);
        let phi = match self.projection {
            SphereProjection::Equirectangular => (0.5 - v) * PI,
            SphereProjection::EqualArea => (1.0 - 2.0 * v).clamp(-1.0, 1.0).asin(),
        }
        .clamp(-FRAC_PI_2, FRAC_PI_2);
        let (sin_t, cos_t) = (TAU * f64::from(uv.x)).sin_cos();
        let (sin_p, cos_p) = phi.sin_cos();
        let p = (self.radius * DVec3::new(cos_p * sin_t, sin_p, cos_p * cos_t)).as_vec3();
        p.is_finite().then_some(p)
    }
}
