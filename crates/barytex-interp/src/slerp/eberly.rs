//! Eberly's polynomial SLERP ("A Fast and Accurate Algorithm for Computing SLERP", JGT 2011,
//! revised 2018): SLERP with multiply-adds only, no trigonometry, no division, no branch but
//! the short-path sign.
//!
//! With `x = cos θ = a·b ∈ [0, 1]`, SLERP is `f(1 − t, x)·a + f(t, x)·b` where
//! `f(t, x) = sin(tθ)/sin θ` has the power series `Σᵢ aᵢ(t)(x − 1)ⁱ`, `a₀ = t`,
//! `aᵢ = (uᵢ t² − vᵢ)·aᵢ₋₁`, `uᵢ = 1/(i(2i + 1))`, `vᵢ = i/(2i + 1)`. Truncating after `n` factors
//! and scaling the last `uₙ, vₙ` by `1 + μₙ` spreads the truncation error over the domain.
//! Our `μₙ` minimize the maximum coefficient error `|fₙ − f|` over `(t, x) ∈ [0, 1]²`; they
//! are fitted by `tools/fit_eberly_mu.py`, which prints the table below with the coefficient
//! error each achieves.

use glam::{Quat, Vec4};

use super::nlerp::short_path;

/// The most factors [`slerp_eberly_quat`] accepts.
pub const EBERLY_MAX_TERMS: usize = 16;

/// `1 + μₙ` for `n = 1 ..= 16` (index `n − 1`), from `tools/fit_eberly_mu.py`.
const ONE_PLUS_MU: [f64; EBERLY_MAX_TERMS] = [
    1.514_966_099_156_931,
    1.641_017_531_668_537,
    1.712_488_271_294_964,
    1.759_354_467_315_099,
    1.792_705_283_809_558,
    1.817_748_087_277_277,
    1.837_287_253_926_553,
    1.852_980_745_369_931,
    1.865_874_285_249_857,
    1.876_663_006_847_118,
    1.885_827_678_798_232,
    1.893_713_087_939_722,
    1.900_570_837_027_834,
    1.906_590_343_813_583,
    1.911_918_437_020_502,
    1.916_667_572_156_612,
];

/// `(uᵢ, vᵢ)` for `i = 1 ..= n`, the last pair scaled by `1 + μₙ`; index `i − 1`.
const fn coefficients<const N: usize>() -> [(f32, f32); N] {
    let mut table = [(0.0f32, 0.0f32); N];
    let mut i = 1;
    while i <= N {
        let denominator = (2 * i + 1) as f64;
        let mut u = 1.0 / (i as f64 * denominator);
        let mut v = i as f64 / denominator;
        if i == N {
            u *= ONE_PLUS_MU[N - 1];
            v *= ONE_PLUS_MU[N - 1];
        }
        table[i - 1] = (u as f32, v as f32);
        i += 1;
    }
    table
}

struct Table<const N: usize>;

impl<const N: usize> Table<N> {
    const CHECKED: () = assert!(
        N >= 1 && N <= EBERLY_MAX_TERMS,
        "Eberly terms must be 1..=16"
    );
    const UV: [(f32, f32); N] = coefficients::<N>();
}

/// Eberly's polynomial SLERP of unit quaternions with `N` factors (`1 ..= 16`, checked at
/// compile time), on the short path.
///
/// The result lies close to the unit sphere but is not renormalized (that would cost a square
/// root); both its direction and its length errors shrink about 2.3× per extra factor.
///
/// # Special values
/// Unit inputs are assumed (not checked); a non-finite input gives the zero quaternion. Never NaN.
///
/// # Accuracy
/// For `t` in `[0, 1]`: 4D angle to the exact SLERP and `|length − 1|` within the bounds of
/// [`QuatInterpolation::Eberly`](super::QuatInterpolation::Eberly) with `N` terms (test
/// `approximation_bounds` in `tests/tests/interp/slerp.rs`); e.g. 8 terms: see
/// [`QuatInterpolation::angle_bound`](super::QuatInterpolation::angle_bound).
///
/// ```
/// use barytex_interp::{slerp, slerp_eberly_quat};
/// use glam::Quat;
///
/// let (a, b) = (Quat::from_rotation_z(0.3), Quat::from_rotation_y(1.2));
/// let exact = slerp(a, b, 0.7);
/// // Not renormalized: normalize before measuring the angle (glam's is the rotation angle).
/// assert!(slerp_eberly_quat::<8>(a, b, 0.7).normalize().angle_between(exact) < 1e-4);
/// ```
#[must_use]
#[inline]
pub fn slerp_eberly_quat<const N: usize>(a: Quat, b: Quat, t: f32) -> Quat {
    let () = Table::<N>::CHECKED;
    let a = Vec4::from(a);
    let (b, x) = short_path(a, Vec4::from(b));
    let y = x - 1.0;
    let s = 1.0 - t;
    let (s2, t2) = (s * s, t * t);
    // Horner from the innermost factor: fᵢ = 1 + (uᵢ·t² − vᵢ)·y·fᵢ₊₁.
    let (mut fa, mut fb) = (1.0f32, 1.0f32);
    for &(u, v) in Table::<N>::UV.iter().rev() {
        fa = 1.0 + (u * s2 - v) * y * fa;
        fb = 1.0 + (u * t2 - v) * y * fb;
    }
    let r = a * (s * fa) + b * (t * fb);
    if r.is_finite() {
        Quat::from_vec4(r)
    } else {
        Quat::from_xyzw(0.0, 0.0, 0.0, 0.0)
    }
}
