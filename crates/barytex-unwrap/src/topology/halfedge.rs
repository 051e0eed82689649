//! A half-edge view of a triangle mesh, stored as a corner table.
//!
//! Half-edge `3 t + i` runs from corner `i` to corner `i + 1 (mod 3)` of triangle `t`; its
//! `next` is implicit, its `twin` is stored. This is the corner table of J. Rossignac,
//! "3D compression made simple: Edgebreaker with ZipandWrap on a corner-table", *Proc. Shape
//! Modeling International*, 2001, with opposite corners replaced by opposite half-edges.

use crate::UnwrapError;
use crate::alloc::try_vec_with_capacity;

/// No twin (a boundary half-edge) or no half-edge (an isolated vertex).
pub const NONE: u32 = u32::MAX;

/// An edge-manifold, vertex-manifold, consistently oriented triangle mesh with its twins.
///
/// ```
/// use barytex_unwrap::HalfEdgeMesh;
///
/// // Two triangles sharing the edge (0, 2): one boundary loop of four vertices.
/// let square = HalfEdgeMesh::from_triangles(4, &[[0, 1, 2], [0, 2, 3]]).expect("manifold");
/// assert_eq!(square.boundary_loops(), vec![vec![0, 1, 2, 3]]);
/// assert_eq!(square.euler_characteristic(), 1);
/// // A third triangle on the same edge makes it non-manifold.
/// assert!(HalfEdgeMesh::from_triangles(5, &[[0, 1, 2], [0, 2, 3], [2, 0, 4]]).is_err());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct HalfEdgeMesh {
    vertex_count: u32,
    triangles: Vec<[u32; 3]>,
    twin: Vec<u32>,
    /// One outgoing half-edge per vertex: the boundary one for a boundary vertex.
    outgoing: Vec<u32>,
}

impl HalfEdgeMesh {
    /// Builds the half-edges of `triangles` over `vertex_count` vertices.
    ///
    /// # Errors
    /// [`UnwrapError::IndexOutOfRange`] for an index `≥ vertex_count`,
    /// [`UnwrapError::RepeatedIndex`] for a triangle naming a vertex twice,
    /// [`UnwrapError::NonManifoldEdge`] for an edge used twice in the same direction (three or
    /// more triangles, or inconsistent orientation), [`UnwrapError::NonManifoldVertex`] for a
    /// vertex whose triangles form more than one fan, [`UnwrapError::TooLarge`] past
    /// [`crate::MAX_VERTICES`] vertices or [`crate::MAX_TRIANGLES`] triangles,
    /// [`UnwrapError::OutOfMemory`].
    pub fn from_triangles(vertex_count: u32, triangles: &[[u32; 3]]) -> Result<Self, UnwrapError> {
        if vertex_count as usize > crate::MAX_VERTICES {
            return Err(UnwrapError::TooLarge {
                what: "vertices",
                requested: u64::from(vertex_count),
                limit: crate::MAX_VERTICES as u64,
            });
        }
        if triangles.len() > crate::MAX_TRIANGLES {
            return Err(UnwrapError::TooLarge {
                what: "triangles",
                requested: triangles.len() as u64,
                limit: crate::MAX_TRIANGLES as u64,
            });
        }
        for (t, tri) in triangles.iter().enumerate() {
            if let Some(&index) = tri.iter().find(|&&i| i >= vertex_count) {
                return Err(UnwrapError::IndexOutOfRange {
                    triangle: t as u32,
                    index,
                    vertices: vertex_count,
                });
            }
            if tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] {
                return Err(UnwrapError::RepeatedIndex { triangle: t as u32 });
            }
        }
        let h_count = 3 * triangles.len();
        // Directed edges sorted by (from, to): a repeated key is a non-manifold edge, the twin
        // of (a, b) is found by binary search for (b, a).
        let mut keys: Vec<(u64, u32)> = try_vec_with_capacity(h_count, "half-edges")?;
        for (t, tri) in triangles.iter().enumerate() {
            for i in 0..3 {
                let (a, b) = (tri[i], tri[(i + 1) % 3]);
                keys.push(((u64::from(a) << 32) | u64::from(b), (3 * t + i) as u32));
            }
        }
        keys.sort_unstable();
        if let Some(w) = keys.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(UnwrapError::NonManifoldEdge {
                a: (w[0].0 >> 32) as u32,
                b: w[0].0 as u32,
            });
        }
        let mut twin: Vec<u32> = try_vec_with_capacity(h_count, "half-edges")?;
        twin.resize(h_count, NONE);
        for &(key, h) in &keys {
            let reverse = key.rotate_right(32);
            if let Ok(k) = keys.binary_search_by(|probe| probe.0.cmp(&reverse)) {
                twin[h as usize] = keys[k].1;
            }
        }
        drop(keys);
        let mut outgoing: Vec<u32> = try_vec_with_capacity(vertex_count as usize, "vertices")?;
        outgoing.resize(vertex_count as usize, NONE);
        let mut degree: Vec<u32> = try_vec_with_capacity(vertex_count as usize, "vertices")?;
        degree.resize(vertex_count as usize, 0);
        for h in 0..h_count {
            let v = triangles[h / 3][h % 3] as usize;
            degree[v] += 1;
            if twin[h] == NONE {
                if outgoing[v] != NONE && twin[outgoing[v] as usize] == NONE {
                    // Two boundary half-edges leave v: two fans meet there.
                    return Err(UnwrapError::NonManifoldVertex { vertex: v as u32 });
                }
                outgoing[v] = h as u32;
            } else if outgoing[v] == NONE {
                outgoing[v] = h as u32;
            }
        }
        let mesh = Self {
            vertex_count,
            triangles: triangles.to_vec(),
            twin,
            outgoing,
        };
        for v in 0..vertex_count {
            if degree[v as usize] != 0 && mesh.fan_size(v) != degree[v as usize] {
                return Err(UnwrapError::NonManifoldVertex { vertex: v });
            }
        }
        Ok(mesh)
    }

    /// The number of triangles around `v` reached by walking its fan from
    /// [`HalfEdgeMesh::outgoing`].
    fn fan_size(&self, v: u32) -> u32 {
        let start = self.outgoing[v as usize];
        if start == NONE {
            return 0;
        }
        let mut h = start;
        let mut count = 0;
        loop {
            count += 1;
            let incoming = Self::prev(h);
            let t = self.twin[incoming as usize];
            if t == NONE || t == start || count > self.triangles.len() as u32 {
                return count;
            }
            h = t;
        }
    }

    /// The number of vertices (including unreferenced ones).
    #[must_use]
    pub fn vertex_count(&self) -> u32 {
        self.vertex_count
    }

    /// The triangles.
    #[must_use]
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The twin of half-edge `h`, or [`NONE`] on the boundary.
    #[must_use]
    pub fn twin(&self, h: u32) -> u32 {
        self.twin[h as usize]
    }

    /// The half-edge after `h` in its triangle.
    #[must_use]
    pub fn next(h: u32) -> u32 {
        if h % 3 == 2 { h - 2 } else { h + 1 }
    }

    /// The half-edge before `h` in its triangle.
    #[must_use]
    pub fn prev(h: u32) -> u32 {
        if h.is_multiple_of(3) { h + 2 } else { h - 1 }
    }

    /// The vertex half-edge `h` leaves.
    #[must_use]
    pub fn origin(&self, h: u32) -> u32 {
        self.triangles[(h / 3) as usize][(h % 3) as usize]
    }

    /// The vertex half-edge `h` enters.
    #[must_use]
    pub fn target(&self, h: u32) -> u32 {
        self.origin(Self::next(h))
    }

    /// One half-edge leaving `v` (the boundary one on the boundary), or [`NONE`] if no triangle
    /// uses `v`.
    #[must_use]
    pub fn outgoing(&self, v: u32) -> u32 {
        self.outgoing[v as usize]
    }

    /// Numbers the vertices that some triangle uses and `select` keeps, in index order: `index[v]`
    /// is `v`'s number, [`NONE`] for the others; also returns how many were numbered (the
    /// unknowns of a linear system over the mesh).
    pub(crate) fn number_vertices(&self, select: impl Fn(u32) -> bool) -> (Vec<u32>, usize) {
        let n = self.vertex_count();
        let mut index = vec![NONE; n as usize];
        let mut count = 0usize;
        for v in 0..n {
            if self.outgoing(v) != NONE && select(v) {
                index[v as usize] = count as u32;
                count += 1;
            }
        }
        (index, count)
    }

    /// Whether `v` lies on the boundary.
    #[must_use]
    pub fn is_boundary_vertex(&self, v: u32) -> bool {
        let h = self.outgoing[v as usize];
        h != NONE && self.twin[h as usize] == NONE
    }

    /// The number of edges (a twin pair counts once).
    #[must_use]
    pub fn edge_count(&self) -> usize {
        let boundary = self.twin.iter().filter(|&&t| t == NONE).count();
        (self.twin.len() + boundary) / 2
    }

    /// The number of vertices used by at least one triangle.
    #[must_use]
    pub fn used_vertex_count(&self) -> usize {
        self.outgoing.iter().filter(|&&h| h != NONE).count()
    }

    /// `V − E + F` over the used vertices.
    #[must_use]
    pub fn euler_characteristic(&self) -> i64 {
        self.used_vertex_count() as i64 - self.edge_count() as i64 + self.triangles.len() as i64
    }

    /// Every boundary loop as its vertices in order, the interior on the left (counter-clockwise
    /// for a counter-clockwise disk). Loops start at their lowest half-edge.
    #[must_use]
    pub fn boundary_loops(&self) -> Vec<Vec<u32>> {
        let mut seen = vec![false; self.twin.len()];
        let mut loops = Vec::new();
        for start in 0..self.twin.len() as u32 {
            if self.twin[start as usize] != NONE || seen[start as usize] {
                continue;
            }
            let mut lp = Vec::new();
            let mut h = start;
            while !seen[h as usize] {
                seen[h as usize] = true;
                lp.push(self.origin(h));
                // The unique boundary half-edge leaving this one's target.
                h = self.outgoing[self.target(h) as usize];
            }
            loops.push(lp);
        }
        loops
    }

    /// The connected components (through shared edges), each with its topology.
    #[must_use]
    pub fn components(&self) -> Vec<Component> {
        let f = self.triangles.len();
        let mut label = vec![NONE; f];
        let mut components = Vec::new();
        let mut stack = Vec::new();
        for seed in 0..f {
            if label[seed] != NONE {
                continue;
            }
            let id = components.len() as u32;
            label[seed] = id;
            stack.push(seed as u32);
            let mut triangles = Vec::new();
            while let Some(t) = stack.pop() {
                triangles.push(t);
                for i in 0..3 {
                    let tw = self.twin[(3 * t + i) as usize];
                    if tw != NONE && label[(tw / 3) as usize] == NONE {
                        label[(tw / 3) as usize] = id;
                        stack.push(tw / 3);
                    }
                }
            }
            triangles.sort_unstable();
            components.push(triangles);
        }
        let loops = self.boundary_loops();
        components
            .into_iter()
            .enumerate()
            .map(|(id, triangles)| {
                let mut vertices: Vec<u32> = triangles
                    .iter()
                    .flat_map(|&t| self.triangles[t as usize])
                    .collect();
                vertices.sort_unstable();
                vertices.dedup();
                let mut half = 0usize;
                let mut boundary_half = 0usize;
                for &t in &triangles {
                    for i in 0..3 {
                        half += 1;
                        if self.twin[(3 * t + i) as usize] == NONE {
                            boundary_half += 1;
                        }
                    }
                }
                let edges = (half + boundary_half) / 2;
                let boundary_loops = loops
                    .iter()
                    .filter(|lp| {
                        let h = self.outgoing[lp[0] as usize];
                        label[(h / 3) as usize] == id as u32
                    })
                    .count() as u32;
                let chi = vertices.len() as i64 - edges as i64 + triangles.len() as i64;
                Component {
                    triangles,
                    vertices,
                    edges,
                    boundary_loops,
                    euler_characteristic: chi,
                }
            })
            .collect()
    }

    /// Whether the mesh is one topological disk: connected, one boundary loop, `χ = 1`.
    ///
    /// # Errors
    /// [`UnwrapError::NotADisk`] with the counts otherwise.
    pub fn check_disk(&self) -> Result<Vec<u32>, UnwrapError> {
        let components = self.components();
        let mut loops = self.boundary_loops();
        let chi = self.euler_characteristic();
        if components.len() == 1 && loops.len() == 1 && chi == 1 {
            Ok(loops.pop().unwrap_or_default())
        } else {
            Err(UnwrapError::NotADisk {
                components: components.len() as u32,
                boundary_loops: loops.len() as u32,
                euler_characteristic: chi,
            })
        }
    }
}

/// One connected component of a [`HalfEdgeMesh`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Component {
    /// Its triangles, ascending.
    pub triangles: Vec<u32>,
    /// Its vertices, ascending.
    pub vertices: Vec<u32>,
    /// Its edges.
    pub edges: usize,
    /// Its boundary loops.
    pub boundary_loops: u32,
    /// `V − E + F`.
    pub euler_characteristic: i64,
}

impl Component {
    /// The genus `g` of this orientable surface: `χ = 2 − 2 g − b` with `b` boundary loops.
    #[must_use]
    pub fn genus(&self) -> i64 {
        (2 - self.euler_characteristic - i64::from(self.boundary_loops)) / 2
    }

    /// Whether it is a topological disk (`χ = 1`, one boundary loop).
    #[must_use]
    pub fn is_disk(&self) -> bool {
        self.euler_characteristic == 1 && self.boundary_loops == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The octahedron: closed, genus 0.
    const OCTAHEDRON: [[u32; 3]; 8] = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];

    #[test]
    fn closed_sphere_has_genus_zero_and_no_boundary() {
        let m = HalfEdgeMesh::from_triangles(6, &OCTAHEDRON).expect("manifold");
        let c = m.components();
        assert_eq!(c.len(), 1);
        assert_eq!(
            (c[0].euler_characteristic, c[0].boundary_loops, c[0].genus()),
            (2, 0, 0)
        );
        assert!(m.boundary_loops().is_empty());
        assert!(m.check_disk().is_err());
    }

    #[test]
    fn bowtie_is_a_non_manifold_vertex() {
        let e = HalfEdgeMesh::from_triangles(5, &[[0, 1, 2], [0, 3, 4]]);
        assert_eq!(e, Err(UnwrapError::NonManifoldVertex { vertex: 0 }));
        // Closed fans that touch at a vertex: two octahedra sharing vertex 4.
        let mut two: Vec<[u32; 3]> = OCTAHEDRON.to_vec();
        two.extend(
            OCTAHEDRON
                .iter()
                .map(|t| t.map(|v| if v == 4 { 4 } else { v + 6 })),
        );
        let e = HalfEdgeMesh::from_triangles(12, &two);
        assert!(
            matches!(e, Err(UnwrapError::NonManifoldVertex { .. })),
            "{e:?}"
        );
    }

    #[test]
    fn inconsistent_orientation_and_repeated_index_are_reported() {
        let e = HalfEdgeMesh::from_triangles(4, &[[0, 1, 2], [0, 1, 3]]);
        assert_eq!(e, Err(UnwrapError::NonManifoldEdge { a: 0, b: 1 }));
        let e = HalfEdgeMesh::from_triangles(4, &[[0, 1, 1]]);
        assert_eq!(e, Err(UnwrapError::RepeatedIndex { triangle: 0 }));
    }

    #[test]
    fn oversize_vertex_counts_are_refused_before_allocating() {
        let e = HalfEdgeMesh::from_triangles(u32::MAX, &[]);
        assert!(
            matches!(
                e,
                Err(UnwrapError::TooLarge {
                    what: "vertices",
                    ..
                })
            ),
            "{e:?}"
        );
    }

    #[test]
    fn annulus_has_two_loops() {
        // A square ring: outer 0..4, inner 4..8.
        let mut t = Vec::new();
        for i in 0..4u32 {
            let (a, b, c, d) = (i, (i + 1) % 4, 4 + (i + 1) % 4, 4 + i);
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
        let m = HalfEdgeMesh::from_triangles(8, &t).expect("manifold");
        let c = m.components();
        assert_eq!(
            (c[0].euler_characteristic, c[0].boundary_loops, c[0].genus()),
            (0, 2, 0)
        );
        assert_eq!(m.boundary_loops().len(), 2);
    }
}
