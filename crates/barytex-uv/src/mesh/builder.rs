//! Shared machinery of the generators: size checks before allocating, the tangent frame, and
//! the (u, v) grid with duplicated seams.

use glam::{DVec2, DVec3, Vec4};

use super::{MAX_VERTICES, TriMesh};
use crate::UvError;

/// One vertex as a generator computes it, in f64 (rounded once, to f32, when stored).
#[derive(Clone, Copy, Debug)]
pub(super) struct Vertex {
    pub(super) position: DVec3,
    pub(super) normal: DVec3,
    /// `∂p/∂u`, or its limit direction where it vanishes (a pole).
    pub(super) dpdu: DVec3,
    /// `∂p/∂v` (only its side of the plane through `n` and `∂p/∂u` matters).
    pub(super) dpdv: DVec3,
    pub(super) uv: DVec2,
}

/// Refuses a resolution below `min`.
pub(super) fn at_least(what: &'static str, value: u32, min: u32) -> Result<(), UvError> {
    if value < min {
        return Err(UvError::OutOfRange {
            what,
            value: f64::from(value),
        });
    }
    Ok(())
}

/// Refuses more than [`MAX_VERTICES`] vertices (computed in u128, so no overflow).
pub(super) fn within_limit(vertices: u128) -> Result<usize, UvError> {
    if vertices > u128::from(MAX_VERTICES) {
        return Err(UvError::TooLarge {
            what: "mesh vertices",
            requested: u64::try_from(vertices).unwrap_or(u64::MAX),
            limit: MAX_VERTICES,
        });
    }
    // Within MAX_VERTICES, so it fits every usize of 32 bits or more.
    usize::try_from(vertices).map_err(|_| UvError::TooLarge {
        what: "mesh vertices",
        requested: MAX_VERTICES,
        limit: MAX_VERTICES,
    })
}

/// The angle `2π·i/n`, with `i = n` giving exactly the values of `i = 0` (so the duplicated seam
/// column has bit-identical positions).
pub(super) fn turn(i: u32, n: u32) -> (f64, f64) {
    let angle = core::f64::consts::TAU * f64::from(i % n) / f64::from(n);
    angle.sin_cos()
}

/// `+0.0` for `−0.0`, so positions that are equal compare equal bit for bit.
fn positive_zero(p: DVec3) -> DVec3 {
    p + DVec3::ZERO
}

/// A mesh under construction.
pub(super) struct Builder {
    mesh: TriMesh,
}

impl Builder {
    pub(super) fn with_capacity(vertices: usize) -> Self {
        Self {
            mesh: TriMesh {
                positions: Vec::with_capacity(vertices),
                normals: Vec::with_capacity(vertices),
                tangents: Vec::with_capacity(vertices),
                uvs: Vec::with_capacity(vertices),
                indices: Vec::with_capacity(vertices * 2),
            },
        }
    }

    /// Adds a vertex; its tangent is `∂p/∂u` made orthogonal to `n`, its handedness the side of
    /// `∂p/∂v` (the bitangent `w·(n × t)` points toward decreasing `v`, as glTF's +y).
    pub(super) fn vertex(&mut self, v: Vertex) -> u32 {
        let n = v.normal.normalize();
        let t = (v.dpdu - n * n.dot(v.dpdu)).normalize();
        let w = if n.cross(t).dot(v.dpdv) <= 0.0 {
            1.0
        } else {
            -1.0
        };
        let index = u32::try_from(self.mesh.positions.len()).unwrap_or(u32::MAX);
        self.mesh
            .positions
            .push(positive_zero(v.position).as_vec3());
        self.mesh.normals.push(n.as_vec3());
        self.mesh.tangents.push(Vec4::from((t.as_vec3(), w)));
        self.mesh.uvs.push(v.uv.as_vec2());
        index
    }

    /// Adds a triangle unless two of its corners share a position (a collapsed pole quad).
    pub(super) fn triangle(&mut self, corners: [u32; 3]) {
        let p = corners.map(|i| self.mesh.positions[i as usize]);
        if p[0] != p[1] && p[1] != p[2] && p[2] != p[0] {
            self.mesh.indices.push(corners);
        }
    }

    /// A `columns × rows` grid of quads over `(u, v) ∈ [0, 1]²` (`u` along columns, `v` down
    /// rows), `(columns + 1)(rows + 1)` vertices from `at(i, j)`, two counter-clockwise
    /// triangles per quad for a non-mirrored mapping (`∂p/∂u × ∂p/∂v` points inward when `v` is
    /// down).
    pub(super) fn grid(&mut self, columns: u32, rows: u32, mut at: impl FnMut(u32, u32) -> Vertex) {
        let base = u32::try_from(self.mesh.positions.len()).unwrap_or(u32::MAX);
        for j in 0..=rows {
            for i in 0..=columns {
                self.vertex(at(i, j));
            }
        }
        let index = |i: u32, j: u32| base + j * (columns + 1) + i;
        for j in 0..rows {
            for i in 0..columns {
                let (p00, p10, p01, p11) = (
                    index(i, j),
                    index(i + 1, j),
                    index(i, j + 1),
                    index(i + 1, j + 1),
                );
                let position = |i: u32| self.mesh.positions[i as usize];
                if position(p01) == position(p11) {
                    // A collapsed bottom edge (the south pole): one triangle, through this
                    // column's own pole vertex so its uvs stay inside the column.
                    self.triangle([p00, p01, p10]);
                } else {
                    // A collapsed top edge (the north pole) leaves only the first.
                    self.triangle([p00, p01, p11]);
                    self.triangle([p00, p11, p10]);
                }
            }
        }
    }

    pub(super) fn finish(self) -> TriMesh {
        self.mesh
    }
}

/// `(i / n)` in f64.
pub(super) fn fraction(i: u32, n: u32) -> f64 {
    f64::from(i) / f64::from(n)
}
