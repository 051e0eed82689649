//! Reading one texel for filtering: address modes applied to integer indices, border colour,
//! conversion to **premultiplied** linear light (filters blend premultiplied colours so a
//! transparent texel's colour cannot bleed into its neighbours).

use glam::Vec4;

use crate::addressing::wrap;
use crate::sampler::{AddressMode, BorderColor};
use crate::{Texel, Texture2d};

/// The address modes and border of one filtering operation, resolved once per lookup.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Addressing {
    pub(crate) u: AddressMode,
    pub(crate) v: AddressMode,
    /// The border colour, premultiplied (all border colours are already).
    pub(crate) border: Vec4,
}

impl Addressing {
    pub(crate) fn new(u: AddressMode, v: AddressMode, border: Option<BorderColor>) -> Self {
        Self {
            u,
            v,
            border: border_value(border.unwrap_or_default()),
        }
    }
}

/// The linear RGBA value of a border colour (premultiplied and straight are the same for these).
#[must_use]
pub(crate) fn border_value(border: BorderColor) -> Vec4 {
    match border {
        BorderColor::TransparentBlack | BorderColor::Zero => Vec4::ZERO,
        BorderColor::OpaqueBlack => Vec4::new(0.0, 0.0, 0.0, 1.0),
        BorderColor::OpaqueWhite => Vec4::ONE,
    }
}

/// Straight → premultiplied alpha.
#[must_use]
#[inline]
pub(crate) fn premultiply(c: Vec4) -> Vec4 {
    Vec4::new(c.x * c.w, c.y * c.w, c.z * c.w, c.w)
}

/// Premultiplied → straight alpha; alpha ≤ 0 (or NaN) gives transparent black. Divides rather
/// than multiplying by `1/α`, whose reciprocal overflows for subnormal alpha (found by the
/// `sampling` fuzz target); a colour that still overflows is dropped to black.
#[must_use]
#[inline]
pub(crate) fn unpremultiply(c: Vec4) -> Vec4 {
    if c.w > 0.0 {
        // One 4-lane division (the w lane's α/α is discarded) and one lane-wise finiteness test,
        // rather than three scalar divisions and three scalar tests: the same values.
        let q = c / c.w;
        if q.is_finite_mask().bitmask() & 0b0111 == 0b0111 {
            Vec4::new(q.x, q.y, q.z, c.w)
        } else {
            Vec4::new(0.0, 0.0, 0.0, c.w)
        }
    } else {
        Vec4::ZERO
    }
}

/// [`unpremultiply`] of one texel of format `T` or of a blend of them with non-negative weights:
/// the same value, with less work where the format allows. For [`Texel::UNIT_RANGE`] formats the
/// quotients are finite (every premultiplied component is at most its alpha, up to rounding), so
/// their test is left out; for such a blend of opaque texels (`OPAQUE`: alpha exactly 1, which a
/// lerp of ones keeps) the division by 1 is left out too.
#[must_use]
#[inline(always)]
pub(crate) fn unpremultiply_texels<T: Texel, const OPAQUE: bool>(c: Vec4) -> Vec4 {
    if !T::UNIT_RANGE {
        return unpremultiply(c);
    }
    if OPAQUE {
        return c;
    }
    if c.w > 0.0 {
        let q = c / c.w;
        Vec4::new(q.x, q.y, q.z, c.w)
    } else {
        Vec4::ZERO
    }
}

/// Texel `(x, y)` of `texture` (indices before wrapping), premultiplied linear, or the border.
#[must_use]
#[inline]
pub(crate) fn fetch<T: Texel>(texture: &Texture2d<T>, x: i64, y: i64, a: &Addressing) -> Vec4 {
    let (w, h) = texture.size();
    fetch_wrapped(texture, wrap(x, w, a.u), wrap(y, h, a.v), a)
}

/// Texel `(x, y)` of `texture` at indices already wrapped (`None`: outside, the border),
/// premultiplied linear.
#[must_use]
#[inline]
pub(crate) fn fetch_wrapped<T: Texel>(
    texture: &Texture2d<T>,
    x: Option<u32>,
    y: Option<u32>,
    a: &Addressing,
) -> Vec4 {
    match (x, y) {
        (Some(x), Some(y)) => premultiply(
            texture.texels()[y as usize * texture.width() as usize + x as usize].to_linear(),
        ),
        _ => a.border,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The previous form: three scalar divisions, `Vec3::is_finite`.
    fn unpremultiply_reference(c: Vec4) -> Vec4 {
        if c.w > 0.0 {
            let rgb = c.truncate() / c.w;
            if rgb.is_finite() {
                rgb.extend(c.w)
            } else {
                Vec4::new(0.0, 0.0, 0.0, c.w)
            }
        } else {
            Vec4::ZERO
        }
    }

    #[test]
    fn unpremultiply_equals_the_scalar_form_bit_for_bit() {
        let values = [
            0.0,
            -0.0,
            1.0,
            0.5,
            0.25,
            1e-40,
            f32::MIN_POSITIVE,
            1e-20,
            3e38,
            f32::MAX,
            f32::INFINITY,
            -f32::INFINITY,
            f32::NAN,
            -1.0,
            0.123_456_78,
        ];
        let mut state = 0x9e37_79b9_u32;
        let mut random = || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            f32::from_bits(state)
        };
        let mut inputs = Vec::new();
        for &w in &values {
            for &r in &values {
                inputs.push(Vec4::new(r, 0.5 * r, random(), w));
            }
        }
        for _ in 0..100_000 {
            inputs.push(Vec4::new(random(), random(), random(), random().abs()));
        }
        for c in inputs {
            let (got, want) = (unpremultiply(c), unpremultiply_reference(c));
            for k in 0..4 {
                assert!(
                    got[k].to_bits() == want[k].to_bits() || (got[k].is_nan() && want[k].is_nan()),
                    "{c:?}: {got:?} vs {want:?}"
                );
            }
        }
    }
}
