//! Exact 2D orientation.

use glam::Vec2;

use crate::InterpError;

/// Which side of the directed line `a → b` the point `c` is on: the sign of the determinant
/// `(b − a) × (c − a)`.
///
/// "Counter-clockwise" is meant in a y-up frame (mathematics); on a y-down screen the same sign
/// looks clockwise.
///
/// ```
/// use barytex_interp::{orient2d, Orientation};
/// use glam::Vec2;
/// let o = orient2d(Vec2::ZERO, Vec2::X, Vec2::new(0.5, -1.0))?;
/// assert_eq!(o, Orientation::Clockwise);
/// assert_eq!(o.sign(), -1);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// `(b − a) × (c − a) > 0`: `c` is left of `a → b`.
    CounterClockwise,
    /// `(b − a) × (c − a) < 0`: `c` is right of `a → b`.
    Clockwise,
    /// `(b − a) × (c − a) = 0` exactly: the three points are collinear.
    Collinear,
}

impl Orientation {
    /// The sign as `1`, `-1` or `0`.
    #[must_use]
    pub fn sign(self) -> i8 {
        match self {
            Self::CounterClockwise => 1,
            Self::Clockwise => -1,
            Self::Collinear => 0,
        }
    }

    pub(crate) fn of_determinant(det: f64) -> Self {
        if det > 0.0 {
            Self::CounterClockwise
        } else if det < 0.0 {
            Self::Clockwise
        } else {
            Self::Collinear
        }
    }
}

/// The exact orientation of three points: the sign of `(b − a) × (c − a)`, never wrong.
///
/// A plain f64 determinant with Shewchuk's error bound decides almost every call; the rest are
/// settled by an exact expansion sum of the six f32 × f32 products, each exact in f64. So the
/// sign is exact for every finite f32 input, huge, tiny and subnormal ones included.
///
/// # Errors
/// [`InterpError::NonFinite`] naming the first point (`"a"`, `"b"` or `"c"`) with a NaN or
/// infinite coordinate.
///
/// # Accuracy
/// Exact sign for all finite inputs (Kettner's grid: zero wrong signs; tests
/// `kettner_grid_has_no_wrong_sign` and `orient2d_matches_exact_rational`).
///
/// ```
/// use barytex_interp::{orient2d, Orientation};
/// use glam::Vec2;
/// assert_eq!(orient2d(Vec2::ZERO, Vec2::X, Vec2::Y)?, Orientation::CounterClockwise);
/// assert_eq!(orient2d(Vec2::ZERO, Vec2::Y, Vec2::X)?, Orientation::Clockwise);
/// // 0.1 is not exact in binary; the three points are still exactly collinear.
/// assert_eq!(orient2d(Vec2::ZERO, Vec2::splat(0.1), Vec2::splat(3.0))?, Orientation::Collinear);
/// assert!(orient2d(Vec2::NAN, Vec2::X, Vec2::Y).is_err());
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[inline]
pub fn orient2d(a: Vec2, b: Vec2, c: Vec2) -> Result<Orientation, InterpError> {
    let det = crate::determinant::orient2d_sign_det(a, b, c);
    if det.is_finite() {
        Ok(Orientation::of_determinant(det))
    } else {
        Err(non_finite_point(&[("a", a), ("b", b), ("c", c)]))
    }
}

/// The [`InterpError::NonFinite`] naming the first non-finite point of `named`.
#[cold]
pub(crate) fn non_finite_point<V: NonFinite>(named: &[(&'static str, V)]) -> InterpError {
    let what = named
        .iter()
        .find(|(_, v)| !v.all_finite())
        .map_or("point", |&(name, _)| name);
    InterpError::NonFinite { what }
}

/// `is_finite` for the point types the predicates take.
pub(crate) trait NonFinite: Copy {
    fn all_finite(self) -> bool;
}

impl NonFinite for Vec2 {
    fn all_finite(self) -> bool {
        self.is_finite()
    }
}

impl NonFinite for glam::Vec3 {
    fn all_finite(self) -> bool {
        self.is_finite()
    }
}

/// `(b − a) × (c − a)` with an exact sign and a relative error below 2⁻³⁰; `None` for non-finite
/// input.
#[inline]
pub(crate) fn orient2d_value(a: Vec2, b: Vec2, c: Vec2) -> Option<f64> {
    let det = crate::determinant::orient2d_det(a, b, c);
    det.is_finite().then_some(det)
}

pub(crate) mod methods {
    use glam::Vec2;

    use super::Orientation;

    /// The textbook f32 determinant `(b − a) × (c − a)`: fast, but its sign is wrong near
    /// collinear points (on Kettner's 65 536 grid points, 5 752 to 11 972 wrong signs depending
    /// on which point is the pivot; see `barytex-report`).
    ///
    /// # Accuracy
    /// No sign guarantee; kept for the speed-vs-error report. Returns `Collinear` for NaN input.
    #[must_use]
    pub fn orient2d_naive_f32(a: Vec2, b: Vec2, c: Vec2) -> Orientation {
        Orientation::of_determinant(f64::from((b - a).perp_dot(c - a)))
    }

    /// Kahan's difference of products with a fused multiply-add: `(b − a) × (c − a)` with one
    /// rounding error in the products, still f32 differences.
    ///
    /// # Accuracy
    /// No sign guarantee (the differences `b − a` round); better than naive on Kettner's grid.
    /// Kept for the speed-vs-error report. Returns `Collinear` for NaN input.
    #[must_use]
    pub fn orient2d_dop_f32(a: Vec2, b: Vec2, c: Vec2) -> Orientation {
        let u = b - a;
        let v = c - a;
        Orientation::of_determinant(f64::from(
            crate::barycentric2d::methods::difference_of_products(u.x, v.y, u.y, v.x),
        ))
    }
}
