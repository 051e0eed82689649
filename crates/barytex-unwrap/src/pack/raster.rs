//! Raster-mask packing of charts: each chart, in each of its four quarter turns, is rasterized
//! conservatively into a bitmap of texels, dilated by the padding, and placed in an atlas
//! bitmap wherever its mask meets no texel of a chart already there — so a chart can sit in
//! another's hole, under its overhang or between its arms, which neither bounding boxes
//! (Jylänki 2010) nor a horizon (Lévy et al. 2002, §6) allow.
//!
//! This is the packer of xatlas (Jonathan Young's texture atlas library,
//! <https://github.com/jpcy/xatlas>, `PackCharts`): charts largest first, each at the position
//! (and turn) that keeps the atlas's bounding square smallest, then lowest, then leftmost.
//! Here one texel density is searched for all charts (secant steps on the filled square's side
//! against the scale, inside a bisection bracket), so that the square fits the texture at the
//! padding asked for, in texels.
//!
//! # Exactness of the padding
//! A chart's texels are every texel that any of its triangles (and points), grown by
//! [`MARGIN_TEXELS`] on every side, touches — a superset of the texels the chart covers. Its
//! mask is those texels dilated by a `(2p + 1)²` square (the Chebyshev ball of radius `p`,
//! the padding). The atlas holds the texels (undilated) of the charts placed; a position is
//! free when the mask there meets none of them. Two charts' texels are then at least `p + 1`
//! texel indices apart along one axis, so any two of their points are at least `p` texels
//! apart — plus twice the margin, which rounding uvs to f32 cannot eat. The mask also stays
//! inside the texture, so a chart's texels are `p` texels from the border.
//!
//! # Cost
//! Each row of a mask is kept as runs of set bits; a run at a candidate position is tested
//! with one query to the atlas ("the last set texel in this range of this row", a few word
//! reads, none for a row outside its set span), and a hit moves the candidate right past that
//! texel at once. The row that failed last is tried first at the next candidate, so most
//! candidates cost one query; a candidate row is refused without any when a mask row is longer
//! than every clear run of the atlas row under it; and only spots better than the best so far
//! are searched. Turns 2 and 3 are the bitmaps of turns 0 and 1 half-turned (exact, the chart
//! moved by the texels' slack past its box), so each chart is rasterized twice per packing.
//! A scale search may do at most 32 units of work (candidate rows and queries) per texel of
//! the texture — about 3 times what Suzanne's 57 charts (at an 80° cone) took at 1024 — and
//! then keeps the best packing it has, so no input of charts makes it run long.

use glam::DVec2;

use super::bitmap::Bitmap;
use super::horizon::{Placed, turn};
use super::{MARGIN_TEXELS, PackOptions};
use crate::Chart;

/// One chart at one scale in one turn.
#[derive(Clone, Debug)]
struct Shape {
    /// The chart's texels, placed `padding` texels right of and above the mask's corner.
    texels: Bitmap,
    /// The mask's width and height (the texels' plus twice the padding).
    w: usize,
    h: usize,
    /// The mask's rows as runs `(first, last)` of set bits: row `r` is
    /// `runs[starts[r]..starts[r + 1]]`.
    runs: Vec<(u32, u32)>,
    starts: Vec<u32>,
    /// Per mask row, its longest run's length (0 for an empty row).
    longest: Vec<u32>,
    /// Where the chart's turned frame sits in its texels, less the margin: zero for a
    /// rasterized turn, the texels' slack past the chart's box for a half-turned bitmap.
    shift: DVec2,
}

impl Shape {
    fn row(&self, r: usize) -> &[(u32, u32)] {
        &self.runs[self.starts[r] as usize..self.starts[r + 1] as usize]
    }

    /// This shape half a turn further, from its bitmaps (cheaper than rasterizing again, and
    /// exact: the texels of a half-turned chart are the half-turned texels, the chart moved by
    /// the texels' slack past its box, `slack`).
    fn half_turned(&self, slack: DVec2) -> Self {
        let (w, h) = (self.w, self.h);
        let mut runs = Vec::with_capacity(self.runs.len());
        let mut starts = Vec::with_capacity(h + 1);
        for r in (0..h).rev() {
            starts.push(runs.len() as u32);
            runs.extend(
                self.row(r)
                    .iter()
                    .rev()
                    .map(|&(a, b)| (w as u32 - 1 - b, w as u32 - 1 - a)),
            );
        }
        starts.push(runs.len() as u32);
        Self {
            texels: self.texels.half_turned(),
            w,
            h,
            runs,
            starts,
            longest: self.longest.iter().rev().copied().collect(),
            shift: slack,
        }
    }
}

/// Sets every texel of `texels` that the triangle `t` (texel coordinates), grown by `m` on every
/// side, has a point in (texel `(i, j)` is `[i, i + 1) × [j, j + 1)`).
fn fill_triangle(texels: &mut Bitmap, t: [DVec2; 3], m: f64) {
    let (w, h) = (texels.width(), texels.height());
    let ylo = t[0].y.min(t[1].y).min(t[2].y) - m;
    let yhi = t[0].y.max(t[1].y).max(t[2].y) + m;
    let Some((r0, r1)) = cells(ylo, yhi, h) else {
        return;
    };
    // Per edge: its y range, and x as a function of y (`None`: flat or too steep a slope for
    // f64, then its whole x range is used, which is still conservative).
    let edges = [0, 1, 2].map(|i| {
        let (p, q) = (t[i], t[(i + 1) % 3]);
        let k = (q.x - p.x) / (q.y - p.y);
        (p.y.min(q.y), p.y.max(q.y), p, q, k.is_finite().then_some(k))
    });
    for r in r0..=r1 {
        // The triangle's points whose grown square reaches row r lie in the slab [a, b]; the
        // clipped triangle's boundary is made of its edges' pieces inside the slab (and
        // horizontal cuts whose ends are on those pieces), so its x range is theirs.
        let (a, b) = (r as f64 - m, r as f64 + 1.0 + m);
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for &(y0, y1, p, q, k) in &edges {
            if y1 < a || y0 > b {
                continue;
            }
            // Plain comparisons (f64::min and clamp also handle NaN, which cannot occur here
            // but costs on every row).
            let within = |y: f64| {
                if y < y0 {
                    y0
                } else if y > y1 {
                    y1
                } else {
                    y
                }
            };
            let (xa, xb) = match k {
                Some(k) => (p.x + (within(a) - p.y) * k, p.x + (within(b) - p.y) * k),
                None => (p.x, q.x),
            };
            let (l, h) = if xa < xb { (xa, xb) } else { (xb, xa) };
            if l < lo {
                lo = l;
            }
            if h > hi {
                hi = h;
            }
        }
        if let Some((c0, c1)) = cells(lo - m, hi + m, w) {
            texels.set_span(r, c0, c1);
        }
    }
}

/// The texels `floor(lo)..=floor(hi)` clipped to `0..n`, or `None` when none is left (or the
/// bounds are not numbers).
fn cells(lo: f64, hi: f64, n: usize) -> Option<(usize, usize)> {
    if lo.is_nan() || hi.is_nan() || lo > hi || n == 0 || hi < 0.0 || lo >= n as f64 {
        return None;
    }
    // Truncation is the floor for these non-negative numbers (and no libm call).
    let first = lo.max(0.0) as usize;
    let last = (hi as usize).min(n - 1);
    Some((first, last))
}

/// The chart's four quarter turns (one when `turns` is off): turns 0 and 1 rasterized, 2 and 3
/// their half turns; `None` for a turn whose mask is larger than `limit` texels.
fn shapes(
    chart: &Chart,
    e: DVec2,
    scale: f64,
    padding: usize,
    limit: usize,
    turns: bool,
) -> Vec<Option<Shape>> {
    if !turns {
        return vec![rasterize(chart, e, 0, scale, padding, limit)];
    }
    let [a, b] = [0, 1].map(|k| rasterize(chart, e, k, scale, padding, limit));
    // The texels' slack past the turned box, which a half turn moves the chart by.
    let slack = |s: &Shape, x: f64, y: f64| {
        let m = 2.0 * MARGIN_TEXELS;
        DVec2::new(
            s.texels.width() as f64 - (x * scale + m),
            s.texels.height() as f64 - (y * scale + m),
        )
    };
    let c = a.as_ref().map(|s| s.half_turned(slack(s, e.x, e.y)));
    let d = b.as_ref().map(|s| s.half_turned(slack(s, e.y, e.x)));
    vec![a, b, c, d]
}

/// A chart (uvs from the origin, box extent `e`) turned `k` quarter turns, scaled by `scale`,
/// rasterized and padded; `None` when its mask is wider or taller than `limit` texels.
fn rasterize(
    chart: &Chart,
    e: DVec2,
    k: u8,
    scale: f64,
    padding: usize,
    limit: usize,
) -> Option<Shape> {
    let m = MARGIN_TEXELS;
    let turned = if k % 2 == 1 { DVec2::new(e.y, e.x) } else { e };
    let side = |x: f64| {
        let t = (x * scale + 2.0 * m).ceil().max(1.0);
        (t.is_finite() && t + 2.0 * padding as f64 <= limit as f64).then_some(t as usize)
    };
    let (tw, th) = (side(turned.x)?, side(turned.y)?);
    let mut texels = Bitmap::new(tw, th)?;
    let map = |p: DVec2| turn(p, e, k) * scale + DVec2::splat(m);
    for t in &chart.triangles {
        let [a, b, c] = t.map(|i| chart.uvs.get(i as usize).map(|&p| map(p)));
        if let (Some(a), Some(b), Some(c)) = (a, b, c) {
            fill_triangle(&mut texels, [a, b, c], m);
        }
    }
    // Points too (a vertex in no triangle still gets a uv that must stay inside).
    for &p in &chart.uvs {
        let q = map(p);
        if let (Some((c0, c1)), Some((r0, r1))) =
            (cells(q.x - m, q.x + m, tw), cells(q.y - m, q.y + m, th))
        {
            for r in r0..=r1 {
                texels.set_span(r, c0, c1);
            }
        }
    }
    let mask = texels.dilated(padding)?;
    let (w, h) = (mask.width(), mask.height());
    let mut runs = Vec::new();
    let mut starts = Vec::with_capacity(h + 1);
    let mut longest = Vec::with_capacity(h);
    let mut row = Vec::new();
    for r in 0..h {
        starts.push(runs.len() as u32);
        mask.runs(r, &mut row);
        runs.extend_from_slice(&row);
        longest.push(row.iter().map(|&(a, b)| b - a + 1).max().unwrap_or(0));
    }
    starts.push(runs.len() as u32);
    Some(Shape {
        texels,
        w,
        h,
        runs,
        starts,
        longest,
        shift: DVec2::ZERO,
    })
}

/// The search's state along one chart turn: the mask row that refused last, and the work done
/// (candidate rows and atlas queries).
#[derive(Clone, Copy, Debug, Default)]
struct Probe {
    hint: usize,
    work: u64,
}

/// Every how many mask rows the clear-run test asks.
const GAP_STRIDE: usize = 8;

/// The first `x <= xmax` where `shape`'s mask at `(x, y)` meets no set texel of `atlas`, whose
/// rows from `filled` up are empty and whose rows have `gaps` (see [`Gaps`]); `hint` is the
/// mask row that failed last.
fn first_fit(
    atlas: &Bitmap,
    gaps: &[Gaps],
    shape: &Shape,
    y: usize,
    xmax: usize,
    filled: usize,
    probe: &mut Probe,
) -> Option<usize> {
    // Rows of the mask that land on empty atlas rows never collide.
    let live = filled.saturating_sub(y).min(shape.h);
    probe.work += 1;
    // A mask row longer than every clear run of its atlas row fits nowhere on this row; the
    // row that refused last is asked first, then every `GAP_STRIDE`th row (refusing rows come
    // in bands, and asking every row would cost as much as the search it saves).
    let end = (xmax + shape.w) as u32;
    let refuses = |r: usize| shape.longest[r] > gaps[y + r].room(end);
    if probe.hint < live && refuses(probe.hint) {
        return None;
    }
    if let Some(r) = (0..live).step_by(GAP_STRIDE).find(|&r| refuses(r)) {
        probe.hint = r;
        return None;
    }
    if probe.hint >= live {
        probe.hint = 0;
    }
    let mut x = 0;
    'candidates: while x <= xmax {
        // The hinted row first, then the others in turn.
        let (first, rest) = (probe.hint..live, 0..probe.hint);
        for r in first.chain(rest) {
            for &(a, b) in shape.row(r) {
                let (a, b) = (a as usize, b as usize);
                probe.work += 1;
                if let Some(c) = atlas.last_set_in(y + r, x + a, x + b) {
                    // Every x' up to c - a puts this run over texel c.
                    x = c + 1 - a;
                    probe.hint = r;
                    continue 'candidates;
                }
            }
        }
        return Some(x);
    }
    None
}

/// The clear runs of an atlas row: the longest one before its last set bit, and where the
/// clear tail after that bit starts.
#[derive(Clone, Copy, Debug, Default)]
struct Gaps {
    inner: u32,
    tail: u32,
}

impl Gaps {
    fn of(atlas: &Bitmap, y: usize, runs: &mut Vec<(u32, u32)>) -> Self {
        atlas.runs(y, runs);
        let mut inner = 0;
        let mut tail = 0u32;
        for &(a, b) in runs.iter() {
            inner = inner.max(a - tail);
            tail = b + 1;
        }
        Self { inner, tail }
    }

    /// The longest clear run of the row's first `end` bits.
    fn room(self, end: u32) -> u32 {
        self.inner.max(end.saturating_sub(self.tail))
    }
}

/// What one packing at one scale gave: where each chart went (in `order`), and the side of
/// the square the masks fill (texture-sized or less when they fit the texture).
#[derive(Clone, Debug)]
pub(crate) struct Packed {
    pub(crate) side: usize,
    pub(crate) placed: Vec<Placed>,
}

/// Packs the charts `order` at `scale` into a `limit`-texel square bitmap, each chart where the
/// square they fill stays smallest, then lowest, then leftmost; `None` when one does not fit
/// the limit (or a bitmap would be too large).
pub(crate) fn try_pack(
    order: &[usize],
    charts: &[Chart],
    extents: &[DVec2],
    scale: f64,
    options: &PackOptions,
    limit: usize,
    work: &mut u64,
) -> Option<Packed> {
    let (padding, turns) = (options.padding, options.rotate);
    let p = padding as usize;
    let mut atlas = Bitmap::new(limit, limit)?;
    let mut gaps = vec![Gaps::default(); limit];
    let mut runs = Vec::new();
    let (mut width, mut height) = (0usize, 0usize);
    let mut placed = Vec::with_capacity(order.len());
    for &i in order {
        let shapes = shapes(&charts[i], extents[i], scale, p, limit, turns);
        // (square side, y, x, turn) of the best spot so far.
        let mut best: Option<(usize, usize, usize, usize)> = None;
        let mut probe = Probe::default();
        for (k, shape) in shapes.iter().enumerate() {
            let Some(shape) = shape else {
                continue;
            };
            probe.hint = 0;
            for y in 0..=(limit - shape.h) {
                let tall = height.max(y + shape.h);
                let least = width.max(tall).max(shape.w);
                let mut xmax = limit - shape.w;
                if let Some((side, by, bx, _)) = best {
                    // The least square only grows with y; a tie loses to the lower spot (and
                    // on the same row, to the left one), so only better spots are searched.
                    if least > side || (least == side && y > by) {
                        break;
                    }
                    let most = if y > by {
                        (side - 1).checked_sub(shape.w)
                    } else {
                        (side - shape.w).checked_sub(usize::from(bx + shape.w == side))
                    };
                    match most {
                        Some(most) => xmax = xmax.min(most),
                        // Past the best row the bound no longer changes with y.
                        None if y > by => break,
                        None => continue,
                    }
                }
                if let Some(x) = first_fit(&atlas, &gaps, shape, y, xmax, height, &mut probe) {
                    let side = least.max(x + shape.w);
                    if best.is_none_or(|b| (side, y, x) < (b.0, b.1, b.2)) {
                        best = Some((side, y, x, k));
                    }
                }
            }
        }
        *work = work.saturating_sub(probe.work);
        if *work == 0 {
            return None;
        }
        let (_, y, x, k) = best?;
        let shape = shapes[k].as_ref()?;
        atlas.blit(&shape.texels, x + p, y + p);
        let rows = y + p..y + p + shape.texels.height();
        for (r, gap) in gaps.iter_mut().enumerate().take(rows.end).skip(rows.start) {
            *gap = Gaps::of(&atlas, r, &mut runs);
        }
        width = width.max(x + shape.w);
        height = height.max(y + shape.h);
        placed.push(Placed {
            turns: k as u8,
            origin: DVec2::new((x + p) as f64, (y + p) as f64) + MARGIN_TEXELS + shape.shift,
        });
    }
    Some(Packed {
        side: width.max(height),
        placed,
    })
}

/// The most packings one scale search runs.
const SEARCH_ATTEMPTS: u32 = 8;

/// The search stops once the bracket is this narrow (relative to its low end).
const SEARCH_TOLERANCE: f64 = 1e-3;

/// The search stops once the filled square is this close to the texture's side (relative).
const FULL: f64 = 2e-3;

/// The work (candidate rows and atlas queries) one scale search may do, per texel of the
/// texture: about 3 times what Suzanne's 57 charts (at an 80° cone) took, so that no input of
/// many charts makes the search run for long (256 charts are allowed; the budget is what bounds
/// the time); the packings done by then still count.
const WORK_PER_TEXEL: u64 = 32;

/// The largest atlas bitmap side (8 MiB of bits; each chart's bitmaps are no larger);
/// textures over half of it (4096 texels) are not packed here.
pub(crate) const MAX_LIMIT: usize = 1 << 13;

/// Searches the largest scale, up to `ceiling`, at which [`try_pack`] fits the charts into a
/// `size`-texel square, starting at `start` (a scale another packer reached): secant steps on
/// the filled square's side against the scale, kept inside a shrinking bracket (bisection
/// when a step leaves it). Each attempt packs into a bitmap twice the texture's side, so a
/// scale that is too large still says by how much. Returns the best scale found and its
/// spots (in `order`), or `None`; `attempts` counts the packings.
pub(crate) fn search(
    order: &[usize],
    charts: &[Chart],
    extents: &[DVec2],
    options: &PackOptions,
    start: f64,
    ceiling: f64,
    attempts: &mut u32,
) -> Option<(f64, Vec<Placed>)> {
    let size = options.size;
    let limit = 2 * size as usize;
    if limit > MAX_LIMIT || start.is_nan() || start <= 0.0 || !ceiling.is_finite() {
        return None;
    }
    let target = f64::from(size);
    let mut work = WORK_PER_TEXEL * u64::from(size) * u64::from(size);
    let (mut lo, mut hi) = (0.0, ceiling.max(start));
    let mut best: Option<(f64, Vec<Placed>)> = None;
    let mut previous: Option<(f64, f64)> = None;
    let mut s = start;
    for _ in 0..SEARCH_ATTEMPTS {
        *attempts += 1;
        let r = try_pack(order, charts, extents, s, options, limit, &mut work);
        if work == 0 {
            // Out of work (charts of a shape that makes every row a maze): the best so far.
            break;
        }
        let side = match r {
            Some(packed) => {
                let side = packed.side as f64;
                if side <= target {
                    lo = s;
                    if best.as_ref().is_none_or(|b| s > b.0) {
                        best = Some((s, packed.placed));
                    }
                } else {
                    hi = s;
                }
                Some(side)
            }
            None => {
                hi = s;
                None
            }
        };
        // Done when the bracket is narrow, or the square fills the texture but for a texel or
        // two per thousand (a larger scale would gain no more than that).
        let full = side.is_some_and(|e| e <= target && e >= target * (1.0 - FULL));
        if full || hi <= lo * (1.0 + SEARCH_TOLERANCE) {
            break;
        }
        let step = match (previous, side) {
            (Some((s0, e0)), Some(e1)) if e1 != e0 => s + (target - e1) * (s - s0) / (e1 - e0),
            (_, Some(e1)) if e1 > 0.0 => s * target / e1,
            _ => f64::NAN,
        };
        if let Some(e1) = side {
            previous = Some((s, e1));
        }
        s = if step.is_finite() && step > lo && step < hi {
            step
        } else {
            0.5 * (lo + hi)
        };
    }
    best
}

#[cfg(test)]
mod tests {
    use super::super::{chart_uv_area, horizon, normalize, place};
    use super::*;
    use crate::overlap::triangles_overlap;

    /// A chart of unit cells (each two triangles, vertices not shared), `side` units each.
    fn cells_chart(cells: &[(u32, u32)], side: f64) -> Chart {
        let mut chart = Chart {
            faces: Vec::new(),
            vertices: Vec::new(),
            triangles: Vec::new(),
            uvs: Vec::new(),
        };
        for &(i, j) in cells {
            let n = chart.uvs.len() as u32;
            let o = DVec2::new(f64::from(i), f64::from(j));
            chart
                .uvs
                .extend([o, o + DVec2::X, o + DVec2::ONE, o + DVec2::Y].map(|p| p * side));
            chart.vertices.extend(n..n + 4);
            chart
                .triangles
                .extend([[n, n + 1, n + 2], [n, n + 2, n + 3]]);
            chart.faces.extend([n / 2, n / 2 + 1]);
        }
        chart
    }

    /// An L of arms `arm` cells long, one cell thick.
    fn l_chart(arm: u32, side: f64) -> Chart {
        let cells: Vec<(u32, u32)> = (0..arm)
            .map(|i| (i, 0))
            .chain((1..arm).map(|j| (0, j)))
            .collect();
        cells_chart(&cells, side)
    }

    /// A square ring `outer` cells wide around a square hole `outer - 2 * thick` cells wide.
    fn annulus(outer: u32, thick: u32, side: f64) -> Chart {
        let cells: Vec<(u32, u32)> = (0..outer)
            .flat_map(|i| (0..outer).map(move |j| (i, j)))
            .filter(|&(i, j)| i < thick || j < thick || i >= outer - thick || j >= outer - thick)
            .collect();
        cells_chart(&cells, side)
    }

    /// Normalizes the charts as `pack` does; their extents and the order largest first.
    fn prepare(charts: &mut [Chart]) -> (Vec<DVec2>, Vec<usize>) {
        let extents: Vec<DVec2> = charts
            .iter_mut()
            .map(|c| normalize(&mut c.uvs, true))
            .collect();
        let mut order: Vec<usize> = (0..charts.len()).collect();
        order.sort_by(|&a, &b| {
            chart_uv_area(&charts[b])
                .total_cmp(&chart_uv_area(&charts[a]))
                .then(a.cmp(&b))
        });
        (extents, order)
    }

    /// The distance between two closed segments.
    fn segment_distance(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> f64 {
        let point = |p: DVec2, a: DVec2, b: DVec2| {
            let l = (b - a).length_squared();
            let t = if l > 0.0 {
                ((p - a).dot(b - a) / l).clamp(0.0, 1.0)
            } else {
                0.0
            };
            p.distance(a + (b - a) * t)
        };
        let crosses = |a: DVec2, b: DVec2, c: DVec2, d: DVec2| {
            let s = |p: DVec2| crate::overlap::orient(a, b, p).signum();
            s(c) * s(d) < 0.0
        };
        if crosses(a, b, c, d) && crosses(c, d, a, b) {
            return 0.0;
        }
        point(a, c, d)
            .min(point(b, c, d))
            .min(point(c, a, b))
            .min(point(d, a, b))
    }

    /// Checks a packed layout (uvs in the unit square): no two triangles of different charts
    /// overlap (exactly), any two are at least `padding` texels apart, and every uv is
    /// `padding` texels inside the border.
    fn assert_padded(charts: &[Chart], size: u32, padding: u32) {
        let texel = 1.0 / f64::from(size);
        let gap = f64::from(padding) * texel;
        let triangles = |c: &Chart| -> Vec<[DVec2; 3]> {
            c.triangles
                .iter()
                .filter_map(|t| {
                    let [a, b, c] = t.map(|i| c.uvs.get(i as usize).copied());
                    Some([a?, b?, c?])
                })
                .collect()
        };
        for (i, c) in charts.iter().enumerate() {
            for uv in &c.uvs {
                assert!(
                    uv.cmpge(DVec2::splat(gap)).all() && uv.cmple(DVec2::splat(1.0 - gap)).all(),
                    "chart {i}: {uv}"
                );
            }
            for (j, d) in charts.iter().enumerate().skip(i + 1) {
                for s in triangles(c) {
                    for t in triangles(d) {
                        assert!(!triangles_overlap(s, t), "charts {i} and {j} overlap");
                        let mut closest = f64::INFINITY;
                        for a in 0..3 {
                            for b in 0..3 {
                                closest = closest.min(segment_distance(
                                    s[a],
                                    s[(a + 1) % 3],
                                    t[b],
                                    t[(b + 1) % 3],
                                ));
                            }
                        }
                        assert!(
                            closest >= gap,
                            "charts {i} and {j}: {} texels apart",
                            closest / texel
                        );
                    }
                }
            }
        }
    }

    /// The largest scale the horizon packer reaches (bisection to 1e-4 relative).
    fn horizon_scale(
        charts: &[Chart],
        extents: &[DVec2],
        order: &[usize],
        size: u32,
        padding: u32,
    ) -> f64 {
        let outlines: Vec<[horizon::Outline; 4]> = charts
            .iter()
            .zip(extents)
            .map(|(c, &e)| [0, 1, 2, 3].map(|k| horizon::Outline::new(&c.uvs, &c.triangles, e, k)))
            .collect();
        let (mut lo, mut hi) = (0.0, f64::from(size));
        while hi > lo * (1.0 + 1e-4) {
            let mid = 0.5 * (lo + hi);
            if horizon::try_pack(order, &outlines, mid, size, padding, true).is_some() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo
    }

    fn mix() -> Vec<Chart> {
        let mut charts: Vec<Chart> = (0..10)
            .map(|k| l_chart(2 + k % 4, 1.0 + 0.1 * f64::from(k)))
            .collect();
        charts.push(annulus(5, 1, 1.0));
        charts.push(cells_chart(&[(0, 0)], 0.7));
        charts
    }

    #[test]
    fn packed_charts_never_overlap_and_keep_the_padding() {
        for (size, padding) in [(256, 3), (200, 1), (128, 0)] {
            let mut charts = mix();
            let (extents, order) = prepare(&mut charts);
            let mut attempts = 0;
            let (scale, spots) = search(
                &order,
                &charts,
                &extents,
                &PackOptions {
                    size,
                    padding,
                    rotate: true,
                },
                1.0,
                1e3,
                &mut attempts,
            )
            .expect("packs");
            assert!(attempts <= SEARCH_ATTEMPTS);
            let efficiency = place(&mut charts, &order, &extents, scale, &spots, size);
            assert!(efficiency > 0.3 && efficiency < 1.0, "{efficiency}");
            assert_padded(&charts, size, padding);
        }
    }

    #[test]
    fn a_small_chart_goes_into_a_hole() {
        let mut charts = vec![annulus(5, 1, 1.0), cells_chart(&[(0, 0)], 1.0)];
        let (extents, order) = prepare(&mut charts);
        assert_eq!(order, [0, 1]);
        // 20 texels a cell: the hole is 60 texels wide, the small chart 20 plus 2 × 4 padding.
        let options = PackOptions {
            size: 256,
            padding: 4,
            rotate: true,
        };
        let packed = try_pack(
            &order,
            &charts,
            &extents,
            20.0,
            &options,
            256,
            &mut u64::MAX.clone(),
        )
        .expect("fits");
        place(&mut charts, &order, &extents, 20.0, &packed.placed, 1);
        let ring = charts[0]
            .uvs
            .iter()
            .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), &p| {
                (lo.min(p), hi.max(p))
            });
        assert!((ring.1 - ring.0 - DVec2::splat(100.0)).abs().max_element() < 1e-9);
        let (lo, hi) = (ring.0 + 20.0, ring.1 - 20.0);
        for p in &charts[1].uvs {
            assert!(
                p.cmpgt(lo).all() && p.cmplt(hi).all(),
                "{p} not in the hole {lo} {hi}"
            );
        }
        // The atlas is no larger than the ring's mask.
        assert_eq!(packed.side, 100 + 1 + 8);
    }

    #[test]
    fn packing_stops_when_out_of_work() {
        let mut charts = mix();
        let (extents, order) = prepare(&mut charts);
        let options = PackOptions {
            size: 256,
            padding: 2,
            rotate: true,
        };
        let mut plenty = u64::MAX;
        let packed = try_pack(&order, &charts, &extents, 5.0, &options, 512, &mut plenty);
        assert!(packed.is_some());
        let spent = u64::MAX - plenty;
        assert!(spent > 10);
        // A budget one short of what that packing needed ends it, with the budget at zero.
        let mut short = spent - 1;
        assert!(try_pack(&order, &charts, &extents, 5.0, &options, 512, &mut short).is_none());
        assert_eq!(short, 0);
    }

    #[test]
    fn l_shapes_pack_denser_than_on_a_horizon() {
        let mut charts: Vec<Chart> = (0..16)
            .map(|k| l_chart(3 + k % 3, 1.0 + 0.05 * f64::from(k)))
            .collect();
        let (extents, order) = prepare(&mut charts);
        let (size, padding) = (512, 2);
        let horizon = horizon_scale(&charts, &extents, &order, size, padding);
        let mut attempts = 0;
        let (raster, _) = search(
            &order,
            &charts,
            &extents,
            &PackOptions {
                size,
                padding,
                rotate: true,
            },
            horizon,
            1e4,
            &mut attempts,
        )
        .expect("packs");
        // Efficiency goes with the scale squared.
        assert!(
            raster > horizon * 1.05,
            "raster {raster} vs horizon {horizon}"
        );
    }

    #[test]
    fn degenerate_charts_are_packed_without_panic() {
        let line = Chart {
            faces: vec![0],
            vertices: vec![0, 1, 2],
            triangles: vec![[0, 1, 2]],
            uvs: vec![DVec2::ZERO, DVec2::X, DVec2::new(2.0, 0.0)],
        };
        let point = Chart {
            faces: vec![0, 1],
            vertices: vec![0, 1, 2],
            triangles: vec![[0, 1, 2], [0, 9, 1]],
            uvs: vec![DVec2::ONE; 3],
        };
        let mut charts = vec![line, point, cells_chart(&[(0, 0)], 1.0)];
        let (extents, order) = prepare(&mut charts);
        for scale in [0.0, 1e-300, 10.0, 1e300, f64::NAN, f64::INFINITY] {
            let options = PackOptions {
                size: 64,
                padding: 2,
                rotate: true,
            };
            let _ = try_pack(
                &order,
                &charts,
                &extents,
                scale,
                &options,
                64,
                &mut (1 << 40),
            );
        }
        let mut attempts = 0;
        let (scale, spots) = search(
            &order,
            &charts,
            &extents,
            &PackOptions {
                size: 64,
                padding: 2,
                rotate: true,
            },
            1.0,
            1e3,
            &mut attempts,
        )
        .expect("packs");
        place(&mut charts, &order, &extents, scale, &spots, 64);
        assert_padded(&charts, 64, 2);
    }
}
