//! A SLERP reference far more precise than f64: 200-bit fixed point on big integers, from the
//! exact values of the inputs, for measuring the f64 SLERPs (whose errors are a few f64 ulps, so
//! an f64 reference cannot see them) and nearly opposite f32 inputs (whose arc plane an f64
//! normalization moves by `2⁻⁵³/sin θ`).
//!
//! The perpendicular part of `b` is `(a·a)·b − (a·b)·a` and `|a ∧ b|² = Σᵢ<ⱼ (aⱼbᵢ − aᵢbⱼ)²`, both
//! computed exactly in integers (so "exactly parallel" is decided exactly); the angle is
//! `atan2(|a ∧ b|, a·b)` by Newton's method on `sin`/`cos` Taylor series; every rounding is a
//! truncation at `2⁻²⁰⁰` relative to unit-size values, so the reference is within `2⁻¹⁹⁰` of the
//! true SLERP of the inputs' directions for `|t| ≤ 8`.

use num_bigint::BigInt;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// Fractional bits of the fixed-point numbers.
const F: u32 = 200;

/// A fixed-point number `v·2⁻²⁰⁰`.
#[derive(Clone, Debug, PartialEq)]
pub struct Fixed(BigInt);

impl Fixed {
    fn one() -> Self {
        Fixed(BigInt::one() << F)
    }
    fn from_int(k: i64) -> Self {
        Fixed(BigInt::from(k) << F)
    }
    /// The exact value of a finite `x` with no bits below `2⁻²⁰⁰` (truncated below).
    fn from_f64(x: f64) -> Self {
        let (m, e) = decompose(x);
        // x = m·2^e; as fixed point: m·2^(e + F).
        let shift = i64::from(e) + i64::from(F);
        Fixed(if shift >= 0 {
            m << shift as usize
        } else {
            m >> (-shift) as usize
        })
    }
    fn add(&self, o: &Self) -> Self {
        Fixed(&self.0 + &o.0)
    }
    fn sub(&self, o: &Self) -> Self {
        Fixed(&self.0 - &o.0)
    }
    fn mul(&self, o: &Self) -> Self {
        Fixed((&self.0 * &o.0) >> F)
    }
    fn div(&self, o: &Self) -> Self {
        Fixed((&self.0 << F) / &o.0)
    }
    fn div_int(&self, k: i64) -> Self {
        Fixed(&self.0 / k)
    }
    fn sqrt(&self) -> Self {
        Fixed((&self.0 << F).sqrt())
    }
    fn is_negligible(&self) -> bool {
        self.0.bits() < 8
    }
    /// The nearest f64 (to within one rounding).
    #[must_use]
    pub fn to_f64(&self) -> f64 {
        let scale = (BigInt::one() << F).to_f64().unwrap_or(f64::INFINITY);
        // Split to keep the conversion's own precision: integer part and fraction.
        let hi = &self.0 >> F;
        let lo = &self.0 - (&hi << F);
        hi.to_f64().unwrap_or(f64::NAN) + lo.to_f64().unwrap_or(f64::NAN) / scale
    }
}

/// `x = m·2^e` with an integer `m`, for finite `x`.
fn decompose(x: f64) -> (BigInt, i32) {
    if x == 0.0 {
        return (BigInt::zero(), 0);
    }
    let bits = x.to_bits();
    let sign = if bits >> 63 == 1 { -1 } else { 1 };
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    let (m, e) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), exponent - 1075)
    };
    (BigInt::from(m) * sign, e)
}

/// π to 200 bits (Machin: `π = 16·atan(1/5) − 4·atan(1/239)`).
fn pi() -> Fixed {
    fn atan_inverse(k: i64) -> Fixed {
        // atan(1/k) = Σ (−1)ⁿ / ((2n + 1)·k^(2n+1))
        let mut power = Fixed::one().div_int(k);
        let mut sum = power.clone();
        let mut n = 1;
        loop {
            power = power.div_int(k * k);
            if power.is_negligible() {
                return sum;
            }
            let term = power.div_int(2 * n + 1);
            sum = if n % 2 == 1 {
                sum.sub(&term)
            } else {
                sum.add(&term)
            };
            n += 1;
        }
    }
    let sixteen = atan_inverse(5).mul(&Fixed::from_int(16));
    sixteen.sub(&atan_inverse(239).mul(&Fixed::from_int(4)))
}

/// `(sin x, cos x)`, with `x` reduced to `[−π, π]` first.
fn sin_cos(x: &Fixed, pi: &Fixed) -> (Fixed, Fixed) {
    let two_pi = pi.add(pi);
    let shifted = x.add(pi).0;
    let mut turns = &shifted / &two_pi.0;
    if shifted.is_negative() && &turns * &two_pi.0 != shifted {
        turns -= 1;
    }
    let x = Fixed(&x.0 - turns * &two_pi.0);
    let x2 = x.mul(&x);
    let (mut sin, mut cos) = (x.clone(), Fixed::one());
    let (mut s_term, mut c_term) = (x, Fixed::one());
    let mut n: i64 = 1;
    loop {
        // s_term = x^(2n+1)/(2n+1)!, c_term = x^(2n)/(2n)!, alternating.
        c_term = c_term.mul(&x2).div_int((2 * n - 1) * (2 * n));
        s_term = s_term.mul(&x2).div_int((2 * n) * (2 * n + 1));
        if c_term.is_negligible() && s_term.is_negligible() {
            return (sin, cos);
        }
        if n % 2 == 1 {
            sin = sin.sub(&s_term);
            cos = cos.sub(&c_term);
        } else {
            sin = sin.add(&s_term);
            cos = cos.add(&c_term);
        }
        n += 1;
    }
}

/// `atan2(y, x)` for `y ≥ 0`, `(x, y) ≠ 0`: Newton's method from the f64 value.
fn atan2(y: &Fixed, x: &Fixed, pi: &Fixed) -> Fixed {
    let mut theta = Fixed::from_f64(y.to_f64().atan2(x.to_f64()));
    for _ in 0..6 {
        let (s, c) = sin_cos(&theta, pi);
        // θ += (y·cos θ − x·sin θ)/(x·cos θ + y·sin θ): the angle from θ to (x, y).
        let num = y.mul(&c).sub(&x.mul(&s));
        let den = x.mul(&c).add(&y.mul(&s));
        let step = num.div(&den);
        theta = theta.add(&step);
        if step.is_negligible() {
            break;
        }
    }
    theta
}

/// Scales `v` (exact values) by a power of two so that its largest component is in `[1, 2)`:
/// exact, and keeps every component of f32 or f64 inputs above `2⁻²⁰⁰`-truncation in practice.
fn fixed_vector(v: &[f64]) -> Vec<Fixed> {
    let m = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let e = if m > 0.0 { m.log2().floor() as i32 } else { 0 };
    v.iter()
        .map(|&x| Fixed::from_f64(x * 2f64.powi(-e.clamp(-1000, 1000))))
        .collect()
}

fn dot(a: &[Fixed], b: &[Fixed]) -> Fixed {
    a.iter()
        .zip(b)
        .fold(Fixed(BigInt::zero()), |s, (x, y)| s.add(&x.mul(y)))
}

/// The great-circle arc from the direction of `a` to that of `b`, in 200-bit fixed point.
#[derive(Clone, Debug)]
pub struct Arc {
    a_hat: Vec<Fixed>,
    e: Vec<Fixed>,
    theta: Fixed,
    pi: Fixed,
}

impl Arc {
    /// The arc of the directions of `a` and `b` (any lengths); `perpendicular` (normalized here)
    /// gives the arc's plane when `a` and `b` are exactly opposite. `None` when `a` or `b` is
    /// zero or not finite.
    #[must_use]
    pub fn new(a: &[f64], b: &[f64], perpendicular: &[f64]) -> Option<Self> {
        let valid = |v: &[f64]| v.iter().all(|x| x.is_finite()) && v.iter().any(|&x| x != 0.0);
        if !(valid(a) && valid(b)) {
            return None;
        }
        let (a, b) = (fixed_vector(a), fixed_vector(b));
        let pi = pi();
        let a_len = dot(&a, &a).sqrt();
        let a_hat: Vec<Fixed> = a.iter().map(|x| x.div(&a_len)).collect();
        // Exact in integers (scale 2^-2F per product): the minors, |a ∧ b|² and a·b.
        let n = a.len();
        let mut wedge2 = BigInt::zero();
        let mut minors = vec![vec![BigInt::zero(); n]; n];
        for i in 0..n {
            for j in 0..n {
                minors[i][j] = &a[j].0 * &b[i].0 - &a[i].0 * &b[j].0;
                if i < j {
                    wedge2 += &minors[i][j] * &minors[i][j];
                }
            }
        }
        let ab: BigInt = a.iter().zip(&b).map(|(x, y)| &x.0 * &y.0).sum();
        let (e, theta) = if wedge2.is_zero() {
            if ab.is_positive() {
                let zero = vec![Fixed(BigInt::zero()); n];
                return Some(Arc {
                    a_hat,
                    e: zero,
                    theta: Fixed(BigInt::zero()),
                    pi,
                });
            }
            let perp = fixed_vector(perpendicular);
            let len = dot(&perp, &perp).sqrt();
            (perp.iter().map(|x| x.div(&len)).collect(), pi.clone())
        } else {
            // p_i = Σ_j a_j·m_ij = (a·a)·b_i − (a·b)·a_i (scale 2^-3F), exact.
            let p: Vec<BigInt> = (0..n)
                .map(|i| (0..n).map(|j| &a[j].0 * &minors[i][j]).sum())
                .collect();
            let p2: BigInt = p.iter().map(|x| x * x).sum();
            let p_len = p2.sqrt();
            let e: Vec<Fixed> = p.iter().map(|x| Fixed((x << F) / &p_len)).collect();
            // sin θ and cos θ both scaled by |a||b| (scale 2^-2F), brought to fixed point.
            let sin = Fixed(wedge2.sqrt() >> F);
            let cos = Fixed(ab >> F);
            let theta = atan2(&sin, &cos, &pi);
            (e, theta)
        };
        Some(Arc {
            a_hat,
            e,
            theta,
            pi,
        })
    }

    /// The arc's angle θ ∈ [0, π].
    #[must_use]
    pub fn angle(&self) -> f64 {
        self.theta.to_f64()
    }

    /// The point at fraction `t` (any finite `t`, `|t| ≤ 64`): `cos(tθ)·â + sin(tθ)·ê`.
    ///
    /// # Panics
    /// For a non-finite `t` or `|t| > 64`.
    #[must_use]
    pub fn at(&self, t: f64) -> Vec<Fixed> {
        assert!(t.is_finite() && t.abs() <= 64.0, "t = {t}");
        let (s, c) = sin_cos(&Fixed::from_f64(t).mul(&self.theta), &self.pi);
        self.a_hat
            .iter()
            .zip(&self.e)
            .map(|(x, y)| c.mul(x).add(&s.mul(y)))
            .collect()
    }
}

/// Angle between the direction of `result` and the unit `reference`, and `|‖result‖ − 1|`, both
/// measured in fixed point (so f64 results a few ulps off are measured, not rounded away).
#[must_use]
pub fn errors(result: &[f64], reference: &[Fixed]) -> (f64, f64) {
    if result.iter().any(|x| !x.is_finite()) || result.iter().all(|&x| x == 0.0) {
        return (f64::INFINITY, f64::INFINITY);
    }
    let r: Vec<Fixed> = result.iter().map(|&x| Fixed::from_f64(x)).collect();
    let len = dot(&r, &r).sqrt();
    let r_hat: Vec<Fixed> = r.iter().map(|x| x.div(&len)).collect();
    let d: Vec<Fixed> = r_hat.iter().zip(reference).map(|(x, y)| x.sub(y)).collect();
    let s: Vec<Fixed> = r_hat.iter().zip(reference).map(|(x, y)| x.add(y)).collect();
    // The angle 2·atan2(|r̂ − ref|, |r̂ + ref|), evaluated in f64 from fixed-point lengths.
    let angle = 2.0
        * dot(&d, &d)
            .sqrt()
            .to_f64()
            .atan2(dot(&s, &s).sqrt().to_f64());
    (angle, len.sub(&Fixed::one()).to_f64().abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pi_and_trig_are_right() {
        let pi = pi();
        assert_eq!(pi.to_f64(), std::f64::consts::PI);
        let (s, c) = sin_cos(&Fixed::from_f64(0.5), &pi);
        assert!((s.to_f64() - 0.5f64.sin()).abs() <= 1e-16);
        assert!((c.to_f64() - 0.5f64.cos()).abs() <= 1e-16);
        let theta = atan2(&Fixed::from_f64(1.0), &Fixed::from_f64(-1.0), &pi);
        assert_eq!(theta.to_f64(), 0.75 * std::f64::consts::PI);
        // sin² + cos² = 1 far beyond f64.
        let (s, c) = sin_cos(&Fixed::from_f64(2.9), &pi);
        assert!(s.mul(&s).add(&c.mul(&c)).sub(&Fixed::one()).0.bits() < 16);
    }

    #[test]
    fn slerp_reference_is_right_on_known_arcs() {
        let r = Arc::new(&[1.0, 0.0], &[0.0, 3.0], &[0.0, 1.0])
            .expect("valid")
            .at(0.5);
        let h = std::f64::consts::FRAC_1_SQRT_2;
        assert_eq!((r[0].to_f64(), r[1].to_f64()), (h, h));
        let r = Arc::new(&[2.0, 0.0, 0.0], &[-1.0, 0.0, 0.0], &[0.0, 0.0, 1.0])
            .expect("valid")
            .at(0.5);
        assert_eq!(
            r.iter().map(Fixed::to_f64).collect::<Vec<_>>(),
            [0.0, 0.0, 1.0]
        );
        let arc = Arc::new(&[1.0, 0.0], &[0.0, 1.0], &[0.0, 1.0]).expect("valid");
        let (angle, length) = errors(&[h, h], &arc.at(0.5));
        assert!(angle < 2e-16 && length < 2e-16, "{angle} {length}");
    }
}
