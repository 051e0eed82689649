//! Distances in units in the last place.

/// The spacing of f32 values at `x`'s magnitude: `ulp(x)`, with `ulp(0)` the smallest subnormal.
#[must_use]
pub fn ulp_f32(x: f64) -> f64 {
    let x = x.abs();
    if !x.is_finite() {
        return f64::INFINITY;
    }
    let min_subnormal = f64::from(f32::from_bits(1));
    if x < f64::from(f32::MIN_POSITIVE) {
        return min_subnormal;
    }
    // 2^(floor(log2 x) − 23), computed from the exponent bits of x as f64.
    let exponent = ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(exponent - 23)
}

/// The number of f32 values strictly between `a` and `b`, plus one (0 when equal); `u64::MAX`
/// when either is NaN.
#[must_use]
pub fn ulps_between_f32(a: f32, b: f32) -> u64 {
    if a.is_nan() || b.is_nan() {
        return u64::MAX;
    }
    let key = |x: f32| {
        let bits = x.to_bits() as i64;
        if bits < 0x8000_0000 {
            bits
        } else {
            0x8000_0000 - bits
        }
    };
    key(a).abs_diff(key(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_of_one_is_epsilon() {
        assert_eq!(ulp_f32(1.0), f64::from(f32::EPSILON));
        assert_eq!(ulp_f32(1.5), f64::from(f32::EPSILON));
        assert_eq!(ulp_f32(2.0), 2.0 * f64::from(f32::EPSILON));
    }

    #[test]
    fn ulps_between_counts_across_zero() {
        assert_eq!(ulps_between_f32(1.0, 1.0), 0);
        assert_eq!(
            ulps_between_f32(1.0, f32::from_bits(1.0f32.to_bits() + 3)),
            3
        );
        assert_eq!(ulps_between_f32(-0.0, 0.0), 0);
        assert_eq!(ulps_between_f32(f32::from_bits(1), -f32::from_bits(1)), 2);
    }
}
