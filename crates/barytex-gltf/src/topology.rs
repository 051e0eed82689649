//! Primitive topologies and their triangulation, with the index formulas of glTF 2.0 §3.7.2.1:
//! strips alternate winding so every triangle keeps the strip's orientation, fans pivot on the
//! first vertex.

/// A primitive's `mode`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Topology {
    /// `POINTS` (0).
    Points,
    /// `LINES` (1).
    Lines,
    /// `LINE_LOOP` (2).
    LineLoop,
    /// `LINE_STRIP` (3).
    LineStrip,
    /// `TRIANGLES` (4), the default.
    Triangles,
    /// `TRIANGLE_STRIP` (5).
    TriangleStrip,
    /// `TRIANGLE_FAN` (6).
    TriangleFan,
}

impl Topology {
    /// The topology for a glTF `mode` value.
    ///
    /// ```
    /// use barytex_gltf::Topology;
    ///
    /// assert_eq!(Topology::from_gl(4), Some(Topology::Triangles));
    /// assert_eq!(Topology::from_gl(6), Some(Topology::TriangleFan));
    /// assert_eq!(Topology::from_gl(7), None); // not a glTF mode
    /// ```
    #[must_use]
    pub fn from_gl(mode: u64) -> Option<Self> {
        Some(match mode {
            0 => Self::Points,
            1 => Self::Lines,
            2 => Self::LineLoop,
            3 => Self::LineStrip,
            4 => Self::Triangles,
            5 => Self::TriangleStrip,
            6 => Self::TriangleFan,
            _ => return None,
        })
    }

    /// Whether the topology produces triangles.
    ///
    /// ```
    /// use barytex_gltf::Topology;
    ///
    /// assert!(Topology::TriangleStrip.is_triangles());
    /// assert!(!Topology::LineLoop.is_triangles());
    /// ```
    #[must_use]
    pub fn is_triangles(self) -> bool {
        matches!(
            self,
            Self::Triangles | Self::TriangleStrip | Self::TriangleFan
        )
    }

    /// How many triangles `n` vertices (or indices) produce.
    ///
    /// ```
    /// use barytex_gltf::Topology;
    ///
    /// assert_eq!(Topology::Triangles.triangle_count(7), 2); // the last vertex is left over
    /// assert_eq!(Topology::TriangleStrip.triangle_count(7), 5);
    /// assert_eq!(Topology::TriangleFan.triangle_count(2), 0);
    /// assert_eq!(Topology::Lines.triangle_count(9), 0);
    /// ```
    #[must_use]
    pub fn triangle_count(self, n: usize) -> usize {
        match self {
            Self::Triangles => n / 3,
            Self::TriangleStrip | Self::TriangleFan => n.saturating_sub(2),
            _ => 0,
        }
    }
}

/// Triangulates `indices` (vertex indices in primitive order) for a triangle topology; returns
/// an empty list for points and lines.
///
/// ```
/// use barytex_gltf::topology::{Topology, triangulate};
///
/// // A strip alternates so every triangle keeps the first one's winding.
/// assert_eq!(triangulate(Topology::TriangleStrip, &[0, 1, 2, 3]), [[0, 1, 2], [1, 3, 2]]);
/// // A fan pivots on its first vertex (glTF lists it last: {v(i+1), v(i+2), v0}).
/// assert_eq!(triangulate(Topology::TriangleFan, &[0, 1, 2, 3]), [[1, 2, 0], [2, 3, 0]]);
/// assert_eq!(triangulate(Topology::Triangles, &[5, 6, 7, 8]), [[5, 6, 7]]);
/// assert!(triangulate(Topology::Points, &[0, 1, 2]).is_empty());
/// ```
#[must_use]
pub fn triangulate(topology: Topology, indices: &[u32]) -> Vec<[u32; 3]> {
    match topology {
        Topology::Triangles => indices
            .chunks_exact(3)
            .map(|t| [t[0], t[1], t[2]])
            .collect(),
        // p_i = {v_i, v_(i + (1 + i % 2)), v_(i + (2 − i % 2))}
        Topology::TriangleStrip => indices
            .windows(3)
            .enumerate()
            .map(|(i, w)| {
                if i % 2 == 0 {
                    [w[0], w[1], w[2]]
                } else {
                    [w[0], w[2], w[1]]
                }
            })
            .collect(),
        // p_i = {v_(i + 1), v_(i + 2), v_0}
        Topology::TriangleFan => match indices.split_first() {
            Some((&first, rest)) => rest.windows(2).map(|w| [w[0], w[1], first]).collect(),
            None => Vec::new(),
        },
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_alternate_and_fans_pivot() {
        assert_eq!(
            triangulate(Topology::TriangleStrip, &[0, 1, 2, 3]),
            vec![[0, 1, 2], [1, 3, 2]]
        );
        assert_eq!(
            triangulate(Topology::TriangleFan, &[0, 1, 2, 3]),
            vec![[1, 2, 0], [2, 3, 0]]
        );
        assert_eq!(
            triangulate(Topology::Triangles, &[0, 1, 2, 3]),
            vec![[0, 1, 2]]
        );
        assert!(triangulate(Topology::Lines, &[0, 1]).is_empty());
        assert_eq!(Topology::TriangleFan.triangle_count(1), 0);
    }
}
