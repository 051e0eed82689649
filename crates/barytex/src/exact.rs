//! Exact rational arithmetic for `barytex examples`: the reference every worked example is
//! checked against, small enough to ship in the command.
//!
//! Every finite f32 is a rational `m·2ᵉ` (IEEE 754-2019, §3.4), so sums, differences, products
//! and quotients of f32 values are exact rationals; [`Q`] holds them as a reduced `i128`
//! fraction. That is enough for the examples, whose inputs are small integers, small fractions
//! and f32 values near them: the largest numerator or denominator they reach is below 2⁶⁴
//! (Kettner's grid: coordinates are multiples of 2⁻²⁴ below 2⁵, so each determinant's terms are
//! multiples of 2⁻⁴⁸ below 2¹¹), far inside `i128`. An operation whose result does not fit
//! panics with [`OVERFLOW`] rather than wrap: with the examples' fixed inputs that would be a bug.
//! (The test suites check the library against `barytex-testkit`'s arbitrary-precision rationals
//! instead; this module is checked against those in its tests.)

use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

use barytex_interp::Location;
use glam::Vec2;

/// The panic message of an operation whose exact result does not fit in `i128`.
pub(crate) const OVERFLOW: &str = "exact rational arithmetic overflowed i128";

/// An exact rational `num / den`, reduced, with `den > 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Q {
    num: i128,
    den: i128,
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// `a / g` for a divisor `g` of `|a|` (so the quotient fits whenever `g > 1` or `a` does).
fn div_exact(a: i128, g: u128) -> i128 {
    if g == 1 {
        return a;
    }
    let q = i128::try_from(a.unsigned_abs() / g).expect(OVERFLOW);
    if a < 0 { -q } else { q }
}

impl Q {
    /// Zero.
    pub(crate) const ZERO: Self = Self { num: 0, den: 1 };

    /// `num / den`, reduced.
    ///
    /// # Panics
    /// When `den` is zero, or the reduced fraction's sign change overflows.
    #[must_use]
    pub(crate) fn new(num: i128, den: i128) -> Self {
        assert!(den != 0, "rational with zero denominator");
        let g = gcd(num.unsigned_abs(), den.unsigned_abs());
        let (num, den) = (div_exact(num, g), div_exact(den, g));
        if den < 0 {
            Self {
                num: num.checked_neg().expect(OVERFLOW),
                den: den.checked_neg().expect(OVERFLOW),
            }
        } else {
            Self { num, den }
        }
    }

    /// The integer `n`.
    #[must_use]
    pub(crate) fn int(n: i64) -> Self {
        Self {
            num: i128::from(n),
            den: 1,
        }
    }

    /// The exact value of `x`: `None` for NaN, infinities, and the f32 values whose exact
    /// fraction this type does not hold (magnitudes of 2¹²⁶ and up, and those that are not a
    /// multiple of 2⁻¹²⁶, all below 2⁻¹⁰²).
    #[must_use]
    pub(crate) fn from_f32(x: f32) -> Option<Self> {
        if !x.is_finite() {
            return None;
        }
        let bits = x.to_bits();
        let exponent = ((bits >> 23) & 0xff) as i32;
        let fraction = bits & 0x7f_ffff;
        // x = ±m·2ᵉ (IEEE 754 binary32: subnormals have no implicit bit and exponent −149).
        let (mut m, mut e) = if exponent == 0 {
            (fraction, -149)
        } else {
            (fraction | 0x80_0000, exponent - 150)
        };
        if m == 0 {
            return Some(Self::ZERO);
        }
        let shift = m.trailing_zeros();
        m >>= shift;
        e += shift as i32;
        let m = i128::from(m);
        let m = if x.is_sign_negative() { -m } else { m };
        let bits_of_m = (32 - (m.unsigned_abs() as u32).leading_zeros()) as i32;
        if e >= 0 {
            (bits_of_m + e <= 126).then(|| Self {
                num: m << e,
                den: 1,
            })
        } else {
            (-e <= 126).then(|| Self {
                num: m,
                den: 1 << -e,
            })
        }
    }

    /// `⌈self⌉`, `None` beyond the `i64` range.
    #[must_use]
    pub(crate) fn ceil(self) -> Option<i64> {
        // den > 0: the floor of −num/den, negated.
        i64::try_from(-(-self.num).div_euclid(self.den)).ok()
    }

    /// The sign: 1, −1 or 0.
    #[must_use]
    pub(crate) fn signum(self) -> i8 {
        self.num.signum() as i8
    }

    /// `|self|`.
    #[must_use]
    pub(crate) fn abs(self) -> Self {
        if self.num < 0 { -self } else { self }
    }

    /// The f64 nearest `self`, ties to even (correctly rounded: 66 quotient bits by long
    /// division and a sticky bit for the rest, then one rounding; no result of an `i128`
    /// fraction is subnormal or infinite in f64).
    #[must_use]
    pub(crate) fn to_f64(self) -> f64 {
        if self.num == 0 {
            return 0.0;
        }
        let (n, d) = (self.num.unsigned_abs(), self.den.unsigned_abs());
        // Normalize both so their top bits are set: n/d = (big_n/big_d)·2^(sd − sn), with
        // big_n/big_d in (1/2, 2).
        let (sn, sd) = (n.leading_zeros(), d.leading_zeros());
        let (big_n, big_d) = (n << sn, d << sd);
        // Long division, one quotient bit per step. The partial remainder r stays below 2·big_d
        // but may pass 2¹²⁸ after doubling: `carry` holds its 2¹²⁸ bit.
        const BITS: i32 = 66;
        let (mut quotient, mut r, mut carry) = (0u128, big_n, false);
        for _ in 0..BITS {
            let bit = carry || r >= big_d;
            if bit {
                r = r.wrapping_sub(big_d);
            }
            quotient = (quotient << 1) | u128::from(bit);
            carry = r >> 127 == 1;
            r <<= 1;
        }
        // quotient = floor(big_n/big_d · 2⁶⁵), with at least 65 significant bits: folding the
        // remainder into the lowest bit (sticky) leaves round-to-nearest-even unchanged and
        // makes an exact tie distinguishable from just above one.
        let sticky = carry || r != 0;
        let magnitude = (quotient | u128::from(sticky)) as f64;
        // 2^(sd − sn − 65) is a normal f64 (the exponent is within ±200), so this product is
        // exact.
        let exponent = sd as i32 - sn as i32 - (BITS - 1);
        let scale = f64::from_bits(((exponent + 1023) as u64) << 52);
        let value = magnitude * scale;
        if self.num < 0 { -value } else { value }
    }
}

impl fmt::Display for Q {
    /// `num/den`, or `num` for an integer.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}

impl PartialOrd for Q {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Q {
    /// a/b against c/d as a·d against c·b (both denominators positive).
    ///
    /// # Panics
    /// When a product does not fit in `i128` ([`OVERFLOW`]).
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        let left = self.num.checked_mul(other.den).expect(OVERFLOW);
        let right = other.num.checked_mul(self.den).expect(OVERFLOW);
        left.cmp(&right)
    }
}

/// The scanline fill's arithmetic (`barytex_raster::scanline`), exactly.
impl barytex_raster::scanline::Scalar for Q {
    fn from_i64(i: i64) -> Self {
        Self::int(i)
    }

    fn half() -> Self {
        Self::new(1, 2)
    }

    fn ceil_i64(&self) -> Option<i64> {
        self.ceil()
    }
}

impl Neg for Q {
    type Output = Self;
    fn neg(self) -> Self {
        Self {
            num: self.num.checked_neg().expect(OVERFLOW),
            den: self.den,
        }
    }
}

impl Add for Q {
    type Output = Self;
    fn add(self, other: Self) -> Self {
        let g = gcd(self.den.unsigned_abs(), other.den.unsigned_abs());
        let (left, right) = (div_exact(self.den, g), div_exact(other.den, g));
        let den = self.den.checked_mul(right).expect(OVERFLOW);
        let num = self
            .num
            .checked_mul(right)
            .and_then(|a| other.num.checked_mul(left).and_then(|b| a.checked_add(b)))
            .expect(OVERFLOW);
        Self::new(num, den)
    }
}

impl Sub for Q {
    type Output = Self;
    fn sub(self, other: Self) -> Self {
        self + -other
    }
}

impl Mul for Q {
    type Output = Self;
    fn mul(self, other: Self) -> Self {
        if self.num == 0 || other.num == 0 {
            return Self::ZERO;
        }
        // Cancel across first, so the products are already reduced.
        let g1 = gcd(self.num.unsigned_abs(), other.den.unsigned_abs());
        let g2 = gcd(other.num.unsigned_abs(), self.den.unsigned_abs());
        Self {
            num: div_exact(self.num, g1)
                .checked_mul(div_exact(other.num, g2))
                .expect(OVERFLOW),
            den: div_exact(self.den, g2)
                .checked_mul(div_exact(other.den, g1))
                .expect(OVERFLOW),
        }
    }
}

impl Div for Q {
    type Output = Self;
    /// # Panics
    /// On division by zero.
    fn div(self, other: Self) -> Self {
        assert!(other.num != 0, "rational division by zero");
        self * Self::new(other.den, other.num)
    }
}

/// A 2D point with rational coordinates.
pub(crate) type P2 = [Q; 2];

/// The exact value of an f32 point.
///
/// # Panics
/// On a coordinate [`Q::from_f32`] cannot hold (the examples' points are small and finite).
#[must_use]
pub(crate) fn p2(v: Vec2) -> P2 {
    [v.x, v.y].map(|c| Q::from_f32(c).expect("a finite f32 of moderate magnitude"))
}

/// `(a − o) × (b − o)`.
#[must_use]
pub(crate) fn cross(o: P2, a: P2, b: P2) -> Q {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// The exact sign of `(b − a) × (c − a)`: 1, −1 or 0.
#[must_use]
pub(crate) fn orient2d_sign(a: Vec2, b: Vec2, c: Vec2) -> i8 {
    cross(p2(a), p2(b), p2(c)).signum()
}

/// The exact barycentric weights of rational `p` in rational `tri`; `None` for zero area.
#[must_use]
pub(crate) fn barycentric(p: P2, [a, b, c]: [P2; 3]) -> Option<[Q; 3]> {
    let total = cross(a, b, c);
    (total.signum() != 0).then(|| {
        [
            cross(b, c, p) / total,
            cross(c, a, p) / total,
            cross(a, b, p) / total,
        ]
    })
}

/// The exact barycentric weights of the f32 point `p` in `tri`; `None` for zero area.
#[must_use]
pub(crate) fn barycentric_2d(p: Vec2, tri: [Vec2; 3]) -> Option<[Q; 3]> {
    barycentric(p2(p), tri.map(p2))
}

/// Where the f32 point `p` lies relative to `tri`, exactly.
#[must_use]
pub(crate) fn location_2d(p: Vec2, tri: [Vec2; 3]) -> Location {
    let Some(w) = barycentric_2d(p, tri) else {
        return Location::Degenerate;
    };
    let signs = w.map(Q::signum);
    if signs.contains(&-1) {
        return Location::Outside;
    }
    match signs.iter().filter(|&&s| s == 0).count() {
        0 => Location::Inside,
        1 => Location::OnEdge(signs.iter().position(|&s| s == 0).unwrap_or(0)),
        _ => Location::OnVertex(signs.iter().position(|&s| s != 0).unwrap_or(0)),
    }
}

/// The bilinear map of the rational quad `[x, y, z, w]` at rational `(α, β)`:
/// `(1−α)(1−β)x + α(1−β)y + αβz + (1−α)βw`.
#[must_use]
pub(crate) fn bilinear(quad: [P2; 4], alpha: Q, beta: Q) -> P2 {
    let one = Q::int(1);
    let weights = [
        (one - alpha) * (one - beta),
        alpha * (one - beta),
        alpha * beta,
        (one - alpha) * beta,
    ];
    std::array::from_fn(|i| {
        weights
            .iter()
            .zip(&quad)
            .fold(Q::ZERO, |sum, (&w, c)| sum + w * c[i])
    })
}

/// `|a − b|`, rounded to f64.
#[must_use]
pub(crate) fn abs_diff(a: Q, b: Q) -> f64 {
    (a - b).abs().to_f64()
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use barytex_testkit::exact as big;
    use barytex_testkit::seeded::XorShift;
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::ToPrimitive;

    /// An f32 that is `k·2⁻ʲ` with `|k| < 2²⁴`, `j ≤ 24`: the examples' kind of value.
    fn moderate_f32(rng: &mut XorShift) -> f32 {
        let k = rng.i32_in(-(1 << 23), 1 << 23) as f32;
        k * 2f32.powi(-rng.i32_in(0, 24))
    }

    fn moderate_point(rng: &mut XorShift) -> Vec2 {
        Vec2::new(moderate_f32(rng), moderate_f32(rng))
    }

    /// The same rational in both representations (compared through their printed form, which is
    /// `num/den` reduced, or the integer, in both).
    fn same(ours: Q, theirs: &big::Q) -> bool {
        ours.to_string() == theirs.to_string()
    }

    #[test]
    fn from_f32_is_exact() {
        let mut rng = XorShift::new(1);
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.5,
            0.1,
            f32::MIN_POSITIVE * 2.0,
            3.0e30,
            11.0 / 3.0,
        ] {
            assert!(same(Q::from_f32(x).unwrap(), &big::qf(x)), "{x}");
        }
        for _ in 0..100_000 {
            let x = f32::from_bits(rng.next_u64() as u32);
            // Representable: finite, below 2¹²⁶, and a multiple of 2⁻¹²⁶ (scaling is exact in
            // f64).
            let fits = x.is_finite()
                && x.abs() < 2f32.powi(126)
                && (f64::from(x) * 2f64.powi(126)).fract() == 0.0;
            match Q::from_f32(x) {
                Some(q) => assert!(fits && same(q, &big::qf(x)), "{x:e}"),
                None => assert!(!fits, "{x:e} refused"),
            }
        }
        // The edges of what fits.
        assert!(Q::from_f32(2f32.powi(-126)).is_some());
        assert!(Q::from_f32(3.0 * 2f32.powi(-127)).is_none());
        assert!(Q::from_f32(1.99 * 2f32.powi(125)).is_some());
        assert!(Q::from_f32(-(2f32.powi(126))).is_none());
        assert_eq!(Q::from_f32(f32::NAN), None);
        assert_eq!(Q::from_f32(f32::INFINITY), None);
        assert_eq!(Q::from_f32(f32::from_bits(1)), None);
    }

    #[test]
    fn arithmetic_matches_big_rationals() {
        let mut rng = XorShift::new(2);
        for _ in 0..10_000 {
            let (x, y) = (moderate_f32(&mut rng), moderate_f32(&mut rng));
            let (a, b) = (Q::from_f32(x).unwrap(), Q::from_f32(y).unwrap());
            let (ba, bb) = (big::qf(x), big::qf(y));
            assert!(same(a + b, &(&ba + &bb)), "{x} + {y}");
            assert!(same(a - b, &(&ba - &bb)), "{x} - {y}");
            assert!(same(a * b, &(&ba * &bb)), "{x} * {y}");
            if y != 0.0 {
                assert!(same(a / b, &(&ba / &bb)), "{x} / {y}");
            }
        }
        assert_eq!(Q::new(6, -4).to_string(), "-3/2");
        assert_eq!(Q::new(-7, 7).to_string(), "-1");
        assert_eq!((Q::int(1) / Q::int(3) * Q::int(3)).to_string(), "1");
    }

    /// Order and ceiling, against the big rationals' (what the scanline fill relies on).
    #[test]
    fn order_and_ceiling_match_big_rationals() {
        let mut rng = XorShift::new(4);
        for _ in 0..10_000 {
            let (x, y) = (moderate_f32(&mut rng), moderate_f32(&mut rng));
            let (a, b) = (Q::from_f32(x).unwrap(), Q::from_f32(y).unwrap());
            assert_eq!(a.cmp(&b), big::qf(x).cmp(&big::qf(y)), "{x} vs {y}");
            let ceil = big::qf(x).ceil().to_integer().to_i64();
            assert_eq!(a.ceil(), ceil, "⌈{x}⌉");
        }
        assert_eq!(Q::new(-7, 2).ceil(), Some(-3));
        assert_eq!(Q::new(7, 2).ceil(), Some(4));
        assert_eq!(Q::int(-3).ceil(), Some(-3));
        assert_eq!(Q::new(i128::MAX, 1).ceil(), None);
        assert!(Q::new(1, 3) < Q::new(1, 2) && Q::new(-1, 2) < Q::new(-1, 3));
    }

    #[test]
    #[should_panic(expected = "overflowed")]
    fn overflow_panics_instead_of_wrapping() {
        let big = Q::new(i128::MAX, 1);
        let _ = big + Q::int(1);
    }

    #[test]
    fn to_f64_is_correctly_rounded() {
        let mut rng = XorShift::new(3);
        // Small numerator and denominator: one IEEE division of exact values is correctly
        // rounded.
        for _ in 0..10_000 {
            let n = (rng.next_u64() >> 12) as i128 - (1 << 51);
            let d = (rng.next_u64() >> 12) as i128 + 1;
            assert_eq!(Q::new(n, d).to_f64(), n as f64 / d as f64, "{n}/{d}");
        }
        // Wide ones, against num-rational's conversion (correctly rounded, ties to even).
        for _ in 0..10_000 {
            let wide = |rng: &mut XorShift| {
                let bits = rng.i32_in(1, 126) as u32;
                ((u128::from(rng.next_u64()) << 64 | u128::from(rng.next_u64())) >> (128 - bits))
                    .max(1) as i128
            };
            let (n, d) = (wide(&mut rng), wide(&mut rng));
            let n = if rng.next_u64() & 1 == 0 { n } else { -n };
            let reference = BigRational::new(BigInt::from(n), BigInt::from(d));
            assert_eq!(
                Q::new(n, d).to_f64(),
                reference.to_f64().unwrap(),
                "{n}/{d}"
            );
        }
        // Exact ties round to even: (2⁵³ + 1)/1 and (2⁵³ + 3)/1.
        assert_eq!(Q::int((1 << 53) + 1).to_f64(), (1u64 << 53) as f64);
        assert_eq!(Q::int((1 << 53) + 3).to_f64(), ((1u64 << 53) + 4) as f64);
        assert_eq!(Q::new(-1, 3).to_f64(), -1.0 / 3.0);
    }

    #[test]
    fn geometry_matches_big_rationals() {
        let mut rng = XorShift::new(4);
        for _ in 0..2_000 {
            let (p, a, b, c) = (
                moderate_point(&mut rng),
                moderate_point(&mut rng),
                moderate_point(&mut rng),
                moderate_point(&mut rng),
            );
            assert_eq!(orient2d_sign(a, b, c), big::orient2d_sign(a, b, c));
            let ours = barycentric_2d(p, [a, b, c]);
            let theirs = big::barycentric_2d(p, [a, b, c]);
            assert_eq!(ours.is_some(), theirs.is_some());
            if let (Some(ours), Some(theirs)) = (ours, theirs) {
                assert!(ours.iter().zip(&theirs).all(|(o, t)| same(*o, t)));
            }
            assert_eq!(location_2d(p, [a, b, c]), big::location_2d(p, [a, b, c]));
            let quad = [a, b, c, p];
            let (alpha, beta) = (rng.f32_in(-1.0, 2.0), rng.f32_in(-1.0, 2.0));
            let ours = bilinear(
                quad.map(p2),
                Q::from_f32(alpha).unwrap(),
                Q::from_f32(beta).unwrap(),
            );
            let theirs = big::bilinear_2d(quad, f64::from(alpha), f64::from(beta));
            assert!(same(ours[0], &theirs[0]) && same(ours[1], &theirs[1]));
        }
        // Exactly on a vertex, on an edge, collinear.
        let tri = [Vec2::ZERO, Vec2::new(2.0, 0.0), Vec2::new(0.0, 2.0)];
        assert_eq!(location_2d(Vec2::new(2.0, 0.0), tri), Location::OnVertex(1));
        assert_eq!(location_2d(Vec2::new(1.0, 1.0), tri), Location::OnEdge(0));
        let flat = [Vec2::ZERO, Vec2::ONE, Vec2::splat(2.0)];
        assert_eq!(location_2d(Vec2::ONE, flat), Location::Degenerate);
    }
}
