//! Texel addressing exactly as the Vulkan specification defines it ("Texel Coordinate Systems",
//! "Wrapping Operation"): coordinates are scaled to texel space, floored to integer indices, and
//! the address mode is applied to the **integers**.
//!
//! - nearest: `i = ⌊u·w⌋`
//! - linear: `i₀ = ⌊u·w − ½⌋`, `i₁ = i₀ + 1`, `α = frac(u·w − ½)`
//! - repeat: `i mod w`; mirrored repeat: `(w − 1) − mirror((i mod 2w) − w)` with
//!   `mirror(n) = n ≥ 0 ? n : −(1 + n)`; clamp to edge: `clamp(i, 0, w − 1)`; clamp to border:
//!   indices outside `[0, w)` read the border colour.
//!
//! `u·w` is computed in f64, where it is exact for every f32 `u` and every side up to 2²⁹, so
//! indices and weights are those of the exact formula, rounded once (a weight to f32).
//! Indices are `i64`, so `u·w` up to the f32 range neither overflows nor wraps wrongly (they
//! saturate at ±2⁶³; neighbours of a saturated index are formed with saturating adds); a NaN
//! coordinate floors to index 0 (Rust's saturating float → int cast), documented rather than
//! undefined.

use crate::sampler::AddressMode;

/// The texel index `⌊u·size⌋` of nearest filtering, before wrapping.
///
/// ```
/// use barytex_texture::addressing::nearest_index;
///
/// assert_eq!(nearest_index(0.0, 4), 0);
/// assert_eq!(nearest_index(0.999_999, 4), 3);
/// assert_eq!(nearest_index(-0.01, 4), -1); // wrapping comes later
/// assert_eq!(nearest_index(f32::NAN, 4), 0);
/// ```
#[must_use]
#[inline]
pub fn nearest_index(u: f32, size: u32) -> i64 {
    // Exact in f64; the cast saturates at ±2⁶³ and maps NaN to 0.
    floor(f64::from(u) * f64::from(size)).0
}

/// `(⌊x⌋ as i64, x − ⌊x⌋)` without calling `f64::floor`, which is a library call on the x86-64
/// baseline (no SSE4.1) and dominated the cost of a bilinear lookup. Values beyond ±2⁵² are
/// integers already; NaN gives `(0, NaN)`.
#[inline]
fn floor(x: f64) -> (i64, f64) {
    const EXACT: f64 = 4_503_599_627_370_496.0; // 2⁵²
    if x.abs() < EXACT {
        let t = x as i64; // truncation toward zero, exact here
        let t = if (t as f64) > x { t - 1 } else { t };
        (t, x - t as f64)
    } else {
        // Saturating cast; NaN → 0.
        (x as i64, if x.is_nan() { x } else { 0.0 })
    }
}

/// The two texel indices and the blend weight of linear filtering along one axis, before
/// wrapping: the result is `(1 − frac)·texel[i0] + frac·texel[i0 + 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearTaps {
    /// The lower index `⌊u·size − ½⌋`.
    pub i0: i64,
    /// The weight of texel `i0 + 1`, in [0, 1).
    pub frac: f32,
}

/// The taps of linear filtering at coordinate `u` over `size` texels.
///
/// `u·size − ½` and its fraction are computed exactly in f64 (sides up to 2²⁹), then the weight
/// is rounded once to f32. A non-finite `u` gives index 0 and weight 0.
///
/// ```
/// use barytex_texture::addressing::{LinearTaps, linear_taps};
///
/// // At texel 1's centre all the weight is on texel 1.
/// assert_eq!(linear_taps(0.375, 4), LinearTaps { i0: 1, frac: 0.0 });
/// // Halfway between the centres of texels 1 and 2.
/// assert_eq!(linear_taps(0.5, 4), LinearTaps { i0: 1, frac: 0.5 });
/// // Left of texel 0's centre the lower tap is index −1.
/// assert_eq!(linear_taps(0.0, 4), LinearTaps { i0: -1, frac: 0.5 });
/// ```
#[must_use]
#[inline]
pub fn linear_taps(u: f32, size: u32) -> LinearTaps {
    let (i0, frac) = floor(f64::from(u) * f64::from(size) - 0.5);
    if frac.is_finite() {
        LinearTaps {
            i0,
            frac: frac as f32,
        }
    } else {
        LinearTaps { i0: 0, frac: 0.0 }
    }
}

/// Applies an address mode to an integer texel index; `None` means "read the border colour"
/// ([`AddressMode::ClampToBorder`] outside `[0, size)`). Every texture side is at least 1; a
/// `size` of 0 is treated as 1.
///
/// ```
/// use barytex_texture::addressing::wrap;
/// use barytex_texture::sampler::AddressMode;
///
/// assert_eq!(wrap(5, 4, AddressMode::Repeat), Some(1));
/// assert_eq!(wrap(-1, 4, AddressMode::Repeat), Some(3));
/// assert_eq!(wrap(4, 4, AddressMode::MirrorRepeat), Some(3)); // 0 1 2 3 | 3 2 1 0
/// assert_eq!(wrap(-1, 4, AddressMode::MirrorRepeat), Some(0));
/// assert_eq!(wrap(9, 4, AddressMode::ClampToEdge), Some(3));
/// assert_eq!(wrap(4, 4, AddressMode::ClampToBorder), None);
/// ```
#[must_use]
#[inline]
pub fn wrap(i: i64, size: u32, mode: AddressMode) -> Option<u32> {
    let size = i64::from(size.max(1));
    // An index inside the texture is its own address under every mode (for the mirror:
    // `i − size ∈ [−size, 0)` mirrors to `size − 1 − i`, which maps back to `i`). Most taps of
    // a lookup are inside, and this spares them the 64-bit divisions below.
    if (0..size).contains(&i) {
        return Some(i as u32);
    }
    let wrapped = match mode {
        AddressMode::ClampToEdge => i.clamp(0, size - 1),
        // Two's complement: for a power-of-two size the low bits are the Euclidean remainder.
        AddressMode::Repeat if size & (size - 1) == 0 => i & (size - 1),
        AddressMode::Repeat => i.rem_euclid(size),
        AddressMode::MirrorRepeat => {
            let t = i.rem_euclid(2 * size) - size;
            let mirror = if t >= 0 { t } else { -(1 + t) };
            (size - 1) - mirror
        }
        // Inside indices returned above: this one is outside, so it reads the border.
        AddressMode::ClampToBorder => return None,
    };
    // In [0, size) ⊂ u32.
    u32::try_from(wrapped).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_and_linear_follow_the_spec_formulas() {
        assert_eq!(nearest_index(0.0, 4), 0);
        assert_eq!(nearest_index(0.999_999, 4), 3);
        assert_eq!(nearest_index(-0.01, 4), -1);
        // At a texel centre the linear taps put all weight on that texel.
        assert_eq!(linear_taps(0.375, 4), LinearTaps { i0: 1, frac: 0.0 });
        // Halfway between texel centres 1 and 2.
        assert_eq!(linear_taps(0.5, 4), LinearTaps { i0: 1, frac: 0.5 });
        assert_eq!(linear_taps(0.0, 4), LinearTaps { i0: -1, frac: 0.5 });
        assert_eq!(linear_taps(f32::NAN, 4), LinearTaps { i0: 0, frac: 0.0 });
    }

    #[test]
    fn floor_matches_the_library_floor() {
        for x in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            2.999_999,
            -2.000_001,
            1e15 + 0.5,
            -1e15 - 0.5,
            4_503_599_627_370_495.5,
            -4_503_599_627_370_495.5,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            let (i, f) = floor(x);
            assert_eq!(i, x.floor() as i64, "{x}");
            if x.abs() < 1e16 {
                assert_eq!(f, x - x.floor(), "{x}");
            } else {
                assert_eq!(f, 0.0, "{x}");
            }
        }
        assert_eq!(floor(f64::NAN).0, 0);
    }

    /// The specification's formulas with no shortcut (the in-range and power-of-two paths of
    /// `wrap` must agree with them).
    fn wrap_by_formula(i: i64, size: u32, mode: AddressMode) -> Option<u32> {
        let size = i64::from(size.max(1));
        let wrapped = match mode {
            AddressMode::ClampToEdge => i.clamp(0, size - 1),
            AddressMode::Repeat => i.rem_euclid(size),
            AddressMode::MirrorRepeat => {
                let t = i.rem_euclid(2 * size) - size;
                (size - 1) - if t >= 0 { t } else { -(1 + t) }
            }
            AddressMode::ClampToBorder => {
                if (0..size).contains(&i) {
                    i
                } else {
                    return None;
                }
            }
        };
        u32::try_from(wrapped).ok()
    }

    #[test]
    fn shortcuts_agree_with_the_formulas() {
        let modes = [
            AddressMode::ClampToEdge,
            AddressMode::Repeat,
            AddressMode::MirrorRepeat,
            AddressMode::ClampToBorder,
        ];
        let sizes = [0, 1, 2, 3, 4, 5, 7, 8, 16, 31, 64, 1 << 20, u32::MAX];
        let extremes = [
            i64::MIN,
            i64::MIN + 1,
            -(1 << 40),
            1 << 40,
            i64::MAX - 1,
            i64::MAX,
        ];
        for mode in modes {
            for size in sizes {
                for i in (-300..300).chain(extremes) {
                    assert_eq!(
                        wrap(i, size, mode),
                        wrap_by_formula(i, size, mode),
                        "{mode:?} size {size} index {i}"
                    );
                }
            }
        }
    }

    #[test]
    fn wrap_modes_match_the_spec_on_a_range_of_indices() {
        let size = 3;
        let repeat: Vec<_> = (-4..5)
            .map(|i| wrap(i, size, AddressMode::Repeat))
            .collect();
        assert_eq!(
            repeat,
            [2, 0, 1, 2, 0, 1, 2, 0, 1].map(Some).to_vec(),
            "repeat"
        );
        let mirror: Vec<_> = (-4..7)
            .map(|i| wrap(i, size, AddressMode::MirrorRepeat))
            .collect();
        // … 2 2 1 0 | 0 1 2 | 2 1 0 0 …
        assert_eq!(
            mirror,
            [2, 2, 1, 0, 0, 1, 2, 2, 1, 0, 0].map(Some).to_vec(),
            "mirror"
        );
        assert_eq!(wrap(-7, size, AddressMode::ClampToEdge), Some(0));
        assert_eq!(wrap(9, size, AddressMode::ClampToEdge), Some(2));
        assert_eq!(wrap(-1, size, AddressMode::ClampToBorder), None);
        assert_eq!(wrap(3, size, AddressMode::ClampToBorder), None);
        assert_eq!(
            wrap(i64::MIN, size, AddressMode::MirrorRepeat).map(|i| i < 3),
            Some(true)
        );
        assert_eq!(
            wrap(i64::MAX, size, AddressMode::Repeat).map(|i| i < 3),
            Some(true)
        );
    }
}
