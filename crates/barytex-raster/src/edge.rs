//! Triangle setup and coverage in fixed point: 8 sub-pixel bits, 64-bit edge functions, the
//! top-left fill rule, samples at pixel centres.
//!
//! Screen coordinates are y-down. A triangle is set up with its vertices ordered so that every
//! edge function is positive inside; an edge function `E(p) = A·pₓ + B·p_y + C` is exactly zero on
//! its edge, and a pixel centre with `E = 0` is covered only for a **top** edge (horizontal, the
//! triangle below it) or a **left** edge (the triangle to its right) — so pixels on an edge shared
//! by two triangles are covered exactly once (watertight), as D3D and Vulkan specify.

use glam::{DVec2, Vec2};

use crate::run_bound::RunBound;

/// Sub-pixel precision: 8 bits (1/256 pixel), as GPUs use.
pub const SUBPIXEL_BITS: u32 = 8;
const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;
/// Side of the blocks that are accepted or rejected whole.
const BLOCK: i64 = 8;

/// The largest |screen coordinate| in pixels the setup accepts (the clipper's guard band keeps
/// vertices inside): 2²², so products of fixed-point differences stay below 2⁶².
pub const MAX_COORDINATE: f32 = 4_194_304.0;

/// A triangle ready to rasterize.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EdgeSetup {
    /// `E_j = a·x + b·y + c` in fixed point, edge `j` opposite **input** vertex `j` (stored in
    /// input order, so `E_j / area2` is vertex `j`'s barycentric with no permutation per pixel).
    a: [i64; 3],
    b: [i64; 3],
    c: [i64; 3],
    /// 0 for top-left edges, 1 otherwise (`E − bias ≥ 0` is covered).
    bias: [i64; 3],
    /// Twice the area in fixed-point units (> 0).
    area2: i64,
    /// `1 / area2`, computed once per triangle rather than once per tile it touches.
    inv_area: f64,
    /// Pixel bounding box `[x0, x1) × [y0, y1)` (not clipped to any target).
    pub(crate) bbox: [i64; 4],
    /// The vertices' y in fixed point, input order (vertex `j` is opposite edge `j`).
    ys: [i64; 3],
}

/// Rounds a screen coordinate to fixed point (to nearest, halves away from zero).
#[inline]
pub(crate) fn fixed(v: f32) -> i64 {
    let x = f64::from(v) * ONE as f64;
    // `f64::round` is a library call on targets without SSE4.1 (six per triangle). Below 2⁵²
    // the truncation is exact and so is the remainder `x − t`, so comparing it with ½ rounds
    // exactly as `round` does.
    if x.abs() < 4_503_599_627_370_496.0 {
        let t = x as i64;
        let rest = x - t as f64;
        // Without a branch: on arbitrary vertices which way a coordinate rounds is a coin toss
        // for the branch predictor (cachegrind: ~3 mispredictions per triangle).
        t + i64::from(rest >= 0.5) - i64::from(rest <= -0.5)
    } else {
        // From 2⁵² on every f64 is an integer: `round` would return `x` itself. (Not calling
        // it matters: LLVM if-converts this branch and, on targets without SSE4.1, called the
        // library `round` on every coordinate.) The cast saturates, as before.
        x as i64
    }
}

/// Which edges bound a triangle's runs on which side, by the signs of their `a`.
#[derive(Clone, Copy)]
struct Sides {
    /// The edge alone on its side.
    lone: u8,
    lone_is_left: bool,
    /// The two edges on the other side (the same edge twice when the third is horizontal).
    pair: [u8; 2],
    /// The horizontal edge, if any.
    horizontal: Option<u8>,
}

/// [`Sides`] for each sign pattern `Σ 3ʲ·sⱼ` (`sⱼ`: 0 for `aⱼ < 0`, 1 for 0, 2 for `aⱼ > 0`).
/// Patterns no triangle has (all one sign, two horizontal edges) get an arbitrary entry.
const SIDES: [Sides; 27] = {
    let mut table = [Sides {
        lone: 0,
        lone_is_left: true,
        pair: [1, 2],
        horizontal: None,
    }; 27];
    let mut pattern = 0;
    while pattern < 27 {
        let s = [pattern % 3, pattern / 3 % 3, pattern / 9];
        let (mut left, mut right) = ([0_u8; 2], [0_u8; 2]);
        let (mut nl, mut nr) = (0, 0);
        let mut horizontal = None;
        let mut i = 0;
        while i < 3 {
            match s[i] {
                2 => {
                    left[nl & 1] = i as u8;
                    nl += 1;
                }
                0 => {
                    right[nr & 1] = i as u8;
                    nr += 1;
                }
                _ => horizontal = Some(i as u8),
            }
            i += 1;
        }
        table[pattern] = if nl == 2 {
            Sides {
                lone: right[0],
                lone_is_left: false,
                pair: left,
                horizontal,
            }
        } else if nr == 2 {
            Sides {
                lone: left[0],
                lone_is_left: true,
                pair: right,
                horizontal,
            }
        } else {
            Sides {
                lone: left[0],
                lone_is_left: true,
                pair: [right[0]; 2],
                horizontal,
            }
        };
        pattern += 1;
    }
    table
};

impl EdgeSetup {
    /// `None` for a zero-area triangle (after snapping) or coordinates beyond
    /// [`MAX_COORDINATE`].
    ///
    /// Without a branch on the winding or on the edges' directions: on arbitrary triangles each
    /// is a coin toss for the branch predictor. (Always inlined: called, it read its argument
    /// back with wide loads from the caller's narrow stores, which stalls store forwarding.)
    #[inline(always)]
    pub(crate) fn new(screen: [Vec2; 3]) -> Option<Self> {
        let mut valid = true;
        for p in &screen {
            valid &= p.is_finite() & (p.x.abs() <= MAX_COORDINATE) & (p.y.abs() <= MAX_COORDINATE);
        }
        if !valid {
            return None;
        }
        let v = [
            (fixed(screen[0].x), fixed(screen[0].y)),
            (fixed(screen[1].x), fixed(screen[1].y)),
            (fixed(screen[2].x), fixed(screen[2].y)),
        ];
        let signed_area2 =
            (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[1].1 - v[0].1) * (v[2].0 - v[0].0);
        if signed_area2 == 0 {
            return None;
        }
        // Edge j, opposite input vertex j, runs from vertex j + 1 to j + 2: `E(r) = dx·(r.y −
        // p.y) − dy·(r.x − p.x)` is positive inside for a positive area. For a negative one
        // the triangle is wound the other way: its edge runs from j + 2 to j + 1, and that
        // edge function is exactly `−E` (`a`, `b`, `c` negated: the same line, reversed).
        // `flip` is 0 or −1: `(x ^ flip) − flip` negates where it is −1.
        let flip = -i64::from(signed_area2 < 0);
        let negate = |x: i64| (x ^ flip) - flip;
        let mut a = [0; 3];
        let mut b = [0; 3];
        let mut c = [0; 3];
        let mut bias = [0; 3];
        for j in 0..3 {
            let (p, q) = (v[(j + 1) % 3], v[(j + 2) % 3]);
            let (dx, dy) = (q.0 - p.0, q.1 - p.1);
            a[j] = negate(-dy);
            b[j] = negate(dx);
            c[j] = negate(dy * p.0 - dx * p.1);
            // Top-left (`E = 0` covered): the edge runs up (`dy < 0` in its wound direction,
            // `a > 0`), or it is horizontal and runs right (`b > 0`: the triangle below it).
            let top_left = (a[j] > 0) | ((a[j] == 0) & (b[j] > 0));
            bias[j] = i64::from(!top_left);
        }
        let area2 = negate(signed_area2);
        let (x_lo, x_hi) = (
            v[0].0.min(v[1].0).min(v[2].0),
            v[0].0.max(v[1].0).max(v[2].0),
        );
        let (y_lo, y_hi) = (
            v[0].1.min(v[1].1).min(v[2].1),
            v[0].1.max(v[1].1).max(v[2].1),
        );
        // Pixels with any sample point (x·256 + [0, 256)) in the triangle's extent: a superset
        // of the pixels whose centre can be inside, and all a multisampled target needs.
        let first = |lo: i64| lo >> SUBPIXEL_BITS;
        let last = |hi: i64| (hi >> SUBPIXEL_BITS) + 1;
        Some(Self {
            a,
            b,
            c,
            bias,
            area2,
            inv_area: 1.0 / area2 as f64,
            bbox: [first(x_lo), first(y_lo), last(x_hi), last(y_hi)],
            ys: [v[0].1, v[1].1, v[2].1],
        })
    }

    /// Calls `visit(x, y, e, all_covered)` for every pixel of `rect` (`[x0, x1) × [y0, y1)`)
    /// that may hold a covered sample, row by row within 8×8 blocks, where `e` are the three
    /// edge values at the pixel's reference point `(x, y)·256 + reference` and `all_covered`
    /// says the whole block is inside (no test needed).
    ///
    /// Samples lie at offsets within `[extent.0, extent.1]` (in 1/256 pixel) of a pixel's
    /// corner on both axes: blocks whose sample region lies outside an edge are skipped whole
    /// (an edge function is linear, so its extremes over the region are at the corners).
    #[inline]
    pub(crate) fn for_each_block_pixel(
        &self,
        rect: [i64; 4],
        extent: (i64, i64),
        reference: (i64, i64),
        mut visit: impl FnMut(i64, i64, [i64; 3], bool),
    ) {
        let step = self.a.map(|a| a * ONE);
        self.for_each_block_row(rect, extent, reference, |y, (xs, xe), mut e, accept| {
            for x in xs..xe {
                visit(x, y, e, accept);
                for i in 0..3 {
                    e[i] += step[i];
                }
            }
        });
    }

    /// Calls `visit(y, (xs, xe), e, all_covered)` for every row of every 8×8 block of `rect`
    /// that [`for_each_block_pixel`](Self::for_each_block_pixel) would visit, with the edge
    /// values `e` at the reference point of pixel `(xs, y)` (the run is `xs..xe`, at most 8
    /// pixels; each pixel to the right adds `a·256`).
    #[inline(always)]
    fn for_each_block_row(
        &self,
        rect: [i64; 4],
        extent: (i64, i64),
        reference: (i64, i64),
        mut visit: impl FnMut(i64, (i64, i64), [i64; 3], bool),
    ) {
        let x0 = self.bbox[0].max(rect[0]);
        let y0 = self.bbox[1].max(rect[1]);
        let x1 = self.bbox[2].min(rect[2]);
        let y1 = self.bbox[3].min(rect[3]);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let down = self.b.map(|b| b * ONE);
        let mut by = y0.div_euclid(BLOCK) * BLOCK;
        while by < y1 {
            let (ys, ye) = (by.max(y0), (by + BLOCK).min(y1));
            let mut bx = x0.div_euclid(BLOCK) * BLOCK;
            'block: while bx < x1 {
                let (xs, xe) = (bx.max(x0), (bx + BLOCK).min(x1));
                bx += BLOCK;
                let (lx, hx) = (xs * ONE + extent.0, (xe - 1) * ONE + extent.1);
                let (ly, hy) = (ys * ONE + extent.0, (ye - 1) * ONE + extent.1);
                let mut accept = true;
                for i in 0..3 {
                    let corner = self.a[i] * lx + self.b[i] * ly + self.c[i];
                    let (dx, dy) = (self.a[i] * (hx - lx), self.b[i] * (hy - ly));
                    if corner + dx.max(0) + dy.max(0) < self.bias[i] {
                        continue 'block;
                    }
                    accept &= corner + dx.min(0) + dy.min(0) >= self.bias[i];
                }
                let (px, py) = (xs * ONE + reference.0, ys * ONE + reference.1);
                let mut e: [i64; 3] =
                    core::array::from_fn(|i| self.a[i] * px + self.b[i] * py + self.c[i]);
                for y in ys..ye {
                    visit(y, (xs, xe), e, accept);
                    for i in 0..3 {
                        e[i] += down[i];
                    }
                }
            }
            by += BLOCK;
        }
    }

    /// Calls `span(y, (xs, xe), e)` for every row of `rect` (`[x0, x1) × [y0, y1)`) where the
    /// triangle covers pixel centres: exactly the pixels `xs..xe` of row `y` are covered (a
    /// triangle is convex, so a row's covered centres are contiguous), and `e` holds the edge
    /// values at the centre of `(xs, y)` (edge `j` opposite input vertex `j`: `e[j] / area2` is
    /// that vertex's weight; each pixel to the right adds `a·256`).
    ///
    /// Each sloped edge bounds the runs on one side, at the exact integer boundary of
    /// `E ≥ bias`, stepped from row to row by [`RunBound`] (no division, no estimate, no branch
    /// per row on which edge bounds it). A triangle has one or two sloped edges on each side;
    /// where it has two, they meet at its middle vertex `M`, and rows above `M` are bounded by
    /// the upper one alone, rows below by the lower one (the left chain of a convex polygon is
    /// convex: the other edge's line lies outside there), so the rows are walked in two phases
    /// with one bound per side. A horizontal edge bounds rows, not runs: only the first
    /// or last row of the box can lie outside it. The runs are exactly the centres that
    /// [`covers`](Self::covers) accepts (the top-left rule unchanged), and no pixel outside
    /// them is tested: thin and small triangles, whose bounding boxes are mostly empty, cost a
    /// few operations per row rather than per pixel.
    #[inline(always)]
    pub(crate) fn for_each_covered_span(
        &self,
        rect: [i64; 4],
        mut span: impl FnMut(i64, (i64, i64), [i64; 3]),
    ) {
        let x0 = self.bbox[0].max(rect[0]);
        let mut y0 = self.bbox[1].max(rect[1]);
        let x1 = self.bbox[2].min(rect[2]);
        let mut y1 = self.bbox[3].min(rect[3]);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let px = x0 * ONE + HALF;
        let value = |i: usize, y: i64| self.a[i] * px + self.b[i] * (y * ONE + HALF) + self.c[i];
        // Edges by side: `a > 0` bounds the run on the left, `a < 0` on the right (the `a` of a
        // triangle sum to zero: one or two on each side), `a = 0` is horizontal. Looked up from
        // the three signs rather than branched on: on arbitrary triangles each sign is a coin
        // toss for the branch predictor.
        let sign = |i: usize| usize::from(self.a[i] > 0) + usize::from(self.a[i] >= 0);
        let Sides {
            lone,
            lone_is_left,
            pair,
            horizontal,
        } = SIDES[sign(0) + 3 * sign(1) + 9 * sign(2)];
        if let Some(i) = horizontal {
            // Rare: a horizontal edge bounds rows, not runs (only the box's first or last row
            // can lie outside it).
            let i = usize::from(i);
            while y0 < y1 && value(i, y0) < self.bias[i] {
                y0 += 1;
            }
            while y1 > y0 && value(i, y1 - 1) < self.bias[i] {
                y1 -= 1;
            }
            if y0 >= y1 {
                return;
            }
        }
        let (lone, pair) = (usize::from(lone), pair.map(usize::from));
        // The lone edge on one side spans all rows; the other side's edges take the rows above
        // `split` (`upper`) and from `split` on (`lower`); with one edge there, it is both.
        // The middle vertex is opposite the lone edge; the upper edge of the pair joins it to
        // the top vertex, so it is opposite the lower (larger y) of the other two.
        let first_lower = self.ys[pair[0]] > self.ys[pair[1]];
        let (upper, lower) = if first_lower {
            (pair[0], pair[1])
        } else {
            (pair[1], pair[0])
        };
        // The first row whose centre is at or below M. On M's own row both edges give the same
        // run: both lines pass through M, and edges on the same side have the same bias (a left
        // edge, `a > 0`, is a left edge of the top-left rule; a right one is not), so either
        // may take it. With one edge on that side (`upper = lower`) the split does not matter.
        // (At or past the last row there is nothing to switch: never.)
        let split = ((self.ys[lone] - HALF + ONE - 1) >> SUBPIXEL_BITS).max(y0);
        let split = if split < y1 { split } else { i64::MAX };
        let mut e: [i64; 3] = core::array::from_fn(|i| value(i, y0));
        let step = self.a.map(|a| a * ONE);
        let down = self.b.map(|b| b * ONE);
        let n = x1 - x0;
        let bound =
            |e: &[i64; 3], i: usize| RunBound::new(e[i] - self.bias[i], step[i].abs(), down[i]);
        let lone_bound = bound(&e, lone);
        let pair_bound = bound(&e, if split == y0 { lower } else { upper });
        let (mut l, mut r) = if lone_is_left {
            (lone_bound, pair_bound)
        } else {
            (pair_bound, lone_bound)
        };
        // The run of a row: its offsets in the box and the edge values at its first pixel.
        let run = |l: &RunBound, r: &RunBound, e: &[i64; 3]| {
            let lo = l.first().max(0);
            let hi = r.end().min(n);
            let at: [i64; 3] = core::array::from_fn(|i| e[i] + step[i] * lo);
            (lo, hi, at)
        };
        let mut current = run(&l, &r, &e);
        for y in y0..y1 {
            // The next row's run is found before this row's pixels are visited: the end of a
            // short run's pixel loop is often mispredicted, and what was computed before the
            // branch survives it, so the next row starts with its bounds in hand.
            for i in 0..3 {
                e[i] += down[i];
            }
            l.advance();
            r.advance();
            if y + 1 == split {
                // The pair's side passes the middle vertex: its lower edge bounds from here.
                if lone_is_left {
                    r = bound(&e, lower);
                } else {
                    l = bound(&e, lower);
                }
            }
            let next = run(&l, &r, &e);
            let (lo, hi, at) = current;
            if lo < hi {
                span(y, (x0 + lo, x0 + hi), at);
            }
            current = next;
        }
    }

    /// The box of the pixels of `rect` (`[x0, x1) × [y0, y1)`) that may hold covered centres,
    /// as a [`SmallBox`](crate::small_box::SmallBox) when it is at most
    /// [`WIDTH`](crate::small_box::WIDTH) pixels wide and its edge values fit 32 bits; `None`
    /// otherwise (and when it is empty).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub(crate) fn small_box(&self, rect: [i64; 4]) -> Option<crate::small_box::SmallBox> {
        let x0 = self.bbox[0].max(rect[0]);
        let y0 = self.bbox[1].max(rect[1]);
        let x1 = self.bbox[2].min(rect[2]);
        let y1 = self.bbox[3].min(rect[3]);
        if x0 >= x1 || y0 >= y1 || x1 - x0 > crate::small_box::WIDTH {
            return None;
        }
        let (px, py) = (x0 * ONE + HALF, y0 * ONE + HALF);
        let t =
            core::array::from_fn(|i| self.a[i] * px + self.b[i] * py + self.c[i] - self.bias[i]);
        let step = self.a.map(|a| a * ONE);
        let down = self.b.map(|b| b * ONE);
        crate::small_box::SmallBox::new([x0, y0, x1, y1], t, step, down, self.bias)
    }

    /// Asks the cache for the setup's lines (x86-64 only).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub(crate) fn prefetch(&self) {
        safe_arch::prefetch_t0(&self.a);
        safe_arch::prefetch_t0(&self.b);
        safe_arch::prefetch_t0(&self.c);
        safe_arch::prefetch_t0(&self.inv_area);
        safe_arch::prefetch_t0(&self.bias);
        safe_arch::prefetch_t0(&self.bbox);
        safe_arch::prefetch_t0(&self.ys);
    }

    /// The change of the edge values per pixel to the right.
    #[inline]
    pub(crate) fn x_step(&self) -> [i64; 3] {
        self.a.map(|a| a * ONE)
    }

    /// Twice the area in fixed-point units: the sum of the three edge values anywhere.
    #[inline]
    pub(crate) fn area2(&self) -> i64 {
        self.area2
    }

    /// `1 / area2`: edge values times it are barycentrics.
    #[inline]
    pub(crate) fn inv_area(&self) -> f64 {
        self.inv_area
    }

    /// Whether edge values `e` (at one sample) are inside under the top-left rule.
    #[inline]
    pub(crate) fn covers(&self, e: [i64; 3]) -> bool {
        (e[0] - self.bias[0]) | (e[1] - self.bias[1]) | (e[2] - self.bias[2]) >= 0
    }

    /// The change of the edge values for a move of `(dx, dy)` in 1/256 pixel.
    #[inline]
    pub(crate) fn offset(&self, dx: i64, dy: i64) -> [i64; 3] {
        core::array::from_fn(|i| self.a[i] * dx + self.b[i] * dy)
    }

    /// Barycentrics (input order) from edge values.
    #[inline]
    pub(crate) fn lambda(&self, e: [i64; 3]) -> [f64; 3] {
        let inv_area = 1.0 / self.area2 as f64;
        e.map(|v| v as f64 * inv_area)
    }

    /// Calls `covered(x, y, λ)` for every pixel of `rect` (`[x0, x1) × [y0, y1)`) whose centre
    /// the triangle covers, row by row over exact spans, with the screen-space barycentrics `λ`
    /// of the centre over the **input** vertex order.
    #[inline]
    pub(crate) fn for_each_covered(
        &self,
        rect: [i64; 4],
        mut covered: impl FnMut(i64, i64, [f64; 3]),
    ) {
        let inv_area = self.inv_area();
        let step = self.a.map(|a| a * ONE);
        self.for_each_covered_span(rect, |y, (xs, xe), mut e| {
            for x in xs..xe {
                // Edge j is opposite input vertex j: its value is that vertex's weight.
                covered(x, y, e.map(|v| v as f64 * inv_area));
                for i in 0..3 {
                    e[i] += step[i];
                }
            }
        });
    }

    /// The change of the barycentrics (input order) per pixel right and per pixel down.
    pub(crate) fn gradients(&self) -> (DVec2, DVec2, DVec2) {
        // `256 / area2` without a division: scaling by a power of two is exact, so this is the
        // correctly rounded quotient, bit for bit (`gradient_scale_is_the_quotient`).
        let s = ONE as f64 * self.inv_area;
        let g = |j: usize| DVec2::new(self.a[j] as f64 * s, self.b[j] as f64 * s);
        (g(0), g(1), g(2))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// xorshift64: a repeatable stream of test coordinates.
    fn stream(mut state: u64) -> impl FnMut() -> u64 {
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        }
    }

    /// `256 · (1 / a)` is `256 / a` bit for bit for every positive integer area below 2⁶²
    /// (a power-of-two scale of a correctly rounded quotient, far from under- and overflow).
    #[test]
    fn gradient_scale_is_the_quotient() {
        let mut next = stream(0x9e37_79b9_7f4a_7c15);
        let mut areas: Vec<i64> = (1..100_000).collect();
        areas.extend((0..62).flat_map(|k| [(1_i64 << k) - 1, 1 << k, (1 << k) + 1]));
        areas.extend((0..200_000).map(|_| (next() >> 2) as i64 >> (next() % 62)));
        for a in areas.into_iter().filter(|&a| a > 0) {
            let quotient = ONE as f64 / a as f64;
            let scaled = ONE as f64 * (1.0 / a as f64);
            assert_eq!(quotient.to_bits(), scaled.to_bits(), "area2 {a}");
        }
    }

    /// Every covered centre of `rect` by brute force: the exact test at each pixel.
    fn brute_force(edge: &EdgeSetup, rect: [i64; 4]) -> Vec<(i64, i64, [i64; 3])> {
        let mut out = Vec::new();
        for y in rect[1]..rect[3] {
            for x in rect[0]..rect[2] {
                let (px, py) = (x * ONE + HALF, y * ONE + HALF);
                let e: [i64; 3] =
                    core::array::from_fn(|i| edge.a[i] * px + edge.b[i] * py + edge.c[i]);
                if edge.covers(e) {
                    out.push((x, y, e));
                }
            }
        }
        out
    }

    #[test]
    fn fixed_rounds_as_round_does() {
        let mut next = stream(0x2545_F491_4F6C_DD1D);
        let mut values: Vec<f32> = vec![
            0.0,
            -0.0,
            0.5 / 256.0,
            -0.5 / 256.0,
            1.5 / 256.0,
            -2.5 / 256.0,
            MAX_COORDINATE,
            -MAX_COORDINATE,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        // Random bit patterns (every exponent) and random halves of the sub-pixel grid.
        for _ in 0..200_000 {
            let r = next();
            values.push(f32::from_bits(r as u32));
            values.push(((r >> 32) as i32 >> 8) as f32 / 512.0);
        }
        for v in values {
            let expected = (f64::from(v) * ONE as f64).round() as i64;
            assert_eq!(fixed(v), expected, "{v:e}");
        }
    }

    /// Checks that the spans `edge` reports inside `rect` (none empty) walk exactly the
    /// centres the per-pixel test covers, with the edge values stepped along them; returns
    /// how many there are.
    fn assert_spans_are_the_covered_centres(
        edge: &EdgeSetup,
        rect: [i64; 4],
        screen: &[Vec2; 3],
    ) -> usize {
        let clipped = [
            edge.bbox[0].max(rect[0]),
            edge.bbox[1].max(rect[1]),
            edge.bbox[2].min(rect[2]),
            edge.bbox[3].min(rect[3]),
        ];
        let mut spans = Vec::new();
        edge.for_each_covered_span(rect, |y, (xs, xe), mut e| {
            assert!(xs < xe, "empty span reported");
            for x in xs..xe {
                spans.push((x, y, e));
                for (value, a) in e.iter_mut().zip(edge.a) {
                    *value += a * ONE;
                }
            }
        });
        let expected = if clipped[0] < clipped[2] && clipped[1] < clipped[3] {
            brute_force(edge, clipped)
        } else {
            Vec::new()
        };
        assert_eq!(spans, expected, "{screen:?} in {rect:?}");
        expected.len()
    }

    #[test]
    fn spans_are_exactly_the_covered_centres() {
        let mut next = stream(0x9E37_79B9_7F4A_7C15);
        let mut checked = 0;
        for case in 0..4000 {
            // Coordinates on pixel centres, corners and the sub-pixel grid, some far outside
            // the rectangle, so that edges pass through centres (the top-left rule decides)
            // and crossings are estimated from far away.
            let mut coordinate = || -> f32 {
                let r = next();
                let base = (r % 96) as f32 - 16.0;
                match (r >> 8) % 4 {
                    0 => base + 0.5,
                    1 => base,
                    2 => base + ((r >> 16) % 256) as f32 / 256.0,
                    _ => (((r >> 16) % 2_000_001) as f32 - 1_000_000.0) * 4.0,
                }
            };
            let screen = [(); 3].map(|()| Vec2::new(coordinate(), coordinate()));
            let Some(edge) = EdgeSetup::new(screen) else {
                continue;
            };
            let rect = if case % 2 == 0 {
                [0, 0, 64, 64]
            } else {
                [13, 7, 50, 41]
            };
            checked += assert_spans_are_the_covered_centres(&edge, rect, &screen);
        }
        assert!(
            checked > 100_000,
            "too few covered pixels checked: {checked}"
        );
    }

    /// The two-phase walk on small triangles whose vertices lie on pixel centres and half-pixel
    /// steps: the middle vertex is often exactly on a row's centre or a pixel's, and the
    /// rectangles start and end above, on and below it.
    #[test]
    fn spans_split_exactly_at_the_middle_vertex() {
        let mut next = stream(0xD1B5_4A32_D192_ED03);
        let mut on_centre = 0;
        for _ in 0..20_000 {
            let mut coordinate = || (next() % 24) as f32 * 0.5 - 2.0;
            let screen = [(); 3].map(|()| Vec2::new(coordinate(), coordinate()));
            let Some(edge) = EdgeSetup::new(screen) else {
                continue;
            };
            let r = next();
            let rect = [
                (r % 5) as i64 - 2,
                ((r >> 8) % 7) as i64 - 2,
                ((r >> 16) % 6) as i64 + 4,
                ((r >> 24) % 7) as i64 + 3,
            ];
            assert_spans_are_the_covered_centres(&edge, rect, &screen);
            on_centre += usize::from(edge.ys.iter().any(|y| y.rem_euclid(ONE) == HALF));
        }
        assert!(
            on_centre > 5_000,
            "too few vertices on row centres: {on_centre}"
        );
    }

    /// The small-box path visits exactly the covered centres the per-pixel test accepts, in
    /// the spans' order, with the weights and depths the scalar evaluation gives, bit for bit;
    /// and it declines boxes whose edge values need more than 32 bits.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn small_boxes_are_the_covered_centres() {
        use crate::run_depth::depth_of;
        let mut next = stream(0x6A09_E667_F3BC_C908);
        let depth = [0.125, 0.75, 0.4375];
        let (mut taken, mut declined, mut pixels) = (0, 0, 0);
        for case in 0..40_000 {
            let r = next();
            // Small triangles on the sub-pixel grid; every fourth one far larger (wide boxes
            // clipped to narrow rectangles, huge edge values).
            let scale = if case % 4 == 3 { 65_536.0 } else { 1.0 };
            let mut coordinate = || ((next() % 6_000) as f32 / 256.0 - 4.0) * scale;
            let screen = [(); 3].map(|()| Vec2::new(coordinate(), coordinate()));
            let Some(edge) = EdgeSetup::new(screen) else {
                continue;
            };
            let (x0, y0) = ((r % 9) as i64 - 2, ((r >> 8) % 9) as i64 - 2);
            let rect = [
                x0,
                y0,
                x0 + 1 + ((r >> 16) % 20) as i64,
                y0 + 1 + ((r >> 24) % 30) as i64,
            ];
            let Some(small) = edge.small_box(rect) else {
                declined += 1;
                continue;
            };
            taken += 1;
            let mut seen = Vec::new();
            small.for_each_covered(edge.inv_area(), depth, |x, y, lambda, z| {
                seen.push((x, y, lambda, z));
            });
            let clipped = [
                edge.bbox[0].max(rect[0]),
                edge.bbox[1].max(rect[1]),
                edge.bbox[2].min(rect[2]),
                edge.bbox[3].min(rect[3]),
            ];
            let expected: Vec<_> = brute_force(&edge, clipped)
                .into_iter()
                .map(|(x, y, e)| {
                    let lambda = e.map(|v| v as f64 * edge.inv_area());
                    (x, y, lambda, depth_of(lambda, depth))
                })
                .collect();
            assert_eq!(seen, expected, "{screen:?} in {rect:?}");
            pixels += seen.len();
        }
        assert!(
            taken > 20_000 && declined > 5_000 && pixels > 300_000,
            "{taken} taken, {declined} declined, {pixels} pixels"
        );
    }
}
