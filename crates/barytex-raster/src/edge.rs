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

/// Rounds a screen coordinate to fixed point.
pub(crate) fn fixed(v: f32) -> i64 {
    (f64::from(v) * ONE as f64).round() as i64
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
        let x0 = self.bbox[0].max(rect[0]);
        let y0 = self.bbox[1].max(rect[1]);
        let x1 = self.bbox[2].min(rect[2]);
        let y1 = self.bbox[3].min(rect[3]);
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let step = self.a.map(|a| a * ONE);
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
                for y in ys..ye {
                    let (px, py) = (xs * ONE + reference.0, y * ONE + reference.1);
                    let mut e: [i64; 3] =
                        core::array::from_fn(|i| self.a[i] * px + self.b[i] * py + self.c[i]);
                    for x in xs..xe {
                        visit(x, y, e, accept);
                        for i in 0..3 {
                            e[i] += step[i];
                        }
                    }
                }
            }
            by += BLOCK;
        }
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
    /// the triangle covers, row by row within blocks, with the screen-space barycentrics `λ` of
    /// the centre over the **input** vertex order.
    #[inline]
    pub(crate) fn for_each_covered(
        &self,
        rect: [i64; 4],
        mut covered: impl FnMut(i64, i64, [f64; 3]),
    ) {
        let inv_area = 1.0 / self.area2 as f64;
        self.for_each_block_pixel(rect, (HALF, HALF), (HALF, HALF), |x, y, e, all| {
            if all || self.covers(e) {
                // Edge j is opposite input vertex j: its value is that vertex's weight.
                covered(x, y, e.map(|v| v as f64 * inv_area));
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
