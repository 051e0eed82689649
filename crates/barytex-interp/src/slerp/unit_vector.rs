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

/// The f64 vectors that carry an f32 SLERP: [`DVec2`], [`DVec3`], [`DVec4`].
pub(crate) trait Wide: Ops<Scalar = f64> {
    /// The part of `b` perpendicular to `self`, scaled by `self·self`: `(a·a)·b − (a·b)·a`, and
    /// `|a ∧ b|² = Σᵢ<ⱼ (aⱼbᵢ − aᵢbⱼ)²`, both from the 2×2 minors `aⱼbᵢ − aᵢbⱼ`.
    ///
    /// For f64 copies of f32 vectors each product of two components is exact (48 significant
    /// bits), so each minor is rounded once, correctly, and is zero exactly when the f32 vectors
    /// are parallel: the perpendicular part is accurate to a few ulps relative at every angle and
    /// every ratio of lengths, with no cancellation against the parallel part.
    fn rejection(self, b: Self) -> (Self, f64);
}

/// `(a·a)·b − (a·b)·a` and `|a ∧ b|²` from the minors of `a` and `b` (see [`Wide::rejection`]).
#[inline]
fn rejection_minors<const N: usize>(a: [f64; N], b: [f64; N]) -> ([f64; N], f64) {
    // m[i][j] = a[j]·b[i] − a[i]·b[j]; antisymmetric, so each minor is computed once.
    let mut m = [[0.0; N]; N];
    let mut wedge2 = 0.0;
    for i in 0..N {
        for j in i + 1..N {
            let minor = a[j] * b[i] - a[i] * b[j];
            m[i][j] = minor;
            m[j][i] = -minor;
            wedge2 += minor * minor;
        }
    }
    // pᵢ = Σⱼ aⱼ·m[i][j] = (a·a)·bᵢ − (a·b)·aᵢ. Its terms cannot cancel badly: Σⱼ|aⱼ·m[i][j]| is
    // at most |a|·|m[i]|, while |p| = |a|·|a ∧ b|.
    let p = core::array::from_fn(|i| (0..N).map(|j| a[j] * m[i][j]).sum());
    (p, wedge2)
}

macro_rules! wide {
    ($($v:ty),*) => {$(
        impl Wide for $v {
            #[inline]
            fn rejection(self, b: Self) -> (Self, f64) {
                let (p, wedge2) = rejection_minors(self.to_array(), b.to_array());
                (Self::from_array(p), wedge2)
            }
        }
    )*};
}

wide!(DVec2, DVec3, DVec4);

/// `1/√len2` for a squared length `len2 > 0`, to a few ulps: near 1 (the common case, an input
/// that is already unit to rounding) by the first terms of `(1 + δ)^(−1/2) = 1 − δ/2 + 3δ²/8 − …`,
/// whose error `5|δ|³/16 ≤ 2⁻⁶¹` for `|δ| ≤ 2⁻²⁰` is far below an f64 ulp, without a square root
/// or a division.
#[inline]
pub(crate) fn inverse_length(len2: f64) -> f64 {
    if (len2 - 1.0).abs() <= NEAR_UNIT {
        inverse_length_near(len2)
    } else {
        inverse_length_far(len2)
    }
}

/// [`inverse_length`] far from 1. Out of line and cold, so that the compiler keeps the branch
/// instead of evaluating the square root and division on every call.
#[cold]
#[inline(never)]
pub(crate) fn inverse_length_far(len2: f64) -> f64 {
    1.0 / math::sqrt(len2)
}

/// `â·b̂ − 1 = (a·b)/√((a·a)(b·b)) − 1` from the three dot products, to a few f64 ulps of 1,
/// for squared lengths `aa`, `bb` within [`NEAR_UNIT`] of 1 (see [`is_near_unit`]).
///
/// By the series of [`inverse_length`] in `d = (a·a)(b·b) − 1` (`|d| ≤ 2⁻¹⁹`, so the neglected
/// `5|d|³/16` is below 2⁻⁵⁸), arranged as `((a·b − 1) − (a·b/2)·d) + (3·a·b/8)·d²` so that
/// `a·b − 1` (exact, by Sterbenz, for `a·b ∈ [½, 2]`) and the correction run side by side.
#[inline]
pub(crate) fn cosine_minus_one(ab: f64, aa: f64, bb: f64) -> f64 {
    let d = aa * bb - 1.0;
    ((ab - 1.0) - (0.5 * ab) * d) + (0.375 * ab) * (d * d)
}

/// [`inverse_length`] for `len2` within [`NEAR_UNIT`] of 1: the series alone, no branch.
#[inline]
pub(crate) fn inverse_length_near(len2: f64) -> f64 {
    let d = len2 - 1.0;
    1.0 - d * (0.5 - 0.375 * d)
}

/// Whether both squared lengths are within [`NEAR_UNIT`] of 1, where [`inverse_length_near`]
/// and [`cosine_minus_one`] apply.
#[inline]
pub(crate) fn is_near_unit(aa: f64, bb: f64) -> bool {
    (aa - 1.0).abs() <= NEAR_UNIT && (bb - 1.0).abs() <= NEAR_UNIT
}

/// `|len² − 1|` up to which [`inverse_length`] uses its series (`2⁻²⁰`).
pub(crate) const NEAR_UNIT: f64 = 1.0 / 1_048_576.0;

/// `v` scaled to unit length, or `None` when `v` is zero or not finite.
///
/// A vector whose squared length is within `4·ε` of 1 is returned unchanged, so unit inputs keep
/// their bits (and SLERP its exact endpoints). Others are first divided by their largest
/// component, so huge (1e38) and tiny (subnormal) vectors normalize without overflow or
/// underflow.
#[inline]
pub(crate) fn unit<V: Ops>(v: V) -> Option<V> {
    unit_within(v, V::Scalar::UNIT_TOLERANCE)
}

/// [`unit`] with the squared-length tolerance `tolerance` instead of `4·ε`.
#[inline]
pub(crate) fn unit_within<V: Ops>(v: V, tolerance: V::Scalar) -> Option<V> {
    let len2 = v.dot(v);
    if len2.sub(V::Scalar::ONE).abs() <= tolerance {
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
