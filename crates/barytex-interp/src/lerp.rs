//! Linear interpolation on a line and its inverse (Buss 2003, ch. IV: `x(α) = (1−α)x₁ + αx₂`,
//! `α = (u−x₁)·(x₂−x₁)/|x₂−x₁|²`).

use glam::{DVec3, Vec2, Vec3};

macro_rules! exact_lerp {
    ($(#[$doc:meta])* $name:ident, $t:ty) => {
        $(#[$doc])*
        #[must_use]
        #[inline]
        pub fn $name(a: $t, b: $t, t: $t) -> $t {
            // The P0811 (C++20 `std::lerp`) construction: each branch keeps all four properties.
            if (a <= 0.0 && b >= 0.0) || (a >= 0.0 && b <= 0.0) {
                // Opposite signs: both products move monotonically with t and cannot cancel.
                return t * b + (1.0 - t) * a;
            }
            if t == 1.0 {
                return b;
            }
            // Same sign: `b − a` cannot overflow and `a + t(b − a)` is exact at t = 0 and
            // consistent for a == b; clamping against b restores monotonicity and boundedness
            // that the rounding of `a + t(b − a)` could break near t = 1.
            // The comparisons are written so that a NaN `x` falls through and is returned.
            let x = a + t * (b - a);
            if (t > 1.0) == (b > a) {
                if b > x { b } else { x }
            } else if b < x {
                b
            } else {
                x
            }
        }
    };
}

exact_lerp!(
    /// Linear interpolation `(1 − t)·a + t·b` with all four properties at once.
    ///
    /// - exact endpoints: `lerp(a, b, 0.0) == a` and `lerp(a, b, 1.0) == b`;
    /// - consistent: `lerp(a, a, t) == a` for every finite `t`;
    /// - monotonic in `t`;
    /// - bounded: for `t` in `[0, 1]` the result lies between `a` and `b`.
    ///
    /// `t` outside `[0, 1]` extrapolates along the same line (Buss's α < 0 and α > 1), still
    /// monotonic. Built as C++20's `std::lerp` (P0811). glam 0.34 offers `lerp`, `a(1 − t) + bt`,
    /// exact at both ends but neither consistent nor monotonic, and `lerp_monotonic`,
    /// `a + (b − a)t`, which is not exact at `t = 1` (glam #823 is the history).
    ///
    /// # Accuracy
    /// For finite inputs and `t` in `[0, 1]`:
    /// `|lerp(a, b, t) − exact| ≤ 2·ε·max(|a|, |b|) + 2⁻¹⁴⁹` with `ε = f32::EPSILON`. The
    /// absolute term is underflow: each of the (at most two) products rounds to the fixed spacing
    /// `2⁻¹⁴⁹` of the subnormals, by at most half of it, and sums of subnormals are exact — so
    /// `lerp(1e-45, 3e-45, 0.5)` is 7e-46 off, far above the relative term alone (tests
    /// `lerp_accuracy_bound`, `lerp_accuracy_bound_with_subnormals` and
    /// `underflow_needs_the_absolute_term` in `tests/tests/interp/lerp.rs`).
    ///
    /// # Special values
    /// A NaN input gives NaN, except that `t == 1` returns `b` as given. An infinite endpoint
    /// gives an infinity or NaN (infinite endpoints of opposite sign give NaN for `0 < t < 1`).
    /// Never panics.
    ///
    /// ```
    /// use barytex_interp::lerp;
    /// assert_eq!(lerp(0.1, 0.7, 1.0), 0.7);
    /// assert_eq!(lerp(3.0, 3.0, 0.3), 3.0);
    /// assert_eq!(lerp(1.0, 3.0, 1.5), 4.0); // extrapolation
    /// ```
    lerp,
    f32
);

exact_lerp!(
    /// [`lerp`] for `f64`, with the same four properties.
    ///
    /// # Accuracy
    /// For finite inputs and `t` in `[0, 1]`:
    /// `|lerp_f64(a, b, t) − exact| ≤ 2·ε·max(|a|, |b|) + 2⁻¹⁰⁷⁴` with `ε = f64::EPSILON`, the
    /// absolute term for underflow as in [`lerp`] (tests `lerp_f64_accuracy_bound` and
    /// `lerp_f64_accuracy_bound_with_subnormals` in `tests/tests/interp/lerp.rs`).
    lerp_f64,
    f64
);

/// The parameter `t` with `lerp(a, b, t) == x`: `(x − a)/(b − a)`.
///
/// A quotient beyond f32's range is returned as the infinity of its sign.
/// `inverse_lerp(a, b, a) == Ok(0.0)` and `inverse_lerp(a, b, b) == Ok(1.0)` exactly.
///
/// # Errors
/// [`InterpError::DegenerateSegment`](crate::InterpError::DegenerateSegment) when `a == b`
/// (every or no `t` would do), [`InterpError::NonFinite`](crate::InterpError::NonFinite) when an
/// input is NaN or infinite (`what` is `"a"`, `"b"` or `"x"`).
///
/// # Accuracy
/// Within 1 ulp of the exact quotient `(x − a)/(b − a)` of the f32 inputs, for every finite
/// input (any magnitudes, subnormals included; a quotient beyond f32's range is the infinity of
/// its sign). Computed in f64: the two differences and the quotient each err by at most 2⁻⁵³
/// relative (no f64 overflow or underflow is possible from f32 inputs), `3·2⁻⁵³` in all, far
/// below the final rounding to f32 (tests `inverse_lerp_is_within_one_ulp` and
/// `inverse_lerp_is_within_one_ulp_at_any_magnitude`).
///
/// ```
/// use barytex_interp::inverse_lerp;
/// use barytex_interp::InterpError;
/// assert_eq!(inverse_lerp(2.0, 4.0, 3.0), Ok(0.5));
/// assert_eq!(inverse_lerp(2.0, 2.0, 3.0), Err(InterpError::DegenerateSegment));
/// ```
pub fn inverse_lerp(a: f32, b: f32, x: f32) -> Result<f32, crate::InterpError> {
    for (what, v) in [("a", a), ("b", b), ("x", x)] {
        if !v.is_finite() {
            return Err(crate::InterpError::NonFinite { what });
        }
    }
    if a == b {
        return Err(crate::InterpError::DegenerateSegment);
    }
    let (a, b, x) = (f64::from(a), f64::from(b), f64::from(x));
    Ok(((x - a) / (b - a)) as f32)
}

/// The projection formula (Buss 2003, ch. IV; Denisjuk, linear interpolation): the parameter α of the point on the line through `x1`, `x2`
/// nearest to `u`, `α = (u − x1)·(x2 − x1)/|x2 − x1|²`, in 2D.
///
/// For `u` on the segment this inverts `x1.lerp(x2, α)`; `α` is outside `[0, 1]` when the
/// projection falls outside the segment.
///
/// # Errors
/// [`InterpError::DegenerateSegment`](crate::InterpError::DegenerateSegment) when `x1 == x2`,
/// [`InterpError::NonFinite`](crate::InterpError::NonFinite) for NaN or infinite input.
///
/// # Accuracy
/// Evaluated in f64 from the f32 inputs and rounded once: for every finite input,
/// `|α̃ − α| ≤ 1 ulp + 2⁻⁴⁷·|u − x1|/|x2 − x1|` of the exact parameter `α`. The second term is the
/// f64 rounding of the differences, the dot product and the quotient (at most `11·2⁻⁵³` times
/// the condition number `|u − x1|/|x2 − x1|`). It is at most half an ulp of `α`, and the result
/// within 1 ulp of the nearest f32 to `α`, whenever `|u − x1| ≤ 2²²·|α|·|x2 − x1|` — unless `u`
/// lies far off the line compared with its projection's distance from `x1` (tests
/// `segment_parameter_matches_exact` on `[−300, 300]²` and
/// `segment_parameter_within_its_condition_bound` with magnitudes 2⁻⁴⁰ … 2⁴⁰).
///
/// ```
/// use barytex_interp::segment_parameter_2d;
/// use glam::Vec2;
/// let a = segment_parameter_2d(Vec2::new(1.0, 5.0), Vec2::ZERO, Vec2::new(4.0, 0.0))?;
/// assert_eq!(a, 0.25);
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
pub fn segment_parameter_2d(u: Vec2, x1: Vec2, x2: Vec2) -> Result<f32, crate::InterpError> {
    check_finite(&[u.x, u.y, x1.x, x1.y, x2.x, x2.y])?;
    let d = x2.as_dvec2() - x1.as_dvec2();
    let den = d.length_squared();
    if den == 0.0 {
        return Err(crate::InterpError::DegenerateSegment);
    }
    Ok(((u.as_dvec2() - x1.as_dvec2()).dot(d) / den) as f32)
}

/// [`segment_parameter_2d`] in 3D.
///
/// # Errors
/// As [`segment_parameter_2d`].
///
/// # Accuracy
/// As [`segment_parameter_2d`] (test `segment_parameter_matches_exact`).
///
/// ```
/// use barytex_interp::{segment_parameter_3d, InterpError};
/// use glam::Vec3;
/// let a = segment_parameter_3d(Vec3::new(1.0, 5.0, -2.0), Vec3::ZERO, Vec3::new(4.0, 0.0, 0.0))?;
/// assert_eq!(a, 0.25);
/// let none = segment_parameter_3d(Vec3::ONE, Vec3::X, Vec3::X);
/// assert_eq!(none, Err(InterpError::DegenerateSegment));
/// # Ok::<(), InterpError>(())
/// ```
pub fn segment_parameter_3d(u: Vec3, x1: Vec3, x2: Vec3) -> Result<f32, crate::InterpError> {
    check_finite(&[u.x, u.y, u.z, x1.x, x1.y, x1.z, x2.x, x2.y, x2.z])?;
    let d: DVec3 = x2.as_dvec3() - x1.as_dvec3();
    let den = d.length_squared();
    if den == 0.0 {
        return Err(crate::InterpError::DegenerateSegment);
    }
    Ok(((u.as_dvec3() - x1.as_dvec3()).dot(d) / den) as f32)
}

fn check_finite(values: &[f32]) -> Result<(), crate::InterpError> {
    if values.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(crate::InterpError::NonFinite { what: "point" })
    }
}
