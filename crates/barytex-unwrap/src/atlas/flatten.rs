//! Charts of one or two triangles, laid flat without distortion: each triangle keeps its edge
//! lengths and angles (an isometry), and a pair is unfolded about its shared edge.
//!
//! These are the charts of [`ChartMethod::PerTriangle`](super::ChartMethod::PerTriangle) and
//! [`ChartMethod::TrianglePairs`](super::ChartMethod::TrianglePairs): no distortion at all, at the price of
//! a seam along every chart edge. They suit lightmaps and baking, where a texel per surface
//! patch matters more than continuity (the per-triangle layouts of lightmappers).

use std::collections::HashMap;

use glam::{DVec2, DVec3};

use crate::{Chart, UnwrapMesh};

/// The smallest height over base a flattened triangle gets, relative to its longest edge. A
/// thinner (or zero-area) surface triangle is widened to it, so that its uv triangle keeps a
/// positive orientation after packing and rounding to f32; such a triangle is the only one
/// whose shape these charts change.
pub const MIN_ASPECT: f64 = 1.0 / 1024.0;

/// The corners of a triangle laid flat: `a` at the origin, `b` on the positive x axis, `c`
/// above it (counter-clockwise), with `|ab|` and `c`'s projection kept; a height under
/// [`MIN_ASPECT`]` · |ab|` is raised to it, and a zero-length `ab` becomes a unit-less right
/// triangle of side `fallback`.
fn lay_flat(a: DVec3, b: DVec3, c: DVec3, fallback: f64) -> [DVec2; 3] {
    let base = b - a;
    let length = base.length();
    if length.is_nan() || length <= 0.0 {
        let s = fallback;
        return [DVec2::ZERO, DVec2::new(s, 0.0), DVec2::new(0.0, s)];
    }
    let x = base / length;
    let ac = c - a;
    let along = ac.dot(x);
    let height = (ac - x * along).length();
    let height = if height.is_finite() {
        height.max(MIN_ASPECT * length)
    } else {
        MIN_ASPECT * length
    };
    [
        DVec2::ZERO,
        DVec2::new(length, 0.0),
        DVec2::new(along, height),
    ]
}

/// The corner order `(k, k+1, k+2)` that starts at the longest edge (a stable base).
fn longest_edge_first(p: [DVec3; 3]) -> usize {
    let len = |i: usize| (p[(i + 1) % 3] - p[i]).length_squared();
    (0..3)
        .max_by(|&i, &j| len(i).total_cmp(&len(j)))
        .unwrap_or(0)
}

/// The mean edge length of the mesh's triangles (a size for degenerate ones), or 1.
fn mean_edge(mesh: &UnwrapMesh) -> f64 {
    let p = mesh.positions();
    let (sum, n) = mesh.triangles().iter().fold((0.0, 0u64), |(s, n), t| {
        let e = (0..3)
            .map(|i| (p[t[(i + 1) % 3] as usize] - p[t[i] as usize]).length())
            .sum::<f64>();
        (s + e, n + 3)
    });
    let mean = sum / n as f64;
    if mean.is_finite() && mean > 0.0 {
        mean
    } else {
        1.0
    }
}

/// One chart per triangle.
pub(crate) fn per_triangle(mesh: &UnwrapMesh) -> Vec<Chart> {
    let p = mesh.positions();
    let fallback = mean_edge(mesh) * MIN_ASPECT;
    mesh.triangles()
        .iter()
        .enumerate()
        .map(|(f, t)| {
            let corners = t.map(|i| p[i as usize]);
            let k = longest_edge_first(corners);
            let flat = lay_flat(
                corners[k],
                corners[(k + 1) % 3],
                corners[(k + 2) % 3],
                fallback,
            );
            // Chart vertex i is corner i of the mesh triangle.
            let mut uvs = [DVec2::ZERO; 3];
            for (j, uv) in flat.into_iter().enumerate() {
                uvs[(k + j) % 3] = uv;
            }
            Chart {
                faces: vec![f as u32],
                vertices: t.to_vec(),
                triangles: vec![[0, 1, 2]],
                uvs: uvs.to_vec(),
            }
        })
        .collect()
}

/// Charts of two triangles that share an edge (matched greedily, longest shared edge first, so
/// a triangulated quad becomes one rectangle-like chart), and of one triangle where no
/// neighbour is left. An edge is shared only when exactly two triangles use it, in opposite
/// directions (consistently oriented), and both are thicker than [`MIN_ASPECT`].
pub(crate) fn triangle_pairs(mesh: &UnwrapMesh) -> Vec<Chart> {
    let p = mesh.positions();
    let tris = mesh.triangles();
    let fallback = mean_edge(mesh) * MIN_ASPECT;
    // Directed edge (from, to) -> (triangle, corner of `from`), and how many triangles use the
    // undirected edge.
    let mut directed: HashMap<(u32, u32), (u32, usize)> = HashMap::with_capacity(3 * tris.len());
    let mut uses: HashMap<(u32, u32), u32> = HashMap::with_capacity(3 * tris.len());
    for (f, t) in tris.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            directed.insert((a, b), (f as u32, k));
            *uses.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    let thick = |t: &[u32; 3]| {
        let c = t.map(|i| p[i as usize]);
        let area2 = (c[1] - c[0]).cross(c[2] - c[0]).length();
        let longest = (0..3)
            .map(|i| (c[(i + 1) % 3] - c[i]).length_squared())
            .fold(0.0, f64::max);
        area2 > MIN_ASPECT * longest && t[0] != t[1] && t[1] != t[2] && t[0] != t[2]
    };
    // Candidate pairs, longest shared edge first.
    let mut candidates: Vec<(f64, u32, usize, u32, usize)> = Vec::new();
    for (f, t) in tris.iter().enumerate() {
        if !thick(t) {
            continue;
        }
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if a >= b || uses.get(&(a, b)).copied() != Some(2) {
                continue;
            }
            let Some(&(g, kg)) = directed.get(&(b, a)) else {
                continue;
            };
            let tg = &tris[g as usize];
            let (c, d) = (t[(k + 2) % 3], tg[(kg + 2) % 3]);
            if g as usize == f || c == d || !thick(tg) {
                continue;
            }
            let length = (p[b as usize] - p[a as usize]).length();
            candidates.push((length, f as u32, k, g, kg));
        }
    }
    candidates.sort_by(|x, y| y.0.total_cmp(&x.0).then(x.1.cmp(&y.1)));
    let mut taken = vec![false; tris.len()];
    let mut charts = Vec::with_capacity(tris.len());
    for &(_, f, k, g, kg) in &candidates {
        if taken[f as usize] || taken[g as usize] {
            continue;
        }
        taken[f as usize] = true;
        taken[g as usize] = true;
        let (tf, tg) = (tris[f as usize], tris[g as usize]);
        let (a, b, c) = (tf[k], tf[(k + 1) % 3], tf[(k + 2) % 3]);
        let d = tg[(kg + 2) % 3];
        let [ua, ub, uc] = lay_flat(p[a as usize], p[b as usize], p[c as usize], fallback);
        // `d` on the other side of ab: g runs b -> a -> d counter-clockwise, so d lies to the
        // right of a -> b; lay g flat from b to a and turn it by half a turn about ab's middle.
        let [_, _, ud] = lay_flat(p[b as usize], p[a as usize], p[d as usize], fallback);
        let ud = ub - ud;
        let local = |v: u32| -> u32 {
            match v {
                _ if v == a => 0,
                _ if v == b => 1,
                _ if v == c => 2,
                _ => 3,
            }
        };
        charts.push(Chart {
            faces: vec![f, g],
            vertices: vec![a, b, c, d],
            triangles: vec![tf.map(local), tg.map(local)],
            uvs: vec![ua, ub, uc, ud],
        });
    }
    // The rest alone.
    let singles: Vec<usize> = (0..tris.len()).filter(|&f| !taken[f]).collect();
    if !singles.is_empty() {
        let all = per_triangle(mesh);
        for (f, chart) in all.into_iter().enumerate() {
            if !taken[f] {
                charts.push(chart);
            }
        }
    }
    charts
}
