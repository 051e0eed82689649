//! The atlas invariants, checked exactly: every chart triangle counter-clockwise (positive
//! `orient2d`), no two triangles' interiors overlapping (between charts or within one), every uv
//! inside the unit square. Shared by [`unwrap`](crate::unwrap), the tests and the fuzz target.

use glam::DVec2;

use crate::Chart;
use crate::overlap::{OverlapReport, find_overlaps, flipped_triangles};

/// What [`check_atlas`] found. Triangles are named by their mesh triangle
/// ([`Chart::faces`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AtlasCheck {
    /// Chart triangles whose uv orientation is not strictly positive, or with a chart index out
    /// of range or a non-finite uv (mesh triangles).
    pub flipped: Vec<u32>,
    /// Overlapping pairs of mesh triangles, between charts and within a chart.
    pub overlaps: OverlapReport,
    /// Chart vertices with a uv outside `[0, 1]²` (or non-finite).
    pub outside: usize,
    /// Charts whose arrays disagree (`faces` and `triangles` of different lengths, or `uvs` and
    /// `vertices`).
    pub malformed_charts: usize,
}

impl AtlasCheck {
    /// No flip, no overlap, nothing outside the square, no malformed chart.
    #[must_use]
    pub fn is_valid(&self) -> bool {
        self.flipped.is_empty()
            && self.overlaps.is_clean()
            && self.outside == 0
            && self.malformed_charts == 0
    }
}

/// Checks the charts of an atlas (see the module docs); exact, and about linear in the
/// triangle count for a packed atlas.
///
/// ```
/// use barytex_unwrap::{Chart, check_atlas};
/// use glam::DVec2;
///
/// let tri = |x: f64| Chart {
///     faces: vec![x as u32],
///     vertices: vec![0, 1, 2],
///     triangles: vec![[0, 1, 2]],
///     uvs: vec![DVec2::new(x, 0.0), DVec2::new(x + 0.4, 0.0), DVec2::new(x, 0.4)],
/// };
/// assert!(check_atlas(&[tri(0.0), tri(0.5)]).is_valid());
/// let clash = check_atlas(&[tri(0.0), tri(0.2)]);
/// assert_eq!(clash.overlaps.between_charts, [(0, 0)]);
/// ```
#[must_use]
pub fn check_atlas(charts: &[Chart]) -> AtlasCheck {
    let mut check = AtlasCheck::default();
    let mut uvs: Vec<DVec2> = Vec::new();
    let mut triangles: Vec<[u32; 3]> = Vec::new();
    let mut chart_of: Vec<u32> = Vec::new();
    let mut face_of: Vec<u32> = Vec::new();
    for (c, chart) in charts.iter().enumerate() {
        if chart.faces.len() != chart.triangles.len() || chart.uvs.len() != chart.vertices.len() {
            check.malformed_charts += 1;
        }
        check.outside += chart
            .uvs
            .iter()
            .filter(|p| !(p.cmpge(DVec2::ZERO).all() && p.cmple(DVec2::ONE).all()))
            .count();
        let base = uvs.len() as u64;
        for (j, t) in chart.triangles.iter().enumerate() {
            let face = chart.faces.get(j).copied().unwrap_or(u32::MAX);
            let in_range = t.iter().all(|&i| (i as usize) < chart.uvs.len());
            let global = if in_range {
                t.map(|i| u32::try_from(base + u64::from(i)).unwrap_or(u32::MAX))
            } else {
                [u32::MAX; 3]
            };
            triangles.push(global);
            chart_of.push(c as u32);
            face_of.push(face);
        }
        uvs.extend_from_slice(&chart.uvs);
    }
    check.flipped = flipped_triangles(&uvs, &triangles)
        .into_iter()
        .map(|k| face_of[k as usize])
        .collect();
    let mut overlaps = find_overlaps(&uvs, &triangles, &chart_of);
    let name = |pairs: &mut Vec<(u32, u32)>| {
        for pair in pairs.iter_mut() {
            let (a, b) = (face_of[pair.0 as usize], face_of[pair.1 as usize]);
            *pair = (a.min(b), a.max(b));
        }
        pairs.sort_unstable();
    };
    name(&mut overlaps.between_charts);
    name(&mut overlaps.within_charts);
    check.overlaps = overlaps;
    check
}
