//! Homogeneous coordinates `(x : w)` (Buss 2003, ch. IV, interpolation and homogeneous
//! coordinates).

use glam::{Vec3, Vec4};

use crate::Interpolate;

/// A point in homogeneous coordinates `(xyz : w)`, standing for `xyz / w` when `w ≠ 0`.
///
/// Convex combinations of homogeneous points with `w > 0` are homogeneous coordinates of a point
/// in the convex hull of the points they stand for (Buss 2003, ch. IV; Denisjuk, convex combinations
/// of homogeneous coordinates): weights `αᵢ` on the homogeneous
/// points become the weights `αᵢwᵢ / Σαⱼwⱼ` on the points themselves. (Perspective correction is
/// the inverse direction: screen weights `αᵢ` become `(αᵢ/wᵢ) / Σ(αⱼ/wⱼ)`; see
/// [`perspective_correct_weights`].)
///
/// [`perspective_correct_weights`]: crate::perspective_correct_weights
///
/// ```
/// use barytex_interp::{ConvexCombination, Homogeneous3};
/// use glam::Vec3;
/// let a = Homogeneous3::new(Vec3::new(2.0, 0.0, 0.0), 2.0); // stands for (1, 0, 0)
/// let b = Homogeneous3::from_point(Vec3::new(0.0, 1.0, 0.0));
/// let mid = ConvexCombination::new([0.5, 0.5])?.apply([a, b]);
/// // (1, 0.5, 0 : 1.5) stands for (2/3, 1/3, 0): on the segment, but not at its midpoint.
/// let p = mid.to_point().unwrap();
/// assert!((p - Vec3::new(2.0 / 3.0, 1.0 / 3.0, 0.0)).length() < 1e-7);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Homogeneous3 {
    /// The scaled coordinates `w·p`.
    pub xyz: Vec3,
    /// The homogeneous weight.
    pub w: f32,
}

impl Homogeneous3 {
    /// `(xyz : w)`.
    #[must_use]
    pub const fn new(xyz: Vec3, w: f32) -> Self {
        Self { xyz, w }
    }

    /// `(p : 1)`.
    #[must_use]
    pub const fn from_point(p: Vec3) -> Self {
        Self { xyz: p, w: 1.0 }
    }

    /// From a glam `Vec4` `(x, y, z, w)`, e.g. a clip-space position.
    #[must_use]
    pub fn from_vec4(v: Vec4) -> Self {
        Self {
            xyz: Vec3::new(v.x, v.y, v.z),
            w: v.w,
        }
    }

    /// As a glam `Vec4`.
    #[must_use]
    pub fn to_vec4(self) -> Vec4 {
        self.xyz.extend(self.w)
    }

    /// The point `xyz / w`; `None` when `w == 0` (a point at infinity) or the result is not
    /// finite.
    ///
    /// # Accuracy
    /// One division per component: correctly rounded.
    ///
    /// ```
    /// use barytex_interp::Homogeneous3;
    /// use glam::Vec3;
    /// let p = Homogeneous3::new(Vec3::new(2.0, 4.0, 6.0), 2.0).to_point();
    /// assert_eq!(p, Some(Vec3::new(1.0, 2.0, 3.0)));
    /// // A direction: the point at infinity along +x.
    /// assert_eq!(Homogeneous3::new(Vec3::X, 0.0).to_point(), None);
    /// ```
    #[must_use]
    pub fn to_point(self) -> Option<Vec3> {
        if self.w == 0.0 {
            return None;
        }
        let p = self.xyz / self.w;
        p.is_finite().then_some(p)
    }
}

impl Interpolate for Homogeneous3 {
    #[inline]
    fn scale(self, w: f32) -> Self {
        Self::new(self.xyz * w, self.w * w)
    }
    #[inline]
    fn add(self, other: Self) -> Self {
        Self::new(self.xyz + other.xyz, self.w + other.w)
    }
    #[inline]
    fn lerp(self, other: Self, t: f32) -> Self {
        Self::new(
            Interpolate::lerp(self.xyz, other.xyz, t),
            crate::lerp(self.w, other.w, t),
        )
    }
}
