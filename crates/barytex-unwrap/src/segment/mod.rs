//! Segmentation of a surface into charts: region growing by normal deviation, and bisection of
//! a region that is not a disk or is too distorted.
//!
//! Region growing follows the idea of Lévy et al. 2002 (§5, "Segmentation") and of Sander,
//! Wood, Gortler, Snyder, Hoppe ("Multi-chart geometry images", SGP 2003): a chart grows
//! best-first from a flat seed while its triangles stay inside a cone of normals around the
//! chart's mean normal. Charts therefore stop at creases (a dihedral angle beyond the cone is
//! never crossed smoothly) — the seams run along high-curvature edges — and a chart whose normals
//! fit in a cone of half-angle below 90° is a height field over its mean plane, the easy case for
//! a conformal map.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use glam::DVec3;

use crate::topology::NONE;

mod smooth;
pub(crate) use smooth::smooth_seams;

/// The face across half-edge `h`'s edge, or [`NONE`].
fn across(twins: &[u32], h: usize) -> u32 {
    let t = twins[h];
    if t == NONE { NONE } else { t / 3 }
}

/// Grows charts over the faces with `usable[f]`, joined across `twins` (a global half-edge
/// table, [`NONE`] where faces are not joined), keeping each chart's normals within the cone
/// `n · n̄ ≥ cos_cone` of its area-weighted mean normal `n̄`.
pub(crate) fn grow_charts(
    normals: &[DVec3],
    areas: &[f64],
    usable: &[bool],
    twins: &[u32],
    cos_cone: f64,
) -> Vec<Vec<u32>> {
    let f = normals.len();
    // Seeds: flattest faces first (smallest normal change to a neighbour).
    let mut order: Vec<(u64, u32)> = (0..f)
        .filter(|&i| usable[i])
        .map(|i| {
            let bend = (0..3)
                .map(|k| across(twins, 3 * i + k))
                .filter(|&g| g != NONE)
                .map(|g| 1.0 - normals[i].dot(normals[g as usize]))
                .fold(0.0f64, f64::max)
                .max(0.0);
            (bend.to_bits(), i as u32)
        })
        .collect();
    order.sort_unstable();
    let mut chart_of = vec![NONE; f];
    let mut charts = Vec::new();
    let mut heap = BinaryHeap::new();
    for &(_, seed) in &order {
        if chart_of[seed as usize] != NONE {
            continue;
        }
        let id = charts.len() as u32;
        let mut faces = vec![seed];
        chart_of[seed as usize] = id;
        let mut sum = normals[seed as usize] * areas[seed as usize];
        heap.clear();
        let push = |heap: &mut BinaryHeap<_>, face: u32, sum: DVec3, chart_of: &[u32]| {
            for k in 0..3 {
                let g = across(twins, 3 * face as usize + k);
                if g != NONE && chart_of[g as usize] == NONE {
                    let cost = (1.0 - normals[g as usize].dot(sum.normalize_or_zero())).max(0.0);
                    heap.push(Reverse((cost.to_bits(), g)));
                }
            }
        };
        push(&mut heap, seed, sum, &chart_of);
        while let Some(Reverse((_, g))) = heap.pop() {
            if chart_of[g as usize] != NONE {
                continue;
            }
            let n = normals[g as usize];
            if n.dot(sum.normalize_or_zero()) < cos_cone {
                continue;
            }
            chart_of[g as usize] = id;
            faces.push(g);
            sum += n * areas[g as usize];
            push(&mut heap, g, sum, &chart_of);
        }
        charts.push(faces);
    }
    charts
}

/// Splits the region `faces` (non-empty, each face once) in two: the faces
/// connected to the first face and the rest when it is disconnected, otherwise the two halves
/// nearer (in dual-graph steps) to each of two far-apart faces found by a double breadth-first
/// sweep. Each part is connected (a breadth-first tree) and non-empty for two or more faces.
pub(crate) fn bisect(faces: &[u32], twins: &[u32]) -> Vec<Vec<u32>> {
    let inside: std::collections::HashSet<u32> = faces.iter().copied().collect();
    let bfs = |sources: &[u32]| -> Vec<(u32, u32)> {
        // (face, source label) in visiting order.
        let mut seen = std::collections::HashMap::with_capacity(faces.len());
        let mut queue = std::collections::VecDeque::new();
        for (label, &s) in sources.iter().enumerate() {
            if seen.insert(s, label as u32).is_none() {
                queue.push_back(s);
            }
        }
        let mut order = Vec::with_capacity(faces.len());
        while let Some(face) = queue.pop_front() {
            let label = seen[&face];
            order.push((face, label));
            for k in 0..3 {
                let g = across(twins, 3 * face as usize + k);
                if g != NONE && inside.contains(&g) && !seen.contains_key(&g) {
                    seen.insert(g, label);
                    queue.push_back(g);
                }
            }
        }
        order
    };
    let first = bfs(&faces[..1]);
    if first.len() < faces.len() {
        let reached: std::collections::HashSet<u32> = first.iter().map(|&(f, _)| f).collect();
        let rest = faces
            .iter()
            .copied()
            .filter(|f| !reached.contains(f))
            .collect();
        return vec![first.into_iter().map(|(f, _)| f).collect(), rest];
    }
    let a = first.last().map_or(faces[0], |&(f, _)| f);
    let b = bfs(&[a]).last().map_or(a, |&(f, _)| f);
    let mut parts = vec![Vec::new(), Vec::new()];
    for (face, label) in bfs(&[a, b]) {
        parts[label as usize].push(face);
    }
    parts.retain(|p| !p.is_empty());
    parts
}
