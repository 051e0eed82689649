//! Straighter seams: boundary triangles that stick into a neighbouring chart are handed to it.
//!
//! Region growing ([`super::grow_charts`]) adds triangles one at a time in order of normal
//! deviation, so where two charts meet on a smooth surface the seam zigzags: a triangle of chart
//! A with two of its three edges on chart B is a tooth of A inside B. Each tooth lengthens the
//! seam by an edge, and after flattening each is a spike of the chart's outline, which wastes
//! packing space around it and splits more vertices. This pass moves every such triangle to the
//! chart that surrounds it on two sides (and a lone-triangle chart to the neighbour whose mean
//! normal is nearest), as long as the triangle stays within that chart's normal cone, until no
//! move is left. The idea is the boundary smoothing of Lévy et al., "Least squares conformal
//! maps for automatic texture atlas generation" (SIGGRAPH 2002, §5), and of Sander, Snyder,
//! Gortler, Hoppe, "Texture mapping progressive meshes" (SIGGRAPH 2001, §4.1: straightening
//! chart boundaries).
//!
//! A triangle with at most one edge on its own chart is a leaf of that chart's dual graph, so
//! taking it away keeps the chart connected, and the chart that receives it shares an edge with
//! it; whether each chart is still a disk is checked later, as for every region.

use glam::DVec3;

use super::across;
use crate::topology::NONE;

/// Passes over all triangles at most (each pass moves only triangles that shorten the seams, so
/// the process ends anyway; the cap bounds its time).
const MAX_PASSES: usize = 8;

/// Hands the teeth of `charts` (faces per chart, as [`super::grow_charts`] returns them; `f`
/// faces in all) to the charts around them, when `n · n̄ ≥ cos_cone` for the moved triangle's
/// normal `n` and the receiving chart's mean normal `n̄` (the test region growing makes). Returns the charts left non-empty, in their
/// first order, each one's faces in increasing order.
pub(crate) fn smooth_seams(
    charts: Vec<Vec<u32>>,
    normals: &[DVec3],
    areas: &[f64],
    twins: &[u32],
    cos_cone: f64,
) -> Vec<Vec<u32>> {
    let f = normals.len();
    let mut chart_of = vec![NONE; f];
    let mut sums = vec![DVec3::ZERO; charts.len()];
    let mut sizes = vec![0usize; charts.len()];
    for (c, faces) in charts.iter().enumerate() {
        for &face in faces {
            chart_of[face as usize] = c as u32;
            sums[c] += normals[face as usize] * areas[face as usize];
            sizes[c] += 1;
        }
    }
    for _ in 0..MAX_PASSES {
        let mut moved = false;
        for face in 0..f {
            let own = chart_of[face];
            if own == NONE {
                continue;
            }
            let around = [0, 1, 2].map(|k| {
                let g = across(twins, 3 * face + k);
                if g == NONE {
                    NONE
                } else {
                    chart_of[g as usize]
                }
            });
            let own_edges = around.iter().filter(|&&c| c == own).count();
            let n = normals[face];
            let weighted = n * areas[face];
            let fits = |c: u32| n.dot(sums[c as usize].normalize_or_zero()) >= cos_cone;
            let target = if sizes[own as usize] == 1 {
                // A lone triangle: to the neighbour chart whose mean normal is nearest.
                around
                    .iter()
                    .copied()
                    .filter(|&c| c != NONE && c != own && fits(c))
                    .max_by(|&a, &b| {
                        let d = |c: u32| n.dot(sums[c as usize].normalize_or_zero());
                        d(a).total_cmp(&d(b)).then(b.cmp(&a))
                    })
            } else if own_edges <= 1 {
                // A tooth: two edges on one other chart.
                around.iter().copied().find(|&c| {
                    c != NONE
                        && c != own
                        && around.iter().filter(|&&d| d == c).count() >= 2
                        && fits(c)
                })
            } else {
                None
            };
            if let Some(to) = target {
                chart_of[face] = to;
                sums[own as usize] -= weighted;
                sums[to as usize] += weighted;
                sizes[own as usize] -= 1;
                sizes[to as usize] += 1;
                moved = true;
            }
        }
        if !moved {
            break;
        }
    }
    let mut out = vec![Vec::new(); charts.len()];
    for (face, &c) in chart_of.iter().enumerate() {
        if c != NONE {
            out[c as usize].push(face as u32);
        }
    }
    out.retain(|faces| !faces.is_empty());
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A strip of faces 0..n, face i joined to i ± 1 (half-edge 3i + 0 to the next, 3i + 1 to
    /// the previous).
    fn strip(n: usize) -> Vec<u32> {
        let mut twins = vec![NONE; 3 * n];
        for i in 0..n - 1 {
            twins[3 * i] = (3 * (i + 1) + 1) as u32;
            twins[3 * (i + 1) + 1] = (3 * i) as u32;
        }
        twins
    }

    #[test]
    fn a_lone_triangle_joins_its_nearest_neighbour_within_the_cone() {
        let twins = strip(3);
        let up = DVec3::Z;
        let tilted = DVec3::new(0.0, 0.6, 0.8);
        let normals = [up, tilted, up];
        let charts = vec![vec![0], vec![1], vec![2]];
        // Within a 45° cone the middle triangle (37° off) joins the first chart (ties go to
        // the lower index) ...
        let out = smooth_seams(
            charts.clone(),
            &normals,
            &[1.0; 3],
            &twins,
            45f64.to_radians().cos(),
        );
        assert!(
            out.len() < 3 && out.iter().any(|c| c.contains(&0) && c.contains(&1)),
            "{out:?}"
        );
        // ... and stays alone in a 30° cone.
        let out = smooth_seams(
            charts,
            &normals,
            &[1.0; 3],
            &twins,
            30f64.to_radians().cos(),
        );
        assert_eq!(out, vec![vec![0], vec![1], vec![2]]);
    }

    #[test]
    fn every_face_stays_in_exactly_one_chart() {
        let n = 50;
        let twins = strip(n);
        let normals: Vec<DVec3> = (0..n)
            .map(|i| DVec3::new((i as f64 * 0.7).sin() * 0.3, 0.0, 1.0).normalize())
            .collect();
        let charts: Vec<Vec<u32>> = (0..n as u32).map(|i| vec![i]).collect();
        let out = smooth_seams(charts, &normals, &vec![1.0; n], &twins, 0.9);
        let mut all: Vec<u32> = out.concat();
        all.sort_unstable();
        assert_eq!(all, (0..n as u32).collect::<Vec<_>>());
    }
}
