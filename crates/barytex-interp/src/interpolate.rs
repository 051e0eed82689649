//! The `Interpolate` trait: values that can be weighted and summed.

use glam::{DVec2, DVec3, DVec4, Vec2, Vec3, Vec3A, Vec4};

use crate::lerp::{lerp, lerp_f64};

/// A value that can be weighted and summed: shader varyings, colours, normals, texture
/// coordinates.
///
/// Implemented for `f32`, `f64`, glam's float vectors, arrays `[T; N]` and tuples of up to four
/// `Interpolate` values, component by component. Weights are `f32` (the data path's precision);
/// `f64` values are scaled by the weight converted to `f64` exactly.
///
/// # Laws
/// Checked for every implementation by one generic test (`tests/tests/interp/interpolate_laws.rs`):
///
/// 1. **Exact endpoints**: `a.lerp(b, 0.0) == a` and `a.lerp(b, 1.0) == b`.
/// 2. **Consistency**: `a.lerp(a, t) == a` for every finite `t`.
/// 3. **Partition of unity**: for weights `wᵢ` that sum to 1,
///    `Σ wᵢ·a` equals `a` within `(n + 1)·ε·Σ|wᵢ|·|a| + n·2⁻¹⁴⁹` per f32 component
///    (`n·2⁻¹⁰⁷⁴` for f64 components): each of the `n` products may underflow, rounding to the
///    subnormal spacing by half of it at most (test `partition_of_unity_with_subnormals`).
/// 4. **Weights that sum to 0 are allowed**: `Σ wᵢ·vᵢ` is a plain linear combination, never
///    normalised, so screen-space derivatives (`∂w/∂x` sums to 0) use the same code; for equal
///    values it is 0 within the same bound.
/// 5. **Linearity**: `a.scale(s).add(b.scale(t))` is computed component by component.
///
/// ```
/// use barytex_interp::Interpolate;
/// use glam::Vec2;
///
/// // A varying made of texture coordinates and a colour, interpolated as one value.
/// let a = (Vec2::ZERO, [1.0f32, 0.0, 0.0]);
/// let b = (Vec2::ONE, [0.0f32, 0.0, 1.0]);
/// assert_eq!(a.lerp(b, 0.0), a);
/// assert_eq!(a.lerp(b, 0.5), (Vec2::splat(0.5), [0.5, 0.0, 0.5]));
/// // Weights that sum to 0: a difference, as in a screen-space derivative.
/// let d = <f32 as Interpolate>::combine([(1.0, 1.0), (3.0, -1.0)]);
/// assert_eq!(d, Some(-2.0));
/// ```
pub trait Interpolate: Copy {
    /// Multiply every component by `w`.
    #[must_use]
    fn scale(self, w: f32) -> Self;

    /// Add component by component.
    #[must_use]
    fn add(self, other: Self) -> Self;

    /// Linear interpolation with exact endpoints and consistency, component by component
    /// (see [`lerp`](crate::lerp)).
    #[must_use]
    fn lerp(self, other: Self, t: f32) -> Self;

    /// The linear combination `Σ wᵢ·vᵢ` of three values, e.g. barycentric interpolation over a
    /// triangle. Weights need not sum to 1.
    ///
    /// Exact at the vertices: weights `(1, 0, 0)` return the first value unchanged.
    #[must_use]
    #[inline]
    fn combine3(values: [Self; 3], weights: [f32; 3]) -> Self {
        values[0]
            .scale(weights[0])
            .add(values[1].scale(weights[1]))
            .add(values[2].scale(weights[2]))
    }

    /// The linear combination `Σ wᵢ·vᵢ` of any number of values; `None` for an empty input.
    #[must_use]
    fn combine<I: IntoIterator<Item = (Self, f32)>>(pairs: I) -> Option<Self> {
        let mut iter = pairs.into_iter();
        let (v0, w0) = iter.next()?;
        Some(iter.fold(v0.scale(w0), |acc, (v, w)| acc.add(v.scale(w))))
    }
}

/// Interpolate three vertex values with barycentric weights: `Σ wᵢ·vᵢ`.
///
/// Same as [`Interpolate::combine3`], as a free function.
///
/// ```
/// use barytex_interp::interpolate3;
/// use glam::Vec3;
/// let red = Vec3::X;
/// let c = interpolate3([red, Vec3::Y, Vec3::Z], [1.0, 0.0, 0.0]);
/// assert_eq!(c, red);
/// ```
#[must_use]
#[inline]
pub fn interpolate3<T: Interpolate>(values: [T; 3], weights: [f32; 3]) -> T {
    T::combine3(values, weights)
}

impl Interpolate for f32 {
    #[inline]
    fn scale(self, w: f32) -> Self {
        self * w
    }
    #[inline]
    fn add(self, other: Self) -> Self {
        self + other
    }
    #[inline]
    fn lerp(self, other: Self, t: f32) -> Self {
        lerp(self, other, t)
    }
}

impl Interpolate for f64 {
    #[inline]
    fn scale(self, w: f32) -> Self {
        self * f64::from(w)
    }
    #[inline]
    fn add(self, other: Self) -> Self {
        self + other
    }
    #[inline]
    fn lerp(self, other: Self, t: f32) -> Self {
        lerp_f64(self, other, f64::from(t))
    }
}

macro_rules! impl_vector {
    ($v:ty, $scalar:ty, $lerp:ident) => {
        impl Interpolate for $v {
            #[inline]
            fn scale(self, w: f32) -> Self {
                self * <$scalar>::from(w)
            }
            #[inline]
            fn add(self, other: Self) -> Self {
                self + other
            }
            #[inline]
            fn lerp(self, other: Self, t: f32) -> Self {
                let t = <$scalar>::from(t);
                let (a, b) = (self.to_array(), other.to_array());
                Self::from_array(core::array::from_fn(|i| $lerp(a[i], b[i], t)))
            }
        }
    };
}

impl_vector!(Vec2, f32, lerp);
impl_vector!(Vec4, f32, lerp);
impl_vector!(Vec3, f32, lerp);
impl_vector!(DVec2, f64, lerp_f64);
impl_vector!(DVec3, f64, lerp_f64);
impl_vector!(DVec4, f64, lerp_f64);

impl_vector!(Vec3A, f32, lerp);

impl<T: Interpolate, const N: usize> Interpolate for [T; N] {
    #[inline]
    fn scale(self, w: f32) -> Self {
        self.map(|v| v.scale(w))
    }
    #[inline]
    fn add(self, other: Self) -> Self {
        let mut out = self;
        for (o, b) in out.iter_mut().zip(other) {
            *o = o.add(b);
        }
        out
    }
    #[inline]
    fn lerp(self, other: Self, t: f32) -> Self {
        let mut out = self;
        for (o, b) in out.iter_mut().zip(other) {
            *o = o.lerp(b, t);
        }
        out
    }
}

macro_rules! impl_tuple {
    ($($name:ident $idx:tt),+) => {
        impl<$($name: Interpolate),+> Interpolate for ($($name,)+) {
            #[inline]
            fn scale(self, w: f32) -> Self {
                ($(self.$idx.scale(w),)+)
            }
            #[inline]
            fn add(self, other: Self) -> Self {
                ($(self.$idx.add(other.$idx),)+)
            }
            #[inline]
            fn lerp(self, other: Self, t: f32) -> Self {
                ($(self.$idx.lerp(other.$idx, t),)+)
            }
        }
    };
}

impl_tuple!(A 0);
impl_tuple!(A 0, B 1);
impl_tuple!(A 0, B 1, C 2);
impl_tuple!(A 0, B 1, C 2, D 3);
