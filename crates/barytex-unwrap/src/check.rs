//! Exact flip checks.

use glam::DVec2;
use robust::{Coord, orient2d};

use crate::Chart;

/// Whether the uv triangle is counter-clockwise, decided exactly (Shewchuk's adaptive
/// `orient2d`): `false` for a clockwise (flipped), degenerate (zero-area) or non-finite one.
#[must_use]
pub fn is_positively_oriented(uv: [DVec2; 3]) -> bool {
    if !uv.iter().all(|p| p.is_finite()) {
        return false;
    }
    let c = |p: DVec2| Coord { x: p.x, y: p.y };
    orient2d(c(uv[0]), c(uv[1]), c(uv[2])) > 0.0
}

/// The number of triangles of `triangles` over `uvs` that are not positively oriented
/// ([`is_positively_oriented`]).
pub(crate) fn count_flips(uvs: &[DVec2], triangles: &[[u32; 3]]) -> usize {
    triangles
        .iter()
        .filter(|t| !is_positively_oriented(t.map(|v| uvs[v as usize])))
        .count()
}

/// The number of the chart's triangles whose uv triangle is flipped, degenerate or non-finite,
/// decided exactly ([`is_positively_oriented`]). Triangles naming a chart vertex that does not
/// exist count as flipped too.
///
/// ```
/// use barytex_unwrap::{Chart, flipped_triangles};
/// use glam::DVec2;
///
/// let mut chart = Chart {
///     faces: vec![0],
///     vertices: vec![0, 1, 2],
///     triangles: vec![[0, 1, 2]],
///     uvs: vec![DVec2::ZERO, DVec2::X, DVec2::Y],
/// };
/// assert_eq!(flipped_triangles(&chart), 0);
/// chart.uvs.swap(1, 2);
/// assert_eq!(flipped_triangles(&chart), 1);
/// ```
#[must_use]
pub fn flipped_triangles(chart: &Chart) -> usize {
    chart
        .triangles
        .iter()
        .filter(|t| {
            let uv = t.map(|v| chart.uvs.get(v as usize).copied().unwrap_or(DVec2::NAN));
            !is_positively_oriented(uv)
        })
        .count()
}
