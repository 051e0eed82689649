//! The whole pipeline: welding, degenerate triangles, segmentation, one parameterization per
//! chart, exact flip checks, splitting of charts that fail.

mod chart;
mod degenerate;
mod join;
mod options;
mod report;

pub use options::{Method, NonManifold, ParamOptions};
pub use report::{ChartReport, Parameterization};

use glam::DVec3;
#[cfg(feature = "parallel")]
use rayon::prelude::*;

use crate::geometry::is_degenerate;
use crate::segment::{bisect, grow_charts, smooth_seams};
use crate::topology::{HalfEdgeMesh, weld_positions};
use crate::{Chart, UnwrapError, UnwrapMesh};
use chart::Context;
use degenerate::{degenerate_chart, mean_edge_length};
use join::join_faces;
use options::validate;

/// Texture coordinates for every triangle of `mesh`, as charts: each a topological disk,
/// flattened with `options.method`, with no flipped triangle (decided exactly, see
/// [`crate::flipped_triangles`]). The uvs are in surface units — each chart scaled so its uv
/// area equals its surface area, so all charts share one texel density — each chart in its own
/// frame: packing them into the unit square is a later step.
///
/// Every mesh triangle belongs to exactly one chart. Degenerate triangles (a repeated vertex, or
/// zero area: doubled area below `1e-12 ×` longest edge²) each get a chart of their own, a right
/// triangle whose legs are the triangle's longest edge (or the mesh's mean edge length).
///
/// A chart that is not a disk, that still flips after the fallbacks, or that is more distorted
/// than the options allow is split in two and both halves are done again; a single triangle is
/// always a disk and always lays out flat, so this ends, with zero flips.
///
/// ```
/// use barytex_unwrap::{ParamOptions, UnwrapMesh, flipped_triangles, parameterize};
/// use glam::DVec3;
///
/// // An open box: five faces of a cube.
/// let p: Vec<DVec3> = (0..8)
///     .map(|i| DVec3::new((i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64))
///     .collect();
/// let t = vec![
///     [0, 2, 1], [1, 2, 3], [0, 1, 5], [0, 5, 4], [1, 3, 7], [1, 7, 5],
///     [3, 2, 6], [3, 6, 7], [2, 0, 4], [2, 4, 6],
/// ];
/// let mesh = UnwrapMesh::new(p, t).expect("valid");
/// let charts = parameterize(&mesh, &ParamOptions::default()).expect("unwrapped");
/// assert_eq!(charts.iter().map(|c| c.faces.len()).sum::<usize>(), 10);
/// assert!(charts.iter().all(|c| flipped_triangles(c) == 0));
/// ```
///
/// # Accuracy
/// Exact where it matters: every returned triangle is positively oriented by Shewchuk's exact
/// `orient2d` (tests `param.rs::closed_meshes_become_disks_without_flips`,
/// `random_soups_never_flip`, the fixture test on Suzanne and the `unwrap_param` fuzz target).
/// Distortion is bounded by the options for the free-boundary methods: every chart of 8 or more
/// triangles has mean angle distortion `≤ max_angle_distortion` and mean area distortion
/// `≤ max_area_distortion` ([`crate::chart_stats`]); a flat piece (a cube face) comes back
/// isometric within `1e-9` (`param.rs::a_cube_splits_along_its_creases`).
///
/// # Errors
/// [`UnwrapError::InvalidOption`] for an option out of range;
/// [`UnwrapError::NonManifoldEdge`] / [`UnwrapError::NonManifoldVertex`] under
/// [`NonManifold::Reject`]; [`UnwrapError::IndexOutOfRange`] for a seam naming a missing
/// vertex; [`UnwrapError::OutOfMemory`].
pub fn parameterize(mesh: &UnwrapMesh, options: &ParamOptions) -> Result<Vec<Chart>, UnwrapError> {
    parameterize_with_report(mesh, options).map(|p| p.charts)
}

/// What became of one region in a round of [`parameterize_with_report`].
enum Outcome {
    /// A chart and its report.
    Chart((Chart, ChartReport)),
    /// The region split in two, for the next round.
    Split(Vec<Vec<u32>>),
}

/// The power of two that brings the mesh's extent near 1, so squares of coordinates neither
/// overflow nor underflow; scaling by it (and back) is exact.
fn power_of_two_scale(positions: &[DVec3]) -> f64 {
    let extent = positions
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0f64, f64::max);
    if !(extent > 0.0 && extent.is_finite()) {
        return 1.0;
    }
    let e = extent.log2().floor().clamp(-1000.0, 1000.0) as i32;
    2f64.powi(-e)
}

/// [`parameterize`], with a report per chart.
///
/// # Errors
/// As [`parameterize`].
pub fn parameterize_with_report(
    mesh: &UnwrapMesh,
    options: &ParamOptions,
) -> Result<Parameterization, UnwrapError> {
    let n = mesh.positions().len() as u32;
    validate(options, n)?;
    let scale = power_of_two_scale(mesh.positions());
    let positions: Vec<DVec3> = mesh.positions().iter().map(|&p| p * scale).collect();
    let weld: Vec<u32> = if options.weld {
        weld_positions(mesh.positions())
    } else {
        (0..n).collect()
    };
    let tris: Vec<[u32; 3]> = mesh
        .triangles()
        .iter()
        .map(|t| t.map(|v| weld[v as usize]))
        .collect();
    let f = tris.len();
    let usable: Vec<bool> = tris
        .iter()
        .map(|t| {
            t[0] != t[1]
                && t[1] != t[2]
                && t[2] != t[0]
                && !is_degenerate(t.map(|v| positions[v as usize]))
        })
        .collect();
    if options.non_manifold == NonManifold::Reject {
        let good: Vec<[u32; 3]> = (0..f).filter(|&i| usable[i]).map(|i| tris[i]).collect();
        HalfEdgeMesh::from_triangles(n, &good)?;
    }
    let (twins, non_manifold) = join_faces(&tris, &usable, &weld, &options.seams)?;
    let (normals, areas): (Vec<DVec3>, Vec<f64>) = tris
        .iter()
        .map(|t| {
            let p = t.map(|v| positions[v as usize]);
            let c = (p[1] - p[0]).cross(p[2] - p[0]);
            (c.normalize_or_zero(), 0.5 * c.length())
        })
        .unzip();
    let cos_cone = options.cone_degrees.to_radians().cos();
    let grown = grow_charts(&normals, &areas, &usable, &twins, cos_cone);
    let mut work = smooth_seams(grown, &normals, &areas, &twins, cos_cone);
    let mut out = Parameterization {
        non_manifold_half_edges: non_manifold,
        ..Parameterization::default()
    };
    let ctx = Context {
        mesh,
        positions: &positions,
        tris: &tris,
        twins: &twins,
        scale,
        options,
    };
    // Regions are independent: each round flattens all of them in parallel, and the ones that
    // fail are split for the next round. The results keep the regions' order, so the charts do
    // not depend on the number of threads.
    while !work.is_empty() {
        #[cfg(feature = "parallel")]
        let regions = work.par_iter();
        #[cfg(not(feature = "parallel"))]
        let regions = work.iter();
        let done: Vec<Result<Outcome, UnwrapError>> = regions
            .map(|region| {
                Ok(match ctx.chart(region)? {
                    Some(chart) => Outcome::Chart(chart),
                    None => Outcome::Split(bisect(region, &twins)),
                })
            })
            .collect();
        work = Vec::new();
        for outcome in done {
            match outcome? {
                Outcome::Chart((chart, report)) => {
                    out.charts.push(chart);
                    out.reports.push(report);
                }
                Outcome::Split(parts) => {
                    out.splits += 1;
                    work.extend(parts);
                }
            }
        }
    }
    let mean_edge = mean_edge_length(mesh);
    for face in (0..f).filter(|&i| !usable[i]) {
        out.charts
            .push(degenerate_chart(mesh, face as u32, mean_edge));
        out.reports.push(ChartReport {
            degenerate: true,
            ..ChartReport::default()
        });
    }
    Ok(out)
}
