//! Trilinear interpolation of eight corner values (Buss 2003, ch. IV, trilinear interpolation).

use glam::Vec3;

use crate::Interpolate;

/// Trilinear interpolation `Σ wᵢ(α) wⱼ(β) wₖ(γ) x_ijk` of the corners of a cell at
/// `t = (α, β, γ)`, with `w₀(s) = 1 − s`, `w₁(s) = s`.
///
/// Corner `x_ijk` is `corners[i + 2j + 4k]` (x fastest, as in a volume texture). Evaluated as
/// four lerps along α, two along β and one along γ, so corners are reproduced exactly.
///
/// # Accuracy
/// Seven [`lerp`](crate::lerp)s in three levels: for `t` in `[0, 1]³` and finite corners,
/// within `8·ε·max|corner| + 3·2⁻¹⁴⁹` of the exact value (per component), the absolute term
/// being [`lerp`]'s underflow term once per level (tests `trilinear_accuracy_bound` and
/// `trilinear_accuracy_bound_with_subnormals`).
///
/// **Exact on dyadic inputs, under this condition:** if every corner is an integer multiple of
/// `2^e`, `t`'s components are multiples of `2^−p`, `2^−q`, `2^−r` in `[0, 1]`, and
/// `max|corner| ≤ 2^(24 + e − p − q − r)`, the result is the exact trilinear value. Proof: each
/// [`lerp`] of values that are multiples of `U` and at most `M` in magnitude, at a `t` that is a
/// multiple of `2^−k`, computes only multiples of `U·2^−k` of magnitude at most `M` (`b − a`
/// for same-sign `a`, `b`; `t·(b − a)`, `t·b`, `(1 − t)·a`, and the sum, which lies between `a`
/// and `b`), and an integer multiple `N·U·2^−k` with `|N| ≤ 2²⁴` is an f32 (subnormals
/// included), so every step is exact. The three levels multiply `U` by `2^−p`, `2^−q`, `2^−r`;
/// the condition is `M ≤ 2²⁴·U·2^−(p+q+r)`. Corners up to 2¹² at `t = k/16` qualify; the audit's
/// corners (up to 76) at `t = (177/256, 69/128, 27/64)` do not, and the result is rounded (test
/// `dyadic_exactness_needs_its_condition`; the condition itself:
/// `trilinear_is_exact_under_the_dyadic_condition`, `trilinear_reproduces_trilinear_functions`).
///
/// [`lerp`]: crate::lerp
///
/// ```
/// use barytex_interp::trilinear;
/// use glam::Vec3;
/// let corners = [0.0f32, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]; // f = x + 2y + 4z
/// assert_eq!(trilinear(corners, Vec3::new(0.5, 0.25, 0.75)), 0.5 + 0.5 + 3.0);
/// ```
#[must_use]
#[inline]
pub fn trilinear<T: Interpolate>(corners: [T; 8], t: Vec3) -> T {
    let [c000, c100, c010, c110, c001, c101, c011, c111] = corners;
    let c00 = c000.lerp(c100, t.x);
    let c10 = c010.lerp(c110, t.x);
    let c01 = c001.lerp(c101, t.x);
    let c11 = c011.lerp(c111, t.x);
    let c0 = c00.lerp(c10, t.y);
    let c1 = c01.lerp(c11, t.y);
    c0.lerp(c1, t.z)
}
