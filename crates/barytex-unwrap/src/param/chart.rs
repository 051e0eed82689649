//! One chart from one region: chart vertices as corner classes, the disk check, the method and its
//! fallbacks, the equal-area scale, the exact flip check and the distortion limits.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use super::degenerate::right_triangle;
use crate::arap::arap_refine;
use crate::embed::{BoundaryShape, Embedding, Weights, embed_with_boundary};
use crate::geometry::flatten;
use crate::lscm::lscm_with_boundary;
use crate::topology::{HalfEdgeMesh, NONE};
use crate::{
    Chart, ChartReport, Method, ParamOptions, UnwrapError, UnwrapMesh, chart_stats, check,
};

/// `uvs` scaled about the origin so the uv area equals the surface area of `triangles` over
/// `pos`, when that keeps every triangle's exact orientation; `uvs` unchanged otherwise.
fn equal_area(pos: &[DVec3], triangles: &[[u32; 3]], uvs: Vec<DVec2>) -> Vec<DVec2> {
    let (mut surface, mut uv_area) = (0.0, 0.0);
    for t in triangles {
        let p = t.map(|v| pos[v as usize]);
        surface += 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).length();
        let q = t.map(|v| uvs[v as usize]);
        uv_area += 0.5 * (q[1] - q[0]).perp_dot(q[2] - q[0]);
    }
    let s = (surface / uv_area).sqrt();
    if !(s.is_finite() && s > 0.0) || s == 1.0 {
        return uvs;
    }
    let scaled: Vec<DVec2> = uvs.iter().map(|&u| u * s).collect();
    if check::count_flips(&scaled, triangles) <= check::count_flips(&uvs, triangles) {
        scaled
    } else {
        uvs
    }
}

/// What every chart needs from the whole mesh.
pub(super) struct Context<'a> {
    pub(super) mesh: &'a UnwrapMesh,
    /// Positions scaled by `scale`.
    pub(super) positions: &'a [DVec3],
    /// Welded triangles.
    pub(super) tris: &'a [[u32; 3]],
    pub(super) twins: &'a [u32],
    pub(super) scale: f64,
    pub(super) options: &'a ParamOptions,
}

/// Smallest region split for distortion alone.
const MIN_FACES_TO_SPLIT: usize = 8;

/// Union-find root with path halving.
fn root(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

impl Context<'_> {
    /// The chart of `region`, or `None` when the region must be split (it is not a disk, still
    /// flips, or is too distorted).
    pub(super) fn chart(
        &self,
        region: &[u32],
    ) -> Result<Option<(Chart, ChartReport)>, UnwrapError> {
        // Chart vertices: corners joined across the region's interior edges.
        let m = region.len();
        let local: HashMap<u32, u32> = region
            .iter()
            .enumerate()
            .map(|(i, &f)| (f, i as u32))
            .collect();
        let mut parent: Vec<u32> = (0..3 * m as u32).collect();
        for (i, &face) in region.iter().enumerate() {
            for k in 0..3 {
                let t = self.twins[3 * face as usize + k];
                let Some(&j) = (t != NONE).then(|| local.get(&(t / 3))).flatten() else {
                    continue;
                };
                let j = j as usize;
                let kt = (t % 3) as usize;
                // This half-edge runs corner k → k+1; its twin runs corner kt → kt+1 the other way.
                let pairs = [
                    (3 * i + k, 3 * j + (kt + 1) % 3),
                    (3 * i + (k + 1) % 3, 3 * j + kt),
                ];
                for (x, y) in pairs {
                    let (rx, ry) = (root(&mut parent, x as u32), root(&mut parent, y as u32));
                    if rx != ry {
                        parent[rx.max(ry) as usize] = rx.min(ry);
                    }
                }
            }
        }
        let mut class = vec![NONE; 3 * m];
        let mut class_vertex: Vec<u32> = Vec::new();
        for c in 0..3 * m {
            let r = root(&mut parent, c as u32) as usize;
            if class[r] == NONE {
                class[r] = class_vertex.len() as u32;
                let face = region[c / 3] as usize;
                class_vertex.push(self.tris[face][c % 3]);
            }
            class[c] = class[r];
        }
        let triangles: Vec<[u32; 3]> = (0..m)
            .map(|i| [class[3 * i], class[3 * i + 1], class[3 * i + 2]])
            .collect();
        let pos: Vec<DVec3> = class_vertex
            .iter()
            .map(|&v| self.positions[v as usize])
            .collect();
        let Ok(he) = HalfEdgeMesh::from_triangles(pos.len() as u32, &triangles) else {
            return Ok(None);
        };
        let Ok(boundary) = he.check_disk() else {
            return Ok(None);
        };
        let (uvs, report) = if m == 1 {
            (
                flatten([pos[0], pos[1], pos[2]]).to_vec(),
                ChartReport::default(),
            )
        } else {
            self.flatten_chart(&pos, &he, &boundary)?
        };
        // Same uv area as surface area (one texel density across charts, whatever the method's
        // own scale: a circle's, two pins'), unless rounding would flip a triangle; then back to
        // surface units (exact: a power of two), then the exact check.
        let uvs = equal_area(&pos, &triangles, uvs);
        let uvs: Vec<DVec2> = uvs.iter().map(|&u| u / self.scale).collect();
        let mut chart = self.expand(region, &class, &triangles, &uvs);
        if check::flipped_triangles(&chart) > 0 {
            if m > 1 {
                return Ok(None);
            }
            // One triangle that rounding degenerated: any positive triangle will do.
            let p = self.mesh.triangles()[region[0] as usize]
                .map(|v| self.mesh.positions()[v as usize]);
            let leg = (0..3)
                .map(|i| (p[i] - p[(i + 1) % 3]).length())
                .fold(0.0, f64::max);
            let rt = right_triangle(leg);
            for tri in &chart.triangles {
                for k in 0..3 {
                    chart.uvs[tri[k] as usize] = rt[k];
                }
            }
        }
        // Only the free-boundary methods gain from smaller charts: a fixed boundary's distortion
        // comes from the circle (or square) itself, and halving a chart leaves two pieces pinned
        // to circles again, each as distorted, so they are never split for distortion.
        let free_boundary = matches!(self.options.method, Method::Lscm | Method::LscmArap);
        if free_boundary && m >= MIN_FACES_TO_SPLIT {
            let s = chart_stats(self.mesh, &chart);
            if s.angle_distortion_mean > self.options.max_angle_distortion
                || s.area_distortion_mean > self.options.max_area_distortion
            {
                return Ok(None);
            }
        }
        Ok(Some((chart, report)))
    }

    /// Chart vertices split by original mesh vertex (welded duplicates keep their own index, so
    /// attributes like normals stay attached), uvs shared within a class.
    fn expand(
        &self,
        region: &[u32],
        class: &[u32],
        triangles: &[[u32; 3]],
        uvs: &[DVec2],
    ) -> Chart {
        let mut index: HashMap<(u32, u32), u32> = HashMap::with_capacity(uvs.len());
        let mut chart = Chart {
            faces: region.to_vec(),
            ..Chart::default()
        };
        for (i, &face) in region.iter().enumerate() {
            let original = self.mesh.triangles()[face as usize];
            let mut tri = [0; 3];
            for k in 0..3 {
                let c = class[3 * i + k];
                debug_assert_eq!(c, triangles[i][k]);
                let next = chart.vertices.len() as u32;
                let v = *index.entry((c, original[k])).or_insert(next);
                if v == next {
                    chart.vertices.push(original[k]);
                    chart.uvs.push(uvs[c as usize]);
                }
                tri[k] = v;
            }
            chart.triangles.push(tri);
        }
        chart
    }

    /// The chart's uvs by the requested method and its fallbacks.
    fn flatten_chart(
        &self,
        pos: &[DVec3],
        he: &HalfEdgeMesh,
        boundary: &[u32],
    ) -> Result<(Vec<DVec2>, ChartReport), UnwrapError> {
        let shape = self.options.boundary;
        let first: Embedding = match self.options.method {
            Method::Tutte => embed_with_boundary(pos, he, boundary, Weights::Uniform, shape)?,
            Method::MeanValue => embed_with_boundary(pos, he, boundary, Weights::MeanValue, shape)?,
            Method::Harmonic => embed_with_boundary(pos, he, boundary, Weights::Cotangent, shape)?,
            Method::Lscm | Method::LscmArap => lscm_with_boundary(pos, he, boundary)?,
        };
        let mut report = ChartReport {
            method: Some(self.options.method),
            solve: first.solve,
            flips_before_fallback: first.flips,
            ..ChartReport::default()
        };
        let mut uvs = first.uvs;
        if first.flips > 0 {
            report.fell_back = true;
            // Mean value on a circle, then Tutte on a circle: bijective in exact arithmetic.
            for (weights, method) in [
                (Weights::MeanValue, Method::MeanValue),
                (Weights::Uniform, Method::Tutte),
            ] {
                let e = embed_with_boundary(pos, he, boundary, weights, BoundaryShape::Circle)?;
                uvs = e.uvs;
                report.method = Some(method);
                report.solve = e.solve;
                if e.flips == 0 {
                    break;
                }
            }
        }
        if self.options.method == Method::LscmArap {
            let arap = arap_refine(pos, he.triangles(), &mut uvs, self.options.max_iterations)?;
            report.arap = Some(arap);
        }
        Ok((uvs, report))
    }
}
