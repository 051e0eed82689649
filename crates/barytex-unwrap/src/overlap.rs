//! Exact overlap checks on a uv layout: which triangles' interiors intersect, and which are
//! flipped (zero or negative orientation), decided by Shewchuk's exact `orient2d`.
//!
//! Two triangles' interiors are disjoint exactly when one edge line of one of them has the other
//! triangle in its closed outer half-plane. This is the separating-axis theorem for convex
//! polygons (Gottschalk, Lin, Manocha, "OBBTree", SIGGRAPH 1996, §4; for polygons the candidate
//! axes are the edge normals): the Minkowski difference `A − B` is a convex polygon whose edges
//! are the edges of `A` and of `−B`, and the origin lies outside its interior exactly when it is
//! on the closed outer side of one of those edge lines — which, for an edge of `A` with outward
//! normal `n`, says `min n·b ≥ max n·a` over `B`, i.e. `B` is beyond that edge's line. Each such
//! test is a sign of `orient2d`, so the answer is exact for any f64 coordinates: touching
//! triangles (a shared edge or vertex) never count as overlapping, and a sliver overlap of one
//! ulp is found.
//!
//! A uniform grid over the layout's bounding box pairs only triangles whose bounding boxes
//! share a cell, so a packed atlas is checked in about linear time, not by testing all
//! `n(n − 1)/2` pairs.

use glam::DVec2;

/// `orient2d(a, b, c)`: positive when `a, b, c` turn counter-clockwise, negative clockwise,
/// zero when collinear — exactly (Shewchuk's adaptive predicate).
#[must_use]
pub fn orient(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    robust::orient2d(
        robust::Coord { x: a.x, y: a.y },
        robust::Coord { x: b.x, y: b.y },
        robust::Coord { x: c.x, y: c.y },
    )
}

/// Whether the interiors of two triangles intersect, decided exactly. Corners may come in
/// either order (a clockwise triangle is turned around first); a degenerate triangle (zero
/// area, or a non-finite corner) has no interior and overlaps nothing.
///
/// ```
/// use barytex_unwrap::overlap::triangles_overlap;
/// use glam::DVec2;
///
/// let a = [DVec2::ZERO, DVec2::X, DVec2::Y];
/// // Sharing the edge from (1, 0) to (0, 1): touching, not overlapping.
/// assert!(!triangles_overlap(a, [DVec2::X, DVec2::ONE, DVec2::Y]));
/// // Pushed one ulp across that edge: overlapping.
/// let x = 1.0 - f64::EPSILON / 2.0;
/// assert!(triangles_overlap(a, [DVec2::new(x, 0.0), DVec2::ONE, DVec2::new(0.0, x)]));
/// ```
#[must_use]
pub fn triangles_overlap(a: [DVec2; 3], b: [DVec2; 3]) -> bool {
    let (Some(a), Some(b)) = (counter_clockwise(a), counter_clockwise(b)) else {
        return false;
    };
    !(separates(&a, &b) || separates(&b, &a))
}

/// The triangle counter-clockwise, or `None` when it is degenerate or not finite.
fn counter_clockwise(t: [DVec2; 3]) -> Option<[DVec2; 3]> {
    if !t.iter().all(|p| p.is_finite()) {
        return None;
    }
    let o = orient(t[0], t[1], t[2]);
    if o > 0.0 {
        Some(t)
    } else if o < 0.0 {
        Some([t[0], t[2], t[1]])
    } else {
        None
    }
}

/// Whether an edge line of the counter-clockwise `a` has all of `b` on its closed outer side.
fn separates(a: &[DVec2; 3], b: &[DVec2; 3]) -> bool {
    (0..3).any(|i| {
        let (p, q) = (a[i], a[(i + 1) % 3]);
        b.iter().all(|&c| orient(p, q, c) <= 0.0)
    })
}

/// How a layout's triangles overlap: pairs of triangles whose interiors intersect, told apart
/// by whether they belong to the same chart.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct OverlapReport {
    /// Overlapping pairs `(i, j)`, `i < j`, of triangles in different charts.
    pub between_charts: Vec<(u32, u32)>,
    /// Overlapping pairs `(i, j)`, `i < j`, of triangles in the same chart (a chart that folds
    /// over itself at its boundary, which a flip-free chart can still do).
    pub within_charts: Vec<(u32, u32)>,
    /// Pairs of triangles whose bounding boxes met and were tested exactly.
    pub pairs_tested: u64,
}

impl OverlapReport {
    /// No two triangles overlap.
    #[must_use]
    pub fn is_clean(&self) -> bool {
        self.between_charts.is_empty() && self.within_charts.is_empty()
    }
}

/// The most grid cells [`find_overlaps`] uses along a side (bounds its memory).
const MAX_GRID_SIDE: usize = 2048;

/// Finds every pair of triangles of a uv layout whose interiors overlap, exactly.
///
/// `triangles[k]` indexes `uvs`; `chart_of[k]` is triangle `k`'s chart (any labels: only
/// equality matters). Triangles with an index out of range, a non-finite corner or zero area
/// have no interior and are never reported (count them as flips with [`flipped_triangles`]).
/// The answer is exact; its cost is about linear for a packed atlas (a uniform grid of about one
/// triangle per cell), and quadratic only where many triangles' bounding boxes share cells.
///
/// # Panics
/// Never; mismatched lengths are read as far as both go.
///
/// ```
/// use barytex_unwrap::overlap::find_overlaps;
/// use glam::DVec2;
///
/// let uvs = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::new(0.2, 0.2), DVec2::new(2.0, 0.2), DVec2::new(0.2, 2.0)];
/// let report = find_overlaps(&uvs, &[[0, 1, 2], [3, 4, 5]], &[0, 1]);
/// assert_eq!(report.between_charts, [(0, 1)]);
/// ```
#[must_use]
pub fn find_overlaps(uvs: &[DVec2], triangles: &[[u32; 3]], chart_of: &[u32]) -> OverlapReport {
    let n = triangles.len().min(chart_of.len());
    // Each usable triangle with its bounding box.
    let mut boxes: Vec<(u32, DVec2, DVec2, [DVec2; 3])> = Vec::with_capacity(n);
    for (k, t) in triangles.iter().take(n).enumerate() {
        let corners = t.map(|i| uvs.get(i as usize).copied());
        let [Some(a), Some(b), Some(c)] = corners else {
            continue;
        };
        let tri = [a, b, c];
        if counter_clockwise(tri).is_none() {
            continue;
        }
        let lo = a.min(b).min(c);
        let hi = a.max(b).max(c);
        boxes.push((k as u32, lo, hi, tri));
    }
    let mut report = OverlapReport::default();
    if boxes.len() < 2 {
        return report;
    }
    let (mut lo, mut hi) = (boxes[0].1, boxes[0].2);
    for b in &boxes {
        lo = lo.min(b.1);
        hi = hi.max(b.2);
    }
    let extent = (hi - lo).max(DVec2::splat(f64::MIN_POSITIVE));
    // About one triangle per cell; fewer cells while long triangles would fill too many (the
    // memory stays within a fixed multiple of the triangle count).
    let mut side = ((boxes.len() as f64).sqrt().ceil() as usize).clamp(1, MAX_GRID_SIDE);
    let budget = 16 * boxes.len() as u64;
    let ranges = loop {
        let ranges: Vec<((usize, usize), (usize, usize))> = boxes
            .iter()
            .map(|b| {
                (
                    grid_cell(b.1, lo, extent, side),
                    grid_cell(b.2, lo, extent, side),
                )
            })
            .collect();
        let entries: u64 = ranges
            .iter()
            .map(|&((x0, y0), (x1, y1))| ((x1 - x0 + 1) * (y1 - y0 + 1)) as u64)
            .sum();
        if side == 1 || entries <= budget {
            break ranges;
        }
        side /= 2;
    };
    let cell_of = |p: DVec2| grid_cell(p, lo, extent, side);
    // Bucket the triangles by cell (a CSR layout: count, prefix sums, fill).
    let mut counts = vec![0usize; side * side + 1];
    for &((x0, y0), (x1, y1)) in &ranges {
        for y in y0..=y1 {
            for x in x0..=x1 {
                counts[y * side + x + 1] += 1;
            }
        }
    }
    for i in 1..counts.len() {
        counts[i] += counts[i - 1];
    }
    let mut fill = counts.clone();
    let mut cells = vec![0u32; counts[side * side]];
    for (slot, &((x0, y0), (x1, y1))) in ranges.iter().enumerate() {
        for y in y0..=y1 {
            for x in x0..=x1 {
                cells[fill[y * side + x]] = slot as u32;
                fill[y * side + x] += 1;
            }
        }
    }
    for y in 0..side {
        for x in 0..side {
            let members = &cells[counts[y * side + x]..counts[y * side + x + 1]];
            for (i, &si) in members.iter().enumerate() {
                for &sj in &members[i + 1..] {
                    let (a, b) = (&boxes[si as usize], &boxes[sj as usize]);
                    let lo_both = a.1.max(b.1);
                    let hi_both = a.2.min(b.2);
                    if lo_both.x > hi_both.x || lo_both.y > hi_both.y {
                        continue;
                    }
                    // Test each pair once: in the cell holding the corner of the boxes'
                    // intersection.
                    if cell_of(lo_both) != (x, y) {
                        continue;
                    }
                    report.pairs_tested += 1;
                    if triangles_overlap(a.3, b.3) {
                        let pair = (a.0.min(b.0), a.0.max(b.0));
                        if chart_of[a.0 as usize] == chart_of[b.0 as usize] {
                            report.within_charts.push(pair);
                        } else {
                            report.between_charts.push(pair);
                        }
                    }
                }
            }
        }
    }
    report.between_charts.sort_unstable();
    report.within_charts.sort_unstable();
    report
}

/// The cell of `p` in a `side × side` grid over the box from `lo` of size `extent`.
fn grid_cell(p: DVec2, lo: DVec2, extent: DVec2, side: usize) -> (usize, usize) {
    let c = ((p - lo) / extent * side as f64).floor();
    let clamp = |v: f64| {
        if v.is_nan() || v < 0.0 {
            0
        } else {
            (v as usize).min(side - 1)
        }
    };
    (clamp(c.x), clamp(c.y))
}

/// The triangles (indices into `triangles`) whose uv orientation is not strictly positive
/// (counter-clockwise), decided exactly; a triangle with an index out of range or a non-finite
/// corner counts as flipped too.
///
/// ```
/// use barytex_unwrap::overlap::flipped_triangles;
/// use glam::DVec2;
///
/// let uvs = [DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::new(2.0, 0.0)];
/// // Counter-clockwise, clockwise, collinear.
/// assert_eq!(flipped_triangles(&uvs, &[[0, 1, 2], [0, 2, 1], [0, 1, 3]]), [1, 2]);
/// ```
#[must_use]
pub fn flipped_triangles(uvs: &[DVec2], triangles: &[[u32; 3]]) -> Vec<u32> {
    triangles
        .iter()
        .enumerate()
        .filter(|(_, t)| {
            let c = t.map(|i| uvs.get(i as usize).copied());
            match c {
                [Some(a), Some(b), Some(c)] => {
                    !(a.is_finite() && b.is_finite() && c.is_finite()) || orient(a, b, c) <= 0.0
                }
                _ => true,
            }
        })
        .map(|(k, _)| k as u32)
        .collect()
}
