//! The sRGB transfer function (IEC 61966-2-1): exact byte decode, correctly rounded byte encode.
//!
//! # Accuracy
//! - [`decode`] returns, for every byte, the f32 nearest the exact transfer function (a table
//!   generated with 60-digit arithmetic by `tools/gen_srgb_tables.py`); 0 → 0.0 and 255 → 1.0
//!   exactly. Checked exhaustively against an f64 evaluation in the tests.
//! - [`encode`] is correctly rounded for **every** f32: it returns the byte nearest
//!   `255 · encode_f32(x)` computed exactly (ties cannot occur at f32 inputs). Checked exhaustively
//!   over the f32 values around each of the 255 decision points.
//! - [`to_linear`] and [`from_linear`] (continuous forms) are within 1 ulp of the exact function
//!   (evaluated in f64).

mod tables;

use tables::{DECODE, ENCODE_THRESHOLDS};

/// The 256-entry decode table: `decode_table()[b]` is the linear value of sRGB byte `b`.
#[must_use]
#[inline]
pub fn decode_table() -> &'static [f32; 256] {
    &DECODE
}

/// sRGB byte → linear value in [0, 1], exactly rounded.
#[must_use]
#[inline]
pub fn decode(byte: u8) -> f32 {
    DECODE[usize::from(byte)]
}

/// Linear value → nearest sRGB byte, correctly rounded. Values ≤ 0 and NaN give 0, values ≥ 1 give
/// 255.
#[must_use]
#[inline]
pub fn encode(linear: f32) -> u8 {
    // The number of thresholds ≤ x is the byte. NaN compares false everywhere: 0.
    let count = ENCODE_THRESHOLDS.partition_point(|&t| t <= linear);
    // partition_point returns at most 255.
    u8::try_from(count).unwrap_or(u8::MAX)
}

/// The continuous sRGB → linear transfer function on [0, 1] (values outside are clamped, NaN gives
/// 0).
#[must_use]
pub fn to_linear(srgb: f32) -> f32 {
    let c = f64::from(clamp_unit(srgb));
    let linear = if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    };
    linear as f32
}

/// The continuous linear → sRGB transfer function on [0, 1] (values outside are clamped, NaN gives
/// 0).
#[must_use]
pub fn from_linear(linear: f32) -> f32 {
    let l = f64::from(clamp_unit(linear));
    let srgb = if l <= 0.003_130_8 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    srgb as f32
}

fn clamp_unit(x: f32) -> f32 {
    if x.is_nan() { 0.0 } else { x.clamp(0.0, 1.0) }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact_decode(byte: u8) -> f64 {
        let c = f64::from(byte) / 255.0;
        if c <= 0.040_45 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    }

    #[test]
    fn decode_is_the_nearest_f32_for_every_byte() {
        for byte in 0..=255_u8 {
            let got = f64::from(decode(byte));
            let exact = exact_decode(byte);
            let ulp = f64::from(f32::EPSILON) * exact.abs().max(f64::from(f32::MIN_POSITIVE));
            assert!(
                (got - exact).abs() <= 0.5 * ulp * 1.000_001,
                "byte {byte}: {got} vs {exact}"
            );
        }
        assert_eq!(decode(0), 0.0);
        assert_eq!(decode(255), 1.0);
    }

    #[test]
    fn encode_inverts_decode_and_is_monotone() {
        for byte in 0..=255_u8 {
            assert_eq!(encode(decode(byte)), byte);
        }
        assert_eq!(encode(f32::NAN), 0);
        assert_eq!(encode(-1.0), 0);
        assert_eq!(encode(f32::INFINITY), 255);
        assert_eq!(encode(2.0), 255);
    }

    #[test]
    fn encode_is_correctly_rounded_around_every_decision_point() {
        // Walk 64 f32 values either side of each threshold and compare with an f64 evaluation.
        for &t in &ENCODE_THRESHOLDS {
            let bits = t.to_bits();
            for offset in -64_i32..64 {
                let x = f32::from_bits(bits.wrapping_add_signed(offset));
                let exact = from_linear_f64(f64::from(x)) * 255.0;
                let want = exact.round();
                // The f64 evaluation may itself sit within 1e-12 of the .5 boundary: skip those.
                if (exact - exact.floor() - 0.5).abs() < 1e-9 {
                    continue;
                }
                assert_eq!(f64::from(encode(x)), want, "x = {x:e}");
            }
        }
    }

    fn from_linear_f64(l: f64) -> f64 {
        if l <= 0.003_130_8 {
            l * 12.92
        } else {
            1.055 * l.powf(1.0 / 2.4) - 0.055
        }
    }

    #[test]
    fn continuous_forms_round_trip() {
        for byte in 0..=255_u8 {
            let s = f32::from(byte) / 255.0;
            let back = from_linear(to_linear(s));
            assert!((back - s).abs() <= 2.0 * f32::EPSILON, "{byte}: {back}");
        }
    }
}
