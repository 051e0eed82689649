//! Displacement mapping (Cook 1984; S. Schaefer's *Shading/Texturing* slides): the geometry itself
//! moves along the normal by a height texture, so — unlike bump and normal mapping — the silhouette
//! changes. The mesh is first tessellated finely enough for the height's detail, then every vertex
//! is offset.
//!
//! Chart seams break naive displacement: the copies of a seam vertex (same position, different
//! uv, e.g. `u = 0` and `u = 1` on a sphere) read different heights and pull apart, opening a
//! crack. [`Seams::Weld`] gives every copy the mean offset of the group, which keeps the surface
//! closed.

use std::collections::HashMap;

use barytex_uv::TriMesh;
use glam::{Vec2, Vec3, Vec4};

use crate::perturb::HeightField;
use crate::{NormalWeighting, vertex_normals};

/// What to do where copies of one position carry different uvs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Seams {
    /// Displace every vertex by its own height: cracks open wherever the height differs across a
    /// seam (the warning of Schaefer's slides: chart boundaries that don't match are "a huge
    /// problem for displacement mapping").
    Ignore,
    /// Displace all copies of a position (bit-identical before displacement) by their mean offset,
    /// and give them their mean normal afterwards: no cracks. The default.
    #[default]
    Weld,
}

/// `mesh` with every triangle split into `level²` triangles (edge points shared exactly between
/// neighbours), every vertex moved by `scale · height(uv)` along its interpolated normal, and
/// normals recomputed from the displaced surface (angle-weighted; welded across seams with
/// [`Seams::Weld`]).
///
/// Tangents are interpolated and re-orthogonalized; missing normals count as zero (no
/// displacement), missing uvs as `(0, 0)`. `level` is clamped to `1..=64`. Triangles with an
/// index out of range are left out. A non-finite height moves nothing.
///
/// ```
/// use barytex_shade::{displace, Seams};
///
/// let sphere = barytex_uv::mesh::sphere(8, 4).expect("valid");
/// // Every vertex 0.25 further out along its normal; level 2 quadruples the triangles.
/// let grown = displace(&sphere, &|_uv: glam::Vec2| 1.0, 0.25, 2, Seams::Weld);
/// assert_eq!(grown.indices.len(), 4 * sphere.indices.len());
/// // The original vertices (normal = position on the unit sphere) move to radius 1.25.
/// assert!(sphere.positions.iter().all(|p| {
///     grown.positions.iter().any(|q| (*q - *p * 1.25).length() < 1e-6)
/// }));
/// ```
#[must_use]
pub fn displace(
    mesh: &TriMesh,
    height: &dyn HeightField,
    scale: f32,
    level: u32,
    seams: Seams,
) -> TriMesh {
    let fine = tessellate(mesh, level.clamp(1, 64));
    let offsets: Vec<Vec3> = (0..fine.positions.len())
        .map(|i| {
            let h = height.height(fine.uvs[i]) * scale;
            let d = fine.normals[i].normalize_or_zero() * h;
            if d.is_finite() { d } else { Vec3::ZERO }
        })
        .collect();
    let groups = match seams {
        Seams::Weld => Some(position_groups(&fine.positions)),
        Seams::Ignore => None,
    };
    let mut out = fine.clone();
    match &groups {
        Some(groups) => {
            for group in groups {
                let mean = group.iter().map(|&i| offsets[i]).sum::<Vec3>() / group.len() as f32;
                for &i in group {
                    out.positions[i] = fine.positions[i] + mean;
                }
            }
        }
        None => {
            for (p, d) in out.positions.iter_mut().zip(&offsets) {
                *p += *d;
            }
        }
    }
    let mut normals = vertex_normals(&out.positions, &out.indices, NormalWeighting::Angle);
    if let Some(groups) = &groups {
        for group in groups {
            let mean = group
                .iter()
                .map(|&i| normals[i])
                .sum::<Vec3>()
                .normalize_or_zero();
            for &i in group {
                normals[i] = mean;
            }
        }
    }
    for (i, t) in out.tangents.iter_mut().enumerate() {
        let n = normals[i];
        let v = t.truncate();
        let v = (v - n * n.dot(v)).normalize_or_zero();
        *t = v.extend(if t.w < 0.0 { -1.0 } else { 1.0 });
    }
    out.normals = normals;
    out
}

/// Indices of vertices with bit-identical positions, grouped (singletons included).
fn position_groups(positions: &[Vec3]) -> Vec<Vec<usize>> {
    let mut map: HashMap<[u32; 3], Vec<usize>> = HashMap::new();
    for (i, p) in positions.iter().enumerate() {
        // +0.0 and −0.0 are the same point.
        let key = (*p + Vec3::ZERO).to_array().map(f32::to_bits);
        map.entry(key).or_default().push(i);
    }
    let mut groups: Vec<Vec<usize>> = map.into_values().collect();
    groups.sort_unstable();
    groups
}

/// Uniform subdivision of every triangle into `level²`; attributes interpolated linearly
/// (normals renormalized). A point on a shared edge is computed from the edge's endpoints in a
/// fixed order (lower vertex index first), so both neighbours get the same bits.
fn tessellate(mesh: &TriMesh, level: u32) -> TriMesh {
    let n = mesh.positions.len();
    let get = |i: u32| -> (Vec3, Vec3, Vec2, Vec4) {
        let i = i as usize;
        (
            mesh.positions[i],
            mesh.normals.get(i).copied().unwrap_or(Vec3::ZERO),
            mesh.uvs.get(i).copied().unwrap_or(Vec2::ZERO),
            mesh.tangents.get(i).copied().unwrap_or(Vec4::ZERO),
        )
    };
    let mut out = TriMesh::default();
    let k = level;
    for tri in mesh
        .indices
        .iter()
        .filter(|t| t.iter().all(|&i| (i as usize) < n))
    {
        let base = out.positions.len() as u32;
        let corners = tri.map(get);
        // Lattice point (i, j): weights (k − i − j, i, j)/k over the triangle's vertices.
        let row_start = |i: u32| -> u32 { (0..i).map(|r| k + 1 - r).sum() };
        for i in 0..=k {
            for j in 0..=k - i {
                let w = [k - i - j, i, j];
                let (p, nn, uv, t) = blend(tri, &corners, w, k);
                out.positions.push(p);
                out.normals.push(nn.normalize_or_zero());
                out.uvs.push(uv);
                out.tangents.push(t);
            }
        }
        let at = |i: u32, j: u32| base + row_start(i) + j;
        for i in 0..k {
            for j in 0..k - i {
                out.indices.push([at(i, j), at(i + 1, j), at(i, j + 1)]);
                if j + 1 < k - i {
                    out.indices
                        .push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
        }
    }
    out
}

/// The attributes at lattice weights `w / k`, summed in the order of the vertex indices so that
/// shared edges give identical bits.
fn blend(
    tri: &[u32; 3],
    corners: &[(Vec3, Vec3, Vec2, Vec4); 3],
    w: [u32; 3],
    k: u32,
) -> (Vec3, Vec3, Vec2, Vec4) {
    // At a corner, return it exactly.
    if let Some(c) = w.iter().position(|&x| x == k) {
        return corners[c];
    }
    let mut order = [0usize, 1, 2];
    order.sort_by_key(|&c| tri[c]);
    let mut acc = (Vec3::ZERO, Vec3::ZERO, Vec2::ZERO, Vec4::ZERO);
    for &c in &order {
        if w[c] == 0 {
            continue;
        }
        let f = w[c] as f32 / k as f32;
        let (p, n, uv, t) = corners[c];
        acc.0 += p * f;
        acc.1 += n * f;
        acc.2 += uv * f;
        acc.3 += t * f;
    }
    acc
}
