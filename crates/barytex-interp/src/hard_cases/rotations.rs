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
/// antipodal, a 180° rotation apart (4D angle 90°, the short path's maximum), and nearly 180°.
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
    ]
    .into_iter()
}

/// Vector pairs: equal, 1e-8 rad apart, exactly antiparallel (axis-aligned and generic), and
/// 1e-7, 1e-5 and 1e-3 rad (0.06°, where glam's `Vec3::slerp` loses up to 18 % of the length)
/// from antiparallel.
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
    ]
    .into_iter()
}
