//! Box (cube) mapping: the face is chosen by the normal's dominant axis, each face is a planar
//! mapping; plus triplanar blend weights.

use glam::{DVec2, DVec3, Vec2, Vec3};

use super::{DUvJacobian, UvMapping64};
use crate::{PositionMapping, UvError, UvJacobian};

/// A face of the box, named by its outward normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BoxFace {
    /// +x.
    PosX,
    /// −x.
    NegX,
    /// +y.
    PosY,
    /// −y.
    NegY,
    /// +z.
    PosZ,
    /// −z.
    NegZ,
}

impl BoxFace {
    /// All six faces.
    pub const ALL: [Self; 6] = [
        Self::PosX,
        Self::NegX,
        Self::PosY,
        Self::NegY,
        Self::PosZ,
        Self::NegZ,
    ];

    /// The face of the normal's dominant axis (ties go to x, then y; the sign of a zero
    /// component picks between the two faces), or `None` for a zero or non-finite normal.
    #[must_use]
    pub fn from_normal(normal: Vec3) -> Option<Self> {
        if !normal.is_finite() || normal == Vec3::ZERO {
            return None;
        }
        let a = normal.abs();
        let face = if a.x >= a.y && a.x >= a.z {
            if normal.x.is_sign_negative() {
                Self::NegX
            } else {
                Self::PosX
            }
        } else if a.y >= a.z {
            if normal.y.is_sign_negative() {
                Self::NegY
            } else {
                Self::PosY
            }
        } else if normal.z.is_sign_negative() {
            Self::NegZ
        } else {
            Self::PosZ
        };
        Some(face)
    }

    /// The outward unit normal.
    #[must_use]
    pub fn normal(self) -> Vec3 {
        match self {
            Self::PosX => Vec3::X,
            Self::NegX => Vec3::NEG_X,
            Self::PosY => Vec3::Y,
            Self::NegY => Vec3::NEG_Y,
            Self::PosZ => Vec3::Z,
            Self::NegZ => Vec3::NEG_Z,
        }
    }

    /// The object-space directions of +u and +v on this face (see [`BoxMapping`]'s table).
    #[must_use]
    pub fn axes(self) -> (Vec3, Vec3) {
        match self {
            Self::PosX => (Vec3::NEG_Z, Vec3::NEG_Y),
            Self::NegX => (Vec3::Z, Vec3::NEG_Y),
            Self::PosY => (Vec3::X, Vec3::Z),
            Self::NegY => (Vec3::X, Vec3::NEG_Z),
            Self::PosZ => (Vec3::X, Vec3::NEG_Y),
            Self::NegZ => (Vec3::NEG_X, Vec3::NEG_Y),
        }
    }
}

/// Box mapping of the cube `center ± size/2`: each face maps onto the whole `[0, 1]²`, seen from
/// outside with `u` to the right and `v` down (the side faces upright, +y up):
///
/// | face | +u | +v |
/// |---|---|---|
/// | +x | −z | −y |
/// | −x | +z | −y |
/// | +y | +x | +z |
/// | −y | +x | −z |
/// | +z | +x | −y |
/// | −z | −x | −y |
///
/// `u = 1/2 + (p − c)·u_axis / size` (likewise `v`); points off the cube are projected along the
/// face normal, so the mapping works for any shape. The face comes from the normal
/// ([`BoxFace::from_normal`]); the Jacobian is constant per face. Blend faces with
/// [`triplanar_weights`].
///
/// # Accuracy
/// Evaluated in f64 and rounded once (within 1 f32 ulp of the formula).
///
/// ```
/// use barytex_uv::mappings::{BoxFace, BoxMapping};
/// use barytex_uv::PositionMapping;
/// use glam::{Vec2, Vec3};
///
/// let cube = BoxMapping::new(Vec3::ZERO, 2.0).expect("valid size");
/// // The top face's corner at (−1, 1, −1) is its top-left texel.
/// assert_eq!(cube.uv(Vec3::new(-1.0, 1.0, -1.0), Vec3::Y), Some(Vec2::ZERO));
/// assert_eq!(cube.point_at(BoxFace::PosY, Vec2::ZERO), Some(Vec3::new(-1.0, 1.0, -1.0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BoxMapping {
    center: DVec3,
    size: f64,
}

impl BoxMapping {
    /// The cube `center ± size/2`.
    ///
    /// # Errors
    /// [`UvError::NonFinite`] for a non-finite center or size, [`UvError::OutOfRange`] for a size
    /// that is not positive or so small that `1/size` overflows f32.
    pub fn new(center: Vec3, size: f32) -> Result<Self, UvError> {
        if !center.is_finite() {
            return Err(UvError::NonFinite { what: "center" });
        }
        let size = super::positive("size", size)?;
        if !f32_finite(1.0 / size) {
            return Err(UvError::OutOfRange {
                what: "size",
                value: size,
            });
        }
        Ok(Self {
            center: center.as_dvec3(),
            size,
        })
    }

    /// The point of `face` whose texture coordinate is `uv` (on the cube's surface for `uv` in
    /// `[0, 1]²`), or `None` for a non-finite `uv`.
    #[must_use]
    pub fn point_at(&self, face: BoxFace, uv: Vec2) -> Option<Vec3> {
        let (a, b) = face.axes();
        let uv = uv.as_dvec2() - DVec2::splat(0.5);
        let p = self.center
            + (face.normal().as_dvec3() * 0.5 + a.as_dvec3() * uv.x + b.as_dvec3() * uv.y)
                * self.size;
        let p = p.as_vec3();
        p.is_finite().then_some(p)
    }
}

/// Whether `x` stays finite when rounded to f32.
#[allow(clippy::cast_possible_truncation)]
fn f32_finite(x: f64) -> bool {
    (x as f32).is_finite()
}

impl UvMapping64 for BoxMapping {
    fn uv_and_jacobian_f64(&self, position: DVec3, normal: DVec3) -> Option<DUvJacobian> {
        if !position.is_finite() {
            return None;
        }
        let face = BoxFace::from_normal(normal.as_vec3())?;
        let (a, b) = face.axes();
        let (du, dv) = (a.as_dvec3() / self.size, b.as_dvec3() / self.size);
        let d = position - self.center;
        Some(DUvJacobian {
            uv: DVec2::new(0.5 + d.dot(du), 0.5 + d.dot(dv)),
            du,
            dv,
        })
    }
}

impl PositionMapping for BoxMapping {
    /// `None` for a non-finite position, a zero or non-finite normal, or a `uv` beyond f32.
    fn uv_and_jacobian(&self, position: Vec3, normal: Vec3) -> Option<UvJacobian> {
        self.uv_and_jacobian_f64(position.as_dvec3(), normal.as_dvec3())?
            .to_f32()
    }
}

/// Triplanar blend weights of the x, y and z projections: `|nᵢ|^sharpness`, normalized to sum
/// to 1. `sharpness` 1 blends linearly, larger values narrow the transition (∞ picks the
/// dominant axis, ties shared).
///
/// Total: a zero or non-finite normal, or a NaN sharpness, gives equal weights `1/3`; a negative
/// sharpness is treated as 0 (equal weights). The magnitudes are divided by the largest first,
/// so large sharpness never underflows all three weights.
///
/// # Accuracy
/// The weights are non-negative and sum to 1 within 4 f32 ulps
/// (`tests/tests/uv/mappings.rs::triplanar_weights_sum_to_one`).
///
/// ```
/// use barytex_uv::mappings::triplanar_weights;
/// use glam::Vec3;
///
/// assert_eq!(triplanar_weights(Vec3::Y, 4.0), Vec3::Y);
/// let w = triplanar_weights(Vec3::new(1.0, 1.0, 0.0).normalize(), 2.0);
/// assert!((w.x - 0.5).abs() < 1e-6 && w.z == 0.0);
/// ```
#[must_use]
pub fn triplanar_weights(normal: Vec3, sharpness: f32) -> Vec3 {
    let equal = Vec3::splat(1.0 / 3.0);
    let a = normal.abs();
    let m = a.max_element();
    if !normal.is_finite() || m == 0.0 || sharpness.is_nan() {
        return equal;
    }
    let k = sharpness.max(0.0);
    let w = (a / m).powf(k);
    // The largest component is exactly 1, so the sum is in [1, 3].
    w / w.element_sum()
}
