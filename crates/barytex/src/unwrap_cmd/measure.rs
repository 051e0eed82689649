//! The figures of a uv layout, measured the same way for ours and for a peer's (xatlas through
//! `--compare-uvs`): charts (connected pieces), flips, overlaps (exact), texture coverage and
//! distortion (barytex-uv's definitions).

use barytex_unwrap::overlap::{find_overlaps, orient};
use barytex_uv::distortion::MeshDistortion;
use barytex_uv::mesh::TriMesh;
use glam::{DVec2, Vec2, Vec3, Vec4};

/// A layout's figures.
#[derive(Clone, Debug)]
pub(crate) struct LayoutStats {
    /// Triangles measured.
    pub(crate) triangles: usize,
    /// Connected pieces (triangles sharing a uv vertex are in one chart).
    pub(crate) charts: usize,
    /// Per chart, the triangles against its majority orientation, plus every zero-area one.
    pub(crate) flips: usize,
    /// Overlapping triangle pairs of different charts.
    pub(crate) overlaps_between: usize,
    /// Overlapping triangle pairs within a chart.
    pub(crate) overlaps_within: usize,
    /// uv vertices outside the unit square.
    pub(crate) outside: usize,
    /// Total uv triangle area (the part of the unit square the surface covers).
    pub(crate) efficiency: f64,
    /// Angle and area distortion, `None` when nothing could be measured.
    pub(crate) distortion: Option<MeshDistortion>,
}

fn find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let up = parent[parent[i as usize] as usize];
        parent[i as usize] = up;
        i = up;
    }
    i
}

/// Measures a layout: `positions[i]` and `uvs[i]` are uv vertex `i`; triangles index both.
/// Triangles naming a vertex out of range are left out.
pub(crate) fn measure(positions: &[Vec3], uvs: &[DVec2], triangles: &[[u32; 3]]) -> LayoutStats {
    let n = positions.len().min(uvs.len());
    let triangles: Vec<[u32; 3]> = triangles
        .iter()
        .copied()
        .filter(|t| t.iter().all(|&i| (i as usize) < n))
        .collect();
    let mut parent: Vec<u32> = (0..n as u32).collect();
    for t in &triangles {
        let r = find(&mut parent, t[0]);
        for &v in &t[1..] {
            let s = find(&mut parent, v);
            parent[s as usize] = r;
        }
    }
    let mut chart_id = vec![u32::MAX; n];
    let mut charts = 0u32;
    let chart_of: Vec<u32> = triangles
        .iter()
        .map(|t| {
            let root = find(&mut parent, t[0]) as usize;
            if chart_id[root] == u32::MAX {
                chart_id[root] = charts;
                charts += 1;
            }
            chart_id[root]
        })
        .collect();
    // Orientation counts per chart: (positive, negative, zero).
    let mut signs = vec![(0usize, 0usize, 0usize); charts as usize];
    let mut efficiency = 0.0;
    for (t, &c) in triangles.iter().zip(&chart_of) {
        let [a, b, d] = t.map(|i| uvs[i as usize]);
        let o = orient(a, b, d);
        let s = &mut signs[c as usize];
        if o > 0.0 {
            s.0 += 1;
        } else if o < 0.0 {
            s.1 += 1;
        } else {
            s.2 += 1;
        }
        efficiency += (b - a).perp_dot(d - a).abs() / 2.0;
    }
    let flips = signs.iter().map(|s| s.0.min(s.1) + s.2).sum();
    let overlaps = find_overlaps(uvs, &triangles, &chart_of);
    let outside = uvs[..n]
        .iter()
        .filter(|p| !(p.cmpge(DVec2::ZERO).all() && p.cmple(DVec2::ONE).all()))
        .count();
    let mesh = TriMesh {
        positions: positions[..n].to_vec(),
        normals: vec![Vec3::Z; n],
        tangents: vec![Vec4::X; n],
        uvs: uvs[..n].iter().map(|p| p.as_vec2()).collect::<Vec<Vec2>>(),
        indices: triangles.clone(),
    };
    LayoutStats {
        triangles: triangles.len(),
        charts: charts as usize,
        flips,
        overlaps_between: overlaps.between_charts.len(),
        overlaps_within: overlaps.within_charts.len(),
        outside,
        efficiency,
        distortion: MeshDistortion::of(&mesh),
    }
}

impl LayoutStats {
    /// The figures as one JSON object (for tools/xatlas_unwrap.py).
    pub(crate) fn to_json(&self) -> serde_json::Value {
        let d = self.distortion;
        // JSON has no infinity: a degenerate uv triangle's distortion is written "inf".
        let num = |x: Option<f64>| match x {
            Some(v) if v.is_finite() => serde_json::json!(v),
            Some(_) => serde_json::json!("inf"),
            None => serde_json::Value::Null,
        };
        serde_json::json!({
            "triangles": self.triangles,
            "charts": self.charts,
            "flips": self.flips,
            "overlaps_between_charts": self.overlaps_between,
            "overlaps_within_charts": self.overlaps_within,
            "outside": self.outside,
            "efficiency": self.efficiency,
            "angle_mean": num(d.map(|d| d.angle_mean)),
            "angle_max": num(d.map(|d| d.angle_max)),
            "area_mean": num(d.map(|d| d.area_mean)),
            "area_max": num(d.map(|d| d.area_max)),
        })
    }

    /// The figures as lines of text.
    pub(crate) fn lines(&self) -> Vec<String> {
        let mut lines = vec![
            format!(
                "charts {}, triangles {}, flips {}, overlapping triangle pairs {} between charts and {} within, uvs outside the square {}",
                self.charts,
                self.triangles,
                self.flips,
                self.overlaps_between,
                self.overlaps_within,
                self.outside
            ),
            format!(
                "packing efficiency {:.1}% (uv area of the triangles over the unit square)",
                100.0 * self.efficiency
            ),
        ];
        if let Some(d) = self.distortion {
            lines.push(format!(
                "distortion (area-weighted mean / max): angle {:.4} / {:.3}, area {:.4} / {:.3}",
                d.angle_mean, d.angle_max, d.area_mean, d.area_max
            ));
        }
        lines
    }
}
