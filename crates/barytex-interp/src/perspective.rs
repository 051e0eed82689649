//! Perspective-correct (hyperbolic) interpolation (Buss 2003, ch. IV, hyperbolic interpolation;
//! Heckbert and Moreton 1991: interpolate `u/z`, `v/z` and `1/z` linearly on screen, then
//! divide).

use crate::{InterpError, Interpolate};

/// Turn screen-space (affine) weights `αᵢ` into perspective-correct weights
/// `βᵢ = (αᵢ/wᵢ) / Σⱼ(αⱼ/wⱼ)`, where `wᵢ` is vertex `i`'s clip-space `w` (its view depth).
///
/// Interpolating attributes with `βᵢ` equals interpolating them in 3D and projecting (Buss's
/// hyperbolic interpolation). Works for any number of vertices: 2 for a line, 3 for a triangle.
///
/// When all `wᵢ` are equal the projection is affine: screen weights that sum to exactly 1 (in
/// f64) are returned unchanged, bit for bit; others go through the formula, which normalises
/// them. The result always sums to 1 within rounding.
///
/// # Errors
/// [`InterpError::NonFinite`] for a NaN or infinite weight (`"screen"`) or `w` (`"w"`),
/// [`InterpError::NonPositiveW`] for a `wᵢ ≤ 0` (at or behind the eye: clip first),
/// [`InterpError::AtInfinity`] when `Σ αⱼ/wⱼ` is 0 (the screen point is on the primitive's
/// vanishing line).
///
/// # Accuracy
/// Evaluated in f64 and rounded once. Convex weights (all `αᵢ ≥ 0`): each result within 1 ulp
/// of the exact formula. Extrapolated (affine) weights: the normalising sum `Σαⱼ/wⱼ` may cancel,
/// and each result `λ̃ᵢ` satisfies the absolute bound
/// `|λ̃ᵢ − λᵢ| ≤ 1 ulp(λᵢ) + 2⁻⁵⁰·κ·(1 + |λᵢ|)` with `κ = Σ|αⱼ/wⱼ| / |Σαⱼ/wⱼ|` (tests
/// `perspective_weights_within_ulps`, `perspective_weights_extrapolated` and
/// `equal_w_is_exactly_affine`).
///
/// ```
/// use barytex_interp::{perspective_correct_weights, InterpError};
/// // Half-way on screen between a near (w = 1) and a far (w = 3) vertex is 1/4 of the way in 3D.
/// assert_eq!(perspective_correct_weights([0.5, 0.5], [1.0, 3.0]), Ok([0.75, 0.25]));
/// assert_eq!(
///     perspective_correct_weights([0.5, 0.5], [1.0, -3.0]),
///     Err(InterpError::NonPositiveW { index: 1, w: -3.0 })
/// );
/// ```
pub fn perspective_correct_weights<const N: usize>(
    screen: [f32; N],
    w: [f32; N],
) -> Result<[f32; N], InterpError> {
    if !screen.iter().all(|a| a.is_finite()) {
        return Err(InterpError::NonFinite { what: "screen" });
    }
    for (index, &wi) in w.iter().enumerate() {
        if !wi.is_finite() {
            return Err(InterpError::NonFinite { what: "w" });
        }
        if wi <= 0.0 {
            return Err(InterpError::NonPositiveW { index, w: wi });
        }
    }
    let screen_sum: f64 = screen.iter().map(|&a| f64::from(a)).sum();
    if w.iter().all(|&wi| wi == w[0]) && screen_sum == 1.0 {
        return Ok(screen);
    }
    let mut q = [0.0f64; N];
    for ((qi, &a), &wi) in q.iter_mut().zip(&screen).zip(&w) {
        *qi = f64::from(a) / f64::from(wi);
    }
    let sum: f64 = q.iter().sum();
    if sum == 0.0 || !sum.is_finite() {
        return Err(InterpError::AtInfinity);
    }
    Ok(q.map(|qi| (qi / sum) as f32))
}

/// Perspective-correct interpolation of vertex values: [`perspective_correct_weights`] then
/// `Σ βᵢ·vᵢ`.
///
/// # Errors
/// As [`perspective_correct_weights`] (which also gives [`InterpError::AtInfinity`] for `N = 0`:
/// no vertices, no point).
///
/// # Accuracy
/// The weights' bound above, then one [`Interpolate::combine`] (see the trait's laws).
///
/// ```
/// use barytex_interp::perspective_interpolate;
/// let u = perspective_interpolate([0.0f32, 1.0], [0.5, 0.5], [1.0, 3.0]);
/// assert_eq!(u, Ok(0.25));
/// ```
pub fn perspective_interpolate<T: Interpolate, const N: usize>(
    values: [T; N],
    screen: [f32; N],
    w: [f32; N],
) -> Result<T, InterpError> {
    let weights = perspective_correct_weights(screen, w)?;
    // `combine` is `None` only for no values, and `N = 0` failed above.
    T::combine(values.into_iter().zip(weights)).ok_or(InterpError::AtInfinity)
}
