//! Exact-rational reference implementations: every finite float is a rational, so these answers
//! carry no rounding at all.

use barytex_interp::Location;
use glam::{Vec2, Vec3};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};

/// An exact rational number.
pub type Q = BigRational;

/// The exact value of a finite float; `None` for NaN or infinities.
#[must_use]
pub fn q(x: f64) -> Option<Q> {
    Q::from_float(x)
}

/// The exact value of a finite float.
///
/// # Panics
/// On NaN or infinite input: callers filter those first.
#[must_use]
pub fn qf(x: f32) -> Q {
    q(f64::from(x)).expect("finite input")
}

/// The rational nearest f64 (rounded by `num`'s conversion).
#[must_use]
pub fn to_f64(x: &Q) -> f64 {
    x.to_f64().unwrap_or(f64::NAN)
}

/// `|a − b|` as f64.
#[must_use]
pub fn abs_diff(a: &Q, b: &Q) -> f64 {
    to_f64(&(a - b).abs())
}

type P2 = [Q; 2];
type P3 = [Q; 3];

fn p2(v: Vec2) -> P2 {
    [qf(v.x), qf(v.y)]
}

fn p3(v: Vec3) -> P3 {
    [qf(v.x), qf(v.y), qf(v.z)]
}

fn cross2(o: &P2, a: &P2, b: &P2) -> Q {
    (&a[0] - &o[0]) * (&b[1] - &o[1]) - (&a[1] - &o[1]) * (&b[0] - &o[0])
}

/// The exact determinant `(b − a) × (c − a)`.
#[must_use]
pub fn orient2d_det(a: Vec2, b: Vec2, c: Vec2) -> Q {
    cross2(&p2(a), &p2(b), &p2(c))
}

/// The exact sign of `(b − a) × (c − a)`: 1, −1 or 0.
#[must_use]
pub fn orient2d_sign(a: Vec2, b: Vec2, c: Vec2) -> i8 {
    sign(&orient2d_det(a, b, c))
}

fn sign(x: &Q) -> i8 {
    if x.is_positive() {
        1
    } else if x.is_negative() {
        -1
    } else {
        0
    }
}

/// Exact barycentric weights of `p` in `tri`; `None` for a zero-area triangle.
#[must_use]
pub fn barycentric_2d(p: Vec2, tri: [Vec2; 3]) -> Option<[Q; 3]> {
    let [a, b, c] = tri.map(p2);
    let p = p2(p);
    let total = cross2(&a, &b, &c);
    if total.is_zero() {
        return None;
    }
    Some([
        cross2(&b, &c, &p) / &total,
        cross2(&c, &a, &p) / &total,
        cross2(&a, &b, &p) / &total,
    ])
}

/// The exact location of `p` relative to `tri`.
#[must_use]
pub fn location_2d(p: Vec2, tri: [Vec2; 3]) -> Location {
    let Some(w) = barycentric_2d(p, tri) else {
        return Location::Degenerate;
    };
    let signs = w.map(|wi| sign(&wi));
    if signs.contains(&-1) {
        return Location::Outside;
    }
    match signs.iter().filter(|&&s| s == 0).count() {
        0 => Location::Inside,
        1 => Location::OnEdge(signs.iter().position(|&s| s == 0).unwrap_or(0)),
        _ => Location::OnVertex(signs.iter().position(|&s| s != 0).unwrap_or(0)),
    }
}

fn sub3(a: &P3, b: &P3) -> P3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn cross3(a: &P3, b: &P3) -> P3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn dot3(a: &P3, b: &P3) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// The exact determinant `det[b − a, c − a, d − a] = ((b − a) × (c − a)) · (d − a)`
/// (the sign convention of `barytex_interp::orient3d`).
///
/// # Panics
/// On NaN or infinite input: callers filter those first.
#[must_use]
pub fn orient3d_det(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> Q {
    let [a, b, c, d] = [a, b, c, d].map(p3);
    dot3(&cross3(&sub3(&b, &a), &sub3(&c, &a)), &sub3(&d, &a))
}

/// The exact sign of `det[b − a, c − a, d − a]`: 1, −1 or 0.
///
/// # Panics
/// On NaN or infinite input: callers filter those first.
#[must_use]
pub fn orient3d_sign(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> i8 {
    sign(&orient3d_det(a, b, c, d))
}

/// Exact barycentric weights of the orthogonal projection of `p` onto the plane of `tri`;
/// `None` for collinear vertices.
#[must_use]
pub fn barycentric_3d(p: Vec3, tri: [Vec3; 3]) -> Option<[Q; 3]> {
    let [a, b, c] = tri.map(p3);
    let p = p3(p);
    let n = cross3(&sub3(&b, &a), &sub3(&c, &a));
    let nn = dot3(&n, &n);
    if nn.is_zero() {
        return None;
    }
    let area = |q: &P3, r: &P3| dot3(&cross3(&sub3(q, &p), &sub3(r, &p)), &n) / &nn;
    Some([area(&b, &c), area(&c, &a), area(&a, &b)])
}

/// The exact bilinear map of `quad` at `(α, β)`.
#[must_use]
pub fn bilinear_2d(quad: [Vec2; 4], alpha: f64, beta: f64) -> [Q; 2] {
    let [x, y, z, w] = quad.map(p2);
    let a = q(alpha).unwrap_or_default();
    let b = q(beta).unwrap_or_default();
    let one = Q::from_integer(BigInt::from(1));
    let wx = (&one - &a) * (&one - &b);
    let wy = &a * (&one - &b);
    let wz = &a * &b;
    let ww = (&one - &a) * &b;
    core::array::from_fn(|i| &wx * &x[i] + &wy * &y[i] + &wz * &z[i] + &ww * &w[i])
}

/// Exact perspective-correct weights `(αᵢ/wᵢ)/Σ(αⱼ/wⱼ)`; `None` when the sum is zero.
#[must_use]
pub fn perspective_weights(screen: &[f32], w: &[f32]) -> Option<Vec<Q>> {
    let q: Vec<Q> = screen
        .iter()
        .zip(w)
        .map(|(&a, &wi)| qf(a) / qf(wi))
        .collect();
    let sum: Q = q.iter().cloned().sum();
    if sum.is_zero() {
        return None;
    }
    Some(q.iter().map(|qi| qi / &sum).collect())
}

/// `x · 2¹⁴⁹`, an integer for every finite f32.
fn fixed_point(x: f32) -> BigInt {
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32;
    let fraction = i64::from(bits & 0x7f_ffff);
    // Subnormals: fraction · 2⁻¹⁴⁹; normals: (2²³ + fraction) · 2^(exponent − 150).
    let (mantissa, shift) = if exponent == 0 {
        (fraction, 0)
    } else {
        (fraction | 0x80_0000, exponent - 1)
    };
    let magnitude = BigInt::from(mantissa) << shift;
    if bits >> 31 == 1 {
        -magnitude
    } else {
        magnitude
    }
}

/// The exact 2D hull's vertex set by brute force (`O(n³)` rational orientations, for small
/// inputs): with `keep`, every distinct point on the boundary, else only the strict corners
/// (for collinear input, the two extreme points). Each point is named by the lowest index of its
/// coordinates (`-0.0` equals `0.0`); the result is sorted ascending.
///
/// A directed pair `(a, b)` of distinct points supports the set when no point is strictly right
/// of `a → b`; the boundary is every point on a supporting line, and a corner is a boundary
/// point that is lowest or highest, in (x, y) order, on one of its supporting lines.
///
/// # Panics
/// On NaN or infinite input: callers filter those first.
#[must_use]
pub fn convex_hull_2d_vertex_set(points: &[Vec2], keep: bool) -> Vec<usize> {
    let mut distinct: Vec<(Vec2, usize)> = Vec::new();
    for (i, &p) in points.iter().enumerate() {
        if !distinct.iter().any(|&(q, _)| q == p) {
            distinct.push((p, i));
        }
    }
    if distinct.len() < 2 {
        return distinct.iter().map(|&(_, i)| i).collect();
    }
    // Every finite f32 is an integer multiple of 2⁻¹⁴⁹: scaled by 2¹⁴⁹ the coordinates are
    // integers, and integer cross products avoid the rationals' gcd on every operation.
    let scaled: Vec<[BigInt; 2]> = distinct
        .iter()
        .map(|&(p, _)| [fixed_point(p.x), fixed_point(p.y)])
        .collect();
    let cross = |o: &[BigInt; 2], a: &[BigInt; 2], b: &[BigInt; 2]| {
        let c = (&a[0] - &o[0]) * (&b[1] - &o[1]) - (&a[1] - &o[1]) * (&b[0] - &o[0]);
        match c.sign() {
            num_bigint::Sign::Plus => 1i8,
            num_bigint::Sign::Minus => -1,
            num_bigint::Sign::NoSign => 0,
        }
    };
    // Keys have `-0.0` normalised to `0.0`, so `total_cmp` is the exact (x, y) order.
    let lex = |a: Vec2, b: Vec2| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y));
    let mut boundary = vec![false; distinct.len()];
    let mut corner = vec![false; distinct.len()];
    for a in 0..distinct.len() {
        for b in 0..distinct.len() {
            if a == b {
                continue;
            }
            let signs: Vec<i8> = scaled
                .iter()
                .map(|q| cross(&scaled[a], &scaled[b], q))
                .collect();
            if signs.contains(&-1) {
                continue;
            }
            let on_line: Vec<usize> = (0..distinct.len()).filter(|&q| signs[q] == 0).collect();
            for &q in &on_line {
                boundary[q] = true;
            }
            let key = |&q: &usize| distinct[q].0 + Vec2::ZERO;
            let ends = [
                on_line.iter().copied().min_by(|x, y| lex(key(x), key(y))),
                on_line.iter().copied().max_by(|x, y| lex(key(x), key(y))),
            ];
            for q in ends.into_iter().flatten() {
                corner[q] = true;
            }
        }
    }
    let chosen = if keep { &boundary } else { &corner };
    let mut out: Vec<usize> = (0..distinct.len())
        .filter(|&q| chosen[q])
        .map(|q| distinct[q].1)
        .collect();
    out.sort_unstable();
    out
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// Example 9 of A. Denisjuk's lecture *Interpolacja i teksturowanie* (the points of
    /// Exercise IV.5 in Buss, *3D Computer Graphics*, 2003): u = (1, 0) in x = (0, 0),
    /// y = (2, 3), z = (3, 1) has the weights (5/7, −1/7, 3/7).
    #[test]
    fn example_9_exact() {
        let tri = [Vec2::ZERO, Vec2::new(2.0, 3.0), Vec2::new(3.0, 1.0)];
        let w = barycentric_2d(Vec2::new(1.0, 0.0), tri).unwrap();
        let expect = [(5, 7), (-1, 7), (3, 7)];
        for (wi, (n, d)) in w.iter().zip(expect) {
            assert_eq!(*wi, Q::new(BigInt::from(n), BigInt::from(d)));
        }
    }

    #[test]
    fn fixed_point_is_exact() {
        let scale = Q::from_integer(BigInt::from(1) << 149);
        for x in [
            0.0f32,
            -0.0,
            1.0,
            -1.5,
            1e-45,
            -3e-39,
            1e-30,
            0.1,
            3.4e38,
            -f32::MAX,
        ] {
            assert_eq!(Q::from_integer(fixed_point(x)), qf(x) * &scale, "{x}");
        }
    }

    #[test]
    fn brute_force_hull_of_a_square_with_edge_points() {
        let points = [
            Vec2::ZERO,
            Vec2::new(1.0, 0.0),
            Vec2::new(2.0, 0.0),
            Vec2::new(2.0, 2.0),
            Vec2::new(0.0, 2.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(-0.0, 0.0),
        ];
        assert_eq!(convex_hull_2d_vertex_set(&points, false), vec![0, 2, 3, 4]);
        assert_eq!(
            convex_hull_2d_vertex_set(&points, true),
            vec![0, 1, 2, 3, 4]
        );
        assert_eq!(convex_hull_2d_vertex_set(&points[..3], false), vec![0, 2]);
        assert_eq!(convex_hull_2d_vertex_set(&points[..3], true), vec![0, 1, 2]);
        assert!(convex_hull_2d_vertex_set(&[], true).is_empty());
    }
}
