//! Exact SLERP of unit vectors and unit quaternions (Shoemake 1985; Buss 2003, ch. IV:
//! `n(t) = (sin(θ(1−t))·n₀ + sin(θt)·n₁) / sin θ`), written so that it is accurate for every
//! angle, including 0 and π, and for every `t`.
//!
//! The textbook two-sine formula cancels catastrophically near θ = π (both weights blow up) and
//! needs a special case at θ = 0. The same curve written in the orthonormal frame of the arc,
//! `n(t) = cos(tθ)·a + sin(tθ)·e`, with `e` the unit vector along `p = b − (a·b)·a`, has neither
//! problem, provided `p` is computed without cancellation: `p = n − ((a·n)/(a·a))·a` with
//! `n = b − a` when the vectors are close and `n = b + a` when they are nearly opposite (each
//! component of `n` is then nearly an exact difference, and the projection removes a small
//! correction). Then `θ = atan2(|p|, a·b)`, accurate to a few ulps at every angle (unlike
//! `acos(a·b)` near 0 and π, which glam uses).

use glam::{DQuat, DVec2, DVec3, DVec4, Quat, Vec2, Vec3, Vec3A, Vec4};

use super::short_arc::{slerp_quat_short_arc, slerp_short_arc};
use super::trig::{Libm, Poly, Trig, select};
use super::unit_vector::{
    Ops, Wide, cosine_minus_one, inverse_length, inverse_length_far, inverse_length_near,
    is_near_unit, unit, unit_within,
};
#[allow(unused_imports)] // doc links
use super::{
    SLERP_F32_ANGLE_BOUND, SLERP_F32_LENGTH_BOUND, SLERP_F64_ANGLE_BOUND, SLERP_F64_LENGTH_BOUND,
};
use crate::InterpError;

/// Which of the two arcs between a quaternion and its neighbour's two representatives `±b` to
/// take.
///
/// `q` and `−q` are the same rotation, so a quaternion SLERP has a choice. `Shortest` (the default,
/// and what an animation system wants) negates `b` when `a·b < 0`, so the rotation turns by at most
/// 180°; `AsGiven` interpolates the 4-vectors as they are, which can turn by up to 360° (and
/// between `q` and `−q`, about the deterministic axis of [`slerp`]). [`slerp`] takes the short
/// path; [`slerp_along`] takes either.
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

/// SLERP of unit vectors in f64 (the f64 API), any finite `t`, with the trigonometry of `K`.
///
/// `a` and `b` are unit to a few ulps (within [`F64_UNIT_TOLERANCE`] of unit squared length, or
/// normalized by [`unit`]); `a`'s own length is divided out, so the result is unit to the f64
/// rounding of its last steps.
#[inline]
pub(crate) fn slerp_unit<V: Ops<Scalar = f64>, K: Trig>(a: V, b: V, t: f64) -> V {
    let cos_theta = a.dot(b);
    // Off the critical path: computed while a·b is.
    let aa = a.dot(a);
    let inv_aa = 1.0 / aa;
    let a_hat = a.scale(inverse_length(aa));
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
    // |p| = |b|·sin θ; `b`'s length is divided out of the angle below with `a·b/|a|`.
    let sin_theta = crate::math::sqrt(p2);
    // Started now, the division runs in parallel with the trigonometry.
    let inv_sin_theta = 1.0 / sin_theta;
    // `p` is zero in exact arithmetic when `n` is radial, i.e. the directions are equal or
    // opposite and only the lengths differ by rounding; then its computed value is rounding
    // noise pointing anywhere, of the order of ε·|n|. Below 4·ε·|n| it is treated as zero.
    if sin_theta <= PARALLEL_TOLERANCE * crate::math::sqrt(near2) || sin_theta == 0.0 {
        if cos_theta >= 0.0 {
            // The same direction (or the difference underflows): the arc is a point.
            return a_hat;
        }
        // Exactly opposite: every great circle through a and b is an arc of length π. Take the
        // documented deterministic one, through `a.perpendicular()`.
        let (st, ct) = K::sin_cos(t * core::f64::consts::PI);
        return a_hat.scale(ct).add(a_hat.perpendicular().scale(st));
    }
    let theta = K::atan2(sin_theta, cos_theta * inverse_length(aa));
    let (st, ct) = K::sin_cos(t * theta);
    a_hat.scale(ct).add(along.scale(st * inv_sin_theta))
}

/// Squared-length tolerance of the f64 API's unit test: `2·ε` (f64 ε). The f64 dot product that
/// computes `a·a` errs by at most `2·ε` itself, so an accepted input's length is within
/// `√(1 + 4ε) − 1 ≤ 2ε` (4.5e-16) of 1 — below [`SLERP_F64_LENGTH_BOUND`] even at the ends, where
/// the input is returned as given.
const F64_UNIT_TOLERANCE: f64 = 2.0 * f64::EPSILON;

/// Squared-length tolerance of the f32 API's unit test: `4·ε` (f32 ε), applied to `a·a`
/// computed in f64 from the f32 components (exact products, one rounding of 2⁻⁵² at most). An
/// accepted input's length is within `√(1 + 4ε) − 1 < 2ε` (2.385e-7) of 1 — below
/// [`SLERP_F32_LENGTH_BOUND`] even at the ends, where the input is returned as given. glam's
/// `normalize` output passes.
pub(crate) const F32_UNIT_TOLERANCE: f64 = 4.0 * f32::EPSILON as f64;

/// The checked f64 entry: inputs within [`F64_UNIT_TOLERANCE`] of unit squared length used as
/// given, others normalized (see [`unit`]); a finite `t`, else `None`; exact endpoints.
#[inline]
fn try_slerp_f64<V: Ops<Scalar = f64>>(a: V, b: V, t: f64) -> Option<V> {
    if !t.is_finite() {
        return None;
    }
    let (a, b) = (
        unit_within(a, F64_UNIT_TOLERANCE)?,
        unit_within(b, F64_UNIT_TOLERANCE)?,
    );
    Some(if t == 0.0 {
        a
    } else if t == 1.0 {
        b
    } else {
        slerp_unit::<V, Libm>(a, b, t)
    })
}

/// The checked f32 entry. The inputs are widened to f64 exactly and never normalized in f32:
/// an input whose squared length (in f64) is within [`F32_UNIT_TOLERANCE`] of 1 is returned as
/// given at its end (`t = 0` or `1`, or both inputs equal), any other is divided by its f64
/// length there; in between, the arc is that of the inputs' directions, computed from the exact
/// inputs ([`slerp_directions`]) and rounded once to f32.
#[inline]
fn try_slerp_f32<V: Ops<Scalar = f32> + PartialEq, W: Wide>(
    a: V,
    b: V,
    t: f32,
    widen: impl Fn(V) -> W,
    narrow: impl Fn(W) -> V,
) -> Option<V> {
    let (wa, wb) = (widen(a), widen(b));
    let (aa, bb) = (wa.dot(wa), wb.dot(wb));
    // For finite f32 components a·a is finite (≤ 4.7e77) and, unless all are zero, at least
    // 2⁻²⁹⁸: no overflow, no underflow, so this one test finds the zero and non-finite inputs.
    if !(t.is_finite() && aa > 0.0 && aa.is_finite() && bb > 0.0 && bb.is_finite()) {
        return None;
    }
    let end = |v: V, w: W, len2: f64| {
        if (len2 - 1.0).abs() <= F32_UNIT_TOLERANCE {
            v
        } else {
            narrow(w.scale(inverse_length(len2)))
        }
    };
    // Equal inputs: the arc is a point (the series would round it to a neighbour).
    Some(if t == 0.0 || a == b {
        end(a, wa, aa)
    } else if t == 1.0 {
        end(b, wb, bb)
    } else if is_near_unit(aa, bb) {
        // The common case: inverse lengths and `â·b̂ − 1` by short series, no square root.
        let ab = wa.dot(wb);
        let inverse_lengths = (inverse_length_near(aa), inverse_length_near(bb));
        let y = cosine_minus_one(ab, aa, bb);
        narrow(slerp_directions(
            wa,
            wb,
            ab,
            inverse_lengths,
            y,
            f64::from(t),
        ))
    } else {
        narrow(slerp_far_from_unit(wa, wb, (aa, bb), f64::from(t)))
    })
}

/// The interior of [`try_slerp_f32`] for inputs whose squared lengths are not both within 2⁻²⁰
/// of 1 (huge, tiny, or merely not normalized): inverse lengths by square roots. Out of line so
/// that the common case stays small.
#[cold]
#[inline(never)]
fn slerp_far_from_unit<W: Wide>(a: W, b: W, (aa, bb): (f64, f64), t: f64) -> W {
    let ab = a.dot(b);
    let (ra, rb) = (inverse_length_far(aa), inverse_length_far(bb));
    slerp_directions(a, b, ab, (ra, rb), ab * (ra * rb) - 1.0, t)
}

/// SLERP of the directions of `a` and `b` (f64 copies of nonzero finite f32 vectors of any
/// length; `ab = a·b`, `ra`, `rb` their inverse lengths and `y = â·b̂ − 1`) at any finite `t` — arcs up to 90° with
/// `t ∈ (0, 1)` by the polynomials of [`slerp_short_arc`], others with the polynomial trigonometry.
///
/// The long arcs take the perpendicular part of `b` from the exact minors of `a` and `b`
/// ([`Wide::rejection`]), not from normalized copies: for nearly opposite inputs the plane of the
/// arc is fixed by a difference far below the rounding of a normalization (an f32 normalization
/// turned it by 0.1 rad in the case `nearly_opposite_not_quite_unit_inputs` tests), and the
/// minors keep it to a few f64 ulps of its own size. Exactly parallel inputs (all minors zero,
/// decided exactly) are the point `â` or, opposite, the documented half turn.
#[inline]
fn slerp_directions<W: Wide>(a: W, b: W, ab: f64, (ra, rb): (f64, f64), y: f64, t: f64) -> W {
    if t > 0.0 && t < 1.0 && ab >= 0.0 {
        // At most 90° apart: `y = â·b̂ − 1` to a few f64 ulps is all the polynomials need (an
        // error δ in it moves the result by about δ, at every angle — hence the division by the
        // lengths, which an input 2ε off unit length would otherwise turn into a 2.4e-7 error).
        return slerp_short_arc(a, b, y, (ra, rb), t);
    }
    let a_hat = a.scale(ra);
    let (p, wedge2) = a.rejection(b);
    if wedge2 == 0.0 {
        if ab > 0.0 {
            return a_hat;
        }
        let (st, ct) = Poly::sin_cos(t * core::f64::consts::PI);
        return a_hat.scale(ct).add(a_hat.perpendicular().scale(st));
    }
    // |a ∧ b| = |a||b|·sin θ and a·b = |a||b|·cos θ, both to a few ulps relative.
    let theta = Poly::atan2(crate::math::sqrt(wedge2), ab);
    let (st, ct) = Poly::sin_cos(t * theta);
    a_hat
        .scale(ct)
        .add(p.scale(st / crate::math::sqrt(p.dot(p))))
}

/// Why a checked SLERP entry returned `None`: the first bad input in the order `t`, `a`, `b`.
#[cold]
fn rejected<V: Ops>(a: V, b: V, t_is_finite: bool) -> InterpError {
    if !t_is_finite {
        return InterpError::NonFinite { what: "t" };
    }
    for (what, v) in [("a", a), ("b", b)] {
        if !v.all_finite() {
            return InterpError::NonFinite { what };
        }
        if unit(v).is_none() {
            return InterpError::ZeroLength { what };
        }
    }
    // Not reached: the entries fail only for the inputs above.
    InterpError::ZeroLength { what: "a" }
}

mod sealed {
    /// Closes the set of [`Slerp`](super::Slerp) types.
    pub trait Sealed {}

    /// Passed to the hidden methods of [`Slerp`](super::Slerp) and
    /// [`SlerpAlong`](super::SlerpAlong): only this crate can make one, so only the crate's free
    /// functions call them.
    #[derive(Clone, Copy, Debug)]
    pub struct Token(pub(super) ());
}

use sealed::Token;

/// The types [`slerp`] and [`try_slerp`] accept: [`Vec2`], [`Vec3`], [`Vec3A`], [`Vec4`] and
/// [`Quat`] (f32), [`DVec2`], [`DVec3`], [`DVec4`] and [`DQuat`] (f64).
///
/// Implemented for these glam types only (the trait is sealed); call the free functions. (glam's
/// inherent `Vec3::slerp` is a different algorithm, inexact near opposite vectors, and
/// `Vec3::slerp(a, b, t)` names it, not this.)
pub trait Slerp: Copy + sealed::Sealed {
    /// The parameter's type: `f32` for the f32 types, `f64` for the `D` types.
    type Scalar: Copy;
    /// The zero vector or quaternion: [`slerp`]'s result for bad input.
    #[doc(hidden)]
    fn zero(_: Token) -> Self;
    /// [`slerp`], `None` for bad input.
    #[doc(hidden)]
    fn checked(a: Self, b: Self, t: Self::Scalar, _: Token) -> Option<Self>;
    /// Why [`checked`](Self::checked) returned `None`.
    #[doc(hidden)]
    fn rejected(a: Self, b: Self, t: Self::Scalar, _: Token) -> InterpError;
}

/// The quaternion types [`slerp_along`] and [`try_slerp_along`] accept: [`Quat`] and [`DQuat`].
pub trait SlerpAlong: Slerp {
    /// [`slerp_along`], `None` for bad input.
    #[doc(hidden)]
    fn checked_along(a: Self, b: Self, t: Self::Scalar, path: QuatPath, _: Token) -> Option<Self>;
}

/// SLERP of two unit vectors or unit quaternions, exact at the ends and unit length everywhere.
///
/// Returns the point at fraction `t` of the great-circle arc from `a` to `b` (Shoemake,
/// "Animating rotation with quaternion curves", SIGGRAPH 1985; Buss, *3D Computer Graphics*,
/// 2003, §IV.6: `(sin((1 − t)θ)·a + sin(tθ)·b) / sin θ`): `a` at `t = 0` and `b` at `t = 1` bit
/// for bit, constant angular speed in between, and `t` outside `[0, 1]` continues along the same
/// great circle (extrapolation). For every [`Slerp`] type: the f32 vectors [`Vec2`], [`Vec3`],
/// [`Vec3A`], [`Vec4`], the f64 vectors [`DVec2`], [`DVec3`], [`DVec4`], and the quaternions
/// [`Quat`] and [`DQuat`] on the short path ([`slerp_along`] chooses the path).
///
/// The arc is written in its orthonormal frame, `cos(tθ)·a + sin(tθ)·p̂` with `p` the part of `b`
/// perpendicular to `a` and `θ = atan2(|p|, a·b)`, accurate at every angle, so nearly opposite
/// vectors stay on the unit sphere (glam's `Vec3::slerp` loses up to 18 % of the length within
/// 0.06° of opposite), and there is no `acos` near 1 and no threshold switching to nlerp. The f32
/// types compute in f64; arcs up to 90° with `t ∈ [0, 1]` write each weight `sin(sθ)/sin θ` as
/// `s·sinc(sθ)/sinc(θ)` with three short polynomials (in `cos θ − 1` and `(sθ)²`), whose error
/// (8e-9) is below the f32 rounding of the result.
///
/// # Unit inputs
/// An input is *unit* when its squared length, computed in f64 from its components, is within
/// `4·ε` of 1 for the f32 types (`ε = 2⁻²³`; the products are exact and the sum errs by at most
/// 2⁻⁵², so the length itself is within 2.385e-7 of 1) or within `2·ε` for the f64 types
/// (`ε = 2⁻⁵²`; with the f64 dot product's own error the length is within 4.5e-16 of 1). A unit
/// input is returned as given, bit for bit, at its end: `a` at `t = 0`, `b` at `t = 1` (and `a`
/// at every `t` when `a == b`). Any other nonzero finite input is used as a direction: the f32
/// types never normalize in f32 — the arc is computed from the exact inputs in f64 and an end
/// that is not unit is the input divided by its f64 length, rounded once; the f64 types
/// normalize it first (after scaling by its largest component, so 1e300 and subnormal vectors
/// work) and return that at its end.
///
/// # Special values
/// - `a == b`: `a` for every `t`.
/// - `a` and `b` in opposite directions — for the f32 types exactly (decided from the exact
///   inputs: `b = −c·a` with `c > 0`), for the f64 types to rounding — : the arc through the
///   deterministic perpendicular of `a` — the counter-clockwise perpendicular in 2D, glam's
///   `any_orthonormal_vector` in 3D, `(y, −x, w, −z)` in 4D (for a quaternion `a` on the
///   [`QuatPath::AsGiven`] path: the full turn about the local z axis of `a`, through `a·k`).
/// - Quaternions: `b` is negated when `a·b < 0` (then `t = 1` returns `−b` exactly).
/// - A zero or non-finite input, or a non-finite `t`: the zero vector or quaternion
///   ([`try_slerp`] says why instead). Never NaN, never panics.
///
/// # Accuracy
/// The reference is the SLERP of the inputs' *directions* at `t`, computed exactly (to 2⁻¹⁹⁰,
/// in 200-bit fixed point from the exact input values: `barytex_testkit::precise`). For the
/// quaternion types the angle is the 4D angle (the rotation angle error is twice it).
///
/// - f32 types, any nonzero finite inputs (unit or not, at every angle including exactly and
///   nearly equal or opposite), `t ∈ [0, 1]` ends included: angle within
///   [`SLERP_F32_ANGLE_BOUND`] (2.4e-7 rad) and `|length − 1|` within [`SLERP_F32_LENGTH_BOUND`]
///   (3e-7). At a returned unit end the angle is 0 and the length error at most 2.385e-7 (the
///   tolerance above); nearly opposite inputs keep the plane of their arc because its
///   perpendicular part is taken from the exact 2×2 minors of the inputs, not from normalized
///   copies.
/// - f64 types, unit inputs (the tolerance above) or inputs whose f64 normalization is exact
///   enough — i.e. not both nearly opposite *and* outside the tolerance, where normalizing
///   moves the arc's plane by up to about `2⁻⁵²/sin(π − θ)` — and `t ∈ [0, 1]`: within
///   [`SLERP_F64_ANGLE_BOUND`] (1e-15 rad) and [`SLERP_F64_LENGTH_BOUND`] (6e-16).
/// - Extrapolation, `t` outside `[0, 1]`: the length bounds hold unchanged and the angle error
///   is at most `|t|` times the angle bound (the arc's angle error is multiplied by `t`).
///
/// Tests `exact_slerp_*`, `inputs_at_the_edge_of_the_unit_tolerance`,
/// `nearly_opposite_not_quite_unit_inputs` and `extrapolation_continues_the_great_circle` in
/// `tests/tests/interp/slerp.rs`; measured figures and their samples in `docs/ACCURACY.md`.
///
/// ```
/// use barytex_interp::slerp;
/// use glam::{DQuat, DVec2, Quat, Vec2, Vec3, Vec3A, Vec4};
///
/// let mid = slerp(Vec2::X, Vec2::Y, 0.5);
/// assert!((mid - Vec2::splat(0.5f32.sqrt())).length() < 1e-7);
/// // Exactly opposite: the arc through the counter-clockwise perpendicular of `a`.
/// assert!((slerp(Vec2::X, -Vec2::X, 0.5) - Vec2::Y).length() < 1e-7);
///
/// let n = slerp(Vec3::X, Vec3::Z, 1.0 / 3.0);
/// assert!((n.angle_between(Vec3::X) - std::f32::consts::FRAC_PI_6).abs() < 1e-6);
/// assert_eq!(slerp(Vec3::X, Vec3::Z, 1.0), Vec3::Z);
/// assert!((slerp(Vec3A::X, Vec3A::Y, 0.5).length() - 1.0).abs() < 3e-7);
/// assert_eq!(slerp(Vec4::X, Vec4::W, 0.0), Vec4::X);
/// let mid = slerp(DVec2::X, DVec2::Y, 0.5);
/// assert!((mid - DVec2::splat(0.5f64.sqrt())).length() < 1e-15);
///
/// let (a, b) = (Quat::from_rotation_z(0.0), Quat::from_rotation_z(1.0));
/// let q = slerp(a, b, 0.25);
/// assert!(q.angle_between(Quat::from_rotation_z(0.25)) < 1e-6);
/// // The short path: -b is the same rotation, the result the same quaternion.
/// assert_eq!(slerp(a, -b, 0.25), q);
/// // Extrapolation, in f64.
/// let q = slerp(DQuat::from_rotation_x(0.5), DQuat::from_rotation_x(2.5), 2.0);
/// assert!(q.angle_between(DQuat::from_rotation_x(4.5)) < 1e-14);
/// ```
#[must_use]
#[inline]
pub fn slerp<V: Slerp>(a: V, b: V, t: V::Scalar) -> V {
    V::checked(a, b, t, Token(())).unwrap_or_else(|| V::zero(Token(())))
}

/// [`slerp`], or why it cannot be computed.
///
/// # Errors
/// The first bad input in the order `t`, `a`, `b`: [`InterpError::NonFinite`] (`what` is `"t"`,
/// `"a"` or `"b"`) for a NaN or infinite one, [`InterpError::ZeroLength`] (`"a"` or `"b"`) for
/// a zero vector or quaternion. [`slerp`] returns zero for exactly these inputs.
///
/// # Accuracy
/// As [`slerp`].
///
/// ```
/// use barytex_interp::{slerp, try_slerp, InterpError};
/// use glam::{DVec3, Vec3};
///
/// assert_eq!(try_slerp(DVec3::ZERO, DVec3::X, 0.5), Err(InterpError::ZeroLength { what: "a" }));
/// assert_eq!(slerp(DVec3::ZERO, DVec3::X, 0.5), DVec3::ZERO);
/// assert_eq!(try_slerp(Vec3::X, Vec3::Y, f32::NAN), Err(InterpError::NonFinite { what: "t" }));
/// assert_eq!(try_slerp(Vec3::X, Vec3::Y, 1.0), Ok(Vec3::Y));
/// ```
#[inline]
pub fn try_slerp<V: Slerp>(a: V, b: V, t: V::Scalar) -> Result<V, InterpError> {
    V::checked(a, b, t, Token(())).ok_or_else(|| V::rejected(a, b, t, Token(())))
}

/// [`slerp`] of unit quaternions along the chosen [`QuatPath`].
///
/// [`QuatPath::Shortest`] is [`slerp`]; [`QuatPath::AsGiven`] interpolates the 4-vectors as they
/// are, which can turn by up to 360° (and between `q` and `−q` turns about the local z axis of
/// `q`, through the quaternion `q·k`).
///
/// # Special values
/// As [`slerp`]: zero for a zero or non-finite input or a non-finite `t`, never NaN.
///
/// # Accuracy
/// As [`slerp`] (tests `exact_slerp_quat_within_bounds` and `exact_slerp_f64_within_bounds`).
///
/// ```
/// use barytex_interp::{slerp, slerp_along, QuatPath};
/// use glam::Quat;
///
/// let (a, b) = (Quat::IDENTITY, -Quat::from_rotation_y(0.5));
/// assert_eq!(slerp_along(a, b, 0.4, QuatPath::Shortest), slerp(a, b, 0.4));
/// // As given, the arc from the identity to −b turns the long way: by 2π − 0.5 in all.
/// let long = slerp_along(a, b, 0.5, QuatPath::AsGiven);
/// let expected = Quat::from_rotation_y(0.25 - std::f32::consts::PI);
/// assert!(long.dot(expected).abs() > 1.0 - 1e-6);
/// assert_eq!(slerp_along(a, b, 1.0, QuatPath::AsGiven), b);
/// ```
#[must_use]
#[inline]
pub fn slerp_along<Q: SlerpAlong>(a: Q, b: Q, t: Q::Scalar, path: QuatPath) -> Q {
    Q::checked_along(a, b, t, path, Token(())).unwrap_or_else(|| Q::zero(Token(())))
}

/// [`slerp_along`], or why it cannot be computed.
///
/// # Errors
/// As [`try_slerp`].
///
/// # Accuracy
/// As [`slerp`].
///
/// ```
/// use barytex_interp::{try_slerp_along, InterpError, QuatPath};
/// use glam::Quat;
///
/// let zero = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
/// let r = try_slerp_along(Quat::IDENTITY, zero, 0.5, QuatPath::AsGiven);
/// assert_eq!(r, Err(InterpError::ZeroLength { what: "b" }));
/// ```
#[inline]
pub fn try_slerp_along<Q: SlerpAlong>(
    a: Q,
    b: Q,
    t: Q::Scalar,
    path: QuatPath,
) -> Result<Q, InterpError> {
    Q::checked_along(a, b, t, path, Token(())).ok_or_else(|| Q::rejected(a, b, t, Token(())))
}

macro_rules! vector_slerp {
    ($v:ty, $s:ty, $entry:expr) => {
        impl sealed::Sealed for $v {}

        impl Slerp for $v {
            type Scalar = $s;
            #[inline]
            fn zero(_: Token) -> Self {
                <$v>::ZERO
            }
            #[inline]
            fn checked(a: Self, b: Self, t: $s, _: Token) -> Option<Self> {
                let entry: fn($v, $v, $s) -> Option<$v> = $entry;
                entry(a, b, t)
            }
            fn rejected(a: Self, b: Self, t: $s, _: Token) -> InterpError {
                rejected(a, b, t.is_finite())
            }
        }
    };
}

vector_slerp!(Vec2, f32, |a, b, t| try_slerp_f32(
    a,
    b,
    t,
    Vec2::as_dvec2,
    |w: DVec2| w.as_vec2()
));
vector_slerp!(Vec3, f32, |a, b, t| try_slerp_f32(
    a,
    b,
    t,
    Vec3::as_dvec3,
    |w: DVec3| w.as_vec3()
));
vector_slerp!(Vec3A, f32, |a, b, t| try_slerp_f32(
    a,
    b,
    t,
    Vec3A::as_dvec3,
    |w: DVec3| Vec3A::from(w.as_vec3())
));
vector_slerp!(Vec4, f32, |a, b, t| try_slerp_f32(
    a,
    b,
    t,
    Vec4::as_dvec4,
    |w: DVec4| w.as_vec4()
));
vector_slerp!(DVec2, f64, try_slerp_f64);
vector_slerp!(DVec3, f64, try_slerp_f64);
vector_slerp!(DVec4, f64, try_slerp_f64);

/// The f32 quaternion entry: the common case ([`slerp_quat_short_arc`]) inline, everything else
/// ([`try_slerp_f32`]) out of line, so that the common case, small, can be inlined into a loop.
#[inline]
fn try_slerp_quat(a: Vec4, b: Vec4, t: f32) -> Option<Vec4> {
    slerp_quat_short_arc(a, b, t).or_else(|| try_slerp_quat_general(a, b, t))
}

/// [`try_slerp_quat`] outside the common case.
#[inline(never)]
fn try_slerp_quat_general(a: Vec4, b: Vec4, t: f32) -> Option<Vec4> {
    try_slerp_f32(a, b, t, Vec4::as_dvec4, |w: DVec4| w.as_vec4())
}

macro_rules! quat_slerp {
    ($q:ty, $v:ty, $s:ty, $entry:expr) => {
        impl sealed::Sealed for $q {}

        impl Slerp for $q {
            type Scalar = $s;
            #[inline]
            fn zero(_: Token) -> Self {
                <$q>::from_xyzw(0.0, 0.0, 0.0, 0.0)
            }
            #[inline]
            fn checked(a: Self, b: Self, t: $s, token: Token) -> Option<Self> {
                Self::checked_along(a, b, t, QuatPath::Shortest, token)
            }
            fn rejected(a: Self, b: Self, t: $s, _: Token) -> InterpError {
                rejected(<$v>::from(a), <$v>::from(b), t.is_finite())
            }
        }

        impl SlerpAlong for $q {
            #[inline]
            fn checked_along(a: Self, b: Self, t: $s, path: QuatPath, _: Token) -> Option<Self> {
                let entry: fn($v, $v, $s) -> Option<$v> = $entry;
                let (a, mut b) = (<$v>::from(a), <$v>::from(b));
                if path == QuatPath::Shortest && a.dot(b) < 0.0 {
                    b = -b;
                }
                entry(a, b, t).map(<$q>::from_vec4)
            }
        }
    };
}

quat_slerp!(Quat, Vec4, f32, try_slerp_quat);
quat_slerp!(DQuat, DVec4, f64, try_slerp_f64);
