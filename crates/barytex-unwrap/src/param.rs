//! The whole pipeline: welding, degenerate triangles, segmentation, one parameterization per
//! chart, exact flip checks, splitting of charts that fail.

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use crate::arap::{ArapReport, arap_refine};
use crate::embed::{BoundaryShape, Embedding, Weights, embed_with_boundary};
use crate::geometry::{flatten, is_degenerate};
use crate::lscm::lscm_with_boundary;
use crate::segment::{bisect, grow_charts};
use crate::sparse::SolveReport;
use crate::topology::{HalfEdgeMesh, NONE, weld_positions};
use crate::{Chart, UnwrapError, UnwrapMesh, chart_stats, check};

/// The parameterization of each chart.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Method {
    /// Tutte's barycentric embedding (uniform weights), boundary on [`ParamOptions::boundary`].
    Tutte,
    /// Floater's mean-value embedding, boundary on [`ParamOptions::boundary`].
    MeanValue,
    /// The harmonic (cotangent-weight) embedding, boundary on [`ParamOptions::boundary`]. Not
    /// guaranteed bijective (negative weights); a chart it flips falls back to mean value.
    Harmonic,
    /// Least squares conformal maps with a free boundary; a chart it flips falls back to mean
    /// value.
    Lscm,
    /// LSCM (or its mean-value fallback), then as-rigid-as-possible refinement that never adds a
    /// flip.
    #[default]
    LscmArap,
}

/// What to do with a non-manifold edge or vertex.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NonManifold {
    /// Cut the surface there: triangles are not joined across a non-manifold edge, and a
    /// non-manifold vertex gets one chart vertex per fan.
    #[default]
    Cut,
    /// Fail with [`UnwrapError::NonManifoldEdge`] or [`UnwrapError::NonManifoldVertex`].
    Reject,
}

/// Options of [`parameterize`].
#[derive(Clone, Debug, PartialEq)]
pub struct ParamOptions {
    /// The parameterization of each chart (default [`Method::LscmArap`]).
    pub method: Method,
    /// The boundary curve of the fixed-boundary methods (default circle).
    pub boundary: BoundaryShape,
    /// Segmentation threshold: a chart's triangle normals stay within this angle, in degrees,
    /// of the chart's mean normal (default 60; in `(0, 180]`). Smaller means more, flatter
    /// charts.
    pub cone_degrees: f64,
    /// A chart whose area-weighted mean angle distortion `σ1/σ2` exceeds this is split in two
    /// (default 1.5; at least 1; infinity never splits). Free-boundary methods only
    /// ([`Method::Lscm`], [`Method::LscmArap`]): a fixed boundary's distortion comes from the
    /// boundary curve, and halves of a chart are pinned to curves again.
    pub max_angle_distortion: f64,
    /// A chart whose area-weighted mean area distortion exceeds this is split in two (default
    /// 3; at least 1). Free-boundary methods only, as above.
    pub max_area_distortion: f64,
    /// ARAP iterations at most (default 20).
    pub max_iterations: u32,
    /// Weld vertices at equal positions before finding the connectivity (default `true`).
    pub weld: bool,
    /// Edges, as pairs of mesh vertices, that must be seams (charts never cross them).
    pub seams: Vec<[u32; 2]>,
    /// Non-manifold edges and vertices (default: cut there).
    pub non_manifold: NonManifold,
}

impl Default for ParamOptions {
    fn default() -> Self {
        Self {
            method: Method::LscmArap,
            boundary: BoundaryShape::Circle,
            cone_degrees: 60.0,
            max_angle_distortion: 1.5,
            max_area_distortion: 3.0,
            max_iterations: 20,
            weld: true,
            seams: Vec::new(),
            non_manifold: NonManifold::Cut,
        }
    }
}

/// How one chart was made.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ChartReport {
    /// The method that produced the chart's uvs (the requested one, or the fallback).
    pub method: Option<Method>,
    /// Whether the requested method flipped a triangle and a fallback was used.
    pub fell_back: bool,
    /// Flips of the requested method before any fallback.
    pub flips_before_fallback: usize,
    /// The linear solve of the embedding (or LSCM).
    pub solve: SolveReport,
    /// The ARAP refinement, for [`Method::LscmArap`].
    pub arap: Option<ArapReport>,
    /// A chart made of one degenerate triangle (zero area or a repeated vertex), laid out as a
    /// right triangle rather than parameterized.
    pub degenerate: bool,
}

/// The charts with a report per chart and counts for the whole mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Parameterization {
    /// The charts.
    pub charts: Vec<Chart>,
    /// One report per chart, in the same order.
    pub reports: Vec<ChartReport>,
    /// Regions split because they were not disks, flipped, or exceeded the distortion limits.
    pub splits: usize,
    /// Edges where the surface was cut because they were non-manifold (each counted once per
    /// half-edge left unjoined).
    pub non_manifold_half_edges: usize,
}

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

fn validate(options: &ParamOptions, vertices: u32) -> Result<(), UnwrapError> {
    if !(options.cone_degrees > 0.0 && options.cone_degrees <= 180.0) {
        return Err(UnwrapError::InvalidOption {
            name: "cone_degrees",
        });
    }
    if options.max_angle_distortion.is_nan() || options.max_angle_distortion < 1.0 {
        return Err(UnwrapError::InvalidOption {
            name: "max_angle_distortion",
        });
    }
    if options.max_area_distortion.is_nan() || options.max_area_distortion < 1.0 {
        return Err(UnwrapError::InvalidOption {
            name: "max_area_distortion",
        });
    }
    for (i, seam) in options.seams.iter().enumerate() {
        if let Some(&index) = seam.iter().find(|&&v| v >= vertices) {
            return Err(UnwrapError::IndexOutOfRange {
                triangle: i as u32,
                index,
                vertices,
            });
        }
    }
    Ok(())
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
    let mut work = grow_charts(&normals, &areas, &usable, &twins, cos_cone);
    let mut out = Parameterization {
        non_manifold_half_edges: non_manifold,
        ..Parameterization::default()
    };
    let mut mark = vec![NONE; f];
    let mut stamp = 0u32;
    let ctx = Context {
        mesh,
        positions: &positions,
        tris: &tris,
        twins: &twins,
        scale,
        options,
    };
    while let Some(region) = work.pop() {
        stamp = stamp.wrapping_add(1);
        for &face in &region {
            mark[face as usize] = stamp;
        }
        match ctx.chart(&region, &mark, stamp)? {
            Some((chart, report)) => {
                out.charts.push(chart);
                out.reports.push(report);
            }
            None => {
                out.splits += 1;
                work.extend(bisect(&region, &twins, &mark, stamp));
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

/// Half-edge twins between usable faces: `twins[3 f + i]` is the half-edge of another usable
/// face running the other way along the same (welded) edge when exactly one such exists, no
/// other face uses the edge, and it is not a seam; [`NONE`] otherwise. Also returns the number
/// of half-edges left unjoined because their edge is non-manifold.
fn join_faces(
    tris: &[[u32; 3]],
    usable: &[bool],
    weld: &[u32],
    seams: &[[u32; 2]],
) -> Result<(Vec<u32>, usize), UnwrapError> {
    let key = |a: u32, b: u32| (u64::from(a) << 32) | u64::from(b);
    let mut keys: Vec<(u64, u32)> =
        crate::alloc::try_vec_with_capacity(3 * tris.len(), "half-edges")?;
    for (t, tri) in tris.iter().enumerate() {
        if usable[t] {
            for i in 0..3 {
                keys.push((key(tri[i], tri[(i + 1) % 3]), (3 * t + i) as u32));
            }
        }
    }
    keys.sort_unstable();
    let mut seam_set = std::collections::HashSet::with_capacity(seams.len());
    for s in seams {
        let (a, b) = (weld[s[0] as usize], weld[s[1] as usize]);
        seam_set.insert(key(a.min(b), a.max(b)));
    }
    let mut twins = vec![NONE; 3 * tris.len()];
    let mut non_manifold = 0;
    let range = |k: u64| {
        let lo = keys.partition_point(|e| e.0 < k);
        let hi = keys.partition_point(|e| e.0 <= k);
        lo..hi
    };
    for &(k, h) in &keys {
        let (a, b) = ((k >> 32) as u32, k as u32);
        let same = range(k);
        let other = range(key(b, a));
        if same.len() == 1 && other.len() == 1 {
            if !seam_set.contains(&key(a.min(b), a.max(b))) {
                twins[h as usize] = keys[other.start].1;
            }
        } else if same.len() > 1 || other.len() > 1 {
            non_manifold += 1;
        }
    }
    Ok((twins, non_manifold))
}

fn mean_edge_length(mesh: &UnwrapMesh) -> f64 {
    let p = mesh.positions();
    let (mut sum, mut count) = (0.0, 0usize);
    for t in mesh.triangles() {
        for i in 0..3 {
            let l = (p[t[i] as usize] - p[t[(i + 1) % 3] as usize]).length();
            if l.is_finite() {
                sum += l;
                count += 1;
            }
        }
    }
    let mean = sum / count.max(1) as f64;
    if mean > 0.0 && mean.is_finite() {
        mean
    } else {
        1.0
    }
}

/// A right triangle with both legs `leg`, clamped so its exact orientation is positive.
fn right_triangle(leg: f64) -> [DVec2; 3] {
    let leg = if leg.is_finite() {
        leg.clamp(1e-100, 1e100)
    } else {
        1.0
    };
    [DVec2::ZERO, DVec2::new(leg, 0.0), DVec2::new(0.0, leg)]
}

fn degenerate_chart(mesh: &UnwrapMesh, face: u32, mean_edge: f64) -> Chart {
    let t = mesh.triangles()[face as usize];
    let p = t.map(|v| mesh.positions()[v as usize]);
    let longest = (0..3)
        .map(|i| (p[i] - p[(i + 1) % 3]).length())
        .fold(0.0f64, f64::max);
    let leg = if longest > 0.0 && longest.is_finite() {
        longest
    } else {
        mean_edge
    };
    Chart {
        faces: vec![face],
        vertices: t.to_vec(),
        triangles: vec![[0, 1, 2]],
        uvs: right_triangle(leg).to_vec(),
    }
}

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
struct Context<'a> {
    mesh: &'a UnwrapMesh,
    /// Positions scaled by `scale`.
    positions: &'a [DVec3],
    /// Welded triangles.
    tris: &'a [[u32; 3]],
    twins: &'a [u32],
    scale: f64,
    options: &'a ParamOptions,
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
    fn chart(
        &self,
        region: &[u32],
        mark: &[u32],
        stamp: u32,
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
                if t == NONE || mark[(t / 3) as usize] != stamp {
                    continue;
                }
                let j = local[&(t / 3)] as usize;
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
