//! The covered pixel centres of a small box, found as bit masks (x86-64, SSE2).
//!
//! A small triangle's box in a tile is a few pixels on a side, and the exact row walker's work
//! per piece and per row ([`RunBound`](crate::run_bound::RunBound)'s divisions and sides, a
//! covered run per row, then a pixel loop over it) outweighed its few pixels; worse, the ends
//! of those loops, a row or two pixels long, were mispredicted branches. Here the rows of the
//! box are tested whole, up to [`WIDTH`] pixels at once: the edge values `t = E − bias` of a
//! row's centres, in 32-bit lanes, are OR'ed over the three edges, and the sign bits of the
//! result are the centres outside (a centre is covered when `t ≥ 0` on every edge: the top-left
//! rule's test, unchanged). The rows' masks are gathered 64 bits at a time (4 rows of 16
//! pixels, 8 of 8 or 16 of 4) and the covered centres visited by their set bits: one loop per
//! 64 pixels of the box rather than two per row, and no branch on a row's coverage.
//!
//! 32 bits are exact here: an edge function is linear, so over the box's centres `|t|` is at
//! most `|t₀| + |step|·(w − 1) + |down|·(h − 1)` (`t₀` at the top-left centre, `step` and `down`
//! its changes per pixel right and down), and a box is only taken when that is below 2³⁰.
//! Every value at a centre inside the box is then exact, whatever the additions modulo 2³² that
//! led to it (lanes past the box's right side and rows past its bottom may wrap: they are
//! masked out). Wider boxes, and larger values, take the exact row walker
//! ([`EdgeSetup::for_each_covered_span`](crate::edge::EdgeSetup::for_each_covered_span)); so
//! do targets other than x86-64, with the same results.

use safe_arch::{
    add_i32_m128i, add_m128d, bitor_m128i, m128d, m128i, move_mask_i8_m128i, mul_m128d,
    pack_i16_to_i8_m128i, pack_i32_to_i16_m128i, set_splat_i32_m128i, set_splat_m128d,
};

use crate::run_depth::lambda_depth_pair;

/// The widest box taken: four registers of four lanes per row.
pub(crate) const WIDTH: i64 = 16;

/// Bound on |t| over the box's centres for exact 32-bit values (with room for the bias).
const LIMIT: u64 = 1 << 30;

/// A piece's box in a tile, at most [`WIDTH`] pixels wide, with its edge values in 32 bits.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SmallBox {
    /// The box's top-left pixel.
    origin: (i64, i64),
    /// Width (`1..=WIDTH`) and height in pixels.
    size: (u32, u32),
    /// `t = E − bias` of each edge at the centre of the top-left pixel.
    t: [i32; 3],
    /// The change of `E` per pixel right and per pixel down.
    step: [i32; 3],
    down: [i32; 3],
    /// The top-left rule's bias of each edge (0 or 1).
    bias: [i32; 3],
}

impl SmallBox {
    /// The box `[x0, x1) × [y0, y1)` (not empty, at most [`WIDTH`] wide) of edges whose values
    /// less `bias` are `t` at the centre of `(x0, y0)` and change by `step` per pixel right and
    /// `down` per pixel down; `None` when their values over the box may need more than 32 bits.
    #[inline(always)]
    pub(crate) fn new(
        [x0, y0, x1, y1]: [i64; 4],
        t: [i64; 3],
        step: [i64; 3],
        down: [i64; 3],
        bias: [i64; 3],
    ) -> Option<Self> {
        debug_assert!(x0 < x1 && y0 < y1 && x1 - x0 <= WIDTH);
        let (right, bottom) = (x1 - x0 - 1, y1 - y0 - 1);
        // A bound on |t| over the box's centres (each term below 2⁶², so no overflow).
        let mut fits = true;
        for i in 0..3 {
            let bound = t[i].unsigned_abs()
                + (step[i] * right).unsigned_abs()
                + (down[i] * bottom).unsigned_abs();
            fits &= bound < LIMIT;
        }
        // Truncation is reduction modulo 2³²: exact for the values inside the box.
        fits.then(|| Self {
            origin: (x0, y0),
            size: ((x1 - x0) as u32, (y1 - y0) as u32),
            t: t.map(|v| v as i32),
            step: step.map(|s| s as i32),
            down: down.map(|d| d as i32),
            bias: bias.map(|b| b as i32),
        })
    }

    /// Calls `pixel(x, y, λ, z)` for every covered centre of the box, row by row from the top,
    /// left to right, with its weights `λⱼ = Eⱼ · inv_area` (input order) and depth
    /// `z = f32(Σ λⱼ·depthⱼ)`, computed two centres at a time as
    /// [`lambda_depth_pair`] computes them.
    #[inline(always)]
    pub(crate) fn for_each_covered(
        &self,
        inv_area: f64,
        depth: [f64; 3],
        pixel: impl FnMut(i64, i64, [f64; 3], f32),
    ) {
        match self.size.0 {
            ..=4 => self.walk::<1>(inv_area, depth, pixel),
            5..=8 => self.walk::<2>(inv_area, depth, pixel),
            _ => self.walk::<4>(inv_area, depth, pixel),
        }
    }

    /// [`for_each_covered`](Self::for_each_covered) with `4·N` lanes per row.
    #[inline(always)]
    fn walk<const N: usize>(
        &self,
        inv_area: f64,
        depth: [f64; 3],
        mut pixel: impl FnMut(i64, i64, [f64; 3], f32),
    ) {
        let lanes = 4 * N as u32;
        let rows = 64 / lanes;
        // Lane `k` of register `q` adds `step·(4q + k)` to the row's first value: the first
        // register from three scalar additions, each next one by adding `4·step` to every lane
        // (additions modulo 2³², as the products were).
        let offsets: [[m128i; N]; 3] = core::array::from_fn(|i| {
            let s = self.step[i];
            let (s2, s4) = (s.wrapping_add(s), s.wrapping_mul(4));
            let four = set_splat_i32_m128i(s4);
            let mut quad = m128i::from([0, s, s2, s2.wrapping_add(s)]);
            core::array::from_fn(|_| {
                let this = quad;
                quad = add_i32_m128i(quad, four);
                this
            })
        });
        // The edge values `E = t + bias` of a centre `(dx, dy)` from the top-left one, in f64:
        // every term and sum is an integer below 2³² in magnitude for centres in the box, so
        // exact, and `E` is the integer the spans give (the same weights, bit for bit).
        let corner = core::array::from_fn::<_, 3, _>(|i| {
            set_splat_m128d(f64::from(self.t[i]) + f64::from(self.bias[i]))
        });
        let right = self.step.map(|s| set_splat_m128d(f64::from(s)));
        let down = self.down.map(|d| set_splat_m128d(f64::from(d)));
        let inv = set_splat_m128d(inv_area);
        let d = depth.map(set_splat_m128d);
        let in_row = (1_u64 << self.size.0) - 1;
        // The lanes of the current row, stepped down a row by one addition each.
        let mut row: [[m128i; N]; 3] = core::array::from_fn(|i| {
            let first = set_splat_i32_m128i(self.t[i]);
            offsets[i].map(|offset| add_i32_m128i(first, offset))
        });
        let step_down = self.down.map(set_splat_i32_m128i);
        let mut top = 0;
        while top < self.size.1 {
            // A fixed number of rows (a loop the branch predictor learns), those past the box
            // masked out after.
            let mut covered = 0_u64;
            for r in 0..rows {
                covered |= (u64::from(!outside::<N>(&row)) & in_row) << (lanes * r);
                row = core::array::from_fn(|i| row[i].map(|v| add_i32_m128i(v, step_down[i])));
            }
            let left = self.size.1 - top;
            if left < rows {
                covered &= (1_u64 << (lanes * left)) - 1;
            }
            // Two centres per step (the second a copy of the first when only one is left).
            while covered != 0 {
                let a = covered.trailing_zeros();
                covered &= covered - 1;
                let pair = covered != 0;
                let b = if pair { covered.trailing_zeros() } else { a };
                covered &= covered.wrapping_sub(1);
                let (ax, ay) = (a % lanes, top + a / lanes);
                let (bx, by) = (b % lanes, top + b / lanes);
                let dx = m128d::from_array([f64::from(ax), f64::from(bx)]);
                let dy = m128d::from_array([f64::from(ay), f64::from(by)]);
                let e = core::array::from_fn(|i| {
                    add_m128d(
                        add_m128d(corner[i], mul_m128d(right[i], dx)),
                        mul_m128d(down[i], dy),
                    )
                });
                let [(la, za), (lb, zb)] = lambda_depth_pair(e, inv, d);
                let (x0, y0) = self.origin;
                pixel(x0 + i64::from(ax), y0 + i64::from(ay), la, za);
                if pair {
                    pixel(x0 + i64::from(bx), y0 + i64::from(by), lb, zb);
                }
            }
            top += rows;
        }
    }
}

/// Bit `k` set where lane `k` of a row is outside an edge (`t < 0` on any), for the row's
/// values `row` (edge by edge, four lanes per register).
#[inline(always)]
fn outside<const N: usize>(row: &[[m128i; N]; 3]) -> u32 {
    let any: [m128i; N] =
        core::array::from_fn(|q| bitor_m128i(bitor_m128i(row[0][q], row[1][q]), row[2][q]));
    // Saturating packs keep each lane's sign: 32 → 16 → 8 bits, then one byte mask. With
    // fewer than four registers the high bytes repeat low lanes (masked out by the caller).
    let bytes = pack_i16_to_i8_m128i(
        pack_i32_to_i16_m128i(any[0], any[1 % N]),
        pack_i32_to_i16_m128i(any[2 % N], any[3 % N]),
    );
    move_mask_i8_m128i(bytes) as u32
}
