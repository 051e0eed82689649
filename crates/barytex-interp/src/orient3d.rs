//! Exact 3D orientation (the sign of a 4×4 determinant).
//!
//! A plain f64 determinant of the differences decides almost every call: Shewchuk's static bound
//! `(7 + 56ε)ε · permanent` says when its sign is certain. The rest are settled exactly: the
//! 4×4 determinant with rows `(x, y, z, 1)`, expanded along the `z` column, is a sum of 24
//! products `x·y·z` of raw f32 coordinates; each `x·y` is exact in f64 (48 significant bits), and
//! each times `z` is exactly two f64 terms (Dekker's two-product), so Shewchuk's expansion
//! arithmetic sums the 48 terms without error and the largest component carries the sign.
//!
//! Why nothing over- or underflows for f32 inputs: an f32 magnitude lies in `[2⁻¹⁴⁹, 2¹²⁸)`, so
//! every product of three f32 values lies in `[2⁻⁴⁴⁷, 2³⁸⁴)` and every sum of 48 of them below
//! `2³⁹⁰`, far inside f64's normal range `[2⁻¹⁰²², 2¹⁰²⁴)`. Every exact intermediate is a multiple
//! of `2⁻⁴⁴⁷` (the f32 grid `2⁻¹⁴⁹` cubed), so the rounding errors that the expansion arithmetic
//! captures are themselves representable (no gradual underflow, which would break the error-free
//! transformations). The filter's differences of f32 values are multiples of `2⁻¹⁴⁹` below
//! `2¹²⁹`, and their triple products again lie in `[2⁻⁴⁴⁷, 2³⁸⁷)`: Shewchuk's bound, which assumes
//! neither overflow nor underflow, holds.

use glam::Vec3;

use crate::{InterpError, Orientation};

/// Shewchuk's `o3derrboundA`, `(7 + 56ε)ε` with `ε = 2⁻⁵³`: the f64 determinant of the rounded
/// differences is within `O3D_ERRBOUND_A · permanent` of the exact one.
const O3D_ERRBOUND_A: f64 = (7.0 + 56.0 * f64::EPSILON / 2.0) * f64::EPSILON / 2.0;

/// The exact orientation of four points: the sign of `det[b − a, c − a, d − a]`, that is of
/// `((b − a) × (c − a)) · (d − a)`, never wrong.
///
/// Sign convention (the 3D twin of [`orient2d`](crate::orient2d)'s `(b − a) × (c − a)`):
/// - [`Orientation::CounterClockwise`] (positive): `d` lies on the side of the plane through
///   `a, b, c` that the normal `(b − a) × (c − a)` points to; seen from `d`, the triangle
///   `a, b, c` runs counter-clockwise. `orient3d(0, x̂, ŷ, ẑ)` is positive.
/// - [`Orientation::Clockwise`] (negative): `d` lies on the other side.
/// - [`Orientation::Collinear`] (zero): the four points are exactly coplanar (the variant keeps its
///   2D name).
///
/// This is the opposite sign of Shewchuk's `orient3d` (and of the `robust` crate's), which is
/// positive when `d` lies *below* a plane whose `a, b, c` run counter-clockwise seen from above.
///
/// # Errors
/// [`InterpError::NonFinite`] naming the first point (`"a"` … `"d"`) with a NaN or infinite
/// coordinate.
///
/// # Accuracy
/// Exact sign for every finite f32 input: huge (up to `f32::MAX`), tiny and subnormal
/// coordinates, mixed magnitudes and exactly coplanar points included (tests
/// `orient3d.rs::{orient3d_matches_exact_rational, orient3d_exact_on_near_coplanar,
/// orient3d_total_on_any_bits, extreme_magnitudes_are_exact}`).
///
/// ```
/// use barytex_interp::{orient3d, InterpError, Orientation};
/// use glam::Vec3;
///
/// let o = orient3d(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z)?;
/// assert_eq!(o, Orientation::CounterClockwise);
/// assert_eq!(orient3d(Vec3::ZERO, Vec3::Y, Vec3::X, Vec3::Z)?, Orientation::Clockwise);
/// // Four points of the plane z = 0.1 (0.1 is not exact in binary: the answer still is).
/// let p = |x: f32, y: f32| Vec3::new(x, y, 0.1);
/// let coplanar = orient3d(p(0.3, 0.7), p(1.1, 0.2), p(0.9, 0.9), p(1e-3, 5e3))?;
/// assert_eq!(coplanar, Orientation::Collinear);
/// assert_eq!(
///     orient3d(Vec3::X, Vec3::NAN, Vec3::Y, Vec3::Z),
///     Err(InterpError::NonFinite { what: "b" })
/// );
/// # Ok::<(), InterpError>(())
/// ```
#[inline]
pub fn orient3d(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> Result<Orientation, InterpError> {
    let det = orient3d_sign_det(a, b, c, d);
    if det.is_finite() {
        Ok(Orientation::of_determinant(det))
    } else {
        Err(crate::orient::non_finite_point(&[
            ("a", a),
            ("b", b),
            ("c", c),
            ("d", d),
        ]))
    }
}

/// `det[b − a, c − a, d − a]` with an exact sign: the f64 determinant when the filter certifies
/// its sign, else the exact sum rounded to f64 (so the value is also a usable approximation, for
/// example to pick the point farthest from a plane). NaN or infinite exactly when an input is.
#[inline]
pub(crate) fn orient3d_sign_det(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> f64 {
    // Scalar conversions: glam's packed `as_dvec3` reloads the f32 triple in halves straight
    // after the caller stored it, a store-forwarding stall that cost more than the arithmetic.
    let diff = |p: Vec3| {
        glam::DVec3::new(
            f64::from(p.x) - f64::from(a.x),
            f64::from(p.y) - f64::from(a.y),
            f64::from(p.z) - f64::from(a.z),
        )
    };
    let (u, v, w) = (diff(b), diff(c), diff(d));
    let vw_x = v.y * w.z - v.z * w.y;
    let vw_y = v.z * w.x - v.x * w.z;
    let vw_z = v.x * w.y - v.y * w.x;
    let det = u.x * vw_x + u.y * vw_y + u.z * vw_z;
    let permanent = u.x.abs() * ((v.y * w.z).abs() + (v.z * w.y).abs())
        + u.y.abs() * ((v.z * w.x).abs() + (v.x * w.z).abs())
        + u.z.abs() * ((v.x * w.y).abs() + (v.y * w.x).abs());
    // A non-finite input always makes `det` NaN or infinite: every difference is multiplied by a
    // cross-product component that contains the other two (an infinite difference meets a zero
    // factor as NaN, a non-zero one as ±∞, and no sum of finite terms cancels either). Finite
    // f32 inputs never overflow (see the module docs), so callers test `det` instead of the
    // twelve inputs.
    // A zero permanent means a zero factor in each of the six products; differences of f32
    // values never round to zero, so the exact determinant is zero too (repeated points land
    // here, not in the exact stage).
    if det.abs() > O3D_ERRBOUND_A * permanent || permanent == 0.0 || !det.is_finite() {
        return det;
    }
    exact_det(a, b, c, d)
}

/// The exact determinant, rounded to f64 (its sign is exact).
#[cold]
#[inline(never)]
fn exact_det(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> f64 {
    use expansion::{Expansion, scale_by_f32, sum};
    let [za, zb, zc, zd] = [a.z, b.z, c.z, d.z];
    let [a, b, c, d] = [a, b, c, d].map(|p| p.as_dvec3());
    // 2×2 minors `m(p, q) = p.x·q.y − q.x·p.y` of the xy projections, as exact product pairs.
    let m = |p: glam::DVec3, q: glam::DVec3| [p.x * q.y, -(q.x * p.y)];
    let (ab, ac, ad, bc, bd, cd) = (m(a, b), m(a, c), m(a, d), m(b, c), m(b, d), m(c, d));
    let neg = |[x, y]: [f64; 2]| [-x, -y];
    // `M(p, q, r) = det[[p.x, p.y, 1], [q.x, q.y, 1], [r.x, r.y, 1]] = m(p,q) + m(q,r) + m(r,p)`:
    // six exact products, at most six components.
    let minor = |x: [f64; 2], y: [f64; 2], z: [f64; 2]| {
        let mut e = Expansion::<6>::new();
        for t in x.into_iter().chain(y).chain(z) {
            e.grow(t);
        }
        e
    };
    // The 4×4 determinant with rows (x, y, z, 1) is `D = z_a·M(b,c,d) − z_b·M(a,c,d) +
    // z_c·M(a,b,d) − z_d·M(a,b,c)` (cofactors along the z column), and `det[b − a, c − a, d − a]
    // = −D` (subtract row a from the others, then expand along the column of ones). Each
    // scaled minor has at most 12 components, each pair sum 24, the total 48.
    let ma: Expansion<12> = scale_by_f32(&minor(bc, cd, neg(bd)), -za);
    let mb: Expansion<12> = scale_by_f32(&minor(ac, cd, neg(ad)), zb);
    let mc: Expansion<12> = scale_by_f32(&minor(ab, bd, neg(ad)), -zc);
    let md: Expansion<12> = scale_by_f32(&minor(ab, bc, neg(ac)), zd);
    let left: Expansion<24> = sum(&ma, &mb);
    let right: Expansion<24> = sum(&mc, &md);
    let total: Expansion<48> = sum(&left, &right);
    total.estimate()
}

/// Shewchuk's expansion arithmetic ("Adaptive Precision Floating-Point Arithmetic and Fast Robust
/// Geometric Predicates", 1997) on fixed-capacity arrays: an expansion is a list of f64
/// components, increasing in magnitude and strongly non-overlapping, whose exact sum is the
/// value. Zero components are dropped, so the last component carries the sign. Each stage has
/// its own capacity (the most components it can reach), so no stage zeroes more memory than it
/// can use.
mod expansion {
    /// A non-overlapping expansion of at most `N` components.
    #[derive(Clone, Copy)]
    pub(super) struct Expansion<const N: usize> {
        components: [f64; N],
        len: usize,
    }

    impl<const N: usize> Expansion<N> {
        pub(super) fn new() -> Self {
            Self {
                components: [0.0; N],
                len: 0,
            }
        }

        fn as_slice(&self) -> &[f64] {
            &self.components[..self.len]
        }

        fn push(&mut self, x: f64) {
            // Every caller stays within N by construction (the component counts in
            // `exact_det`); the guard only keeps an impossible overflow from panicking.
            if let Some(slot) = self.components.get_mut(self.len) {
                *slot = x;
                self.len += 1;
            }
        }

        /// Adds one f64 exactly (Shewchuk's `grow_expansion` with zero elimination).
        pub(super) fn grow(&mut self, b: f64) {
            let mut q = b;
            let mut out = 0;
            for i in 0..self.len {
                let (s, err) = two_sum(q, self.components[i]);
                q = s;
                if err != 0.0 {
                    self.components[out] = err;
                    out += 1;
                }
            }
            self.len = out;
            if q != 0.0 {
                self.push(q);
            }
        }

        /// The sum of the components from the smallest: the exact value rounded within one ulp,
        /// with its exact sign (zero only for the empty expansion).
        pub(super) fn estimate(&self) -> f64 {
            self.as_slice().iter().fold(0.0, |acc, &x| acc + x)
        }
    }

    /// Knuth's two-sum: `a + b = s + e` exactly.
    #[inline]
    fn two_sum(a: f64, b: f64) -> (f64, f64) {
        let s = a + b;
        let bv = s - a;
        let av = s - bv;
        (s, (a - av) + (b - bv))
    }

    /// Veltkamp's split into two halves of at most 26 significant bits each, `a = hi + lo`.
    #[inline]
    fn split(a: f64) -> (f64, f64) {
        const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
        let c = SPLITTER * a;
        let big = c - a;
        let hi = c - big;
        (hi, a - hi)
    }

    /// Dekker's two-product `a·b = p + e` exactly, for `b` an f32 value (at most 24 significant
    /// bits, so it needs no split: `hi(a)·b` and `lo(a)·b` are exact). A fused multiply-add would
    /// take two operations, but without a hardware FMA `f64::mul_add` is a slow software routine;
    /// this is portable and only runs on the rare exact path.
    #[inline]
    fn two_product_f32(a: f64, b: f64) -> (f64, f64) {
        let p = a * b;
        let (ahi, alo) = split(a);
        (p, alo * b - (p - ahi * b))
    }

    /// `e · b` exactly for `b` an f32 value (Shewchuk's `scale_expansion_zeroelim`); at most
    /// `2N` components.
    pub(super) fn scale_by_f32<const N: usize, const M: usize>(
        e: &Expansion<N>,
        b: f32,
    ) -> Expansion<M> {
        let b = f64::from(b);
        let mut h = Expansion::<M>::new();
        let mut parts = e.as_slice().iter();
        let Some(&first) = parts.next() else {
            return h;
        };
        let (mut q, low) = two_product_f32(first, b);
        if low != 0.0 {
            h.push(low);
        }
        for &x in parts {
            let (p1, p0) = two_product_f32(x, b);
            let (s, err) = two_sum(q, p0);
            if err != 0.0 {
                h.push(err);
            }
            let (s2, err2) = two_sum(p1, s);
            q = s2;
            if err2 != 0.0 {
                h.push(err2);
            }
        }
        if q != 0.0 {
            h.push(q);
        }
        h
    }

    /// `e + f` exactly (Shewchuk's `fast_expansion_sum_zeroelim`: merge by magnitude, then one
    /// pass of two-sums); at most `A + B` components.
    pub(super) fn sum<const A: usize, const B: usize, const C: usize>(
        e: &Expansion<A>,
        f: &Expansion<B>,
    ) -> Expansion<C> {
        let (e, f) = (e.as_slice(), f.as_slice());
        let mut h = Expansion::<C>::new();
        let (mut i, mut j) = (0, 0);
        // The merge is consumed on the fly: the next component in order of magnitude.
        let mut next = || {
            let take_e = match (e.get(i), f.get(j)) {
                (Some(x), Some(y)) => x.abs() <= y.abs(),
                (Some(_), None) => true,
                (None, Some(_)) => false,
                (None, None) => return None,
            };
            if take_e {
                i += 1;
                Some(e[i - 1])
            } else {
                j += 1;
                Some(f[j - 1])
            }
        };
        let Some(mut q) = next() else {
            return h;
        };
        while let Some(x) = next() {
            let (s, err) = two_sum(q, x);
            q = s;
            if err != 0.0 {
                h.push(err);
            }
        }
        if q != 0.0 {
            h.push(q);
        }
        h
    }
}

pub(crate) mod methods {
    use glam::Vec3;

    use crate::Orientation;

    /// The textbook f64 determinant `det[b − a, c − a, d − a]`, no filter: fast, but its sign can
    /// be wrong (or zero) for nearly and exactly coplanar points.
    ///
    /// # Accuracy
    /// No sign guarantee; kept for the benchmarks. Returns `Collinear` for NaN input.
    #[must_use]
    pub fn orient3d_naive_f64(a: Vec3, b: Vec3, c: Vec3, d: Vec3) -> Orientation {
        let a = a.as_dvec3();
        let (u, v, w) = (b.as_dvec3() - a, c.as_dvec3() - a, d.as_dvec3() - a);
        Orientation::of_determinant(u.dot(v.cross(w)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_tetrahedron_signs() {
        let o = |a, b, c, d| orient3d(a, b, c, d).map(Orientation::sign);
        assert_eq!(o(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z), Ok(1));
        assert_eq!(o(Vec3::ZERO, Vec3::X, Vec3::Y, -Vec3::Z), Ok(-1));
        assert_eq!(
            o(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::ONE.with_z(0.0)),
            Ok(0)
        );
    }

    #[test]
    fn exact_path_agrees_on_simple_values() {
        // The exact path alone, on values whose determinant is known.
        assert_eq!(exact_det(Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z), 1.0);
        assert_eq!(exact_det(Vec3::ZERO, Vec3::Y, Vec3::X, Vec3::Z), -1.0);
        let s = Vec3::splat(1e30);
        assert_eq!(
            exact_det(s, s + Vec3::X * 2.0, s + Vec3::Y * 3.0, s + Vec3::Z * 5.0),
            // 1e30 + 2 rounds to 1e30 in f32: the points are all equal.
            0.0
        );
        let t = exact_det(
            Vec3::ONE,
            Vec3::new(2.0, 1.0, 1.0),
            Vec3::new(1.0, 3.0, 1.0),
            Vec3::new(1.0, 1.0, 5.0),
        );
        assert_eq!(t, 8.0);
    }
}
