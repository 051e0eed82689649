//! Planar mapping in any frame.

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{DUvJacobian, InverseUvMapping, UvMapping64};
use crate::{PositionMapping, UvError, UvJacobian};

/// Planar projection: `u` and `v` are the coordinates of the point in the frame
/// `(origin, u_axis, v_axis)`, projected along the plane's normal.
///
/// For orthogonal axes this is the inverse of linear interpolation along each axis (Buss, *3D
/// Computer Graphics* (2003), §IV.1: `α = (u − x₁)·(x₂ − x₁)/|x₂ − x₁|²`), `u = (p − o)·U/|U|²`,
/// `v = (p − o)·V/|V|²`; for skew axes the dual basis is used so that
/// [`point_at`](InverseUvMapping::point_at) (`o + u U + v V`) is an exact inverse on the plane. The
/// Jacobian is constant: `∇u` and `∇v` are the dual axes.
///
/// # Accuracy
/// Evaluated in f64 and rounded once: `uv` within 1 f32 ulp of the f64 formula, which matches
/// central finite differences to a relative 1e-7 (`tests/tests/uv/mappings.rs::jacobian_matches_finite_differences`).
///
/// ```
/// use barytex_uv::mappings::Planar;
/// use barytex_uv::PositionMapping;
/// use glam::{Vec2, Vec3};
///
/// // One texture repeat per 2 units on the floor.
/// let floor = Planar::xz(2.0).expect("valid scale");
/// assert_eq!(floor.uv(Vec3::new(1.0, 5.0, 0.5), Vec3::Y), Some(Vec2::new(0.5, 0.25)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Planar {
    origin: DVec3,
    u_axis: DVec3,
    v_axis: DVec3,
    du: DVec3,
    dv: DVec3,
}

impl Planar {
    /// The frame `origin + u·u_axis + v·v_axis`.
    ///
    /// # Errors
    /// [`UvError::NonFinite`] for a non-finite component; [`UvError::OutOfRange`] for a zero
    /// axis, (nearly) parallel axes (`sin` of their angle below 1e-6, `value` is that sine), or
    /// axes so short that the gradients overflow f32.
    pub fn new(origin: Vec3, u_axis: Vec3, v_axis: Vec3) -> Result<Self, UvError> {
        for (what, v) in [("origin", origin), ("u_axis", u_axis), ("v_axis", v_axis)] {
            if !v.is_finite() {
                return Err(UvError::NonFinite { what });
            }
        }
        let (u_axis, v_axis) = (u_axis.as_dvec3(), v_axis.as_dvec3());
        for (what, a) in [("u_axis", u_axis), ("v_axis", v_axis)] {
            if a.length_squared() == 0.0 {
                return Err(UvError::OutOfRange { what, value: 0.0 });
            }
        }
        let n = u_axis.cross(v_axis);
        let n2 = n.length_squared();
        let sine = (n2 / (u_axis.length_squared() * v_axis.length_squared())).sqrt();
        // Nearly parallel axes make the dual basis explode; 1e-6 keeps it within 1e6 |axis|⁻¹.
        if sine.is_nan() || sine < 1e-6 {
            return Err(UvError::OutOfRange {
                what: "v_axis",
                value: sine,
            });
        }
        let du = v_axis.cross(n) / n2;
        let dv = n.cross(u_axis) / n2;
        if !(du.as_vec3().is_finite() && dv.as_vec3().is_finite()) {
            return Err(UvError::OutOfRange {
                what: "u_axis",
                value: u_axis.length(),
            });
        }
        Ok(Self {
            origin: origin.as_dvec3(),
            u_axis,
            v_axis,
            du,
            dv,
        })
    }

    /// The xz plane (a floor seen from +y): `u = x / scale`, `v = z / scale`, so +z (towards
    /// the viewer) is down in the image.
    ///
    /// # Errors
    /// [`UvError::NonFinite`] or [`UvError::OutOfRange`] for a scale that is not finite and
    /// positive.
    pub fn xz(scale: f32) -> Result<Self, UvError> {
        let s = super::positive("scale", scale)?;
        #[allow(clippy::cast_possible_truncation)]
        let s = s as f32;
        Self::new(Vec3::ZERO, Vec3::X * s, Vec3::Z * s)
    }

    /// The frame's origin.
    #[must_use]
    pub fn origin(&self) -> Vec3 {
        self.origin.as_vec3()
    }

    /// The u axis (one texture repeat).
    #[must_use]
    pub fn u_axis(&self) -> Vec3 {
        self.u_axis.as_vec3()
    }

    /// The v axis (one texture repeat, downwards in the image).
    #[must_use]
    pub fn v_axis(&self) -> Vec3 {
        self.v_axis.as_vec3()
    }
}

impl UvMapping64 for Planar {
    fn uv_and_jacobian_f64(&self, position: DVec3, normal: DVec3) -> Option<DUvJacobian> {
        if !(position.is_finite() && normal.is_finite()) {
            return None;
        }
        let d = position - self.origin;
        Some(DUvJacobian {
            uv: DVec2::new(d.dot(self.du), d.dot(self.dv)),
            du: self.du,
            dv: self.dv,
        })
    }
}

impl PositionMapping for Planar {
    /// `None` for a non-finite position or normal (the normal is otherwise unused) or a `uv`
    /// beyond f32.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian> {
        self.uv_and_jacobian_f64(position.as_dvec3(), normal.as_dvec3())?
            .to_f32()
    }
}

impl InverseUvMapping for Planar {
    fn point_at(&self, uv: Vec2) -> Option<Vec3> {
        let uv = uv.as_dvec2();
        let p = (self.origin + uv.x * self.u_axis + uv.y * self.v_axis).as_vec3();
        p.is_finite().then_some(p)
    }
}
