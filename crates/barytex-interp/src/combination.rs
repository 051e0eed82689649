//! Affine and convex combinations as checked types (Denisjuk, Definition 2; Buss 2003, ch. IV,
//! weighted averages and affine combinations).

use crate::{InterpError, Interpolate};

/// How far the f64 sum of `N` f32 weights may be from 1: `N·ε` with `ε = f32::EPSILON`, the
/// worst case of rounding `N` weights that sum to one exactly.
fn sum_tolerance(n: usize) -> f64 {
    n as f64 * f64::from(f32::EPSILON)
}

/// The f64 sum of finite weights; `NonFinite` when one is NaN or infinite.
fn finite_sum(weights: &[f32]) -> Result<f64, InterpError> {
    if !weights.iter().all(|w| w.is_finite()) {
        return Err(InterpError::NonFinite { what: "weights" });
    }
    Ok(weights.iter().map(|&w| f64::from(w)).sum())
}

fn checked_sum(weights: &[f32]) -> Result<f64, InterpError> {
    let sum = finite_sum(weights)?;
    if (sum - 1.0).abs() > sum_tolerance(weights.len()) {
        return Err(InterpError::WeightsDoNotSumToOne { sum });
    }
    Ok(sum)
}

fn normalize<const N: usize>(weights: [f32; N]) -> Result<[f32; N], InterpError> {
    let sum = finite_sum(&weights)?;
    if sum == 0.0 || !sum.is_finite() {
        return Err(InterpError::WeightsDoNotSumToOne { sum });
    }
    let normalized = weights.map(|w| (f64::from(w) / sum) as f32);
    // A sum that cancels to a tiny value can push a quotient beyond f32's range.
    if !normalized.iter().all(|w| w.is_finite()) {
        return Err(InterpError::NonFinite {
            what: "normalized weights",
        });
    }
    Ok(normalized)
}

/// Weights `α₁ … α_N` with `Σαᵢ = 1`: an affine combination `Σαᵢxᵢ`, which affine maps preserve
/// (Denisjuk, Theorem 3).
///
/// ```
/// use barytex_interp::AffineCombination;
/// use glam::Vec2;
/// let c = AffineCombination::new([2.0, -1.0])?; // extrapolation is affine, not convex
/// assert_eq!(c.apply([Vec2::ZERO, Vec2::X]), Vec2::new(-1.0, 0.0));
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AffineCombination<const N: usize> {
    weights: [f32; N],
}

impl<const N: usize> AffineCombination<N> {
    /// Check that the weights are finite and sum to 1 within `N·f32::EPSILON` (in f64).
    ///
    /// # Errors
    /// [`InterpError::NonFinite`] or [`InterpError::WeightsDoNotSumToOne`].
    pub fn new(weights: [f32; N]) -> Result<Self, InterpError> {
        checked_sum(&weights)?;
        Ok(Self { weights })
    }

    /// Divide the weights by their sum so they sum to 1.
    ///
    /// # Errors
    /// [`InterpError::NonFinite`] (also when a quotient overflows f32), or
    /// [`InterpError::WeightsDoNotSumToOne`] when the sum is 0.
    pub fn normalized(weights: [f32; N]) -> Result<Self, InterpError> {
        Ok(Self {
            weights: normalize(weights)?,
        })
    }

    /// The weights.
    #[must_use]
    pub fn weights(&self) -> [f32; N] {
        self.weights
    }

    /// The combination `Σαᵢxᵢ` of `points`.
    #[must_use]
    pub fn apply<T: Interpolate>(&self, points: [T; N]) -> T {
        combine(points, self.weights)
    }
}

/// Weights `α₁ … α_N` with `Σαᵢ = 1` and every `αᵢ ≥ 0`: a convex combination (weighted average),
/// which always lies in the convex hull of the points.
///
/// ```
/// use barytex_interp::{ConvexCombination, InterpError};
/// assert!(ConvexCombination::new([0.25, 0.75]).is_ok());
/// assert!(matches!(
///     ConvexCombination::new([2.0, -1.0]),
///     Err(InterpError::NegativeWeight { index: 1, .. })
/// ));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvexCombination<const N: usize> {
    weights: [f32; N],
}

impl<const N: usize> ConvexCombination<N> {
    /// Check that the weights are finite, non-negative (`-0.0` counts as zero) and sum to 1 within
    /// `N·f32::EPSILON`.
    ///
    /// # Errors
    /// [`InterpError::NonFinite`], [`InterpError::NegativeWeight`] or
    /// [`InterpError::WeightsDoNotSumToOne`].
    pub fn new(weights: [f32; N]) -> Result<Self, InterpError> {
        checked_sum(&weights)?;
        check_non_negative(&weights)?;
        Ok(Self { weights })
    }

    /// Divide non-negative weights by their sum so they sum to 1.
    ///
    /// # Errors
    /// As [`ConvexCombination::new`]; a zero sum gives [`InterpError::WeightsDoNotSumToOne`].
    pub fn normalized(weights: [f32; N]) -> Result<Self, InterpError> {
        check_non_negative(&weights)?;
        Ok(Self {
            weights: normalize(weights)?,
        })
    }

    /// The weights.
    #[must_use]
    pub fn weights(&self) -> [f32; N] {
        self.weights
    }

    /// The weighted average `Σαᵢxᵢ` of `points`.
    #[must_use]
    pub fn apply<T: Interpolate>(&self, points: [T; N]) -> T {
        combine(points, self.weights)
    }

    /// The same weights as an affine combination (every convex combination is affine).
    #[must_use]
    pub fn to_affine(self) -> AffineCombination<N> {
        AffineCombination {
            weights: self.weights,
        }
    }
}

fn check_non_negative(weights: &[f32]) -> Result<(), InterpError> {
    match weights.iter().position(|&w| w < 0.0) {
        Some(index) => Err(InterpError::NegativeWeight {
            index,
            weight: weights[index],
        }),
        None => Ok(()),
    }
}

fn combine<T: Interpolate, const N: usize>(points: [T; N], weights: [f32; N]) -> T {
    // N == 0 cannot pass `checked_sum` (the empty sum is 0), so the first pair exists.
    let mut acc = points[0].scale(weights[0]);
    for i in 1..N {
        acc = acc.add(points[i].scale(weights[i]));
    }
    acc
}
