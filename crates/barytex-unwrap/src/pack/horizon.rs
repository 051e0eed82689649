//! Horizon packing of chart outlines (Lévy, Petitjean, Ray, Maillot, "Least squares conformal
//! maps for automatic texture atlas generation", SIGGRAPH 2002, §6, a "Tetris" packer): the
//! packed area's upper outline is kept per texel column; each chart, in each of its four
//! quarter turns, is lowered from above onto it at every column and goes where its top ends
//! lowest. Unlike boxes, a chart's own lower outline nests into the outline below, so irregular
//! charts (those of a parameterization) waste much less space than their bounding boxes do;
//! space under a chart's overhangs is lost, as in the paper.
//!
//! Outlines are conservative: a column's extent is that of every triangle's bounding box that
//! crosses it. Padding is kept by raising the outline `padding` texels above a chart and
//! spreading it `padding` columns to each side, so two charts are always `padding` texels apart
//! in one direction or the other.

use glam::DVec2;

use super::MARGIN_TEXELS;

/// One chart turned by a quarter turn: its triangles' boxes in its own frame (unscaled).
#[derive(Clone, Debug)]
pub(crate) struct Outline {
    /// The chart's extent in this turn.
    pub(crate) extent: DVec2,
    /// Each triangle's box `(lo, hi)` in this turn.
    pub(crate) boxes: Vec<(DVec2, DVec2)>,
}

/// `p` turned by `k` quarter turns counter-clockwise inside a box of extent `e` (so the result
/// is again inside `[0, e']`): a rotation, never a mirror.
pub(crate) fn turn(p: DVec2, e: DVec2, k: u8) -> DVec2 {
    match k % 4 {
        0 => p,
        1 => DVec2::new(e.y - p.y, p.x),
        2 => DVec2::new(e.x - p.x, e.y - p.y),
        _ => DVec2::new(p.y, e.x - p.x),
    }
}

impl Outline {
    /// The outline of a chart's triangles (uvs from the origin, extent `e`) turned `k` times.
    pub(crate) fn new(uvs: &[DVec2], triangles: &[[u32; 3]], e: DVec2, k: u8) -> Self {
        let extent = if k % 2 == 1 { DVec2::new(e.y, e.x) } else { e };
        let boxes = triangles
            .iter()
            .filter_map(|t| {
                let [a, b, c] = t.map(|i| uvs.get(i as usize).map(|&p| turn(p, e, k)));
                let (a, b, c) = (a?, b?, c?);
                Some((a.min(b).min(c), a.max(b).max(c)))
            })
            .collect();
        Self { extent, boxes }
    }

    /// Per column at `scale`: the lowest and highest point (`+∞`/`−∞` for an empty column).
    fn profile(&self, scale: f64) -> (Vec<f64>, Vec<f64>) {
        let w = columns(self.extent.x, scale);
        let mut bottom = vec![f64::INFINITY; w];
        let mut top = vec![f64::NEG_INFINITY; w];
        for (lo, hi) in &self.boxes {
            let (lo, hi) = (*lo * scale, *hi * scale);
            let first = (lo.x.floor().max(0.0) as usize).min(w - 1);
            let last = (hi.x.floor().max(0.0) as usize).min(w - 1);
            for c in first..=last {
                bottom[c] = bottom[c].min(lo.y);
                top[c] = top[c].max(hi.y);
            }
        }
        (bottom, top)
    }
}

/// Texel columns a chart of width `x` covers at `scale` (at least 1).
fn columns(x: f64, scale: f64) -> usize {
    let c = (x * scale + MARGIN_TEXELS).ceil();
    if c.is_finite() && c >= 1.0 {
        c.min(f64::from(u32::MAX)) as usize
    } else {
        1
    }
}

/// Where a chart went: its quarter turns and the texel position of its frame's origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Placed {
    pub(crate) turns: u8,
    pub(crate) origin: DVec2,
}

/// Packs the charts (each given by its four turned outlines, in `order`) at `scale` into a
/// `size`-texel square with `padding`, or `None` when one does not fit.
pub(crate) fn try_pack(
    order: &[usize],
    outlines: &[[Outline; 4]],
    scale: f64,
    size: u32,
    padding: u32,
    turns: bool,
) -> Option<Vec<Placed>> {
    let size_f = f64::from(size);
    let p = padding as usize;
    let pf = f64::from(padding);
    let mut horizon = vec![pf; size as usize];
    let mut placed = Vec::with_capacity(order.len());
    for &i in order {
        let mut best: Option<(f64, usize, u8, f64)> = None;
        for k in 0..if turns { 4 } else { 1 } {
            let outline = &outlines[i][k as usize];
            let (bottom, top) = outline.profile(scale);
            let w = bottom.len();
            let highest = top.iter().copied().fold(0.0, f64::max);
            if p + w + p > size as usize {
                continue;
            }
            // Only columns with content constrain the chart.
            let filled: Vec<(usize, f64)> = bottom
                .iter()
                .enumerate()
                .filter(|(_, b)| b.is_finite())
                .map(|(c, &b)| (c, b))
                .collect();
            // Wide charts are tried every `1 + w/64` columns (at most a 1/64 of their width
            // from the best column), which keeps the search near `size × 64` per chart.
            for x in (p..=(size as usize - p - w)).step_by(1 + w / 64) {
                // Lowered until it rests on the horizon; given up as soon as it cannot end
                // lower than the best spot so far.
                let bound = best.map_or(size_f - pf, |b| b.0.min(size_f - pf));
                let mut y = pf;
                let mut hopeless = false;
                for &(c, b) in &filled {
                    y = y.max(horizon[x + c] - b);
                    if y + highest >= bound {
                        hopeless = true;
                        break;
                    }
                }
                if hopeless || y + highest >= bound {
                    continue;
                }
                best = Some((y + highest, x, k, y));
            }
        }
        let (_, x, k, y) = best?;
        let (_, top) = outlines[i][k as usize].profile(scale);
        for (c, &t) in top.iter().enumerate() {
            if !t.is_finite() {
                continue;
            }
            let raised = y + t + pf + MARGIN_TEXELS;
            let from = (x + c).saturating_sub(p);
            let to = (x + c + p).min(size as usize - 1);
            for h in &mut horizon[from..=to] {
                *h = h.max(raised);
            }
        }
        placed.push(Placed {
            turns: k,
            origin: DVec2::new(x as f64, y),
        });
    }
    Some(placed)
}
