//! 3D barycentric coordinates (Buss 2003, ch. IV, barycentric coordinates in R³).

use glam::{DVec3, Vec3, Vec3Swizzles};

use crate::{InterpError, Interpolate, interpolate3};

/// Barycentric coordinates `(α, β, γ)` of a point with respect to a 3D triangle: the result of
/// [`barycentric_3d`] (the 2D twin, with an exact location, is
/// [`Barycentric2d`](crate::Barycentric2d)).
///
/// `p′ = α·a + β·b + γ·c` with `α + β + γ = 1`, where `p′` is the orthogonal projection of the
/// point onto the triangle's plane.
///
/// ```
/// use barytex_interp::barycentric_3d;
/// use glam::{Vec2, Vec3};
///
/// let tri = [Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0)];
/// // 5 above the plane z = 0: the weights are those of (1, 0.5, 0).
/// let b = barycentric_3d(Vec3::new(1.0, 0.5, 5.0), tri)?;
/// assert_eq!(b.weights, [0.25, 0.5, 0.25]);
/// // Interpolate per-vertex texture coordinates at the point.
/// let uv = b.interpolate([Vec2::ZERO, Vec2::X, Vec2::Y]);
/// assert_eq!(uv, Vec2::new(0.5, 0.25));
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Barycentric3d {
    /// `[α, β, γ]`, the weights of vertices `a`, `b`, `c`.
    pub weights: [f32; 3],
}

impl Barycentric3d {
    /// `Σ wᵢ·vᵢ`: the value at the point from per-vertex values ([`interpolate3`] with
    /// [`weights`](Self::weights)).
    ///
    /// # Accuracy
    /// As [`Interpolate::combine3`]: exact at a vertex (weights `eᵢ` return `values[i]`).
    #[must_use]
    #[inline]
    pub fn interpolate<T: Interpolate>(&self, values: [T; 3]) -> T {
        interpolate3(values, self.weights)
    }
}

/// Barycentric coordinates `(α, β, γ)` of `p` with respect to the triangle `tri = [a, b, c]` in
/// 3D, by the cross-product form in f64.
///
/// A point off the triangle's plane is projected orthogonally onto it first (the weights are
/// those of the projection). Each weight is its own ratio
/// `((vⱼ − p) × (vₖ − p))·n / |n|²` with `n = (b − a) × (c − a)`, so none is derived from the others
/// by subtraction. The cross-product form's error grows like 1/aspect of a sliver; Cramer's
/// dot-product form (`methods::barycentric_3d_cramer_f32`) grows like 1/aspect² and is not used.
///
/// # Errors
/// [`InterpError::DegenerateTriangle`] when the vertices are exactly collinear (`n = 0`),
/// [`InterpError::NonFinite`] for NaN or infinite coordinates.
///
/// # Accuracy
/// For all finite input (any distance of `p` from the triangle, any scale), each weight is
/// within `1 ulp + 2⁻⁴⁶·κ` of the exact rational weight of the projected point,
/// `κ = max(|p|, |a|, |b|, |c|) · max edge length / |2·area|`. A weight computed beyond f32's
/// range is an infinity of its sign when its exact value is beyond that range too (the
/// computed value exceeds `f32::MAX` by more than `2⁻⁴⁷·κ`), else `±f32::MAX`, within the
/// bound of any exact value the error allows. Derivation: the weight of `a` is computed as
/// `((b − p) × (c − b))·n / |n|²` in f64 from the exact f32 inputs, with `v = (b − p) × (c − b)`,
/// `|v|/|n| ≤ 2κ`. The numerator's rounding error is at most `8·2⁻⁵³·|v|·|n|`, which is
/// `2⁻⁴⁹·κ` of the weight; `n`'s components are within `2⁻⁵⁰` relative, which moves `v·n` by
/// at most `2⁻⁵⁰·|v|·|n|` (another `2⁻⁴⁹·κ`: off the plane `v` is not parallel to `n`, so the
/// direction counts, not only the length) and `|n|²` by `2⁻⁴⁹` relative (at most `2⁻⁴⁸·κ`, the
/// weight being at most `2κ`): at most `2⁻⁴⁷·κ` before the final rounding to f32 (tests
/// `barycentric_3d_within_bar`, `slivers_3d_within_bar` and `far_points_within_bar`; the fuzz
/// target `interp_3d` found a point off the plane where a `2⁻³⁰`-accurate `n` broke the bound).
///
/// ```
/// use barytex_interp::barycentric_3d;
/// use glam::Vec3;
/// let tri = [Vec3::X, Vec3::Y, Vec3::Z];
/// let b = barycentric_3d(Vec3::splat(1.0 / 3.0), tri)?;
/// assert!(b.weights.iter().all(|&wi| (wi - 1.0 / 3.0).abs() < 1e-7));
/// # Ok::<(), barytex_interp::InterpError>(())
/// ```
pub fn barycentric_3d(p: Vec3, tri: [Vec3; 3]) -> Result<Barycentric3d, InterpError> {
    if !p.is_finite() {
        return Err(InterpError::NonFinite { what: "point" });
    }
    if !tri.iter().all(|v| v.is_finite()) {
        return Err(InterpError::NonFinite { what: "triangle" });
    }
    // Each component of n = (b − a) × (c − a) is the orientation determinant of the triangle's
    // projection onto a coordinate plane: exact in sign, 2⁻⁵⁰ relative, so `n = 0` exactly when
    // the vertices are collinear (a rounded f64 cross product of rounded differences is not).
    // 2⁻³⁰, as the 2D predicates use, is not enough here: off the plane the numerator's vector
    // is far from parallel to n, and an error in n's direction moved a weight of 2e10 by 5e5
    // (fuzz target `interp_3d`, inputs from 1e-44 to 1e-26).
    let [a32, b32, c32] = tri;
    let det = crate::determinant::orient2d_det_precise;
    let n = DVec3::new(
        det(a32.yz(), b32.yz(), c32.yz()),
        det(a32.zx(), b32.zx(), c32.zx()),
        det(a32.xy(), b32.xy(), c32.xy()),
    );
    let p = p.as_dvec3();
    let [a, b, c] = tri.map(|v| v.as_dvec3());
    let nn = n.length_squared();
    if nn == 0.0 {
        return Err(InterpError::DegenerateTriangle);
    }
    // The weight of a is the signed area of (p, b, c) over that of (a, b, c):
    // `((b − p) × (c − p))·n / |n|²`. Written as `((b − p) × (c − b))·n / |n|²` (equal, since
    // `(b − p) × (b − p) = 0`), the rounding of each product is relative to `|b − p|·|c − b|`, one
    // long vector times one edge, instead of `|b − p|·|c − p|`: far from a small triangle the
    // latter is quadratic in the distance and rounds the weight away.
    let weight = |q: DVec3, r: DVec3| (q - p).cross(r - q).dot(n) / nn;
    let weights = [weight(b, c), weight(c, a), weight(a, b)];
    Ok(Barycentric3d {
        weights: weights.map(|w| to_f32_saturating(w, || kappa(p, [a, b, c], nn))),
    })
}

/// 2⁻⁴⁷ (`powi` is not in `core`).
const TWO_POW_MINUS_47: f64 = 1.0 / (1_u64 << 47) as f64;

/// `w as f32`, except that a finite `w` beyond f32's range whose exact value may be within it
/// (`|w| − 2⁻⁴⁷·κ ≤ f32::MAX`, `2⁻⁴⁷·κ` the f64 error bound) becomes `±f32::MAX`: an infinity
/// there would be infinitely far from a finite exact weight, `f32::MAX` is within `2⁻⁴⁶·κ` of
/// it. Found by the fuzz target `interp_3d`:
/// a weight of exact value 3.8e37 computed as 3.5e38 (κ ≈ 2¹⁸⁰) was an infinity.
fn to_f32_saturating(w: f64, kappa: impl FnOnce() -> f64) -> f32 {
    let rounded = w as f32;
    if rounded.is_infinite()
        && w.is_finite()
        && w.abs() - kappa() * TWO_POW_MINUS_47 <= f64::from(f32::MAX)
    {
        return f32::MAX.copysign(rounded);
    }
    rounded
}

/// `κ = max(|p|, |a|, |b|, |c|) · max edge length / |n|` (`|n| = |2·area|`, `nn = |n|²`), the
/// condition number of the accuracy bound; only computed for weights beyond f32's range.
fn kappa(p: DVec3, [a, b, c]: [DVec3; 3], nn: f64) -> f64 {
    let size = [p, a, b, c].iter().map(|v| v.length()).fold(0.0, f64::max);
    let edge = (b - a).length().max((c - b).length()).max((a - c).length());
    size * edge / crate::math::sqrt(nn)
}

pub(crate) mod methods {
    use glam::Vec3;

    use crate::InterpError;

    /// Cramer's rule on the dot products (Ericson, *Real-Time Collision Detection*) in f32.
    ///
    /// # Accuracy
    /// None guaranteed: the denominator `(e₁·e₁)(e₂·e₂) − (e₁·e₂)²` cancels like 1/aspect², so a
    /// sliver of aspect 1e-4 already loses every digit. Kept to show it in the report. Degenerate
    /// triangles give NaN or infinities.
    #[must_use]
    pub fn barycentric_3d_cramer_f32(p: Vec3, [a, b, c]: [Vec3; 3]) -> [f32; 3] {
        let v0 = b - a;
        let v1 = c - a;
        let v2 = p - a;
        let d00 = v0.dot(v0);
        let d01 = v0.dot(v1);
        let d11 = v1.dot(v1);
        let d20 = v2.dot(v0);
        let d21 = v2.dot(v1);
        let den = d00 * d11 - d01 * d01;
        let beta = (d11 * d20 - d01 * d21) / den;
        let gamma = (d00 * d21 - d01 * d20) / den;
        [1.0 - beta - gamma, beta, gamma]
    }

    /// The cross-product form in f32: `β = ((p−a)×e₂)·n/|n|²`, `γ = (e₁×(p−a))·n/|n|²`,
    /// `α = 1 − β − γ`.
    ///
    /// # Accuracy
    /// Error grows like 1/aspect at f32 precision. Kept for the speed-vs-error report.
    #[must_use]
    pub fn barycentric_3d_cross_f32(p: Vec3, [a, b, c]: [Vec3; 3]) -> [f32; 3] {
        let e1 = b - a;
        let e2 = c - a;
        let f = p - a;
        let n = e1.cross(e2);
        let inv = 1.0 / n.length_squared();
        let beta = f.cross(e2).dot(n) * inv;
        let gamma = e1.cross(f).dot(n) * inv;
        [1.0 - beta - gamma, beta, gamma]
    }

    /// Buss's precomputed form (2003, ch. IV): per triangle
    /// `u_β = (e₂²e₁ − (e₁·e₂)e₂)/(e₁²e₂² − (e₁·e₂)²)` and `u_γ` likewise, then per point
    /// `β = u_β·f`, `γ = u_γ·f` with `f = p − a`: two dot products per query.
    ///
    /// # Accuracy
    /// The denominator is Cramer's, so the error grows like 1/aspect² (as
    /// [`barycentric_3d_cramer_f32`]); fastest per query when a triangle is queried many times.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct PrecomputedTriangle3 {
        origin: Vec3,
        u_beta: Vec3,
        u_gamma: Vec3,
    }

    impl PrecomputedTriangle3 {
        /// Precompute `u_β` and `u_γ` for the triangle `[a, b, c]`.
        ///
        /// # Errors
        /// [`InterpError::DegenerateTriangle`] when the f32 denominator is zero or not finite,
        /// [`InterpError::NonFinite`] for NaN or infinite vertices.
        pub fn new([a, b, c]: [Vec3; 3]) -> Result<Self, InterpError> {
            if !(a.is_finite() && b.is_finite() && c.is_finite()) {
                return Err(InterpError::NonFinite { what: "triangle" });
            }
            let e1 = b - a;
            let e2 = c - a;
            let e11 = e1.dot(e1);
            let e22 = e2.dot(e2);
            let e12 = e1.dot(e2);
            let den = e11 * e22 - e12 * e12;
            if den == 0.0 || !den.is_finite() {
                return Err(InterpError::DegenerateTriangle);
            }
            Ok(Self {
                origin: a,
                u_beta: (e22 * e1 - e12 * e2) / den,
                u_gamma: (e11 * e2 - e12 * e1) / den,
            })
        }

        /// `[α, β, γ]` of `p` (projected onto the plane).
        #[must_use]
        pub fn weights(&self, p: Vec3) -> [f32; 3] {
            let f = p - self.origin;
            let beta = self.u_beta.dot(f);
            let gamma = self.u_gamma.dot(f);
            [1.0 - beta - gamma, beta, gamma]
        }
    }
}
