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
/// Seven [`lerp`](crate::lerp)s: within `8·ε·max|corner|` for `t` in `[0, 1]³` (test
/// `trilinear_reproduces_trilinear_functions`, which also checks exactness on dyadic inputs).
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
