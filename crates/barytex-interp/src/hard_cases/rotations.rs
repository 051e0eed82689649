//! Hard cases for the SLERP family: nearly equal and nearly antipodal rotations, (nearly)
//! antiparallel vectors. The tests compare every method against an f64 reference on each.

use glam::{Quat, Vec3};

/// A named pair of unit quaternions.
#[derive(Clone, Copy, Debug)]
pub struct QuatPairCase {
    /// What makes the case hard.
    pub name: &'static str,
    /// Start rotation.
    pub a: Quat,
    /// End rotation.
    pub b: Quat,
}

/// A named pair of unit vectors.
#[derive(Clone, Copy, Debug)]
pub struct VectorPairCase {
    /// What makes the case hard.
    pub name: &'static str,
    /// Start direction.
    pub a: Vec3,
    /// End direction.
    pub b: Vec3,
}

/// A unit quaternion of no special alignment, so rounding is typical.
fn generic_rotation() -> Quat {
    Quat::from_axis_angle(Vec3::new(0.267, -0.534, 0.802).normalize(), 0.731)
}

/// Quaternion pairs: equal, 1e-8 rad apart (4D angle), 1e-8 rad from antipodal, exactly
/// antipodal, a 180° rotation apart (4D angle 90°, the short path's maximum), nearly 180°, and
/// the audit's nearly opposite pair that is unit only to f32 rounding.
pub fn quaternion_pairs() -> impl Iterator<Item = QuatPairCase> {
    let a = generic_rotation();
    // A rotation by angle φ about an axis moves the quaternion by the 4D angle φ/2.
    let nudge = |four_d_angle: f32| a * Quat::from_rotation_y(2.0 * four_d_angle);
    [
        QuatPairCase {
            name: "equal",
            a,
            b: a,
        },
        QuatPairCase {
            name: "1e-8 rad apart",
            a,
            b: nudge(1e-8),
        },
        QuatPairCase {
            name: "1e-6 rad apart",
            a,
            b: nudge(1e-6),
        },
        QuatPairCase {
            name: "1e-8 rad from antipodal",
            a,
            b: -nudge(1e-8),
        },
        QuatPairCase {
            name: "antipodal (same rotation)",
            a,
            b: -a,
        },
        QuatPairCase {
            name: "4D angle 90° (rotation 180°)",
            a,
            b: nudge(core::f32::consts::FRAC_PI_2),
        },
        QuatPairCase {
            name: "4D angle 90° − 1e-6",
            a,
            b: nudge(core::f32::consts::FRAC_PI_2 - 1e-6),
        },
        // Nearly opposite and unit only to f32 rounding: the plane of the arc (as given) is set
        // by b + a, far below an f32 normalization's rounding, which once turned the arc by
        // 0.109 rad at t = 0.5219818.
        QuatPairCase {
            name: "audit: nearly opposite, not quite unit",
            a: Quat::from_xyzw(-0.301_563_83, 0.707_113, 0.553_461_1, 0.320_517_24),
            b: Quat::from_xyzw(0.301_563_83, -0.707_113_3, -0.553_461_2, -0.320_517_24),
        },
    ]
    .into_iter()
}

/// Vector pairs: equal, 1e-8 rad apart, exactly antiparallel (axis-aligned and generic), and
/// 1e-7, 1e-5 and 1e-3 rad (0.06°, where glam's `Vec3::slerp` loses up to 18 % of the length)
/// from antiparallel; and the audit's two pairs at the edge of the unit tolerance (unit only to
/// within 3.1e-7).
pub fn vector_pairs() -> impl Iterator<Item = VectorPairCase> {
    let a = Vec3::new(0.267, -0.534, 0.802).normalize();
    let axis = a.any_orthonormal_vector();
    let turn = |angle: f32| Quat::from_axis_angle(axis, angle) * a;
    [
        VectorPairCase {
            name: "equal",
            a,
            b: a,
        },
        VectorPairCase {
            name: "1e-8 rad apart",
            a,
            b: turn(1e-8),
        },
        VectorPairCase {
            name: "antiparallel, axis-aligned",
            a: Vec3::X,
            b: -Vec3::X,
        },
        VectorPairCase {
            name: "antiparallel, generic",
            a,
            b: -a,
        },
        VectorPairCase {
            name: "1e-7 rad from antiparallel",
            a,
            b: -turn(1e-7),
        },
        VectorPairCase {
            name: "1e-5 rad from antiparallel",
            a,
            b: -turn(1e-5),
        },
        VectorPairCase {
            name: "1e-3 rad from antiparallel",
            a,
            b: -turn(1e-3),
        },
        // At the edge of the unit tolerance: the first was 2.48e-7 rad off at t = 0.99 (inputs
        // 2ε off unit length used as if unit); the second was accepted as unit with
        // |a| − 1 = 3.06e-7 and returned as given at t = 0.
        VectorPairCase {
            name: "audit: 2ε off unit length, 2.5e-7 rad at t = 0.99",
            a: Vec3::new(0.804_116_25, 0.548_267_84, -0.229_782_48),
            b: Vec3::new(-0.984_735_6, -0.038_564_228, 0.169_730_98),
        },
        VectorPairCase {
            name: "audit: accepted 3.06e-7 off unit length",
            a: Vec3::new(-0.411_605_72, 0.734_760_4, -0.539_173_9),
            b: Vec3::new(0.267, -0.534, 0.802).normalize(),
        },
    ]
    .into_iter()
}
