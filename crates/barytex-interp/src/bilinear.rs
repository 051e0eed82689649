//! Bilinear interpolation over a quad (Buss 2003, ch. IV, bilinear interpolation).

use crate::Interpolate;

/// Bilinear interpolation of the corner values `[x, y, z, w]` of a quad at `(α, β)`:
/// `(1−α)(1−β)x + α(1−β)y + αβz + (1−α)βw`.
///
/// Corner order follows Buss and Denisjuk: `x` at `(0, 0)`, `y` at `(1, 0)`, `z` at `(1, 1)`, `w` at
/// `(0, 1)`, i.e. around the quad. Evaluated as two lerps along α then one along β, so the
/// corners are reproduced exactly and constant values stay constant.
///
/// # Accuracy
/// Three [`lerp`](crate::lerp)s in two levels: for `(α, β)` in `[0, 1]²` and finite corners of
/// any shape, each component is within `6·ε·max|corner| + 2·2⁻¹⁴⁹` of the exact value, with
/// `max|corner|` over that component's four corner values. The absolute term is [`lerp`]'s
/// underflow term, once per level (the second level's lerp is a convex combination, so the
/// first level's errors pass through it undamped but not amplified) (tests
/// `bilinear_accuracy_bound` and, with subnormal, huge and non-convex corners,
/// `bilinear_accuracy_bound_any_corners`).
///
/// [`lerp`]: crate::lerp
///
/// ```
/// use barytex_interp::bilinear;
/// use glam::Vec2;
/// // Denisjuk, Example 10.
/// let quad = [Vec2::new(0.0, 0.0), Vec2::new(4.0, 0.0), Vec2::new(5.0, 3.0), Vec2::new(0.0, 2.0)];
/// assert_eq!(bilinear(quad, 1.0, 0.0), Vec2::new(4.0, 0.0));
/// assert_eq!(bilinear(quad, 0.5, 0.25), Vec2::new(17.0 / 8.0, 5.0 / 8.0));
/// ```
#[must_use]
#[inline]
pub fn bilinear<T: Interpolate>([x, y, z, w]: [T; 4], alpha: f32, beta: f32) -> T {
    let bottom = x.lerp(y, alpha);
    let top = w.lerp(z, alpha);
    bottom.lerp(top, beta)
}
