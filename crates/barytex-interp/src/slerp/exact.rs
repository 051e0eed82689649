//! Exact SLERP of unit vectors and unit quaternions (seed 003:
//! `n(t) = (sin(θ(1−t))·n₀ + sin(θt)·n₁) / sin θ`), written so that it is accurate for every
//! angle, including 0 and π, and for every `t`.
//!
//! The seed's two-sine formula cancels catastrophically near θ = π (both weights blow up) and
//! needs a special case at θ = 0. The same curve written in the orthonormal frame of the arc,
//! `n(t) = cos(tθ)·a + sin(tθ)·e`, with `e` the unit vector along `p = b − (a·b)·a`, has neither
//! problem, provided `p` is computed without cancellation: `p = n − ((a·n)/(a·a))·a` with
//! `n = b − a` when the vectors are close and `n = b + a` when they are nearly opposite (each
//! component of `n` is then nearly an exact difference, and the projection removes a small
//! correction). Then `θ = atan2(|p|, a·b)`, accurate to a few ulps at every angle (unlike
//! `acos(a·b)` near 0 and π, which glam uses).

use glam::{DQuat, DVec2, DVec3, DVec4, Quat, Vec2, Vec3, Vec3A, Vec4};

use super::short_arc::slerp_short_arc;
use super::trig::{Libm, Poly, Trig, select};
use super::unit_vector::{Ops, unit};
#[allow(unused_imports)] // the doc links of the generated functions
use super::{
    SLERP_F32_ANGLE_BOUND, SLERP_F32_LENGTH_BOUND, SLERP_F64_ANGLE_BOUND, SLERP_F64_LENGTH_BOUND,
};

/// Which of the two arcs between a quaternion and its neighbour's two representatives `±b` to
/// take.
///
/// `q` and `−q` are the same rotation, so a quaternion SLERP has a choice. `Shortest` (the default,
/// and what an animation system wants) negates `b` when `a·b < 0`, so the rotation turns by at most
/// 180°; `AsGiven` interpolates the 4-vectors as they are, which can turn by up to 360° (and
/// between `q` and `−q`, about the deterministic axis of [`slerp_quat`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum QuatPath {
    /// Negate `b` when `a·b < 0`: the shorter rotation. At `t = 1` the result is then `−b`.
    #[default]
    Shortest,
    /// Interpolate `a` to `b` as given.
    AsGiven,
}

/// Relative size below which the perpendicular part of `b` is rounding noise (4·ε).
const PARALLEL_TOLERANCE: f64 = 4.0 * f64::EPSILON;

/// SLERP of unit vectors in f64, any finite `t`, with the trigonometry of `K`.
#[inline]
pub(crate) fn slerp_unit<V: Ops<Scalar = f64>, K: Trig>(a: V, b: V, t: f64) -> V {
    let cos_theta = a.dot(b);
    // Off the critical path: computed while a·b is.
    let inv_aa = 1.0 / a.dot(a);
    // The part of `b` perpendicular to `a`, `p = n − ((a·n)/(a·a))·a`, from whichever of
    // `n = b ∓ a` is the short vector, so that what remains is the subtraction of a small
    // correction. Dividing by `a·a` rather than assuming 1 keeps `p` perpendicular to `a` when
    // `a` is an ulp off unit length, which matters when `n` is mostly radial (equal or opposite
    // directions, lengths differing by rounding) and `p` is much shorter than `n`.
    let sign = select(cos_theta >= 0.0, 1.0, -1.0);
    let near = b.sub(a.scale(sign));
    // Not `a·b ∓ a·a`: that cancels when n is short, and near θ = π the error would be
    // amplified by 1/sin θ.
    let a_near = a.dot(near);
    let near2 = near.dot(near);
    let k = a_near * inv_aa;
    let along = near.sub(a.scale(k));
    // |p|² = |n|² − k·(a·n) lets the square root start before `p` exists. For unit `a`, `b` and
    // the short `n`, |p|² ≥ |n|²/2, so the subtraction loses at most one bit; below |n|²/4 `n`
    // has a radial part (lengths differing by rounding), the formula may cancel, and |p|² is
    // taken from `p` itself. That branch is rare, hence predictable.
    let mut p2 = near2 - k * a_near;
    if p2 < 0.25 * near2 {
        p2 = along.dot(along);
    }
    let sin_theta = crate::math::sqrt(p2);
    // Started now, the division runs in parallel with the trigonometry.
    let inv_sin_theta = 1.0 / sin_theta;
    // `p` is zero in exact arithmetic when `n` is radial, i.e. the directions are equal or
    // opposite and only the lengths differ by rounding; then its computed value is rounding
    // noise pointing anywhere, of the order of ε·|n|. Below 4·ε·|n| it is treated as zero.
    if sin_theta <= PARALLEL_TOLERANCE * crate::math::sqrt(near2) || sin_theta == 0.0 {
        if cos_theta >= 0.0 {
            // The same direction (or the difference underflows): the arc is a point.
            return a;
        }
        // Exactly opposite: every great circle through a and b is an arc of length π. Take the
        // documented deterministic one, through `a.perpendicular()`.
        let (st, ct) = K::sin_cos(t * core::f64::consts::PI);
        return a.scale(ct).add(a.perpendicular().scale(st));
    }
    let theta = K::atan2(sin_theta, cos_theta);
    let (st, ct) = K::sin_cos(t * theta);
    a.scale(ct).add(along.scale(st * inv_sin_theta))
}

/// The checked f64 entry: unit-normalized inputs (see [`unit`]) and a finite `t`, else `None`;
/// exact endpoints.
#[inline]
fn try_slerp_f64<V: Ops<Scalar = f64>>(a: V, b: V, t: f64) -> Option<V> {
    if !t.is_finite() {
        return None;
    }
    let (a, b) = (unit(a)?, unit(b)?);
    Some(if t == 0.0 {
        a
    } else if t == 1.0 {
        b
    } else {
        slerp_unit::<V, Libm>(a, b, t)
    })
}

/// The checked f32 entry: normalized in f32 (so unit inputs keep their bits and the endpoints
/// are exact), computed in f64 — arcs up to 90° with `t ∈ [0, 1]` by the series of
/// [`slerp_short_arc`], others with the polynomial trigonometry — and rounded once at the end.
#[inline]
fn try_slerp_f32<V: Ops<Scalar = f32> + PartialEq, W: Ops<Scalar = f64>>(
    a: V,
    b: V,
    t: f32,
    widen: impl Fn(V) -> W,
    narrow: impl Fn(W) -> V,
) -> Option<V> {
    if !t.is_finite() {
        return None;
    }
    let (a, b) = (unit(a)?, unit(b)?);
    // Equal inputs: the arc is a point (the series would round it to a neighbour).
    Some(if t == 0.0 || a == b {
        a
    } else if t == 1.0 {
        b
    } else {
        let (a, b, t) = (widen(a), widen(b), f64::from(t));
        narrow(if t > 0.0 && t < 1.0 && a.dot(b) >= 0.0 {
            slerp_short_arc(a, b, t)
        } else {
            slerp_unit::<W, Poly>(a, b, t)
        })
    })
}

macro_rules! vector_slerp {
    ($v:ty, $s:ty, $slerp:ident, $try_slerp:ident, $entry:expr, $bound:literal, $example:literal) => {
        #[doc = concat!("SLERP of two unit [`", stringify!($v), "`]s, exact at the ends and unit length everywhere.")]
        ///
        /// Returns the point at fraction `t` of the great-circle arc from `a` to `b`:
        /// `a` at `t = 0` and `b` at `t = 1` bit for bit, constant angular speed in between, and
        /// `t` outside `[0, 1]` continues along the same great circle (extrapolation). The arc is
        /// written in its orthonormal frame, `cos(tθ)·a + sin(tθ)·p̂` with `p` the part of `b`
        /// perpendicular to `a` and `θ = atan2(|p|, a·b)`, accurate at every angle, so nearly
        /// opposite vectors stay on the unit sphere (glam's `Vec3::slerp` loses up to 18 % of the
        /// length within 0.06° of opposite). The f32 functions compute in f64; arcs up to 90° with
        /// `t ∈ [0, 1]` use Eberly's series with 16 balanced factors, whose error is below the
        /// f32 rounding of the result.
        ///
        /// Inputs that are not unit length are normalized first (inputs within `4·ε` of unit
        /// squared length are used as given, so the endpoints stay exact); huge and tiny vectors
        /// normalize without overflow.
        ///
        /// # Special values
        /// - `a == b`: `a` for every `t`.
        /// - `a` and `b` in opposite directions (to rounding): the arc through the
        ///   deterministic perpendicular of `a` — the
        ///   counter-clockwise perpendicular in 2D, glam's `any_orthonormal_vector` in 3D,
        ///   `(y, −x, w, −z)` in 4D.
        /// - A zero or non-finite input, or a non-finite `t`: the zero vector (use the `try_`
        ///   variant to get `None` instead). Never NaN, never panics.
        ///
        /// # Accuracy
        /// For unit inputs and `t` in `[0, 1]`: angle to the exact SLERP (computed in higher
        #[doc = concat!("precision) within ", $bound, " (tests `exact_slerp_*` in `tests/slerp.rs`).")]
        ///
        /// ```
        #[doc = $example]
        /// ```
        #[must_use]
        #[inline]
        pub fn $slerp(a: $v, b: $v, t: $s) -> $v {
            $try_slerp(a, b, t).unwrap_or(<$v>::ZERO)
        }

        #[doc = concat!("[`", stringify!($slerp), "`], or `None` when `a` or `b` is zero or not finite, or `t` is not finite.")]
        ///
        /// # Accuracy
        #[doc = concat!("As [`", stringify!($slerp), "`].")]
        #[must_use]
        #[inline]
        pub fn $try_slerp(a: $v, b: $v, t: $s) -> Option<$v> {
            let entry: fn($v, $v, $s) -> Option<$v> = $entry;
            entry(a, b, t)
        }
    };
}

vector_slerp!(
    Vec2,
    f32,
    slerp_vec2,
    try_slerp_vec2,
    |a, b, t| try_slerp_f32(a, b, t, Vec2::as_dvec2, |w: DVec2| w.as_vec2()),
    "[`SLERP_F32_ANGLE_BOUND`] radians, length within [`SLERP_F32_LENGTH_BOUND`] of 1",
    "use barytex_interp::slerp_vec2;\nuse glam::Vec2;\n\nlet mid = slerp_vec2(Vec2::X, Vec2::Y, 0.5);\nassert!((mid - Vec2::splat(0.5f32.sqrt())).length() < 1e-7);\n// Exactly opposite: the arc through the counter-clockwise perpendicular of `a`.\nassert!((slerp_vec2(Vec2::X, -Vec2::X, 0.5) - Vec2::Y).length() < 1e-7);"
);
vector_slerp!(
    Vec3,
    f32,
    slerp_vec3,
    try_slerp_vec3,
    |a, b, t| try_slerp_f32(a, b, t, Vec3::as_dvec3, |w: DVec3| w.as_vec3()),
    "[`SLERP_F32_ANGLE_BOUND`] radians, length within [`SLERP_F32_LENGTH_BOUND`] of 1",
    "use barytex_interp::slerp_vec3;\nuse glam::Vec3;\n\nlet n = slerp_vec3(Vec3::X, Vec3::Z, 1.0 / 3.0);\nassert!((n.angle_between(Vec3::X) - std::f32::consts::FRAC_PI_6).abs() < 1e-6);\nassert_eq!(slerp_vec3(Vec3::X, Vec3::Z, 1.0), Vec3::Z);"
);
vector_slerp!(
    Vec3A,
    f32,
    slerp_vec3a,
    try_slerp_vec3a,
    |a, b, t| try_slerp_f32(a, b, t, Vec3A::as_dvec3, |w: DVec3| Vec3A::from(
        w.as_vec3()
    )),
    "[`SLERP_F32_ANGLE_BOUND`] radians, length within [`SLERP_F32_LENGTH_BOUND`] of 1",
    "use barytex_interp::slerp_vec3a;\nuse glam::Vec3A;\n\nlet n = slerp_vec3a(Vec3A::X, Vec3A::Y, 0.5);\nassert!((n.length() - 1.0).abs() < 3e-7);"
);
vector_slerp!(
    Vec4,
    f32,
    slerp_vec4,
    try_slerp_vec4,
    |a, b, t| try_slerp_f32(a, b, t, Vec4::as_dvec4, |w: DVec4| w.as_vec4()),
    "[`SLERP_F32_ANGLE_BOUND`] radians, length within [`SLERP_F32_LENGTH_BOUND`] of 1",
    "use barytex_interp::slerp_vec4;\nuse glam::Vec4;\n\nassert_eq!(slerp_vec4(Vec4::X, Vec4::W, 0.0), Vec4::X);"
);
vector_slerp!(
    DVec2,
    f64,
    slerp_dvec2,
    try_slerp_dvec2,
    try_slerp_f64,
    "[`SLERP_F64_ANGLE_BOUND`] radians, length within [`SLERP_F64_LENGTH_BOUND`] of 1",
    "use barytex_interp::slerp_dvec2;\nuse glam::DVec2;\n\nlet mid = slerp_dvec2(DVec2::X, DVec2::Y, 0.5);\nassert!((mid - DVec2::splat(0.5f64.sqrt())).length() < 1e-15);"
);
vector_slerp!(
    DVec3,
    f64,
    slerp_dvec3,
    try_slerp_dvec3,
    try_slerp_f64,
    "[`SLERP_F64_ANGLE_BOUND`] radians, length within [`SLERP_F64_LENGTH_BOUND`] of 1",
    "use barytex_interp::{slerp_dvec3, try_slerp_dvec3};\nuse glam::DVec3;\n\nassert_eq!(try_slerp_dvec3(DVec3::ZERO, DVec3::X, 0.5), None);\nassert_eq!(slerp_dvec3(DVec3::ZERO, DVec3::X, 0.5), DVec3::ZERO);"
);
vector_slerp!(
    DVec4,
    f64,
    slerp_dvec4,
    try_slerp_dvec4,
    try_slerp_f64,
    "[`SLERP_F64_ANGLE_BOUND`] radians, length within [`SLERP_F64_LENGTH_BOUND`] of 1",
    "use barytex_interp::slerp_dvec4;\nuse glam::DVec4;\n\nassert_eq!(slerp_dvec4(DVec4::X, DVec4::Y, 1.0), DVec4::Y);"
);

macro_rules! quat_slerp {
    ($q:ty, $v:ty, $s:ty, $slerp:ident, $try_slerp:ident, $entry:expr, $bound:literal, $example:literal) => {
        #[doc = concat!("SLERP of two unit [`", stringify!($q), "`]s: exact at the ends, unit length, never NaN.")]
        ///
        /// With [`QuatPath::Shortest`] `b` is negated when `a·b < 0` (then `t = 1` returns `−b`
        /// exactly); with [`QuatPath::AsGiven`] the 4-vectors are interpolated as they are.
        /// `t` outside `[0, 1]` extrapolates along the same great circle, also for nearly equal
        /// rotations (glam #356). The algorithm is that of [`slerp_vec4`]: the arc in its
        /// orthonormal frame with `θ = atan2(|p|, a·b)` (f32: the short arc by Eberly's balanced
        /// series in f64), so there is no `acos` near 1 and no threshold switching to nlerp.
        ///
        /// # Special values
        /// - Non-unit inputs are normalized first (inputs within `4·ε` of unit squared length are
        ///   used as given).
        /// - `a == −b` with [`QuatPath::AsGiven`]: the full turn about the local z axis of `a`
        ///   (through the quaternion `a·k`).
        /// - A zero or non-finite input, or a non-finite `t`: the zero quaternion (the `try_`
        ///   variant gives `None`). Never NaN, never panics.
        ///
        /// # Accuracy
        /// For unit inputs and `t` in `[0, 1]`: 4D angle to the exact SLERP (computed in higher
        #[doc = concat!("precision) within ", $bound, "; the rotation angle error is twice the 4D angle")]
        /// (tests `exact_slerp_*` in `tests/slerp.rs`).
        ///
        /// ```
        #[doc = $example]
        /// ```
        #[must_use]
        #[inline]
        pub fn $slerp(a: $q, b: $q, t: $s, path: QuatPath) -> $q {
            $try_slerp(a, b, t, path).unwrap_or(<$q>::from_xyzw(0.0, 0.0, 0.0, 0.0))
        }

        #[doc = concat!("[`", stringify!($slerp), "`], or `None` when `a` or `b` is zero or not finite, or `t` is not finite.")]
        ///
        /// # Accuracy
        #[doc = concat!("As [`", stringify!($slerp), "`].")]
        #[must_use]
        #[inline]
        pub fn $try_slerp(a: $q, b: $q, t: $s, path: QuatPath) -> Option<$q> {
            let entry: fn($v, $v, $s) -> Option<$v> = $entry;
            let (a, mut b) = (<$v>::from(a), <$v>::from(b));
            if path == QuatPath::Shortest && a.dot(b) < 0.0 {
                b = -b;
            }
            entry(a, b, t).map(<$q>::from_vec4)
        }
    };
}

quat_slerp!(
    Quat,
    Vec4,
    f32,
    slerp_quat,
    try_slerp_quat,
    |a, b, t| try_slerp_f32(a, b, t, Vec4::as_dvec4, |w: DVec4| w.as_vec4()),
    "[`SLERP_F32_ANGLE_BOUND`] radians, length within [`SLERP_F32_LENGTH_BOUND`] of 1",
    "use barytex_interp::{slerp_quat, QuatPath};\nuse glam::Quat;\n\nlet a = Quat::from_rotation_z(0.0);\nlet b = Quat::from_rotation_z(1.0);\nlet q = slerp_quat(a, b, 0.25, QuatPath::Shortest);\nassert!(q.angle_between(Quat::from_rotation_z(0.25)) < 1e-6);\n// The short path: -b is the same rotation, the result the same quaternion.\nassert_eq!(slerp_quat(a, -b, 0.25, QuatPath::Shortest), q);"
);
quat_slerp!(
    DQuat,
    DVec4,
    f64,
    slerp_dquat,
    try_slerp_dquat,
    try_slerp_f64,
    "[`SLERP_F64_ANGLE_BOUND`] radians, length within [`SLERP_F64_LENGTH_BOUND`] of 1",
    "use barytex_interp::{slerp_dquat, QuatPath};\nuse glam::DQuat;\n\nlet a = DQuat::from_rotation_x(0.5);\nlet b = DQuat::from_rotation_x(2.5);\nlet q = slerp_dquat(a, b, 2.0, QuatPath::Shortest); // extrapolation\nassert!(q.angle_between(DQuat::from_rotation_x(4.5)) < 1e-14);"
);
