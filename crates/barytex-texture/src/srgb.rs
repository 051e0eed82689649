//! The sRGB transfer function (IEC 61966-2-1): exact byte decode, correctly rounded byte encode.
//!
//! # Accuracy
//! - [`decode`] returns, for every byte, the f32 nearest the exact transfer function (a table
//!   generated with 60-digit arithmetic by `tools/gen_srgb_tables.py`); 0 → 0.0 and 255 → 1.0
//!   exactly. Checked exhaustively against an f64 evaluation in the tests.
//! - [`encode`] is correctly rounded for **every** f32: it returns the byte nearest
//!   `255 · encode_f32(x)` computed exactly (ties cannot occur at f32 inputs). Checked exhaustively
//!   over the f32 values around each of the 255 decision points, and over every f32 in [0, 1].
//! - [`to_linear`] and [`from_linear`] (continuous forms) are within 1 ulp of the exact function
//!   (evaluated in f64).

mod tables;

use tables::{DECODE, ENCODE_THRESHOLDS};

/// The 256-entry decode table: `decode_table()[b]` is the linear value of sRGB byte `b`.
///
/// ```
/// use barytex_texture::srgb;
///
/// let table = srgb::decode_table();
/// assert_eq!((table[0], table[255]), (0.0, 1.0));
/// assert_eq!(table[188], srgb::decode(188));
/// // Decoding is strictly increasing.
/// assert!(table.windows(2).all(|w| w[0] < w[1]));
/// ```
#[must_use]
#[inline]
pub fn decode_table() -> &'static [f32; 256] {
    &DECODE
}

/// sRGB byte → linear value in [0, 1], exactly rounded.
///
/// ```
/// use barytex_texture::srgb;
///
/// // Byte 10 is on the linear segment: (10/255) / 12.92.
/// assert_eq!(srgb::decode(10), (10.0_f64 / 255.0 / 12.92) as f32);
/// // Byte 188 is about 50 % linear light.
/// assert!((srgb::decode(188) - 0.5).abs() < 0.003);
/// ```
#[must_use]
#[inline]
pub fn decode(byte: u8) -> f32 {
    DECODE[usize::from(byte)]
}

/// Linear value → nearest sRGB byte, correctly rounded. Values ≤ 0 and NaN give 0, values ≥ 1 give
/// 255.
///
/// ```
/// use barytex_texture::srgb;
///
/// assert_eq!(srgb::encode(0.5), 188);
/// // encode inverts decode for every byte.
/// assert!((0..=255_u8).all(|b| srgb::encode(srgb::decode(b)) == b));
/// assert_eq!((srgb::encode(f32::NAN), srgb::encode(-1.0), srgb::encode(2.0)), (0, 0, 255));
/// ```
#[must_use]
#[inline]
pub fn encode(linear: f32) -> u8 {
    // The byte is the number of thresholds ≤ x. For x in [2⁻¹⁴, 1) the f32 bits above the 15 low
    // mantissa bits name a bucket (an octave cut into 256 equal parts) that holds at most one
    // threshold (checked when the table is built), so the byte is the bucket's count plus one
    // comparison. Below 2⁻¹⁴ (< the first threshold, 1.5·10⁻⁴) every x gives 0.
    let bits = linear.to_bits();
    let offset = bits.wrapping_sub(LOW_BITS);
    if offset < ONE_BITS - LOW_BITS {
        let start = BUCKET_COUNT[(offset >> BUCKET_SHIFT) as usize];
        return start + u8::from(linear >= THRESHOLDS_PADDED[usize::from(start)]);
    }
    // Outside [2⁻¹⁴, 1): NaN, ≤ 0 and tiny → 0, ≥ 1 → 255.
    if linear >= 1.0 { 255 } else { 0 }
}

/// The bits of 2⁻¹⁴ (below the first threshold) and of 1.0.
const LOW_BITS: u32 = 0x3880_0000;
const ONE_BITS: u32 = 0x3f80_0000;
/// 23 mantissa bits less the 8 that cut an octave into buckets.
const BUCKET_SHIFT: u32 = 15;
const BUCKETS: usize = ((ONE_BITS - LOW_BITS) >> BUCKET_SHIFT) as usize;

/// The thresholds with a 256th that no x < 1 reaches, so a bucket past the last threshold
/// compares against it.
static THRESHOLDS_PADDED: [f32; 256] = padded_thresholds();

const fn padded_thresholds() -> [f32; 256] {
    let mut t = [2.0_f32; 256];
    let mut k = 0;
    while k < 255 {
        t[k] = ENCODE_THRESHOLDS[k];
        k += 1;
    }
    t
}

/// `BUCKET_COUNT[k]`: the number of thresholds ≤ the smallest f32 of bucket `k`.
static BUCKET_COUNT: [u8; BUCKETS] = bucket_counts();

/// Builds the bucket table and checks, at compile time, that no bucket holds two thresholds: the
/// next threshold after the bucket's start must exceed the bucket's largest f32.
const fn bucket_counts() -> [u8; BUCKETS] {
    // Everything below the table encodes to 0.
    assert!(ENCODE_THRESHOLDS[0] > f32::from_bits(LOW_BITS));
    let mut table = [0_u8; BUCKETS];
    let mut k = 0;
    let mut byte = 0_usize;
    while k < BUCKETS {
        let first = f32::from_bits(LOW_BITS + ((k as u32) << BUCKET_SHIFT));
        let last = f32::from_bits(LOW_BITS + (((k as u32) + 1) << BUCKET_SHIFT) - 1);
        while byte < 255 && first >= ENCODE_THRESHOLDS[byte] {
            byte += 1;
        }
        assert!(byte + 1 >= 256 || padded_thresholds()[byte + 1] > last);
        table[k] = byte as u8;
        k += 1;
    }
    table
}

/// The continuous sRGB → linear transfer function on [0, 1] (values outside are clamped, NaN gives
/// 0).
///
/// ```
/// use barytex_texture::srgb;
///
/// assert_eq!(srgb::to_linear(0.0), 0.0);
/// assert_eq!(srgb::to_linear(1.0), 1.0);
/// // The curve is about 0.214 at sRGB 0.5, well below 0.5.
/// assert!((srgb::to_linear(0.5) - 0.214_041).abs() < 1e-6);
/// assert_eq!(srgb::to_linear(f32::NAN), 0.0);
/// ```
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
///
/// ```
/// use barytex_texture::srgb;
///
/// // The inverse of to_linear, within a couple of ulps.
/// let s = 0.3_f32;
/// assert!((srgb::from_linear(srgb::to_linear(s)) - s).abs() <= 2.0 * f32::EPSILON);
/// // Linear 0.5 is about sRGB 0.735 (byte 188 = round(0.735 · 255)).
/// assert!((srgb::from_linear(0.5) - 0.735_357).abs() < 1e-5);
/// assert_eq!(srgb::from_linear(7.0), 1.0);
/// ```
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
    fn encode_equals_counting_thresholds_on_a_dense_sweep() {
        // Every 64th f32 in (0, 1), plus all bucket boundaries' neighbours.
        let count = |x: f32| ENCODE_THRESHOLDS.partition_point(|&t| t <= x);
        let mut bits = 1_u32;
        while f32::from_bits(bits) < 1.0 {
            let x = f32::from_bits(bits);
            assert_eq!(usize::from(encode(x)), count(x), "x = {x:e}");
            bits += 64;
        }
        // Every bucket's first and last f32 and their neighbours, and the four f32s either side
        // of every threshold: with at most one threshold per bucket (checked when the table is
        // built) encode is a step function there, so these cover every place it can change.
        let mut probes = Vec::new();
        for k in 0..=BUCKETS as u32 {
            let first = LOW_BITS + (k << BUCKET_SHIFT);
            probes.extend([first - 2, first - 1, first, first + 1]);
        }
        for t in ENCODE_THRESHOLDS {
            probes.extend((t.to_bits() - 4)..=(t.to_bits() + 4));
        }
        for bits in probes {
            let y = f32::from_bits(bits);
            assert_eq!(usize::from(encode(y)), count(y), "y = {y:e}");
        }
    }

    /// Every f32 from 0 to 1 (2³⁰ values, about 8 s in the test profile here): the byte against a
    /// running count of the thresholds passed.
    #[test]
    fn encode_equals_counting_thresholds_for_every_f32_in_the_unit_interval() {
        let mut count = 0_usize;
        for bits in 0..=1.0_f32.to_bits() {
            let x = f32::from_bits(bits);
            while count < 255 && x >= ENCODE_THRESHOLDS[count] {
                count += 1;
            }
            assert_eq!(usize::from(encode(x)), count, "x = {x:e}");
        }
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
