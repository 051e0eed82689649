//! Points and line segments through the same [`Shader`] seam as triangles.
//!
//! - Points (OpenGL 4.6 core specification, §14.4 "Points", point size 1): a point covers the
//!   samples whose positions lie in the square of side 1 centred on its window position. The
//!   square is half-open, `[x − ½, x + ½) × [y − ½, y + ½)` in screen space (y down), so two
//!   points one pixel apart never cover the same sample; with one sample per pixel that is the
//!   one pixel whose centre lies in the square. A point outside the view volume
//!   (`−w ≤ x, y ≤ w`, `0 ≤ z ≤ w`) is dropped whole (OpenGL 4.6, "Primitive Clipping": a
//!   point outside the clip volume is discarded).
//! - Line segments (§14.5 "Line Segments", §14.5.1, width 1): the diamond-exit rule. Each
//!   pixel centre `c` has the open diamond `|x − c.x| + |y − c.y| < ½`; a segment from `a` to
//!   `b` produces a fragment for each pixel whose diamond it intersects, except the pixel whose
//!   diamond contains `b` (the end is not drawn, so a strip or loop draws every shared vertex
//!   once). Ties are broken as the specification does, by moving both endpoints by
//!   `−(ε, ε²)` in window coordinates for an infinitesimal `ε`; window y points up there, so in
//!   this crate's y-down screen space the move is `(−ε, +ε²)`. The test is exact: endpoints on
//!   the 1/256-pixel grid, integer arithmetic, and ε carried symbolically. Segments are clipped
//!   in clip space against the near and far planes (and the guard band that keeps coordinates
//!   in range, far outside the viewport); varyings are interpolated perspective-correctly at
//!   `t = (c − a)·(b − a)/‖b − a‖²` (§14.5.1; `t` clamped to [0, 1]) and depth
//!   linearly in window space.
//!
//! Both run single-threaded, in submission order (deterministic for any thread count), with the
//! triangles' depth test, blending, viewport, scissor and mask. They shade once per pixel even
//! with [`PipelineState::sample_shading`]. In a multisampled target a point covers the samples
//! in its square; a line's fragment covers every sample of its pixel (the diamond rule decides
//! pixels, not samples; §14.5.4's rectangle coverage is not implemented). Points and lines are
//! front-facing and never culled.

use barytex_interp::Interpolate;
use glam::{DVec2, UVec2, Vec2, Vec3, Vec4};
use rayon::prelude::*;

use crate::clip::planes;
use crate::draw::{DrawStats, writable_rect};
use crate::edge::{MAX_COORDINATE, SUBPIXEL_BITS, fixed};
use crate::shader::PieceContext;
use crate::state::{PipelineState, Viewport};
use crate::target::{Framebuffer, premultiply};
use crate::tile::blend;
use crate::{Fragment, Shader};

const ONE: i64 = 1 << SUBPIXEL_BITS;
const HALF: i64 = ONE / 2;

/// How an index list is read as line segments (glTF 2.0 §3.7.2.1 modes 1–3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum LineTopology {
    /// Pairs: `(i0, i1), (i2, i3), …`; an odd last index is ignored.
    #[default]
    List,
    /// `(i0, i1), (i1, i2), …`.
    Strip,
    /// A strip closed by `(i_{n−1}, i0)` (with two or more indices).
    Loop,
}

impl LineTopology {
    /// The segments of `indices`, as index pairs.
    ///
    /// ```
    /// use barytex_raster::LineTopology;
    ///
    /// assert_eq!(LineTopology::List.segments(&[0, 1, 2, 3, 4]), [[0, 1], [2, 3]]);
    /// assert_eq!(LineTopology::Strip.segments(&[0, 1, 2]), [[0, 1], [1, 2]]);
    /// assert_eq!(LineTopology::Loop.segments(&[0, 1, 2]), [[0, 1], [1, 2], [2, 0]]);
    /// assert!(LineTopology::Loop.segments(&[7]).is_empty());
    /// ```
    #[must_use]
    pub fn segments(self, indices: &[u32]) -> Vec<[u32; 2]> {
        match self {
            Self::List => indices.chunks_exact(2).map(|p| [p[0], p[1]]).collect(),
            Self::Strip | Self::Loop => {
                let mut out: Vec<[u32; 2]> = indices.windows(2).map(|p| [p[0], p[1]]).collect();
                if self == Self::Loop
                    && let (Some(&first), Some(&last)) = (indices.first(), indices.last())
                    && indices.len() >= 2
                {
                    out.push([last, first]);
                }
                out
            }
        }
    }
}

/// Window position (f32, as triangles compute it), window depth and 1/w of a clip position.
fn window(viewport: Viewport, p: Vec4) -> (Vec2, f64, f64) {
    let n: Vec3 = p.truncate() / p.w;
    (
        Vec2::new(
            viewport.x + (n.x + 1.0) * 0.5 * viewport.width,
            viewport.y + (1.0 - n.y) * 0.5 * viewport.height,
        ),
        f64::from(viewport.min_depth)
            + f64::from(n.z) * f64::from(viewport.max_depth - viewport.min_depth),
        1.0 / f64::from(p.w),
    )
}

/// The window position on the 1/256-pixel grid, `None` if non-finite or beyond
/// [`MAX_COORDINATE`].
fn snap(p: Vec2) -> Option<(i64, i64)> {
    (p.is_finite() && p.abs().max_element() <= MAX_COORDINATE).then(|| (fixed(p.x), fixed(p.y)))
}

/// Where fragments go: the target, the writable rectangle, the state and the statistics.
struct Sink<'a> {
    target: &'a mut Framebuffer,
    rect: [i64; 4],
    state: &'a PipelineState,
    stats: &'a mut DrawStats,
}

impl Sink<'_> {
    fn inside(&self, x: i64, y: i64) -> bool {
        x >= self.rect[0] && x < self.rect[2] && y >= self.rect[1] && y < self.rect[3]
    }

    /// Depth-tests the `covered` samples of pixel `(x, y)` at depth `z`, shades the pixel once
    /// and writes the samples that passed.
    fn shade<S: Shader>(
        &mut self,
        shader: &S,
        (x, y): (i64, i64),
        covered: u32,
        z: f32,
        lambda: [f64; 3],
        context: &PieceContext<S::Varying>,
    ) {
        if covered == 0 || !self.inside(x, y) {
            return;
        }
        let pixel = self.target.pixel_index(x as u32, y as u32);
        if let Some(mask) = self.target.mask.as_deref()
            && !mask[pixel]
        {
            return;
        }
        let samples = self.target.samples();
        let base = pixel * samples as usize;
        let mut passed = 0_u32;
        for k in 0..samples {
            if covered & (1 << k) != 0
                && self
                    .state
                    .depth_compare
                    .is_none_or(|op| op.passes(z, self.target.depth[base + k as usize]))
            {
                passed |= 1 << k;
            }
        }
        if passed == 0 {
            self.stats.fragments_depth_failed += 1;
            return;
        }
        let weights = context.weights(lambda);
        let fragment = Fragment {
            varying: S::Varying::combine3(context.varyings, context.input_weights(weights)),
            depth: z,
            pixel: UVec2::new(x as u32, y as u32),
            front_facing: true,
            coverage: covered,
            lambda,
            piece: context,
        };
        self.stats.fragments_shaded += 1;
        let Some(c) = shader.fragment(&fragment) else {
            self.stats.fragments_discarded += 1;
            return;
        };
        let src = premultiply(c);
        for k in 0..samples {
            if passed & (1 << k) == 0 {
                continue;
            }
            let i = base + k as usize;
            self.target.color[i] = blend(self.state, src, self.target.color[i]);
            if self.state.depth_write {
                self.target.depth[i] = z;
            }
        }
    }
}

/// Draws the vertices `indices` as points of size 1 (OpenGL 4.6 §14.4) into `target`.
///
/// A point covers the samples in the half-open square `[x − ½, x + ½) × [y − ½, y + ½)`
/// around its window position (with one sample per pixel: the pixel whose centre is in it);
/// points outside the view volume are dropped (`clipped_away`), like out-of-range indices
/// (`dropped_bad_index`) and non-finite positions (`dropped_non_finite`). Single-threaded, in
/// submission order.
///
/// ```
/// use barytex_raster::{Fragment, Framebuffer, PipelineState, Shader, TargetLimits, draw_points};
/// use glam::{Vec2, Vec4};
///
/// /// Positions given in pixels of an 8 × 8 target, one colour.
/// struct Pixels;
/// impl Shader for Pixels {
///     type Vertex = Vec2;
///     type Varying = f32;
///     fn vertex(&self, p: &Vec2) -> (Vec4, f32) {
///         (Vec4::new(p.x / 4.0 - 1.0, 1.0 - p.y / 4.0, 0.5, 1.0), 0.0)
///     }
///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> { Some(Vec4::ONE) }
/// }
/// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
/// // (2.5, 3.5) is pixel (2, 3)'s centre; (5, 1) is a pixel corner: its square's top-left
/// // corner is pixel (4, 0)'s centre, which the half-open square keeps.
/// let points = [Vec2::new(2.5, 3.5), Vec2::new(5.0, 1.0)];
/// let stats = draw_points(&mut fb, &Pixels, &PipelineState::default(), &points, &[0, 1]);
/// assert_eq!(stats.fragments_shaded, 2);
/// assert_eq!(fb.pixel(2, 3), Some(Vec4::ONE));
/// assert_eq!(fb.pixel(4, 0), Some(Vec4::ONE));
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
pub fn draw_points<S: Shader>(
    target: &mut Framebuffer,
    shader: &S,
    state: &PipelineState,
    vertices: &[S::Vertex],
    indices: &[u32],
) -> DrawStats {
    let mut stats = DrawStats::default();
    let shaded: Vec<(Vec4, S::Varying)> = vertices.par_iter().map(|v| shader.vertex(v)).collect();
    let viewport = state
        .viewport
        .unwrap_or_else(|| Viewport::full(target.width(), target.height()));
    let rect = writable_rect(target, state, viewport);
    let pattern = target.pattern();
    let samples = target.samples();
    let mut sink = Sink {
        target,
        rect,
        state,
        stats: &mut stats,
    };
    for &index in indices {
        sink.stats.points_in += 1;
        let Some(&(p, varying)) = shaded.get(index as usize) else {
            sink.stats.dropped_bad_index += 1;
            continue;
        };
        if !p.is_finite() {
            sink.stats.dropped_non_finite += 1;
            continue;
        }
        let visible = p.w > 0.0 && p.x.abs() <= p.w && p.y.abs() <= p.w && p.z >= 0.0 && p.z <= p.w;
        if !visible {
            sink.stats.clipped_away += 1;
            continue;
        }
        let (screen, depth, inv_w) = window(viewport, p);
        let Some((px, py)) = snap(screen) else {
            sink.stats.degenerate += 1;
            continue;
        };
        let context = PieceContext {
            varyings: [varying; 3],
            grads: [DVec2::ZERO; 3],
            inv_w: [inv_w; 3],
            bary: None,
            interpolation: state.interpolation,
        };
        // The pixels the square [p − ½, p + ½) can reach: two columns and two rows at most.
        let (x0, y0) = ((px - HALF).div_euclid(ONE), (py - HALF).div_euclid(ONE));
        let (x1, y1) = (
            (px + HALF - 1).div_euclid(ONE),
            (py + HALF - 1).div_euclid(ONE),
        );
        for y in y0..=y1 {
            for x in x0..=x1 {
                let mut covered = 0_u32;
                for k in 0..samples {
                    let (ox, oy) = pattern.fixed_offset(x, y, k);
                    let (sx, sy) = (x * ONE + ox, y * ONE + oy);
                    if (px - HALF..px + HALF).contains(&sx) && (py - HALF..py + HALF).contains(&sy)
                    {
                        covered |= 1 << k;
                    }
                }
                sink.shade(
                    shader,
                    (x, y),
                    covered,
                    depth as f32,
                    [1.0, 0.0, 0.0],
                    &context,
                );
            }
        }
    }
    stats
}

/// `c0 + c1·ε + c2·ε²` for an infinitesimal `ε > 0`: ordered lexicographically.
type Eps = (i128, i128, i128);

fn eps_scale(a: Eps, k: i128) -> Eps {
    (a.0 * k, a.1 * k, a.2 * k)
}

/// `n / d` with `d > 0`.
#[derive(Clone, Copy)]
struct Ratio {
    n: Eps,
    d: i128,
}

impl Ratio {
    fn less(self, other: Self) -> bool {
        eps_scale(self.n, other.d) < eps_scale(other.n, self.d)
    }
}

/// Whether the perturbed segment from `a` to `b` (1/256-pixel units) intersects pixel
/// `(x, y)`'s open diamond and does not end in it: the diamond-exit rule.
fn exits_diamond((ax, ay): (i64, i64), (bx, by): (i64, i64), x: i64, y: i64) -> bool {
    let (cx, cy) = (i128::from(x * ONE + HALF), i128::from(y * ONE + HALF));
    // Rotated coordinates u = dx + dy, v = dx − dy about the centre, of an endpoint moved by
    // (−ε, +ε²): the diamond becomes the open square |u|, |v| < ½ pixel.
    let uv = |px: i64, py: i64| -> (Eps, Eps) {
        let (dx, dy) = (i128::from(px) - cx, i128::from(py) - cy);
        ((dx + dy, -1, 1), (dx - dy, -1, -1))
    };
    let half = i128::from(HALF);
    let inside = |w: Eps| (-half, 0, 0) < w && w < (half, 0, 0);
    let (ua, va) = uv(ax, ay);
    let (ub, vb) = uv(bx, by);
    if inside(ub) && inside(vb) {
        return false;
    }
    // Liang–Barsky over t ∈ [0, 1] against the two open slabs.
    let mut lower: Option<Ratio> = None; // t > lower
    let mut upper: Option<Ratio> = None; // t < upper
    for (w0, w1) in [(ua, ub), (va, vb)] {
        let delta = w1.0 - w0.0; // the ε terms cancel: both endpoints move alike
        if delta == 0 {
            if !inside(w0) {
                return false;
            }
            continue;
        }
        // −½ < w0 + t·Δ < ½.
        let lo = (-half - w0.0, -w0.1, -w0.2);
        let hi = (half - w0.0, -w0.1, -w0.2);
        let (l, h) = if delta > 0 {
            (Ratio { n: lo, d: delta }, Ratio { n: hi, d: delta })
        } else {
            (
                Ratio {
                    n: eps_scale(hi, -1),
                    d: -delta,
                },
                Ratio {
                    n: eps_scale(lo, -1),
                    d: -delta,
                },
            )
        };
        lower = Some(lower.map_or(l, |m| if m.less(l) { l } else { m }));
        upper = Some(upper.map_or(h, |m| if h.less(m) { h } else { m }));
    }
    let zero = Ratio { n: (0, 0, 0), d: 1 };
    let one = Ratio { n: (1, 0, 0), d: 1 };
    let l = lower.unwrap_or(Ratio {
        n: (-1, 0, 0),
        d: 1,
    });
    let h = upper.unwrap_or(Ratio { n: (2, 0, 0), d: 1 });
    l.less(h) && l.less(one) && zero.less(h)
}

/// Draws line segments of width 1 (OpenGL 4.6 §14.5) from `indices` read as `topology`
/// into `target`, with the diamond-exit rule (see the module documentation).
///
/// Segments are clipped against the near and far planes (and the guard band); one entirely
/// outside is `clipped_away`, one that crosses a plane `clipped`, one of zero length on the
/// 1/256-pixel grid `degenerate`. Single-threaded, in submission order.
///
/// ```
/// use barytex_raster::{Fragment, Framebuffer, LineTopology, PipelineState, Shader,
///     TargetLimits, draw_lines};
/// use glam::{Vec2, Vec4};
///
/// /// Positions given in pixels of an 8 × 8 target, one colour.
/// struct Pixels;
/// impl Shader for Pixels {
///     type Vertex = Vec2;
///     type Varying = f32;
///     fn vertex(&self, p: &Vec2) -> (Vec4, f32) {
///         (Vec4::new(p.x / 4.0 - 1.0, 1.0 - p.y / 4.0, 0.5, 1.0), 0.0)
///     }
///     fn fragment(&self, _: &Fragment<'_, f32>) -> Option<Vec4> { Some(Vec4::ONE) }
/// }
/// let mut fb = Framebuffer::new(8, 8, Vec4::ZERO, &TargetLimits::default())?;
/// // From pixel (1, 2)'s centre to pixel (5, 2)'s: four pixels, the last one not drawn.
/// let ends = [Vec2::new(1.5, 2.5), Vec2::new(5.5, 2.5)];
/// let stats = draw_lines(&mut fb, &Pixels, &PipelineState::default(), &ends, &[0, 1],
///     LineTopology::List);
/// assert_eq!(stats.fragments_shaded, 4);
/// assert_eq!(fb.pixel(1, 2), Some(Vec4::ONE));
/// assert_eq!(fb.pixel(4, 2), Some(Vec4::ONE));
/// assert_eq!(fb.pixel(5, 2), Some(Vec4::ZERO));
/// # Ok::<(), barytex_raster::RasterError>(())
/// ```
pub fn draw_lines<S: Shader>(
    target: &mut Framebuffer,
    shader: &S,
    state: &PipelineState,
    vertices: &[S::Vertex],
    indices: &[u32],
    topology: LineTopology,
) -> DrawStats {
    let mut stats = DrawStats::default();
    let shaded: Vec<(Vec4, S::Varying)> = vertices.par_iter().map(|v| shader.vertex(v)).collect();
    let viewport = state
        .viewport
        .unwrap_or_else(|| Viewport::full(target.width(), target.height()));
    let rect = writable_rect(target, state, viewport);
    let all_samples = if target.samples() >= 32 {
        u32::MAX
    } else {
        (1_u32 << target.samples()) - 1
    };
    let mut sink = Sink {
        target,
        rect,
        state,
        stats: &mut stats,
    };
    for [i, j] in topology.segments(indices) {
        sink.stats.lines_in += 1;
        let (Some(&(pa, va)), Some(&(pb, vb))) = (shaded.get(i as usize), shaded.get(j as usize))
        else {
            sink.stats.dropped_bad_index += 1;
            continue;
        };
        if !pa.is_finite() || !pb.is_finite() {
            sink.stats.dropped_non_finite += 1;
            continue;
        }
        // Liang–Barsky in clip space against near, far and the guard band.
        let (da, db) = (planes(pa), planes(pb));
        let (mut t0, mut t1) = (0.0_f32, 1.0_f32);
        let mut out = false;
        for k in 0..6 {
            let (a, b) = (da[k], db[k]);
            if a < 0.0 && b < 0.0 {
                out = true;
                break;
            }
            if a < 0.0 {
                t0 = t0.max(a / (a - b));
            } else if b < 0.0 {
                t1 = t1.min(a / (a - b));
            }
        }
        let (ca, cb) = (pa + (pb - pa) * t0, pa + (pb - pa) * t1);
        if out || t0 >= t1 || ca.w <= 0.0 || cb.w <= 0.0 {
            sink.stats.clipped_away += 1;
            continue;
        }
        let clipped = t0 > 0.0 || t1 < 1.0;
        if clipped {
            sink.stats.clipped += 1;
        }
        let (sa, za, ia) = window(viewport, ca);
        let (sb, zb, ib) = window(viewport, cb);
        let (Some(a), Some(b)) = (snap(sa), snap(sb)) else {
            sink.stats.degenerate += 1;
            continue;
        };
        if a == b {
            sink.stats.degenerate += 1;
            continue;
        }
        let bary = |t: f32| Vec3::new(1.0 - t, t, 0.0);
        let (dx, dy) = ((b.0 - a.0) as f64, (b.1 - a.1) as f64);
        let len2 = dx * dx + dy * dy;
        // dt per pixel right and down.
        let g = DVec2::new(dx, dy) * (ONE as f64 / len2);
        let context = PieceContext {
            varyings: [va, vb, vb],
            grads: [-g, g, DVec2::ZERO],
            inv_w: [ia, ib, ib],
            bary: clipped.then(|| [bary(t0), bary(t1), bary(t1)]),
            interpolation: state.interpolation,
        };
        let mut emit = |x: i64, y: i64| {
            if !exits_diamond(a, b, x, y) {
                return;
            }
            let (cx, cy) = ((x * ONE + HALF - a.0) as f64, (y * ONE + HALF - a.1) as f64);
            let t = ((cx * dx + cy * dy) / len2).clamp(0.0, 1.0);
            let z = ((1.0 - t) * za + t * zb) as f32;
            sink.shade(shader, (x, y), all_samples, z, [1.0 - t, t, 0.0], &context);
        };
        // Walk the major axis; three candidates across it cover every diamond the segment meets.
        let x_major = dx.abs() >= dy.abs();
        let (ma, mb, na, slope) = if x_major {
            (a.0, b.0, a.1, dy / dx)
        } else {
            (a.1, b.1, a.0, dx / dy)
        };
        let (lo, hi) = (
            ma.min(mb).div_euclid(ONE) - 1,
            ma.max(mb).div_euclid(ONE) + 1,
        );
        let (clo, chi) = if x_major {
            (rect[0], rect[2] - 1)
        } else {
            (rect[1], rect[3] - 1)
        };
        for m in lo.max(clo)..=hi.min(chi) {
            let minor = na as f64 + ((m * ONE + HALF - ma) as f64) * slope;
            let n0 = (minor / ONE as f64).floor() as i64;
            for n in n0 - 1..=n0 + 1 {
                if x_major {
                    emit(m, n);
                } else {
                    emit(n, m);
                }
            }
        }
    }
    stats
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: i64 = ONE;

    #[test]
    fn diamond_exit_on_centres_is_half_open() {
        // Pixel (0, 0)'s centre to pixel (3, 0)'s: pixels 0, 1, 2.
        let (a, b) = ((P / 2, P / 2), (3 * P + P / 2, P / 2));
        let hit: Vec<i64> = (-1..5).filter(|&x| exits_diamond(a, b, x, 0)).collect();
        assert_eq!(hit, [0, 1, 2]);
        assert!(!exits_diamond(a, b, 1, 1) && !exits_diamond(a, b, 1, -1));
    }

    #[test]
    fn ties_go_left_and_down() {
        // A horizontal segment on the boundary y = 1 between rows 0 and 1: the perturbation
        // (−ε, +ε²) in y-down screen space moves it into row 1.
        let (a, b) = ((P / 2, P), (3 * P + P / 2, P));
        assert!((0..3).all(|x| exits_diamond(a, b, x, 1) && !exits_diamond(a, b, x, 0)));
        // A vertical one on x = 1 between columns 0 and 1 moves into column 0.
        let (a, b) = ((P, P / 2), (P, 3 * P + P / 2));
        assert!((0..3).all(|y| exits_diamond(a, b, 0, y) && !exits_diamond(a, b, 1, y)));
    }
}
