//! One edge's bound on a triangle's covered run in each pixel row, stepped from row to row
//! exactly and without division.
//!
//! In a row, an edge's value at the centre of pixel `x₀ + k` is `E(k) = e + s·k` (`s = a·256`,
//! its change per pixel), and the centre is inside the edge when `E(k) ≥ bias` (the top-left
//! rule's 0 or 1). With `t = e − bias` and `m = |s|`: for `s > 0` the edge bounds the run on the
//! left, `k ≥ −⌊t / m⌋`; for `s < 0` on the right, `k ≤ ⌊t / m⌋`. One row down, `t` grows by
//! `d = b·256`; with `d = q·m + r` (`0 ≤ r < m`), the quotient `⌊t / m⌋` grows by `q`, the
//! remainder by `r`, and a remainder that reaches `m` carries one into the quotient. This is the
//! exact integer edge stepper of C. Hecker, "Perspective Texture Mapping, Part II:
//! Rasterization", *Game Developer*, June/July 1995 (its `FloorDivMod` and error term), applied
//! to the edge functions: two divisions per edge and triangle, then a few additions and one
//! conditional move per row, and no branch whose direction depends on the row.

/// `⌊t / m⌋` in the current row and its remainder, and their change per row.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RunBound {
    /// `⌊t / m⌋`.
    quotient: i64,
    /// `t − quotient·m`, in `[0, m)`.
    remainder: i64,
    /// `m > 0`.
    m: i64,
    /// `⌊d / m⌋` and `d − ⌊d / m⌋·m`.
    step: (i64, i64),
}

impl RunBound {
    /// The bound for `t = e − bias` in the first row, `m = |a·256| > 0` and the change of the
    /// edge value per row `d = b·256`.
    #[inline]
    pub(crate) fn new(t: i64, m: i64, d: i64) -> Self {
        debug_assert!(m > 0);
        Self {
            quotient: t.div_euclid(m),
            remainder: t.rem_euclid(m),
            m,
            step: (d.div_euclid(m), d.rem_euclid(m)),
        }
    }

    /// The first covered offset of the row for a left edge (`s > 0`).
    #[inline(always)]
    pub(crate) fn first(&self) -> i64 {
        -self.quotient
    }

    /// One past the last covered offset of the row for a right edge (`s < 0`).
    #[inline(always)]
    pub(crate) fn end(&self) -> i64 {
        self.quotient + 1
    }

    /// To the next row.
    #[inline(always)]
    pub(crate) fn advance(&mut self) {
        self.quotient += self.step.0;
        self.remainder += self.step.1;
        let carry = self.remainder >= self.m;
        self.quotient += i64::from(carry);
        self.remainder -= if carry { self.m } else { 0 };
    }
}
