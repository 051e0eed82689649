//! [`nlerp_corrected_quat`] over slices, four quaternions per SIMD operation.
//!
//! One call interpolates a whole pose (every joint of a skeleton, every particle's
//! orientation). The per-call function spends most of its instructions moving lanes: a 4D dot
//! product is a horizontal sum, and the correction's scalar polynomial runs beside idle lanes.
//! Here the quaternions are transposed in groups of four (structure of arrays: one `Vec4` holds
//! the `x` of four quaternions), so each dot product is three vertical additions and every
//! operation of the correction works on four quaternions at once.
//!
//! The arithmetic is the per-call function's, operation for operation and in the same order
//! (the dot products sum `(x + z) + (y + w)`, as glam's SSE2 `Vec4::dot` does), so on x86-64 the
//! results are bit-identical to [`nlerp_corrected_quat`] and [`nlerp_quat`] (test
//! `batch_equals_the_per_call_functions` in `tests/tests/interp/slerp.rs`).

use glam::{Mat4, Quat, Vec4};

use super::nlerp::{NlerpCorrection, fit, nlerp_corrected_quat, nlerp_quat};
use crate::InterpError;

/// Four quaternions, one `Vec4` per component.
#[derive(Clone, Copy)]
struct Quat4 {
    x: Vec4,
    y: Vec4,
    z: Vec4,
    w: Vec4,
}

impl Quat4 {
    /// A 4×4 transpose (glam's `Mat4::transpose`: eight shuffles with SSE2, where building the
    /// lanes one scalar at a time takes about three times as many).
    #[inline]
    fn load(q: &[Quat; 4]) -> Self {
        let rows = Mat4::from_cols(q[0].into(), q[1].into(), q[2].into(), q[3].into()).transpose();
        Self {
            x: rows.x_axis,
            y: rows.y_axis,
            z: rows.z_axis,
            w: rows.w_axis,
        }
    }

    #[inline]
    fn store(self, out: &mut [Quat; 4]) {
        let columns = Mat4::from_cols(self.x, self.y, self.z, self.w).transpose();
        *out = [
            Quat::from_vec4(columns.x_axis),
            Quat::from_vec4(columns.y_axis),
            Quat::from_vec4(columns.z_axis),
            Quat::from_vec4(columns.w_axis),
        ];
    }

    /// The four dot products, summed `(x + z) + (y + w)` like glam's SSE2 `Vec4::dot`.
    #[inline]
    fn dot(self, other: Self) -> Vec4 {
        (self.x * other.x + self.z * other.z) + (self.y * other.y + self.w * other.w)
    }

    #[inline]
    fn map(self, f: impl Fn(Vec4) -> Vec4) -> Self {
        Self {
            x: f(self.x),
            y: f(self.y),
            z: f(self.z),
            w: f(self.w),
        }
    }

    #[inline]
    fn zip(self, other: Self, f: impl Fn(Vec4, Vec4) -> Vec4) -> Self {
        Self {
            x: f(self.x, other.x),
            y: f(self.y, other.y),
            z: f(self.z, other.z),
            w: f(self.w, other.w),
        }
    }
}

/// The correction's coefficients for four `t` at once, as `corrected_t_coefficients` computes
/// them for one.
#[inline]
fn coefficients4(t: Vec4, correction: Option<NlerpCorrection>) -> [Vec4; 4] {
    let Some(correction) = correction else {
        return [t, Vec4::ZERO, Vec4::ZERO, Vec4::ZERO];
    };
    let c = t - 0.5;
    let s = t * c * (t - 1.0);
    let (a, b) = fit(correction);
    let k = |i: usize| match correction {
        NlerpCorrection::Fast => Vec4::splat(b[i]) * s,
        NlerpCorrection::Precise => (Vec4::splat(a[i]) * (c * c) + Vec4::splat(b[i])) * s,
    };
    [k(0) + t, k(1), k(2), k(3)]
}

/// The group of four: short path (a lane select where the per-call function branches),
/// corrected parameter, lerp, normalization.
#[inline]
fn nlerp4(a: Quat4, b: Quat4, t: Vec4, correction: Option<NlerpCorrection>) -> Quat4 {
    let [c0, c1, c2, c3] = coefficients4(t, correction);
    let d = a.dot(b);
    let negative = d.cmplt(Vec4::ZERO);
    let b = b.map(|v| Vec4::select(negative, -v, v));
    let d = d.abs();
    let t = (c0 + c1 * d) + (d * d) * (c2 + c3 * d);
    let q = a.zip(b, |a, b| a + (b - a) * t);
    // glam's `normalize_or_zero`, lane by lane: the reciprocal of the length, used when finite
    // and positive.
    let reciprocal = Vec4::ONE / q.dot(q).sqrt();
    let usable = reciprocal.cmpgt(Vec4::ZERO) & reciprocal.cmplt(Vec4::INFINITY);
    q.map(|v| Vec4::select(usable, v * reciprocal, Vec4::ZERO))
}

/// Checks that every slice has `out`'s length.
fn check_lengths(a: &[Quat], b: &[Quat], t: &[f32], out: &[Quat]) -> Result<(), InterpError> {
    for (what, len) in [("a", a.len()), ("b", b.len()), ("t", t.len())] {
        if len != out.len() {
            return Err(InterpError::LengthMismatch {
                what,
                len,
                expected: out.len(),
            });
        }
    }
    Ok(())
}

/// The shared loop: groups of four, then the rest one by one.
fn nlerp_slices(
    a: &[Quat],
    b: &[Quat],
    t: &[f32],
    out: &mut [Quat],
    correction: Option<NlerpCorrection>,
) -> Result<(), InterpError> {
    check_lengths(a, b, t, out)?;
    let (a4, a_rest) = a.as_chunks::<4>();
    let (b4, b_rest) = b.as_chunks::<4>();
    let (t4, t_rest) = t.as_chunks::<4>();
    let (out4, out_rest) = out.as_chunks_mut::<4>();
    // One loop per correction, so that the match is decided once, outside.
    let mut groups = |correction: Option<NlerpCorrection>| {
        for (((a, b), t), out) in a4.iter().zip(b4).zip(t4).zip(&mut *out4) {
            nlerp4(
                Quat4::load(a),
                Quat4::load(b),
                Vec4::from_array(*t),
                correction,
            )
            .store(out);
        }
    };
    match correction {
        None => groups(None),
        Some(NlerpCorrection::Fast) => groups(Some(NlerpCorrection::Fast)),
        Some(NlerpCorrection::Precise) => groups(Some(NlerpCorrection::Precise)),
    }
    for (((&a, &b), &t), out) in a_rest.iter().zip(b_rest).zip(t_rest).zip(out_rest) {
        *out = match correction {
            Some(correction) => nlerp_corrected_quat(a, b, t, correction),
            None => nlerp_quat(a, b, t),
        };
    }
    Ok(())
}

/// [`nlerp_corrected_quat`] of every `(a[i], b[i], t[i])` into `out[i]`, four at a time.
///
/// Bit-identical to calling [`nlerp_corrected_quat`] for each element on x86-64 (see the module
/// docs), about twice as fast as that loop on 1024 pairs (`cargo bench -p barytex-benches
/// --bench slerp`, `docs/report/peers.md`).
///
/// # Errors
/// [`InterpError::LengthMismatch`] when `a`, `b` or `t` does not have `out`'s length; nothing
/// is written then.
///
/// # Special values
/// As [`nlerp_corrected_quat`]: unit inputs are assumed, a non-finite input gives the zero
/// quaternion in its slot (and only there).
///
/// # Accuracy
/// As [`nlerp_corrected_quat`].
///
/// ```
/// use barytex_interp::{NlerpCorrection, nlerp_corrected_quat, nlerp_corrected_quats};
/// use glam::Quat;
///
/// let a: Vec<Quat> = (0..10).map(|i| Quat::from_rotation_x(0.1 * i as f32)).collect();
/// let b: Vec<Quat> = (0..10).map(|i| Quat::from_rotation_y(0.2 * i as f32)).collect();
/// let t = vec![0.3; 10];
/// let mut out = vec![Quat::IDENTITY; 10];
/// nlerp_corrected_quats(&a, &b, &t, NlerpCorrection::Precise, &mut out).expect("same lengths");
/// let one = nlerp_corrected_quat(a[7], b[7], 0.3, NlerpCorrection::Precise);
/// assert!(out[7].angle_between(one) < 1e-6);
/// assert!(nlerp_corrected_quats(&a, &b[..9], &t, NlerpCorrection::Fast, &mut out).is_err());
/// ```
pub fn nlerp_corrected_quats(
    a: &[Quat],
    b: &[Quat],
    t: &[f32],
    correction: NlerpCorrection,
    out: &mut [Quat],
) -> Result<(), InterpError> {
    nlerp_slices(a, b, t, out, Some(correction))
}

/// [`nlerp_quat`] of every `(a[i], b[i], t[i])` into `out[i]`, four at a time; bit-identical to
/// the per-call function on x86-64.
///
/// # Errors
/// [`InterpError::LengthMismatch`] when `a`, `b` or `t` does not have `out`'s length; nothing
/// is written then.
///
/// # Accuracy
/// As [`nlerp_quat`].
///
/// ```
/// use barytex_interp::nlerp_quats;
/// use glam::Quat;
///
/// let (a, b) = ([Quat::IDENTITY; 5], [Quat::from_rotation_z(0.4); 5]);
/// let mut out = [Quat::NAN; 5];
/// nlerp_quats(&a, &b, &[0.5; 5], &mut out).expect("same lengths");
/// // Halfway along the arc: the rotation by 0.2 about z (glam's `angle_between` of nearly
/// // equal f32 quaternions is only good to about 1e-3, so compare components).
/// assert!(out.iter().all(|q| (*q - Quat::from_rotation_z(0.2)).length() < 1e-6));
/// ```
pub fn nlerp_quats(a: &[Quat], b: &[Quat], t: &[f32], out: &mut [Quat]) -> Result<(), InterpError> {
    nlerp_slices(a, b, t, out, None)
}
