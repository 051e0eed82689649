//! The SLERP family: exact spherical linear interpolation of unit vectors and unit quaternions,
//! its fast approximations, and normal interpolation for Phong shading.
//!
//! | need | items |
//! |---|---|
//! | exact, total, f32 and f64 | [`slerp`] and [`try_slerp`] for every [`Slerp`] type (`Vec2`, `Vec3`, `Vec3A`, `Vec4`, `Quat` and their `D` twins); [`slerp_along`] and [`try_slerp_along`] for quaternions on a chosen [`QuatPath`] |
//! | fast quaternion approximations | [`nlerp_quat`], [`nlerp_corrected_quat`] with [`NlerpCorrection`], [`slerp_eberly_quat`]; over slices, four at a time: [`nlerp_quats`], [`nlerp_corrected_quats`] |
//! | pick by speed against error | [`QuatInterpolation`] with its `angle_bound` / `length_bound` |
//! | normals | [`interpolate_normal`], [`NormalInterpolation`], [`renormalize_spacing_error`] |

mod eberly;
mod exact;
mod method;
mod nlerp;
mod nlerp_batch;
mod normals;
mod pair;
mod short_arc;
mod trig;
mod unit_vector;

pub use eberly::{EBERLY_MAX_TERMS, slerp_eberly_quat};
pub use exact::{QuatPath, Slerp, SlerpAlong, slerp, slerp_along, try_slerp, try_slerp_along};
pub use method::QuatInterpolation;
pub use nlerp::{NlerpCorrection, nlerp_corrected_quat, nlerp_quat};
pub use nlerp_batch::{nlerp_corrected_quats, nlerp_quats};
pub use normals::{NormalInterpolation, interpolate_normal, renormalize_spacing_error};

/// Largest angle (radians) between an f32 exact SLERP result and the SLERP of its inputs'
/// directions, for every nonzero finite input and `t` in `[0, 1]` (see [`slerp`]'s Accuracy);
/// enforced by `tests/tests/interp/slerp.rs` (`exact_slerp_*` and the edge-case tests).
pub const SLERP_F32_ANGLE_BOUND: f32 = 2.4e-7;
/// Largest `|length − 1|` of an f32 exact SLERP result for every nonzero finite input and `t` in
/// `[0, 1]`, ends included (a unit input returned as given is within 2.385e-7 of unit length).
pub const SLERP_F32_LENGTH_BOUND: f32 = 3.0e-7;
/// Largest angle (radians) between an f64 exact SLERP result and the SLERP of its inputs'
/// directions, for unit inputs and `t` in `[0, 1]` (see [`slerp`]'s Accuracy).
pub const SLERP_F64_ANGLE_BOUND: f64 = 1.0e-15;
/// Largest `|length − 1|` of an f64 exact SLERP result for unit inputs and `t` in `[0, 1]`, ends
/// included (a unit input returned as given is within 4.5e-16 of unit length).
pub const SLERP_F64_LENGTH_BOUND: f64 = 6.0e-16;
