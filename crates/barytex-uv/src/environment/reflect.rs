//! Mirror reflection of a view vector about a normal, the direction an environment map is looked
//! up with.

use glam::Vec3;

/// `r = 2(n·v)n − v`: the mirror image of `v` about the normal `n`.
///
/// Convention (as in S. Schaefer's *Shading/Texturing* lecture slides, Texas A&M University): `v`
/// points **from the surface towards the eye**, so `r` points away from the surface into the
/// environment. (GLSL's `reflect(I, N)` takes the incident vector `I = −v`, pointing towards the
/// surface, and returns the same `r`.)
///
/// For a unit `n`, `|r| = |v|`. No normalization is done and nothing is checked: NaN or infinite
/// input gives NaN or infinite output (never a panic); use [`reflect_normalized`] for a checked
/// unit result.
///
/// # Accuracy
/// For unit `n` and `v` the result is within 4 ulps of 1 in length and within `4·ε` radians of
/// the exact reflection (`environment.rs::reflect_matches_f64`).
///
/// ```
/// use barytex_uv::environment::reflect;
/// use glam::Vec3;
///
/// // Looking straight down at a floor: the ray bounces straight up.
/// assert_eq!(reflect(Vec3::Y, Vec3::Y), Vec3::Y);
/// // A 45° view is mirrored about the normal.
/// let v = Vec3::new(1.0, 1.0, 0.0);
/// assert_eq!(reflect(Vec3::Y, v), Vec3::new(-1.0, 1.0, 0.0));
/// ```
#[must_use]
#[inline]
pub fn reflect(n: Vec3, v: Vec3) -> Vec3 {
    2.0 * n.dot(v) * n - v
}

/// [`reflect`] of the normalized `n` and `v`, normalized: a unit reflection direction, or `None`
/// when `n` or `v` is zero, NaN or infinite.
///
/// Any finite nonzero lengths work, subnormal or huge (the vectors are rescaled before
/// normalizing, so `|v|²` never overflows or underflows).
///
/// # Accuracy
/// Within `8·ε` radians of the exact reflection of the exact unit vectors (the two
/// normalizations each move their vector by up to `ε`, which the reflection doubles)
/// (`environment.rs::reflect_matches_f64`).
///
/// ```
/// use barytex_uv::environment::reflect_normalized;
/// use glam::Vec3;
///
/// let r = reflect_normalized(Vec3::Y * 3.0, Vec3::new(2.0, 2.0, 0.0)).expect("nonzero");
/// assert!((r - Vec3::new(-1.0, 1.0, 0.0).normalize()).length() < 1e-6);
/// assert_eq!(reflect_normalized(Vec3::ZERO, Vec3::X), None);
/// ```
#[must_use]
pub fn reflect_normalized(n: Vec3, v: Vec3) -> Option<Vec3> {
    let (n, v) = (unit(n)?, unit(v)?);
    unit(reflect(n, v))
}

/// `d / |d|`, or `None` for a zero or non-finite `d`. Divides by the largest component first so
/// that the squared length neither overflows (huge `d`) nor underflows (subnormal `d`).
pub(crate) fn unit(d: Vec3) -> Option<Vec3> {
    if !d.is_finite() {
        return None;
    }
    let m = d.abs().max_element();
    if m == 0.0 {
        return None;
    }
    (d / m).try_normalize()
}
