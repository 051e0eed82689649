//! The quaternion members of the SLERP family behind one interface, each with its enforced
//! error bound, so a caller (or the report) can pick by speed against error.

use glam::Quat;

use super::eberly::slerp_eberly_quat;
use super::exact::slerp;
use super::nlerp::{NlerpCorrection, nlerp_corrected_quat, nlerp_quat};

/// A way to interpolate unit quaternions on the short path, from exact to cheap.
///
/// Every variant states the largest 4D angle to the exact SLERP ([`angle_bound`]) and the largest
/// `|length − 1|` ([`length_bound`]) it produces for unit inputs and `t` in `[0, 1]`; the test
/// `approximation_bounds` in `tests/tests/interp/slerp.rs` measures both over a dense grid of angles and
/// parameters and fails if either is exceeded, or if a bound is more than twice the measured
/// error (so the bounds stay honest in both directions).
///
/// [`angle_bound`]: QuatInterpolation::angle_bound
/// [`length_bound`]: QuatInterpolation::length_bound
///
/// ```
/// use barytex_interp::QuatInterpolation;
/// use glam::Quat;
///
/// let (a, b) = (Quat::IDENTITY, Quat::from_rotation_z(1.0));
/// for method in [QuatInterpolation::Slerp, QuatInterpolation::Eberly { terms: 8 }] {
///     let q = method.interpolate(a, b, 0.5);
///     assert!(q.angle_between(Quat::from_rotation_z(0.5)) <= 2.0 * method.angle_bound());
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum QuatInterpolation {
    /// [`slerp`] (on the short path): exact to rounding.
    Slerp,
    /// [`nlerp_quat`]: on the arc, not at constant speed.
    Nlerp,
    /// [`nlerp_corrected_quat`] with [`NlerpCorrection::Fast`], Kapoulkine's quadratic `k(d)`.
    NlerpCorrectedFast,
    /// [`nlerp_corrected_quat`] with [`NlerpCorrection::Precise`], Kapoulkine's `t`-dependent fit.
    NlerpCorrected,
    /// [`slerp_eberly_quat`] with `terms` factors, clamped to `1 ..= 16`.
    Eberly {
        /// Number of factors of the series (Eberly's `n`); 8 is his default.
        terms: u8,
    },
}

/// Maxima measured by `approximation_bounds` in tests/tests/interp/slerp.rs (600 quaternion pairs with 4D
/// angles over `[0, π/2]`, 41 parameters each), rounded up: 4D angle, then `|length − 1|`; index
/// `terms − 1`.
const EBERLY_BOUNDS: [(f32, f32); 16] = [
    (0.014, 0.04),
    (0.0035, 0.011),
    (0.0011, 0.0037),
    (0.0004, 0.0014),
    (0.00015, 0.00053),
    (6.1e-5, 0.00021),
    (2.5e-5, 8.8e-5),
    (1e-5, 3.7e-5),
    (4.4e-6, 1.6e-5),
    (1.9e-6, 7.1e-6),
    (9.1e-7, 3.2e-6),
    (4.3e-7, 1.5e-6),
    (2.5e-7, 7.6e-7),
    (2.4e-7, 4.3e-7),
    (2.4e-7, 3.8e-7),
    (2.4e-7, 3e-7),
];

impl QuatInterpolation {
    /// Every variant the crate offers, Eberly with 4, 8, 12 and 16 terms: the report's rows.
    pub const ALL: [Self; 8] = [
        Self::Slerp,
        Self::Nlerp,
        Self::NlerpCorrectedFast,
        Self::NlerpCorrected,
        Self::Eberly { terms: 4 },
        Self::Eberly { terms: 8 },
        Self::Eberly { terms: 12 },
        Self::Eberly { terms: 16 },
    ];

    /// Interpolate from `a` to `b` (on the short path) at `t`.
    ///
    /// # Accuracy
    /// 4D angle to the exact SLERP within [`angle_bound`](Self::angle_bound) and length within
    /// [`length_bound`](Self::length_bound) of 1, for unit inputs and `t` in `[0, 1]`.
    #[must_use]
    #[inline]
    pub fn interpolate(self, a: Quat, b: Quat, t: f32) -> Quat {
        match self {
            Self::Slerp => slerp(a, b, t),
            Self::Nlerp => nlerp_quat(a, b, t),
            Self::NlerpCorrectedFast => nlerp_corrected_quat(a, b, t, NlerpCorrection::Fast),
            Self::NlerpCorrected => nlerp_corrected_quat(a, b, t, NlerpCorrection::Precise),
            Self::Eberly { terms } => eberly(terms, a, b, t),
        }
    }

    /// The largest 4D angle (radians) between this method's result and the exact SLERP, for unit
    /// inputs and `t` in `[0, 1]` (the rotation angle error is twice this).
    #[must_use]
    pub const fn angle_bound(self) -> f32 {
        match self {
            Self::Slerp => super::SLERP_F32_ANGLE_BOUND,
            Self::Nlerp => 7.1e-2,
            Self::NlerpCorrectedFast => 5.4e-3,
            Self::NlerpCorrected => 5.0e-4,
            Self::Eberly { terms } => EBERLY_BOUNDS[clamp_terms(terms) - 1].0,
        }
    }

    /// The largest `|length − 1|` of this method's result, for unit inputs and `t` in `[0, 1]`.
    #[must_use]
    pub const fn length_bound(self) -> f32 {
        match self {
            Self::Slerp => super::SLERP_F32_LENGTH_BOUND,
            Self::Nlerp | Self::NlerpCorrectedFast | Self::NlerpCorrected => 2.4e-7,
            Self::Eberly { terms } => EBERLY_BOUNDS[clamp_terms(terms) - 1].1,
        }
    }

    /// A short name for tables: `slerp`, `nlerp`, `nlerp-corrected-fast`, `nlerp-corrected`,
    /// `eberly-8`, ….
    #[must_use]
    pub fn name(self) -> alloc::string::String {
        match self {
            Self::Slerp => "slerp".into(),
            Self::Nlerp => "nlerp".into(),
            Self::NlerpCorrectedFast => "nlerp-corrected-fast".into(),
            Self::NlerpCorrected => "nlerp-corrected".into(),
            Self::Eberly { terms } => alloc::format!("eberly-{}", clamp_terms(terms)),
        }
    }
}

const fn clamp_terms(terms: u8) -> usize {
    let n = terms as usize;
    if n < 1 {
        1
    } else if n > super::EBERLY_MAX_TERMS {
        super::EBERLY_MAX_TERMS
    } else {
        n
    }
}

/// Runtime `terms` to the const-generic implementation.
fn eberly(terms: u8, a: Quat, b: Quat, t: f32) -> Quat {
    match clamp_terms(terms) {
        1 => slerp_eberly_quat::<1>(a, b, t),
        2 => slerp_eberly_quat::<2>(a, b, t),
        3 => slerp_eberly_quat::<3>(a, b, t),
        4 => slerp_eberly_quat::<4>(a, b, t),
        5 => slerp_eberly_quat::<5>(a, b, t),
        6 => slerp_eberly_quat::<6>(a, b, t),
        7 => slerp_eberly_quat::<7>(a, b, t),
        8 => slerp_eberly_quat::<8>(a, b, t),
        9 => slerp_eberly_quat::<9>(a, b, t),
        10 => slerp_eberly_quat::<10>(a, b, t),
        11 => slerp_eberly_quat::<11>(a, b, t),
        12 => slerp_eberly_quat::<12>(a, b, t),
        13 => slerp_eberly_quat::<13>(a, b, t),
        14 => slerp_eberly_quat::<14>(a, b, t),
        15 => slerp_eberly_quat::<15>(a, b, t),
        _ => slerp_eberly_quat::<16>(a, b, t),
    }
}
