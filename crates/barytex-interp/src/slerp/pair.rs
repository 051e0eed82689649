//! Two f64 lanes computed together: one SSE2 register on x86-64 (through `safe_arch`, as the
//! workspace forbids `unsafe`), a plain pair elsewhere. The f32 SLERP evaluates its two weights,
//! and two polynomials sharing one variable, side by side; written with scalar pairs (or glam's
//! `DVec2`, a plain struct) the compiler keeps them scalar, with twice the instructions.
//!
//! Every operation is one IEEE operation per lane (no fused multiply-add), so both versions give
//! the same bits.

#[cfg(target_arch = "x86_64")]
mod lanes {
    use glam::Vec4;
    use safe_arch::{
        add_m128d, bitand_m128d, cmp_le_mask_m128d, convert_to_m128_from_m128d,
        convert_to_m128d_from_lower2_m128, get_f64_from_m128d_s, m128, m128d, move_high_low_m128,
        move_low_high_m128, move_mask_m128d, mul_m128d, set_reversed_m128d, set_splat_m128d,
        sub_m128d, unpack_high_m128d, unpack_low_m128d,
    };

    /// Two f64 lanes, `lo` and `hi`.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F64x2(m128d);

    impl F64x2 {
        #[inline(always)]
        pub(crate) fn new(lo: f64, hi: f64) -> Self {
            Self(set_reversed_m128d(lo, hi))
        }
        #[inline(always)]
        pub(crate) fn splat(v: f64) -> Self {
            Self(set_splat_m128d(v))
        }
        #[inline(always)]
        pub(crate) fn lo(self) -> f64 {
            get_f64_from_m128d_s(self.0)
        }
        #[inline(always)]
        pub(crate) fn hi(self) -> f64 {
            get_f64_from_m128d_s(unpack_high_m128d(self.0, self.0))
        }
        #[inline(always)]
        pub(crate) fn add(self, o: Self) -> Self {
            Self(add_m128d(self.0, o.0))
        }
        #[inline(always)]
        pub(crate) fn sub(self, o: Self) -> Self {
            Self(sub_m128d(self.0, o.0))
        }
        #[inline(always)]
        pub(crate) fn mul(self, o: Self) -> Self {
            Self(mul_m128d(self.0, o.0))
        }
        /// Whether both lanes are within `bound` of 0 (false for NaN).
        #[inline(always)]
        pub(crate) fn both_within(self, bound: f64) -> bool {
            let magnitude = bitand_m128d(self.0, set_splat_m128d(f64::from_bits(!0 >> 1)));
            move_mask_m128d(cmp_le_mask_m128d(magnitude, set_splat_m128d(bound))) == 0b11
        }
        /// `(self.lo, o.lo)`.
        #[inline(always)]
        pub(crate) fn los(self, o: Self) -> Self {
            Self(unpack_low_m128d(self.0, o.0))
        }
        /// `(self.hi, o.hi)`.
        #[inline(always)]
        pub(crate) fn his(self, o: Self) -> Self {
            Self(unpack_high_m128d(self.0, o.0))
        }
        /// `v`'s `(x, y)` and `(z, w)`, exactly.
        #[inline(always)]
        pub(crate) fn widen(v: Vec4) -> (Self, Self) {
            let v = m128(v.into());
            let zw = move_high_low_m128(v, v);
            (
                Self(convert_to_m128d_from_lower2_m128(v)),
                Self(convert_to_m128d_from_lower2_m128(zw)),
            )
        }
        /// `(xy.lo, xy.hi, zw.lo, zw.hi)` rounded to f32.
        #[inline(always)]
        pub(crate) fn narrow(xy: Self, zw: Self) -> Vec4 {
            let (xy, zw) = (
                convert_to_m128_from_m128d(xy.0),
                convert_to_m128_from_m128d(zw.0),
            );
            Vec4::from(move_low_high_m128(xy, zw).0)
        }
    }
}

#[cfg(not(target_arch = "x86_64"))]
mod lanes {
    /// Two f64 lanes, `lo` and `hi`.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F64x2([f64; 2]);

    impl F64x2 {
        #[inline(always)]
        pub(crate) fn new(lo: f64, hi: f64) -> Self {
            Self([lo, hi])
        }
        #[inline(always)]
        pub(crate) fn splat(v: f64) -> Self {
            Self([v, v])
        }
        #[inline(always)]
        pub(crate) fn lo(self) -> f64 {
            self.0[0]
        }
        #[inline(always)]
        pub(crate) fn hi(self) -> f64 {
            self.0[1]
        }
        #[inline(always)]
        pub(crate) fn add(self, o: Self) -> Self {
            Self([self.0[0] + o.0[0], self.0[1] + o.0[1]])
        }
        #[inline(always)]
        pub(crate) fn sub(self, o: Self) -> Self {
            Self([self.0[0] - o.0[0], self.0[1] - o.0[1]])
        }
        #[inline(always)]
        pub(crate) fn mul(self, o: Self) -> Self {
            Self([self.0[0] * o.0[0], self.0[1] * o.0[1]])
        }
        /// Whether both lanes are within `bound` of 0 (false for NaN).
        #[inline(always)]
        pub(crate) fn both_within(self, bound: f64) -> bool {
            self.0[0].abs() <= bound && self.0[1].abs() <= bound
        }
        /// `(self.lo, o.lo)`.
        #[inline(always)]
        pub(crate) fn los(self, o: Self) -> Self {
            Self([self.0[0], o.0[0]])
        }
        /// `(self.hi, o.hi)`.
        #[inline(always)]
        pub(crate) fn his(self, o: Self) -> Self {
            Self([self.0[1], o.0[1]])
        }
        /// `v`'s `(x, y)` and `(z, w)`, exactly.
        #[inline(always)]
        pub(crate) fn widen(v: glam::Vec4) -> (Self, Self) {
            let v = v.as_dvec4();
            (Self([v.x, v.y]), Self([v.z, v.w]))
        }
        /// `(xy.lo, xy.hi, zw.lo, zw.hi)` rounded to f32.
        #[inline(always)]
        pub(crate) fn narrow(xy: Self, zw: Self) -> glam::Vec4 {
            glam::DVec4::new(xy.0[0], xy.0[1], zw.0[0], zw.0[1]).as_vec4()
        }
    }
}

pub(crate) use lanes::F64x2;
