//! The two trigonometric functions SLERP needs, in f64, as short polynomials on reduced ranges:
//! accurate to ~1e-9, far below what an f32 result can show, and several times faster than the
//! libm calls (which are correctly rounded in f64 but cost 15–40 ns each). Both are written for
//! latency: Estrin's scheme, selects instead of branches, one division.
//!
//! The f32 SLERP functions compute in f64 with these; the f64 ones use libm/std.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// `atan(u)/u` as a polynomial in `u²` for `|u| ≤ tan(π/8)`, fitted by `tools/fit_atan.py`
/// (relative error 6.1e-10 over that range: far below an f32 ulp, and short enough that the
/// polynomial is not the critical path).
const ATAN: [f64; 6] = [
    9.999_999_993_921e-1,
    -3.333_330_749_342_966e-1,
    1.999_821_079_756_873e-1,
    -1.423_998_291_880_683e-1,
    1.057_281_447_620_748e-1,
    -6.033_241_702_961_839e-2,
];

/// `tan(π/8)`: the sector boundaries of the reduction in [`atan2_upper`].
const TAN_PI_8: f64 = 0.414_213_562_373_095_03;

/// The trigonometric functions the SLERP core calls.
pub(crate) trait Trig {
    /// `atan2(y, x)` for `y ≥ 0`: an angle in `[0, π]`.
    fn atan2(y: f64, x: f64) -> f64;
    /// `(sin x, cos x)`.
    fn sin_cos(x: f64) -> (f64, f64);
}

/// std or libm: correctly rounded (or nearly), for the f64 API.
pub(crate) struct Libm;

impl Trig for Libm {
    #[inline]
    fn atan2(y: f64, x: f64) -> f64 {
        crate::math::atan2(y, x)
    }
    #[inline]
    fn sin_cos(x: f64) -> (f64, f64) {
        crate::math::sin_cos(x)
    }
}

/// The polynomials of this module, for the f32 API.
pub(crate) struct Poly;

impl Trig for Poly {
    #[inline]
    fn atan2(y: f64, x: f64) -> f64 {
        atan2_upper(y, x)
    }
    #[inline]
    fn sin_cos(x: f64) -> (f64, f64) {
        sin_cos(x)
    }
}

/// `atan2(y, x)` for `y ≥ 0` and any `x` (not both zero, not NaN): an angle in `[0, π]`.
///
/// The first-quadrant angle `atan2(y, |x|)` is split into three sectors, each needing one
/// division: below π/8 `atan(y/|x|)`, above 3π/8 `π/2 − atan(|x|/y)`, between them
/// `π/4 + atan((y − |x|)/(y + |x|))`; every reduced argument is within `tan(π/8)`. The sectors
/// are chosen by selects rather than branches, as the angles SLERP sees are random.
///
/// # Accuracy
/// Within 1e-9 relative + 1e-15 absolute of `f64::atan2` (unit test
/// `trig_polynomials` below).
#[inline]
pub(crate) fn atan2_upper(y: f64, x: f64) -> f64 {
    let ax = x.abs();
    let low = y <= TAN_PI_8 * ax;
    let high = ax < TAN_PI_8 * y;
    let num = select(low, y, select(high, -ax, y - ax));
    let den = select(low, ax, select(high, y, y + ax));
    let base = select(low, 0.0, select(high, FRAC_PI_2, FRAC_PI_4));
    let u = num / den;
    let z = u * u;
    let first_quadrant = base + u * estrin6(&ATAN, z, z * z);
    select(x < 0.0, PI - first_quadrant, first_quadrant)
}

/// `sin(r)/r` as a polynomial in `r²` for `|r| ≤ π/2` (`tools/fit_sin_cos.py`, error 2.7e-11).
const SIN: [f64; 6] = [
    9.999_999_999_829_727e-1,
    -1.666_666_661_691_718e-1,
    8.333_330_977_501_361e-3,
    -1.984_086_155_307_52e-4,
    2.752_528_711_430_502e-6,
    -2.388_949_862_930_367e-8,
];

/// `cos(r)` as a polynomial in `r²` for `|r| ≤ π/2` (`tools/fit_sin_cos.py`, error 2.2e-10).
const COS: [f64; 6] = [
    9.999_999_997_799_097e-1,
    -4.999_999_935_695_633e-1,
    4.166_663_620_892_759e-2,
    -1.388_836_084_254_816e-3,
    2.476_013_551_688_805e-5,
    -2.605_107_637_942_972e-7,
];

/// A degree-5 polynomial in `z` by Estrin's scheme (depth 3 instead of Horner's 5).
#[inline]
fn estrin6(c: &[f64; 6], z: f64, z2: f64) -> f64 {
    let p01 = c[0] + c[1] * z;
    let p23 = c[2] + c[3] * z;
    let p45 = c[4] + c[5] * z;
    p01 + z2 * (p23 + z2 * p45)
}

/// `(sin x, cos x)` for `x ∈ [0, π]` — every `t·θ` of a SLERP with `t ∈ [0, 1]` — by one
/// pair of polynomials around π/2 (`sin x = cos r`, `cos x = −sin r`, `r = x − π/2`), with no
/// range reduction and no branch; libm outside that interval (extrapolation).
///
/// # Accuracy
/// Within 3e-10 absolute of `f64::sin_cos` on `[0, π]`, libm's accuracy elsewhere (unit test
/// `trig_polynomials` below).
#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if !(0.0..=PI).contains(&x) {
        return crate::math::sin_cos(x);
    }
    let r = x - FRAC_PI_2;
    let z = r * r;
    let z2 = z * z;
    (estrin6(&COS, z, z2), -r * estrin6(&SIN, z, z2))
}

/// `a` if `condition`, else `b`, without a branch: the conditions here depend on random angles,
/// and a mispredicted branch costs more than both arms.
#[inline]
pub(crate) fn select(condition: bool, a: f64, b: f64) -> f64 {
    let mask = 0u64.wrapping_sub(u64::from(condition));
    f64::from_bits((a.to_bits() & mask) | (b.to_bits() & !mask))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trig_polynomials() {
        let mut worst_atan = 0.0f64;
        let mut worst_sin_cos = 0.0f64;
        for i in 0..=200_000 {
            let angle = PI * f64::from(i) / 200_000.0;
            let (s, c) = angle.sin_cos();
            for scale in [1.0, 1e-30, 3e30] {
                let got = atan2_upper(s * scale, c * scale);
                let want = (s * scale).atan2(c * scale);
                worst_atan = worst_atan.max((got - want).abs() / (want.abs() * 1e-9 + 1e-15));
            }
            let (ps, pc) = sin_cos(angle);
            worst_sin_cos = worst_sin_cos.max((ps - s).abs().max((pc - c).abs()));
        }
        assert!(worst_atan <= 1.0, "atan2 error {worst_atan} of its bound");
        assert!(worst_sin_cos <= 3e-10, "sin_cos error {worst_sin_cos}");
        // Outside [0, π]: libm, exactly.
        for x in [-1.0, 4.0, 1e6] {
            assert_eq!(sin_cos(x), x.sin_cos());
        }
        assert_eq!(atan2_upper(0.0, 1.0), 0.0);
        assert_eq!(atan2_upper(1.0, 0.0), FRAC_PI_2);
        assert_eq!(atan2_upper(0.0, -1.0), PI);
    }
}
