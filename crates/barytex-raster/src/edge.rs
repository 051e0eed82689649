//! Triangle setup and coverage in fixed point: 8 sub-pixel bits, 64-bit edge functions, the
//! top-left fill rule, samples at pixel centres.
//!
//! Screen coordinates are y-down. A triangle is set up with its vertices ordered so that every
//! edge function is positive inside; an edge function `E(p) = A·pₓ + B·p_y + C` is exactly zero on
//! its edge, and a pixel centre with `E = 0` is covered only for a **top** edge (horizontal, the
//! triangle below it) or a **left** edge (the triangle to its right) — so pixels on an edge shared
//! by two triangles are covered exactly once (watertight), as D3D and Vulkan specify.

use glam::{DVec2, Vec2};

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
    /// Pixel bounding box `[x0, x1) × [y0, y1)` (not clipped to any target).
    pub(crate) bbox: [i64; 4],
}

/// Rounds a screen coordinate to fixed point (to nearest, halves away from zero).
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
        x.round() as i64
    }
}

impl EdgeSetup {
    /// `None` for a zero-area triangle (after snapping) or coordinates beyond
    /// [`MAX_COORDINATE`].
    pub(crate) fn new(screen: [Vec2; 3]) -> Option<Self> {
        if screen
            .iter()
            .any(|p| !p.is_finite() || p.abs().max_element() > MAX_COORDINATE)
        {
            return None;
        }
        let mut order = [0, 1, 2];
        let mut v = screen.map(|p| (fixed(p.x), fixed(p.y)));
        let cross = |v: &[(i64, i64); 3]| {
            (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[1].1 - v[0].1) * (v[2].0 - v[0].0)
        };
        let mut area2 = cross(&v);
        if area2 == 0 {
            return None;
        }
        if area2 < 0 {
            v.swap(1, 2);
            order.swap(1, 2);
            area2 = -area2;
        }
        let mut a = [0; 3];
        let mut b = [0; 3];
        let mut c = [0; 3];
        let mut bias = [0; 3];
        for i in 0..3 {
            let (p, q) = (v[(i + 1) % 3], v[(i + 2) % 3]);
            let (dx, dy) = (q.0 - p.0, q.1 - p.1);
            // E(r) = dx·(r.y − p.y) − dy·(r.x − p.x): positive on the inside for this winding.
            let top_left = (dy == 0 && dx > 0) || dy < 0;
            // Stored under the input vertex this edge is opposite.
            let j = order[i];
            a[j] = -dy;
            b[j] = dx;
            c[j] = dy * p.0 - dx * p.1;
            bias[j] = i64::from(!top_left);
        }
        let xs = v.map(|p| p.0);
        let ys = v.map(|p| p.1);
        let min = |s: [i64; 3]| s.iter().copied().min().unwrap_or(0);
        let max = |s: [i64; 3]| s.iter().copied().max().unwrap_or(0);
        // Pixels with any sample point (x·256 + [0, 256)) in the triangle's extent: a superset
        // of the pixels whose centre can be inside, and all a multisampled target needs.
        let first = |lo: i64| lo.div_euclid(ONE);
        let last = |hi: i64| hi.div_euclid(ONE) + 1;
        Some(Self {
            a,
            b,
            c,
            bias,
            area2,
            bbox: [first(min(xs)), first(min(ys)), last(max(xs)), last(max(ys))],
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
    /// Each edge bounds the row's run on one side: `E(x) = E(x₀) + a·256·(x − x₀) ≥ bias`. The
    /// bound is estimated in floating point, then corrected with the exact integer test, so the
    /// runs are exactly the centres that [`covers`](Self::covers) accepts (the top-left rule
    /// unchanged) and no pixel outside them is tested — thin and small triangles, whose
    /// bounding boxes are mostly empty, cost a few operations per row rather than per pixel.
    #[inline(always)]
    pub(crate) fn for_each_covered_span(
        &self,
        rect: [i64; 4],
        mut span: impl FnMut(i64, (i64, i64), [i64; 3]),
    ) {
        let x0 = self.bbox[0].max(rect[0]);
        let y0 = self.bbox[1].max(rect[1]);
        let x1 = self.bbox[2].min(rect[2]);
        let y1 = self.bbox[3].min(rect[3]);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let n = x1 - x0;
        let step = self.a.map(|a| a * ONE);
        let down = self.b.map(|b| b * ONE);
        let inv_step = step.map(|s| if s == 0 { 0.0 } else { 1.0 / s as f64 });
        let (px, py) = (x0 * ONE + HALF, y0 * ONE + HALF);
        let mut e: [i64; 3] = core::array::from_fn(|i| self.a[i] * px + self.b[i] * py + self.c[i]);
        for y in y0..y1 {
            // The run [lo, hi) of pixel offsets from x0 inside all three edges.
            let (mut lo, mut hi) = (0_i64, n);
            for i in 0..3 {
                let (e0, s, bias) = (e[i], step[i], self.bias[i]);
                let inside = |k: i64| e0 + s * k >= bias;
                if s == 0 {
                    if e0 < bias {
                        hi = 0;
                    }
                    continue;
                }
                // An edge that holds over the whole row bounds nothing (most rows of a
                // triangle meet two of its edges, not three).
                if (s > 0 && inside(lo)) || (s < 0 && inside(hi - 1)) {
                    continue;
                }
                // The offset where the edge crosses `bias`, estimated (the cast saturates),
                // then moved to the exact boundary.
                let mut k = ((bias - e0) as f64 * inv_step[i]) as i64;
                k = k.clamp(0, n);
                if s > 0 {
                    // Inside from the first k with E ≥ bias on.
                    while k < n && !inside(k) {
                        k += 1;
                    }
                    while k > 0 && inside(k - 1) {
                        k -= 1;
                    }
                    lo = lo.max(k);
                } else {
                    // Inside up to the last k with E ≥ bias: the run ends after it.
                    while k > 0 && !inside(k - 1) {
                        k -= 1;
                    }
                    while k < n && inside(k) {
                        k += 1;
                    }
                    hi = hi.min(k);
                }
            }
            if lo < hi {
                let at: [i64; 3] = core::array::from_fn(|i| e[i] + step[i] * lo);
                span(y, (x0 + lo, x0 + hi), at);
            }
            for i in 0..3 {
                e[i] += down[i];
            }
        }
    }

    /// The change of the edge values per pixel to the right.
    #[inline]
    pub(crate) fn x_step(&self) -> [i64; 3] {
        self.a.map(|a| a * ONE)
    }

    /// `1 / area2`: edge values times it are barycentrics.
    #[inline]
    pub(crate) fn inv_area(&self) -> f64 {
        1.0 / self.area2 as f64
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
        let s = ONE as f64 / self.area2 as f64;
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
                brute_force(&edge, clipped)
            } else {
                Vec::new()
            };
            assert_eq!(spans, expected, "{screen:?} in {rect:?}");
            checked += expected.len();
        }
        assert!(
            checked > 100_000,
            "too few covered pixels checked: {checked}"
        );
    }
}
