//! Charts that overlap themselves, split until they do not.
//!
//! A chart can be free of flipped triangles and still fold over itself at its boundary: a free
//! boundary (LSCM, ARAP) may swing round and cross another part of the same chart. The exact
//! overlap test finds such a chart; it is cut in two across its longest extent on the surface
//! and each half is parameterized again, recursively. A single triangle never overlaps itself,
//! so this ends; each level halves the charts, so it takes at most `log2` of a chart's triangle
//! count levels.

use std::collections::HashMap;

use glam::DVec3;

use crate::overlap::find_overlaps;
use crate::{Chart, ParamOptions, UnwrapError, UnwrapMesh, parameterize};

/// Whether a chart's triangles overlap each other (exactly).
fn overlaps_itself(chart: &Chart) -> bool {
    let same = vec![0u32; chart.triangles.len()];
    !find_overlaps(&chart.uvs, &chart.triangles, &same).is_clean()
}

/// The charts with every self-overlapping one replaced by charts of its halves (see the module
/// docs); also returns how many charts were split.
pub(crate) fn untangle(
    mesh: &UnwrapMesh,
    charts: Vec<Chart>,
    options: &ParamOptions,
) -> Result<(Vec<Chart>, usize), UnwrapError> {
    let mut done = Vec::with_capacity(charts.len());
    let mut pending = charts;
    let mut splits = 0;
    while let Some(chart) = pending.pop() {
        if chart.faces.len() < 2 || !overlaps_itself(&chart) {
            done.push(chart);
            continue;
        }
        splits += 1;
        for half in halves(mesh, &chart.faces) {
            pending.extend(parameterize_faces(mesh, &half, options)?);
        }
    }
    Ok((done, splits))
}

/// The faces split in two at the median of their centroids along the axis of longest extent.
fn halves(mesh: &UnwrapMesh, faces: &[u32]) -> [Vec<u32>; 2] {
    let p = mesh.positions();
    let centroid = |f: u32| {
        let t = mesh.triangles()[f as usize];
        (p[t[0] as usize] + p[t[1] as usize] + p[t[2] as usize]) / 3.0
    };
    let (lo, hi) = faces.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), &f| (lo.min(centroid(f)), hi.max(centroid(f))),
    );
    let extent = hi - lo;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mut sorted = faces.to_vec();
    sorted.sort_by(|&a, &b| {
        centroid(a)[axis]
            .total_cmp(&centroid(b)[axis])
            .then(a.cmp(&b))
    });
    let second = sorted.split_off(sorted.len() / 2);
    [sorted, second]
}

/// `parameterize` on the sub-mesh of `faces`, with the charts named in the whole mesh's faces
/// and vertices.
fn parameterize_faces(
    mesh: &UnwrapMesh,
    faces: &[u32],
    options: &ParamOptions,
) -> Result<Vec<Chart>, UnwrapError> {
    let mut local: HashMap<u32, u32> = HashMap::new();
    let mut vertices: Vec<u32> = Vec::new();
    let mut positions = Vec::new();
    let triangles: Vec<[u32; 3]> = faces
        .iter()
        .map(|&f| {
            mesh.triangles()[f as usize].map(|v| {
                *local.entry(v).or_insert_with(|| {
                    vertices.push(v);
                    positions.push(mesh.positions()[v as usize]);
                    (vertices.len() - 1) as u32
                })
            })
        })
        .collect();
    let sub = UnwrapMesh::new(positions, triangles)?;
    let mut charts = parameterize(&sub, options)?;
    for chart in &mut charts {
        for f in &mut chart.faces {
            *f = faces[*f as usize];
        }
        for v in &mut chart.vertices {
            *v = vertices[*v as usize];
        }
    }
    Ok(charts)
}
