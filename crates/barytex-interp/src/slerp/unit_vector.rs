//! The vector types the SLERP family works on, behind one crate-private trait so the exact
//! algorithm is written once for f32 and f64, 2, 3 and 4 dimensions.

use glam::{DVec2, DVec3, DVec4, Vec2, Vec3, Vec3A, Vec4};

use crate::math;

/// Scalar operations the algorithms need, for f32 and f64.
pub(crate) trait Real: Copy + PartialOrd + core::fmt::Debug {
    const ZERO: Self;
    const ONE: Self;
    /// Unit roundoff bound used to accept an input as already unit length: `4·ε`.
    const UNIT_TOLERANCE: Self;
    fn sub(self, o: Self) -> Self;
    fn abs(self) -> Self;
    fn sqrt(self) -> Self;
}

/// Vector operations the algorithms need, for [`Vec2`], [`Vec3`], [`Vec3A`], [`Vec4`], [`DVec2`],
/// [`DVec3`] and [`DVec4`].
pub(crate) trait Ops: Copy + core::fmt::Debug {
    type Scalar: Real;
    fn add(self, o: Self) -> Self;
    fn sub(self, o: Self) -> Self;
    fn scale(self, s: Self::Scalar) -> Self;
    fn unscale(self, s: Self::Scalar) -> Self;
    fn dot(self, o: Self) -> Self::Scalar;
    fn max_abs_component(self) -> Self::Scalar;
    fn all_finite(self) -> bool;
    /// A unit vector perpendicular to the unit vector `self`, chosen deterministically.
    fn perpendicular(self) -> Self;
}

macro_rules! real {
    ($t:ty, $sqrt:path) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const UNIT_TOLERANCE: Self = 4.0 * <$t>::EPSILON;
            #[inline]
            fn sub(self, o: Self) -> Self {
                self - o
            }
            #[inline]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline]
            fn sqrt(self) -> Self {
                $sqrt(self)
            }
        }
    };
}

real!(f32, math::sqrt_f32);
real!(f64, math::sqrt);

macro_rules! ops {
    ($v:ty, $s:ty, $perp:expr) => {
        impl Ops for $v {
            type Scalar = $s;
            #[inline]
            fn add(self, o: Self) -> Self {
                self + o
            }
            #[inline]
            fn sub(self, o: Self) -> Self {
                self - o
            }
            #[inline]
            fn scale(self, s: $s) -> Self {
                self * s
            }
            #[inline]
            fn unscale(self, s: $s) -> Self {
                self / s
            }
            #[inline]
            fn dot(self, o: Self) -> $s {
                <$v>::dot(self, o)
            }
            #[inline]
            fn max_abs_component(self) -> $s {
                self.abs().max_element()
            }
            #[inline]
            fn all_finite(self) -> bool {
                self.is_finite()
            }
            #[inline]
            fn perpendicular(self) -> Self {
                let perp: fn($v) -> $v = $perp;
                perp(self)
            }
        }
    };
}

// 2D: the counter-clockwise perpendicular. 3D: glam's branch-free orthonormal basis (Duff et al.
// 2017), the same vector on every platform. 4D: `q·k` read as a quaternion product, `(y, −x, w,
// −z)`: perpendicular to `q` for every `q`, so an antipodal quaternion pair turns about the local
// z axis of `q`.
ops!(Vec2, f32, |v| v.perp());
ops!(Vec3, f32, |v| v.any_orthonormal_vector());
ops!(Vec3A, f32, |v| v.any_orthonormal_vector());
ops!(Vec4, f32, |v| Vec4::new(v.y, -v.x, v.w, -v.z));
ops!(DVec2, f64, |v| v.perp());
ops!(DVec3, f64, |v| v.any_orthonormal_vector());
ops!(DVec4, f64, |v| DVec4::new(v.y, -v.x, v.w, -v.z));

/// `v` scaled to unit length, or `None` when `v` is zero or not finite.
///
/// A vector whose squared length is within `4·ε` of 1 is returned unchanged, so unit inputs keep
/// their bits (and SLERP its exact endpoints). Others are first divided by their largest
/// component, so huge (1e38) and tiny (subnormal) vectors normalize without overflow or
/// underflow.
#[inline]
pub(crate) fn unit<V: Ops>(v: V) -> Option<V> {
    let len2 = v.dot(v);
    if len2.sub(V::Scalar::ONE).abs() <= V::Scalar::UNIT_TOLERANCE {
        return Some(v);
    }
    unit_slow(v)
}

#[cold]
fn unit_slow<V: Ops>(v: V) -> Option<V> {
    if !v.all_finite() {
        return None;
    }
    let m = v.max_abs_component();
    if m == V::Scalar::ZERO {
        return None;
    }
    // Divide, not multiply by 1/m: the reciprocal of a subnormal overflows.
    let w = v.unscale(m);
    Some(w.unscale(w.dot(w).sqrt()))
}
