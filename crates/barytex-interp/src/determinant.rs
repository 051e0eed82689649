//! The 2×2 orientation determinant of f32 points, with an exact sign and an accurate magnitude.
//!
//! Shewchuk's adaptive predicates (the `robust` crate) guarantee the sign, but the value they
//! return after an adaptive stage is only accurate relative to the *input* magnitudes: on a
//! nearly collinear triple its relative error reached 5e-8, enough to spoil f32 barycentric
//! weights. For f32 inputs an exact answer is cheap instead: every product of two f32 values is
//! exact in f64 (48 significant bits, exponents far inside f64's range), so the determinant is an
//! exact sum of f64 products, which an expansion sum (Shewchuk's `grow_expansion`) adds without
//! error.

use glam::Vec2;

/// Shewchuk's `ccwerrboundA`, `(3 + 16ε)ε` with `ε = 2⁻⁵³`: the naive f64 cross product of
/// differences is within `CCW_ERRBOUND_A · (|left| + |right|)` of the exact one.
const CCW_ERRBOUND_A: f64 = (3.0 + 16.0 * f64::EPSILON / 2.0) * f64::EPSILON / 2.0;

/// The fast path is taken only when its relative error is below 2⁻³⁰, far below an f32 ulp.
const FAST_PATH_FACTOR: f64 = (1u64 << 30) as f64 * CCW_ERRBOUND_A;

/// `(b − a) × (c − a)` for f32 points (NaN or infinite when an input is): the sign is exact
/// and the value is within `2⁻³⁰` relative of the exact determinant (exactly 0 when the points
/// are collinear).
#[inline]
pub(crate) fn orient2d_det(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    filtered_cross(b, a, c, a, FAST_PATH_FACTOR)
}

/// The tighter filter of [`orient2d_det_precise`]: relative error below 2⁻⁵⁰.
const PRECISE_FACTOR: f64 = (1u64 << 50) as f64 * CCW_ERRBOUND_A;

/// [`orient2d_det`] within `2⁻⁵⁰` relative of the exact determinant: where a determinant's
/// error is not relative to a result that uses it alone (the normal of `barycentric_3d`, whose
/// direction error is multiplied by a point's distance from the plane).
#[inline]
pub(crate) fn orient2d_det_precise(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    filtered_cross(b, a, c, a, PRECISE_FACTOR)
}

/// `(b − a) × (c − a)` for finite f32 points with an exact sign; the value may be inaccurate
/// when the sign alone was certain. The filter is Shewchuk's plain bound, so near-collinear
/// points reach the exact sum only when even the sign is in doubt.
#[inline]
pub(crate) fn orient2d_sign_det(a: Vec2, b: Vec2, c: Vec2) -> f64 {
    filtered_cross(b, a, c, a, CCW_ERRBOUND_A)
}

/// `(p − q) × (r − s)` for f32 points, within 2⁻³⁰ relative of the exact value (exact sign): the
/// coefficients of the inverse-bilinear quadratic, where translating by one corner in f64 is not
/// exact once magnitudes differ by more than 2²⁹.
#[inline]
pub(crate) fn cross_of_differences(p: Vec2, q: Vec2, r: Vec2, s: Vec2) -> f64 {
    filtered_cross(p, q, r, s, FAST_PATH_FACTOR)
}

/// `(p − q) × (r − s)` in plain f64 when its error bound, `filter` times the products'
/// magnitudes, is below its magnitude; otherwise the exact sum of the eight f32 × f32 products.
#[inline]
fn filtered_cross(p: Vec2, q: Vec2, r: Vec2, s: Vec2, filter: f64) -> f64 {
    let [px, py, qx, qy, rx, ry, sx, sy] = [p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y].map(f64::from);
    let left = (px - qx) * (ry - sy);
    let right = (py - qy) * (rx - sx);
    let det = left - right;
    // A non-finite input always makes `det` NaN or infinite (every coordinate meets an infinite
    // difference in some product), and finite f32 inputs never do: callers test `det` instead of
    // the eight inputs.
    if det.abs() > filter * (left.abs() + right.abs()) || !det.is_finite() {
        return det;
    }
    exact_cross(px, py, qx, qy, rx, ry, sx, sy)
}

#[cold]
#[allow(clippy::too_many_arguments)]
fn exact_cross(px: f64, py: f64, qx: f64, qy: f64, rx: f64, ry: f64, sx: f64, sy: f64) -> f64 {
    exact_sum(&cross_products(px, py, qx, qy, rx, ry, sx, sy))
}

/// The exact sum of at most [`MAX_TERMS`] f64 values (each product of two f32 values is one),
/// rounded within one ulp.
fn exact_sum(terms: &[f64]) -> f64 {
    let mut expansion = [0.0f64; MAX_TERMS];
    let mut len = 0;
    for &t in terms.iter().take(MAX_TERMS) {
        len = grow_expansion(&mut expansion, len, t);
    }
    // Components are non-overlapping and in increasing magnitude: summing from the smallest
    // gives the exact sum rounded within one ulp.
    expansion[..len].iter().fold(0.0, |acc, &x| acc + x)
}

/// The most terms [`exact_sum`] adds: the 16 products of the inverse-bilinear coefficient `B`.
const MAX_TERMS: usize = 16;

/// `(p − q) × (r − s) − (t − v) × (r' − s')`-style sums: the difference of two crosses of
/// differences, each given as its four points, within 2⁻³⁰ relative of the exact value.
pub(crate) fn difference_of_crosses(first: [Vec2; 4], second: [Vec2; 4]) -> f64 {
    let a = first.map(|v| v.as_dvec2());
    let b = second.map(|v| v.as_dvec2());
    let l1 = (a[0].x - a[1].x) * (a[2].y - a[3].y);
    let r1 = (a[0].y - a[1].y) * (a[2].x - a[3].x);
    let l2 = (b[0].x - b[1].x) * (b[2].y - b[3].y);
    let r2 = (b[0].y - b[1].y) * (b[2].x - b[3].x);
    let value = (l1 - r1) - (l2 - r2);
    let magnitude = l1.abs() + r1.abs() + l2.abs() + r2.abs();
    // Two crosses and one more subtraction: twice the single-cross filter is a safe bound.
    if value.abs() > 2.0 * FAST_PATH_FACTOR * magnitude || !value.is_finite() {
        return value;
    }
    let c1 = cross_products(
        a[0].x, a[0].y, a[1].x, a[1].y, a[2].x, a[2].y, a[3].x, a[3].y,
    );
    let c2 = cross_products(
        b[0].x, b[0].y, b[1].x, b[1].y, b[2].x, b[2].y, b[3].x, b[3].y,
    );
    let mut terms = [0.0; 16];
    terms[..8].copy_from_slice(&c1);
    for (t, c) in terms[8..].iter_mut().zip(c2) {
        *t = -c;
    }
    exact_sum(&terms)
}

/// The eight exact products of `(p − q) × (r − s)` expanded.
#[allow(clippy::too_many_arguments)]
fn cross_products(
    px: f64,
    py: f64,
    qx: f64,
    qy: f64,
    rx: f64,
    ry: f64,
    sx: f64,
    sy: f64,
) -> [f64; 8] {
    [
        px * ry,
        -(px * sy),
        -(qx * ry),
        qx * sy,
        -(py * rx),
        py * sx,
        qy * rx,
        -(qy * sx),
    ]
}

/// Knuth's two-sum: `a + b = s + e` exactly.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// Add `b` to the non-overlapping expansion `e[..len]` (Shewchuk's `grow_expansion` with zero
/// elimination); returns the new length, at most `len + 1`.
fn grow_expansion(e: &mut [f64; MAX_TERMS], len: usize, b: f64) -> usize {
    let mut q = b;
    let mut out = 0;
    for i in 0..len {
        let (sum, err) = two_sum(q, e[i]);
        q = sum;
        if err != 0.0 {
            e[out] = err;
            out += 1;
        }
    }
    if q != 0.0 || out == 0 {
        e[out] = q;
        out += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cancellation_is_exact() {
        // Found by a property test: robust's value was 5e-8 off here.
        let a = Vec2::new(0.0, -0.0);
        let b = Vec2::new(-0.0, -1.441_152e18);
        let c = Vec2::new(18.666_668, 1.917_516_9e27);
        let det = orient2d_det(a, b, c);
        // Exact: −(−1.441152e18 · 18.666668) computed in f64 (exact product of f32 values).
        let want = -(f64::from(b.y) * f64::from(c.x));
        assert_eq!(det, want);
    }

    #[test]
    fn collinear_is_zero() {
        let a = Vec2::new(12.0, 12.0);
        let b = Vec2::new(24.0, 24.0);
        assert_eq!(orient2d_det(a, b, Vec2::new(0.5, 0.5)), 0.0);
        assert_eq!(orient2d_det(Vec2::ONE, Vec2::ONE, Vec2::ONE), 0.0);
    }
}
